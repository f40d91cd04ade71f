/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/boussinesq: buoyancy of a fluid whose density varies with
   temperature only in the body force (Reece et al. 2024, eq 15):
     f_i = -m_i g beta_i (T_i - T0)
   g from the 'gravity' keyword, or the acceleration of fix gravity, which
   then also adds the weight m g: together g (1 - beta (T - T0)).
   T0 'mean': the group's mean temperature weighted by m beta, updated every
   step, so that the buoyancy sums to zero: the uniform part of the body
   force, which in a closed domain only the pressure balances (and which
   compresses a weakly compressible fluid), is never applied.
   T0 'layers': the same mean in each layer across g, linear between the
   layers' centres. A body force that depends on the height along g alone
   is the gradient of a potential: in an incompressible fluid only the
   pressure changes with it, but a weakly compressible one is compressed by
   it. Taking it out leaves the flow of the Boussinesq equations unchanged
   and does not make a stratified fluid carry its weight by compression.
------------------------------------------------------------------------- */

#include "fix_sph_boussinesq.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_hold_volume.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_adami.h"
#include "fix_sph_wall_dirichlet.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_buoyancy.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_eos.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "sph_scene_defaults.h"
#include "sph_sound_speed.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/boussinesq";

// the largest compression by the buoyancy's pressure without a warning
// (the bound of check_compression(); in the cavity of de Vahl Davis, T0
// halfway between the walls, 0.1 put Nu 0.46 % low and its estimates 1.9 %
// apart, 0.025 within 0.04 % and 0.41 %: doc/src/fix_sph_boussinesq.rst)
static constexpr double MAX_COMPRESSION = 0.05;
// with 'potential' the pressure that balances the buoyancy needs no
// compression, and 'auto' takes c0 = SPEED_FACTOR times the largest speed
// estimated from b = |g| beta max|T - T0| L: the smaller of a free-fall
// speed FREE_FALL sqrt(b) and a viscous one b L / (VISCOUS_SPEED nu), fitted
// to the side-heated cavity at Ra = 1e3 to 1e5 (the estimate is 1.07, 1.26
// and 1.14 times the benchmark's largest v on y = 1/2 there:
// bench/convection/sound_speed.md)
static constexpr double SPEED_FACTOR = SPHSoundSpeed::SPEED_FACTOR;
static constexpr double FREE_FALL = 0.42;
static constexpr double VISCOUS_SPEED = 120.0;

/* ---------------------------------------------------------------------- */

FixSPHBoussinesq::FixSPHBoussinesq(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), gravity_keyword(0), reference_kind(REFERENCE_GIVEN), layer_given(0.0),
    spacing(0.0), beta(nullptr), force_summed(0), zero_warned(0), compression_checked(0),
    hold_request(-1), hold_logged(-1), potential_sweeps(0), potential_solved(0),
    nmax_potential(0), potential(nullptr), wall_force(nullptr), comm_what(0), list(nullptr),
    wall_bits(0), cutsq_potential(0.0)
{
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/boussinesq requires atom style sph (esph, cv)");
  if (narg < 4)
    error->all(FLERR, "Illegal {} command: expected <T0> (a temperature, 'mean' or 'layers')", cmd);
  if (strcmp(arg[3], "mean") == 0)
    reference_kind = REFERENCE_MEAN;
  else if (strcmp(arg[3], "layers") == 0)
    reference_kind = REFERENCE_LAYERS;
  buoyancy.t0 = (reference_kind == REFERENCE_GIVEN) ? utils::numeric(FLERR, arg[3], false, lmp)
                                                    : 0.0;
  gravity_given[0] = gravity_given[1] = gravity_given[2] = 0.0;
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "gravity") == 0) {
      if (iarg + 3 >= narg)
        error->all(FLERR, "Illegal {} command: 'gravity' needs 3 values (gx gy gz)", cmd);
      for (int k = 0; k < 3; k++)
        gravity_given[k] = utils::numeric(FLERR, arg[iarg + 1 + k], false, lmp);
      gravity_keyword = 1;
      iarg += 4;
    } else if (strcmp(arg[iarg], "layer") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: 'layer' needs a thickness", cmd);
      if (reference_kind != REFERENCE_LAYERS)
        error->all(FLERR, "Illegal {} command: 'layer' is the thickness of T0 'layers'; T0 is {}",
                   cmd, arg[3]);
      layer_given = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(layer_given > 0.0) || !std::isfinite(layer_given))
        error->all(FLERR, "Illegal {} command: 'layer {}': the thickness must be > 0", cmd,
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "potential") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: 'potential' needs the sweeps per step", cmd);
      potential_sweeps = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (potential_sweeps < 0)
        error->all(FLERR, "Illegal {} command: 'potential {}': the sweeps per step must be >= 0",
                   cmd, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "hold") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: 'hold' needs yes or no", cmd);
      if (strcmp(arg[iarg + 1], "yes") == 0)
        hold_request = 1;
      else if (strcmp(arg[iarg + 1], "no") == 0)
        hold_request = 0;
      else
        error->all(FLERR, "Illegal {} command: 'hold {}': give yes or no", cmd, arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }
  // in 2d the atoms move in the xy plane: a z component would push them out of it
  if (gravity_keyword && domain->dimension == 2 && gravity_given[2] != 0.0)
    error->all(FLERR,
               "Illegal {} command: 'gravity {} {} {}' has a z component in a 2d simulation; "
               "give gz = 0 (gravity in the xy plane)",
               cmd, gravity_given[0], gravity_given[1], gravity_given[2]);
  memory->create(beta, atom->ntypes + 1, "sph/boussinesq:beta");
  for (int t = 0; t <= atom->ntypes; t++) beta[t] = 0.0;
  buoyancy.beta = beta;
  buoyancy.groupbit = groupbit;
  buoyancy.gravity = gravity_given;
  buoyancy.nlayers = 0;
  buoyancy.layer_t0 = nullptr;
  buoyancy.unit[0] = buoyancy.unit[1] = buoyancy.unit[2] = 0.0;
  buoyancy.origin = 0.0;
  buoyancy.width = 0.0;    // set at the first update
  buoyancy.potential = nullptr;
  if (potential_sweeps > 0) {
    buoyancy.potential = &potential;
    comm_forward = 3;
    maxexchange = 1;
    restart_peratom = 1;
    peratom_flag = 1;
    size_peratom_cols = 0;
    peratom_freq = 1;
    grow_arrays(atom->nmax);
    atom->add_callback(Atom::GROW);
    atom->add_callback(Atom::RESTART);
  }

  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 1;
  for (int k = 0; k < 3; k++) force_local[k] = force_total[k] = 0.0;
}

FixSPHBoussinesq::~FixSPHBoussinesq()
{
  if (!id_hold.empty() && modify->nfix && modify->find_fix(id_hold) >= 0)
    modify->delete_fix(id_hold);
  memory->destroy(beta);
  if (potential_sweeps > 0) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(potential);
  memory->destroy(wall_force);
}

/* ----------------------------------------------------------------------
   the volume of the group is held by a fix sph/hold/volume of its own
   (which migrates nothing, keeps the volume across restarts and reports
   it), switched on or off at each init by choose_hold()
------------------------------------------------------------------------- */

void FixSPHBoussinesq::post_constructor()
{
  if (hold_request == 0) return;
  id_hold = std::string(id) + "_hold";
  modify->add_fix(fmt::format("{} {} sph/hold/volume", id_hold, group->names[igroup]));
}

int FixSPHBoussinesq::setmask()
{
  return POST_FORCE | (reference_kind != REFERENCE_GIVEN ? END_OF_STEP : 0) |
      (potential_sweeps > 0 ? PRE_FORCE : 0);
}

/* ---------------------------------------------------------------------- */

void FixSPHBoussinesq::init()
{
  if (SPHHub(lmp).fixes<FixSPHBoussinesq>().size() > 1)
    error->all(FLERR,
               "Fix sph/boussinesq: only one may be defined (give each type its beta in "
               "fix sph/materials instead)");

  // g: the keyword's, or fix gravity's (which then also adds the weight)
  const double *gvec = SPHBodyForce::find(lmp, "Fix sph/boussinesq");
  if (gravity_keyword) {
    if (gvec &&
        (gvec[0] != gravity_given[0] || gvec[1] != gravity_given[1] || gvec[2] != gravity_given[2]))
      error->all(FLERR,
                 "Fix sph/boussinesq: 'gravity {} {} {}' differs from the acceleration of the "
                 "body-force fix ({} {} {}); give gravity once (drop the keyword to use the fix's)",
                 gravity_given[0], gravity_given[1], gravity_given[2], gvec[0], gvec[1], gvec[2]);
    buoyancy.gravity = gravity_given;
  } else if (gvec) {
    buoyancy.gravity = gvec;
    // fix gravity of magnitude 0 (a number, not a variable that may ramp it up)
    Fix *source = SPHBodyForce::source(lmp);
    if (!zero_warned && SPHBodyForce::constant_zero(source)) {
      if (comm->me == 0)
        error->warning(FLERR,
                       "Fix sph/boussinesq: the gravity of fix {} (style {}) has magnitude 0, so "
                       "there is no buoyancy; give fix {} a magnitude (or a variable one)",
                       source->id, source->style, source->id);
      zero_warned = 1;
    }
  } else
    error->all(FLERR,
               "Fix sph/boussinesq needs gravity: give 'gravity gx gy gz' (buoyancy only) or "
               "define fix gravity (weight and buoyancy)");
  if (gravity_keyword && gravity_given[0] == 0.0 && gravity_given[1] == 0.0 &&
      gravity_given[2] == 0.0)
    error->all(FLERR, "Fix sph/boussinesq: gravity 0 0 0 gives no buoyancy");

  // beta per type from the hub; the group must have some
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/boussinesq");
  for (int t = 1; t <= atom->ntypes; t++) beta[t] = materials->expansion(t);
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  std::string without;
  int buoyant = 0;
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!present[t]) continue;
    // its equation of state already makes it buoyant under gravity
    const sphe_eos *eos = materials->eos(t);
    if (eos && eos->thermal)
      error->all(FLERR,
                 "Fix sph/boussinesq: atom type {} of group {} has thermal expansion in its "
                 "equation of state (eos ... thermal), which makes it buoyant under fix gravity "
                 "already: use one or the other",
                 t, group->names[igroup]);
    if (beta[t] != 0.0)
      buoyant = 1;
    else
      without += (without.empty() ? "" : " ") + std::to_string(t);
  }
  if (!buoyant)
    error->all(FLERR,
               "Fix sph/boussinesq: no atom type of group {} has an expansion coefficient; set "
               "'expansion' in fix sph/materials",
               group->names[igroup]);
  if (!without.empty() && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/boussinesq: atom type(s) {} of group {} have no expansion coefficient "
                   "and feel no buoyancy",
                   without, group->names[igroup]);
  SPHCheck::atom_state(lmp, FLERR, "Fix sph/boussinesq", groupbit, SPHCheck::CV);
  // before the walls and the pair read T0 in the set-up's forces
  update_reference();
  // before any wall extrapolates a pressure from the buoyancy (at set-up);
  // a fix gravity with variables sets its acceleration at its set-up first
  const int known = gravity_keyword || SPHBodyForce::constant(SPHBodyForce::source(lmp));
  if (known && !gravity_keyword)
    SPHBodyForce::check_finite(lmp, FLERR, "Fix sph/boussinesq", buoyancy.gravity);
  // an 'auto' speed of sound is found here, before any force: it needs g
  if (!compression_checked && !known)
    for (int t = 1; t <= atom->ntypes; t++)
      if (present[t] && beta[t] != 0.0 && materials->sound_speed_pending(t))
        error->all(FLERR,
                   "Fix sph/boussinesq: the speed of sound of atom type {} is 'auto' (fix "
                   "sph/materials), found from g at the run's init, but the gravity of fix {} "
                   "is a variable's: give c0, or the 'gravity' keyword",
                   t, SPHBodyForce::source(lmp)->id);
  if (!compression_checked && known) {
    derive_sound_speeds(materials);
    check_compression();
    compression_checked = 1;
  }
  choose_hold();
  if (potential_sweeps > 0) {
    // phi's Laplacian and the walls' extrapolation use the flow's kernel
    const SPHKernelSettings ks =
        SPHHub(lmp).require_flow("Fix sph/boussinesq with 'potential'")->kernel_settings();
    kernel = sphk_make(ks.kind, domain->dimension, ks.cutoff);
    cutsq_potential = ks.cutoff * ks.cutoff;
    SPHCompat::request_full_list(neighbor, this, instance_me);
    wall_bits = 0;
    for (FixSPHWallAdami *wall : SPHHub(lmp).fixes<FixSPHWallAdami>()) {
      // a wall atom takes the phi its wall extrapolates, a group atom solves for it
      bigint local = 0, both = 0;
      for (int i = 0; i < atom->nlocal; i++)
        if ((atom->mask[i] & groupbit) && (atom->mask[i] & wall->groupbit)) local++;
      MPI_Allreduce(&local, &both, 1, MPI_LMP_BIGINT, MPI_SUM, world);
      if (both)
        error->all(FLERR,
                   "Fix sph/boussinesq with 'potential': {} atoms of group {} are walls of fix {} "
                   "(sph/wall/adami); the buoyant group must be the fluid only",
                   both, group->names[igroup], wall->id);
      wall_bits |= wall->groupbit;
    }
  }
}

/* ----------------------------------------------------------------------
   'hold': the fix's own fix sph/hold/volume on or off, by the keyword or
   the scene's default (SPHSceneDefaults::volume_hold), logged when it
   changes
------------------------------------------------------------------------- */

void FixSPHBoussinesq::choose_hold()
{
  if (id_hold.empty()) return;
  const int ifix = modify->find_fix(id_hold);
  if (ifix < 0) error->all(FLERR, "Fix sph/boussinesq {}: its fix {} was deleted", id, id_hold);
  auto *hold = dynamic_cast<FixSPHHoldVolume *>(modify->fix[ifix]);
  if (!hold)
    error->all(FLERR, "Fix sph/boussinesq {}: fix {} is not its fix sph/hold/volume", id, id_hold);
  SPHSceneDefaults::Choice choice = {1, "the keyword", 0.0};
  if (hold_request < 0) choice = SPHSceneDefaults::volume_hold(lmp, this, hold);
  hold->set_active(choice.value);
  const std::string who = fmt::format("Fix sph/boussinesq {}", id);
  const std::string what = choice.value ? fmt::format("yes, by fix {}", id_hold) : "no";
  SPHSceneDefaults::log(lmp, who.c_str(), "hold", what.c_str(), choice, hold_logged);
}

/* ---------------------------------------------------------------------- */

void FixSPHBoussinesq::setup(int vflag)
{
  post_force(vflag);
  if (!compression_checked) check_compression();
  compression_checked = 1;
}

/* ----------------------------------------------------------------------
   the pressure that balances the buoyancy compresses a weakly compressible
   fluid: across the extent L of the group along g, by at most
     |g| beta max|T - T0| L / c0^2
   (a column at the largest |T - T0| there can be; the temperatures stay
   within those at the start without heat sources). The temperatures: all
   atoms' but those of fix sph/wall/dirichlet, whose own are extrapolated,
   and its wall temperatures. Found once, at the first run's init (at its
   set-up when fix gravity's acceleration is a variable's); 0 when g, the
   extent or the temperature difference is
------------------------------------------------------------------------- */

int FixSPHBoussinesq::compression_scale(double &gnorm, double &dt_max, double &extent)
{
  const SPHParticles particles(atom);
  const double *const g = buoyancy.gravity;
  // scaled: |g| of a typo such as 1e300 must not overflow to inf
  const double gmax = fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
  if (!(gmax > 0.0)) return 0;
  gnorm = gmax *
      sqrt((g[0] / gmax) * (g[0] / gmax) + (g[1] / gmax) * (g[1] / gmax) +
           (g[2] / gmax) * (g[2] / gmax));
  const double unit[3] = {g[0] / gnorm, g[1] / gnorm, g[2] / gnorm};

  int dirichlet_bits = 0;
  double dt_wall = 0.0;
  for (FixSPHWallDirichlet *wall : SPHHub(lmp).fixes<FixSPHWallDirichlet>()) {
    dirichlet_bits |= wall->groupbit;
    dt_wall = fmax(dt_wall, fabs(wall->wall_temperature() - buoyancy.t0));
  }

  const double *const *const x = atom->x;
  const double *const cv = atom->cv;
  const int *const mask = atom->mask;
  // -(lowest projection), highest projection on g, largest |T - T0|
  double local[3] = {-INFINITY, -INFINITY, dt_wall};
  for (int i = 0; i < atom->nlocal; i++) {
    if (mask[i] & groupbit) {
      const double along = x[i][0] * unit[0] + x[i][1] * unit[1] + x[i][2] * unit[2];
      local[0] = fmax(local[0], -along);
      local[1] = fmax(local[1], along);
    }
    if ((mask[i] & dirichlet_bits) || !(cv[i] > 0.0)) continue;
    const double dt = fabs(particles.temperature(i) - buoyancy.t0);
    if (std::isfinite(dt)) local[2] = fmax(local[2], dt);
  }
  double all[3];
  MPI_Allreduce(local, all, 3, MPI_DOUBLE, MPI_MAX, world);
  extent = all[0] + all[1];
  dt_max = all[2];
  return (extent > 0.0) && (dt_max > 0.0);
}

/* ----------------------------------------------------------------------
   'eos ... auto' of fix sph/materials: the speed of sound of each buoyant
   type of the group at which the compression bound of check_compression()
   holds with equality, c0^2 = |g| beta max|T - T0| L / MAX_COMPRESSION;
   the other types with 'auto' take the largest of these
------------------------------------------------------------------------- */

void FixSPHBoussinesq::derive_sound_speeds(FixSPHMaterials *materials)
{
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  int pending = 0;
  for (int t = 1; t <= atom->ntypes; t++)
    if (present[t] && beta[t] != 0.0 && materials->sound_speed_pending(t)) pending = t;
  if (!pending) return;
  double gnorm = 0.0, dt_max = 0.0, extent = 0.0;
  if (!compression_scale(gnorm, dt_max, extent))
    error->all(FLERR,
               "Fix sph/boussinesq: the speed of sound of atom type {} is 'auto' (fix "
               "sph/materials), found from the buoyancy's compression |g| beta max|T - T0| L, "
               "but that is 0 at this run's start (|g| = {:.6g}, max|T - T0| = {:.6g}, L = "
               "{:.6g}): give c0",
               pending, gnorm, dt_max, extent);
  double fastest = 0.0;
  for (int t = 1; t <= atom->ntypes; t++) {
    if (!present[t] || beta[t] == 0.0 || !materials->sound_speed_pending(t)) continue;
    const double scale = gnorm * fabs(beta[t]) * dt_max * extent;
    if (potential_sweeps > 0) {
      // the potential carries the buoyancy's pressure: c0 from the speed
      const double nu = materials->viscosity_at(t, 0.0, "Fix sph/boussinesq") /
          materials->eos(t)->rho0;
      const double free_fall = FREE_FALL * sqrt(scale);
      const double viscous = nu > 0.0 ? scale * extent / (VISCOUS_SPEED * nu) : free_fall;
      const double c0 = SPEED_FACTOR * fmin(free_fall, viscous);
      fastest = fmax(fastest, c0);
      materials->set_sound_speed(
          t, c0,
          fmt::format("auto: {} times the speed estimated from the buoyancy of fix "
                      "sph/boussinesq {} (its potential on), min({} sqrt(b), b L / ({} nu)) = "
                      "min({:.6g}, {:.6g}) with b = |g| beta max|T - T0| L, |g| = {:.6g}, "
                      "beta = {:.6g}, max|T - T0| = {:.6g}, L = {:.6g}, nu = {:.6g}",
                      SPEED_FACTOR, id, FREE_FALL, VISCOUS_SPEED, free_fall, viscous, gnorm,
                      beta[t], dt_max, extent, nu));
      continue;
    }
    const double c0 = sqrt(scale / MAX_COMPRESSION);
    fastest = fmax(fastest, c0);
    materials->set_sound_speed(
        t, c0,
        fmt::format("auto: the buoyancy of fix sph/boussinesq {} compresses it by {}, |g| beta "
                    "max|T - T0| L / c0^2 with |g| = {:.6g}, beta = {:.6g}, max|T - T0| = {:.6g}, "
                    "L = {:.6g}",
                    id, MAX_COMPRESSION, gnorm, beta[t], dt_max, extent));
  }
  // the other 'auto' types that have atoms (the walls of fix sph/wall/adami,
  // which take the pressure of the fluid they bound): the fastest found
  const std::vector<int> anywhere = SPHCheck::group_types(lmp, 1);    // group all
  for (int t = 1; t <= atom->ntypes; t++)
    if (anywhere[t] && materials->sound_speed_pending(t))
      materials->set_sound_speed(
          t, fastest,
          fmt::format("auto: without buoyancy in fix sph/boussinesq {}, the fastest of its types",
                      id));
}

/* ----------------------------------------------------------------------
   the pressure that balances the buoyancy compresses a weakly compressible
   fluid by at most |g| beta max|T - T0| L / c0^2 (compression_scale):
   an error above 1, a warning above MAX_COMPRESSION
------------------------------------------------------------------------- */

void FixSPHBoussinesq::check_compression()
{
  // the potential's pressure carries the buoyancy without compression
  if (potential_sweeps > 0) return;
  double gnorm = 0.0, dt_max = 0.0, extent = 0.0;
  if (!compression_scale(gnorm, dt_max, extent)) return;

  // the type of the group compressed the most
  FixSPHMaterials *materials = FixSPHMaterials::find(lmp, "Fix sph/boussinesq");
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  double worst = 0.0, worst_c0 = 0.0;
  int worst_type = 0;
  for (int t = 1; t <= atom->ntypes; t++) {
    const sphe_eos *eos = materials->eos(t);
    if (!present[t] || !eos || !(eos->c0 > 0.0)) continue;
    const double compression = gnorm * fabs(beta[t]) * dt_max * extent / (eos->c0 * eos->c0);
    if (compression > worst) worst = compression, worst_c0 = eos->c0, worst_type = t;
  }
  // above 1 no weakly compressible state holds the column (a typo in T0,
  // beta or g, most likely): the run would end at a wall or the EOS's floor
  if (worst >= 1.0)
    error->all(FLERR,
               "Fix sph/boussinesq: the buoyancy would compress atom type {} of group {} by {:.3g} "
               "(|g| beta max|T - T0| L / c0^2 with |g| = {:.6g}, beta = {:.6g}, "
               "max|T - T0| = {:.6g}, L = {:.6g}, c0 = {:.6g}): no weakly compressible state; "
               "check T0, beta and g",
               worst_type, group->names[igroup], worst, gnorm, beta[worst_type], dt_max, extent,
               worst_c0);
  // (an 'auto' c0 meets the bound to round-off)
  if (worst > MAX_COMPRESSION * (1.0 + 1e-12) && comm->me == 0)
    error->warning(FLERR,
                   "Fix sph/boussinesq: the buoyancy may compress atom type {} of group {} by up "
                   "to {:.3g} (|g| beta max|T - T0| L / c0^2 with |g| = {:.6g}, beta = {:.6g}, "
                   "max|T - T0| = {:.6g}, L = {:.6g} the group's extent along g, c0 = {:.6g}), "
                   "more than {}, which biases the flow and the heat transfer; raise c0 of type {} "
                   "in fix sph/materials to {:.4g} or more",
                   worst_type, group->names[igroup], worst, gnorm, beta[worst_type], dt_max, extent,
                   worst_c0, MAX_COMPRESSION, worst_type,
                   sqrt(gnorm * fabs(beta[worst_type]) * dt_max * extent / MAX_COMPRESSION));
}

/* ----------------------------------------------------------------------
   T0 'mean': sum m beta T / sum m beta over the group, the T0 at which the
   buoyancy sums to zero; after each step's temperatures, for the next
   step's forces (the walls' and the pair's before this fix's post_force)
------------------------------------------------------------------------- */

void FixSPHBoussinesq::update_mean_reference()
{
  const SPHParticles particles(atom);
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  double local[3] = {0.0, 0.0, 0.0}, all[3];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double weight = particles.mass(i) * beta[type[i]];
    local[0] += weight * particles.temperature(i);
    local[1] += weight;
    local[2] += fabs(weight);
  }
  MPI_Allreduce(local, all, 3, MPI_DOUBLE, MPI_SUM, world);
  buoyancy.t0 = checked_mean(all, fmt::format("T0 mean of group {} is", group->names[igroup]));
}

/* ----------------------------------------------------------------------
   sum m beta T / sum m beta from the group's sums (m beta T, m beta,
   m |beta|), for T0 mean and T0 layers alike; 'head' names which
------------------------------------------------------------------------- */

double FixSPHBoussinesq::checked_mean(const double sum[3], const std::string &head)
{
  const double t0 = sum[0] / sum[1];
  // expansion coefficients of both signs that (nearly) cancel leave T0 to round-off
  if (!std::isfinite(t0) || !(fabs(sum[1]) > 1e-10 * sum[2]))
    error->all(FLERR,
               "Fix sph/boussinesq: {} {} (sum of m beta T {}, of m beta {}, of m |beta| {}): the "
               "group's expansion coefficients sum to zero, or a temperature is not finite",
               head, t0, sum[0], sum[1], sum[2]);
  return t0;
}

/* ----------------------------------------------------------------------
   T0 'layers': sum m beta T / sum m beta over the group's atoms in each
   layer across g. The layers tile the group's extent along g, each about
   the thickness asked for; a layer without buoyant atoms takes the value
   of the nearest one that has some.
------------------------------------------------------------------------- */

void FixSPHBoussinesq::update_layer_reference()
{
  const double *const g = buoyancy.gravity;
  const double gnorm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  // no direction yet (a variable gravity at 0): one layer, the mean
  if (!(gnorm > 0.0) || !std::isfinite(gnorm)) {
    update_mean_reference();
    buoyancy.nlayers = 0;
    return;
  }
  if (!(spacing > 0.0)) spacing = mean_spacing();
  const double thickness = layer_given > 0.0 ? layer_given : 2.0 * spacing;
  for (int k = 0; k < 3; k++) {
    buoyancy.unit[k] = g[k] / gnorm;
    // a periodic image has another height: no layers along a periodic direction
    if (buoyancy.unit[k] != 0.0 && domain->periodicity[k])
      error->all(FLERR,
                 "Fix sph/boussinesq: T0 layers across g = ({} {} {}) need a box that is not "
                 "periodic along g, but it is periodic in {}",
                 g[0], g[1], g[2], "xyz"[k]);
  }
  // the group's extent along g, half a spacing beyond its outer atoms: the
  // layers then centre on the rows of a lattice that fills it
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  double local_extent[2] = {-INFINITY, -INFINITY}, extent[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double along =
        x[i][0] * buoyancy.unit[0] + x[i][1] * buoyancy.unit[1] + x[i][2] * buoyancy.unit[2];
    local_extent[0] = fmax(local_extent[0], -along);
    local_extent[1] = fmax(local_extent[1], along);
  }
  MPI_Allreduce(local_extent, extent, 2, MPI_DOUBLE, MPI_MAX, world);
  const double lo = -extent[0] - 0.5 * spacing;
  const double span = extent[1] + extent[0] + spacing;
  const int n = std::max(1, (int) lround(span / thickness));
  buoyancy.origin = lo;
  buoyancy.width = span / n;
  buoyancy.nlayers = n;

  const SPHParticles particles(atom);
  const int *const type = atom->type;
  std::vector<double> local(3 * (size_t) n, 0.0), all(3 * (size_t) n);
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double along =
        x[i][0] * buoyancy.unit[0] + x[i][1] * buoyancy.unit[1] + x[i][2] * buoyancy.unit[2];
    const int k = std::min(n - 1, std::max(0, (int) floor((along - lo) / buoyancy.width)));
    const double weight = particles.mass(i) * beta[type[i]];
    local[3 * k] += weight * particles.temperature(i);
    local[3 * k + 1] += weight;
    local[3 * k + 2] += fabs(weight);
  }
  MPI_Allreduce(local.data(), all.data(), 3 * n, MPI_DOUBLE, MPI_SUM, world);
  layer_t0.assign(n, 0.0);
  std::vector<int> filled(n, 0);
  double sum[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < n; k++) {
    for (int c = 0; c < 3; c++) sum[c] += all[3 * k + c];
    if (fabs(all[3 * k + 1]) > 1e-10 * all[3 * k + 2]) {
      layer_t0[k] = all[3 * k] / all[3 * k + 1];
      filled[k] = std::isfinite(layer_t0[k]);
    }
  }
  // the whole group's mean, checked as 'mean' checks it; it is the
  // compression check's T0: next to heated sides the buoyancy of the
  // temperature along a layer compresses as that about the mean does
  buoyancy.t0 =
      checked_mean(sum, fmt::format("T0 layers of group {}: the mean is", group->names[igroup]));
  // layers without buoyant atoms: the nearest filled layer's value
  int last = -1;
  for (int k = 0; k < n; k++) {
    if (filled[k]) {
      for (int e = last + 1; e < k; e++)
        layer_t0[e] = (last < 0 || k - e < e - last) ? layer_t0[k] : layer_t0[last];
      last = k;
    }
  }
  for (int e = last + 1; e < n; e++) layer_t0[e] = layer_t0[last];
  buoyancy.layer_t0 = layer_t0.data();
}

/* ----------------------------------------------------------------------
   the group's mean spacing (m / rho)^(1/d); twice it is the default
   thickness of the layers, two rows of particles (fewer atoms per layer
   make T0 noisy, thicker ones leave more of the stratification to the
   pressure)
------------------------------------------------------------------------- */

double FixSPHBoussinesq::mean_spacing()
{
  const SPHParticles particles(atom);
  const double *const rho = atom->rho;
  const int *const mask = atom->mask;
  const double exponent = 1.0 / domain->dimension;
  double local[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !(rho[i] > 0.0)) continue;
    local[0] += pow(particles.mass(i) / rho[i], exponent);
    local[1] += 1.0;
  }
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  const double mean = all[1] > 0.0 ? all[0] / all[1] : 0.0;
  if (!(mean > 0.0) || !std::isfinite(mean))
    error->all(FLERR,
               "Fix sph/boussinesq: T0 layers: group {} has no atom with a finite mass and "
               "density > 0 to take the layers' thickness from; give 'layer <thickness>'",
               group->names[igroup]);
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix sph/boussinesq: T0 by layers across g, {:.6g} thick ({})\n",
                   layer_given > 0.0 ? layer_given : 2.0 * mean,
                   layer_given > 0.0
                       ? std::string("keyword 'layer'")
                       : "twice the mean spacing of group " + std::string(group->names[igroup]));
  return mean;
}

void FixSPHBoussinesq::update_reference()
{
  if (reference_kind == REFERENCE_MEAN)
    update_mean_reference();
  else if (reference_kind == REFERENCE_LAYERS)
    update_layer_reference();
}

void FixSPHBoussinesq::end_of_step()
{
  update_reference();
}

/* ---------------------------------------------------------------------- */

void FixSPHBoussinesq::post_force(int /*vflag*/)
{
  const SPHParticles particles(atom);
  double *const *const f = atom->f;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const double *const g = buoyancy.gravity;
  const double *const *const x = atom->x;
  force_local[0] = force_local[1] = force_local[2] = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double a[3];
    sphb_acceleration(g, beta[type[i]], particles.temperature(i),
                      SPHBodyForce::reference(buoyancy, x[i]), a);
    const double m = particles.mass(i);
    for (int k = 0; k < 3; k++) {
      f[i][k] += m * a[k];
      force_local[k] += m * a[k];
    }
  }
  force_summed = 0;
}

/* ----------------------------------------------------------------------
   the total buoyancy force now
------------------------------------------------------------------------- */

double FixSPHBoussinesq::compute_vector(int n)
{
  if (!force_summed) {
    MPI_Allreduce(force_local, force_total, 3, MPI_DOUBLE, MPI_SUM, world);
    force_summed = 1;
  }
  return force_total[n];
}
