/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SOUND_SPEED_H
#define LMP_SPH_SOUND_SPEED_H

#include <cmath>

namespace LAMMPS_NS {

class LAMMPS;
class FixSPHMaterials;

// 'eos ... auto' of fix sph/materials: the speed of sound a weakly
// compressible fluid needs, from the scene. One rule: c0 = SPEED_FACTOR
// times the largest speed U the flow is expected to reach, so that the
// density varies by about (U / c0)^2 = 1 % (Monaghan 1994). Fix
// sph/boussinesq estimates U from its buoyancy; every other flow takes here
// the largest of
//   - the speed its eos gives ('speed U': a driven flow's scale, e.g. the
//     centre-line speed of a channel, which the package cannot see in a fix
//     addforce),
//   - the largest speed of any atom at the run's start (moving walls, an
//     initial flow),
//   - sqrt(|g| H) of fix gravity, H the height of the fluid it acts on along
//     g (only along non-periodic dimensions: a periodic one has no
//     hydrostatic head), so that rho0 |g| H is 1 % of rho0 c0^2.
// Fluids of different rest density get the same rho0 c0^2 (the densest
// one's), which a layered two-fluid scene needs to be stable
// (doc/src/Howto_settings.rst, Two fluids).
namespace SPHSoundSpeed {

  constexpr double SPEED_FACTOR = 10.0;

  // give every pending 'auto' type with atoms its speed of sound by the
  // rule above; an error naming 'who' and the type when U is 0. 'level'
  // (finite) is the free surface's height along -g of sph/set hydrostatic,
  // above the fluid atoms of fix gravity's group that are in 'groupbit'
  // (when not 0)
  void derive(LAMMPS *lmp, FixSPHMaterials *materials, const char *who, int groupbit = 0,
              double level = NAN);

}    // namespace SPHSoundSpeed
}    // namespace LAMMPS_NS

#endif
