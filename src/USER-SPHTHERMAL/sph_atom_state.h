/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_ATOM_STATE_H
#define LMP_SPH_ATOM_STATE_H

#include "pointers.h"

#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixSPHMaterials;

// The per-atom state that the pair styles derive from the atom style's
// arrays, stored once and filled at most once per force evaluation, for
// owned and ghost atoms (ghosts carry esph, cv, rho, type and mask, so no
// communication is needed): T = esph / cv, the mass, the volume m / rho
// and the conductivity at T. The hub (fix sph/materials) owns it and marks
// it stale before each force evaluation (its pre_force; fix sph/wall/dirichlet
// writes its dummies' esph in its own pre_force, before any pair reads).
// A style asks for the fields it reads; the first to ask in an evaluation
// fills them, the others read the same arrays. Styles that run outside a
// force evaluation (walls in pre_force, computes, fixes at the step's end)
// derive the same quantities with SPHParticles (sph_particle.h).
class SPHAtomState : protected Pointers {
 public:
  enum Field { TEMPERATURE = 1, MASS = 2, VOLUME = 4, CONDUCTIVITY = 8 };

  SPHAtomState(LAMMPS *lmp, FixSPHMaterials *materials);
  ~SPHAtomState() override;

  // at the hub's init: the walls whose dummies take a wall temperature
  void init();
  // before each force evaluation
  void stale() { filled = 0; }
  // the fields (Field bits) filled for this evaluation; 'who' is named by
  // the errors of the materials' laws
  void fill(int fields, const char *who);

  // per atom, owned and ghost, after fill() of the field
  const double *temperature() const { return temperature_of; }
  const double *mass() const { return mass_of; }
  const double *volume() const { return volume_of; }
  // at T, but at the wall temperature for the dummies of fix
  // sph/wall/dirichlet: their extrapolated T is no state of the material
  // and can lie far outside the range of the law (k = exp(4 T) would choke
  // the wall)
  const double *conductivity() const { return conductivity_of; }

  double memory_usage() const { return 4.0 * nmax * sizeof(double); }

 private:
  FixSPHMaterials *materials;
  int filled;    // Field bits of this evaluation
  int nmax;
  double *temperature_of, *mass_of, *volume_of, *conductivity_of;
  std::vector<std::pair<int, double>> dummy_walls;    // group bit, wall temperature
  void grow();
  void release();
};

}    // namespace LAMMPS_NS

#endif
