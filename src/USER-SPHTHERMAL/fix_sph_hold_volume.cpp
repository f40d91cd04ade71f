/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/hold/volume: the volume sum_i m_i / rho_i of a group that fills
   a closed container stays at its value at the first run's start. The
   discrete continuity equation does not keep it where the flow meets walls
   (a convecting cell's mean density rises by about 0.6 % per diffusion
   time, with or without shifting), and the kinematic viscosity, the
   diffusivity and the Rayleigh number drift with it. After every step all
   densities of the group are scaled by one factor, V / V_held: the masses
   stay, the volume is the container's again.
------------------------------------------------------------------------- */

#include "fix_sph_hold_volume.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "group.h"
#include "sph_checks.h"
#include "sph_eos.h"
#include "sph_particle.h"

#include <cmath>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state (1: the volume held, the group's name)
static constexpr int RESTART_VERSION = 1;

static const char cmd[] = "fix sph/hold/volume";

/* ---------------------------------------------------------------------- */

FixSPHHoldVolume::FixSPHHoldVolume(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), active(1), held(0.0), volume_before(0.0)
{
  if (narg != 3)
    error->all(FLERR, "Illegal {} command: expected 'fix ID <group> {}'", cmd, cmd + 4);
  if (!atom->rho_flag) error->all(FLERR, "Fix sph/hold/volume requires atom style sph (rho)");
  scalar_flag = 1;    // the volume before the last step's correction
  extscalar = 1;
  global_freq = 1;
  restart_global = 1;
}

int FixSPHHoldVolume::setmask()
{
  return END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHHoldVolume::init()
{
  if (!active) return;
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "Fix sph/hold/volume: group {} has no atoms", group->names[igroup]);
  // a fluid whose equation of state expands with T changes its volume for a reason
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/hold/volume");
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  for (int t = 1; t <= atom->ntypes; t++) {
    const sphe_eos *eos = materials->eos(t);
    if (present[t] && eos && eos->thermal)
      error->all(FLERR,
                 "Fix sph/hold/volume: atom type {} of group {} expands with temperature in its "
                 "equation of state (eos ... thermal), so its volume is not the container's: "
                 "use fix sph/boussinesq for its buoyancy, or no fix sph/hold/volume",
                 t, group->names[igroup]);
  }
}

void FixSPHHoldVolume::setup(int /*vflag*/)
{
  if (!active || held > 0.0) return;
  held = group_volume();
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix sph/hold/volume: the volume of group {} is held at {:.10g}\n",
                   group->names[igroup], held);
}

/* ----------------------------------------------------------------------
   sum m / rho over the group; an error naming the atom whose density is
   not finite and positive
------------------------------------------------------------------------- */

double FixSPHHoldVolume::group_volume()
{
  const SPHParticles particles(atom);
  const double *const rho = atom->rho;
  const int *const mask = atom->mask;
  double local = 0.0, all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (!(rho[i] > 0.0) || !std::isfinite(rho[i]))
      SPHCheck::stop(lmp, FLERR,
                     fmt::format("Fix sph/hold/volume: rho of atom {} (type {}) is {}; it must be "
                                 "finite and > 0",
                                 atom->tag[i], atom->type[i], rho[i]));
    local += particles.mass(i) / rho[i];
  }
  MPI_Allreduce(&local, &all, 1, MPI_DOUBLE, MPI_SUM, world);
  return all;
}

void FixSPHHoldVolume::end_of_step()
{
  if (!active) return;
  volume_before = group_volume();
  const double scale = volume_before / held;
  double *const rho = atom->rho;
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) rho[i] *= scale;
}

double FixSPHHoldVolume::compute_scalar()
{
  return volume_before;
}

/* ----------------------------------------------------------------------
   the volume held carries across restarts: a fix defined again on another
   group starts from that group's volume, with a warning
------------------------------------------------------------------------- */

void FixSPHHoldVolume::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> state = {held};
  SPHCheck::pack_name(state, group->names[igroup]);
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state.data(), (int) state.size());
}

void FixSPHHoldVolume::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  int at = 1;
  const std::string name = SPHCheck::unpack_name(state, at);
  if (name == group->names[igroup]) {
    held = state[0];
    return;
  }
  if (comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/hold/volume {}: the restart file's volume ({}) is that of group {}, "
                   "the fix is now on group {}: it holds that group's volume at the next run's "
                   "start",
                   id, state[0], name, group->names[igroup]);
}
