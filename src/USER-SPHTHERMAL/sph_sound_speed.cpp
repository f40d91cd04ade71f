/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#include "sph_sound_speed.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_sph_materials.h"
#include "sph_body_force.h"
#include "sph_checks.h"

#include <cmath>
#include <string>
#include <vector>

using namespace LAMMPS_NS;

namespace {

// the speed sqrt(|g| H) of fix gravity's weight: g along the non-periodic
// dimensions, H the height along it of the fluid atoms (types with an eos)
// of fix gravity's group (and of 'groupbit' when not 0), each atom counted
// as a cell of its volume m / rho0; with a finite 'level', from the lowest
// cell's bottom up to that level
double weight_speed(LAMMPS *lmp, FixSPHMaterials *materials, const char *who, int groupbit,
                    double level, double &g_along, double &height)
{
  g_along = height = 0.0;
  Fix *source = SPHBodyForce::source(lmp);
  if (!source || !SPHBodyForce::constant(source)) return 0.0;
  const double *gvec = SPHBodyForce::find(lmp, who);
  SPHBodyForce::check_finite(lmp, FLERR, who, gvec);
  double up[3];
  for (int k = 0; k < 3; k++) {
    up[k] = lmp->domain->periodicity[k] ? 0.0 : -gvec[k];
    g_along += up[k] * up[k];
  }
  g_along = sqrt(g_along);
  if (!(g_along > 0.0)) return 0.0;
  for (int k = 0; k < 3; k++) up[k] /= g_along;
  // the fluid that has weight (of 'groupbit', when given)
  const int weighed = source->groupbit;

  Atom *atom = lmp->atom;
  const int dimension = lmp->domain->dimension;
  double local[2] = {-INFINITY, -INFINITY};    // -(lowest bottom), highest top
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & weighed) || (groupbit && !(atom->mask[i] & groupbit))) continue;
    const sphe_eos *eos = materials->eos(atom->type[i]);
    if (!eos) continue;
    const double mass = atom->rmass_flag ? atom->rmass[i] : atom->mass[atom->type[i]];
    const double half = 0.5 * pow(mass / eos->rho0, 1.0 / dimension);
    const double along = up[0] * atom->x[i][0] + up[1] * atom->x[i][1] + up[2] * atom->x[i][2];
    local[0] = fmax(local[0], half - along);
    local[1] = fmax(local[1], along + half);
  }
  double all[2];
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (!std::isfinite(all[0])) return 0.0;    // no fluid atom
  height = (std::isfinite(level) ? level : all[1]) + all[0];
  return height > 0.0 ? sqrt(g_along * height) : 0.0;
}

}    // namespace

void SPHSoundSpeed::derive(LAMMPS *lmp, FixSPHMaterials *materials, const char *who, int groupbit,
                           double level)
{
  Atom *atom = lmp->atom;
  const std::vector<int> present = SPHCheck::group_types(lmp, 1);    // group all
  int first = 0;
  double given = 0.0, rho0_max = 0.0;
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!present[t] || !materials->sound_speed_pending(t)) continue;
    if (!first) first = t;
    given = fmax(given, materials->flow_speed(t));
    rho0_max = fmax(rho0_max, materials->eos(t)->rho0);
  }
  if (!first) return;

  // the largest speed of any atom now: moving walls, an initial flow
  double moving = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    const double *v = atom->v[i];
    moving = fmax(moving, v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  }
  double moving_all = 0.0;
  MPI_Allreduce(&moving, &moving_all, 1, MPI_DOUBLE, MPI_MAX, lmp->world);
  moving = sqrt(moving_all);

  double g_along = 0.0, height = 0.0;
  const double weight = weight_speed(lmp, materials, who, groupbit, level, g_along, height);
  const double speed = fmax(given, fmax(moving, weight));
  if (!(speed > 0.0) || !std::isfinite(speed))
    lmp->error->all(FLERR,
                    "{}: the speed of sound of atom type {} is 'auto' (fix sph/materials), but "
                    "this scene gives no speed to find it from: no atom moves at the start, no "
                    "fix gravity acts along a non-periodic dimension, no fix sph/boussinesq "
                    "derives it, and its eos gives no 'speed U'; give 'speed U' (the flow's "
                    "largest expected speed) or c0",
                    who, first);

  for (int t = 1; t <= atom->ntypes; t++) {
    if (!present[t] || !materials->sound_speed_pending(t)) continue;
    const double rho0 = materials->eos(t)->rho0;
    const double c0 = SPEED_FACTOR * speed * sqrt(rho0_max / rho0);
    std::string stiffness;
    if (rho0 < rho0_max)
      stiffness = fmt::format(", times sqrt({:.6g} / {:.6g}) for the densest fluid's rho0 c0^2",
                              rho0_max, rho0);
    materials->set_sound_speed(
        t, c0,
        fmt::format("auto: {} times the flow's speed {:.6g}, the largest of the speed its eos "
                    "gives ({:.6g}), the atoms' largest at the start ({:.6g}) and sqrt(|g| H) of "
                    "fix gravity ({:.6g}; |g| = {:.6g}, H = {:.6g}){}",
                    SPEED_FACTOR, speed, given, moving, weight, g_along, height, stiffness));
  }
}
