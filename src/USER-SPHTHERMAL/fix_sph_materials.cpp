/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/materials: per-type material properties, given in the input
   or read from a material file (potentials/NAME.sphmat), for every style of
   the package.
------------------------------------------------------------------------- */

#include "fix_sph_materials.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "potential_file_reader.h"
#include "sph_checks.h"
#include "tokenizer.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/materials";

/* ---------------------------------------------------------------------- */

FixSPHMaterials::FixSPHMaterials(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), eos_type(nullptr), eos_set(nullptr), cv_type(nullptr),
    rho0_type(nullptr), expansion_type(nullptr)
{
  ntypes = atom->ntypes;
  conductivity_laws.resize(ntypes + 1);
  viscosity_laws.resize(ntypes + 1);
  for (int i = 0; i <= ntypes; i++) {
    memset(&conductivity_laws[i].law, 0, sizeof(sphm_law));
    memset(&viscosity_laws[i].law, 0, sizeof(sphm_law));
    conductivity_laws[i].set = viscosity_laws[i].set = 0;
    conductivity_laws[i].warned = viscosity_laws[i].warned = 0;
  }
  eos_type = new sphe_eos[ntypes + 1];
  memset(eos_type, 0, (ntypes + 1) * sizeof(sphe_eos));
  memory->create(eos_set, ntypes + 1, "sph/materials:eos_set");
  memory->create(cv_type, ntypes + 1, "sph/materials:cv");
  memory->create(rho0_type, ntypes + 1, "sph/materials:rho0");
  memory->create(expansion_type, ntypes + 1, "sph/materials:expansion");
  for (int i = 0; i <= ntypes; i++) {
    eos_set[i] = 0;
    cv_type[i] = rho0_type[i] = expansion_type[i] = -1.0;
  }

  if (narg < 4)
    error->all(FLERR, "Illegal {} command: expected 'type <I> <property> ...' or 'file ...'", cmd);

  // global array, one row per type: rho0, cv (for input scripts: masses, set sph/cv)
  array_flag = 1;
  size_array_rows = ntypes;
  size_array_cols = 2;
  extarray = 0;
  global_freq = 1;

  std::vector<std::string> words(arg + 3, arg + narg);
  size_t iword = 0;
  while (iword < words.size()) {
    if (words[iword] == "type") {
      if (iword + 1 >= words.size())
        error->all(FLERR, "Illegal {} command: missing atom type after 'type'", cmd);
      int ilo, ihi;
      type_range(words[iword + 1], ilo, ihi);
      const std::string where = fmt::format("{} command, type {}", cmd, words[iword + 1]);
      iword += 2;
      if (iword >= words.size() || words[iword] == "type" || words[iword] == "file")
        error->all(FLERR, "Illegal {}: no property given", where);
      while (iword < words.size() && words[iword] != "type" && words[iword] != "file")
        iword += parse_property(ilo, ihi, words, iword, where);
    } else if (words[iword] == "file") {
      if (iword + 3 >= words.size())
        error->all(FLERR, "Illegal {} command: expected 'file <path> <material> <type> ...'", cmd);
      const std::string file = words[iword + 1];
      std::vector<std::string> names;
      std::vector<int> types;
      iword += 2;
      while (iword + 1 < words.size() && words[iword] != "type" && words[iword] != "file") {
        int ilo, ihi;
        type_range(words[iword + 1], ilo, ihi);
        for (int i = ilo; i <= ihi; i++) {
          names.push_back(words[iword]);
          types.push_back(i);
        }
        iword += 2;
      }
      if (iword < words.size() && words[iword] != "type" && words[iword] != "file")
        error->all(FLERR, "Illegal {} command: material '{}' of file {} has no atom type", cmd,
                   words[iword], file);
      read_file(file, names, types);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, words[iword]);
  }

  // an equation of state is relative to the reference density of its type
  for (int i = 1; i <= ntypes; i++) {
    if (!eos_set[i]) continue;
    if (rho0_type[i] <= 0.0)
      error->all(FLERR, "Illegal {} command: type {} has an equation of state but no rho0", cmd,
                 i);
    eos_type[i].rho0 = rho0_type[i];
  }
}

/* ---------------------------------------------------------------------- */

FixSPHMaterials::~FixSPHMaterials()
{
  delete[] eos_type;
  memory->destroy(eos_set);
  memory->destroy(cv_type);
  memory->destroy(rho0_type);
  memory->destroy(expansion_type);
}

/* ---------------------------------------------------------------------- */

int FixSPHMaterials::setmask()
{
  return 0;
}

/* ----------------------------------------------------------------------
   every run warns again about temperatures outside a table
------------------------------------------------------------------------- */

void FixSPHMaterials::init()
{
  for (int i = 0; i <= ntypes; i++) conductivity_laws[i].warned = viscosity_laws[i].warned = 0;
}

/* ----------------------------------------------------------------------
   a law left its range at T (sphm_value_valid, sphm_law_covers): a value
   that is no conductivity or viscosity stops the run; a table evaluated
   beyond its ends is held at its end value, which may be intended
------------------------------------------------------------------------- */

void FixSPHMaterials::out_of_range(MaterialLaw &slot, int type, double T, double value,
                                   const char *who, const char *property)
{
  const char *law = sphm_law_name(slot.law.kind);
  if (!sphm_value_valid(value))
    SPHCheck::stop(lmp,
                   fmt::format("{}: {} of atom type {} is {} at T = {} ({} law of fix "
                               "sph/materials); it must be finite and >= 0",
                               who, property, type, value, T, law));
  if (!slot.warned) {
    slot.warned = 1;
    error->warning(FLERR,
                   "{}: T = {} of an atom of type {} is outside its {} table ({} to {}); the "
                   "{} is held at the end value {}",
                   who, T, type, property, slot.law.table_t[0],
                   slot.law.table_t[slot.law.ntable - 1], property, value);
  }
}

/* ----------------------------------------------------------------------
   atom types I, I*J, *J, I*, *: an empty range is named as such
------------------------------------------------------------------------- */

void FixSPHMaterials::type_range(const std::string &word, int &ilo, int &ihi)
{
  const size_t star = word.find('*');
  if (star != std::string::npos && star > 0 && star + 1 < word.size()) {
    const int lo = utils::inumeric(FLERR, word.substr(0, star).c_str(), false, lmp);
    const int hi = utils::inumeric(FLERR, word.substr(star + 1).c_str(), false, lmp);
    if (lo > hi)
      error->all(FLERR, "Illegal {} command: atom type range {} is empty (first type {} > last {})",
                 cmd, word, lo, hi);
  }
  utils::bounds(FLERR, word, 1, ntypes, ilo, ihi, error);
}

/* ----------------------------------------------------------------------
   row = type - 1; column 0: rho0, 1: cv (-1 when not given)
------------------------------------------------------------------------- */

double FixSPHMaterials::compute_array(int row, int column)
{
  return (column == 0) ? rho0_type[row + 1] : cv_type[row + 1];
}

/* ---------------------------------------------------------------------- */

FixSPHMaterials *FixSPHMaterials::find(LAMMPS *lmp, const char *who)
{
  FixSPHMaterials *hub = nullptr;
  int count = 0;
  for (int i = 0; i < lmp->modify->nfix; i++)
    if (strcmp(lmp->modify->fix[i]->style, "sph/materials") == 0) {
      hub = (FixSPHMaterials *) lmp->modify->fix[i];
      count++;
    }
  if (count == 0) lmp->error->all(FLERR, "{} requires fix sph/materials (the material properties)", who);
  if (count > 1) lmp->error->all(FLERR, "{}: only one fix sph/materials may be defined", who);
  return hub;
}

int FixSPHMaterials::constant(const std::vector<MaterialLaw> &laws)
{
  for (const auto &slot : laws)
    if (slot.set && slot.law.kind != SPHM_CONSTANT) return 0;
  return 1;
}

/* ----------------------------------------------------------------------
   one property of types ilo..ihi from words[iword]; returns the number
   of words it took
------------------------------------------------------------------------- */

int FixSPHMaterials::parse_property(int ilo, int ihi, const std::vector<std::string> &words,
                                    size_t iword, const std::string &where)
{
  const std::string &name = words[iword];
  const size_t left = words.size() - iword - 1;

  if (name == "cv" || name == "rho0") {
    if (left < 1) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    const double value = positive(words[iword + 1], name, where, false);
    for (int i = ilo; i <= ihi; i++) (name == "cv" ? cv_type : rho0_type)[i] = value;
    return 2;
  }

  if (name == "expansion") {
    if (left < 1) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    const double value = utils::numeric(FLERR, words[iword + 1].c_str(), false, lmp);
    for (int i = ilo; i <= ihi; i++) expansion_type[i] = value;
    return 2;
  }
  if (name == "conductivity") return parse_law(conductivity_laws, ilo, ihi, words, iword, where);
  if (name == "viscosity") return parse_law(viscosity_laws, ilo, ihi, words, iword, where);
  if (name == "eos") return parse_eos(ilo, ihi, words, iword, where);

  error->all(FLERR,
             "Illegal {}: unknown property '{}' (conductivity, viscosity, eos, cv, rho0 or "
             "expansion)",
             where, name);
  return 0;
}

/* ----------------------------------------------------------------------
   '<property> <law> <coefficients>' of types ilo..ihi (property:
   conductivity or viscosity, both >= 0); returns the number of words taken
------------------------------------------------------------------------- */

int FixSPHMaterials::parse_law(std::vector<MaterialLaw> &laws, int ilo, int ihi,
                               const std::vector<std::string> &words, size_t iword,
                               const std::string &where)
{
  const std::string &what = words[iword];
  const size_t left = words.size() - iword - 1;
  if (left < 1) error->all(FLERR, "Illegal {}: missing law after '{}'", where, what);
  const int kind = sphm_law_lookup(words[iword + 1].c_str());
  if (kind < 0)
    error->all(FLERR, "Illegal {}: unknown {} law '{}' (constant, linear, exponential or table)",
               where, what, words[iword + 1]);
  sphm_law law;
  memset(&law, 0, sizeof(law));
  law.kind = kind;
  int ncoeffs = sphm_law_ncoeffs(kind);
  std::vector<double> t, p;
  if (kind == SPHM_TABLE) {
    if (left < 2) error->all(FLERR, "Illegal {}: missing number of table points", where);
    const int n = utils::inumeric(FLERR, words[iword + 2].c_str(), false, lmp);
    if (n < 2) error->all(FLERR, "Illegal {}: a {} table needs at least 2 points", where, what);
    if (left < 2 + 2 * (size_t) n)
      error->all(FLERR, "Illegal {}: {} table of {} points needs {} values", where, what, n, 2 * n);
    for (int k = 0; k < n; k++) {
      t.push_back(utils::numeric(FLERR, words[iword + 3 + 2 * k].c_str(), false, lmp));
      p.push_back(positive(words[iword + 4 + 2 * k], what, where, true));
      if (k > 0 && t[k] <= t[k - 1])
        error->all(FLERR, "Illegal {}: {} table temperatures must increase ({} after {})", where,
                   what, words[iword + 3 + 2 * k], words[iword + 1 + 2 * k]);
    }
    ncoeffs = 1 + 2 * n;
  } else {
    if (left < 1 + (size_t) ncoeffs)
      error->all(FLERR, "Illegal {}: {} {} needs {} coefficient(s)", where, what,
                 words[iword + 1], ncoeffs);
    for (int k = 0; k < ncoeffs; k++)
      law.c[k] = (k == 0) ? positive(words[iword + 2], what, where, true)
                          : utils::numeric(FLERR, words[iword + 2 + k].c_str(), false, lmp);
  }
  for (int i = ilo; i <= ihi; i++) {
    MaterialLaw &slot = laws[i];
    slot.table_t = t;
    slot.table_p = p;
    slot.law = law;
    slot.law.ntable = (int) t.size();
    slot.law.table_t = slot.table_t.data();
    slot.law.table_p = slot.table_p.data();
    slot.set = 1;
  }
  return 2 + ncoeffs;
}

/* ----------------------------------------------------------------------
   'eos tait <c0> <gamma> [background <P>]' or 'eos linear <c0> [background <P>]'
------------------------------------------------------------------------- */

int FixSPHMaterials::parse_eos(int ilo, int ihi, const std::vector<std::string> &words,
                               size_t iword, const std::string &where)
{
  const size_t left = words.size() - iword - 1;
  if (left < 1) error->all(FLERR, "Illegal {}: missing equation of state after 'eos'", where);
  const int kind = sphe_lookup(words[iword + 1].c_str());
  if (kind < 0)
    error->all(FLERR, "Illegal {}: unknown equation of state '{}' (tait or linear)", where,
               words[iword + 1]);
  const int ncoeffs = sphe_ncoeffs(kind);
  if (left < 1 + (size_t) ncoeffs)
    error->all(FLERR, "Illegal {}: eos {} needs {} coefficient(s)", where, words[iword + 1],
               ncoeffs);
  sphe_eos eos;
  memset(&eos, 0, sizeof(eos));
  eos.kind = kind;
  eos.c0 = positive(words[iword + 2], "speed of sound", where, false);
  if (kind == SPHE_TAIT) eos.gamma = positive(words[iword + 3], "gamma", where, false);
  int taken = 2 + ncoeffs;
  if (left >= (size_t) taken && words[iword + taken] == "background") {
    if (left < (size_t) taken + 1)
      error->all(FLERR, "Illegal {}: missing value after 'background'", where);
    eos.p_background = utils::numeric(FLERR, words[iword + taken + 1].c_str(), false, lmp);
    taken += 2;
  }
  for (int i = ilo; i <= ihi; i++) {
    eos_type[i] = eos;
    eos_set[i] = 1;
  }
  return taken;
}

/* ---------------------------------------------------------------------- */

double FixSPHMaterials::positive(const std::string &word, const std::string &what,
                                 const std::string &where, bool zero_ok)
{
  const double value = utils::numeric(FLERR, word.c_str(), false, lmp);
  if (value < 0.0 || (!zero_ok && value == 0.0))
    error->all(FLERR, "Illegal {}: {} {} must be {}", where, what, word, zero_ok ? ">= 0" : "> 0");
  return value;
}

/* ----------------------------------------------------------------------
   material file: '# DATE: ... UNITS: ...' header, then lines
     <material> <property> <values>
   with the properties and values of the command. Rank 0 reads, every
   rank parses the same text, so errors are collective.
------------------------------------------------------------------------- */

void FixSPHMaterials::read_file(const std::string &file, const std::vector<std::string> &names,
                                const std::vector<int> &types)
{
  // checked here, collectively: an error on rank 0 alone may never be printed
  std::string path = utils::get_potential_file_path(file);
  if (path.empty()) error->all(FLERR, "Illegal {} command: cannot open material file {}", cmd, file);
  const std::string units = utils::get_potential_units(path, "sph/materials");
  if (units.empty())
    error->all(FLERR,
               "Illegal {} command: material file {} has no '# DATE: ... UNITS: ...' first line, so "
               "its units cannot be checked against this run's {} units",
               cmd, file, update->unit_style);
  if (units != update->unit_style)
    error->all(FLERR, "Illegal {} command: material file {} is in {} units, not {} units", cmd, file,
               units, update->unit_style);

  std::string text;
  if (comm->me == 0) {
    PotentialFileReader reader(lmp, file, "sph/materials");
    char *line;
    while ((line = reader.next_line())) {
      text += line;
      if (text.back() != '\n') text += '\n';
    }
  }
  int n = (int) text.size();
  MPI_Bcast(&n, 1, MPI_INT, 0, world);
  text.resize(n);
  MPI_Bcast(&text[0], n, MPI_CHAR, 0, world);

  std::vector<int> found(names.size(), 0);
  for (const auto &line : Tokenizer(text, "\n").as_vector()) {
    std::vector<std::string> words = utils::split_words(line);
    if (words.size() < 2) continue;
    for (size_t m = 0; m < names.size(); m++) {
      if (words[0] != names[m]) continue;
      found[m] = 1;
      const std::string where = fmt::format("{} command, material {} (type {}) in {}", cmd,
                                            names[m], types[m], file);
      size_t iword = 1;
      while (iword < words.size())
        iword += parse_property(types[m], types[m], words, iword, where);
    }
  }
  for (size_t m = 0; m < names.size(); m++)
    if (!found[m])
      error->all(FLERR, "Illegal {} command: material '{}' not found in {}", cmd, names[m], file);
}
