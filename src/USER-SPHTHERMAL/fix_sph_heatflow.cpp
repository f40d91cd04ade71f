/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/heatflow: the heat that pair sph/cleary/heat conducts into a
   group from another, as power and as energy integrated the way fix sph
   and sph/stationary integrate esph, so that it balances the change of the
   group's thermal energy to round-off.
------------------------------------------------------------------------- */

#include "fix_sph_heatflow.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "pair_sph_cleary_heat.h"
#include "sph_hub.h"
#include "sph_checks.h"
#include "update.h"

#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
// (1: the energy; 2: the energy, the names of the group and of the group
// the heat comes from)
static constexpr int RESTART_VERSION = 2;

static const char cmd[] = "fix sph/heatflow";

/* ----------------------------------------------------------------------
   fix ID group sph/heatflow group2: heat into group from group2
------------------------------------------------------------------------- */

FixSPHHeatflow::FixSPHHeatflow(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), from_groupbit(0), pair(nullptr), flow_index(-1), dt_half(0.0),
    power_previous(0.0), power(0.0), energy(0.0)
{
  if (narg != 4)
    error->all(FLERR, "Illegal {} command: expected 'fix ID <group> sph/heatflow <from group>'",
               cmd);
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/heatflow requires atom style sph (esph, desph, cv)");
  from_name = arg[3];
  if (group->find(arg[3]) < 0)
    error->all(FLERR, "Illegal {} command: no group {} (the group the heat comes from)", cmd,
               arg[3]);

  scalar_flag = 1;    // energy since the fix was defined
  extscalar = 0;
  vector_flag = 1;    // power now, energy
  size_vector = 2;
  extvector = 0;
  global_freq = 1;
  restart_global = 1;
}

int FixSPHHeatflow::setmask()
{
  return POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixSPHHeatflow::init()
{
  const int from_group = group->find(from_name);
  if (from_group < 0)
    error->all(FLERR, "Fix sph/heatflow: group {} (the group the heat comes from) was deleted",
               from_name);
  from_groupbit = group->bitmask[from_group];
  if (from_groupbit == groupbit)
    error->all(FLERR, "Fix sph/heatflow: the heat into group {} from itself is zero by definition",
               from_name);
  // either group can be emptied between the definition and the run
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "Fix sph/heatflow {}: group {} (the group the heat goes into) has no atoms",
               id, group->names[igroup]);
  if (SPHCheck::group_count(lmp, from_groupbit) == 0)
    error->all(FLERR, "Fix sph/heatflow {}: group {} (the group the heat comes from) has no atoms",
               id, from_name);
  if (SPHCheck::groups_overlap(lmp, groupbit, from_groupbit))
    error->all(FLERR,
               "Fix sph/heatflow: groups {} and {} share atoms; the heat between them needs "
               "disjoint groups",
               group->names[igroup], from_name);
  pair = SPHHub(lmp).require_heat("Fix sph/heatflow");
  flow_index = pair->request_heat_flow(groupbit, from_groupbit);
  reset_dt();
}

void FixSPHHeatflow::reset_dt()
{
  dt_half = 0.5 * update->dt * force->ftm2v;
}

void FixSPHHeatflow::setup(int /*vflag*/)
{
  tally(1);
}

void FixSPHHeatflow::post_force(int /*vflag*/)
{
  tally(0);
}

/* ----------------------------------------------------------------------
   fix sph and sph/stationary apply each rate for half a step twice, so the
   energy grows by dt/2 (power before + power now) per step; at a run's
   setup the power is only recorded
------------------------------------------------------------------------- */

void FixSPHHeatflow::tally(int first)
{
  power = pair->heat_flow(flow_index);
  if (!first) energy += dt_half * (power_previous + power);
  power_previous = power;
}

/* ---------------------------------------------------------------------- */

double FixSPHHeatflow::compute_scalar()
{
  return energy;
}

double FixSPHHeatflow::compute_vector(int n)
{
  return (n == 0) ? power : energy;
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   the energy carries across restarts, with the groups it was between: a
   fix defined again between other groups continues it, with a warning
------------------------------------------------------------------------- */

void FixSPHHeatflow::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> state = {energy};
  SPHCheck::pack_name(state, group->names[igroup]);
  SPHCheck::pack_name(state, from_name);
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state.data(), (int) state.size());
}

void FixSPHHeatflow::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  energy = state[0];
  int at = 1;
  const std::string into = SPHCheck::unpack_name(state, at);
  const std::string from = SPHCheck::unpack_name(state, at);
  if ((into != group->names[igroup] || from != from_name) && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/heatflow {}: the restart file's energy is of the heat into group {} "
                   "from group {}, the fix is now into group {} from group {}: its energy ({}) "
                   "continues from the other groups'; give the fix another ID to start it at 0",
                   id, into, from, group->names[igroup], from_name, energy);
}
