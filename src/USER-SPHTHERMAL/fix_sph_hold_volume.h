/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/hold/volume,FixSPHHoldVolume);
// clang-format on
#else

#ifndef LMP_FIX_SPH_HOLD_VOLUME_H
#define LMP_FIX_SPH_HOLD_VOLUME_H

#include "fix.h"

namespace LAMMPS_NS {

// The volume sum m / rho of a group of fluid that fills a closed container
// held at its value at the first run's start: after every step all its
// densities are scaled by one factor.
class FixSPHHoldVolume : public Fix {
 public:
  FixSPHHoldVolume(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  // off: the fix does nothing (fix sph/boussinesq's own hold, when the
  // scene has a free surface or the user holds the volume with another)
  void set_active(int on) { active = on; }

 protected:
  int active;              // 1: hold (the default)
  double held;             // the volume held, 0 until the first setup
  double volume_before;    // the volume before the last correction (the scalar)

  double group_volume();
};

}    // namespace LAMMPS_NS

#endif
#endif
