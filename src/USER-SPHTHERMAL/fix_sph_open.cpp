/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/open: an inlet or outlet of the fluid with a buffer of particles
   behind a plane (A. Tafuni, J. M. Dominguez, R. Vacondio, A. J. C.
   Crespo, A versatile algorithm for the treatment of open boundary
   conditions in Smoothed particle hydrodynamics GPU models, Computer
   Methods in Applied Mechanics and Engineering 342 (2018) 604-624,
   section 3: buffer particles, their quantities prescribed or
   extrapolated from the fluid at their mirror points across the open
   boundary, particles created and deleted as they cross it).
   - The inlet buffer has the prescribed velocity and temperature (set at
     each run's set-up); each step, before the forces, its density is
     extrapolated to first order, rho_b = rho_g + grad rho_g . (r_b - r_g), from the
     fluid at the mirror point g (Liu & Liu's corrected interpolation,
     sph_interpolation.h); the outlet buffer's density is the equation of
     state's at the prescribed pressure, its velocity and temperature the
     fluid's at g (zero gradient across the plane). The buffer moves with
     its velocity (fix sph does not integrate it).
   - At the end of each step: an inlet buffer particle that has crossed
     the plane joins the fluid's group, and a copy of it (the buffer's
     velocity, density and temperature) waits to enter at the buffer's back,
     one buffer length upstream; a fluid particle that has crossed the
     outlet plane joins the buffer. What crossed is tallied, and so are
     the momentum and heat the buffer gives the fluid through the pair
     styles' forces and conduction across the plane.
   - At the next step's neighbour build (which the fix asks for) the copies
     are created, on the rank whose sub-domain holds them, and outlet
     particles past the buffer's back are deleted.
------------------------------------------------------------------------- */

#include "fix_sph_open.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "dump.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neighbor.h"
#include "output.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_eos.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_kernels.h"
#include "sph_particle.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 2;
// an entering copy: x (3), v (3), type, mask, rho, esph, cv, mass
static constexpr int RECORD = 12;

static const char cmd[] = "fix sph/open";

// A dump sorted by atom ID whose atoms' IDs were 1..N at the run's start
// places each atom at index ID - lowest ID while the count is unchanged
// (LAMMPS's Dump::sort, which exempts only fix gcmc). Atoms created and
// deleted in balance keep the count but not the IDs, and the dump would
// write past its index: such dumps sort by comparing IDs instead.
namespace {
struct DumpSortByComparison : public Dump {
  static void apply(Dump *dump) { dump->*(&DumpSortByComparison::reorderflag) = 0; }
};
}    // namespace

/* ----------------------------------------------------------------------
   fix ID group sph/open inlet|outlet <direction> <position> fluid <group-ID>
       inlet: velocity <U> | velocity parabolic <U_max> <axis> <lo> <hi>,
              temperature <T>
       outlet: pressure <P>
------------------------------------------------------------------------- */

FixSPHOpen::FixSPHOpen(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), kind(INLET), axis(0), direction(1), position(0.0), fluid_group(-1),
    fluidbit(0), profile(UNIFORM), speed(0.0), profile_axis(-1), profile_lo(0.0), profile_hi(0.0),
    temperature_given(0), temperature(0.0), pressure_given(0), pressure(0.0), length(0.0),
    spacing(0.0), kernel_kind(0), cutoff(0.0), materials(nullptr), extrapolated(0)
{
  if (!atom->rho_flag || !atom->esph_flag || !atom->cv_flag || !atom->vest_flag)
    error->all(FLERR, "Fix sph/open requires atom style sph (rho, esph, cv, vest)");
  if (narg < 8)
    error->all(FLERR,
               "Illegal {} command: expected inlet|outlet <direction> <position> fluid "
               "<group-ID>",
               cmd);
  if (strcmp(arg[3], "inlet") == 0)
    kind = INLET;
  else if (strcmp(arg[3], "outlet") == 0)
    kind = OUTLET;
  else
    error->all(FLERR, "Illegal {} command: '{}' must be inlet or outlet", cmd, arg[3]);
  SPHCompat::signed_axis(lmp, FLERR, cmd, "direction", arg[4], "the direction the fluid flows in",
                         axis, direction);
  position = SPHCompat::finite_numeric(lmp, FLERR, cmd, "position", arg[5]);
  if (strcmp(arg[6], "fluid") != 0)
    error->all(FLERR, "Illegal {} command: expected 'fluid <group-ID>' after the position", cmd);
  fluid_group = group->find(arg[7]);
  if (fluid_group < 0)
    error->all(FLERR, "Illegal {} command: fluid group {} does not exist", cmd, arg[7]);
  if (fluid_group == igroup)
    error->all(FLERR,
               "Illegal {} command: the fluid group {} is the fix's own group, the buffer's "
               "particles",
               cmd, arg[7]);
  fluidbit = group->bitmask[fluid_group];

  int velocity_given = 0;
  int iarg = 8;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    if (keyword == "velocity" || keyword == "temperature" || keyword == "pressure") {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after '{}'", cmd, keyword);
      if ((keyword == "pressure") != (kind == OUTLET))
        error->all(FLERR, "Illegal {} command: '{}' is an {} keyword only", cmd, keyword,
                   kind == OUTLET ? "inlet" : "outlet");
    }
    if (keyword == "velocity") {
      velocity_given = 1;
      if (strcmp(arg[iarg + 1], "parabolic") == 0) {
        if (iarg + 5 >= narg)
          error->all(FLERR, "Illegal {} command: velocity parabolic needs <U_max> <axis> <lo> <hi>",
                     cmd);
        profile = PARABOLIC;
        speed = SPHCompat::finite_numeric(lmp, FLERR, cmd, "U_max", arg[iarg + 2]);
        const std::string across = arg[iarg + 3];
        if (across.size() != 1 || across[0] < 'x' || across[0] > 'z' || across[0] - 'x' == axis ||
            (domain->dimension == 2 && across[0] == 'z'))
          error->all(FLERR,
                     "Illegal {} command: velocity parabolic axis '{}' must be x, y or z, "
                     "across the flow (not along it, nor z in 2d)",
                     cmd, across);
        profile_axis = across[0] - 'x';
        profile_lo = SPHCompat::finite_numeric(lmp, FLERR, cmd, "lo", arg[iarg + 4]);
        profile_hi = SPHCompat::finite_numeric(lmp, FLERR, cmd, "hi", arg[iarg + 5]);
        if (!(profile_hi > profile_lo))
          error->all(FLERR, "Illegal {} command: velocity parabolic needs lo < hi, not {} {}", cmd,
                     arg[iarg + 4], arg[iarg + 5]);
        iarg += 6;
      } else {
        profile = UNIFORM;
        speed = SPHCompat::finite_numeric(lmp, FLERR, cmd, "velocity", arg[iarg + 1]);
        iarg += 2;
      }
      if (!(speed > 0.0))
        error->all(FLERR,
                   "Illegal {} command: the inflow speed {} must be > 0 (the direction gives "
                   "its sign)",
                   cmd, speed);
    } else if (keyword == "temperature") {
      temperature = SPHCompat::finite_numeric(lmp, FLERR, cmd, "temperature", arg[iarg + 1]);
      if (!(temperature > 0.0))
        error->all(FLERR, "Illegal {} command: temperature {} must be > 0", cmd, temperature);
      temperature_given = 1;
      iarg += 2;
    } else if (keyword == "pressure") {
      pressure = SPHCompat::finite_numeric(lmp, FLERR, cmd, "pressure", arg[iarg + 1]);
      pressure_given = 1;
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, keyword);
  }
  if (kind == INLET && !velocity_given)
    error->all(FLERR, "Illegal {} command: an inlet needs 'velocity'", cmd);

  for (double &value : crossed) value = 0.0;
  for (double &value : start_half) value = 0.0;
  vector_flag = 1;
  size_vector = NTALLY;
  extvector = 0;
  global_freq = 1;
  restart_global = 1;
  nevery = 1;
  force_reneighbor = 1;
  next_reneighbor = -1;
  comm_forward = 8;
}

int FixSPHOpen::setmask()
{
  return INITIAL_INTEGRATE | PRE_EXCHANGE | PRE_FORCE | END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHOpen::init()
{
  SPHHub hub(lmp);
  const SPHKernelSettings given = hub.require_flow("Fix sph/open")->kernel_settings();
  kernel_kind = given.kind;
  cutoff = given.cutoff;
  materials = FixSPHMaterials::find(lmp, "Fix sph/open");
  const char xyz[] = "xyz";
  if (domain->triclinic) error->all(FLERR, "Fix {} {}: the box must be orthogonal", id, style);
  if (domain->periodicity[axis])
    error->all(FLERR,
               "Fix {} {}: the box is periodic along {}, the open boundary's normal (make it "
               "non-periodic there: boundary f or s)",
               id, style, xyz[axis]);
  if (SPHCheck::groups_overlap(lmp, groupbit, fluidbit))
    error->all(FLERR, "Fix {} {}: the buffer (group {}) shares atoms with the fluid group {}", id,
               style, group->names[igroup], group->names[fluid_group]);
  // the fluid's fix sph moves what crosses into the fluid's group, and
  // nothing else moves the buffer
  int fluid_moved = 0;
  for (int m = 0; m < modify->nfix; m++) {
    Fix *other = modify->fix[m];
    if (!hub.fix_sph_moves(other)) continue;
    if (other->igroup == fluid_group) fluid_moved = 1;
    if (SPHCheck::groups_overlap(lmp, groupbit, other->groupbit))
      error->all(FLERR,
                 "Fix {} {}: fix {} {} moves the buffer's atoms (group {}); the buffer moves "
                 "with its own velocity: give fix {} the fluid group {}",
                 id, style, other->id, other->style, group->names[igroup], other->id,
                 group->names[fluid_group]);
  }
  if (!fluid_moved)
    error->all(FLERR,
               "Fix {} {}: no fix sph moves the fluid group {}: the atoms that cross into "
               "the fluid join that group, and fix sph must move exactly it",
               id, style, group->names[fluid_group]);
  for (FixSPHOpen *other : hub.fixes<FixSPHOpen>())
    if (other != this && SPHCheck::groups_overlap(lmp, groupbit, other->groupbit))
      error->all(FLERR, "Fix {} {}: group {} shares atoms with the buffer of fix {}", id, style,
                 group->names[igroup], other->id);
  // (the flow pair has checked that the buffer's types have an equation of state)
  if (length == 0.0) find_length();
  // the mirror points of the buffer lie up to a buffer length inside the
  // fluid, whose atoms within the cutoff of them this rank must hold
  const double needed = 2.0 * length + cutoff + neighbor->skin;
  if (comm->cutghostuser < needed) comm->cutghostuser = needed;
}

/* ----------------------------------------------------------------------
   the buffer's depth behind the plane, from its atoms as first set up: a
   whole number of spacings (the spacing from the particles' volume), at
   least the kernel's reach and half the skin, so that an atom that enters
   at the back is out of the fluid's reach until it is created
------------------------------------------------------------------------- */

void FixSPHOpen::find_length()
{
  const SPHParticles particles(atom);
  const int dim = domain->dimension;
  double local[2] = {0.0, -INFINITY};    // spacing, depth
  int any = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    any = 1;
    const double volume = particles.mass(i) / materials->eos(atom->type[i])->rho0;
    local[0] = fmax(local[0], pow(volume, 1.0 / dim));
    const double s = downstream_of_plane(atom->x[i]);
    local[1] = fmax(local[1], kind == INLET ? -s : s);
  }
  int any_all = 0;
  MPI_Allreduce(&any, &any_all, 1, MPI_INT, MPI_MAX, world);
  if (!any_all)
    error->all(FLERR,
               "Fix {} {}: group {} has no atoms: create the buffer's particles behind the "
               "plane first",
               id, style, group->names[igroup]);
  double all[2];
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MAX, world);
  spacing = all[0];
  const int layers = (int) std::lround(all[1] / spacing + 0.5);
  length = layers * spacing;
  const double reach = cutoff + 0.5 * neighbor->skin;
  if (length < reach * (1.0 - 1e-9))
    error->all(FLERR,
               "Fix {} {}: the buffer is {:.8g} deep ({} layers of spacing {:.8g}); it must reach "
               "at least the kernel's cutoff plus half the skin, {:.8g} ({} layers)",
               id, style, length, layers, spacing, reach, (int) std::ceil(reach / spacing));
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix {} {}: a buffer of {} layers, {} deep, spacing {}\n", id, style,
                   layers, length, spacing);
}

/* ----------------------------------------------------------------------
   the fluid on its side of the plane, the buffer on the other, and room in
   the box for the atoms that enter or leave at the buffer's back
------------------------------------------------------------------------- */

void FixSPHOpen::check_sides()
{
  const double tolerance = 0.5 * spacing;
  SPHCheck::FirstBad bad;
  for (int i = 0; i < atom->nlocal; i++) {
    const double s = downstream_of_plane(atom->x[i]);
    // the buffer side: upstream of an inlet, downstream of an outlet
    const double behind = (kind == INLET) ? -s : s;
    if ((atom->mask[i] & fluidbit) && behind > tolerance)
      bad.consider(atom->tag[i], 0.0, atom->x[i][axis]);
    else if ((atom->mask[i] & groupbit) && -behind > tolerance)
      bad.consider(atom->tag[i], 1.0, atom->x[i][axis]);
  }
  const char xyz[] = "xyz";
  if (bad.agree(lmp))
    error->all(
        FLERR,
        "Fix {} {}: {} atom {} at {} = {:.8g} lies on the {} side of the plane {} = {:.8g} (the "
        "fluid flows {}{}: an inlet's buffer lies upstream of it, an outlet's "
        "downstream)",
        id, style, bad.info[0] == 0.0 ? "fluid" : "buffer", bad.tag, xyz[axis], bad.info[1],
        bad.info[0] == 0.0 ? "buffer's" : "fluid's", xyz[axis], position, direction > 0 ? '+' : '-',
        xyz[axis]);
  // inlet: copies enter a buffer length behind the plane; outlet: atoms
  // travel up to half a skin past the back before they are deleted
  const double back = position - direction * (kind == INLET ? length : -(length + neighbor->skin));
  if (back < domain->boxlo[axis] - 1e-9 * length || back > domain->boxhi[axis] + 1e-9 * length)
    error->all(
        FLERR,
        "Fix {} {}: the buffer's back, at {} = {:.8g}, lies outside the box ({:.8g} to {:.8g}): "
        "extend the box along {}",
        id, style, xyz[axis], back, domain->boxlo[axis], domain->boxhi[axis], xyz[axis]);
}

/* ---------------------------------------------------------------------- */

void FixSPHOpen::inlet_velocity(const double *x, double *v) const
{
  double u = speed;
  if (profile == PARABOLIC) {
    const double c = x[profile_axis];
    const double width = profile_hi - profile_lo;
    u = (c > profile_lo && c < profile_hi)
        ? 4.0 * speed * (c - profile_lo) * (profile_hi - c) / (width * width)
        : 0.0;
  }
  v[0] = v[1] = v[2] = 0.0;
  v[axis] = direction * u;
}

/* ----------------------------------------------------------------------
   before the first force: the sides checked, the inlet's prescribed
   velocity (so that an 'auto' speed of sound sees it) and temperature set;
   nothing changes them during the run, and the entering copies carry them
------------------------------------------------------------------------- */

void FixSPHOpen::setup_pre_exchange()
{
  // what the last step (of a previous run, or before a restart) left
  if (kind == INLET)
    create_pending(0.0);
  else
    delete_passed();
  next_reneighbor = -1;
  check_sides();
  if (kind != INLET) return;
  const SPHParticles particles(atom);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    inlet_velocity(atom->x[i], atom->v[i]);
    for (int k = 0; k < 3; k++) atom->vest[i][k] = atom->v[i][k];
    if (temperature_given) atom->esph[i] = particles.energy_at(i, temperature);
  }
}

/* ----------------------------------------------------------------------
   the buffer's quantities are found once, at the first run's set-up: later
   set-ups (the next run, a restart) keep those of the last step, with
   which that step's forces were computed, so that a run in pieces follows
   the same path as one run
------------------------------------------------------------------------- */

void FixSPHOpen::setup_pre_force(int /*vflag*/)
{
  if (!extrapolated)
    extrapolate();    // which sends the ghosts their values
  else
    SPHCompat::forward_comm(comm, this);
  extrapolated = 1;
}

void FixSPHOpen::setup(int /*vflag*/)
{
  // after the dumps' init, before the run's first frame
  for (int d = 0; d < output->ndump; d++) DumpSortByComparison::apply(output->dump[d]);
  if (kind != INLET) return;
  // a buffer faster than sound would outrun the pressure that holds it
  double c0 = INFINITY;
  const std::vector<int> types = SPHCheck::group_types(lmp, groupbit);
  for (int t = 1; t <= atom->ntypes; t++)
    if (materials->eos(t) && types[t]) c0 = fmin(c0, materials->eos(t)->c0);
  if (!(speed < c0))
    error->all(FLERR,
               "Fix {} {}: the inflow speed {} is not below the buffer's speed of sound {}: "
               "weakly compressible SPH needs c0 of about 10 times the largest speed",
               id, style, speed, c0);
}

/* ----------------------------------------------------------------------
   the buffer moves with its velocity
------------------------------------------------------------------------- */

void FixSPHOpen::initial_integrate(int /*vflag*/)
{
  // the fluid's half step now applies the last forces and heat rates
  for (double &value : start_half) value = 0.0;
  add_buffer_half_step(start_half);
  const double dtv = update->dt;
  double **x = atom->x, **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) x[i][k] += dtv * v[i][k];
  }
}

/* ----------------------------------------------------------------------
   the buffer's quantities, before the forces; the ghosts get them
------------------------------------------------------------------------- */

void FixSPHOpen::pre_force(int /*vflag*/)
{
  extrapolate();
}

void FixSPHOpen::extrapolate()
{
  const SPHParticles particles(atom);
  double *const *const x = atom->x;
  double *const *const v = atom->v;
  double *const *const vest = atom->vest;
  double *const rho = atom->rho;
  double *const esph = atom->esph;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const sphk_kernel kernel = sphk_make(kernel_kind, dim, cutoff);

  // the fluid within reach of the mirror points, binned
  not_near.assign(nall, 1);
  const double reach = length + cutoff;
  for (int j = 0; j < nall; j++) {
    if (!(mask[j] & fluidbit)) continue;
    const double s = downstream_of_plane(x[j]);
    const double inside = (kind == INLET) ? s : -s;
    if (inside < reach) not_near[j] = 0;
  }
  cells.bin(x, not_near.data(), nall, 1, cutoff);

  const int nfields = (kind == INLET) ? 1 : 4;    // rho; or v (3) and T
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double g[3] = {x[i][0], x[i][1], x[i][2]};
    g[axis] = 2.0 * position - x[i][axis];
    sphi_point point[4];
    for (int f = 0; f < nfields; f++) sphi_begin(&point[f], dim);
    cells.within(x, g, cutoff, [&](int j) {
      const double d[3] = {x[j][0] - g[0], x[j][1] - g[1], x[j][2] - g[2]};
      const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      const double w = sphk_w(&kernel, r), dwdr = sphk_dwdr(&kernel, r);
      const double volume = particles.volume(j);
      if (kind == INLET)
        sphi_add(&point[0], d, r, w, dwdr, volume, rho[j]);
      else {
        for (int k = 0; k < 3; k++) sphi_add(&point[k], d, r, w, dwdr, volume, v[j][k]);
        sphi_add(&point[3], d, r, w, dwdr, volume, particles.temperature(j));
      }
    });
    const sphe_eos *eos = materials->eos(type[i]);
    if (kind == INLET) {
      double value = rho[i], grad[3];
      const int how = sphi_solve(&point[0], kernel.h, &value, grad);
      if (how == SPHI_CORRECTED)
        for (int k = 0; k < 3; k++) value += grad[k] * (x[i][k] - g[k]);
      // (the flow pair checks every atom's density before it is used)
      rho[i] = value;
    } else {
      const double p = pressure_given ? pressure : eos->p_background;
      rho[i] = sphe_density_at(eos, p, particles.temperature(i));
      if (!(rho[i] > 0.0) || !std::isfinite(rho[i]))
        SPHCheck::nonfinite(lmp, FLERR, "Fix sph/open", "density at the outlet pressure", i, rho[i],
                            fmt::format("pressure {} and its equation of state", p));
      double value[4];
      int found = 1;
      for (int f = 0; f < 4; f++) {
        value[f] = (f < 3) ? v[i][f] : particles.temperature(i);
        if (sphi_solve(&point[f], kernel.h, &value[f], nullptr) == SPHI_NONE) found = 0;
      }
      if (!found) continue;    // no fluid near: it keeps its own
      for (int k = 0; k < 3; k++) v[i][k] = vest[i][k] = value[k];
      esph[i] = particles.energy_at(i, value[3]);
    }
  }
  SPHCompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   what crossed the plane in this step changes sides
------------------------------------------------------------------------- */

void FixSPHOpen::end_of_step()
{
  const SPHParticles particles(atom);
  double *const *const x = atom->x;
  double *const *const v = atom->v;
  int *const mask = atom->mask;
  // atoms, mass, momentum, energy crossed; the atoms to create or delete;
  // the buffer's force and heat over the step's two halves
  double local[11] = {0.0};
  for (int k = 0; k < 4; k++) local[7 + k] = start_half[k];
  add_buffer_half_step(local + 7);
  for (int i = 0; i < atom->nlocal; i++) {
    const double s = downstream_of_plane(x[i]);
    int crosses = 0;
    if (kind == INLET && (mask[i] & groupbit) && s >= 0.0) {
      // its copy enters at the buffer's back, as it was here
      double record[RECORD];
      for (int k = 0; k < 3; k++) record[k] = x[i][k];
      record[axis] -= direction * length;
      for (int k = 0; k < 3; k++) record[3 + k] = v[i][k];
      record[6] = atom->type[i];
      record[7] = mask[i];
      record[8] = atom->rho[i];
      record[9] = atom->esph[i];
      record[10] = atom->cv[i];
      record[11] = particles.mass(i);
      pending.insert(pending.end(), record, record + RECORD);
      mask[i] = (mask[i] & ~groupbit) | fluidbit;
      crosses = 1;
    } else if (kind == OUTLET && (mask[i] & fluidbit) && s >= 0.0) {
      mask[i] = (mask[i] & ~fluidbit) | groupbit;
      crosses = 1;
    } else if (kind == OUTLET && (mask[i] & groupbit) && s > length)
      local[6] += 1.0;
    if (!crosses) continue;
    // the ghosts' masks change at the next neighbour build, which it asks for
    local[6] += 1.0;
    const double m = particles.mass(i);
    local[0] += 1.0;
    local[1] += m;
    for (int k = 0; k < 3; k++) local[2 + k] += m * v[i][k];
    local[5] += m * atom->esph[i];
  }
  double all[11];
  MPI_Allreduce(local, all, 11, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < 6; k++) crossed[k] += all[k];
  // what the buffer took from the rest the fluid gave up (the pair styles
  // conserve momentum and energy pair by pair): into the fluid at an
  // inlet, out of it at an outlet
  const double sign = (kind == INLET) ? -1.0 : 1.0;
  for (int k = 0; k < 3; k++) crossed[FORCE_MOMENTUM + k] += sign * all[7 + k];
  crossed[CONDUCTED_HEAT] += sign * all[10];
  if (all[6] > 0.0) next_reneighbor = update->ntimestep + 1;
}

/* ----------------------------------------------------------------------
   fix sph moves the fluid by half steps, v += dt/2 f / m and
   esph += dt/2 desph, at the step's start with the last forces and at its
   end with the new ones, for the atoms of the fluid group at that time.
   The buffer's atoms at those times get none: their force and heat rate
   (from every pair with the fluid, the walls and other buffers, the last
   two summing to zero over a step) are what the fluid gave up across the
   plane
------------------------------------------------------------------------- */

void FixSPHOpen::add_buffer_half_step(double *half) const
{
  const SPHParticles particles(atom);
  const double dt_half = 0.5 * update->dt * force->ftm2v;
  const int *const mask = atom->mask;
  const double *const *const f = atom->f;
  const double *const desph = atom->desph;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int k = 0; k < 3; k++) half[k] += dt_half * f[i][k];
    half[3] += dt_half * particles.mass(i) * desph[i];
  }
}

/* ----------------------------------------------------------------------
   at a neighbour build: the copies enter, the outlet's passed atoms leave
------------------------------------------------------------------------- */

void FixSPHOpen::pre_exchange()
{
  // the copies left at the end of the last step; the buffer has moved
  // once since
  if (kind == INLET)
    create_pending(update->dt);
  else
    delete_passed();
}

void FixSPHOpen::create_pending(double moved_for)
{
  const int nprocs = comm->nprocs;
  int mine = pending.size();
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    offsets[p] = total;
    total += counts[p];
  }
  if (total == 0) return;
  std::vector<double> records(total);
  MPI_Allgatherv(pending.data(), mine, MPI_DOUBLE, records.data(), counts.data(), offsets.data(),
                 MPI_DOUBLE, world);
  pending.clear();
  const double *sublo = domain->sublo, *subhi = domain->subhi;
  const int nrecords = total / RECORD;
  // IDs in the order of the copies' places across the flow, whatever rank
  // made each: the buffer moves along the axis only, so those coordinates
  // are the same on any number of ranks (and no two copies share them)
  std::vector<int> order(nrecords);
  for (int r = 0; r < nrecords; r++) order[r] = r;
  const int across[2] = {(axis + 1) % 3, (axis + 2) % 3};
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double *ra = &records[(size_t) a * RECORD], *rb = &records[(size_t) b * RECORD];
    const double ka[2] = {ra[across[0]], ra[across[1]]}, kb[2] = {rb[across[0]], rb[across[1]]};
    return std::lexicographical_compare(ka, ka + 2, kb, kb + 2);
  });
  tagint maxtag = 0, maxtag_all = 0;
  for (int i = 0; i < atom->nlocal; i++) maxtag = std::max(maxtag, atom->tag[i]);
  MPI_Allreduce(&maxtag, &maxtag_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  for (int n = 0; n < nrecords; n++) {
    const double *record = &records[(size_t) order[n] * RECORD];
    // where it is now: the buffer moved since its copy was recorded
    double x[3];
    for (int k = 0; k < 3; k++) x[k] = record[k] + moved_for * record[3 + k];
    imageint image = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    bool here = true;
    for (int k = 0; k < 3; k++)
      here = here && x[k] >= sublo[k] &&
          (x[k] < subhi[k] || (subhi[k] >= domain->boxhi[k] && x[k] <= subhi[k]));
    if (!here) continue;
    atom->avec->create_atom((int) record[6], x);
    const int i = atom->nlocal - 1;
    atom->tag[i] = maxtag_all + 1 + n;
    atom->image[i] = image;
    atom->mask[i] = (int) record[7];
    for (int k = 0; k < 3; k++) atom->v[i][k] = atom->vest[i][k] = record[3 + k];
    atom->rho[i] = record[8];
    atom->esph[i] = record[9];
    atom->cv[i] = record[10];
    if (atom->rmass_flag) atom->rmass[i] = record[11];
    modify->create_attribute(i);
  }
  // each copy lies in the box (check_sides), so on exactly one rank
  atom->natoms += nrecords;
  if (atom->map_style != Atom::MAP_NONE) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

void FixSPHOpen::delete_passed()
{
  int deleted = 0;
  for (int i = atom->nlocal - 1; i >= 0; i--) {
    if (!(atom->mask[i] & groupbit) || downstream_of_plane(atom->x[i]) <= length) continue;
    atom->avec->copy(atom->nlocal - 1, i, 1);
    atom->nlocal--;
    deleted++;
  }
  bigint mine = deleted, all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all == 0) return;
  atom->natoms -= all;
  if (atom->map_style != Atom::MAP_NONE) {
    atom->nghost = 0;
    atom->map_init();
    atom->map_set();
  }
}

/* ----------------------------------------------------------------------
   since the first run, into the fluid at an inlet and out of it at an
   outlet: 1 atoms, 2 mass, 3-5 momentum, 6 thermal energy (m esph) that
   crossed the plane; 7-9 momentum by the forces across it (pressure and
   viscous), 10 heat conducted across it
------------------------------------------------------------------------- */

double FixSPHOpen::compute_vector(int n)
{
  return crossed[n];
}

/* ---------------------------------------------------------------------- */

int FixSPHOpen::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    buf[m++] = atom->rho[j];
    buf[m++] = atom->esph[j];
    for (int c = 0; c < 3; c++) buf[m++] = atom->v[j][c];
    for (int c = 0; c < 3; c++) buf[m++] = atom->vest[j][c];
  }
  return m;
}

void FixSPHOpen::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int j = first; j < first + n; j++) {
    if (!(atom->mask[j] & groupbit)) {
      m += 8;
      continue;
    }
    atom->rho[j] = buf[m++];
    atom->esph[j] = buf[m++];
    for (int c = 0; c < 3; c++) atom->v[j][c] = buf[m++];
    for (int c = 0; c < 3; c++) atom->vest[j][c] = buf[m++];
  }
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   the buffer's length and spacing, the tallies, and the copies waiting to
   enter (gathered from every rank: this is called on each)
------------------------------------------------------------------------- */

void FixSPHOpen::write_restart(FILE *fp)
{
  const int nprocs = comm->nprocs;
  int mine = pending.size();
  std::vector<int> counts(nprocs), offsets(nprocs, 0);
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  int total = 0;
  for (int p = 0; p < nprocs && comm->me == 0; p++) {
    offsets[p] = total;
    total += counts[p];
  }
  std::vector<double> state = {length, spacing};
  for (double value : crossed) state.push_back(value);
  state.push_back(extrapolated);
  state.push_back(total / RECORD);
  const size_t head = state.size();
  state.resize(head + total);
  MPI_Gatherv(pending.data(), mine, MPI_DOUBLE, state.data() + head, counts.data(), offsets.data(),
              MPI_DOUBLE, 0, world);
  if (comm->me == 0) SPHCheck::write_restart_state(fp, RESTART_VERSION, state.data(), state.size());
}

void FixSPHOpen::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  length = state[0];
  spacing = state[1];
  for (int k = 0; k < NTALLY; k++) crossed[k] = state[2 + k];
  extrapolated = (int) state[2 + NTALLY];
  const int nrecords = (int) state[3 + NTALLY];
  // rank 0 holds them; they are created at the next run's set-up
  pending.clear();
  const double *const records = state + 4 + NTALLY;
  if (comm->me == 0) pending.assign(records, records + (size_t) nrecords * RECORD);
}
