/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/wall/isothermal,FixSPHWallIsothermal);
// clang-format on
#else

#ifndef LMP_FIX_SPH_WALL_ISOTHERMAL_H
#define LMP_FIX_SPH_WALL_ISOTHERMAL_H

#include "fix_sph_wall_tally.h"

namespace LAMMPS_NS {

class FixSPHWallIsothermal : public FixSPHWallTally {
 public:
  FixSPHWallIsothermal(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;

 protected:
  double t_wall;    // the wall's temperature

  void hold_and_tally(int first);
  void hold();
};

}    // namespace LAMMPS_NS

#endif
#endif
