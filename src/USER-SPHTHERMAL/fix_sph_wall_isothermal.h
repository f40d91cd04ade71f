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

#include "fix.h"

namespace LAMMPS_NS {

class FixSPHWallIsothermal : public Fix {
 public:
  FixSPHWallIsothermal(class LAMMPS *, int, char **);
  ~FixSPHWallIsothermal() override;
  int setmask() override;
  void init() override;
  void reset_dt() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

 protected:
  double t_wall;            // the wall's temperature
  double spacing;           // particle spacing for the flux of eq 10, 0 when not given
  double rate_previous;     // heat rate into the wall at the previous force evaluation
  double rate;              // heat rate into the wall now (sum over all ranks)
  double energy;            // energy taken up by the wall since the fix was defined
  double dt_half;
  double **wall;            // per atom: heat rate in, energy taken up [, flux]

  void hold_and_tally(int first);
};

}    // namespace LAMMPS_NS

#endif
#endif
