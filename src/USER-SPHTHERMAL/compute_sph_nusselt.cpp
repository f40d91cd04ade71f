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
     no-slip wall, where d2T/dn2 = 0.
------------------------------------------------------------------------- */

#include "compute_sph_nusselt.h"

#include "atom.h"
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

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char cmd[] = "compute sph/nusselt";
// wall atoms within this factor of the smallest ghost depth are the first layer
static constexpr double FIRST_LAYER = 1.1;

/* ---------------------------------------------------------------------- */

ComputeSPHNusselt::ComputeSPHNusselt(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), wall(nullptr), wall_surface(nullptr), delta_t(0.0), length(0.0),
    conductivity(0.0), area(0.0), spacing(0.0), conductivity_type(0), nmax(0), local(nullptr),
    local_heat(nullptr)
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
  tagint stray = MAXTAGINT;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && !(mask[i] & wall->groupbit)) stray = MIN(stray, atom->tag[i]);
  tagint first = MAXTAGINT;
  MPI_Allreduce(&stray, &first, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (first != MAXTAGINT)
    error->all(FLERR, "{}: atom {} of group {} is not in group {} of wall fix {}", cmd, first,
               group->names[igroup], group->names[wall->igroup], wall_id);

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
    gradient_values(first_layer_depth());
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
------------------------------------------------------------------------- */

double ComputeSPHNusselt::wall_spacing(double depth_min)
{
  if (spacing > 0.0) return spacing;
  if (wall->spacing_given() > 0.0) return wall->spacing_given();
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
