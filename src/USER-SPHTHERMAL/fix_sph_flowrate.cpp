/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/flowrate: the flow-rate controller of a periodic channel. Every
   atom of the group gets the force m a along one axis; after every step
   the group's mean velocity U_g = sum m v / sum m is measured and, with the
   error e = U - U_g,
       I <- I + e dt / tau^2,    a = I + 2 e / tau,
   a proportional-integral controller whose closed loop for a group with
   no other force along the axis is (s + 1/tau)^2: critically damped, no
   overshoot. In a steady channel I is the drive that balances the walls'
   drag per unit mass, so e goes to 0 without a steady offset.
------------------------------------------------------------------------- */

#include "fix_sph_flowrate.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "group.h"
#include "sph_checks.h"
#include "sph_eos.h"
#include "sph_particle.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state (1: the integral part, tau)
static constexpr int RESTART_VERSION = 1;
// the default time constant in steps of the first run: slow against a step
// (the discrete loop is then the continuous one), fast against the channel's
// viscous time at any resolution that resolves it
static constexpr double DEFAULT_TAU_STEPS = 100.0;

/* ---------------------------------------------------------------------- */

FixSPHFlowRate::FixSPHFlowRate(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), axis(0), target(0.0), tau(0.0), tau_given(0), integral(0.0), accel(0.0),
    mean(0.0)
{
  if (narg < 5)
    error->all(FLERR,
               "Illegal fix sph/flowrate command: expected 'fix ID group sph/flowrate x|y|z U "
               "[relax tau]'");
  if (strcmp(arg[3], "x") == 0)
    axis = 0;
  else if (strcmp(arg[3], "y") == 0)
    axis = 1;
  else if (strcmp(arg[3], "z") == 0)
    axis = 2;
  else
    error->all(FLERR, "Fix sph/flowrate {}: direction {} must be x, y or z", id, arg[3]);
  target = utils::numeric(FLERR, arg[4], false, lmp);
  int iarg = 5;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "relax") == 0) {
      if (iarg + 2 > narg) error->all(FLERR, "Fix sph/flowrate {}: relax needs a value (tau)", id);
      tau = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(tau > 0.0) || !std::isfinite(tau))
        error->all(FLERR, "Fix sph/flowrate {}: relax {} must be a finite time > 0", id,
                   arg[iarg + 1]);
      tau_given = 1;
      iarg += 2;
    } else
      error->all(FLERR, "Fix sph/flowrate {}: unknown keyword {} (expected relax)", id, arg[iarg]);
  }
  if (axis == 2 && domain->dimension == 2)
    error->all(FLERR, "Fix sph/flowrate {}: direction z in a 2d simulation", id);
  vector_flag = 1;
  size_vector = 2;    // the acceleration, the group's mean velocity
  extvector = 0;
  global_freq = 1;
  restart_global = 1;
}

int FixSPHFlowRate::setmask()
{
  return POST_FORCE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHFlowRate::init()
{
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "Fix sph/flowrate {}: group {} has no atoms", id, group->names[igroup]);
  if (tau == 0.0) {
    tau = DEFAULT_TAU_STEPS * update->dt;
    if (comm->me == 0)
      utils::logmesg(lmp, "Fix sph/flowrate {}: relax {:.6g} ({} steps of {:.6g})\n", id, tau,
                     DEFAULT_TAU_STEPS, update->dt);
  }
}

/* ----------------------------------------------------------------------
   the group's mass-weighted mean velocity along the axis (a velocity that
   is not finite makes the next step's pair forces so, which the flow pair
   stops at, naming the atom)
------------------------------------------------------------------------- */

void FixSPHFlowRate::measure()
{
  const SPHParticles particles(atom);
  const double *const *const v = atom->v;
  const int *const mask = atom->mask;
  double local[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) {
      const double m = particles.mass(i);
      local[0] += m * v[i][axis];
      local[1] += m;
    }
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  mean = all[1] > 0.0 ? all[0] / all[1] : 0.0;
}

void FixSPHFlowRate::update_accel(double dt)
{
  const double e = target - mean;
  integral += e * dt / (tau * tau);
  accel = integral + 2.0 * e / tau;
}

/* ---------------------------------------------------------------------- */

void FixSPHFlowRate::setup(int vflag)
{
  // the speeds of sound are known from here on ('auto' ones included)
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/flowrate");
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  for (int t = 1; t <= atom->ntypes; t++) {
    const sphe_eos *eos = materials->eos(t);
    if (present[t] && eos && !(std::fabs(target) < eos->c0))
      error->all(FLERR,
                 "Fix sph/flowrate {}: the mean velocity {} is not below the speed of sound "
                 "{} of atom type {} in group {}: weakly compressible SPH needs speeds ten "
                 "times below it",
                 id, target, eos->c0, t, group->names[igroup]);
  }
  measure();
  update_accel(0.0);
  post_force(vflag);
}

void FixSPHFlowRate::post_force(int /*vflag*/)
{
  const SPHParticles particles(atom);
  double *const *const f = atom->f;
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) f[i][axis] += particles.mass(i) * accel;
}

void FixSPHFlowRate::end_of_step()
{
  measure();
  update_accel(update->dt);
}

/* ----------------------------------------------------------------------
   1 the acceleration of the next step, 2 the group's mean velocity
------------------------------------------------------------------------- */

double FixSPHFlowRate::compute_vector(int n)
{
  return n == 0 ? accel : mean;
}

/* ----------------------------------------------------------------------
   the integral part (the drive a steady channel needs) and tau carry
   across restarts, so that a continued run goes on with the same drive
------------------------------------------------------------------------- */

void FixSPHFlowRate::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double state[2] = {integral, tau_given ? 0.0 : tau};
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state, 2);
}

void FixSPHFlowRate::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  integral = state[0];
  if (!tau_given) tau = state[1];
}
