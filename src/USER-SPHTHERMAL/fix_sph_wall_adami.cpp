/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/wall/adami: wall particles of weakly compressible flow with the
   pressure and no-slip velocity extrapolated from the fluid (Adami, Hu &
   Adams 2012; Ng et al. 2020, eqs 8-9, with the body-force term of Adami
   kept):
     P_w = (sum_f P_f W_wf + sum_f rho_f (g_f - a_w) . r_wf W_wf) / sum_f W_wf
   (g_f: the body acceleration of fluid particle f, with its own buoyancy)
     rho_w from P_w by the wall type's equation of state
     vest_w = 2 v_w - sum_f v_f W_wf / sum_f W_wf   (v_w: the wall's own v)
   over the fluid neighbours f (particles of no sph/wall/adami fix); with
   'surface', from the fluid's velocity and its gradient at the wall
   particle's mirror point g across the surface (the ghost points of
   English et al. 2022), from a quadratic least-squares fit there:
     vest_w = v_w - 3 (v(g) - v_w) + (g - x_w) . grad v(g)
   the quadratic profile across the surface with v = v_w on it (no slip),
   v(g) and grad v(g), which extends a linear or quadratic profile through
   the wall exactly; the part along the surface's normal g - x_w takes the
   mirror image 2 v_w - v(g) instead.
------------------------------------------------------------------------- */

#include "fix_sph_wall_adami.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_dispatch.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_kernels.h"
#include "sph_mirror.h"
#include "sph_particle.h"
#include "sph_threads.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 1;

static const char cmd[] = "fix sph/wall/adami";
// a fluid atom whose two nearest wall atoms are together this near, in
// wall spacings, has gone 0.4 (midway between two wall atoms) to 0.48 (in
// line with one) spacings past a flat wall's surface, about as far as the
// first wall row (the mirror walls' check; warn_entered_wall())
static constexpr double ENTERED = 1.02;

/* ---------------------------------------------------------------------- */

FixSPHWallAdami::FixSPHWallAdami(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), body_given(0), moving_keyword(-1), moving(0), v_sampled(nullptr),
    accel(nullptr), remaining_sampled(0.0), sampled(0), body_force(nullptr), buoyancy(nullptr),
    wall_groupbit(0), kernel_kind(0), cutoff(0.0), materials(nullptr), thermal_expansion(0),
    fluid_near_valid(false), entered_warned(0), solid_type(nullptr), any_solid(0),
    solid_state(nullptr), nmax(0), mirror(nullptr)
{
  if (!atom->rho_flag || !atom->vest_flag)
    error->all(FLERR, "Fix sph/wall/adami requires atom style sph (rho, vest)");
  body[0] = body[1] = body[2] = 0.0;
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "body") == 0) {
      if (iarg + 3 >= narg)
        error->all(FLERR, "Illegal {} command: 'body' needs 3 values (gx gy gz)", cmd);
      for (int k = 0; k < 3; k++) body[k] = utils::numeric(FLERR, arg[iarg + 1 + k], false, lmp);
      body_given = 1;
      iarg += 4;
    } else if (strcmp(arg[iarg], "moving") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: 'moving' needs yes, no or auto", cmd);
      if (strcmp(arg[iarg + 1], "yes") == 0)
        moving_keyword = 1;
      else if (strcmp(arg[iarg + 1], "no") == 0)
        moving_keyword = 0;
      else if (strcmp(arg[iarg + 1], "auto") == 0)
        moving_keyword = -1;
      else
        error->all(FLERR, "Illegal {} command: moving {}: yes, no or auto", cmd, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "surface") == 0) {
      delete mirror;
      mirror = new SPHMirror(lmp, cmd, false, SPHMirror::VELOCITY);
      iarg += mirror->parse(narg, arg, iarg);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }
  memory->create(solid_type, atom->ntypes + 1, "sph/wall/adami:solid_type");
  for (int t = 0; t <= atom->ntypes; t++) solid_type[t] = 0;
  restart_global = 1;
  restart_peratom = 1;
  // atoms created in a run (fix sph/open) start with no velocity sample
  create_attribute = 1;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixSPHWallAdami::~FixSPHWallAdami()
{
  memory->destroy(solid_type);
  memory->destroy(solid_state);
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(v_sampled);
  memory->destroy(accel);
  delete mirror;
}

int FixSPHWallAdami::setmask()
{
  return PRE_NEIGHBOR | PRE_FORCE | POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixSPHWallAdami::init()
{
  // the kernel and its support are those of the flow pair style
  SPHHub hub(lmp);
  const SPHKernelSettings given = hub.require_flow("Fix sph/wall/adami")->kernel_settings();
  kernel_kind = given.kind;
  cutoff = given.cutoff;
  if (mirror) mirror->init(groupbit, kernel_kind, cutoff, id);
  materials = FixSPHMaterials::find(lmp, "Fix sph/wall/adami");
  entered_warned = 0;    // once a run
  // ghost velocities: turned on and checked by the pair, which this fix requires
  SPHCheck::group_of_kind(lmp, FLERR, this, hub.fixes_of_any<FixSPHWallAdami>(), false, false);
  // a wall type without an equation of state is a solid of its own density
  int local_solid = 0;
  for (int t = 1; t <= atom->ntypes; t++) solid_type[t] = materials->eos(t) ? 0 : 1;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && solid_type[atom->type[i]]) {
      local_solid = 1;
      if (!(materials->rho0(atom->type[i]) > 0.0))
        SPHCheck::stop(lmp, FLERR,
                       fmt::format("Fix sph/wall/adami: atom type {} of wall atom {} has no "
                                   "equation of state, so it is a solid, but no rho0 in fix "
                                   "sph/materials",
                                   atom->type[i], atom->tag[i]));
    }
  MPI_Allreduce(&local_solid, &any_solid, 1, MPI_INT, MPI_MAX, world);
  // rho and vest, and with solids their state as the flow sees it
  comm_forward = any_solid ? 4 + SOLID_STATE_SIZE : 4;
  // (the solids' rho: pair sph/harmonic/visc, which this fix requires, has
  // checked every atom's at its init, which comes before the fixes')
  // with thermal expansion the wall's density follows its temperature (the
  // pair, which this fix requires, checks every atom's cv and esph then)
  thermal_expansion = materials->thermal_expansion();
  // without 'body', the fluid's body force is the run's (a resting wall)
  body_force = body_given ? nullptr : SPHBodyForce::find(lmp, "Fix sph/wall/adami");
  if (body_given)
    SPHBodyForce::warn_overridden(lmp, "Fix sph/wall/adami", "body", body,
                                  "without 'body' the wall reads it");
  // each fluid particle's own buoyancy, which varies with its temperature
  buoyancy = SPHBodyForce::find_buoyancy(lmp);

  wall_groupbit = hub.groupbits<FixSPHWallAdami>();
  fluid_near_valid = false;

  // moving walls: a fix that moves atoms of this group (auto), or the keyword
  moving = moving_keyword;
  if (moving < 0) {
    int local = 0, any = 0;
    for (int ifix = 0; ifix < modify->nfix; ifix++) {
      Fix *other = modify->fix[ifix];
      if (!hub.moves_bodies(other)) continue;
      for (int i = 0; i < atom->nlocal; i++)
        if ((atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit)) local = 1;
    }
    MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, world);
    moving = any;
  }
}

// atoms were exchanged or sorted: the fluid found near each wall particle is stale
void FixSPHWallAdami::setup_pre_neighbor()
{
  pre_neighbor();
}

void FixSPHWallAdami::pre_neighbor()
{
  fluid_near_valid = false;
  if (mirror) mirror->neighbours_changed();
}

/* ----------------------------------------------------------------------
   the fluid (owned and ghost) within cutoff + skin of each owned wall
   particle: until the next neighbour build no atom moves by half the skin
------------------------------------------------------------------------- */

void FixSPHWallAdami::find_fluid_near()
{
  double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  const double reach = cutoff + neighbor->skin;
  cells.bin(x, mask, nall, wall_groupbit, reach);
  cells.near_points(
      x, atom->nlocal, nall, reach,
      [&](int i) {
        return (mask[i] & groupbit) ? x[i] : nullptr;
      },
      // the fluid: atoms with an equation of state (not the grains of fix
      // sph/grains, nor solids of other groups)
      [&](int j) {
        return materials->eos(type[j]) != nullptr;
      },
      first_fluid, fluid_near, fluid_atoms);
  fluid_near_valid = true;
  if (!entered_warned) warn_entered_wall();
}

/* ----------------------------------------------------------------------
   a fluid atom whose two nearest wall atoms (owned here) are together
   nearer than ENTERED wall spacings (the spacing from the wall atom's
   volume, (m / rho0)^(1/d)): at a flat wall's surface they are at least
   1.41 spacings (midway between two) and 1.5 (in line with one), in a
   corner 1.41; on the first wall row's line 1 spacing. Named by the lowest atom
   ID of all ranks, once a run.
------------------------------------------------------------------------- */

void FixSPHWallAdami::warn_entered_wall()
{
  double *const *const x = atom->x;
  const int *const type = atom->type;
  const tagint *const tag = atom->tag;
  const double inv_dim = 1.0 / domain->dimension;
  // per fluid atom of fluid_atoms: its two nearest wall atoms' distances,
  // the nearest one's ID and spacing
  const int nfluid = fluid_atoms.size();
  std::vector<double> near1(nfluid, INFINITY), near2(nfluid, INFINITY), spacing(nfluid, 0.0);
  std::vector<tagint> wall_of(nfluid, 0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (first_fluid[i] == first_fluid[i + 1]) continue;
    const double rho0 = materials->rho0(type[i]);
    const double mass_i = atom->rmass_flag ? atom->rmass[i] : atom->mass[type[i]];
    if (!(rho0 > 0.0) || !(mass_i > 0.0)) continue;
    const double spacing_i = pow(mass_i / rho0, inv_dim);
    for (int n = first_fluid[i]; n < first_fluid[i + 1]; n++) {
      const int m = fluid_near[n], j = fluid_atoms[m];
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (r < near1[m]) {
        near2[m] = near1[m];
        near1[m] = r;
        spacing[m] = spacing_i;
        wall_of[m] = tag[i];
      } else if (r < near2[m])
        near2[m] = r;
    }
  }
  // the find with the lowest fluid atom ID: fluid ID, wall ID, distance,
  // spacing, fluid x
  double found[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  tagint lowest = MAXTAGINT;
  for (int m = 0; m < nfluid; m++) {
    const int j = fluid_atoms[m];
    if (!(near1[m] + near2[m] < ENTERED * spacing[m]) || tag[j] >= lowest) continue;
    lowest = tag[j];
    const double row[7] = {
        (double) tag[j], (double) wall_of[m], near1[m], spacing[m], x[j][0], x[j][1], x[j][2]};
    for (int k = 0; k < 7; k++) found[k] = row[k];
  }
  tagint lowest_all = MAXTAGINT;
  MPI_Allreduce(&lowest, &lowest_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (lowest_all == MAXTAGINT) return;
  entered_warned = 1;
  // the rank with the lowest ID gives its find to rank 0
  int mine = (lowest == lowest_all) ? comm->me : comm->nprocs, from = 0;
  MPI_Allreduce(&mine, &from, 1, MPI_INT, MPI_MIN, world);
  MPI_Bcast(found, 7, MPI_DOUBLE, from, world);
  if (comm->me == 0)
    error->warning(
        FLERR,
        "Fix {} sph/wall/adami: fluid atom {} at ({:.6g} {:.6g} {:.6g}) is {:.3g} from "
        "wall atom {} and its two nearest wall atoms are together nearer than {} "
        "times the wall's spacing {:.3g}, at step {}: it is about a wall row deep in the "
        "wall, where the walls' pressure may no longer push it out (pair "
        "sph/harmonic/visc's 'artificial' damps films and splashes at walls: 0.1 by default "
        "under fix gravity)",
        id, (tagint) found[0], found[4], found[5], found[6], found[2], (tagint) found[1], ENTERED,
        found[3], update->ntimestep);
}

void FixSPHWallAdami::setup_pre_force(int /*vflag*/)
{
  // the atoms' own state before the walls extrapolate from it
  SPHCheck::particles(lmp, FLERR, "Fix sph/wall/adami", SPHCheck::RHO | SPHCheck::ESPH);
  // at setup v is the full-step velocity: the sample of this step
  if (moving) sample_acceleration(0.0);
  pre_force_walls();
}

void FixSPHWallAdami::pre_force(int /*vflag*/)
{
  SPHCheck::particles(lmp, FLERR, "Fix sph/wall/adami", SPHCheck::RHO | SPHCheck::ESPH);
  // in a step v is the half-step velocity of fix rigid, move and sph
  if (moving) sample_acceleration(0.5 * update->dt);
  pre_force_walls();
}

/* ----------------------------------------------------------------------
   a_w of each owned wall particle from its velocity now and at the last
   sample, a_w = (v - v_sampled) / (time between them); 0 before the first
   sample. half_dt: time from the start of this step to now (0 at setup).
------------------------------------------------------------------------- */

void FixSPHWallAdami::sample_acceleration(double half_dt)
{
  double *const *const v = atom->v;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  // from the last sample to the end of its step, then to now
  const double between = remaining_sampled + half_dt;
  const int known = sampled && between > 0.0;
  const double inv = known ? 1.0 / between : 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) {
      accel[i][k] = known ? (v[i][k] - v_sampled[i][k]) * inv : 0.0;
      v_sampled[i][k] = v[i][k];
    }
  }
  sampled = 1;
  remaining_sampled = (half_dt > 0.0) ? update->dt - half_dt : 0.0;
}

struct FixSPHWallAdami::AtomsCall {
  FixSPHWallAdami *fix;
  int from, to;
  double *fluid_weight;
  const sphk_kernel *kernel;
  int *below_eos;
  template <int KERNEL> void run()
  {
    fix->pre_force_atoms<KERNEL>(from, to, fluid_weight, *kernel, *below_eos);
  }
};

/* ----------------------------------------------------------------------
   density and viscous velocity of the owned wall particles, then of their
   ghost copies; a wall particle with no fluid neighbour is at rest density
------------------------------------------------------------------------- */

void FixSPHWallAdami::pre_force_walls()
{
  const SPHParticles particles(atom);
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const sphk_kernel kernel = sphk_make(kernel_kind, domain->dimension, cutoff);
  int below_eos = 0;
  // fix gravity may vary its acceleration in time
  if (!body_given) {
    // a fix gravity with variables sets its acceleration at its first force,
    // after this set-up
    if (!update->setupflag || SPHBodyForce::constant(SPHBodyForce::source(lmp)))
      SPHBodyForce::check_finite(lmp, FLERR, "Fix sph/wall/adami", body_force);
    for (int k = 0; k < 3; k++) body[k] = body_force ? body_force[k] : 0.0;
  }

  if (any_solid && atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(solid_state);
    memory->create(solid_state, nmax, SOLID_STATE_SIZE, "sph/wall/adami:solid_state");
  }
  const int ntypes = atom->ntypes;

  if (!fluid_near_valid || (int) first_fluid.size() != atom->nlocal + 1) find_fluid_near();
  // no slip through the surface: the fluid's velocity at the mirror points
  if (mirror) mirror->interpolate_velocity(ghost_velocity, ghost_how);
  // each fluid particle's pressure and rho times its body acceleration, once
  const int nfluid = fluid_atoms.size();
  fluid_pressure.resize(nfluid);
  fluid_rho_accel.resize(3 * (size_t) nfluid);
  // on the threads of package omp: each fluid atom's state, then each
  // thread a share of the wall atoms (of about as many fluid neighbours)
  const int nthreads = comm->nthreads;
  sph_parallel_for(nfluid, nthreads, [&](int m) {
    const int j = fluid_atoms[m];
    // with thermal expansion the pair refuses a T without reference density
    fluid_pressure[m] = sphe_pressure_at(materials->eos(type[j]), particles.fluid_density(j),
                                         thermal_expansion ? particles.temperature(j) : 0.0);
    if (buoyancy)
      fluid_pressure[m] +=
          materials->eos(type[j])->rho0 * SPHBodyForce::potential_of(buoyancy, mask[j], j);
    double accel[3];
    SPHBodyForce::acceleration(body, buoyancy, mask[j], type[j],
                               buoyancy ? particles.temperature(j) : 0.0, atom->x[j], accel);
    const double fluid_rho = particles.fluid_density(j);
    for (int k = 0; k < 3; k++) fluid_rho_accel[3 * (size_t) m + k] = fluid_rho * accel[k];
  });
  fluid_weights.resize((size_t) nthreads * (ntypes + 1));
  std::vector<int> below_eos_of(nthreads, 0);
  // each thread the wall atoms of a share of the fluid neighbours
  std::vector<int> slices;
  sph_work_slices(first_fluid.data(), atom->nlocal, nthreads, slices);
  sph_parallel(nthreads, [&](int tid) {
    AtomsCall call = {this,   slices[tid], slices[tid + 1],
                      fluid_weights.data() + (size_t) tid * (ntypes + 1), &kernel,
                      &below_eos_of[tid]};
    SPHDispatch<SPHKernelKinds>::to(call, &kernel_kind);
  });
  for (int t = 0; t < nthreads; t++) below_eos += below_eos_of[t];
  // a tension beyond the equation of state leaves no density: stop, collectively
  int below_eos_all = 0;
  MPI_Allreduce(&below_eos, &below_eos_all, 1, MPI_INT, MPI_SUM, world);
  if (below_eos_all)
    error->all(FLERR,
               "Fix sph/wall/adami: the extrapolated pressure of {} wall particle(s) is below the "
               "lowest pressure of their equation of state (raise its speed of sound or "
               "background pressure)",
               below_eos_all);
  SPHCompat::forward_comm(comm, this);
}

/* the extrapolated state of the wall atoms [from, to) of the group, with
   fluid_weight the room for a weight per type and below_eos counting the
   atoms whose pressure is below their equation of state's; KERNEL a
   constant, so that the kernel's switch leaves the loop over the fluid
   neighbours */

template <int KERNEL>
void FixSPHWallAdami::pre_force_atoms(int from, int to, double *fluid_weight,
                                      const sphk_kernel &kernel, int &below_eos)
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
  const double *const *const v = atom->v;
  double *const *const vest = atom->vest;
  double *const rho = atom->rho;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const double cutsq = cutoff * cutoff;
  const int ntypes = atom->ntypes;
  // local copies: the solid's viscosity call in the loop could change any
  // member, which would then be read again for every pair
  const double w_scale = kernel.w_scale, inv_h = kernel.inv_h;
  const int moving = this->moving;
  const int *const first = first_fluid.data();
  const int *const near = fluid_near.data();
  const int *const atom_of = fluid_atoms.data();
  const double *const pressure_of = fluid_pressure.data();
  const double *const rho_accel_of = fluid_rho_accel.data();
  for (int i = from; i < to; i++) {
    if (!(mask[i] & groupbit)) continue;
    const int is_solid = solid_type[type[i]];
    double weight = 0.0, weighted_p = 0.0, hydrostatic = 0.0;
    double weighted_rho_r[3] = {0.0, 0.0, 0.0};    // moving walls: sum_f rho_f r_wf W_wf
    double weighted_mu = 0.0;                      // solids only; and the weight of each fluid type
    if (is_solid)
      for (int t = 1; t <= ntypes; t++) fluid_weight[t] = 0.0;
    double weighted_v[3] = {0.0, 0.0, 0.0};
    for (int n = first[i]; n < first[i + 1]; n++) {
      const int m = near[n];
      const int j = atom_of[m];
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq >= cutsq) continue;
      const double w = w_scale * sphk_f(KERNEL, sqrt(rsq) * inv_h);
      weight += w;
      weighted_p += w * pressure_of[m];
      const double *const rho_accel = &rho_accel_of[3 * (size_t) m];
      hydrostatic += w * (rho_accel[0] * dx + rho_accel[1] * dy + rho_accel[2] * dz);
      if (moving) {
        const double w_rho = w * rho[j];
        weighted_rho_r[0] += w_rho * dx;
        weighted_rho_r[1] += w_rho * dy;
        weighted_rho_r[2] += w_rho * dz;
      }
      for (int k = 0; k < 3; k++) weighted_v[k] += w * v[j][k];
      if (is_solid) {
        fluid_weight[type[j]] += w;
        weighted_mu +=
            w * materials->viscosity_at(type[j], particles.temperature(j), "Fix sph/wall/adami");
      }
    }
    // the wall's own acceleration: P_w gets -a_w . sum_f rho_f r_wf W_wf
    if (moving)
      hydrostatic -= accel[i][0] * weighted_rho_r[0] + accel[i][1] * weighted_rho_r[1] +
          accel[i][2] * weighted_rho_r[2];
    if (is_solid) {
      // the density and viscosity of the fluid at the wall pressure: the
      // kernel-weighted mean over the fluid neighbours' materials
      const double p_wall = (weight > 0.0) ? (weighted_p + hydrostatic) / weight : 0.0;
      // (at the wall's temperature, with thermal expansion)
      const double t_wall = thermal_expansion ? particles.temperature(i) : 0.0;
      double weighted_rho = 0.0, weighted_rho0 = 0.0;
      for (int t = 1; t <= ntypes; t++)
        if (fluid_weight[t] > 0.0) {
          const sphe_eos *eos = materials->eos(t);
          weighted_rho += fluid_weight[t] * sphe_density_at(eos, p_wall, t_wall);
          weighted_rho0 += fluid_weight[t] * sphe_reference_density(eos, t_wall);
        }
      // no fluid in reach: a wall at the background pressure of no fluid, whose
      // density and viscosity no fluid particle sees
      solid_state[i][0] = p_wall;
      solid_state[i][1] = (weight > 0.0) ? weighted_rho / weight : materials->rho0(type[i]);
      solid_state[i][2] = (weight > 0.0) ? weighted_mu / weight : 0.0;
      // its volume compressed as the fluid is: rho0 / rho of the fluid at P_w
      solid_state[i][3] = (weight > 0.0 && weighted_rho > 0.0) ? weighted_rho0 / weighted_rho : 1.0;
      if (weight > 0.0 && solid_state[i][1] <= 0.0) below_eos++;
    } else {
      const sphe_eos *eos = materials->eos(type[i]);
      const double t_wall = eos->thermal ? particles.temperature(i) : 0.0;
      rho[i] = (weight > 0.0) ? sphe_density_at(eos, (weighted_p + hydrostatic) / weight, t_wall)
                              : sphe_density_at(eos, eos->p_background, t_wall);
      if (weight > 0.0 && rho[i] <= 0.0) below_eos++;
    }
    // the no-slip velocity: a solid keeps it apart from its own vest
    double *const no_slip = is_solid ? &solid_state[i][SOLID_VELOCITY] : vest[i];
    const int how = mirror ? ghost_how[i] : SPHI_NONE;
    if (how == SPHI_CORRECTED) {
      // the quadratic through the wall's v at the surface and the fluid's v
      // and its gradient at the mirror point g, at the wall particle: the
      // 1-D profile u(s) = A s + B s^2 (s from the surface, u = v - v_w)
      // with u(d) and u'(d) given has u(-d) = 2 d u'(d) - 3 u(d)
      const double *const fluid = &ghost_velocity[12 * (size_t) i];
      const double *const g = mirror->ghost_point_of(i);
      const double span[3] = {g[0] - x[i][0], g[1] - x[i][1], g[2] - x[i][2]};
      const double span_sq = span[0] * span[0] + span[1] * span[1] + span[2] * span[2];
      double normal_excess = 0.0;
      for (int k = 0; k < 3; k++) {
        const double *const grad = &fluid[3 + 3 * k];
        no_slip[k] = v[i][k] - 3.0 * (fluid[k] - v[i][k]) + grad[0] * span[0] + grad[1] * span[1] +
            grad[2] * span[2];
        normal_excess += (no_slip[k] - (2.0 * v[i][k] - fluid[k])) * span[k];
      }
      // along the normal, the mirror image 2 v_w - v(g): the quadratic
      // amplifies the particles' noise threefold there, which broke up a
      // jittered channel flow; the shear lies in the tangential part
      if (span_sq > 0.0)
        for (int k = 0; k < 3; k++) no_slip[k] -= normal_excess * span[k] / span_sq;
    } else {
      // the image of the fluid's velocity: at the mirror point where the
      // fluid there is too thin for the fit, else Adami's Shepard mean
      for (int k = 0; k < 3; k++) {
        const double fluid = (how == SPHI_SHEPARD) ? ghost_velocity[12 * (size_t) i + k]
            : (weight > 0.0)                       ? weighted_v[k] / weight
                                                   : v[i][k];
        no_slip[k] = 2.0 * v[i][k] - fluid;
      }
    }
  }
}

/* ---------------------------------------------------------------------- */

SPHCommStage FixSPHWallAdami::forward_fields() const
{
  SPHCommStage stage;
  stage.flat(atom->rho, 1).rows(atom->vest, 3);
  if (any_solid) stage.rows(solid_state, SOLID_STATE_SIZE);
  return stage;
}

int FixSPHWallAdami::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                       int * /*pbc*/)
{
  return forward_fields().pack(n, send, buf);
}

void FixSPHWallAdami::unpack_forward_comm(int n, int first, double *buf)
{
  if (any_solid && atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->grow(solid_state, nmax, SOLID_STATE_SIZE, "sph/wall/adami:solid_state");
  }
  forward_fields().unpack_forward(n, first, buf);
}

/* ----------------------------------------------------------------------
   the last velocity sample travels and restarts with its atom (restarts
   continue the acceleration as an uninterrupted run would)
------------------------------------------------------------------------- */

void FixSPHWallAdami::grow_arrays(int nmax_atom)
{
  memory->grow(v_sampled, nmax_atom, 3, "sph/wall/adami:v_sampled");
  memory->grow(accel, nmax_atom, 3, "sph/wall/adami:accel");
}

void FixSPHWallAdami::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < 3; k++) {
    v_sampled[j][k] = v_sampled[i][k];
    accel[j][k] = accel[i][k];
  }
}

void FixSPHWallAdami::set_arrays(int i)
{
  for (int k = 0; k < 3; k++) v_sampled[i][k] = accel[i][k] = 0.0;
}

int FixSPHWallAdami::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 3; k++) buf[k] = v_sampled[i][k];
  return 3;
}

int FixSPHWallAdami::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 3; k++) {
    v_sampled[nlocal][k] = buf[k];
    accel[nlocal][k] = 0.0;
  }
  return 3;
}

int FixSPHWallAdami::pack_restart(int i, double *buf)
{
  buf[0] = 4;
  for (int k = 0; k < 3; k++) buf[1 + k] = v_sampled[i][k];
  return 4;
}

void FixSPHWallAdami::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < 3; k++) {
    v_sampled[nlocal][k] = extra[nlocal][m + k];
    accel[nlocal][k] = 0.0;
  }
}

int FixSPHWallAdami::size_restart(int /*nlocal*/)
{
  return 4;
}

int FixSPHWallAdami::maxsize_restart()
{
  return 4;
}

void FixSPHWallAdami::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double state[2] = {(double) sampled, remaining_sampled};
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state, 2);
}

void FixSPHWallAdami::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  sampled = (int) state[0];
  remaining_sampled = state[1];
}

double FixSPHWallAdami::memory_usage()
{
  return 6.0 * atom->nmax * sizeof(double) +
      (any_solid ? (double) SOLID_STATE_SIZE * nmax * sizeof(double) : 0.0);
}

/* ----------------------------------------------------------------------
   a solid wall does not move: the continuity equation must not change its
   own density (fix sph/stationary integrates rho with esph)
------------------------------------------------------------------------- */

void FixSPHWallAdami::setup(int vflag)
{
  // the setup forces' drho too: fix sph/stationary's first half-step uses it
  post_force(vflag);
}

void FixSPHWallAdami::post_force(int /*vflag*/)
{
  if (!any_solid) return;
  double *const drho = atom->drho;
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && solid_type[atom->type[i]]) drho[i] = 0.0;
}
