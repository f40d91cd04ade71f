/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/inlet/temperature: the inlet temperature of a channel periodic
   along the flow, without a reset zone (Ng, Ng, Sheu & Mukhtar 2020,
   section 3.2). The periodic plane (box face lo = box face hi of the axis)
   is the channel's inlet and outlet:
   - a particle of the group takes T_inlet in the step it passes the
     outlet (the box face downstream), once;
   - a pair across the plane exchanges no heat (the outlet is adiabatic,
     as are the ends of solids), except that a particle of the group on the
     inlet side receives the pair term with its neighbour at T_inlet (held:
     the fluid upstream of the inlet is at T_inlet, as in the paper), or at
     2 T_inlet - T(g), g the neighbour's mirror point across the plane and
     T(g) from the particle's first-order corrected temperature gradient
     (mirror: exact for linear T, so T_inlet holds on the plane itself;
     held ghosts put it about a kernel radius upstream, as held wall
     particles do at walls).
   Which side of the plane a particle is on follows from the periodic cell
   its coordinate lies in (ghost images lie in the next cells), so the rule
   holds however the box is split between ranks. The pairs are corrected
   after the pair style has computed them and before the ghosts' rates are
   sent home (pre_reverse), so every style after it sees the corrected
   rates.
------------------------------------------------------------------------- */

#include "fix_sph_inlet_temperature.h"
#include "fix_sph_shift.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "sph_hub.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_gradient.h"
#include "update.h"
#include "sph_particle.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 1;

static const char cmd[] = "fix sph/inlet/temperature";

/* ----------------------------------------------------------------------
   fix ID group sph/inlet/temperature T_inlet [flow +x|-x|+y|-y|+z|-z]
                                              [ghosts mirror|held]
------------------------------------------------------------------------- */

FixSPHInletTemperature::FixSPHInletTemperature(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), t_inlet(0.0), axis(0), downstream(1), cuts_plane(0), mirror(1),
    list(nullptr), pair(nullptr), rate_previous(0.0), rate(0.0), energy_reset(0.0),
    energy_plane(0.0), passes(nullptr), crossed_along(0), crossed_against(0), against_warned(0)
{
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/inlet/temperature requires atom style sph (esph, cv)");
  if (narg < 4) error->all(FLERR, "Illegal {} command: expected <T_inlet>", cmd);
  t_inlet = SPHCompat::finite_numeric(lmp, FLERR, cmd, "T_inlet", arg[3]);
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "flow") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'flow'", cmd);
      SPHCompat::signed_axis(lmp, FLERR, cmd, "flow", arg[iarg + 1],
                             "the direction the fluid leaves the box in", axis, downstream);
      iarg += 2;
    } else if (strcmp(arg[iarg], "ghosts") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'ghosts'", cmd);
      if (strcmp(arg[iarg + 1], "mirror") == 0)
        mirror = 1;
      else if (strcmp(arg[iarg + 1], "held") == 0)
        mirror = 0;
      else
        error->all(FLERR,
                   "Illegal {} command: ghosts '{}' must be mirror or held (the neighbours "
                   "across the inlet plane at their mirror value or at T_inlet)",
                   cmd, arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }

  scalar_flag = 1;
  extscalar = 1;
  vector_flag = 1;
  size_vector = 4;
  extvector = 1;
  global_freq = 1;
  restart_global = 1;
  // atoms created in a run (fix sph/open) count their passes from where they are
  create_attribute = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

FixSPHInletTemperature::~FixSPHInletTemperature()
{
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(passes);
}

int FixSPHInletTemperature::setmask()
{
  return PRE_REVERSE | POST_INTEGRATE;
}

/* ---------------------------------------------------------------------- */

void FixSPHInletTemperature::init()
{
  SPHHub hub(lmp);
  pair = hub.require_heat("Fix sph/inlet/temperature");
  const char xyz[] = "xyz";
  if (!domain->periodicity[axis])
    error->all(FLERR,
               "Fix {} {}: the box must be periodic along {}, the direction of the flow (the "
               "periodic plane is the channel's inlet and outlet)",
               id, style, xyz[axis]);
  if (domain->triclinic) error->all(FLERR, "Fix {} {}: the box must be orthogonal", id, style);
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "Fix {} {}: group {} has no atoms", id, style, group->names[igroup]);

  // one plane for all of them: the first removes the pairs across it, each
  // gives its own group its inlet temperature
  const auto inlets = hub.fixes<FixSPHInletTemperature>();
  cuts_plane = (inlets.front() == this);
  for (FixSPHInletTemperature *other : inlets) {
    if (other == this) continue;
    if (other->axis != axis)
      error->all(FLERR, "Fix {} {}: its flow is along {}, that of fix {} along {}: one axis only",
                 id, style, xyz[axis], other->id, xyz[other->axis]);
    if (SPHCheck::groups_overlap(lmp, groupbit, other->groupbit))
      error->all(FLERR, "Fix {} {}: group {} shares atoms with group {} of fix {}", id, style,
                 group->names[igroup], group->names[other->igroup], other->id);
  }
  // (cv and esph: pair sph/cleary/heat, which this fix requires, has checked
  // every atom's at its init, which comes before the fixes')
  if (!against_warned) check_direction();
  // the inlet side's particles see all their neighbours, on both sides
  SPHCompat::request_full_list(neighbor, this, instance_me);

  for (FixSPHShift *shift : hub.fixes<FixSPHShift>()) {
    if (shift->corrects() && comm->me == 0)
      error->warning(FLERR,
                     "Fix {} {}: the temperature correction of fix {} sph/shift takes its "
                     "gradient across the inlet plane too",
                     id, style, shift->id);
  }
}

/* ----------------------------------------------------------------------
   a group that flows against the fix's direction never passes its outlet
   and never takes T_inlet: warn (once) when its mean velocity along the
   axis opposes the direction by more than a tenth of its rms speed (at
   rest, noise has a mean far below that)
------------------------------------------------------------------------- */

void FixSPHInletTemperature::check_direction()
{
  const double *const *const v = atom->v;
  const int *const mask = atom->mask;
  double local[3] = {0.0, 0.0, 0.0};    // count, sum of v along the axis, sum of v^2
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    local[0] += 1.0;
    local[1] += v[i][axis];
    local[2] += v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
  }
  double sum[3];
  MPI_Allreduce(local, sum, 3, MPI_DOUBLE, MPI_SUM, world);
  if (!(sum[0] > 0.0)) return;
  const double mean = sum[1] / sum[0];
  const double rms = sqrt(sum[2] / sum[0]);
  if (!(downstream * mean < -0.1 * rms)) return;
  const char xyz[] = "xyz";
  if (comm->me == 0)
    error->warning(FLERR,
                   "Fix {} {}: the mean velocity of group {} along {} is {:.6g}, against the "
                   "fix's flow {}{} (the direction the fluid leaves the box in): no particle "
                   "will pass the outlet and take T_inlet; give 'flow {}{}' if the fluid flows "
                   "that way",
                   id, style, group->names[igroup], xyz[axis], mean, downstream > 0 ? '+' : '-',
                   xyz[axis], downstream > 0 ? '-' : '+', xyz[axis]);
  against_warned = 1;
}

void FixSPHInletTemperature::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

void FixSPHInletTemperature::setup_pre_reverse(int, int)
{
  for (int i = 0; i < atom->nlocal; i++) passes[i] = passes_now(i);
  crossed_along = crossed_against = 0;
  correct_pairs(1);
}

void FixSPHInletTemperature::pre_reverse(int, int)
{
  correct_pairs(0);
}

/* ----------------------------------------------------------------------
   the pairs across the plane: the first fix of this style removes what the
   pair style computed for them (with its list; with newton on, a ghost's
   share goes home in the reverse communication that follows, with it off
   the rank that owns j does j's share); then each fix gives its group's
   owned particles on the inlet side the pair term with every neighbour
   across the plane at its ghost temperature (with its own full list). The
   heat that comes in through the plane is tallied as the wall fixes do it:
   fix sph applies each rate half a step twice.
------------------------------------------------------------------------- */

void FixSPHInletTemperature::correct_pairs(int first)
{
  if (cuts_plane) remove_plane_pairs();
  const double rate_local = mirror ? inlet_terms<1>() : inlet_terms<0>();
  MPI_Allreduce(&rate_local, &rate, 1, MPI_DOUBLE, MPI_SUM, world);
  const double dt_half = 0.5 * update->dt * force->ftm2v;    // fix sph's half step
  if (!first) energy_plane += dt_half * (rate_previous + rate);
  rate_previous = rate;
}

/* ----------------------------------------------------------------------
   the inlet terms of the group's owned particles on the inlet side; returns
   their heat rate (this rank)
------------------------------------------------------------------------- */

template <int MIRROR> double FixSPHInletTemperature::inlet_terms()
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  double *const desph = atom->desph;
  const double cut = pair->support();
  const double cutsq = cut * cut;
  const double lo = domain->boxlo[axis];
  const double length = domain->prd[axis];

  double rate_local = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    if (x[i][axis] >= lo + cut && x[i][axis] < lo + length - cut) continue;
    const double cell_i = periodic_cell(domain, x[i][axis], axis);
    const double mass_i = particles.mass(i);
    const double temp_i = particles.temperature(i);
    double grad[3] = {0.0, 0.0, 0.0};
    int gradient_known = 0;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double cell_j = periodic_cell(domain, x[j][axis], axis);
      // j across the plane, upstream of i: i is on the inlet side
      if (!(downstream * (cell_i - cell_j) > 0.0)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq) continue;
      // walls and solids across the plane stand at T_inlet: mirrored, the
      // hot wall's own extension would give the corner ghosts far below it
      double temp_ghost = t_inlet;
      if (MIRROR && (mask[j] & groupbit)) {
        if (!gradient_known) temperature_gradient(i, cell_i, grad), gradient_known = 1;
        // j's mirror point g across the plane, which lies between the cells
        const double plane = lo + length * std::max(cell_i, cell_j);
        double to_mirror[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        to_mirror[axis] = 2.0 * plane - x[j][axis] - x[i][axis];
        const double temp_mirror =
            temp_i + grad[0] * to_mirror[0] + grad[1] * to_mirror[1] + grad[2] * to_mirror[2];
        temp_ghost = 2.0 * t_inlet - temp_mirror;
      }
      const double mass_j = particles.mass(j);
      const double f = pair->pair_term(i, j, rsq, temp_i - temp_ghost);
      desph[i] += mass_j * f;
      rate_local += mass_i * mass_j * f;
    }
  }
  return rate_local;
}

/* ----------------------------------------------------------------------
   take back what the pair style conducted across the plane
------------------------------------------------------------------------- */

void FixSPHInletTemperature::remove_plane_pairs()
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
  double *const desph = atom->desph;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const NeighList *const pair_list = pair->pair_list();
  const double cut = pair->support();
  const double cutsq = cut * cut;
  const double lo = domain->boxlo[axis];
  const double length = domain->prd[axis];

  for (int ii = 0; ii < pair_list->inum; ii++) {
    const int i = pair_list->ilist[ii];
    // no neighbour across the plane (and inside the box: cell 0)
    if (x[i][axis] >= lo + cut && x[i][axis] < lo + length - cut) continue;
    const double cell_i = periodic_cell(domain, x[i][axis], axis);
    const double mass_i = particles.mass(i);
    const double temp_i = particles.temperature(i);
    const int *const jlist = pair_list->firstneigh[i];
    for (int jj = 0; jj < pair_list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (periodic_cell(domain, x[j][axis], axis) == cell_i) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq) continue;
      const double f = pair->pair_term(i, j, rsq, temp_i - particles.temperature(j));
      desph[i] -= particles.mass(j) * f;
      if (newton || j < nlocal) desph[j] += mass_i * f;
    }
  }
}

/* ----------------------------------------------------------------------
   grad T at owned atom i from its neighbours on its own side of the plane,
   with the first-order correction (sph_gradient.h: exact for linear T, also
   with the support cut by the plane, a wall or a corner); the kernel
   estimate where the neighbours are too few to correct it
------------------------------------------------------------------------- */

void FixSPHInletTemperature::temperature_gradient(int i, double cell_i, double *grad) const
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
  const double cut = pair->support();
  const double cutsq = cut * cut;
  const double temp_i = particles.temperature(i);
  double g[3] = {0.0, 0.0, 0.0};
  double L[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const int *const jlist = list->firstneigh[i];
  for (int jj = 0; jj < list->numneigh[i]; jj++) {
    const int j = jlist[jj] & NEIGHMASK;
    if (periodic_cell(domain, x[j][axis], axis) != cell_i) continue;
    const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    if (rsq >= cutsq || rsq == 0.0) continue;
    const double r = sqrt(rsq);
    // grad_i W_ij = dW/dr (r_i - r_j) / r
    const double f = pair->kernel_dwdr(r) / r;
    const double grad_w[3] = {f * del[0], f * del[1], f * del[2]};
    sphg_add(g, L, del, grad_w, particles.volume(j),
             particles.temperature(j) - temp_i);
  }
  sphg_solve_transposed(L, g, grad, domain->dimension);
}

/* ----------------------------------------------------------------------
   the passes of owned atom i through the outlet so far: its periodic cell
   along the axis (downstream counted positive), image flag included
------------------------------------------------------------------------- */

double FixSPHInletTemperature::passes_now(int i) const
{
  const imageint image = atom->image[i];
  const imageint flag = (axis == 0) ? (image & IMGMASK)
      : (axis == 1)                 ? ((image >> IMGBITS) & IMGMASK)
                                    : (image >> IMG2BITS);
  return downstream * (periodic_cell(domain, atom->x[i][axis], axis) + (double) ((int) flag - IMGMAX));
}

/* ----------------------------------------------------------------------
   after the positions' update: the group's particles that have passed the
   outlet in this step take T_inlet (once: wrapping them into the box does
   not count as a pass)
------------------------------------------------------------------------- */

void FixSPHInletTemperature::post_integrate()
{
  const SPHParticles particles(atom);
  double *const esph = atom->esph;
  const int *const mask = atom->mask;

  double energy_local = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double now = passes_now(i);
    // an atom that came from another rank in this step has its count from there
    const bool passed = now > passes[i];
    if (now < passes[i]) crossed_against++;
    passes[i] = now;
    if (!passed) continue;
    crossed_along++;
    const double esph_inlet = particles.energy_at(i, t_inlet);
    energy_local += particles.mass(i) * (esph_inlet - esph[i]);
    esph[i] = esph_inlet;
  }
  double energy_step = 0.0;
  MPI_Allreduce(&energy_local, &energy_step, 1, MPI_DOUBLE, MPI_SUM, world);
  energy_reset += energy_step;
}

/* ----------------------------------------------------------------------
   at the end of a run: particles that crossed the plane against the flow,
   four times as many as along it, flow the other way (particles that
   wander across and back count once each way)
------------------------------------------------------------------------- */

void FixSPHInletTemperature::post_run()
{
  const bigint local[2] = {crossed_along, crossed_against};
  bigint all[2];
  MPI_Allreduce(local, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all[1] > 0 && all[1] > 4 * all[0] && comm->me == 0) {
    const char xyz[] = "xyz";
    const char sign = downstream > 0 ? '+' : '-', other = downstream > 0 ? '-' : '+';
    error->warning(FLERR,
                   "Fix {} {}: in this run {} particles of group {} crossed the inlet plane "
                   "against the fix's flow {}{} and {} along it (the passes that take "
                   "T_inlet): the fluid flows the other way; give 'flow {}{}'",
                   id, style, all[1], group->names[igroup], sign, xyz[axis], all[0], other,
                   xyz[axis]);
  }
}

/* ----------------------------------------------------------------------
   scalar: energy the inlet has added (resets and plane); vector: that,
   the resets' share, the plane's share, the heat rate through the plane
------------------------------------------------------------------------- */

double FixSPHInletTemperature::compute_scalar()
{
  return energy_reset + energy_plane;
}

double FixSPHInletTemperature::compute_vector(int n)
{
  if (n == 0) return energy_reset + energy_plane;
  if (n == 1) return energy_reset;
  if (n == 2) return energy_plane;
  return rate;
}

/* ---------------------------------------------------------------------- */

void FixSPHInletTemperature::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    const double state[2] = {energy_reset, energy_plane};
    SPHCheck::write_restart_state(fp, RESTART_VERSION, state, 2);
  }
}

void FixSPHInletTemperature::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  energy_reset = state[0];
  energy_plane = state[1];
}

/* ----------------------------------------------------------------------
   the pass counts travel with the atoms; they are set afresh at each run's
   setup, so restarts need none
------------------------------------------------------------------------- */

void FixSPHInletTemperature::grow_arrays(int nmax)
{
  memory->grow(passes, nmax, "sph/inlet/temperature:passes");
}

void FixSPHInletTemperature::copy_arrays(int i, int j, int /*delflag*/)
{
  passes[j] = passes[i];
}

void FixSPHInletTemperature::set_arrays(int i)
{
  passes[i] = passes_now(i);
}

int FixSPHInletTemperature::pack_exchange(int i, double *buf)
{
  buf[0] = passes[i];
  return 1;
}

int FixSPHInletTemperature::unpack_exchange(int nlocal, double *buf)
{
  passes[nlocal] = buf[0];
  return 1;
}

double FixSPHInletTemperature::memory_usage()
{
  return (double) atom->nmax * sizeof(double);
}
