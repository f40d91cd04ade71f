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
#include "sph_material_laws.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// The package's one place for per-type material properties: every style
// that needs a conductivity (and later viscosity, expansion, EOS) asks it.
class FixSPHMaterials : public Fix {
 public:
  FixSPHMaterials(class LAMMPS *, int, char **);
  ~FixSPHMaterials() override;
  int setmask() override;
  double compute_array(int, int) override;

  // the hub of this run: error (naming 'who') when there is none or several
  static FixSPHMaterials *find(class LAMMPS *, const char *who);

  // conductivity law of a type, nullptr when none was given
  const sphm_law *conductivity(int type) const;
  // 1 when every type has a constant conductivity
  int conductivity_constant() const;
  // specific heat and reference density of a type, -1 when not given
  double cv(int type) const { return cv_type[type]; }
  double rho0(int type) const { return rho0_type[type]; }

 protected:
  int ntypes;
  sphm_law *conductivity_law;
  int *conductivity_set;
  double *cv_type, *rho0_type;
  std::vector<std::vector<double>> table_t, table_p;    // per type

  int parse_property(int ilo, int ihi, const std::vector<std::string> &words, size_t iword,
                     const std::string &where);
  void read_file(const std::string &file, const std::vector<std::string> &names,
                 const std::vector<int> &types);
  double positive(const std::string &word, const std::string &what, const std::string &where,
                  bool zero_ok);
};

}    // namespace LAMMPS_NS

#endif
#endif
