/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/nusselt: Nu = q L / (k dT) of a wall of prescribed
   temperature, q the heat flux from the wall into the medium.
   - from the heat: q of the group = minus the heat rate its particles take
     up (the tally of fix sph/wall/dirichlet or sph/wall/isothermal, the
     energy method of Cleary 1998, eq 10) over the wall's area;
   - from the gradient (walls with a surface): q = -k dT/dn on the surface,
     between the wall temperature there and the temperature at the ghost
     point of each wall particle of the first layer (Reece et al. 2024,
     eq 37). This two-point difference is of second order on an isothermal
     no-slip wall, where d2T/dn2 = 0. It needs wall particles in layers
     parallel to a flat surface, the first half a spacing outside it; on a
     staircase (a curved or slanted wall cut from a lattice) the compute
     warns and points to the estimate from the heat (check_surface()).
------------------------------------------------------------------------- */

#include "compute_sph_nusselt.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_dirichlet.h"
#include "fix_sph_wall_tally.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "sph_checks.h"
#include "update.h"
#include "sph_particle.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char cmd[] = "compute sph/nusselt";
// wall atoms within this factor of the smallest ghost depth are the first layer
static constexpr double FIRST_LAYER = 1.1;
// a staircase wall: the first layer's ghost points are not half a spacing
// deep within this fraction of the spacing, or some lie deeper than the
// first layer but less than this factor of its depth (a layered flat wall
// has none below sqrt(2) times it, the vertex of a corner)
static constexpr double HALF_SPACING_TOLERANCE = 0.1;
static constexpr double NEXT_DEPTH = 1.3;

/* ---------------------------------------------------------------------- */

ComputeSPHNusselt::ComputeSPHNusselt(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), wall(nullptr), wall_surface(nullptr), delta_t(0.0), length(0.0),
    conductivity(0.0), area(0.0), spacing(0.0), conductivity_type(0), nmax(0), surface_checked(0),
    staircase_warned(0), staircase_spacing(0.0), local(nullptr), local_heat(nullptr)
{
  if (narg < 7)
    error->all(FLERR, "Illegal {} command: expected <wall-fix-ID> <dT> <length> <conductivity>",
               cmd);
  wall_id = arg[3];
  delta_t = utils::numeric(FLERR, arg[4], false, lmp);
  if (delta_t == 0.0 || !std::isfinite(delta_t))
    error->all(FLERR, "Illegal {} command: temperature difference dT = {} must be finite and not 0",
               cmd, arg[4]);
  length = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(length > 0.0) || !std::isfinite(length))
    error->all(FLERR, "Illegal {} command: length {} must be > 0", cmd, arg[5]);
  int iarg = 6;
  if (strcmp(arg[iarg], "type") == 0) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal {} command: 'type' needs the atom type whose conductivity to use",
                 cmd);
    conductivity_type = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
    if (conductivity_type < 1 || conductivity_type > atom->ntypes)
      error->all(FLERR, "Illegal {} command: conductivity type {} is not an atom type (1-{})", cmd,
                 arg[iarg + 1], atom->ntypes);
    iarg += 2;
  } else {
    conductivity = utils::numeric(FLERR, arg[iarg], false, lmp);
    if (!(conductivity > 0.0) || !std::isfinite(conductivity))
      error->all(FLERR, "Illegal {} command: conductivity {} must be > 0", cmd, arg[iarg]);
    iarg += 1;
  }
  area = pow(length, domain->dimension - 1);
  while (iarg < narg) {
    const bool area_kw = strcmp(arg[iarg], "area") == 0;
    if (area_kw || strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after '{}'", cmd, arg[iarg]);
      const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(value > 0.0) || !std::isfinite(value))
        error->all(FLERR, "Illegal {} command: {} {} must be > 0", cmd, arg[iarg], arg[iarg + 1]);
      (area_kw ? area : spacing) = value;
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }

  find_wall();
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = wall_surface ? 2 : 1;
  extvector = 0;
  vector = new double[size_vector];
  peratom_flag = 1;
  // a per-atom vector (from the heat) or array (heat, gradient)
  size_peratom_cols = wall_surface ? 2 : 0;
}

ComputeSPHNusselt::~ComputeSPHNusselt()
{
  delete[] vector;
  memory->destroy(local);
  memory->destroy(local_heat);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHNusselt::find_wall()
{
  const int ifix = modify->find_fix(wall_id);
  if (ifix < 0) error->all(FLERR, "{}: wall fix {} does not exist", cmd, wall_id);
  Fix *fix = modify->fix[ifix];
  wall = dynamic_cast<FixSPHWallTally *>(fix);
  if (!wall)
    error->all(FLERR,
               "{}: fix {} is {}, not a wall that holds a temperature (sph/wall/dirichlet or "
               "sph/wall/isothermal)",
               cmd, wall_id, fix->style);
  auto dirichlet = dynamic_cast<FixSPHWallDirichlet *>(fix);
  wall_surface = (dirichlet && dirichlet->has_surface()) ? dirichlet : nullptr;
}

void ComputeSPHNusselt::init()
{
  // the fix may have been redefined since; its kind must not have changed
  const int had_surface = wall_surface != nullptr;
  find_wall();
  if ((wall_surface != nullptr) != had_surface)
    error->all(FLERR, "{}: wall fix {} was redefined {} a surface; define the compute anew", cmd,
               wall_id, had_surface ? "without" : "with");

  // the group's atoms are wall atoms of that fix, and there are some (the
  // group can be emptied between the definition and the run)
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "{} {}: group {} has no atoms; give wall atoms of fix {}", cmd, id,
               group->names[igroup], wall_id);
  const int *const mask = atom->mask;
  SPHCheck::FirstBad stray;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && !(mask[i] & wall->groupbit)) stray.consider(atom->tag[i]);
  if (stray.agree(lmp))
    error->all(FLERR, "{}: atom {} of group {} is not in group {} of wall fix {}", cmd, stray.tag,
               group->names[igroup], group->names[wall->igroup], wall_id);

  // the surface is looked at in the first evaluation of the run, once the
  // wall fix has found its ghost points
  surface_checked = 0;
  staircase_spacing = 0.0;

  if (conductivity_type > 0) {
    FixSPHMaterials *hub = FixSPHMaterials::find(lmp, cmd);
    // (pair sph/cleary/heat has made sure that every type has a law)
    const sphm_law *law = hub->conductivity(conductivity_type);
    if (!law || law->kind != SPHM_CONSTANT)
      error->all(FLERR,
                 "{}: the conductivity of type {} is not constant in fix sph/materials; give the "
                 "reference conductivity as a number",
                 cmd, conductivity_type);
    conductivity = hub->conductivity_at(conductivity_type, 0.0, cmd);
    if (!(conductivity > 0.0))
      error->all(FLERR, "{}: the conductivity of type {} is {}; Nu needs k > 0", cmd,
                 conductivity_type, conductivity);
  }
}

/* ----------------------------------------------------------------------
   scalar: mean Nu from the heat
------------------------------------------------------------------------- */

double ComputeSPHNusselt::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  compute_vector();
  scalar = vector[0];
  return scalar;
}

/* ----------------------------------------------------------------------
   1 mean Nu from the heat over the area, 2 mean Nu from the gradient over
   the first layer's atoms
------------------------------------------------------------------------- */

void ComputeSPHNusselt::compute_vector()
{
  invoked_vector = update->ntimestep;
  const int *const mask = atom->mask;
  const double scale = length / (conductivity * delta_t);
  double sums[3] = {0.0, 0.0, 0.0}, total[3];
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) sums[0] -= wall->rate_into(i) * scale;
  if (wall_surface) {
    const double depth_min = first_layer_depth();
    if (!surface_checked) check_surface(depth_min);
    gradient_values(depth_min);
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && local[i][1] != 0.0) {
        sums[1] += local[i][1];
        sums[2] += 1.0;
      }
  }
  MPI_Allreduce(sums, total, 3, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = total[0] / area;
  if (wall_surface) vector[1] = (total[2] > 0.0) ? total[1] / total[2] : 0.0;
}

/* ----------------------------------------------------------------------
   per atom: the local Nu from the heat (the heat of the atoms at one place
   along the wall, summed over the wall's layers, is the local Nu there)
   and from the gradient
------------------------------------------------------------------------- */

void ComputeSPHNusselt::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  const double depth_min = wall_surface ? first_layer_depth() : INFINITY;
  if (wall_surface && !surface_checked) check_surface(depth_min);
  const double element = pow(wall_spacing(depth_min), domain->dimension - 1);
  const double scale = length / (conductivity * delta_t);
  if (wall_surface)
    gradient_values(depth_min);
  else
    grow_local();
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    const double nu = (mask[i] & groupbit) ? -wall->rate_into(i) * scale / element : 0.0;
    if (wall_surface)
      local[i][0] = nu;
    else
      local_heat[i] = nu;
  }
}

void ComputeSPHNusselt::grow_local()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    if (wall_surface) {
      memory->destroy(local);
      memory->create(local, nmax, 2, "sph/nusselt:local");
      array_atom = local;
    } else {
      memory->destroy(local_heat);
      memory->create(local_heat, nmax, "sph/nusselt:local_heat");
      vector_atom = local_heat;
    }
  }
}

/* ----------------------------------------------------------------------
   the smallest depth of a ghost point of the group's atoms below the
   surface (over all ranks), INFINITY when no atom has one
------------------------------------------------------------------------- */

double ComputeSPHNusselt::first_layer_depth()
{
  double depth_min_local = INFINITY, depth_min = INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    double gradient, depth;
    if ((atom->mask[i] & groupbit) && wall_surface->surface_gradient(i, gradient, depth))
      depth_min_local = MIN(depth_min_local, depth);
  }
  MPI_Allreduce(&depth_min_local, &depth_min, 1, MPI_DOUBLE, MPI_MIN, world);
  return depth_min;
}

/* ----------------------------------------------------------------------
   once per run, at the first evaluation with ghost points: is the wall a
   staircase? The gradient estimate takes the wall particles to lie in
   layers parallel to a flat surface, the first half a spacing outside it
   (as fix sph/wall/dirichlet asks): every first-layer ghost point is then
   half a spacing deep, and the next depth is sqrt(2) (the vertex of a
   corner) or 3 times that. Particles cut from a lattice by a curved or
   slanted surface lie at every depth: the shallowest ghost points lie well
   under half a spacing deep (the spacing from the particles' volume,
   (m/rho)^(1/d)), or others lie just deeper than them. There (T_g - T_w)/d
   divides the error of the temperature interpolated at the ghost point by
   a depth that can be a small part of the spacing, and the 'first layer'
   is a few of the wall's particles: on the annulus between two cylinders
   the mean was 1.2 to 2 times the exact Nu, while the heat's was within
   0.1 %. Then a warning (once per compute) that points to the heat, and
   the particles' spacing for the per-atom values when none is given.
------------------------------------------------------------------------- */

void ComputeSPHNusselt::check_surface(double depth_min)
{
  const SPHParticles particles(atom);
  if (!std::isfinite(depth_min)) return;    // no ghost points yet (on any rank)
  surface_checked = 1;
  staircase_spacing = 0.0;
  const int dimension = domain->dimension;
  const int *const mask = atom->mask;
  // the first layer's summed spacing and atoms, the atoms just deeper
  double sums[3] = {0.0, 0.0, 0.0}, total[3];
  for (int i = 0; i < atom->nlocal; i++) {
    double gradient, depth;
    if (!(mask[i] & groupbit) || !wall_surface->surface_gradient(i, gradient, depth)) continue;
    if (depth <= FIRST_LAYER * depth_min) {
      const double mass = particles.mass(i);
      const double rho = atom->rho ? atom->rho[i] : 0.0;
      if (mass > 0.0 && rho > 0.0 && std::isfinite(mass / rho)) {
        sums[0] += pow(mass / rho, 1.0 / dimension);
        sums[1] += 1.0;
      }
    } else if (depth < NEXT_DEPTH * depth_min)
      sums[2] += 1.0;
  }
  MPI_Allreduce(sums, total, 3, MPI_DOUBLE, MPI_SUM, world);
  if (!(total[1] > 0.0)) return;
  const double particle_spacing = total[0] / total[1];
  const double ratio = depth_min / particle_spacing;
  const bool shallow = fabs(ratio - 0.5) > HALF_SPACING_TOLERANCE;
  const bool between = total[2] > 0.0;
  if (!shallow && !between) return;
  staircase_spacing = particle_spacing;
  if (!staircase_warned && comm->me == 0)
    error->warning(FLERR,
                   "{} {}: the wall atoms of group {} do not lie in layers parallel to the surface "
                   "of fix {} (the nearest ghost points lie {:.3g} spacings deep, not 1/2; {} "
                   "lie between 1.1 and 1.3 times as deep): a staircase, as a curved or slanted "
                   "wall cut from a lattice gives. The mean Nu from the gradient (vector element "
                   "2, per-atom column 2) is unreliable there (1.2 to 2.4 times the right value on "
                   "cylinders); use the mean from the heat (the scalar, vector element 1) with "
                   "'area' the wall's {}",
                   cmd, id, group->names[igroup], wall_id, ratio, (bigint) total[2],
                   dimension == 2 ? "length" : "area");
  staircase_warned = 1;
}

/* ----------------------------------------------------------------------
   local[i][1]: Nu from the wall-normal gradient on the surface next to
   each wall atom of the first layer (ghost points within FIRST_LAYER of
   the smallest depth), 0 elsewhere
------------------------------------------------------------------------- */

void ComputeSPHNusselt::gradient_values(double depth_min)
{
  grow_local();
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    local[i][1] = 0.0;
    double gradient, depth;
    if ((mask[i] & groupbit) && wall_surface->surface_gradient(i, gradient, depth) &&
        depth <= FIRST_LAYER * depth_min)
      local[i][1] = -gradient * length / delta_t;
  }
}

/* ----------------------------------------------------------------------
   the spacing of the wall particles along the wall: given here, else to
   the wall fix, else twice the depth of the first layer's ghost points
   (on a staircase: the particles' spacing, (m/rho)^(1/d))
------------------------------------------------------------------------- */

double ComputeSPHNusselt::wall_spacing(double depth_min)
{
  if (spacing > 0.0) return spacing;
  if (wall->spacing_given() > 0.0) return wall->spacing_given();
  if (staircase_spacing > 0.0) return staircase_spacing;
  if (!std::isfinite(depth_min))
    error->all(FLERR,
               "{}: the spacing of the wall particles is unknown: give 'spacing' to the compute or "
               "to fix {}{}",
               cmd, wall_id, wall_surface ? " (or run, so that its ghost points are found)" : "");
  return 2.0 * depth_min;
}

double ComputeSPHNusselt::memory_usage()
{
  return (double) nmax * (wall_surface ? 2 : 1) * sizeof(double);
}
