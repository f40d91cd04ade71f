/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/surface/flux: a prescribed heat flux into a group of surface
   particles (Xu, LS-DYNA conference paper), or a convective one,
   q = h (T_inf - T).
------------------------------------------------------------------------- */

#include "fix_sph_surface_flux.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_adiabatic.h"
#include "fix_sph_wall_dirichlet.h"
#include "force.h"
#include "sph_checks.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 1;

/* ---------------------------------------------------------------------- */

FixSPHSurfaceFlux::FixSPHSurfaceFlux(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), convective(0), q_given(0.0), h_transfer(0.0), t_ambient(0.0), area(0.0),
    spacing(0.0), dt_half(0.0), rate_previous(0.0), energy(0.0), materials(nullptr)
{
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/surface/flux requires atom style sph (esph, desph, cv)");
  if (narg < 4)
    error->all(
        FLERR,
        "Illegal fix sph/surface/flux command: expected 'flux <q>' or 'convection <h> <T_inf>'");

  int iarg = 3;
  if (strcmp(arg[iarg], "flux") == 0) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal fix sph/surface/flux command: missing value after 'flux'");
    q_given = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    iarg += 2;
  } else if (strcmp(arg[iarg], "convection") == 0) {
    if (iarg + 2 >= narg)
      error->all(FLERR, "Illegal fix sph/surface/flux command: 'convection' needs <h> <T_inf>");
    convective = 1;
    h_transfer = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    t_ambient = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
    if (h_transfer < 0.0)
      error->all(FLERR,
                 "Illegal fix sph/surface/flux command: heat transfer coefficient {} must be >= 0",
                 arg[iarg + 1]);
    iarg += 3;
  } else
    error->all(FLERR,
               "Illegal fix sph/surface/flux command: unknown keyword '{}' (flux or convection)",
               arg[iarg]);

  while (iarg < narg) {
    if (strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal fix sph/surface/flux command: missing value after 'spacing'");
      spacing = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (spacing <= 0.0)
        error->all(FLERR, "Illegal fix sph/surface/flux command: spacing {} must be > 0",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal fix sph/surface/flux command: unknown keyword '{}'", arg[iarg]);
  }
  if (spacing <= 0.0)
    error->all(FLERR,
               "Illegal fix sph/surface/flux command: 'spacing <dx>' is required (the surface area "
               "of a particle is dx^(d-1))");

  scalar_flag = 1;
  extscalar = 1;
  global_freq = 1;
  restart_global = 1;
}

/* ---------------------------------------------------------------------- */

int FixSPHSurfaceFlux::setmask()
{
  return PRE_FORCE;
}

/* ----------------------------------------------------------------------
   the half-step weight of fix sph and fix sph/stationary (with ftm2v as they
   have it), renewed when a timestep fix changes dt
------------------------------------------------------------------------- */

void FixSPHSurfaceFlux::reset_dt()
{
  dt_half = 0.5 * update->dt * force->ftm2v;
}

void FixSPHSurfaceFlux::init()
{
  SPHCheck::group_of_kind(lmp, FLERR, this,
                          SPHHub(lmp).fixes_of_any<FixSPHWallDirichlet, FixSPHWallAdiabatic>(),
                          true, true);
  SPHCheck::atom_state(lmp, FLERR, "Fix sph/surface/flux", groupbit, SPHCheck::CV | SPHCheck::ESPH);
  reset_dt();
  area = pow(spacing, domain->dimension - 1);
  // (MACHDYN solids exist only with fix sph/materials, which hears of their heat)
  const std::vector<FixSPHMaterials *> hubs = SPHHub(lmp).fixes<FixSPHMaterials>();
  materials = hubs.empty() ? nullptr : hubs[0];
}

void FixSPHSurfaceFlux::setup_pre_force(int /*vflag*/)
{
  add_flux(1);
}

void FixSPHSurfaceFlux::pre_force(int /*vflag*/)
{
  add_flux(0);
}

/* ----------------------------------------------------------------------
   desph_i += q_i A / m_i, before the pair styles add theirs (desph is
   cleared before pre_force): a fix that acts after the forces, such as
   fix sph/wall/isothermal, sees the flux in any order of the fixes. The
   heat added is tallied with the half-step weights of fix sph and fix
   sph/stationary (see fix sph/wall/isothermal), so it equals the change
   of sum(m esph) it causes
------------------------------------------------------------------------- */

void FixSPHSurfaceFlux::add_flux(int first)
{
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const desph = atom->desph;

  // [0] into particles integrated as by fix sph (half steps), [1] into
  // MACHDYN solids, whose fix smd/integrate_tlsph applies a step's rate
  // once, for the whole step
  double rate_local[2] = {0.0, 0.0};
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double q = convective ? h_transfer * (t_ambient - particles.temperature(i)) : q_given;
    const double rate = q * area / particles.mass(i) * particles.esph_per_specific(i);
    desph[i] += rate;
    rate_local[particles.machdyn(i) ? 1 : 0] += q * area;
    if (particles.machdyn(i) && materials) materials->note_solid_heat(i, rate);
  }
  double rate[2];
  MPI_Allreduce(rate_local, rate, 2, MPI_DOUBLE, MPI_SUM, world);
  if (!first) energy += dt_half * (rate_previous + rate[0]) + update->dt * rate[1];
  rate_previous = rate[0];
}

/* ---------------------------------------------------------------------- */

double FixSPHSurfaceFlux::compute_scalar()
{
  return energy;
}

void FixSPHSurfaceFlux::write_restart(FILE *fp)
{
  if (comm->me == 0) SPHCheck::write_restart_state(fp, RESTART_VERSION, &energy, 1);
}

void FixSPHSurfaceFlux::restart(char *buf)
{
  energy = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION)[0];
}
