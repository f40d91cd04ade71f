/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The check of a run's fixed timestep against the stability limits of
   the package's pair styles (fix_sph_timestep_check.h, sph_timestep.h).
------------------------------------------------------------------------- */

#include "fix_sph_timestep_check.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "modify.h"
#include "pair_sph_cleary_heat.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_body_force.h"
#include "sph_compat.h"
#include "sph_eos.h"
#include "sph_hub.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char FIX_ID[] = "SPH_TIMESTEP_CHECK";

// larger than any timestep
static constexpr double BIG = 1.0e300;

/* ---------------------------------------------------------------------- */

FixSPHTimestepCheck::FixSPHTimestepCheck(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), check_dt(0), heat_asked(nullptr), warned_sound(0)
{
  for (int k = 0; k < SPHTimestep::NLIMITS; k++) warned_dt[k] = 0.0;
}

int FixSPHTimestepCheck::setmask()
{
  // setup() is called for every fix
  return 0;
}

void FixSPHTimestepCheck::ensure(LAMMPS *lmp)
{
  if (lmp->modify->find_fix(FIX_ID) < 0)
    lmp->modify->add_fix(fmt::format("{} all SPH/TIMESTEP/CHECK", FIX_ID));
}

/* ----------------------------------------------------------------------
   the pair styles' init has run (force->init before modify->init): ask
   pair sph/cleary/heat for its relaxation rates in the setup's force
   computation when the timestep is fixed
------------------------------------------------------------------------- */

void FixSPHTimestepCheck::init()
{
  heat_asked = nullptr;
  SPHHub hub(lmp);
  check_dt = (update->whichflag == 1) && !hub.timestep_resetter(this);
  if (!check_dt) return;
  PairSPHClearyHeat *heat = hub.heat();
  if (heat && (hub.moved_by_fix_sph() || hub.held_by_fix_sph_stationary())) {
    heat_asked = heat;
    heat->want_relax_rates(true);
  }
}

/* ---------------------------------------------------------------------- */

void FixSPHTimestepCheck::setup(int /*vflag*/)
{
  if (update->whichflag != 1) return;
  if (check_dt) check_timestep();
  if (heat_asked) heat_asked->want_relax_rates(false);
  heat_asked = nullptr;
  check_sound_speed();
}

/* ----------------------------------------------------------------------
   the limits of the atoms that fix sph moves (acoustic, force, viscous:
   pair sph/harmonic/visc) and of those whose energy fix sph or fix
   sph/stationary advances (thermal: pair sph/cleary/heat)
------------------------------------------------------------------------- */

void FixSPHTimestepCheck::check_timestep()
{
  const double h = SPHTimestep::smoothing_length(lmp);
  if (h <= 0.0) return;
  int moving = 0, heated = 0;
  SPHHub hub(lmp);
  moving = hub.moved_by_fix_sph();
  heated = moving | hub.held_by_fix_sph_stationary();
  const PairSPHHarmonicVisc *flow = hub.flow();

  double local[SPHTimestep::NLIMITS], limit[SPHTimestep::NLIMITS];
  int bad[SPHTimestep::NLIMITS];
  for (int k = 0; k < SPHTimestep::NLIMITS; k++) local[k] = BIG;
  SPHTimestep::Scan scan;
  scan.h = h;
  scan.relax_rate = nullptr;
  scan.body_force = nullptr;
  scan.who = "Pair style sph/harmonic/visc";
  if (flow && moving) {
    scan.coeff[SPHTimestep::ACOUSTIC] = COEFF_ACOUSTIC;
    scan.coeff[SPHTimestep::FORCE] = COEFF_FORCE;
    scan.coeff[SPHTimestep::VISCOUS] = COEFF_VISCOUS;
    scan.coeff[SPHTimestep::THERMAL] = 0.0;
    scan.groupbit = moving;
    scan.materials = FixSPHMaterials::find(lmp, "Pair style sph/harmonic/visc");
    scan.body_force = SPHBodyForce::find(lmp, "Pair style sph/harmonic/visc");
    SPHTimestep::local_limits(lmp, scan, BIG, local, bad);
  }
  const double *relax = heat_asked ? heat_asked->relax_rates() : nullptr;
  if (relax && heated) {
    double thermal[SPHTimestep::NLIMITS];
    for (int k = 0; k < SPHTimestep::NLIMITS; k++) scan.coeff[k] = 0.0;
    scan.coeff[SPHTimestep::THERMAL] = COEFF_THERMAL;
    scan.groupbit = heated;
    scan.materials = nullptr;
    scan.relax_rate = relax;
    scan.body_force = nullptr;
    SPHTimestep::local_limits(lmp, scan, BIG, thermal, bad);
    local[SPHTimestep::THERMAL] = thermal[SPHTimestep::THERMAL];
  }
  // a limit that is not a number is left to the pair styles' own checks
  MPI_Allreduce(local, limit, SPHTimestep::NLIMITS, MPI_DOUBLE, MPI_MIN, world);
  if (comm->me != 0) return;

  // the formulas without and with the unit factor of fix sph (s = 1 or not)
  static const char *const formula[2][SPHTimestep::NLIMITS] = {
      {"{} h / (c + |v|), Ng et al. 2020, eq 18", "{} sqrt(h m / |f|), Ng et al. 2020, eq 18",
       "{} h^2 rho / mu, Ng et al. 2020, eq 18",
       "{} / lambda, lambda the rate at which the pair relaxes T towards the neighbours'"},
      {"{} h / (ftm2v c + |v|), Ng et al. 2020, eq 18",
       "{} sqrt(h m / (ftm2v |f|)), Ng et al. 2020, eq 18",
       "{} h^2 rho / (ftm2v mu), Ng et al. 2020, eq 18",
       "{} / (ftm2v lambda), lambda the rate at which the pair relaxes T towards the "
       "neighbours'"}};
  const double s = force->ftm2v;
  const int scaled = (s != 1.0);
  const std::string units = (s == 1.0) ? std::string(update->unit_style)
                                       : fmt::format("{}, ftm2v = {:.6g}", update->unit_style, s);
  static const double coeffs[SPHTimestep::NLIMITS] = {COEFF_ACOUSTIC, COEFF_FORCE, COEFF_VISCOUS,
                                                      COEFF_THERMAL};
  const double dt = update->dt;
  for (int k = 0; k < SPHTimestep::NLIMITS; k++) {
    if (!(dt > limit[k]) || dt == warned_dt[k]) continue;
    warned_dt[k] = dt;
    // the limit rounded down to 3 significant digits
    const double unit = pow(10.0, floor(log10(limit[k])) - 2.0);
    const double suggest = floor(limit[k] / unit) * unit;
    error->warning(FLERR,
                   "Pair style {}: timestep {} is {:.3g} times its {} limit {:.6g} ({}; h = {}, "
                   "units {}) at the setup of the run: use a timestep of at most {:.3g} or fix "
                   "sph/dt/reset",
                   k == SPHTimestep::THERMAL ? "sph/cleary/heat" : "sph/harmonic/visc", dt,
                   dt / limit[k], SPHTimestep::name(k), limit[k],
                   fmt::format(formula[scaled][k], coeffs[k]), h, units, suggest);
  }
}

/* ----------------------------------------------------------------------
   weak compressibility: the density error grows as (|v| / c)^2, so the
   speed of sound should be 10 times the largest speed (of the particles
   with an equation of state; c as integrated, s c of sph_timestep.h)
------------------------------------------------------------------------- */

void FixSPHTimestepCheck::check_sound_speed()
{
  SPHHub hub(lmp);
  if (warned_sound || !hub.flow()) return;
  if (hub.fixes<FixSPHMaterials>().size() != 1) return;
  const FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Pair style sph/harmonic/visc");
  const double s = force->ftm2v;
  const double *const *const v = atom->v;
  // local: the largest speed, minus the smallest speed of sound (and its type)
  double local[2] = {0.0, -BIG}, global[2];
  int slow_type = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    const sphe_eos *eos = materials->eos(atom->type[i]);
    if (!eos) continue;
    const double speed = sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    const double c = SPHTimestep::signal_speed(sphe_sound_speed(eos, atom->rho[i]), 0.0, s);
    if (speed > local[0]) local[0] = speed;
    if (-c > local[1]) {
      local[1] = -c;
      slow_type = atom->type[i];
    }
  }
  MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, world);
  const double vmax = global[0], cmin = -global[1];
  // (the type of the slowest sound: from a rank that has it)
  int type_global = 0;
  const int mine = (-local[1] == cmin) ? slow_type : 0;
  MPI_Allreduce(&mine, &type_global, 1, MPI_INT, MPI_MAX, world);
  if (!(vmax > 0.0) || !(cmin < SOUND_SPEED_RATIO * vmax * (1.0 - 1.0e-9))) return;
  warned_sound = 1;
  if (comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/harmonic/visc: the speed of sound {}{} (atom type {}) is only "
                   "{:.3g} times the largest speed {} at the setup of the run; the density error "
                   "of weakly compressible SPH grows as (v / c)^2: give the equation of state of "
                   "fix sph/materials a c0 of at least {} times the largest speed expected",
                   cmin,
                   s == 1.0 ? std::string()
                            : fmt::format(" (units {}: ftm2v = {} times the equation of state's c)",
                                          update->unit_style, s),
                   type_global, cmin / vmax, vmax, SOUND_SPEED_RATIO);
}
