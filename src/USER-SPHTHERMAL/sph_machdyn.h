/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_MACHDYN_H
#define LMP_SPH_MACHDYN_H

#include "pointers.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixSPHMaterials;

// The MACHDYN solids of a run: the atom types of LAMMPS's pair smd/tlsph
// (alone or in a hybrid), whose particles hold their energy as MACHDYN
// does (the convention of sph_particle.h). Owned by the hub (fix
// sph/materials), which gives their atoms, before the first force
// evaluation, the solid's cv and reference density rho0 (m / vfrac, checked
// against the type's rho0) and marks them with their type's T0 in the
// per-atom vector SPHParticles::T0_VECTOR before every force evaluation,
// owned and ghost atoms alike (an internal fix property/atom holds it).
class SPHMachdynSolids : protected Pointers {
 public:
  SPHMachdynSolids(LAMMPS *lmp, FixSPHMaterials *materials) :
      Pointers(lmp), materials(materials), vector_fix_made(0), periodic_warned(0)
  {
  }

  // the per-atom vectors of the solids, made with the hub (its post_constructor) and
  // deleted with it
  void create_vector();
  void delete_vector();

  // at the hub's init: the solid types, each checked (the atom style, its
  // properties in fix sph/materials, the styles that act on its atoms)
  void init();
  bool any() const { return !types.empty(); }
  // 1 for a MACHDYN solid type
  int solid(int type) const { return solid_type.empty() ? 0 : solid_type[type]; }
  // the solid types as text, e.g. "2 3", for messages
  std::string type_list() const;
  // at init (fix sph/materials.prepare_solids): cv and rho of the solid atoms
  void setup();
  // at the end of each step: rho = m / (vfrac det F) of the owned solid atoms
  // (the ghosts get it with the next step's communication of atom style sph)
  void follow_deformation();
  // before every force evaluation: the thermal part of the stress rate
  // added to pair smd/tlsph's stress state (types with an expansion)
  void thermal_stress();
  // before every force evaluation: every owned and ghost atom marked,
  // MACHDYN solid or not, with its T0
  void mark();
  // heat that the package's styles add to owned solid atom i during a
  // force evaluation before its pairs are done (a surface flux, the
  // conduction), per particle: the rest of desph is pair smd/tlsph's work
  void note_heat(int i, double rate);
  // after the pairs of a force evaluation: pair smd/tlsph's work in desph
  // replaced by fwork times the plastic work of the evaluation; 'step' (not
  // at a run's set-up) takes the plastic strain as converted and tallies
  void work_to_heat(int step);
  // the tallies since the first run: pair smd/tlsph's work on the solids
  // and the heat converted from their plastic work (sums over all ranks)
  double work_done() const;
  double heat_from_work() const;
  // the tallies read back from a restart file
  void restore_tallies(double work, double heat);

  // the types of pair smd/tlsph (empty without one)
  static std::vector<int> tlsph_types(LAMMPS *lmp);

 private:
  FixSPHMaterials *materials;
  std::vector<int> types, solid_type;
  int vector_fix_made, periodic_warned;
  int unused_warned = 0;                        // a type not a solid has properties of solids
  int expanding = 0;                            // some solid type has a thermal expansion
  int stress_started = 0;                       // the thermal stress's start temperatures were set
  int plastic_started = 0;                      // the converted plastic strains were set
  std::vector<double> noted_heat;               // note_heat's rates, by owned atom
  bigint noted_step = -1;                       // the step they were noted at
  double work_local = 0.0, heat_local = 0.0;    // this rank's tallies
  double *stress_temperature();
  double *converted_strain();
  static constexpr const char *VECTOR_FIX = "SPH_ENERGY_T0";
  // (owned solid atoms) the temperature their thermal stress was last brought to
  static constexpr const char *STRESS_T_VECTOR = "sph_stress_temperature";
  // (owned solid atoms) the effective plastic strain whose work was made heat
  static constexpr const char *PLASTIC_VECTOR = "sph_converted_plastic_strain";
  void check_styles();
  void check_exclusions();
  void check_periodic();
  void check_density();
};

}    // namespace LAMMPS_NS

#endif
