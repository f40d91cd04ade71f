/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/dt/reset,FixSPHDtReset);
// clang-format on
#else

#ifndef LMP_FIX_SPH_DT_RESET_H
#define LMP_FIX_SPH_DT_RESET_H

#include "fix.h"
#include "sph_timestep.h"

namespace LAMMPS_NS {

class FixSPHDtReset : public Fix {
 public:
  FixSPHDtReset(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void end_of_step() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // the limits, in the order of the output vector (active limit = index + 1)
  enum {
    ACOUSTIC = SPHTimestep::ACOUSTIC,
    FORCE = SPHTimestep::FORCE,
    VISCOUS = SPHTimestep::VISCOUS,
    THERMAL = SPHTimestep::THERMAL,
    NLIMITS = SPHTimestep::NLIMITS
  };
  enum { BOUND = NLIMITS + 1 };

 protected:
  double coeff[NLIMITS];    // 0 = limit off
  double dtmin, dtmax;      // dtmax = BIG: no upper bound
  double h_user;            // 'h' keyword, 0 = from the pair style
  double h;                 // smoothing length used
  double until;             // 'until': stop the run at this elapsed time; < 0: no end
  int reset_every;          // N: choose dt every N steps
  double limit[NLIMITS];    // global minimum of each limit, coefficient applied
  int active;               // 1..4 a limit, 5 the min/max bound, 0 none computed yet
  int respa_flag;
  int warned;    // the fix-order warning was given
  int bound_warned;    // the warning that 'min' overrides a limit was given (per run)
  int halted;          // this run was stopped at 'until' (the timer to reset after it)
  class FixSPHMaterials *materials;
  // the conduction pair, whose per-atom relaxation rates set the thermal
  // limit (nullptr without conduction or that limit); the rates are wanted
  // only in the force computations whose step chooses dt (they cost in the
  // pair loop)
  class PairSPHClearyHeat *heat;
  const double *body_force;    // the run's body force (fix gravity), nullptr when none

  double parse_value(int, int, char **, bool);
  double smoothing_length();
  void choose_dt();
  void set_dt(double);
  double elapsed_time() const;
  int end_at_until(bool at_setup);
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void bad_limit(int);
};

}    // namespace LAMMPS_NS

#endif
#endif
