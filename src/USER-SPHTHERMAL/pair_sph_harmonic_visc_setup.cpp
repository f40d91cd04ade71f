/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/harmonic/visc: its command, settings, restart and communication, and
   the shift sums it makes for fix sph/shift.
------------------------------------------------------------------------- */

#include "pair_sph_harmonic_visc.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_adami.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "sph_consistent.h"
#include "sph_flow.h"
#include "sph_hub.h"
#include "sph_scene_defaults.h"
#include "sph_support.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char cmd[] = "pair_style sph/harmonic/visc";

// the layout of the restart settings: raise it when a setting is added
static constexpr int RESTART_VERSION = 2;

/* ---------------------------------------------------------------------- */

bool PairSPHHarmonicVisc::provide_shift_sums(int groupbit)
{
  // only the averaged pressure form's loop makes them (fix sph/shift then sums them itself)
  if (pressure_form != SPHF_P_AVERAGED) return false;
  const int ntypes = atom->ntypes;
  std::vector<int> group_type(ntypes + 1, 0), group_type_all(ntypes + 1, 0);
  int in_wall = 0, in_wall_any = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) {
      group_type[atom->type[i]] = 1;
      if (atom->mask[i] & wall_groupbit) in_wall = 1;
    }
  MPI_Allreduce(group_type.data(), group_type_all.data(), ntypes + 1, MPI_INT, MPI_MAX, world);
  MPI_Allreduce(&in_wall, &in_wall_any, 1, MPI_INT, MPI_MAX, world);
  if (in_wall_any) return false;
  for (int t = 1; t <= ntypes; t++)
    if (group_type_all[t])
      for (int u = 1; u <= ntypes; u++)
        if (!setflag[MIN(t, u)][MAX(t, u)]) return false;
  shift_sums_wanted = 1;
  return true;
}

/* ----------------------------------------------------------------------
   the pressure form and the density diffusion not given in the command:
   the scene's (sph_scene_defaults.h); the forms given, checked against
   the scene: with the grains of fix sph/grains the fluid's density
   follows the porosity, and the averaged and symmetric forms, or a weak
   diffusion, let its speeds grow (sph_scene_defaults.cpp)
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::choose_scene_forms()
{
  static constexpr double MIN_GRAIN_DELTA = 0.2;    // measured stable with grains
  const char *who = "Pair style sph/harmonic/visc";
  if (pressure_request < 0) {
    const SPHSceneDefaults::Choice choice =
        SPHSceneDefaults::pressure_form(lmp, gradient_request >= 1);
    pressure_form = choice.value;
    SPHSceneDefaults::log(lmp, who, "pressure", sphf_pressure_name(pressure_form), choice,
                          pressure_logged);
  } else
    pressure_form = pressure_request;
  // a number the command gave (>= 0), or the scene's default, logged
  auto number = [&](double request, const char *setting, SPHSceneDefaults::Choice (*rule)(LAMMPS *),
                    int &logged) {
    if (request >= 0.0) return request;
    const SPHSceneDefaults::Choice choice = rule(lmp);
    SPHSceneDefaults::log(lmp, who, setting, fmt::format("{}", choice.number).c_str(), choice,
                          logged);
    return choice.number;
  };
  delta = number(delta_request, "delta", SPHSceneDefaults::density_diffusion, delta_logged);
  artificial = number(artificial_request, "artificial", SPHSceneDefaults::artificial_viscosity,
                      artificial_logged);

  const std::string grains = SPHSceneDefaults::grains_fix(lmp);
  if (grains.empty() || comm->me != 0 || grain_forms_warned) return;
  grain_forms_warned = 1;
  const double grain_delta = SPHSceneDefaults::density_diffusion(lmp).number;
  if (pressure_form != SPHF_P_SUM)
    error->warning(FLERR,
                   "{}: pressure {} with the unresolved grains of fix sph/grains {}: where the "
                   "porosity changes (a bed's surface, grains that move) the fluid's speeds can "
                   "grow without bound; pressure sum (the default with grains) keeps them down",
                   who, sphf_pressure_name(pressure_form), grains);
  if (delta < MIN_GRAIN_DELTA)
    error->warning(FLERR,
                   "{}: delta {} with the unresolved grains of fix sph/grains {}: where the "
                   "porosity changes the fluid's speeds can grow without bound below {} (the "
                   "default with grains is {})",
                   who, delta, grains, MIN_GRAIN_DELTA, grain_delta);
}

/* ----------------------------------------------------------------------
   pair_style sph/harmonic/visc kernel cutoff [pressure symmetric|sum|averaged]
     [viscosity cleary|adami|morris] [xi value] [eta f] [delta value]
     [diffusion fourtakas|molteni] [fourtakas gx gy gz] [heating fraction]
     [mean_pressure P|none] [correction none|gradient] [artificial alpha]
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::settings(int narg, char **arg)
{
  int iarg = parse_kernel(narg, arg);
  pressure_request = -1;    // the scene's default at init (choose_scene_forms)
  viscosity_form = SPHF_V_ADAMI;
  xi = SPHF_XI_CLEARY;
  xi_given = 0;
  eta_factor = -1.0;       // the default depends on the viscosity form
  delta_request = -1.0;    // the scene's default at init (choose_scene_forms)
  heating = 0.0;           // Reece et al. 2024 and Ng et al. 2020 neglect it
  artificial_request = -1.0;    // the scene's default at init (choose_scene_forms)
  mean_pressure_held = 0;
  mean_pressure = 0.0;
  gradient_request = -1;    // the scene's default at init
  // Fourtakas's form equals Molteni's without gravity and keeps a column at
  // rest with it (examples/flow-hydrostatic): the default
  diffusion_form = DIFFUSION_BODY_FORCE;
  hydrostatic = 0;
  gravity[0] = gravity[1] = gravity[2] = 0.0;
  while (iarg < narg) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal {} command: missing value after '{}'", cmd, arg[iarg]);
    const char *value = arg[iarg + 1];
    if (strcmp(arg[iarg], "pressure") == 0) {
      pressure_request = sphf_pressure_lookup(value);
      if (pressure_request < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown pressure form '{}' (symmetric, sum or averaged)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "viscosity") == 0) {
      viscosity_form = sphf_viscosity_lookup(value);
      if (viscosity_form < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown viscosity form '{}' (cleary, adami or morris)", cmd,
                   value);
    } else if (strcmp(arg[iarg], "xi") == 0) {
      xi = utils::numeric(FLERR, value, false, lmp);
      xi_given = 1;
      if (xi <= 0.0) error->all(FLERR, "Illegal {} command: xi {} must be > 0", cmd, value);
    } else if (strcmp(arg[iarg], "eta") == 0) {
      eta_factor = utils::numeric(FLERR, value, false, lmp);
      if (eta_factor < 0.0)
        error->all(FLERR, "Illegal {} command: eta {} must be >= 0", cmd, value);
    } else if (strcmp(arg[iarg], "diffusion") == 0) {
      if (strcmp(value, "fourtakas") == 0)
        diffusion_form = DIFFUSION_BODY_FORCE;
      else if (strcmp(value, "molteni") == 0)
        diffusion_form = DIFFUSION_MOLTENI;
      else
        error->all(FLERR, "Illegal {} command: unknown diffusion '{}' (fourtakas or molteni)", cmd,
                   value);
    } else if (strcmp(arg[iarg], "fourtakas") == 0) {
      if (iarg + 3 >= narg)
        error->all(FLERR,
                   "Illegal {} command: 'fourtakas' needs 3 values (gx gy gz); without them, "
                   "'diffusion fourtakas' (the default) reads fix gravity",
                   cmd);
      diffusion_form = DIFFUSION_GIVEN;
      hydrostatic = 1;
      for (int k = 0; k < 3; k++) gravity[k] = utils::numeric(FLERR, arg[iarg + 1 + k], false, lmp);
      iarg += 4;
      continue;
    } else if (strcmp(arg[iarg], "heating") == 0) {
      heating = utils::numeric(FLERR, value, false, lmp);
      if (heating < 0.0 || heating > 1.0)
        error->all(FLERR,
                   "Illegal {} command: heating {} must be in [0, 1] (the fraction of the "
                   "viscous work turned into heat)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "artificial") == 0) {
      artificial_request = utils::numeric(FLERR, value, false, lmp);
      if (!(artificial_request >= 0.0 && artificial_request <= 1.0))
        error->all(FLERR,
                   "Illegal {} command: artificial {} must be in [0, 1] (alpha of Monaghan's "
                   "artificial viscosity; 0: none)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "mean_pressure") == 0) {
      mean_pressure_held = (strcmp(value, "none") != 0);
      mean_pressure = mean_pressure_held ? utils::numeric(FLERR, value, false, lmp) : 0.0;
    } else if (strcmp(arg[iarg], "correction") == 0) {
      if (strcmp(value, "gradient") == 0)
        gradient_request = 1;
      else if (strcmp(value, "gradient/hold") == 0)
        gradient_request = GRADIENT_HOLD;
      else if (strcmp(value, "none") == 0)
        gradient_request = 0;
      else
        error->all(FLERR,
                   "Illegal {} command: unknown correction '{}' (none, gradient or gradient/hold)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "delta") == 0) {
      delta_request = utils::numeric(FLERR, value, false, lmp);
      if (delta_request < 0.0)
        error->all(FLERR, "Illegal {} command: delta {} must be >= 0", cmd, value);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
    iarg += 2;
  }
  if (xi_given && viscosity_form != SPHF_V_CLEARY)
    error->all(FLERR,
               "Illegal {} command: xi is a factor of the cleary viscosity form only; viscosity {} "
               "does not use it",
               cmd, sphf_viscosity_name(viscosity_form));
  if (gradient_request >= 1 && pressure_request >= 0 && pressure_request != SPHF_P_AVERAGED)
    error->all(FLERR,
               "Illegal {} command: correction gradient needs the averaged pressure form (the "
               "default), not pressure {}",
               cmd, sphf_pressure_name(pressure_request));
  if (diffusion_form == DIFFUSION_GIVEN && gravity[0] == 0.0 && gravity[1] == 0.0 &&
      gravity[2] == 0.0)
    error->all(FLERR,
               "Illegal {} command: fourtakas 0 0 0 is Molteni's diffusion: give the gravity "
               "vector, or use 'diffusion molteni'",
               cmd);
  // Cleary's xi was calibrated with eta = 0.1 h; the consistent forms only
  // need eta against r -> 0, and 0.1 h would lower their viscosity by 1-4 %
  if (eta_factor < 0.0) eta_factor = (viscosity_form == SPHF_V_CLEARY) ? 0.1 : 0.01;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::init_style()
{
  if (!atom->rho_flag || !atom->vest_flag || !atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Pair style sph/harmonic/visc requires atom style sph (rho, drho, vest)");

  // turned on by the constructor; off only after an explicit comm_modify vel no
  if (!comm->ghost_velocity)
    error->all(FLERR,
               "Pair style sph/harmonic/visc requires ghost velocities: remove comm_modify vel no");

  materials = FixSPHMaterials::find(lmp, "Pair style sph/harmonic/visc");
  // the walls first: a wall type without an equation of state is a solid
  wall_groupbit = 0;
  adami_walls.clear();
  for (FixSPHWallAdami *wall : SPHHub(lmp).fixes<FixSPHWallAdami>()) {
    wall_groupbit |= wall->groupbit;
    adami_walls.push_back(wall);
  }
  // a body moved by a fix rigid is a moving wall: its particles must be in
  // a fix sph/wall/adami group, or the flow would treat them as fluid
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    Fix *rigid = modify->fix[ifix];
    if (!SPHHub(lmp).rigid(rigid)) continue;
    SPHCheck::FirstBad stray;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & rigid->groupbit) && !(atom->mask[i] & wall_groupbit))
        stray.consider(atom->tag[i]);
    if (stray.agree(lmp))
      error->all(FLERR,
                 "Pair style sph/harmonic/visc: atom {} of fix {} ({}) is in no fix sph/wall/adami "
                 "group: the particles of a rigid body must be walls of fix sph/wall/adami, which "
                 "moves them with the body",
                 stray.tag, rigid->id, rigid->style);
  }
  // every particle of a type with a pair of this style (in a hybrid, the
  // others may be grains of fix sph/grains) that is not such a wall needs
  // its fluid's properties
  std::vector<int> has_pair(atom->ntypes + 1, 0);
  for (int t = 1; t <= atom->ntypes; t++)
    for (int s = 1; s <= atom->ntypes; s++)
      if (setflag[std::min(t, s)][std::max(t, s)]) has_pair[t] = 1;
  SPHCheck::FirstBad bad;    // type, 1 no eos / 2 no viscosity
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->mask[i] & wall_groupbit) continue;
    const int t = atom->type[i];
    if (!has_pair[t]) continue;
    const int missing = !materials->eos(t) ? 1 : (!materials->viscosity(t) ? 2 : 0);
    if (missing) bad.consider(atom->tag[i], t, missing);
  }
  if (bad.agree(lmp))
    error->all(FLERR,
               "Pair style sph/harmonic/visc: atom type {} has no {} in fix sph/materials (atom {} "
               "is a fluid particle; only the solid particles of fix sph/wall/adami may lack it)",
               (int) bad.info[0], bad.info[1] == 1.0 ? "equation of state (eos)" : "viscosity",
               bad.tag);
  viscosity_varies = !materials->viscosity_constant();
  // the per-atom arrays are sized again with the diffused density
  if (materials->thermal_expansion() != thermal_expansion) {
    thermal_expansion = materials->thermal_expansion();
    nmax = 0;
  }
  SPHCheck::atom_state(
      lmp, FLERR, "Pair style sph/harmonic/visc", 0,
      SPHCheck::RHO |
          ((viscosity_varies || thermal_expansion) ? SPHCheck::CV | SPHCheck::ESPH : 0));

  // the hydrostatic diffusion reads the body force of the run, or assumes one
  body_force = SPHBodyForce::find(lmp, "Pair style sph/harmonic/visc");
  // and the buoyancy of fix sph/boussinesq, which varies from atom to atom
  buoyancy = (diffusion_form == DIFFUSION_MOLTENI) ? nullptr : SPHBodyForce::find_buoyancy(lmp);
  pressure_buoyancy = SPHBodyForce::find_buoyancy(lmp);
  if (diffusion_form == DIFFUSION_MOLTENI) {
    hydrostatic = 0;
  } else if (diffusion_form == DIFFUSION_BODY_FORCE) {
    read_body_force();
  } else {
    int other_force = 0;
    for (int ifix = 0; ifix < modify->nfix; ifix++)
      if (SPHHub(lmp).adds_force(modify->fix[ifix])) other_force = 1;
    if (!body_force && !other_force)
      error->warning(FLERR,
                     "Pair style sph/harmonic/visc: fourtakas {} {} {} assumes gravity, but no fix "
                     "gravity or addforce is defined",
                     gravity[0], gravity[1], gravity[2]);
    else
      SPHBodyForce::warn_overridden(lmp, "Pair style sph/harmonic/visc", "fourtakas", gravity,
                                    "'diffusion fourtakas' (the default) reads it");
  }

  choose_scene_forms();
  // without 'correction' in the command, the scene's default (the
  // correction is made for the averaged pressure form only)
  if (gradient_request < 0 && pressure_form == SPHF_P_AVERAGED) {
    const SPHSceneDefaults::Choice choice = SPHSceneDefaults::pressure_correction(lmp);
    gradient_correction = choice.value;
    SPHSceneDefaults::log(lmp, "Pair style sph/harmonic/visc", "correction",
                          gradient_correction ? "gradient" : "none", choice, gradient_logged);
  } else
    gradient_correction = (gradient_request >= 1);

  eta2 = init_kernel();
  eos_of.assign(atom->ntypes + 1, nullptr);
  for (int t = 1; t <= atom->ntypes; t++) eos_of[t] = materials->eos(t);
  warn_background();
  warn_soft_fluid();
  // sph/cleary/heat decides at its init whether this loop evaluates its term
  heat = SPHHub(lmp).heat();
  // fix sph/shift asks again at its init, compute sph/force at its own
  shift_sums_wanted = 0;
  group_forces.clear();

  SPHCompat::request_half_list(neighbor, this, instance_me);
}

double PairSPHHarmonicVisc::init_one(int, int)
{
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::write_restart_settings(FILE *fp)
{
  // the pressure form, delta and artificial as the command gave them (-1: the scene's)
  const int ints[6] = {kernel_kind,    pressure_request,   viscosity_form,
                       diffusion_form, mean_pressure_held, gradient_request};
  // xi_given only checks the command line
  const double doubles[10] = {
      cut_global, xi,         eta_factor, delta_request, gravity[0],
      gravity[1], gravity[2], heating,    mean_pressure, artificial_request};
  SPHCheck::write_restart_head(fp, RESTART_VERSION);
  fwrite(ints, sizeof(int), 6, fp);
  fwrite(doubles, sizeof(double), 10, fp);
}

void PairSPHHarmonicVisc::read_restart_settings(FILE *fp)
{
  SPHCheck::read_restart_head(lmp, FLERR, fp, "pair sph/harmonic/visc", RESTART_VERSION);
  int ints[6];
  double doubles[10];
  if (comm->me == 0) {
    utils::sfread(FLERR, ints, sizeof(int), 6, fp, nullptr, error);
    utils::sfread(FLERR, doubles, sizeof(double), 10, fp, nullptr, error);
  }
  MPI_Bcast(ints, 6, MPI_INT, 0, world);
  MPI_Bcast(doubles, 10, MPI_DOUBLE, 0, world);
  // the body force is read again from fix gravity at init
  diffusion_form = ints[3];
  hydrostatic = (diffusion_form == DIFFUSION_GIVEN);
  for (int k = 0; k < 3; k++) gravity[k] = doubles[4 + k];
  kernel_kind = ints[0];
  // files written before the scene's defaults hold the forms taken: read as given
  pressure_request = ints[1];
  viscosity_form = ints[2];
  cut_global = doubles[0];
  xi = doubles[1];
  eta_factor = doubles[2];
  delta_request = doubles[3];
  heating = doubles[7];
  artificial_request = doubles[9];    // -1: the scene's default, again at init
  mean_pressure_held = ints[4];
  mean_pressure = doubles[8];
  gradient_request = ints[5];    // -1: the scene's default, again at init
}

/* ---------------------------------------------------------------------- */

double PairSPHHarmonicVisc::memory_usage()
{
  return Pair::memory_usage() +
      ((velocity_seen_store ? 8.0 : 5.0) * nmax + 3.0 * nmax_shift + 6.0 * nmax_gradient) *
      sizeof(double) +
      gradient_sums.memory_usage();
}

/* ----------------------------------------------------------------------
   the kernel gradient of a uniform pressure is not zero where the particles
   are not on a lattice: a background pressure large against a fluid's own
   rho0 c0^2 accelerates its particles apart (bench/stability, two-fluid
   Couette at density ratio 1000: stable with the light fluid's background
   up to 0.4 of its rho0 c0^2, unstable at every timestep from 1 on, e.g.
   with the heavy fluid's 0.01 rho0 c0^2 given to both)
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::warn_background()
{
  static constexpr double MAX_BACKGROUND = 0.5;    // of rho0 c0^2
  if (comm->me != 0 || background_warned) return;
  for (int t = 1; t <= atom->ntypes; t++) {
    const sphe_eos *eos = eos_of[t];
    if (!eos || !(eos->rho0 > 0.0) || !(eos->c0 > 0.0)) continue;
    const double stiffness = sphe_bulk_modulus(eos);
    if (!(eos->p_background > MAX_BACKGROUND * stiffness)) continue;
    error->warning(FLERR,
                   "Pair style sph/harmonic/visc: the background pressure {} of atom type {} is "
                   "{:.3g} rho0 c0^2 of its equation of state (rho0 {}, c0 {}), more than {}: the "
                   "kernel gradient's error of a uniform pressure drives its particles apart; with "
                   "fluids of different densities give the background from the lightest "
                   "(fix sph/materials 'background')",
                   eos->p_background, t, eos->p_background / stiffness, eos->rho0, eos->c0,
                   MAX_BACKGROUND);
    background_warned = 1;
  }
}

/* ----------------------------------------------------------------------
   fluids of different rest densities under a body force: a fluid whose
   bulk modulus rho0 c0^2 is much below another's is compressed by the
   other's pressure noise at their interface (bench/stability, two fluids
   layered in a column under gravity, the default fix sph/dt/reset:
   stable with spurious speeds below 0.08 % of sqrt(g H) at density ratios
   10 to 1000 whenever the lighter fluid's rho0 c0^2 is 0.5 to 2.25 times
   the heavier's; from 0.4 down, some unstable at each ratio)
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::warn_soft_fluid()
{
  static constexpr double MIN_MODULUS_RATIO = 0.5;    // of the stiffest fluid's rho0 c0^2
  if (soft_fluid_warned || (!body_force && !buoyancy)) return;
  // the types that have fluid particles (the walls of fix sph/wall/adami take their pressure)
  std::vector<int> local(atom->ntypes + 1, 0), fluid(atom->ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (!(atom->mask[i] & wall_groupbit)) local[atom->type[i]] = 1;
  MPI_Allreduce(local.data(), fluid.data(), atom->ntypes + 1, MPI_INT, MPI_MAX, world);
  // (a c0 that fix sph/materials derives ('auto') is not known before the fixes' init)
  int stiffest = 0;
  for (int t = 1; t <= atom->ntypes; t++) {
    fluid[t] = fluid[t] && eos_of[t] && eos_of[t]->rho0 > 0.0 && eos_of[t]->c0 > 0.0;
    if (fluid[t] &&
        (!stiffest || sphe_bulk_modulus(eos_of[t]) > sphe_bulk_modulus(eos_of[stiffest])))
      stiffest = t;
  }
  if (!stiffest) return;
  const double modulus = sphe_bulk_modulus(eos_of[stiffest]);
  for (int t = 1; t <= atom->ntypes && !soft_fluid_warned; t++) {
    if (!fluid[t]) continue;
    const double ratio = sphe_bulk_modulus(eos_of[t]) / modulus;
    if (!(ratio < MIN_MODULUS_RATIO)) continue;
    soft_fluid_warned = 1;    // on every rank: the next init skips the reduction everywhere
    if (comm->me == 0)
      error->warning(
          FLERR,
          "Pair style sph/harmonic/visc: the fluid of atom type {} has rho0 c0^2 = {:.4g} "
          "(rho0 {}, c0 {}), {:.3g} times that of atom type {} ({:.4g}), less than {}: "
          "under a body force the stiffer fluid's pressure noise compresses it at their "
          "interface, which can go unstable; give type {} c0 {:.4g} or more in fix "
          "sph/materials (the same rho0 c0^2)",
          t, sphe_bulk_modulus(eos_of[t]), eos_of[t]->rho0, eos_of[t]->c0, ratio, stiffest, modulus,
          MIN_MODULUS_RATIO, t, sqrt(modulus / eos_of[t]->rho0));
  }
}

/* ----------------------------------------------------------------------
   'diffusion fourtakas': the acceleration of the hydrostatic diffusion is
   the run's body force (0 without one); hydrostatic with it or a buoyancy
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::read_body_force()
{
  for (int k = 0; k < 3; k++) gravity[k] = body_force ? body_force[k] : 0.0;
  hydrostatic = (gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0) || buoyancy;
}
