/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SCENE_DEFAULTS_H
#define LMP_SPH_SCENE_DEFAULTS_H

#include <string>

namespace LAMMPS_NS {

class LAMMPS;
class Fix;

// The package's defaults that depend on the kind of scene, in one place:
// the rule, and the sentence the log gives for the value taken. A setting
// given in a command is never changed; a style asks at its init and says
// what it took (SPHSceneDefaults::Choice::log), so that a run's log names
// every numerical setting it did not get from the input.
namespace SPHSceneDefaults {

  struct Choice {
    int value;          // the setting, in the asking style's own code
    std::string why;    // the scene's reason, for the log
    double number;      // the setting's value, for a number (value: which rule)
  };

  // 'correction' of pair sph/cleary/heat: consistent in a flow of shifted
  // particles (fix sph/shift), buoyant or driven, none otherwise
  // (SPHConductionWeights::Kind)
  Choice heat_correction(LAMMPS *lmp);

  // 'correction' of pair sph/harmonic/visc (1: gradient, 0: none): the
  // corrected pressure gradient in a buoyancy-driven flow of shifted
  // particles in 2-d, the plain one otherwise
  Choice pressure_correction(LAMMPS *lmp);

  // 'eta' of pair sph/cleary/heat (number): 0.01 in a buoyancy-driven flow
  // of shifted particles, as the flow pair's, 0.1 (Cleary's) otherwise
  Choice heat_eta(LAMMPS *lmp);

  // 'pressure' of pair sph/harmonic/visc (SPHF_P_* of sph_flow.h): the
  // sum form (P_a + P_b) / (rho_a rho_b) with the unresolved grains of fix
  // sph/grains, the averaged form otherwise; 'correction gradient' given
  // keeps the averaged form it needs
  Choice pressure_form(LAMMPS *lmp, int gradient_given);

  // 'delta' of pair sph/harmonic/visc (number): 0.3 with the unresolved
  // grains of fix sph/grains, 0.1 (Ng et al. 2020) otherwise
  Choice density_diffusion(LAMMPS *lmp);

  // 'artificial' of pair sph/harmonic/visc (number: alpha of Monaghan's
  // artificial viscosity, which acts on pairs with a particle at a free
  // surface and between fluid and walls): 0.1 under weight (fix gravity;
  // one of magnitude 0 weighs nothing),
  // where a free surface may strike walls (the pair turns it off where a
  // run starts without a free surface), 0 otherwise
  Choice artificial_viscosity(LAMMPS *lmp);

  // the fix sph/grains of the scene (its ID), "" when there is none
  std::string grains_fix(LAMMPS *lmp);

  // 'background' of an equation of state of fix sph/materials that gives
  // none (number: the pressure as a multiple of rho0 c0^2): 0.1 in a
  // buoyancy-driven flow of shifted particles, 0.01 in an unshifted flow
  // without weight (fix gravity) or buoyancy whose fluid lies between
  // walls of fix sph/wall/adami along every non-periodic dimension (no
  // free surface), 0 otherwise
  Choice background(LAMMPS *lmp);

  // 'hold' of fix sph/boussinesq 'buoyancy' (1: its group's volume held,
  // 0: not): held in a closed domain, which the buoyancy alone drives (its
  // 'gravity' keyword and no fix gravity: without weight only walls and
  // periodic boundaries keep the fluid together, there is no free surface),
  // when every type of the group is a fluid, none of its atoms a wall of
  // fix sph/wall/adami, and no fix sph/hold/volume but
  // 'own' (the fix's own) holds that group already
  Choice volume_hold(LAMMPS *lmp, const Fix *buoyancy, const Fix *own);

  // log "<who>: <setting> <value> (<why>)" on rank 0 when 'choice' differs
  // from 'last' (the value last logged, -1 before the first); who: e.g.
  // "Pair style sph/cleary/heat"
  void log(LAMMPS *lmp, const char *who, const char *setting, const char *value,
           const Choice &choice, int &last);

}    // namespace SPHSceneDefaults

}    // namespace LAMMPS_NS

#endif
