/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/materials,FixSPHMaterials);
// clang-format on
#else

#ifndef LMP_FIX_SPH_MATERIALS_H
#define LMP_FIX_SPH_MATERIALS_H

#include "fix.h"
#include "sph_atom_state.h"
#include "sph_eos.h"
#include "sph_machdyn.h"
#include "sph_material_laws.h"

#include <cmath>
#include <string>
#include <vector>

namespace LAMMPS_NS {

// The package's one place for per-type material properties: every style
// that needs a conductivity, viscosity, equation of state or expansion
// coefficient asks it.
class FixSPHMaterials : public Fix {
 public:
  FixSPHMaterials(class LAMMPS *, int, char **);
  ~FixSPHMaterials() override;
  void post_constructor() override { solids->create_vector(); }
  int setmask() override;
  double compute_array(int, int) override;
  void *extract(const char *, int &) override;

  // the hub of this run: error (naming 'who') when there is none or several
  static FixSPHMaterials *find(class LAMMPS *, const char *who);

  // conductivity and viscosity laws of a type, nullptr when none was given
  const sphm_law *conductivity(int type) const { return law_of(conductivity_laws, type); }
  const sphm_law *viscosity(int type) const { return law_of(viscosity_laws, type); }
  // 1 when every type with the property has a constant law
  int conductivity_constant() const { return constant(conductivity_laws); }
  int viscosity_constant() const { return constant(viscosity_laws); }
  // a law evaluated at T for an atom, checked: an error (on this rank)
  // naming 'who', the type, T and the value when it is not finite or is
  // negative; a warning, once per type and run, when T is outside a table
  double conductivity_at(int type, double T, const char *who)
  {
    return checked(conductivity_laws[type], type, T, who, "conductivity");
  }
  double viscosity_at(int type, double T, const char *who)
  {
    return checked(viscosity_laws[type], type, T, who, "viscosity");
  }
  void init() override;
  // the per-atom state is stale before every force evaluation; at the
  // first, every 'auto' speed of sound of the run's types must be known
  void setup_pre_force(int) override;
  void pre_force(int) override
  {
    state->stale();
    solids->mark();
    solids->thermal_stress();
  }
  void min_pre_force(int) override { state->stale(); }
  // after the pairs: the MACHDYN solids' work to heat
  void setup_pre_reverse(int, int) override { solids->work_to_heat(0); }
  void pre_reverse(int, int) override { solids->work_to_heat(1); }
  // the work-to-heat tallies
  double compute_vector(int) override;
  // the MACHDYN solids' density follows their deformation
  void end_of_step() override { solids->follow_deformation(); }
  // the per-atom state the pair styles derive, filled once per force
  // evaluation (sph_atom_state.h)
  SPHAtomState &atom_state() { return *state; }

  // equation of state of a type (rho0 filled in), nullptr when none was given
  const sphe_eos *eos(int type) const { return eos_set[type] ? &eos_type[type] : nullptr; }
  // 1 when some type's equation of state has thermal expansion (its
  // pressure depends on T)
  int thermal_expansion() const
  {
    for (int t = 1; t <= ntypes; t++)
      if (eos_set[t] && eos_type[t].thermal) return 1;
    return 0;
  }
  // specific heat, reference density (-1 when not given), expansion
  // coefficient (0 when not given: no buoyancy)
  double cv(int type) const { return cv_type[type]; }
  double rho0(int type) const { return rho0_type[type]; }
  double expansion(int type) const { return expansion_type[type]; }
  // sph/set temperature gave the atoms of a type esph in the convention of a
  // MACHDYN solid (1) or of atom style sph (0) (sph_particle.h)
  void note_energy_convention(int type, int machdyn) { energy_convention[type] = machdyn; }
  int energy_convention_of(int type) const { return energy_convention[type]; }
  // reference temperature of a MACHDYN solid type (NaN when not given)
  double tref(int type) const { return tref_type[type]; }
  // bulk modulus of a MACHDYN solid type (its thermal stress), 0 when not given
  double bulk(int type) const { return bulk_type[type]; }
  // fraction of a MACHDYN solid type's plastic work that becomes heat
  // (Taylor and Quinney's 0.9 when not given)
  double fwork(int type) const { return std::isnan(fwork_type[type]) ? 0.9 : fwork_type[type]; }
  // 1 when a type was given a property that only MACHDYN solids use
  int solid_property_given(int type) const
  {
    return std::isfinite(tref_type[type]) || bulk_type[type] > 0.0 || !std::isnan(fwork_type[type]);
  }
  // heat a style adds to an owned MACHDYN solid atom before the pairs are
  // done (SPHMachdynSolids::note_heat)
  void note_solid_heat(int i, double rate) { solids->note_heat(i, rate); }
  // the MACHDYN solids of the run (pair smd/tlsph's types)
  const SPHMachdynSolids &machdyn() const { return *solids; }
  // find the solids, give their atoms cv and rho and mark them (at this
  // fix's init; a style that writes their energy at its own init calls it
  // first, as the fixes' order is the input's)
  void prepare_solids()
  {
    solids->init();
    solids->setup();
    solids->mark();
  }

  // 'eos ... auto': the speed of sound of a type is found from the scene at
  // the first run (fix sph/boussinesq's buoyancy at its init, the flow's
  // speed scale at the set-up: sph_sound_speed.h); until then c0 = 0
  int sound_speed_pending(int type) const { return c0_kind[type] == C0_PENDING; }
  // 'speed U' of a type's 'auto' eos: the flow's speed scale (0: none given)
  double flow_speed(int type) const { return speed_type[type]; }
  // give a pending type its speed of sound (and a background given
  // relative to rho0 c0^2); the log says the value and 'why'
  void set_sound_speed(int type, double c0, const std::string &why);
  // the speeds found carry across restarts
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  // a law of one type: the C description and the storage of its table
  struct MaterialLaw {
    sphm_law law;
    std::vector<double> table_t, table_p;
    int set;
    int warned;    // the out-of-table warning of this run was given
  };
  int ntypes;
  SPHAtomState *state;
  SPHMachdynSolids *solids;
  std::vector<MaterialLaw> conductivity_laws, viscosity_laws;    // index: type
  sphe_eos *eos_type;
  int *eos_set;
  double *cv_type, *rho0_type, *expansion_type, *tref_type, *bulk_type, *fwork_type;
  std::vector<int> energy_convention;    // per type: -1 not set by sph/set, else machdyn
  enum { C0_GIVEN = 0, C0_PENDING, C0_FOUND };
  int *c0_kind;                   // per type: given, 'auto' pending or found
  double *background_relative;    // per type: 'background B relative' B, else NaN
  int *background_given;          // per type: 1 when its eos names a background
  int background_logged;          // the scene's default last logged (-1: none yet)
  double *speed_type;             // per type: 'speed U' of an 'auto' eos, else 0

  static const sphm_law *law_of(const std::vector<MaterialLaw> &laws, int type)
  {
    return laws[type].set ? &laws[type].law : nullptr;
  }
  static int constant(const std::vector<MaterialLaw> &laws);
  double checked(MaterialLaw &slot, int type, double T, const char *who, const char *property)
  {
    const double value = sphm_law_eval(&slot.law, T);
    if (!sphm_value_valid(value) || !sphm_law_covers(&slot.law, T))
      out_of_range(slot, type, T, value, who, property);
    return value;
  }
  void out_of_range(MaterialLaw &slot, int type, double T, double value, const char *who,
                    const char *property);
  void type_range(const std::string &word, int &ilo, int &ihi);
  int parse_property(int ilo, int ihi, const std::vector<std::string> &words, size_t iword,
                     const std::string &where);
  int parse_law(std::vector<MaterialLaw> &laws, int ilo, int ihi,
                const std::vector<std::string> &words, size_t iword, const std::string &where);
  int parse_eos(int ilo, int ihi, const std::vector<std::string> &words, size_t iword,
                const std::string &where);
  std::string find_material_file(const std::string &file, std::vector<std::string> &tried);
  static std::string input_script_dir();
  void read_file(const std::string &file, const std::vector<std::string> &names,
                 const std::vector<int> &types);
  int apply_relative_background(int type);
  void default_background();
  double positive(const std::string &word, const std::string &what, const std::string &where,
                  bool zero_ok);
};

}    // namespace LAMMPS_NS

#endif
#endif
