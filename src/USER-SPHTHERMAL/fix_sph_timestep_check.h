/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(SPH/TIMESTEP/CHECK,FixSPHTimestepCheck);
// clang-format on
#else

#ifndef LMP_FIX_SPH_TIMESTEP_CHECK_H
#define LMP_FIX_SPH_TIMESTEP_CHECK_H

#include "fix.h"
#include "sph_timestep.h"

namespace LAMMPS_NS {

// Internal fix (not a command): the package's SPH pair styles add it at
// their init. At the setup of a run with a fixed timestep (no fix
// sph/dt/reset or dt/reset), it compares the timestep with the stability
// limits the pair styles know (sph_timestep.h) and warns about each limit
// the timestep exceeds; and, with or without them, about a speed of sound
// below 10 times the largest speed present.
class FixSPHTimestepCheck : public Fix {
 public:
  FixSPHTimestepCheck(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;

  // add the fix unless it exists (called by the pair styles' init)
  static void ensure(class LAMMPS *);

  // the coefficients of the limits the timestep is checked against: those
  // of Ng et al. 2020, eq 18, and the thermal limit that is sure to be stable
  static constexpr double COEFF_ACOUSTIC = 0.25;
  static constexpr double COEFF_FORCE = 0.25;
  static constexpr double COEFF_VISCOUS = 0.125;
  static constexpr double COEFF_THERMAL = 1.0;
  // the speed of sound at least this many times the largest speed
  static constexpr double SOUND_SPEED_RATIO = 10.0;

 protected:
  int check_dt;              // this run: compare the fixed timestep with the limits
  // the conduction pair while this fix wants its relaxation rates (from
  // init to the end of setup), else nullptr
  class PairSPHClearyHeat *heat_asked;
  // the timestep of the last warning of each limit (a warning is repeated
  // only for another timestep), and whether the speed of sound was reported
  double warned_dt[SPHTimestep::NLIMITS];
  int warned_sound;

  void check_timestep();
  void check_sound_speed();
};

}    // namespace LAMMPS_NS

#endif
#endif
