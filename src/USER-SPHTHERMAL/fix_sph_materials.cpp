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
#include "sph_compat.h"
#include "sph_hub.h"
#include "sph_scene_defaults.h"
#include "sph_sound_speed.h"
#include "tokenizer.h"
#include "update.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/materials";

/* ---------------------------------------------------------------------- */

FixSPHMaterials::FixSPHMaterials(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), state(new SPHAtomState(lmp, this)),
    solids(new SPHMachdynSolids(lmp, this)), eos_type(nullptr), eos_set(nullptr), cv_type(nullptr),
    rho0_type(nullptr), expansion_type(nullptr), tref_type(nullptr), bulk_type(nullptr),
    fwork_type(nullptr), c0_kind(nullptr), background_relative(nullptr), background_given(nullptr),
    background_logged(-1), speed_type(nullptr)
{
  ntypes = atom->ntypes;
  conductivity_laws.resize(ntypes + 1);
  energy_convention.assign(ntypes + 1, -1);
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
  memory->create(tref_type, ntypes + 1, "sph/materials:tref");
  memory->create(bulk_type, ntypes + 1, "sph/materials:bulk");
  memory->create(fwork_type, ntypes + 1, "sph/materials:fwork");
  memory->create(c0_kind, ntypes + 1, "sph/materials:c0_kind");
  memory->create(background_relative, ntypes + 1, "sph/materials:background_relative");
  memory->create(background_given, ntypes + 1, "sph/materials:background_given");
  memory->create(speed_type, ntypes + 1, "sph/materials:speed");
  for (int i = 0; i <= ntypes; i++) {
    eos_set[i] = 0;
    c0_kind[i] = C0_GIVEN;
    background_relative[i] = NAN;
    background_given[i] = 0;
    speed_type[i] = 0.0;
    cv_type[i] = rho0_type[i] = -1.0;
    expansion_type[i] = 0.0;
    tref_type[i] = NAN;
    bulk_type[i] = 0.0;
    fwork_type[i] = NAN;
  }

  if (narg < 4)
    error->all(FLERR, "Illegal {} command: expected 'type <I> <property> ...' or 'file ...'", cmd);

  // global array, one row per type: every property, for input scripts
  array_flag = 1;
  size_array_rows = ntypes;
  size_array_cols = 6;
  extarray = 0;
  // global vector: the MACHDYN solids' work and the heat made from it
  vector_flag = 1;
  size_vector = 2;
  extvector = 1;
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
      error->all(FLERR, "Illegal {} command: type {} has an equation of state but no rho0", cmd, i);
    eos_type[i].rho0 = rho0_type[i];
    // thermal expansion of the reference density: the type's expansion coefficient
    if (eos_type[i].thermal) {
      if (expansion_type[i] == 0.0)
        error->all(FLERR,
                   "Illegal {} command: type {}: eos ... thermal {} needs the type's expansion "
                   "coefficient (expansion beta)",
                   cmd, i, eos_type[i].t0);
      eos_type[i].beta = expansion_type[i];
    }
    apply_relative_background(i);
  }
  // the speeds that the scene gives are kept in restart files
  for (int i = 1; i <= ntypes; i++)
    if (c0_kind[i] == C0_PENDING) restart_global = 1;
}

/* ---------------------------------------------------------------------- */

FixSPHMaterials::~FixSPHMaterials()
{
  delete state;
  solids->delete_vector();
  delete solids;
  delete[] eos_type;
  memory->destroy(eos_set);
  memory->destroy(cv_type);
  memory->destroy(rho0_type);
  memory->destroy(expansion_type);
  memory->destroy(tref_type);
  memory->destroy(bulk_type);
  memory->destroy(fwork_type);
  memory->destroy(c0_kind);
  memory->destroy(background_relative);
  memory->destroy(background_given);
  memory->destroy(speed_type);
}

/* ---------------------------------------------------------------------- */

int FixSPHMaterials::setmask()
{
  return PRE_FORCE | MIN_PRE_FORCE | PRE_REVERSE | END_OF_STEP;
}

/* ----------------------------------------------------------------------
   every run warns again about temperatures outside a table
------------------------------------------------------------------------- */

void FixSPHMaterials::init()
{
  state->init();
  prepare_solids();
  // the MACHDYN solids' work-to-heat tallies are kept in restart files
  if (solids->any()) restart_global = 1;
  for (int i = 0; i <= ntypes; i++) conductivity_laws[i].warned = viscosity_laws[i].warned = 0;
  default_background();
}

/* ----------------------------------------------------------------------
   the background pressure of each equation of state that names none: the
   scene's (SPHSceneDefaults::background), a multiple of rho0 c0^2 applied
   once c0 is known; logged when it changes
------------------------------------------------------------------------- */

void FixSPHMaterials::default_background()
{
  int any = 0;
  for (int t = 1; t <= ntypes; t++) any |= (eos_set[t] && !background_given[t]);
  if (!any) return;
  const SPHSceneDefaults::Choice choice = SPHSceneDefaults::background(lmp);
  for (int t = 1; t <= ntypes; t++) {
    if (!eos_set[t] || background_given[t]) continue;
    background_relative[t] = choice.value ? choice.number : NAN;
    eos_type[t].p_background = 0.0;
    if (c0_kind[t] != C0_PENDING) apply_relative_background(t);
  }
  SPHSceneDefaults::log(lmp, "Fix sph/materials", "background",
                        choice.value ? fmt::format("{:g} rho0 c0^2", choice.number).c_str() : "0",
                        choice, background_logged);
}

/* ----------------------------------------------------------------------
   at the first force evaluation of a run every speed of sound of the
   run's types is known: an 'auto' one is found at the init of the style
   that derives it
------------------------------------------------------------------------- */

void FixSPHMaterials::setup_pre_force(int /*vflag*/)
{
  state->stale();
  // (the solids' cv and rho were given at init and travel with the atoms)
  solids->mark();
  solids->thermal_stress();
  int pending = 0;
  for (int t = 1; t <= ntypes; t++) pending |= (c0_kind[t] == C0_PENDING);
  // fix sph/boussinesq derived its types' at its init; the rest from the flow
  if (pending) SPHSoundSpeed::derive(lmp, this, "Fix sph/materials");
}

/* ----------------------------------------------------------------------
   an 'auto' speed of sound found from the scene; logged once
------------------------------------------------------------------------- */

void FixSPHMaterials::set_sound_speed(int type, double c0, const std::string &why)
{
  if (c0_kind[type] != C0_PENDING) return;
  std::string reason = why;
  // the flow's speed given in the eos bounds any estimate from below
  if (SPHSoundSpeed::SPEED_FACTOR * speed_type[type] > c0) {
    reason = fmt::format("{} times the speed {} its eos gives, above {:.6g}, {}",
                         SPHSoundSpeed::SPEED_FACTOR, speed_type[type], c0, why);
    c0 = SPHSoundSpeed::SPEED_FACTOR * speed_type[type];
  }
  eos_type[type].c0 = c0;
  c0_kind[type] = C0_FOUND;
  std::string background;
  if (apply_relative_background(type))
    background = fmt::format(", background pressure {:.6g} ({} rho0 c0^2)",
                             eos_type[type].p_background, background_relative[type]);
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix sph/materials: speed of sound of atom type {} is {:.6g} ({}){}\n",
                   type, c0, reason, background);
}

/* ----------------------------------------------------------------------
   'background B relative': the pressure B rho0 c0^2 of a type, once its c0
   is given or found; 1 when the type has such a background
------------------------------------------------------------------------- */

int FixSPHMaterials::apply_relative_background(int type)
{
  if (!std::isfinite(background_relative[type])) return 0;
  const sphe_eos &eos = eos_type[type];
  eos_type[type].p_background = background_relative[type] * eos.rho0 * eos.c0 * eos.c0;
  return 1;
}

/* ----------------------------------------------------------------------
   [1] pair smd/tlsph's work on the MACHDYN solids since the first run,
   [2] the heat made from their plastic work (SPHMachdynSolids::work_to_heat)
------------------------------------------------------------------------- */

double FixSPHMaterials::compute_vector(int n)
{
  return n == 0 ? solids->work_done() : solids->heat_from_work();
}

/* ----------------------------------------------------------------------
   restart state: the speed of sound of each type found from the scene (0
   for the others), so that a pending 'auto' type takes it back and a
   restarted run goes on at the speed it started with; then the MACHDYN
   solids' work-to-heat tallies.
------------------------------------------------------------------------- */

static constexpr int RESTART_VERSION = 2;

void FixSPHMaterials::write_restart(FILE *fp)
{
  // (every rank calls it: the tallies are sums over the ranks)
  const double work = solids->work_done(), heat = solids->heat_from_work();
  if (comm->me != 0) return;
  std::vector<double> state(ntypes + 1, 0.0);    // the number of types, each one's c0
  state[0] = ntypes;
  for (int t = 1; t <= ntypes; t++)
    if (c0_kind[t] == C0_FOUND) state[t] = eos_type[t].c0;
  state.push_back(work);
  state.push_back(heat);
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state.data(), state.size());
}

void FixSPHMaterials::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  const int n = (int) state[0];
  for (int t = 1; t <= ntypes && t <= n; t++)
    if (state[t] > 0.0) set_sound_speed(t, state[t], "auto, from the restart file");
  solids->restore_tallies(state[n + 1], state[n + 2]);
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
    SPHCheck::stop(lmp, FLERR,
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
   row = type - 1; columns: rho0, cv, expansion, speed of sound, then the
   conductivity and viscosity (the value of a constant law, the first
   coefficient k0 or mu0 of the others, the first value of a table); -1
   when not given (0 for the expansion)
------------------------------------------------------------------------- */

double FixSPHMaterials::compute_array(int row, int column)
{
  const int type = row + 1;
  auto law_value = [](const MaterialLaw &slot) {
    if (!slot.set) return -1.0;
    return (slot.law.kind == SPHM_TABLE) ? slot.law.table_p[0] : slot.law.c[0];
  };
  switch (column) {
    case 0:
      return rho0_type[type];
    case 1:
      return cv_type[type];
    case 2:
      return expansion_type[type];
    case 3:
      return eos_set[type] ? eos_type[type].c0 : -1.0;
    case 4:
      return law_value(conductivity_laws[type]);
    default:
      return law_value(viscosity_laws[type]);
  }
}

/* ----------------------------------------------------------------------
   per-type arrays (index: type) for other styles and the library interface
------------------------------------------------------------------------- */

void *FixSPHMaterials::extract(const char *name, int &dim)
{
  dim = 1;
  if (strcmp(name, "rho0") == 0) return (void *) rho0_type;
  if (strcmp(name, "cv") == 0) return (void *) cv_type;
  if (strcmp(name, "expansion") == 0) return (void *) expansion_type;
  dim = 0;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

FixSPHMaterials *FixSPHMaterials::find(LAMMPS *lmp, const char *who)
{
  const std::vector<FixSPHMaterials *> all = SPHHub(lmp).fixes<FixSPHMaterials>();
  const int count = all.size();
  if (count == 0)
    lmp->error->all(FLERR, "{} requires fix sph/materials (the material properties)", who);
  if (count > 1) lmp->error->all(FLERR, "{}: only one fix sph/materials may be defined", who);
  return all[0];
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

  if (name == "cv" || name == "rho0" || name == "bulk") {
    if (left < 1) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    const double value = positive(words[iword + 1], name, where, false);
    double *const slot = (name == "cv") ? cv_type : (name == "rho0") ? rho0_type : bulk_type;
    for (int i = ilo; i <= ihi; i++) slot[i] = value;
    return 2;
  }

  if (name == "tref") {
    if (left < 1) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    const double value = utils::numeric(FLERR, words[iword + 1].c_str(), false, lmp);
    for (int i = ilo; i <= ihi; i++) tref_type[i] = value;
    return 2;
  }

  if (name == "fwork") {
    if (left < 1) error->all(FLERR, "Illegal {}: missing value after '{}'", where, name);
    const double value = utils::numeric(FLERR, words[iword + 1].c_str(), false, lmp);
    if (!(value >= 0.0 && value <= 1.0))
      error->all(FLERR, "Illegal {}: fwork {} is not a fraction between 0 and 1", where,
                 words[iword + 1]);
    for (int i = ilo; i <= ihi; i++) fwork_type[i] = value;
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
             "Illegal {}: unknown property '{}' (conductivity, viscosity, eos, cv, rho0, "
             "expansion, tref, bulk or fwork)",
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
      error->all(FLERR, "Illegal {}: {} {} needs {} coefficient(s)", where, what, words[iword + 1],
                 ncoeffs);
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
   'eos tait <c0> <gamma> [options]' or 'eos linear <c0> [options]', c0 a
   speed or 'auto'; options: background <P> [relative], thermal <T0>,
   speed <U> (with 'auto')
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
  // 'auto': found from the scene at the first run (set_sound_speed)
  const int c0_auto = (words[iword + 2] == "auto");
  eos.c0 = c0_auto ? 0.0 : positive(words[iword + 2], "speed of sound", where, false);
  if (kind == SPHE_TAIT) eos.gamma = positive(words[iword + 3], "gamma", where, false);
  int taken = 2 + ncoeffs;
  double relative = NAN, speed = 0.0;
  int background = 0;
  // options, in any order: background P [relative], thermal T0, speed U
  while (left >= (size_t) taken &&
         (words[iword + taken] == "background" || words[iword + taken] == "thermal" ||
          words[iword + taken] == "speed")) {
    const std::string &option = words[iword + taken];
    if (left < (size_t) taken + 1)
      error->all(FLERR, "Illegal {}: missing value after '{}'", where, option);
    if (option == "speed") {
      // the flow's speed scale, from which 'auto' takes c0
      if (!c0_auto)
        error->all(FLERR,
                   "Illegal {}: 'speed' is the flow's speed from which an 'auto' speed of "
                   "sound is found, but c0 {} is given",
                   where, words[iword + 2]);
      speed = positive(words[iword + taken + 1], "speed", where, false);
      taken += 2;
      continue;
    }
    const double value = utils::numeric(FLERR, words[iword + taken + 1].c_str(), false, lmp);
    if (option == "background") {
      eos.p_background = value;
      background = 1;
      relative = NAN;
      // a multiple of rho0 c0^2, set once both are known
      if (left >= (size_t) taken + 2 && words[iword + taken + 2] == "relative") {
        relative = value;
        taken++;
      }
    } else {
      // beta is the type's expansion, checked once every property is known
      eos.thermal = 1;
      eos.t0 = value;
    }
    taken += 2;
  }
  for (int i = ilo; i <= ihi; i++) {
    eos_type[i] = eos;
    eos_set[i] = 1;
    c0_kind[i] = c0_auto ? C0_PENDING : C0_GIVEN;
    background_relative[i] = relative;
    background_given[i] = background;
    speed_type[i] = speed;
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
   where a material file is looked for, as LAMMPS does for potential files:
   the name as given (relative to the working directory), then by its file
   name in each directory of $LAMMPS_POTENTIALS, the directory of the input
   script (-in), the package's own potentials/ (plugin builds) and the
   potentials directory of Debian's LAMMPS; 'tried' lists every place
------------------------------------------------------------------------- */

std::string FixSPHMaterials::find_material_file(const std::string &file,
                                                std::vector<std::string> &tried)
{
  std::vector<std::string> candidates = {file};
  const std::string name = SPHCompat::path_basename(file);
  if (const char *env = getenv("LAMMPS_POTENTIALS"))
    for (const auto &dir : Tokenizer(env, ":").as_vector())
      candidates.push_back(SPHCompat::path_join(dir, name) + "  (LAMMPS_POTENTIALS)");
  const std::string input_dir = input_script_dir();
  if (!input_dir.empty() && !file.empty() && file[0] != '/')
    candidates.push_back(SPHCompat::path_join(input_dir, file) +
                         "  (directory of the input script)");
#ifdef SPHTHERMAL_POTENTIALS_DIR
  candidates.push_back(SPHCompat::path_join(SPHTHERMAL_POTENTIALS_DIR, name) +
                       "  (potentials of USER-SPHTHERMAL)");
#endif
  candidates.push_back(SPHCompat::path_join("/usr/share/lammps/potentials", name) +
                       "  (Debian's LAMMPS potentials)");
  for (const auto &candidate : candidates) {
    const std::string path = candidate.substr(0, candidate.find("  ("));
    tried.push_back(candidate);
    if (SPHCompat::file_is_readable(path)) return path;
  }
  return "";
}

/* ----------------------------------------------------------------------
   directory of the input script given with -in (or -i); empty when read
   from standard input or when the command line is not readable (Linux's
   /proc only)
------------------------------------------------------------------------- */

std::string FixSPHMaterials::input_script_dir()
{
  FILE *fp = fopen("/proc/self/cmdline", "rb");
  if (!fp) return "";
  std::string cmdline;
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof(buffer), fp)) > 0) cmdline.append(buffer, n);
  fclose(fp);
  std::vector<std::string> args;
  for (size_t start = 0; start < cmdline.size();) {
    const size_t end = cmdline.find('\0', start);
    args.push_back(
        cmdline.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  for (size_t k = 0; k + 1 < args.size(); k++)
    if (args[k] == "-in" || args[k] == "-i") {
      const std::string dir = SPHCompat::path_dirname(args[k + 1]);
      return dir.empty() ? std::string(".") : dir;
    }
  return "";
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
  std::vector<std::string> tried;
  const std::string path = find_material_file(file, tried);
  if (path.empty()) {
    std::string where;
    for (const auto &place : tried) where += "\n  " + place;
    error->all(FLERR, "Illegal {} command: cannot open material file {}; looked for:{}", cmd, file,
               where);
  }
  const std::string units = utils::get_potential_units(path, "sph/materials");
  if (units.empty())
    error->all(
        FLERR,
        "Illegal {} command: material file {} has no '# DATE: ... UNITS: ...' first line, so "
        "its units cannot be checked against this run's {} units",
        cmd, file, update->unit_style);
  if (units != update->unit_style)
    error->all(FLERR, "Illegal {} command: material file {} is in {} units, not {} units", cmd,
               file, units, update->unit_style);

  std::string text;
  if (comm->me == 0) {
    PotentialFileReader reader(lmp, path, "sph/materials");
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
      const std::string where =
          fmt::format("{} command, material {} (type {}) in {}", cmd, names[m], types[m], file);
      size_t iword = 1;
      while (iword < words.size()) iword += parse_property(types[m], types[m], words, iword, where);
    }
  }
  for (size_t m = 0; m < names.size(); m++)
    if (!found[m])
      error->all(FLERR, "Illegal {} command: material '{}' not found in {}", cmd, names[m], file);
}
