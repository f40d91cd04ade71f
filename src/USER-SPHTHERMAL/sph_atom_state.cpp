/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The per-atom state that the pair styles derive, filled once per force
   evaluation (sph_atom_state.h).
------------------------------------------------------------------------- */

#include "sph_atom_state.h"

#include "atom.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_dirichlet.h"
#include "memory.h"
#include "sph_hub.h"
#include "sph_particle.h"

using namespace LAMMPS_NS;

SPHAtomState::SPHAtomState(LAMMPS *lmp, FixSPHMaterials *materials) :
    Pointers(lmp), materials(materials), filled(0), nmax(0), temperature_of(nullptr),
    mass_of(nullptr), volume_of(nullptr), conductivity_of(nullptr)
{
}

SPHAtomState::~SPHAtomState()
{
  release();
}

void SPHAtomState::release()
{
  memory->destroy(temperature_of);
  memory->destroy(mass_of);
  memory->destroy(volume_of);
  memory->destroy(conductivity_of);
}

void SPHAtomState::init()
{
  dummy_walls.clear();
  for (FixSPHWallDirichlet *wall : SPHHub(lmp).fixes<FixSPHWallDirichlet>())
    dummy_walls.emplace_back(wall->groupbit, wall->wall_temperature());
  filled = 0;
}

void SPHAtomState::grow()
{
  if (atom->nmax <= nmax) return;
  nmax = atom->nmax;
  release();
  memory->create(temperature_of, nmax, "sph/atom_state:temperature");
  memory->create(mass_of, nmax, "sph/atom_state:mass");
  memory->create(volume_of, nmax, "sph/atom_state:volume");
  memory->create(conductivity_of, nmax, "sph/atom_state:conductivity");
  filled = 0;    // new arrays hold nothing yet
}

void SPHAtomState::fill(int fields, const char *who)
{
  grow();
  // what is asked that this evaluation has not filled; the volume and the
  // conductivity are made from the mass and the temperature
  int missing = fields & ~filled;
  if (!missing) return;
  if (missing & VOLUME) missing |= MASS & ~filled;
  if (missing & CONDUCTIVITY) missing |= TEMPERATURE & ~filled;
  const SPHParticles particles(atom);
  const int nall = atom->nlocal + atom->nghost;
  if (missing & TEMPERATURE) particles.temperatures(temperature_of, nall);
  if (missing & MASS) particles.masses(mass_of, nall);
  if (missing & VOLUME) {
    const double *const rho = atom->rho;
    for (int i = 0; i < nall; i++) volume_of[i] = mass_of[i] / rho[i];
  }
  if (missing & CONDUCTIVITY) {
    const int *const type = atom->type;
    const int *const mask = atom->mask;
    for (int i = 0; i < nall; i++) {
      double t = temperature_of[i];
      for (const auto &wall : dummy_walls)
        if (mask[i] & wall.first) t = wall.second;
      conductivity_of[i] = materials->conductivity_at(type[i], t, who);
    }
  }
  filled |= missing;
}
