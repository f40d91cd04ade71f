/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/dt/reset: adaptive timestep of weakly compressible, thermal SPH,
   the minimum over the particles of the group of four limits
     acoustic  C_c h / (s c_i + |v_i|)      (Cleary eq 5, Ng eq 18, Reece eq 21)
     force     C_f sqrt(h / |a_i|)           (Ng eq 18, Reece eq 20)
     viscous   C_v h^2 rho_i / (s mu_i)      (Ng eq 18, Reece eq 22)
     thermal   C_t / (s lambda_i)            (Cleary eq 7, Ng eq 18, Reece eqs 23-25)
   clamped to [dtmin, dtmax], with a_i = s f_i / m_i and s = force->ftm2v,
   the factor fix sph integrates every rate with (the formulas and why:
   sph_timestep.h). lambda_i is the rate at which pair
   sph/cleary/heat relaxes T_i towards its neighbours, with the conductance
   the pair uses (either mean, any kernel, material ratio and disorder):
   the explicit update of T is then a convex combination of the old
   temperatures for C_t <= 1, so it is stable and overshoots nowhere.
   dt is set at the setup of every run and then every N steps at the end
   of the step, the way fix dt/reset does it, so
   that the elapsed time (thermo keyword time) stays the sum of the steps.
   With 'until T' the last one or two steps are shortened so that the
   elapsed time lands on T, and the run stops there (as fix halt's
   'error continue' does), so that a run with an adaptive dt can end at a
   time.
   Cleary: Cleary 1998; Ng: Ng et al. 2020; Reece: Reece et al. 2024
   (doc/src/Bibliography_sphthermal.rst).
------------------------------------------------------------------------- */

#include "fix_sph_dt_reset.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "group.h"
#include "integrate.h"
#include "modify.h"
#include "output.h"
#include "pair_sph_cleary_heat.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_eos.h"
#include "sph_hub.h"
#include "sph_kernels.h"
#include "sph_material_laws.h"
#include "sph_particle.h"
#include "sph_timestep.h"
#include "timer.h"
#include "update.h"

#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 1;

static const char cmd[] = "fix sph/dt/reset";

static const char *limit_name(int active)
{
  static const char *const names[] = {"no", "acoustic", "force", "viscous", "thermal", "bound"};
  return names[active];
}

// "no limit": larger than any timestep, finite so that thermo can print it
static constexpr double BIG = 1.0e300;

/* ---------------------------------------------------------------------- */

FixSPHDtReset::FixSPHDtReset(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), dtmin(0.0), dtmax(BIG), h_user(0.0), h(0.0), until(-1.0), active(0),
    respa_flag(0), warned(0), bound_warned(0), halted(0), materials(nullptr), heat(nullptr),
    body_force(nullptr)
{
  if (!atom->rho_flag || !atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/dt/reset requires atom style sph (rho, esph, cv)");
  if (narg < 4)
    error->all(FLERR, "Illegal {} command: missing N (recompute the timestep every N steps)", cmd);
  char *end = nullptr;
  const long n = strtol(arg[3], &end, 10);
  if (end == arg[3] || *end != '\0' || n <= 0 || n > MAXSMALLINT)
    error->all(FLERR, "Illegal {} command: N must be a positive integer, not '{}'", cmd, arg[3]);
  // the fix acts at every step's end (the end time is checked there) and
  // chooses dt every N steps
  reset_every = (int) n;
  nevery = 1;

  // defaults: the acoustic one stable for the package's flows under
  // gravity, Ng et al. 2020, eq 18, for the force and viscous limits, the thermal
  // one half the limit that is sure to be stable (see the doc)
  // acoustic, force, viscous, thermal
  static constexpr double defaults[NLIMITS] = {0.1, 0.25, 0.125, 0.5};
  for (int k = 0; k < NLIMITS; k++) coeff[k] = defaults[k];

  static const char *const names[NLIMITS] = {"acoustic", "force", "viscous", "thermal"};
  double start_time = -1.0;    // 'time': < 0, the time is kept
  int iarg = 4;
  while (iarg < narg) {
    int which = -1;
    for (int k = 0; k < NLIMITS; k++)
      if (strcmp(arg[iarg], names[k]) == 0) which = k;
    if (which >= 0)
      coeff[which] = parse_value(iarg, narg, arg, true);
    else if (strcmp(arg[iarg], "min") == 0)
      dtmin = parse_value(iarg, narg, arg, true);
    else if (strcmp(arg[iarg], "max") == 0)
      dtmax = parse_value(iarg, narg, arg, false);
    else if (strcmp(arg[iarg], "h") == 0)
      h_user = parse_value(iarg, narg, arg, false);
    else if (strcmp(arg[iarg], "until") == 0)
      until = parse_value(iarg, narg, arg, false);
    else if (strcmp(arg[iarg], "time") == 0)
      start_time = parse_value(iarg, narg, arg, true);
    else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
    iarg += 2;
  }
  // the acoustic, force and viscous coefficients are fractions of their
  // limit: past 1 no explicit step is stable (a typo, most likely)
  for (int k : {ACOUSTIC, FORCE, VISCOUS})
    if (coeff[k] > 1.0 && comm->me == 0)
      error->warning(FLERR,
                     "Fix sph/dt/reset: {} {} is above 1, past the stable step of the explicit "
                     "update (the default is {})",
                     names[k], coeff[k], defaults[k]);
  if (coeff[THERMAL] > 1.0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/dt/reset: thermal {} is above 1, where the explicit conduction update "
                   "is no longer sure to be stable",
                   coeff[THERMAL]);
  if (dtmin > dtmax)
    error->all(FLERR, "Illegal {} command: min {} is larger than max {}", cmd, dtmin, dtmax);
  if (coeff[ACOUSTIC] == 0.0 && coeff[FORCE] == 0.0 && coeff[VISCOUS] == 0.0 &&
      coeff[THERMAL] == 0.0 && dtmax == BIG)
    error->all(FLERR, "Illegal {} command: every limit is off (0) and no 'max' is given", cmd);

  for (int k = 0; k < NLIMITS; k++) limit[k] = BIG;

  // a restart file written during a run (the 'restart' command) holds the
  // time of that run's start, and the next run's init drops the steps since
  // (Integrate::init sets atimestep): bring the time up to date with the dt
  // that made those steps, as the 'timestep' command does; a no-op after a
  // run, and a restart file of this fix sets its own time below
  update->update_time();
  // 'time': the elapsed time from here on (reset_timestep's own 'time'
  // keyword is missing from LAMMPS 29Sep2021, whose reset_timestep keeps it)
  if (start_time >= 0.0) {
    update->atime = start_time;
    update->atimestep = update->ntimestep;
  }

  // the elapsed time depends on every dt: keep it across restarts, and
  // forbid reset_timestep while the fix exists (as fix dt/reset does)
  time_depend = 1;
  restart_global = 1;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 2 + NLIMITS;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
  dynamic_group_allow = 1;
}

/* ----------------------------------------------------------------------
   value of keyword arg[iarg]: a number >= 0 (zero_ok) or > 0
------------------------------------------------------------------------- */

double FixSPHDtReset::parse_value(int iarg, int narg, char **arg, bool zero_ok)
{
  if (iarg + 1 >= narg)
    error->all(FLERR, "Illegal {} command: missing value after '{}'", cmd, arg[iarg]);
  const char *word = arg[iarg + 1];
  char *end = nullptr;
  const double value = strtod(word, &end);
  if (end == word || *end != '\0' || !std::isfinite(value))
    error->all(FLERR, "Illegal {} command: {} value '{}' is not a number", cmd, arg[iarg], word);
  if (value < 0.0 || (!zero_ok && value == 0.0))
    error->all(FLERR, "Illegal {} command: {} {} must be {}", cmd, arg[iarg], word,
               zero_ok ? ">= 0" : "> 0");
  return value;
}

/* ---------------------------------------------------------------------- */

int FixSPHDtReset::setmask()
{
  return PRE_FORCE | END_OF_STEP | POST_RUN;
}

// the relaxation rates in the force computations before choose_dt() only
void FixSPHDtReset::setup_pre_force(int /*vflag*/)
{
  if (heat) heat->want_relax_rates(true);
}

void FixSPHDtReset::pre_force(int /*vflag*/)
{
  if (heat) heat->want_relax_rates(update->ntimestep % reset_every == 0);
}

/* ---------------------------------------------------------------------- */

void FixSPHDtReset::init()
{
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "Fix sph/dt/reset {}: group {} has no atoms, so no limit to take dt from",
               id, group->names[igroup]);

  // two fixes changing dt would overwrite each other's choice
  if (Fix *other = SPHHub(lmp).timestep_resetter(this))
    error->all(FLERR, "Fix sph/dt/reset: fix {} (style {}) also resets the timestep", other->id,
               other->style);

  // setup() runs in the order of the fixes: a fix defined later that adds
  // forces after the pair (addforce, gravity, ...) has not done so yet when
  // the first dt is chosen
  if (coeff[FORCE] > 0.0 && !warned) {
    warned = 1;
    const int me_index = modify->find_fix(id);
    int dim;
    for (int i = me_index + 1; i < modify->nfix; i++)
      // the body force counts by itself (below); this package's fixes
      // acting then tally or hold energies, not forces
      if ((modify->fmask[i] & POST_FORCE) && !modify->fix[i]->extract("gvec", dim) &&
          !SPHHub::ours(modify->fix[i]) && comm->me == 0)
        error->warning(FLERR,
                       "Fix sph/dt/reset: fix {} (style {}) is defined after it and acts after "
                       "the forces; if it changes forces, define fix sph/dt/reset after it so "
                       "that the first dt sees them",
                       modify->fix[i]->id, modify->fix[i]->style);
  }

  h = smoothing_length();
  body_force = SPHBodyForce::find(lmp, "Fix sph/dt/reset");

  // the hub is needed only by the limits that read material properties
  materials = nullptr;
  if (coeff[ACOUSTIC] > 0.0 || coeff[VISCOUS] > 0.0)
    materials = FixSPHMaterials::find(lmp, "Fix sph/dt/reset");

  // the thermal limit is the conduction pair's own relaxation rate
  heat = (coeff[THERMAL] > 0.0) ? SPHHub(lmp).heat() : nullptr;
  bound_warned = 0;

  respa_flag = utils::strmatch(update->integrate_style, "^respa") ? 1 : 0;
}

/* ----------------------------------------------------------------------
   h from the 'h' keyword, else cutoff / q_max of the package's SPH pair
   styles (the smallest when there are several, e.g. in hybrid/overlay)
------------------------------------------------------------------------- */

double FixSPHDtReset::smoothing_length()
{
  if (h_user > 0.0) return h_user;
  const double hmin = SPHTimestep::smoothing_length(lmp);
  if (hmin <= 0.0)
    error->all(FLERR,
               "Fix sph/dt/reset: no smoothing length: give keyword 'h' or use pair style "
               "sph/harmonic/visc or sph/cleary/heat");
  return hmin;
}

/* ----------------------------------------------------------------------
   before the first step of every run: the forces of the initial state are
   known, the first step must already use the limited dt
------------------------------------------------------------------------- */

void FixSPHDtReset::setup(int /*vflag*/)
{
  choose_dt();
  if (until < 0.0) return;
  if (end_at_until(true) && update->nsteps > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/dt/reset {}: the elapsed time {} is already at until {}: the run of {} "
                   "steps stops before its first step",
                   id, elapsed_time(), until, update->nsteps);
}

void FixSPHDtReset::end_of_step()
{
  if (update->ntimestep % reset_every == 0) choose_dt();
  if (until >= 0.0) end_at_until(false);
}

// said after the run, below the last step's thermo row (a log parser reads
// the table through to it); a run stopped at 'until' must not stop the next
void FixSPHDtReset::post_run()
{
  if (halted) {
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "Fix sph/dt/reset {}: the elapsed time reached until {} at step {}: the run "
                     "stopped\n",
                     id, until, update->ntimestep);
    timer->reset_timeout();
  }
  halted = 0;
}

/* ---------------------------------------------------------------------- */

double FixSPHDtReset::elapsed_time() const
{
  return update->atime + (double) (update->ntimestep - update->atimestep) * update->dt;
}

/* ----------------------------------------------------------------------
   'until': stop the run once the elapsed time has reached it (to
   round-off), else shorten dt when at most two steps are left: the last
   step lands on it, two steps share what is left rather than the second
   being a sliver. Returns 1 when the run stops. The last step gets a
   thermo row of its own, as the last step of a run of fixed length does:
   it is scheduled at the step before, since computes that tally energy
   must know before their step begins; at setup, where Output::setup comes
   after and would undo it, one step left becomes two.
------------------------------------------------------------------------- */

int FixSPHDtReset::end_at_until(bool at_setup)
{
  const double left = until - elapsed_time();
  if (left <= 1.0e-9 * until) {
    halted = 1;
    timer->force_timeout();
    return 1;
  }
  // after a halving, 'left' is the halved dt up to round-off: land on it
  if (left <= update->dt * (1.0 + 1.0e-9) && !at_setup) {
    set_dt(left);
    const bigint last = update->ntimestep + 1;
    if (output->next_thermo > last) {
      output->next_thermo = last;
      output->next = MIN(output->next, last);
    }
    modify->addstep_compute(last);
  } else if (left < 2.0 * update->dt)
    set_dt(0.5 * left);
  return 0;
}

/* ----------------------------------------------------------------------
   the four limits over the group, their global minima, the new dt
------------------------------------------------------------------------- */

void FixSPHDtReset::choose_dt()
{
  double local[NLIMITS];
  int bad[NLIMITS];
  SPHTimestep::Scan scan;
  for (int k = 0; k < NLIMITS; k++) scan.coeff[k] = coeff[k];
  scan.h = h;
  scan.groupbit = groupbit;
  scan.materials = materials;
  scan.relax_rate = heat ? heat->relax_rates() : nullptr;
  scan.body_force = (coeff[FORCE] > 0.0) ? body_force : nullptr;
  scan.who = "Fix sph/dt/reset";
  SPHTimestep::local_limits(lmp, scan, BIG, local, bad);
  for (int k = 0; k < NLIMITS; k++)
    if (bad[k]) bad_limit(k);

  // minima are exact, so every rank count that gives the same per-atom
  // state gives the same dt and the same active limit
  MPI_Allreduce(local, limit, NLIMITS, MPI_DOUBLE, MPI_MIN, world);

  double dt = BIG;
  active = 0;
  for (int k = 0; k < NLIMITS; k++)
    if (limit[k] < dt) {
      dt = limit[k];
      active = k + 1;
    }
  if (active == 0) {
    // no limit applies (e.g. only the force limit, and no force): keep dt
    // unless a maximum is given
    if (dtmax < BIG) {
      dt = dtmax;
      active = BOUND;
    } else
      dt = update->dt;
  }
  if (dt < dtmin) {
    if (!bound_warned && comm->me == 0)
      error->warning(FLERR,
                     "Fix sph/dt/reset: min {} overrides the {} limit {} (ratio {:.3g}) at step {}: "
                     "the run may be unstable",
                     dtmin, limit_name(active), dt, dtmin / dt, update->ntimestep);
    bound_warned = 1;
    dt = dtmin;
    active = BOUND;
  } else if (dt > dtmax) {
    dt = dtmax;
    active = BOUND;
  }

  set_dt(dt);
}

/* ---------------------------------------------------------------------- */

void FixSPHDtReset::set_dt(double dt)
{
  if (dt == update->dt) return;

  // as fix dt/reset: account the elapsed time with the old dt first
  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  if (respa_flag) update->integrate->reset_dt();
  if (force->pair) force->pair->reset_dt();
  for (int i = 0; i < modify->nfix; i++) modify->fix[i]->reset_dt();
}

/* ----------------------------------------------------------------------
   a limit of some owned atom is 0 or not a number: name the atom and what
   its limit reads (the first such atom; on this rank)
------------------------------------------------------------------------- */

void FixSPHDtReset::bad_limit(int k)
{
  const SPHParticles particles(atom);
  const double *const *const v = atom->v;
  const double *const *const f = atom->f;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int itype = atom->type[i];
    double dt = BIG;
    std::string state;
    if (k == ACOUSTIC && materials->eos(itype)) {
      const double speed = sqrt(v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
      dt = SPHTimestep::acoustic(
          coeff[k], h,
          SPHTimestep::signal_speed(sphe_sound_speed(materials->eos(itype), atom->rho[i]), speed,
                                    force->ftm2v));
      state = fmt::format("rho = {}, |v| = {}", atom->rho[i], speed);
    } else if (k == FORCE) {
      const double m = particles.mass(i);
      const double fsq = f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2];
      if (fsq > 0.0 || !std::isfinite(fsq))
        dt = SPHTimestep::force(coeff[k], h, SPHTimestep::acceleration(sqrt(fsq), m, force->ftm2v));
      state = fmt::format("|f| = {}, mass = {}", sqrt(fsq), m);
    } else if (k == VISCOUS && materials->viscosity(itype)) {
      const double T = particles.temperature(i);
      const double mu = sphm_law_eval(materials->viscosity(itype), T);
      if (mu > 0.0 || !std::isfinite(mu))
        dt = SPHTimestep::viscous(coeff[k], h, atom->rho[i], mu, force->ftm2v);
      state = fmt::format("rho = {}, viscosity = {} at T = {}", atom->rho[i], mu, T);
    } else if (k == THERMAL && heat && heat->relax_rates()) {
      const double rate = heat->relax_rates()[i];
      dt = SPHTimestep::thermal(coeff[k], SPHTimestep::relaxation(rate, force->ftm2v));
      state = fmt::format("relaxation rate = {}, rho = {}, cv = {}", rate,
                          atom->rho[i], atom->cv[i]);
    }
    if (!(dt > 0.0))
      SPHCheck::stop(lmp, FLERR, fmt::format("Fix sph/dt/reset: {} limit of atom {} (type {}) is {} at step {} "
                                 "({})",
                                 limit_name(k + 1), atom->tag[i], itype, dt, update->ntimestep,
                                 state));
  }
}

/* ---------------------------------------------------------------------- */

double FixSPHDtReset::compute_scalar()
{
  return update->dt;
}

/* ----------------------------------------------------------------------
   1 = dt, 2 = active limit, 3..6 = acoustic, force, viscous, thermal
------------------------------------------------------------------------- */

double FixSPHDtReset::compute_vector(int n)
{
  if (n == 0) return update->dt;
  if (n == 1) return (double) active;
  return limit[n - 2];
}

/* ----------------------------------------------------------------------
   LAMMPS 29Sep2021 writes ntimestep and dt to a restart file but not the
   elapsed time, which read_restart then starts at 0; with a variable dt it
   cannot be recomputed as step * dt, so the fix keeps it (and the dt of
   that moment, for information: the next run's setup recomputes dt).
   LAMMPS 4Feb2025 keeps it too (atime, atimestep); both agree
------------------------------------------------------------------------- */

void FixSPHDtReset::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const double list[2] = {elapsed_time(), update->dt};
    SPHCheck::write_restart_state(fp, RESTART_VERSION, list, 2);
  }
}

void FixSPHDtReset::restart(char *buf)
{
  const double *list = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  update->atime = list[0];
  update->atimestep = update->ntimestep;
}
