/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/grains: unresolved grains of LAMMPS's GRANULAR package in an SPH
   fluid, coupled both ways by the fluid's kernel (the interpolation and
   the sharing of Robinson, Ramaioli and Luding, Int. J. Multiphase Flow 59
   (2014) 121-134), with the exchange laws of sph_grain_laws.h.
------------------------------------------------------------------------- */

#include "fix_sph_grains.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_inlet_temperature.h"
#include "fix_sph_materials.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_body_force.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_eos.h"
#include "sph_grain_laws.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_particle.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/grains";

static double sphere_volume(double radius)
{
  return 4.0 / 3.0 * M_PI * radius * radius * radius;
}

/* ----------------------------------------------------------------------
   fix ID grains sph/grains fluid <group> [drag <law>] [heat <law>] [fill yes|no]
                                  [pressure gradient|hydrostatic]
------------------------------------------------------------------------- */

// the restart's layout: whether the fluid was filled into the pores
static constexpr int RESTART_VERSION = 1;

FixSPHGrains::FixSPHGrains(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), fluid_groupbit(0), drag_kind(SPHG_DRAG_DIFELICE),
    heat_kind(SPHG_HEAT_RANZ_MARSHALL), pressure_kind(SPHG_PRESSURE_HYDROSTATIC), list(nullptr),
    materials(nullptr), kernel(), cutsq(0.0), reaction(nullptr), nmax(0), at_grain(nullptr),
    totals_step(-1), fill(0), filled(0), porosity(nullptr), reverse_mode(REVERSE_REACTION)
{
  for (int iarg = 3; iarg < narg; iarg += 2) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal {} command: keyword {} needs a value", cmd, arg[iarg]);
    const char *value = arg[iarg + 1];
    if (strcmp(arg[iarg], "fluid") == 0) {
      if (group->find(value) < 0)
        error->all(FLERR, "Illegal {} command: no group {} (keyword fluid)", cmd, value);
      fluid_name = value;
    } else if (strcmp(arg[iarg], "drag") == 0) {
      drag_kind = sphg_drag_lookup(value);
      if (drag_kind < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown drag law {} (expected stokes, difelice or "
                   "gidaspow)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "heat") == 0) {
      heat_kind = sphg_heat_lookup(value);
      if (heat_kind < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown heat law {} (expected none, ranz-marshall or "
                   "gunn)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "fill") == 0) {
      fill = SPHCompat::yes_no(error, FLERR, cmd, "fill", value);
    } else if (strcmp(arg[iarg], "pressure") == 0) {
      pressure_kind = sphg_pressure_lookup(value);
      if (pressure_kind < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown pressure form {} (expected gradient or "
                   "hydrostatic)",
                   cmd, value);
    } else
      error->all(FLERR,
                 "Illegal {} command: unknown keyword {} (expected fluid, drag, heat, fill or "
                 "pressure)",
                 cmd, arg[iarg]);
  }
  if (fluid_name.empty())
    error->all(FLERR, "Illegal {} command: keyword fluid (the fluid's group) is required", cmd);
  check_atom_style();

  vector_flag = 1;    // force on the grains (3), heat into them, grains out of fluid, porosity
  size_vector = 6;
  extvector = 0;
  global_freq = 1;
  peratom_flag = 1;    // slip (3), porosity and fluid temperature at each grain
  size_peratom_cols = 5;
  peratom_freq = 1;
  comm_reverse = REACTION_VALUES;
  comm_forward = 1;
  restart_global = 1;
  for (double &v : local) v = 0.0;
  for (double &v : totals) v = 0.0;
}

FixSPHGrains::~FixSPHGrains()
{
  if (porosity_fix_made && modify->nfix && modify->find_fix(porosity_fix_id().c_str()) >= 0)
    modify->delete_fix(porosity_fix_id().c_str());
  memory->destroy(reaction);
  memory->destroy(at_grain);
}

int FixSPHGrains::setmask()
{
  return PRE_FORCE | POST_FORCE;
}

/* ----------------------------------------------------------------------
   the fluid's porosity, a per-atom vector of an internal fix property/atom
   that grows it with the atoms and gives the ghosts room (made here: a fix
   cannot be added during init)
------------------------------------------------------------------------- */

std::string FixSPHGrains::porosity_fix_id() const
{
  return std::string(id) + "_porosity";
}

void FixSPHGrains::post_constructor()
{
  if (SPHParticles::porosity_of(atom))
    error->all(FLERR,
               "{} {}: another fix sph/grains holds the fluid's porosity ({}): one fix "
               "sph/grains per scene, its group all the grains",
               cmd, id, SPHParticles::POROSITY_VECTOR);
  modify->add_fix(fmt::format("{} all property/atom d_{} ghost yes", porosity_fix_id(),
                              SPHParticles::POROSITY_VECTOR));
  porosity_fix_made = 1;
  porosity = SPHParticles::porosity_of(atom);
  for (int i = 0; i < atom->nlocal + atom->nghost; i++) porosity[i] = 1.0;
}

void FixSPHGrains::check_atom_style() const
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR,
               "{} requires the grains' radius and mass of atom style sphere (atom_style hybrid "
               "sph sphere)",
               cmd);
  if (!atom->rho_flag || !atom->esph_flag || !atom->cv_flag)
    error->all(FLERR,
               "{} requires the fluid's rho, esph and cv of atom style sph (atom_style hybrid "
               "sph sphere)",
               cmd);
}

/* ---------------------------------------------------------------------- */

void FixSPHGrains::init()
{
  if (domain->dimension != 3)
    error->all(FLERR, "{}: the grains' drag and heat laws are those of spheres: a 3-d run only",
               cmd);
  check_atom_style();
  const int fluid_group = group->find(fluid_name);
  if (fluid_group < 0)
    error->all(FLERR, "{} {}: group {} (keyword fluid) was deleted", cmd, id, fluid_name);
  fluid_groupbit = group->bitmask[fluid_group];
  if (SPHCheck::groups_overlap(lmp, groupbit, fluid_groupbit))
    error->all(FLERR, "{} {}: the grains (group {}) and the fluid (group {}) share atoms", cmd, id,
               group->names[igroup], fluid_name);
  if (SPHCheck::group_count(lmp, fluid_groupbit) == 0)
    error->all(FLERR, "{} {}: the fluid (group {}) has no atoms", cmd, id, fluid_name);
  // the ghosts' velocities: the flow pair's (it requires them)

  materials = FixSPHMaterials::find(lmp, cmd);
  SPHHub hub(lmp);
  PairSPHHarmonicVisc *flow = hub.require_flow(cmd);
  const SPHKernelSettings settings = flow->kernel_settings();
  kernel = sphk_make(settings.kind, 3, settings.cutoff);
  cutsq = settings.cutoff * settings.cutoff;

  // the fluid is the flow's (which checks that its types have an eos and a
  // viscosity); the heat laws also read its conductivity
  const int ntypes = atom->ntypes;
  std::vector<int> mine(ntypes + 1, 0), fluid_types(ntypes + 1, 0);
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & fluid_groupbit) mine[atom->type[i]] = 1;
  MPI_Allreduce(mine.data(), fluid_types.data(), ntypes + 1, MPI_INT, MPI_MAX, world);
  for (int type = 1; type <= ntypes; type++) {
    if (!fluid_types[type]) continue;
    if (!flow->setflag[type][type])
      error->all(FLERR,
                 "{} {}: fluid type {} (group {}) is not a fluid of pair sph/harmonic/visc "
                 "(pair_coeff {} {})",
                 cmd, id, type, fluid_name, type, type);
    if (heat_kind != SPHG_HEAT_NONE && !materials->conductivity(type))
      error->all(FLERR, "{} {}: fluid type {} has no conductivity in fix sph/materials (heat {})",
                 cmd, id, type, sphg_heat_name(heat_kind));
  }
  if (heat_kind != SPHG_HEAT_NONE) {
    // one message for both releases: 29Sep2021 has no granular heat model
    const bool fields = SPHCompat::granular_temperature(atom) && SPHCompat::granular_heatflow(atom);
    if (!fields || (hub.heat_flow_integrated() & groupbit) != groupbit)
      error->all(FLERR,
                 "{} {}: heat {} needs the granular heat model of LAMMPS 4Feb2025 or later: the "
                 "grains' temperature and heat flow (fix property/atom temperature heatflow) and "
                 "fix heat/flow on the grains (group {}) to integrate them; {}. Or 'heat none'",
                 cmd, id, sphg_heat_name(heat_kind), group->names[igroup],
                 !SPHCompat::has_granular_heat() ? "this LAMMPS has no such model"
                     : !fields                   ? "the atoms have no temperature"
                                                 : "no fix heat/flow integrates them all");
  }
  // a periodic inlet (fix sph/inlet/temperature): the grains' heat keeps to
  // their side of its plane, as the fluid's conduction does
  inlet_axis = -1;
  for (FixSPHInletTemperature *inlet : hub.fixes<FixSPHInletTemperature>())
    inlet_axis = inlet->flow_axis();
  // the hydrostatic form's buoyancy: the body force's (none: no buoyancy)
  body_force = (pressure_kind == SPHG_PRESSURE_HYDROSTATIC)
      ? SPHBodyForce::find(lmp, "Fix sph/grains")
      : nullptr;
  if (body_force) warn_weightless_fluid();
  SPHCompat::request_full_list(neighbor, this, instance_me, settings.cutoff);
}

/* the buoyancy -V rho_f g is the reaction of the fluid's weight: a body
   force on the grains that leaves some of the fluid out pushes that fluid
   down with nothing to hold it (and without the hydrostatic form the
   grains would float on nothing) */

void FixSPHGrains::warn_weightless_fluid()
{
  const int weighted = SPHBodyForce::groupbits(lmp);
  bigint mine = 0, weightless = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & fluid_groupbit) && !(atom->mask[i] & weighted)) mine++;
  MPI_Allreduce(&mine, &weightless, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (weightless > 0 && comm->me == 0)
    error->warning(FLERR,
                   "{} {}: {} atoms of the fluid (group {}) are not under the body force that "
                   "gives the grains their buoyancy (pressure hydrostatic): the buoyancy's "
                   "reaction pushes them with no weight to balance it; apply it to the fluid too",
                   cmd, id, weightless, fluid_name);
}

void FixSPHGrains::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

void FixSPHGrains::setup_pre_force(int /*vflag*/)
{
  update_porosity();
  if (fill && !filled) fill_pores();
}

void FixSPHGrains::pre_force(int /*vflag*/)
{
  update_porosity();
}

void FixSPHGrains::setup(int /*vflag*/)
{
  exchange();
}

/* ----------------------------------------------------------------------
   each fluid atom's porosity eps = 1 - sum_k V_k W_jk over the grains k
   (as at a grain, after Robinson et al. 2014), owned and ghost; 1 for
   every other atom
------------------------------------------------------------------------- */

void FixSPHGrains::update_porosity()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  refresh_arrays();
  for (int i = 0; i < nall; i++) reaction[i][0] = 0.0;
  double **x = atom->x;
  const double *radius = atom->radius;
  const int *mask = atom->mask;
  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const double grain_volume = sphere_volume(radius[i]);
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & fluid_groupbit)) continue;
      const double dx[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq < cutsq) reaction[j][0] += grain_volume * sphk_w(&kernel, sqrt(rsq));
    }
  }
  reverse_mode = REVERSE_POROSITY;
  SPHCompat::reverse_comm(comm, this);
  reverse_mode = REVERSE_REACTION;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & fluid_groupbit)) {
      porosity[i] = 1.0;
      continue;
    }
    porosity[i] = 1.0 - reaction[i][0];
    if (!(porosity[i] > 0.0))
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format("{} {}: the grains fill {} of the kernel's volume around fluid atom {}: "
                      "the porosity there is not positive; the kernel's support ({}) must be "
                      "several grain diameters and the grains must not overlap",
                      cmd, id, reaction[i][0], atom->tag[i], sqrt(cutsq)));
  }
  SPHCompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   'fill yes', once (a restart remembers it): the fluid around grains placed
   in it takes the pores' share of its mass, rho and m times eps, so that
   the fluid's own density rho / eps and its particles' volumes m / rho are
   those the fluid had without the grains (owned and ghost alike)
------------------------------------------------------------------------- */

void FixSPHGrains::fill_pores()
{
  double *rho = atom->rho, *rmass = atom->rmass;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal + atom->nghost; i++) {
    if (!(mask[i] & fluid_groupbit)) continue;
    rho[i] *= porosity[i];
    rmass[i] *= porosity[i];
  }
  filled = 1;
}

void FixSPHGrains::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double state[1] = {(double) filled};
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state, 1);
}

void FixSPHGrains::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  filled = state[0] != 0.0;
}

void FixSPHGrains::post_force(int /*vflag*/)
{
  exchange();
}

// this step's arrays: the fix's own grown to the atoms, the porosity's
// pointer (moved when fix property/atom grows it)
void FixSPHGrains::refresh_arrays()
{
  porosity = SPHParticles::porosity_of(atom);
  if (atom->nlocal + atom->nghost <= nmax) return;
  memory->destroy(reaction);
  memory->destroy(at_grain);
  nmax = atom->nmax;
  memory->create(reaction, nmax, REACTION_VALUES, "sph/grains:reaction");
  memory->create(at_grain, nmax, 5, "sph/grains:at_grain");
  array_atom = at_grain;
}

/* ----------------------------------------------------------------------
   the exchange of one force evaluation: each owned grain's interpolation,
   laws and share; the fluid's ghosts send their shares to their owners
------------------------------------------------------------------------- */

void FixSPHGrains::exchange()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  refresh_arrays();
  for (int i = 0; i < nlocal; i++) {
    for (int k = 0; k < 5; k++) at_grain[i][k] = 0.0;
    if (atom->mask[i] & fluid_groupbit) at_grain[i][3] = porosity[i];
  }
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < REACTION_VALUES; k++) reaction[i][k] = 0.0;

  double **x = atom->x, **v = atom->v, **f = atom->f;
  const double *radius = atom->radius, *rmass = atom->rmass;
  double *desph = atom->desph;
  const int *mask = atom->mask, *type = atom->type;
  const tagint *tag = atom->tag;
  const double *grain_temperature = SPHCompat::granular_temperature(atom);
  double *heatflow = SPHCompat::granular_heatflow(atom);
  const SPHParticles particles(atom);
  const double dt = update->dt;
  const double minus_dwdr_r_scale = -kernel.dw_scale * kernel.inv_h;
  const double w0 = sphk_w(&kernel, 0.0);
  const int heat = heat_kind != SPHG_HEAT_NONE;

  for (double &value : local) value = 0.0;
  local[5] = 1.0;
  totals_step = -1;

  const int inum = list->inum;
  const int *ilist = list->ilist, *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const double d = 2.0 * radius[i];
    const double grain_volume = sphere_volume(radius[i]);
    // Shepard sums of the fluid (weight V_j W_ij) and the grains' volume
    // fraction; the heat's of the fluid on the grain's side of an inlet plane
    double weight = 0.0, u[3] = {0.0, 0.0, 0.0}, fluid_t = 0.0, fluid_rho = 0.0;
    double fluid_mu = 0.0, fluid_k = 0.0, fluid_cp = 0.0, heat_weight = 0.0;
    const double side = (inlet_axis < 0)
        ? 0.0
        : FixSPHInletTemperature::periodic_cell(domain, x[i][inlet_axis], inlet_axis);
    double solid = grain_volume * w0;
    sphi_point pressure;
    sphi_begin(&pressure, 3);
    shares.clear();
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq) continue;
      const double r = sqrt(rsq);
      const double w = sphk_w(&kernel, r);
      if (mask[j] & groupbit) {
        solid += sphere_volume(radius[j]) * w;
        continue;
      }
      if (!(mask[j] & fluid_groupbit)) continue;
      const double volume = particles.volume(j);
      const double vw = volume * w;
      const double vw_heat =
          (inlet_axis < 0 ||
           FixSPHInletTemperature::periodic_cell(domain, x[j][inlet_axis], inlet_axis) == side)
          ? vw
          : 0.0;
      shares.push_back({j, vw, vw_heat, particles.temperature(j)});
      const double t = particles.temperature(j);
      weight += vw;
      for (int k = 0; k < 3; k++) u[k] += vw * v[j][k];
      const double rho_j = particles.fluid_density(j);
      fluid_rho += vw * rho_j;
      fluid_mu += vw * materials->viscosity_at(type[j], t, cmd);
      heat_weight += vw_heat;
      fluid_t += vw_heat * t;
      if (heat) {
        fluid_k += vw_heat * materials->conductivity_at(type[j], t, cmd);
        fluid_cp += vw_heat * particles.sensible_cv(j);
      }
      if (pressure_kind == SPHG_PRESSURE_GRADIENT) {
        const double g = minus_dwdr_r_scale * sphk_df_over_q(kernel.kind, r * kernel.inv_h);
        sphi_add_g(&pressure, dx, w, g, volume,
                   sphe_pressure_at(materials->eos(type[j]), rho_j, t));
      }
    }
    if (!(weight > 0.0)) {    // out of the fluid (above its surface, say): no exchange
      local[4] += 1.0;
      continue;
    }
    const double porosity = 1.0 - solid;
    if (!(porosity > 0.0))
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format("{} {}: the grains fill {} of the kernel's volume around grain atom {}: the "
                      "porosity there is not positive; the kernel's support ({}) must be several "
                      "grain diameters ({})",
                      cmd, id, solid, tag[i], sqrt(cutsq), d));
    local[5] = std::min(local[5], porosity);
    for (double &value : u) value /= weight;
    if (heat_weight > 0.0) fluid_t /= heat_weight;
    fluid_rho /= weight;
    fluid_mu /= weight;
    double pressure_value = 0.0, grad_p[3] = {0.0, 0.0, 0.0};
    if (pressure_kind == SPHG_PRESSURE_GRADIENT)
      sphi_solve(&pressure, kernel.h, &pressure_value, grad_p);

    const double slip[3] = {u[0] - v[i][0], u[1] - v[i][1], u[2] - v[i][2]};
    const double speed = sqrt(slip[0] * slip[0] + slip[1] * slip[1] + slip[2] * slip[2]);
    const double beta = sphg_drag_beta(drag_kind, d, porosity, fluid_rho, fluid_mu, speed);
    double force[3];
    sphg_fluid_force(pressure_kind, beta, porosity, slip, grain_volume, grad_p, fluid_rho,
                     body_force, force);
    const double slip_coefficient = sphg_slip_coefficient(pressure_kind, beta, porosity);
    // h A, and the heat h A (T_f - T_i) with T_f the fluid's at the grain
    double conductance = 0.0, q = 0.0;
    if (heat && heat_weight > 0.0) {
      conductance = sphg_conductance(heat_kind, d, porosity, fluid_rho, fluid_mu,
                                     fluid_k / heat_weight, fluid_cp / heat_weight, speed);
      q = conductance * (fluid_t - grain_temperature[i]);
    }
    if (!std::isfinite(force[0] + force[1] + force[2] + q))
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format("{} {}: grain atom {} gets a non-finite exchange with the fluid (force {} {} "
                      "{}, heat {}; fluid at the grain: T {}, rho {}, viscosity {})",
                      cmd, id, tag[i], force[0], force[1], force[2], q, fluid_t, fluid_rho,
                      fluid_mu));
    if (dt * slip_coefficient > rmass[i])
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format(
              "{} {}: the drag relaxes the slip of grain atom {} in m / beta = {}, less than "
              "the timestep {}: the explicit coupling is unstable; take a smaller timestep",
              cmd, id, tag[i], rmass[i] / slip_coefficient, dt));
    for (int k = 0; k < 3; k++) {
      f[i][k] += force[k];
      local[k] += force[k];
    }
    if (heat) heatflow[i] += q;
    local[3] += q;
    for (int k = 0; k < 3; k++) at_grain[i][k] = slip[k];
    at_grain[i][3] = porosity;
    at_grain[i][4] = fluid_t;

    // the opposite, shared in proportion to V_j W_ij: the shares sum to one.
    // The heat pair by pair, h A (T_j - T_i) V_j W_ij / sum: the same total
    // (T_f is linear in the T_j), and a fluid particle colder than the
    // grain never gives it heat (a share in proportion to V_j W_ij alone
    // would cool the fluid ahead of a hot front below its temperature)
    const double inv_weight = 1.0 / weight;
    const double heat_scale = (heat_weight > 0.0) ? conductance / heat_weight : 0.0;
    for (const Share &share : shares) {
      for (int k = 0; k < 3; k++) reaction[share.atom][k] -= share.weight * inv_weight * force[k];
      reaction[share.atom][4] += share.weight * inv_weight * slip_coefficient;
      if (heat)
        reaction[share.atom][3] -=
            share.heat_weight * heat_scale * (share.temperature - grain_temperature[i]);
    }
  }

  SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & fluid_groupbit)) continue;
    for (int k = 0; k < 3; k++) f[i][k] += reaction[i][k];
    desph[i] += reaction[i][3] / particles.mass(i);
    // the fluid's side of the explicit drag: its shares of the grains' beta
    // relax its velocity in m / sum beta
    if (dt * reaction[i][4] > particles.mass(i))
      SPHCheck::stop(
          lmp, FLERR,
          fmt::format("{} {}: the grains' drag relaxes the velocity of fluid atom {} in m / "
                      "(its share of their beta) = {}, less than the timestep {}: the "
                      "explicit coupling is unstable; take a smaller timestep",
                      cmd, id, tag[i], particles.mass(i) / reaction[i][4], dt));
  }
}

/* ---------------------------------------------------------------------- */

int FixSPHGrains::pack_reverse_comm(int n, int first, double *buf)
{
  const int values = reverse_mode == REVERSE_POROSITY ? 1 : REACTION_VALUES;
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int k = 0; k < values; k++) buf[m++] = reaction[i][k];
  return m;
}

void FixSPHGrains::unpack_reverse_comm(int n, int *list_send, double *buf)
{
  const int values = reverse_mode == REVERSE_POROSITY ? 1 : REACTION_VALUES;
  int m = 0;
  for (int i = 0; i < n; i++)
    for (int k = 0; k < values; k++) reaction[list_send[i]][k] += buf[m++];
}

int FixSPHGrains::pack_forward_comm(int n, int *list_send, double *buf, int /*pbc_flag*/,
                                    int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = porosity[list_send[i]];
  return n;
}

void FixSPHGrains::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) porosity[first + i] = buf[i];
}

/* ----------------------------------------------------------------------
   the last exchange's totals over all ranks: force of the fluid on the
   grains (1-3), heat into them (4), grains with no fluid around (5), the
   smallest porosity at a grain with fluid around (6; 1 with none)
------------------------------------------------------------------------- */

double FixSPHGrains::compute_vector(int n)
{
  if (totals_step != update->ntimestep) {
    MPI_Allreduce(local, totals, 5, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(&local[5], &totals[5], 1, MPI_DOUBLE, MPI_MIN, world);
    totals_step = update->ntimestep;
  }
  return totals[n];
}

double FixSPHGrains::memory_usage()
{
  return (REACTION_VALUES + 5.0) * nmax * sizeof(double);
}
