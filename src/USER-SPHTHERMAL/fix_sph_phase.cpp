/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/phase: melting and solidification by the enthalpy method. The
   types that change phase get a latent heat and a solidus and liquidus
   temperature; their particles keep integrating esph, which then includes
   the latent heat (sph_phase_laws.h), and every style reads their
   temperature through SPHParticles, which finds the laws in per-atom
   vectors that this fix keeps.
------------------------------------------------------------------------- */

#include "fix_sph_phase.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_boussinesq.h"
#include "fix_sph_flowrate.h"
#include "fix_sph_grains.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/phase";
// the internal fix property/atom that holds the per-atom vectors
static const char VECTOR_FIX[] = "SPH_PHASE_LAWS";

// whether a fix changes the atoms' forces after the pair styles: LAMMPS's
// fixes with post_force, and the package's that add forces there (buoyancy,
// drive, grains); its others there tally or hold the walls' states
static bool adds_forces_after_pair(const Fix *fix, int mask)
{
  if (!(mask & POST_FORCE)) return false;
  return !SPHHub::ours(fix) || dynamic_cast<const FixSPHBoussinesq *>(fix) ||
      dynamic_cast<const FixSPHFlowRate *>(fix) || dynamic_cast<const FixSPHGrains *>(fix);
}

/* ----------------------------------------------------------------------
   fix ID group sph/phase type I melting Tm latent L [cv_liquid cl] [mushy C]
                          type I solidus Ts liquidus Tl latent L [cv_liquid cl] [mushy C] ...
                          [epsilon e]
------------------------------------------------------------------------- */

FixSPHPhase::FixSPHPhase(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), mushy_eps(1.0e-3), damps(0), order_warned(0), vectors_made(0), nmax(0),
    fraction(nullptr), totals{0.0, 0.0}, totals_current(0)
{
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "{} requires atom style sph (esph, cv)", cmd);
  if (atom->smd_flag)
    error->all(FLERR, "{}: MACHDYN solids (atom style smd) cannot change phase yet", cmd);
  if (narg < 4) error->all(FLERR, "Illegal {} command: expected 'type I ...' after the style", cmd);

  const int ntypes = atom->ntypes;
  laws.assign(ntypes + 1, SPHPhaseLaw{0.0, 0.0, 0.0, 0.0});
  changes.assign(ntypes + 1, 0);
  mushy.assign(ntypes + 1, 0.0);
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "epsilon") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'epsilon'", cmd);
      mushy_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(mushy_eps > 0.0))
        error->all(FLERR, "Illegal {} command: epsilon {} must be > 0", cmd, arg[iarg + 1]);
      iarg += 2;
    } else
      parse_type(narg, arg, iarg);
  }
  for (int t = 1; t <= ntypes; t++) damps |= (mushy[t] > 0.0);

  peratom_flag = 1;    // the liquid fraction
  size_peratom_cols = 0;
  peratom_freq = 1;
  vector_flag = 1;    // the group's liquid mass fraction, the latent heat it holds
  size_vector = 2;
  extvector = -1;
  extlist = new int[2]{0, 1};
  global_freq = 1;
  nevery = 1;
  FixSPHPhase::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

/* ---------------------------------------------------------------------- */

FixSPHPhase::~FixSPHPhase()
{
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(fraction);
  delete[] extlist;
  // the laws go with the fix: without it the atoms are of one phase again
  if (vectors_made && modify->nfix && modify->find_fix(VECTOR_FIX) >= 0)
    modify->delete_fix(VECTOR_FIX);
}

/* ----------------------------------------------------------------------
   'type I ...' at arg[iarg]; moves iarg past it
------------------------------------------------------------------------- */

void FixSPHPhase::parse_type(int narg, char **arg, int &iarg)
{
  if (strcmp(arg[iarg], "type") != 0)
    error->all(FLERR, "Illegal {} command: unknown keyword '{}' (expected 'type I ...')", cmd,
               arg[iarg]);
  if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: missing I after 'type'", cmd);
  int ilo, ihi;
  utils::bounds(FLERR, arg[iarg + 1], 1, atom->ntypes, ilo, ihi, error);
  const std::string where = fmt::format("{} command: type {}", cmd, arg[iarg + 1]);
  iarg += 2;

  double melting = NAN, solidus = NAN, liquidus = NAN, latent = NAN, liquid_cv = NAN;
  double damping = 0.0;
  while (iarg < narg && strcmp(arg[iarg], "type") != 0 && strcmp(arg[iarg], "epsilon") != 0) {
    const char *name = arg[iarg];
    double *slot = !strcmp(name, "melting") ? &melting
        : !strcmp(name, "solidus")          ? &solidus
        : !strcmp(name, "liquidus")         ? &liquidus
        : !strcmp(name, "latent")           ? &latent
        : !strcmp(name, "mushy")            ? &damping
        : !strcmp(name, "cv_liquid")        ? &liquid_cv
                                            : nullptr;
    if (!slot)
      error->all(FLERR,
                 "Illegal {}: unknown property '{}' (melting, solidus, liquidus, latent, "
                 "cv_liquid or mushy)",
                 where, name);
    if (iarg + 1 >= narg) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    *slot = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    iarg += 2;
  }

  if (std::isnan(latent)) error->all(FLERR, "Illegal {}: no latent heat (latent L)", where);
  if (!(latent > 0.0)) error->all(FLERR, "Illegal {}: latent {} must be > 0", where, latent);
  if (!std::isnan(melting) && (!std::isnan(solidus) || !std::isnan(liquidus)))
    error->all(FLERR, "Illegal {}: give melting Tm or solidus Ts and liquidus Tl, not both", where);
  if (!std::isnan(melting)) solidus = liquidus = melting;
  if (std::isnan(solidus) || std::isnan(liquidus))
    error->all(FLERR,
               "Illegal {}: latent {} without its melting temperature (melting Tm, or solidus "
               "Ts and liquidus Tl)",
               where, latent);
  if (liquidus < solidus)
    error->all(FLERR, "Illegal {}: liquidus {} is below solidus {}", where, liquidus, solidus);
  if (!(damping >= 0.0)) error->all(FLERR, "Illegal {}: mushy {} must be >= 0", where, damping);
  if (!std::isnan(liquid_cv) && !(liquid_cv > 0.0 && std::isfinite(liquid_cv)))
    error->all(FLERR, "Illegal {}: cv_liquid {} must be > 0", where, liquid_cv);
  if (std::isnan(liquid_cv)) liquid_cv = 0.0;    // the law's 0: the liquid's cv is the solid's
  for (int t = ilo; t <= ihi; t++) {
    laws[t] = SPHPhaseLaw{solidus, liquidus, latent, liquid_cv};
    changes[t] = 1;
    mushy[t] = damping;
  }
}

/* ----------------------------------------------------------------------
   the per-atom vectors, held by an internal fix property/atom that moves
   them with the atoms and to the ghosts; marked at once, so that sph/set
   after this fix sets the phase-changing atoms' energy with their laws
------------------------------------------------------------------------- */

void FixSPHPhase::post_constructor()
{
  int flag, cols;
  if (atom->find_custom(SPHParticles::PHASE_LATENT_VECTOR, flag, cols) < 0) {
    modify->add_fix(
        fmt::format("{} all property/atom d_{} d_{} d_{} d_{} ghost yes", VECTOR_FIX,
                    SPHParticles::PHASE_SOLIDUS_VECTOR, SPHParticles::PHASE_LIQUIDUS_VECTOR,
                    SPHParticles::PHASE_LATENT_VECTOR, SPHParticles::PHASE_LIQUID_CV_VECTOR));
    vectors_made = 1;
  }
  mark();
}

/* ---------------------------------------------------------------------- */

int FixSPHPhase::setmask()
{
  return POST_NEIGHBOR | END_OF_STEP | (damps ? POST_FORCE : 0);
}

/* ---------------------------------------------------------------------- */

void FixSPHPhase::init()
{
  if (SPHHub(lmp).fixes<FixSPHPhase>().size() > 1)
    error->all(FLERR, "{}: only one fix sph/phase may be defined", cmd);
  mark();
  // the damping must see every force: one added by a fix after it would
  // move the solid
  if (damps && !order_warned) {
    order_warned = 1;
    for (int i = modify->find_fix(id) + 1; i < modify->nfix; i++)
      if (adds_forces_after_pair(modify->fix[i], modify->fmask[i]) && comm->me == 0)
        error->warning(FLERR,
                       "{} {}: fix {} (style {}) is defined after it and acts after the forces: "
                       "its force on solid and mushy atoms is not damped (define fix {} after it)",
                       cmd, id, modify->fix[i]->id, modify->fix[i]->style, id);
  }
}

/* ----------------------------------------------------------------------
   'mushy C': the solid part of a melting fluid stops. A mushy atom's
   velocity is damped by the Carman-Kozeny term of the enthalpy-porosity
   method (Voller and Prakash 1987; Brent, Voller and Reid 1988), per mass
   A = C (1 - f)^2 / ((f^3 + epsilon) rho), implicitly: fix sph moves the
   velocity between two steps' half steps by dt f / m with the force left
   here, and f = (F - m A v) / (1 + dt A) makes that move backward Euler's,
   v' = (v + dt F / m) / (1 + dt A): a decay by 1 / (1 + dt A) per step,
   stable and monotonic whatever A dt, and the terminal velocity F / (m A)
   under a steady force F. A solid atom (f = 0) is held: no velocity and
   no force, so it does not move.
------------------------------------------------------------------------- */

void FixSPHPhase::post_force(int /*vflag*/)
{
  const SPHParticles particles(atom);
  double **const v = atom->v;
  double **const f = atom->f;
  double **const vest = atom->vest;
  const double *const rho = atom->rho;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const double dt = update->dt, ftm2v = force->ftm2v;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || mushy[type[i]] <= 0.0) continue;
    const double liquid = particles.liquid_fraction(i);
    if (liquid <= 0.0) {
      for (int a = 0; a < 3; a++) v[i][a] = vest[i][a] = f[i][a] = 0.0;
      continue;
    }
    const double solid = 1.0 - liquid;
    const double rate =
        mushy[type[i]] * solid * solid / ((liquid * liquid * liquid + mushy_eps) * rho[i]);
    if (rate <= 0.0) continue;
    const double m_rate = particles.mass(i) * rate / ftm2v;    // force per velocity
    for (int a = 0; a < 3; a++) f[i][a] = (f[i][a] - m_rate * v[i][a]) / (1.0 + dt * rate);
  }
}

/* ----------------------------------------------------------------------
   the laws follow the atom types: owned and ghost atoms alike, also those
   made since the last marking (fix sph/open, deposit)
------------------------------------------------------------------------- */

void FixSPHPhase::mark()
{
  int flag, cols;
  const int isolidus = atom->find_custom(SPHParticles::PHASE_SOLIDUS_VECTOR, flag, cols);
  const int iliquidus = atom->find_custom(SPHParticles::PHASE_LIQUIDUS_VECTOR, flag, cols);
  const int ilatent = atom->find_custom(SPHParticles::PHASE_LATENT_VECTOR, flag, cols);
  const int iliquid_cv = atom->find_custom(SPHParticles::PHASE_LIQUID_CV_VECTOR, flag, cols);
  if (isolidus < 0 || iliquidus < 0 || ilatent < 0 || iliquid_cv < 0) return;
  double *const solidus = atom->dvector[isolidus];
  double *const liquidus = atom->dvector[iliquidus];
  double *const latent = atom->dvector[ilatent];
  double *const liquid_cv = atom->dvector[iliquid_cv];
  const int *const type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) {
    const SPHPhaseLaw &law = laws[type[i]];
    solidus[i] = law.solidus;
    liquidus[i] = law.liquidus;
    latent[i] = law.latent;    // 0: the type does not change phase
    liquid_cv[i] = law.liquid_cv;
  }
}

void FixSPHPhase::setup_post_neighbor()
{
  mark();
}

void FixSPHPhase::post_neighbor()
{
  mark();
}

/* ---------------------------------------------------------------------- */

void FixSPHPhase::setup(int vflag)
{
  // the forces of the run's first step are damped too
  if (damps) post_force(vflag);
  update_fraction();
}

void FixSPHPhase::end_of_step()
{
  update_fraction();
}

/* ----------------------------------------------------------------------
   the liquid fraction of every owned atom; the group's totals on demand
------------------------------------------------------------------------- */

void FixSPHPhase::update_fraction()
{
  if (atom->nmax > nmax) grow_arrays(atom->nmax);
  const SPHParticles particles(atom);
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) fraction[i] = particles.liquid_fraction(i);
  totals_current = 0;
}

double FixSPHPhase::compute_vector(int n)
{
  if (!totals_current) {
    const SPHParticles particles(atom);
    const int *const mask = atom->mask;
    const int *const type = atom->type;
    double local[3] = {0.0, 0.0, 0.0};    // liquid mass, mass of phase-changing types, latent
    for (int i = 0; i < atom->nlocal; i++) {
      if (!(mask[i] & groupbit) || !changes[type[i]]) continue;
      const double m = particles.mass(i), f = particles.liquid_fraction(i);
      local[0] += m * f;
      local[1] += m;
      local[2] += m * f * laws[type[i]].latent;
    }
    double all[3];
    MPI_Allreduce(local, all, 3, MPI_DOUBLE, MPI_SUM, world);
    totals[0] = all[1] > 0.0 ? all[0] / all[1] : 0.0;
    totals[1] = all[2];
    totals_current = 1;
  }
  return totals[n];
}

/* ---------------------------------------------------------------------- */

void FixSPHPhase::grow_arrays(int n)
{
  memory->grow(fraction, n, "sph/phase:fraction");
  vector_atom = fraction;
  nmax = n;
}

double FixSPHPhase::memory_usage()
{
  return (double) nmax * sizeof(double);
}
