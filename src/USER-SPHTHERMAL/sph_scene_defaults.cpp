/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The defaults that depend on the kind of scene (sph_scene_defaults.h).
   Why these: doc/src/Howto_settings.rst. In the differentially heated
   cavity (de Vahl Davis 1983) the consistent conduction gives back the
   1.4-2 % of the wall heat that the plain operator loses on shifted
   particles, and in the heated channel (Ng et al. 2020) it halves the
   downstream temperature error; on unshifted ones (the onset of
   Rayleigh-Benard convection) and on lattices the plain operator is the
   closer one. The corrected pressure gradient in shifted buoyant flows in
   2-d: in the cavity it makes the velocity converge (the plain gradient's
   largest velocity stays 3.5-4 % low at Ra = 1e3 at every resolution) and
   with shifting and the consistent conduction keeps Nu within the
   benchmark's bounds from Ra = 1e3 to 1e6; in the Rayleigh-Benard layer
   above onset the plain gradient puts Nu 1.9 % low. eta: 0.01 in the
   cavity, the tanks and the Rayleigh-Benard layer (shifted, buoyant),
   Cleary's 0.1 in conduction, the channels and around bodies. A
   background pressure of 0.1 rho0 c0^2 keeps shifted buoyant flows from
   opening voids (the cavities, the tanks, the Rayleigh-Benard layer above
   onset); without shifting it would suppress the onset of convection
   (examples/convection-rayleigh-benard), so none there. A flow that walls
   or forces drive, without weight or buoyancy, unshifted, between walls
   (or periodic boundaries) along every dimension, takes 0.01 rho0 c0^2:
   without it the Poiseuille flow of Morris et al. (1997) at 20 across ends
   8.5 % off with |v_y| 2.8 % of u_max, with it 0.44 % (the Couette flow:
   0.39 % and 0.13 %); under weight a free surface takes none; shifted,
   the driven flows need none (the Poiseuille flow with Wendland's kernel
   0.42 % either way, and in the Re = 652 channel, its volume held, 0.01
   rho0 c0^2 raised |v| across the flow from 0.02 to 0.4 % of u_max). The
   volume of a closed convection cell held: the continuity equation lets
   its mean density rise where the flow meets walls (0.6 % per diffusion time in
   the Rayleigh-Benard layer), and the viscosity, diffusivity and Rayleigh
   number the fluid sees drift with it. With the unresolved grains of fix
   sph/grains the fluid's density is its superficial one, which changes
   with the porosity: at the top of a bed, and in a bed of free grains
   poured at random (unittest/grains/in.freebed), the averaged and
   the symmetric pressure forms and a density diffusion of 0.1 let
   round-off grow to speeds of the order of the speed of sound within
   tenths of a second, at every timestep tried (0.05 to 0.2 h / c); the
   sum form with 0.2 and 0.3 keeps the bed at rest (the fluid's speeds
   decay). The sum form's force on a particle carries its absolute
   pressure times the kernel gradient's sum, which is not nil where the
   porosity changes: a background pressure of 0.01 rho0 c0^2 (40 Pa)
   lowered a free bed's pressure drop from 40.4 to 33.5 Pa (at U = 4.5
   mm/s), but without it the liquid's largest speed in a bed at rest grew
   from 4 to 100 mm/s in 0.3 s (unittest/grains/in.freebed): the scene's
   background stays.
------------------------------------------------------------------------- */

#include "sph_scene_defaults.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "fix_sph_boussinesq.h"
#include "fix_sph_grains.h"
#include "fix_sph_hold_volume.h"
#include "fix_sph_materials.h"
#include "fix_sph_shift.h"
#include "fix_sph_wall_adami.h"
#include "lammps.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_conduction_weights.h"
#include "sph_flow.h"
#include "sph_hub.h"
#include "utils.h"

#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

namespace {
// the fix that gives the fluid weight (fix gravity), or nullptr: none, or
// one of magnitude 0 given as a number, which weighs nothing
const Fix *weight_fix(LAMMPS *lmp)
{
  Fix *gravity = SPHBodyForce::source(lmp);
  return (gravity && !SPHBodyForce::constant_zero(gravity)) ? gravity : nullptr;
}

// the id of the run's fix sph/boussinesq, empty without one: a
// buoyancy-driven flow (natural convection, buoyant mixing)
std::string buoyancy_fix(LAMMPS *lmp)
{
  const std::vector<FixSPHBoussinesq *> all = SPHHub(lmp).fixes<FixSPHBoussinesq>();
  return all.empty() ? std::string() : std::string(all.front()->id);
}
}    // namespace

namespace {
// the id of the run's first fix sph/shift in a flow, empty without one
std::string shifted_flow(LAMMPS *lmp)
{
  const std::vector<FixSPHShift *> shifts = SPHHub(lmp).fixes<FixSPHShift>();
  if (shifts.empty() || !SPHHub(lmp).flow()) return std::string();
  return std::string(shifts.front()->id);
}

// in a buoyancy-driven flow of shifted particles, the scene's reason for
// the log; empty otherwise
std::string buoyant_shifted_flow(LAMMPS *lmp)
{
  const std::string buoyancy = buoyancy_fix(lmp);
  const std::string shift = shifted_flow(lmp);
  if (buoyancy.empty() || shift.empty()) return std::string();
  return fmt::format("the default with buoyancy and shifting, fix sph/boussinesq {} and fix "
                     "sph/shift {}",
                     buoyancy, shift);
}
const char without[] = "the default without a buoyancy-driven flow of shifted particles";

// the first non-periodic dimension ("x", "y", "z") along which the fluid
// (atoms whose type has an equation of state, outside the groups of fix
// sph/wall/adami) does not lie between atoms of those walls, where it may
// have a free surface; empty when it lies between walls along every one
std::string open_dimension(LAMMPS *lmp)
{
  int wallbits = 0;
  for (FixSPHWallAdami *wall : SPHHub(lmp).fixes<FixSPHWallAdami>()) wallbits |= wall->groupbit;
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/materials");
  Atom *atom = lmp->atom;
  // per dimension: -lowest, highest of the fluid; -lowest, highest of the walls
  double local[12], all[12];
  for (double &v : local) v = -INFINITY;
  for (int i = 0; i < atom->nlocal; i++) {
    const int wall = (atom->mask[i] & wallbits) != 0;
    if (!wall && !materials->eos(atom->type[i])) continue;
    for (int d = 0; d < 3; d++) {
      local[6 * wall + 2 * d] = fmax(local[6 * wall + 2 * d], -atom->x[i][d]);
      local[6 * wall + 2 * d + 1] = fmax(local[6 * wall + 2 * d + 1], atom->x[i][d]);
    }
  }
  MPI_Allreduce(local, all, 12, MPI_DOUBLE, MPI_MAX, lmp->world);
  static const char *const names[3] = {"x", "y", "z"};
  for (int d = 0; d < lmp->domain->dimension; d++) {
    if (lmp->domain->periodicity[d]) continue;
    if (!(all[6 + 2 * d] > all[2 * d] && all[6 + 2 * d + 1] > all[2 * d + 1])) return names[d];
  }
  return std::string();
}

// a setting (value, number) that is 'on' in a buoyancy-driven flow of
// shifted particles and 'off' otherwise, with the reason for the log
SPHSceneDefaults::Choice by_buoyant_shift(LAMMPS *lmp, int off_value, double off_number,
                                          int on_value, double on_number)
{
  const std::string why = buoyant_shifted_flow(lmp);
  if (why.empty()) return {off_value, without, off_number};
  return {on_value, why, on_number};
}
}    // namespace

SPHSceneDefaults::Choice SPHSceneDefaults::heat_correction(LAMMPS *lmp)
{
  // shifted particles, buoyant or driven: the plain operator loses wall heat
  // on them in the cavity and in the heated channels alike
  const std::string shift = shifted_flow(lmp);
  if (shift.empty())
    return {SPHConductionWeights::NONE, "the default without shifted particles", 0.0};
  return {SPHConductionWeights::CONSISTENT,
          fmt::format("the default with shifting, fix sph/shift {}", shift), 0.0};
}

SPHSceneDefaults::Choice SPHSceneDefaults::pressure_correction(LAMMPS *lmp)
{
  const Choice buoyant = by_buoyant_shift(lmp, 0, 0.0, 1, 0.0);
  // measured in 2-d only; in the 3-d cylindrical tank it made the flow lose
  // its axisymmetry (rings of wall particles are not symmetric about every
  // plane through the axis, and the corrected gradient follows them)
  if (buoyant.value && lmp->domain->dimension == 3)
    return {0,
            "the default in 3-d, with buoyancy and shifting too: there the corrected gradient is "
            "not validated (the cylindrical tank lost its axisymmetry with it)",
            0.0};
  return buoyant;
}

std::string SPHSceneDefaults::grains_fix(LAMMPS *lmp)
{
  const auto grains = SPHHub(lmp).fixes<FixSPHGrains>();
  return grains.empty() ? std::string() : std::string(grains.front()->id);
}

SPHSceneDefaults::Choice SPHSceneDefaults::pressure_form(LAMMPS *lmp, int gradient_given)
{
  const std::string grains = grains_fix(lmp);
  if (grains.empty())
    return {SPHF_P_AVERAGED, "the default without the unresolved grains of fix sph/grains", 0.0};
  if (gradient_given) return {SPHF_P_AVERAGED, "the form that 'correction gradient' needs", 0.0};
  return {SPHF_P_SUM,
          fmt::format("the default with the unresolved grains of fix sph/grains {}: where the "
                      "porosity changes, the averaged and symmetric forms grow unstable",
                      grains),
          0.0};
}

SPHSceneDefaults::Choice SPHSceneDefaults::density_diffusion(LAMMPS *lmp)
{
  const std::string grains = grains_fix(lmp);
  if (grains.empty()) return {0, "the default, Ng et al. 2020", 0.1};
  return {1,
          fmt::format("the default with the unresolved grains of fix sph/grains {}: where the "
                      "porosity changes, 0.1 lets the fluid's speeds grow",
                      grains),
          0.3};
}

SPHSceneDefaults::Choice SPHSceneDefaults::artificial_viscosity(LAMMPS *lmp)
{
  const Fix *weight = weight_fix(lmp);
  if (!weight) return {0, "the default without weight: no free surface to strike walls", 0.0};
  return {
      1,
      fmt::format(
          "the default under the weight of fix {}, where a free surface may strike "
          "walls; it acts on pairs with a particle at a free surface and between fluid and walls, "
          "and not where the run starts without a free surface",
          weight->id),
      0.1};
}

SPHSceneDefaults::Choice SPHSceneDefaults::heat_eta(LAMMPS *lmp)
{
  return by_buoyant_shift(lmp, 0, 0.1, 1, 0.01);
}

SPHSceneDefaults::Choice SPHSceneDefaults::background(LAMMPS *lmp)
{
  const Choice buoyant = by_buoyant_shift(lmp, 0, 0.0, 1, 0.1);
  if (buoyant.value || !buoyancy_fix(lmp).empty()) return buoyant;
  // under weight the fluid may have a free surface
  const Fix *weight = weight_fix(lmp);
  if (weight)
    return {0,
            fmt::format("the default under the weight of fix {}: a free surface takes none",
                        weight->id),
            0.0};
  if (!SPHHub(lmp).flow()) return buoyant;
  const std::string shift = shifted_flow(lmp);
  if (!shift.empty())
    return {0,
            fmt::format("the default in a driven flow of shifted particles (fix sph/shift {}), "
                        "which the shifting keeps ordered",
                        shift),
            0.0};
  const std::string open = open_dimension(lmp);
  if (!open.empty())
    return {0,
            fmt::format("the default without weight or buoyancy when the fluid is not between "
                        "walls of fix sph/wall/adami along {}: a free surface takes none",
                        open),
            0.0};
  return {1,
          "the default in a flow without weight or buoyancy between walls or periodic "
          "boundaries, which walls or forces drive",
          0.01};
}

SPHSceneDefaults::Choice SPHSceneDefaults::volume_hold(LAMMPS *lmp, const Fix *buoyancy,
                                                       const Fix *own)
{
  const Fix *weight = weight_fix(lmp);
  if (weight)
    return {0,
            fmt::format("the default with fix {} (style {}): the fluid has weight and may have a "
                        "free surface",
                        weight->id, weight->style),
            0.0};
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/boussinesq");
  const std::vector<int> present = SPHCheck::group_types(lmp, buoyancy->groupbit);
  for (int t = 1; t < (int) present.size(); t++)
    if (present[t] && !materials->eos(t))
      return {0,
              fmt::format("the default when the group has atom type {}, which has no equation of "
                          "state (a solid)",
                          t),
              0.0};
  // the walls of fix sph/wall/adami take their density from the fluid's
  for (FixSPHWallAdami *wall : SPHHub(lmp).fixes<FixSPHWallAdami>()) {
    int local = 0, any = 0;
    for (int i = 0; i < lmp->atom->nlocal && !local; i++)
      local = (lmp->atom->mask[i] & buoyancy->groupbit) && (lmp->atom->mask[i] & wall->groupbit);
    MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, lmp->world);
    if (any)
      return {0,
              fmt::format("the default when the group has wall atoms of fix sph/wall/adami {}",
                          wall->id),
              0.0};
  }
  for (FixSPHHoldVolume *hold : SPHHub(lmp).fixes<FixSPHHoldVolume>())
    if (hold != own && hold->groupbit == buoyancy->groupbit)
      return {0, fmt::format("fix sph/hold/volume {} holds it already", hold->id), 0.0};
  return {1,
          "the default in a closed domain: buoyancy without weight (no fix gravity, or one of "
          "magnitude 0), so no free surface",
          0.0};
}

void SPHSceneDefaults::log(LAMMPS *lmp, const char *who, const char *setting, const char *value,
                           const Choice &choice, int &last)
{
  if (choice.value == last) return;
  last = choice.value;
  if (lmp->comm->me == 0) utils::logmesg(lmp, "{}: {} {} ({})\n", who, setting, value, choice.why);
}
