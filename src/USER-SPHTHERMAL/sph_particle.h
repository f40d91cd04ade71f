/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_PARTICLE_H
#define LMP_SPH_PARTICLE_H

#include "atom.h"
#include "sph_phase_laws.h"

namespace LAMMPS_NS {

// What an SPH particle's state derives from the atom style's arrays, defined
// once for every style: its mass (per-atom rmass where the atom style has it,
// per-type mass otherwise), temperature and volume m / rho.
//
// The energy convention, here and nowhere else. Two kinds of particle hold
// esph differently:
//  - atom style sph (the fluids, the held solids): esph is the specific
//    internal energy, T = esph / cv;
//  - a MACHDYN solid (a type of pair smd/tlsph, in atom_style hybrid sph
//    smd): esph is the particle's internal energy above its type's
//    reference temperature T0, T = T0 + esph / (m cv), as MACHDYN's
//    pair smd/tlsph adds the work of its stress to it and its Johnson-Cook
//    model and equations of state read it.
// fix sph/materials marks the MACHDYN solids: the per-atom vectors
// 'sph_machdyn' (SOLID_VECTOR, 1 for their atoms, 0 for every other atom,
// also for an atom made since the last marking) and 'sph_energy_t0'
// (T0_VECTOR, their T0), for owned and ghost atoms alike (sph_machdyn.h);
// a scene whose atom style is not smd (hybrid) has no such vectors.
// The fluid's density among unresolved grains (fix sph/grains), here and
// nowhere else: there a fluid particle's rho is the superficial density
// eps rho_f (mass of fluid per volume of fluid and grains, as the kernel sum
// and the continuity equation make it), eps the porosity the grains leave
// it, in the per-atom vector 'sph_porosity' (POROSITY_VECTOR, made by fix
// sph/grains, owned and ghost atoms alike, 1 for an atom no grain is near).
// The equation of state and the drag laws see the fluid's own density
// rho_f = rho / eps (the locally averaged equations of the SPH-DEM of
// Robinson, Ramaioli and Luding, Int. J. Multiphase Flow 59 (2014)
// 121-134); without grains rho_f = rho.
// The atoms of a type that melts and solidifies (fix sph/phase) hold in
// esph their specific enthalpy, the latent heat included; T and the liquid
// fraction follow from it by their type's law (sph_phase_laws.h), whose
// solidus, liquidus, latent heat and liquid's specific heat fix sph/phase
// puts on every atom in the per-atom vectors PHASE_*_VECTOR (latent 0: the
// atom does not change phase), owned and ghost atoms alike.
// A view of this step's arrays: make one where the arrays are read (they
// move when atoms are added), for owned and ghost atoms alike.
class SPHParticles {
 public:
  static constexpr const char *SOLID_VECTOR = "sph_machdyn";
  static constexpr const char *T0_VECTOR = "sph_energy_t0";
  static constexpr const char *POROSITY_VECTOR = "sph_porosity";
  static constexpr const char *PHASE_SOLIDUS_VECTOR = "sph_phase_solidus";
  static constexpr const char *PHASE_LIQUIDUS_VECTOR = "sph_phase_liquidus";
  static constexpr const char *PHASE_LATENT_VECTOR = "sph_phase_latent";
  static constexpr const char *PHASE_LIQUID_CV_VECTOR = "sph_phase_liquid_cv";

  explicit SPHParticles(Atom *atom) :
      rmass((atom->rmass_flag && atom->rmass) ? atom->rmass : nullptr), type_mass(atom->mass),
      type(atom->type), esph(atom->esph), cv(atom->cv), rho(atom->rho), solid(nullptr), t0(nullptr),
      porosity(porosity_of(atom)), solidus(vector_of(atom, PHASE_SOLIDUS_VECTOR)),
      liquidus(vector_of(atom, PHASE_LIQUIDUS_VECTOR)),
      latent(vector_of(atom, PHASE_LATENT_VECTOR)),
      liquid_cv(vector_of(atom, PHASE_LIQUID_CV_VECTOR))
  {
    if (!solidus || !liquidus || !liquid_cv) latent = nullptr;
    if (!atom->smd_flag) return;
    int flag, cols;
    const int isolid = atom->find_custom(SOLID_VECTOR, flag, cols);
    const int it0 = atom->find_custom(T0_VECTOR, flag, cols);
    if (isolid < 0 || it0 < 0) return;
    solid = atom->ivector[isolid];
    t0 = atom->dvector[it0];
  }

  double mass(int i) const { return rmass ? rmass[i] : type_mass[type[i]]; }
  double volume(int i) const { return mass(i) / rho[i]; }
  // the fluid's own density (the equation of state's): rho / eps among grains
  double fluid_density(int i) const { return porosity ? rho[i] / porosity[i] : rho[i]; }
  // eps of atom i: 1 without grains
  double porosity_at(int i) const { return porosity ? porosity[i] : 1.0; }
  // the per-atom porosity of fix sph/grains, or nullptr without one
  static double *porosity_of(Atom *atom) { return vector_of(atom, POROSITY_VECTOR); }
  // the per-atom double vector 'name' of a fix property/atom, or nullptr
  static double *vector_of(Atom *atom, const char *name)
  {
    int flag, cols;
    const int index = atom->find_custom(name, flag, cols);
    return (index >= 0 && flag == 1 && cols == 0) ? atom->dvector[index] : nullptr;
  }
  // whether atom i holds its energy as a MACHDYN solid does
  bool machdyn(int i) const { return solid && solid[i]; }
  // whether atom i melts and solidifies (its esph includes the latent heat)
  bool changes_phase(int i) const { return latent && latent[i] > 0.0; }
  SPHPhaseLaw phase_law(int i) const
  {
    return SPHPhaseLaw{solidus[i], liquidus[i], latent[i], liquid_cv[i]};
  }
  double temperature(int i) const
  {
    if (machdyn(i)) return temperature_of_solid(i, t0[i]);
    if (changes_phase(i)) {
      const SPHPhaseLaw law = phase_law(i);
      return sphp_temperature(esph[i], cv[i], &law);
    }
    return esph[i] / cv[i];
  }
  // the liquid fraction of atom i (0 for an atom that does not change phase)
  double liquid_fraction(int i) const
  {
    if (!changes_phase(i)) return 0.0;
    const SPHPhaseLaw law = phase_law(i);
    return sphp_liquid_fraction(esph[i], cv[i], &law);
  }
  // d esph / dT of atom i at its state (not a MACHDYN solid): cv, or in a
  // mushy zone cv + L / (Tl - Ts), 0 at a single melting temperature
  double esph_per_temperature(int i) const
  {
    if (!changes_phase(i)) return cv[i];
    const SPHPhaseLaw law = phase_law(i);
    return sphp_heat_capacity(esph[i], cv[i], &law);
  }
  // the temperature of a MACHDYN solid atom whose type's T0 is t0_type
  // (also before the atoms are marked)
  double temperature_of_solid(int i, double t0_type) const
  {
    return t0_type + esph[i] / (mass(i) * cv[i]);
  }
  // the esph of atom i at temperature T
  double energy_at(int i, double T) const
  {
    if (machdyn(i)) return machdyn_energy(mass(i), cv[i], T, t0[i]);
    if (changes_phase(i)) {
      const SPHPhaseLaw law = phase_law(i);
      return sphp_energy(T, cv[i], &law);
    }
    return cv[i] * T;
  }
  // a MACHDYN solid particle's esph: its energy above T0
  static double machdyn_energy(double m, double cv, double T, double T0)
  {
    return m * cv * (T - T0);
  }
  // the specific heat of atom i's phases without the latent heat (cv, or
  // between the solid's and the liquid's by the liquid fraction): the
  // weight of its temperature in a mean by heat capacity
  double sensible_cv(int i) const
  {
    if (!changes_phase(i)) return cv[i];
    const SPHPhaseLaw law = phase_law(i);
    return sphp_sensible_cv(esph[i], cv[i], &law);
  }
  // the smaller specific heat of atom i's phases (cv where it has one
  // phase): its temperature's fastest response to a heat flow
  double smallest_cv(int i) const
  {
    if (!changes_phase(i)) return cv[i];
    const SPHPhaseLaw law = phase_law(i);
    return sphp_smallest_cv(cv[i], &law);
  }
  // esph per unit of specific energy: a heating rate per unit mass times
  // this is the rate of esph
  double esph_per_specific(int i) const { return machdyn(i) ? mass(i) : 1.0; }
  // the thermal energy m cv T of atom i and its rate of change
  double thermal_energy(int i) const
  {
    return machdyn(i) ? esph[i] + mass(i) * cv[i] * t0[i] : mass(i) * esph[i];
  }
  double heating_rate(int i, const double *desph) const
  {
    return machdyn(i) ? desph[i] : mass(i) * desph[i];
  }

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
    if (solid || latent)
      for (int i = 0; i < n; i++) out[i] = temperature(i);
    else
      for (int i = 0; i < n; i++) out[i] = esph[i] / cv[i];
  }

 private:
  const double *rmass, *type_mass;
  const int *type;
  const double *esph, *cv, *rho;
  const int *solid;          // per atom: 1 for a MACHDYN solid
  const double *t0;          // per atom: its T0
  const double *porosity;    // per atom: eps among grains, or nullptr
  // per atom: the phase law (fix sph/phase), or nullptr
  const double *solidus, *liquidus, *latent, *liquid_cv;
};

}    // namespace LAMMPS_NS

#endif
