/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_PARTICLE_H
#define LMP_SPH_PARTICLE_H

#include "atom.h"

namespace LAMMPS_NS {

// What an SPH particle's state derives from the atom style's arrays, defined
// once for every style: its mass (per-atom rmass where the atom style has it,
// per-type mass otherwise), temperature T = esph / cv and volume m / rho.
// A view of this step's arrays: make one where the arrays are read (they
// move when atoms are added), for owned and ghost atoms alike.
class SPHParticles {
 public:
  explicit SPHParticles(const Atom *atom) :
      rmass((atom->rmass_flag && atom->rmass) ? atom->rmass : nullptr), type_mass(atom->mass),
      type(atom->type), esph(atom->esph), cv(atom->cv), rho(atom->rho)
  {
  }

  double mass(int i) const { return rmass ? rmass[i] : type_mass[type[i]]; }
  double temperature(int i) const { return esph[i] / cv[i]; }
  double volume(int i) const { return mass(i) / rho[i]; }

  // the masses of atoms 0..n-1 into 'out'
  void masses(double *out, int n) const
  {
    if (rmass)
      for (int i = 0; i < n; i++) out[i] = rmass[i];
    else
      for (int i = 0; i < n; i++) out[i] = type_mass[type[i]];
  }
  void temperatures(double *out, int n) const
  {
    for (int i = 0; i < n; i++) out[i] = esph[i] / cv[i];
  }

 private:
  const double *rmass, *type_mass;
  const int *type;
  const double *esph, *cv, *rho;
};

}    // namespace LAMMPS_NS

#endif
