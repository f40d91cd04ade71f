/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/harmonic/visc: continuity and momentum of weakly compressible
   SPH in one pass per pair (sph_flow.h): the pressure forms of Cleary 1998,
   Ng et al. 2020 and Reece et al. 2024 with their continuity equations,
   viscosity with a harmonic (Cleary 1998, eq 4; Ng et al. 2020, eq 7) or
   arithmetic (Reece et al. 2024, eq 12) mean of the per-type, optionally
   temperature-dependent viscosities, equations of state and materials from
   fix sph/materials; optional density diffusion (Ng et al. 2020, eq 5).
   References: doc/src/Bibliography_sphthermal.rst.
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
#include "sph_support.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static const char cmd[] = "pair_style sph/harmonic/visc";

// the layout of the restart settings: raise it when a setting is added
static constexpr int RESTART_VERSION = 1;

/* ---------------------------------------------------------------------- */

PairSPHHarmonicVisc::PairSPHHarmonicVisc(LAMMPS *lmp) :
    PairSPHKernel(lmp, "sph/harmonic/visc",
                  "viscosities and equations of state come from fix sph/materials"),
    pressure_form(SPHF_P_AVERAGED), viscosity_form(SPHF_V_ADAMI), xi(SPHF_XI_CLEARY), delta(0.1),
    heating(0.0), mean_pressure_held(0), mean_pressure(0.0), gradient_correction(0),
    gradient_inverse(nullptr), nmax_gradient(0), comm_stage(COMM_VEST),
    diffusion_form(DIFFUSION_BODY_FORCE), hydrostatic(0), body_force(nullptr), eta2(0.0),
    materials(nullptr), viscosity_varies(0), wall_groupbit(0), pressure(nullptr),
    viscosity(nullptr), mass_of(nullptr), volume(nullptr), density(nullptr),
    diffused_density(nullptr), diffusion_rho(nullptr), thermal_expansion(0), nmax(0), heat(nullptr),
    shift_sums_wanted(0), shift_sum(nullptr), nmax_shift(0)
{
  // the continuity equation and the viscous term need the velocities of
  // ghost atoms: turned on here, as comm_modify vel yes would
  comm->ghost_velocity = 1;
  comm_forward = 6;    // vest at setup (3); the gradient correction's B (6)
  comm_reverse = 6;    // the shift sums of ghosts (3); the gradient correction's moments (6)
  // compute pair: the offset 'mean_pressure' subtracted (0 without it)
  nextra = 1;
  pvector = new double[nextra];
  pvector[0] = 0.0;
  gravity[0] = gravity[1] = gravity[2] = 0.0;
}

PairSPHHarmonicVisc::~PairSPHHarmonicVisc()
{
  memory->destroy(pressure);
  memory->destroy(viscosity);
  memory->destroy(mass_of);
  memory->destroy(volume);
  memory->destroy(density);
  memory->destroy(diffused_density);
  memory->destroy(shift_sum);
  memory->destroy(gradient_inverse);
  delete[] pvector;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  begin_compute();
  const Rates rates = {atom->f, atom->drho, atom->desph, heat_term.relax_rate, nullptr};
  eval_pairs(0, list->inum, rates);
  end_compute();
  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   before the pair loops: the per-atom state they read
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::begin_compute()
{
  SPHCheck::particles(lmp, FLERR, "Pair style sph/harmonic/visc", SPHCheck::RHO | SPHCheck::ESPH);
  // fix sph sets vest = v on owned atoms at setup without updating their
  // ghosts: refresh them, or results depend on newton and the rank count
  if (update->setupflag) {
    comm_stage = COMM_VEST;
    SPHCompat::forward_comm(comm, this);
  }
  update_atom_state();
  if (update->setupflag) check_neighbours();
  if (gradient_correction) {
    switch (kernel_kind) {
      case SPHK_LUCY:
        update_gradient_correction<SPHK_LUCY>();
        break;
      case SPHK_CUBIC:
        update_gradient_correction<SPHK_CUBIC>();
        break;
      case SPHK_QUINTIC:
        update_gradient_correction<SPHK_QUINTIC>();
        break;
      case SPHK_WENDLAND:
        update_gradient_correction<SPHK_WENDLAND>();
        break;
    }
  }
  // fix gravity may vary its acceleration in time
  if (diffusion_form == DIFFUSION_BODY_FORCE && body_force) {
    for (int k = 0; k < 3; k++) gravity[k] = body_force[k];
    hydrostatic = (gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0);
  }
  heat_term = PairSPHClearyHeat::FlowLoopTerm();
  if (heat && heat->term_in_flow_loop()) heat_term = heat->begin_flow_loop_term();
  if (shift_sums_wanted) {
    if (atom->nmax > nmax_shift) {
      nmax_shift = atom->nmax;
      memory->destroy(shift_sum);
      memory->create(shift_sum, 3 * nmax_shift, "pair:shift_sum");
    }
    memset(shift_sum, 0, 3 * sizeof(double) * (atom->nlocal + atom->nghost));
  }
}

/* ----------------------------------------------------------------------
   the pair loops over ilist[ifrom..ito), adding to 'rates'
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::eval_pairs(int ifrom, int ito, const Rates &rates)
{
  switch (kernel_kind) {
    case SPHK_LUCY:
      eval_kernel<SPHK_LUCY>(ifrom, ito, rates);
      break;
    case SPHK_CUBIC:
      eval_kernel<SPHK_CUBIC>(ifrom, ito, rates);
      break;
    case SPHK_QUINTIC:
      eval_kernel<SPHK_QUINTIC>(ifrom, ito, rates);
      break;
    case SPHK_WENDLAND:
      eval_kernel<SPHK_WENDLAND>(ifrom, ito, rates);
      break;
  }
}

/* ----------------------------------------------------------------------
   after the pair loops (the rates summed): no non-finite rate
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::end_compute()
{
  check_rates3(atom->f, "force");
  check_rates(atom->drho, "drho");
  if (heat && heat->term_in_flow_loop()) heat->end_flow_loop_term();
  if (shift_sums_wanted && force->newton_pair) {
    comm_stage = COMM_SHIFT;
    SPHCompat::reverse_comm(comm, this);
  }
}

/* ---------------------------------------------------------------------- */

bool PairSPHHarmonicVisc::provide_shift_sums(int groupbit)
{
  // the corrected loop does not make them (fix sph/shift then sums them itself)
  if (pressure_form != SPHF_P_AVERAGED || gradient_correction) return false;
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

int PairSPHHarmonicVisc::pack_reverse_comm(int n, int first, double *buf)
{
  if (comm_stage == COMM_GRADIENT_MOMENT) {
    int m = 0;
    for (int i = first; i < first + n; i++)
      for (int k = 0; k < 6; k++) buf[m++] = gradient_inverse[i][k];
    return m;
  }
  memcpy(buf, &shift_sum[3 * (size_t) first], 3 * sizeof(double) * n);
  return 3 * n;
}

void PairSPHHarmonicVisc::unpack_reverse_comm(int n, int *list_send, double *buf)
{
  if (comm_stage == COMM_GRADIENT_MOMENT) {
    for (int k = 0; k < n; k++)
      for (int a = 0; a < 6; a++) gradient_inverse[list_send[k]][a] += buf[6 * k + a];
    return;
  }
  for (int k = 0; k < n; k++)
    for (int a = 0; a < 3; a++) shift_sum[3 * (size_t) list_send[k] + a] += buf[3 * k + a];
}

/* ----------------------------------------------------------------------
   'correction gradient': B = M^-1 per fluid atom, with the moment
     M_i = sum_j V_j (-dW/dr / r) r_ij (x) r_ij = -sum_j V_j r_ij (x) grad_i W_ij
   over every neighbour in the support (fluid and wall), which is I for a
   complete support in the continuum (0.974 I on a square lattice with
   Wendland C2 and h = 1.3 dx, about 0.95 I on particles that have
   rearranged). With B grad W in place of grad W (Bonet & Lok 1999) the pair
   force of a linear pressure field is exactly -V grad p where the
   neighbours' B are equal and sum_j V_j grad W_ij = 0 (any lattice; test
   flow.gradient.linear); on disordered particles the moment's error is
   removed and the zeroth-order sum remains, which moves particles towards
   an even arrangement as in the plain form. Atoms whose smallest
   eigenvalue of M is below FULL_SUPPORT (a free surface) and wall
   particles keep B = I.
------------------------------------------------------------------------- */

// smallest eigenvalue of M that counts as complete support: 0.974 inside a
// square lattice, about 0.5 in the first row of a free surface
static constexpr double FULL_SUPPORT = 0.7;

template <int KERNEL> void PairSPHHarmonicVisc::update_gradient_correction()
{
  const int dim = domain->dimension;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  if (atom->nmax > nmax_gradient) {
    nmax_gradient = atom->nmax;
    memory->destroy(gradient_inverse);
    memory->create(gradient_inverse, nmax_gradient, 6, "pair:gradient_inverse");
  }
  double **const moment = gradient_inverse;    // M until B replaces it
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < 6; k++) moment[i][k] = 0.0;
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = ilist[ii];
    const int wall_i = mask[i] & wall_groupbit;
    const int *const jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1],
                             (dim == 3) ? x[i][2] - x[j][2] : 0.0};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq_kernel) continue;
      const double g = -dwdr_r_scale * sphk_df_over_q(KERNEL, sqrt(rsq) * inv_h);
      if (!wall_i) sphc_moment_add(moment[i], g * volume[j], del);
      if (!wall_j && (newton_pair || j < nlocal)) sphc_moment_add(moment[j], g * volume[i], del);
    }
  }
  comm_stage = COMM_GRADIENT_MOMENT;
  if (newton_pair) SPHCompat::reverse_comm(comm, this);
  bigint plain = 0, fluid = 0;
  for (int i = 0; i < nlocal; i++) {
    double inverse[6] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
    if (!(mask[i] & wall_groupbit)) {
      fluid++;
      const int full = sphc_sym_min_eigen(dim, moment[i]) >= FULL_SUPPORT &&
          sphc_sym_inverse(dim, moment[i], inverse) > 0.0;
      if (!full) {
        plain++;
        for (int k = 0; k < 6; k++) inverse[k] = (k < 3) ? 1.0 : 0.0;
      }
    }
    for (int k = 0; k < 6; k++) moment[i][k] = inverse[k];
  }
  comm_stage = COMM_GRADIENT_INVERSE;
  SPHCompat::forward_comm(comm, this);
  if (update->setupflag) {
    bigint mine[2] = {plain, fluid}, all[2];
    MPI_Allreduce(mine, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "Pair style sph/harmonic/visc: correction gradient on {} fluid atoms; {} keep "
                     "the plain gradient (incomplete kernel support: free surfaces or too few "
                     "neighbours)\n",
                     all[1] - all[0], all[0]);
  }
}

void PairSPHHarmonicVisc::tally_pair(int i, int j, double fx, double fy, double fz, double delx,
                                     double dely, double delz, void * /*thread*/)
{
  ev_tally_xyz(i, j, atom->nlocal, force->newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
}

template <int KERNEL>
void PairSPHHarmonicVisc::eval_kernel(int ifrom, int ito, const Rates &rates)
{
  switch (pressure_form) {
    case SPHF_P_SYMMETRIC:
      eval_pressure<KERNEL, SPHF_P_SYMMETRIC>(ifrom, ito, rates);
      break;
    case SPHF_P_SUM:
      eval_pressure<KERNEL, SPHF_P_SUM>(ifrom, ito, rates);
      break;
    default:
      eval_pressure<KERNEL, SPHF_P_AVERAGED>(ifrom, ito, rates);
  }
  // viscous heating: a pass of its own, only when asked for
  if (heating > 0.0) eval_heating_kernel<KERNEL>(ifrom, ito, rates);
}

template <int KERNEL, int PRESSURE>
void PairSPHHarmonicVisc::eval_pressure(int ifrom, int ito, const Rates &rates)
{
  switch (viscosity_form) {
    case SPHF_V_CLEARY:
      eval_terms<KERNEL, PRESSURE, SPHF_V_CLEARY>(ifrom, ito, rates);
      break;
    case SPHF_V_MORRIS:
      eval_terms<KERNEL, PRESSURE, SPHF_V_MORRIS>(ifrom, ito, rates);
      break;
    default:
      eval_terms<KERNEL, PRESSURE, SPHF_V_ADAMI>(ifrom, ito, rates);
  }
}

template <int KERNEL, int PRESSURE, int VISCOSITY>
void PairSPHHarmonicVisc::eval_terms(int ifrom, int ito, const Rates &rates)
{
  int terms = (delta > 0.0) ? DIFFUSION : 0;
  if (heat && heat->term_in_flow_loop())
    terms |= HEAT_ON | (heat_term.conductivity ? HEAT_ATOM_K : 0) |
        (heat_term.relax_rate ? HEAT_RELAX : 0);
  switch (terms) {
    case 0:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, 0>(ifrom, ito, rates);
      break;
    case HEAT_ON:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, HEAT_ON>(ifrom, ito, rates);
      break;
    case HEAT_ON | HEAT_ATOM_K:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, HEAT_ON | HEAT_ATOM_K>(ifrom, ito, rates);
      break;
    case HEAT_ON | HEAT_RELAX:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, HEAT_ON | HEAT_RELAX>(ifrom, ito, rates);
      break;
    case HEAT_ON | HEAT_ATOM_K | HEAT_RELAX:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, HEAT_ON | HEAT_ATOM_K | HEAT_RELAX>(ifrom, ito,
                                                                                      rates);
      break;
    case DIFFUSION:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, DIFFUSION>(ifrom, ito, rates);
      break;
    case DIFFUSION | HEAT_ON:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, DIFFUSION | HEAT_ON>(ifrom, ito, rates);
      break;
    case DIFFUSION | HEAT_ON | HEAT_ATOM_K:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, DIFFUSION | HEAT_ON | HEAT_ATOM_K>(ifrom, ito,
                                                                                     rates);
      break;
    case DIFFUSION | HEAT_ON | HEAT_RELAX:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, DIFFUSION | HEAT_ON | HEAT_RELAX>(ifrom, ito,
                                                                                    rates);
      break;
    default:
      eval_dimension<KERNEL, PRESSURE, VISCOSITY, DIFFUSION | HEAT_ON | HEAT_ATOM_K | HEAT_RELAX>(
          ifrom, ito, rates);
  }
}

template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS>
void PairSPHHarmonicVisc::eval_dimension(int ifrom, int ito, const Rates &rates)
{
  // the shift sums only with the default pressure form (else SHIFT is 0 and
  // both branches are the same instantiation)
  constexpr int SHIFT = (PRESSURE == SPHF_P_AVERAGED) ? SHIFT_SUMS : 0;
  // likewise the corrected gradient (which fix sph/shift never asks to sum with)
  constexpr int CORRECTED = (PRESSURE == SPHF_P_AVERAGED) ? GRADIENT : 0;
  // 2-D: the z components are zero, and so are their terms
  if (CORRECTED && gradient_correction) {
    if (domain->dimension == 2)
      eval<KERNEL, PRESSURE, VISCOSITY, TERMS | CORRECTED, 2>(ifrom, ito, rates);
    else
      eval<KERNEL, PRESSURE, VISCOSITY, TERMS | CORRECTED, 3>(ifrom, ito, rates);
  } else if (SHIFT && shift_sums_wanted) {
    if (domain->dimension == 2)
      eval<KERNEL, PRESSURE, VISCOSITY, TERMS | SHIFT, 2>(ifrom, ito, rates);
    else
      eval<KERNEL, PRESSURE, VISCOSITY, TERMS | SHIFT, 3>(ifrom, ito, rates);
  } else if (domain->dimension == 2)
    eval<KERNEL, PRESSURE, VISCOSITY, TERMS, 2>(ifrom, ito, rates);
  else
    eval<KERNEL, PRESSURE, VISCOSITY, TERMS, 3>(ifrom, ito, rates);
}

/* ----------------------------------------------------------------------
   pressure, viscosity and mass of every owned and ghost atom (ghosts carry
   rho, esph, cv: no communication is needed)
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::update_atom_state()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(pressure);
    memory->destroy(viscosity);
    memory->destroy(mass_of);
    memory->destroy(volume);
    memory->destroy(density);
    memory->destroy(diffused_density);
    memory->create(volume, nmax, "pair:volume");
    if (thermal_expansion) memory->create(diffused_density, nmax, "pair:diffused_density");
    memory->create(pressure, nmax, "pair:pressure");
    memory->create(viscosity, nmax, "pair:viscosity");
    memory->create(mass_of, nmax, "pair:mass_of");
    memory->create(density, nmax, "pair:density");
  }
  const double *const rho = atom->rho;
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nall = atom->nlocal + atom->nghost;
  diffusion_rho = thermal_expansion ? diffused_density : rho;
  if (atom->rmass_flag && atom->rmass)
    memcpy(mass_of, atom->rmass, nall * sizeof(double));
  else
    for (int i = 0; i < nall; i++) mass_of[i] = atom->mass[type[i]];
  // the walls that hold solid particles (known after the walls' init)
  std::vector<FixSPHWallAdami *> solid_walls;
  for (auto wall : adami_walls)
    if (wall->has_solids()) solid_walls.push_back(wall);
  for (int i = 0; i < nall; i++) {
    FixSPHWallAdami *solid = nullptr;
    for (auto wall : solid_walls)
      if ((mask[i] & wall->groupbit) && wall->solid(i)) solid = wall;
    if (solid) {
      // its own volume, filled with the fluid as the wall extrapolates it and
      // compressed with it (so that wall and fluid particles keep their share)
      volume[i] = mass_of[i] / rho[i] * solid->compression(i);
      pressure[i] = solid->pressure(i);
      density[i] = solid->fluid_density(i);
      viscosity[i] = solid->viscosity(i);
      mass_of[i] = density[i] * volume[i];
      if (thermal_expansion) diffused_density[i] = rho[i];
      continue;
    }
    const sphe_eos *eos = materials->eos(type[i]);
    if (eos->thermal) {
      const double t = esph[i] / cv[i];
      const double rho_ref = sphe_reference_density(eos, t);
      if (!(rho_ref > 0.0) || !std::isfinite(rho_ref))
        SPHCheck::stop(lmp, FLERR, fmt::format(
                "Pair style sph/harmonic/visc: atom {} (type {}) at T = {} has no reference "
                "density: 1 + beta (T - T0) = {} of its equation of state's thermal "
                "expansion must be > 0",
                atom->tag[i], type[i], t, 1.0 + eos->beta * (t - eos->t0)));
      pressure[i] = sphe_pressure_ref(eos, rho[i], rho_ref);
      diffused_density[i] = rho[i] - (rho_ref - eos->rho0);
    } else {
      pressure[i] = sphe_pressure(eos, rho[i]);
      if (thermal_expansion) diffused_density[i] = rho[i];
    }
    viscosity[i] = materials->viscosity_at(type[i], viscosity_varies ? esph[i] / cv[i] : 0.0,
                                           "Pair style sph/harmonic/visc");
    density[i] = rho[i];
    volume[i] = mass_of[i] / rho[i];
  }
  pvector[0] = mean_pressure_held ? hold_mean_pressure() : 0.0;
}

/* ----------------------------------------------------------------------
   'mean_pressure P': every particle's pressure, owned or ghost, wall or
   fluid, less one offset such that the volume-weighted mean over the
   fluid (the atoms of no wall group) is P. The pair terms then do not see
   how the kernel sum of a changing particle arrangement moves the mean
   pressure of a closed container, and a constant offset of all pressures
   changes no pair force (the walls extrapolate the fluid's pressure, so
   their pressure moves with it). Returns the offset.
------------------------------------------------------------------------- */

double PairSPHHarmonicVisc::hold_mean_pressure()
{
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double mine[2] = {0.0, 0.0}, sum[2];
  for (int i = 0; i < nlocal; i++)
    if (!(mask[i] & wall_groupbit)) {
      mine[0] += pressure[i] * volume[i];
      mine[1] += volume[i];
    }
  MPI_Allreduce(mine, sum, 2, MPI_DOUBLE, MPI_SUM, world);
  // no fluid: nothing to hold
  if (!(sum[1] > 0.0)) return 0.0;
  // a non-finite mean makes every force non-finite, which the pair's
  // check of the forces reports with the atom
  const double offset = sum[0] / sum[1] - mean_pressure;
  for (int i = 0; i < nall; i++) pressure[i] -= offset;
  return offset;
}

/* ----------------------------------------------------------------------
   f_i += F_ij, f_j -= F_ij and drho of both for every pair in the kernel
   support; the viscosity sees vest (the velocity fix sph extrapolates to
   the end of the step, and the no-slip velocity of wall particles), the
   continuity equation v
------------------------------------------------------------------------- */

template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS, int DIM>
void PairSPHHarmonicVisc::eval(int ifrom, int ito, const Rates &rates)
{
  const int newton_pair = force->newton_pair;
  const double *const *const x = atom->x;
  const double *const *const v = atom->v;
  const double *const *const vest = atom->vest;
  double *const *const f = rates.f;
  double *const drho = rates.drho;
  double *const desph = rates.desph;
  double *const relax_rate = rates.relax_rate;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int wall_groupbit = this->wall_groupbit;
  // local copies: a store to f could alias a member, which would then be
  // read again for every pair
  const double *const mass_of = this->mass_of;
  const double *const density = this->density;
  const double *const volume = this->volume;
  const double *const pressure = this->pressure;
  const double *const viscosity = this->viscosity;
  const double xi = this->xi;
  const double eta2 = this->eta2;
  // the density the diffusion evens out (with thermal expansion, less the
  // thermal part of each particle's reference density)
  const double *const atom_rho = diffusion_rho;
  const sphe_eos *const *const eos_of = this->eos_of.data();
  const double delta_h_half = 0.5 * delta * kernel.h;
  const int hydrostatic = this->hydrostatic;
  const double gravity[3] = {this->gravity[0], this->gravity[1], this->gravity[2]};
  const PairSPHClearyHeat::FlowLoopTerm term = heat_term;
  double *const shift_sum = this->shift_sum;
  const double *const *const gradient_inverse = this->gradient_inverse;

  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;    // dW/dr / r = this f'(q) / q

  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;

  // the entries of each list inside the support (sph_support.h)
  SPHSupport support;

  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const sphf_particle a = {mass_of[i], density[i], volume[i], pressure[i], viscosity[i]};
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    const int nin = support.gather<DIM, true>(x[i], x, jlist, jnum, cutsq_kernel);
    const int *const jin = support.index;
    const double *const del_in = support.del;
    const double *const rsq_in = support.rsq;
    double *const dwdr_r_in = support.a;
    // dW/dr / r needs r only for q
    for (int k = 0; k < nin; k++)
      dwdr_r_in[k] = dwdr_r_scale * sphk_df_over_q(KERNEL, sqrt(rsq_in[k]) * inv_h);

    double fx_i = 0.0, fy_i = 0.0, fz_i = 0.0, drho_i = 0.0, desph_i = 0.0, relax_i = 0.0;
    double shift_i[3] = {0.0, 0.0, 0.0};
    // the heat term's state of i (sph/cleary/heat's eval())
    const double temp_i = (TERMS & HEAT_ON) ? term.temperature[i] : 0.0;
    const double hmass_i = (TERMS & HEAT_ON) ? term.mass[i] : 0.0;
    const double rho_i = (TERMS & HEAT_ON) ? term.rho[i] : 0.0;
    const double k_i = (TERMS & HEAT_ATOM_K) ? term.conductivity[i] : 0.0;
    const double *const conductance_i = (TERMS & HEAT_ATOM_K) ? nullptr : term.conductance[type[i]];
    const int wall_i = mask[i] & wall_groupbit;
    const sphe_eos *const eos_i = (TERMS & DIFFUSION) ? eos_of[type[i]] : nullptr;

    // the heat term of sph/cleary/heat's eval() for the pair, given 1 over
    // its denominator: F_ij per unit temperature difference, then F_ij
    auto add_heat = [&](int j, double r_dwdr, double inv_heat) {
      const double conductance_ij = (TERMS & HEAT_ATOM_K)
          ? sphc_harmonic_conductance(k_i, term.conductivity[j])
          : conductance_i[type[j]];
      const double relax_ij = sphc_cleary_pair_inv(conductance_ij, 1.0, r_dwdr, inv_heat);
      const double heat_ij = relax_ij * (temp_i - term.temperature[j]);
      desph_i += term.mass[j] * heat_ij;
      if (TERMS & HEAT_RELAX) relax_i -= term.mass[j] * relax_ij;
      if (newton_pair || j < nlocal) {
        desph[j] -= hmass_i * heat_ij;
        if (TERMS & HEAT_RELAX) relax_rate[j] -= hmass_i * relax_ij;
      }
    };

    for (int k = 0; k < nin; k++) {
      const int j = jin[k];
      const double delx = del_in[3 * k], dely = del_in[3 * k + 1], delz = del_in[3 * k + 2];
      const double rsq = rsq_in[k];
      const double dwdr_r = dwdr_r_in[k];
      // between two wall particles the flow changes nothing: fix sph/wall/adami
      // sets their density and velocity every step and they are not
      // integrated with fix sph; heat still flows
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) {
        if (TERMS & HEAT_ON)
          add_heat(j, rsq * dwdr_r,
                   1.0 / sphc_cleary_denominator(rho_i, term.rho[j], rsq, term.eta2));
        continue;
      }
      const sphf_particle b = {mass_of[j], density[j], volume[j], pressure[j], viscosity[j]};
      const double dvx = vest[i][0] - vest[j][0];
      const double dvy = vest[i][1] - vest[j][1];
      const double dvz = (DIM == 3) ? vest[i][2] - vest[j][2] : 0.0;
      const double vr_est = (VISCOSITY == SPHF_V_CLEARY) ? dvx * delx + dvy * dely + dvz * delz : 0.0;
      double s_r, s_rv, s_v, c_i, c_j, inv_heat;
      // the heat term's denominator shares the flow's one division
      const double heat_den =
          (TERMS & HEAT_ON) ? sphc_cleary_denominator(rho_i, term.rho[j], rsq, term.eta2) : 1.0;
      sphf_pair(PRESSURE, VISCOSITY, xi, &a, &b, rsq, dwdr_r, eta2, vr_est, heat_den, &s_r, &s_rv,
                &s_v, &c_i, &c_j, &inv_heat);
      double fx, fy, fz;
      if (TERMS & GRADIENT) {
        // the pressure force along B grad W: the mean of the two particles'
        // B for a fluid pair, the fluid particle's with a wall (one matrix
        // per pair: the force stays antisymmetric and momentum is kept)
        const double del[3] = {delx, dely, delz};
        double b_del[3];
        if (wall_i || wall_j)
          sphc_sym_apply(gradient_inverse[wall_i ? j : i], del, b_del);
        else {
          double b_del_j[3];
          sphc_sym_apply(gradient_inverse[i], del, b_del);
          sphc_sym_apply(gradient_inverse[j], del, b_del_j);
          for (int k = 0; k < 3; k++) b_del[k] = 0.5 * (b_del[k] + b_del_j[k]);
        }
        const double s_p = s_r - s_rv;    // the pressure's share of s_r
        fx = s_p * b_del[0] + s_rv * delx + s_v * dvx;
        fy = s_p * b_del[1] + s_rv * dely + s_v * dvy;
        fz = s_p * b_del[2] + s_rv * delz + s_v * dvz;
      } else {
        fx = s_r * delx + s_v * dvx;
        fy = s_r * dely + s_v * dvy;
        fz = s_r * delz + s_v * dvz;
      }
      // fix sph/shift's sums: grad_i W_ij = dW/dr / r (r_i - r_j)
      const double shift_ij = (TERMS & SHIFT_SUMS) ? dwdr_r * b.vol : 0.0;
      const double shift_ji = (TERMS & SHIFT_SUMS) ? dwdr_r * a.vol : 0.0;
      if (TERMS & SHIFT_SUMS) {
        shift_i[0] += shift_ij * delx;
        shift_i[1] += shift_ij * dely;
        if (DIM == 3) shift_i[2] += shift_ij * delz;
      }
      const double vr = (v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely +
          ((DIM == 3) ? (v[i][2] - v[j][2]) * delz : 0.0);
      fx_i += fx;
      fy_i += fy;
      fz_i += fz;
      drho_i += c_i * vr;
      if (TERMS & HEAT_ON) add_heat(j, rsq * dwdr_r, inv_heat);
      // density diffusion (Ng et al. 2020, eqs 5-6; Fourtakas's with
      // hydrostatic), not across walls (the papers set rho_b = rho_a there)
      double diffusion_j = 0.0;
      if ((TERMS & DIFFUSION) && !wall_i && !wall_j) {
        const sphe_eos *const eos_j = eos_of[type[j]];
        // one coefficient per pair: the mean speed of sound of the two
        const double delta_h_c0 = delta_h_half * (eos_i->c0 + eos_j->c0);
        double drho_ji = atom_rho[j] - atom_rho[i], drho_ij = -drho_ji;
        if (hydrostatic) {
          const double g_r = gravity[0] * delx + gravity[1] * dely + gravity[2] * delz;
          drho_ji -= sphe_density(eos_i, eos_i->p_background - eos_i->rho0 * g_r) - eos_i->rho0;
          drho_ij -= sphe_density(eos_j, eos_j->p_background + eos_j->rho0 * g_r) - eos_j->rho0;
        }
        // neither is a wall: their volumes are m / rho
        drho_i += sphf_diffusion_pair(delta_h_c0, b.vol, dwdr_r) * drho_ji;
        diffusion_j = sphf_diffusion_pair(delta_h_c0, a.vol, dwdr_r) * drho_ij;
      }
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        if (DIM == 3) f[j][2] -= fz;
        drho[j] += c_j * vr + diffusion_j;
        if (TERMS & SHIFT_SUMS) {
          shift_sum[3 * j] -= shift_ji * delx;
          shift_sum[3 * j + 1] -= shift_ji * dely;
          if (DIM == 3) shift_sum[3 * j + 2] -= shift_ji * delz;
        }
      }
      if (evflag) tally_pair(i, j, fx, fy, fz, delx, dely, delz, rates.thread);
    }
    f[i][0] += fx_i;
    f[i][1] += fy_i;
    if (DIM == 3) f[i][2] += fz_i;
    drho[i] += drho_i;
    if (TERMS & HEAT_ON) desph[i] += desph_i;
    if (TERMS & HEAT_RELAX) relax_rate[i] += relax_i;
    if (TERMS & SHIFT_SUMS)
      for (int a = 0; a < DIM; a++) shift_sum[3 * i + a] += shift_i[a];
  }
}

/* ----------------------------------------------------------------------
   viscous heating (sph_flow.h, sphf_viscous_power): the kinetic energy the
   viscous force of each pair removes, times 'heating', as heat. A fluid
   pair shares it equally; with a wall particle the fluid particle takes it
   all, and the energy is counted with the wall's own velocity v (its vest
   is the no-slip mirror velocity, not a motion), so the work done on a
   moving wall or body is not heat. The same force as the main loop's, to
   round-off.
------------------------------------------------------------------------- */

template <int KERNEL>
void PairSPHHarmonicVisc::eval_heating_kernel(int ifrom, int ito, const Rates &rates)
{
  const int dim3 = domain->dimension == 3;
  switch (viscosity_form) {
    case SPHF_V_CLEARY:
      if (dim3)
        eval_heating<KERNEL, SPHF_V_CLEARY, 3>(ifrom, ito, rates);
      else
        eval_heating<KERNEL, SPHF_V_CLEARY, 2>(ifrom, ito, rates);
      break;
    case SPHF_V_MORRIS:
      if (dim3)
        eval_heating<KERNEL, SPHF_V_MORRIS, 3>(ifrom, ito, rates);
      else
        eval_heating<KERNEL, SPHF_V_MORRIS, 2>(ifrom, ito, rates);
      break;
    default:
      if (dim3)
        eval_heating<KERNEL, SPHF_V_ADAMI, 3>(ifrom, ito, rates);
      else
        eval_heating<KERNEL, SPHF_V_ADAMI, 2>(ifrom, ito, rates);
  }
}

template <int KERNEL, int VISCOSITY, int DIM>
void PairSPHHarmonicVisc::eval_heating(int ifrom, int ito, const Rates &rates)
{
  const int newton_pair = force->newton_pair;
  const double *const *const x = atom->x;
  const double *const *const v = atom->v;
  const double *const *const vest = atom->vest;
  double *const desph = rates.desph;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int wall_groupbit = this->wall_groupbit;
  const double *const mass_of = this->mass_of;
  const double *const density = this->density;
  const double *const volume = this->volume;
  const double *const viscosity = this->viscosity;
  const double xi = this->xi, eta2 = this->eta2, heating = this->heating;
  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;

  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const int wall_i = mask[i] & wall_groupbit;
    // the flow's particle state (pressure plays no part)
    const sphf_particle a = {mass_of[i], density[i], volume[i], 0.0, viscosity[i]};
    const double *const u_i = wall_i ? v[i] : vest[i];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double desph_i = 0.0;
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1],
                             (DIM == 3) ? x[i][2] - x[j][2] : 0.0};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq_kernel) continue;
      const double dwdr_r = dwdr_r_scale * sphk_df_over_q(KERNEL, sqrt(rsq) * inv_h);
      const sphf_particle b = {mass_of[j], density[j], volume[j], 0.0, viscosity[j]};
      const double *const u_j = wall_j ? v[j] : vest[j];
      const double dv[3] = {vest[i][0] - vest[j][0], vest[i][1] - vest[j][1],
                            (DIM == 3) ? vest[i][2] - vest[j][2] : 0.0};
      const double du[3] = {u_i[0] - u_j[0], u_i[1] - u_j[1], (DIM == 3) ? u_i[2] - u_j[2] : 0.0};
      const double vr =
          (VISCOSITY == SPHF_V_CLEARY) ? dv[0] * del[0] + dv[1] * del[1] + dv[2] * del[2] : 0.0;
      double s_r, s_rv, s_v, c_i, c_j, inv_other;
      sphf_pair(SPHF_P_SUM, VISCOSITY, xi, &a, &b, rsq, dwdr_r, eta2, vr, 1.0, &s_r, &s_rv, &s_v,
                &c_i, &c_j, &inv_other);
      const double heat = heating * sphf_viscous_power(s_rv, s_v, del, dv, du);
      // a fluid pair halves it; with a wall the fluid particle takes it all
      const double share_i = wall_i ? 0.0 : (wall_j ? 1.0 : 0.5);
      desph_i += share_i * heat;
      if (!wall_j && (newton_pair || j < nlocal))
        desph[j] += (wall_i ? 1.0 : 0.5) * heat / mass_of[j];
    }
    if (!wall_i) desph[i] += desph_i / mass_of[i];
  }
}

/* ----------------------------------------------------------------------
   pair_style sph/harmonic/visc kernel cutoff [pressure symmetric|sum|averaged]
     [viscosity cleary|adami|morris] [xi value] [eta f] [delta value]
     [diffusion fourtakas|molteni] [fourtakas gx gy gz] [heating fraction]
     [mean_pressure P|none] [correction none|gradient]
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::settings(int narg, char **arg)
{
  int iarg = parse_kernel(narg, arg);
  pressure_form = SPHF_P_AVERAGED;
  viscosity_form = SPHF_V_ADAMI;
  xi = SPHF_XI_CLEARY;
  xi_given = 0;
  eta_factor = -1.0;    // the default depends on the viscosity form
  delta = 0.1;    // Ng et al. 2020: "not a tunable parameter", 0.1 for all flows
  heating = 0.0;    // Reece et al. 2024 and Ng et al. 2020 neglect it
  mean_pressure_held = 0;
  mean_pressure = 0.0;
  gradient_correction = 0;
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
      pressure_form = sphf_pressure_lookup(value);
      if (pressure_form < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown pressure form '{}' (symmetric, sum or averaged)",
                   cmd, value);
    } else if (strcmp(arg[iarg], "viscosity") == 0) {
      viscosity_form = sphf_viscosity_lookup(value);
      if (viscosity_form < 0)
        error->all(FLERR,
                   "Illegal {} command: unknown viscosity form '{}' (cleary, adami or morris)",
                   cmd, value);
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
    } else if (strcmp(arg[iarg], "mean_pressure") == 0) {
      mean_pressure_held = (strcmp(value, "none") != 0);
      mean_pressure = mean_pressure_held ? utils::numeric(FLERR, value, false, lmp) : 0.0;
    } else if (strcmp(arg[iarg], "correction") == 0) {
      if (strcmp(value, "gradient") == 0)
        gradient_correction = 1;
      else if (strcmp(value, "none") == 0)
        gradient_correction = 0;
      else
        error->all(FLERR, "Illegal {} command: unknown correction '{}' (none or gradient)", cmd,
                   value);
    } else if (strcmp(arg[iarg], "delta") == 0) {
      delta = utils::numeric(FLERR, value, false, lmp);
      if (delta < 0.0) error->all(FLERR, "Illegal {} command: delta {} must be >= 0", cmd, value);
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
    iarg += 2;
  }
  if (xi_given && viscosity_form != SPHF_V_CLEARY)
    error->all(FLERR,
               "Illegal {} command: xi is a factor of the cleary viscosity form only; viscosity {} "
               "does not use it",
               cmd, sphf_viscosity_name(viscosity_form));
  if (gradient_correction && pressure_form != SPHF_P_AVERAGED)
    error->all(FLERR,
               "Illegal {} command: correction gradient needs the averaged pressure form (the "
               "default), not pressure {}",
               cmd, sphf_pressure_name(pressure_form));
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
    error->all(FLERR, "Pair style sph/harmonic/visc requires ghost velocities: remove comm_modify vel no");

  materials = FixSPHMaterials::find(lmp, "Pair style sph/harmonic/visc");
  // the walls first: a wall type without an equation of state is a solid
  wall_groupbit = 0;
  adami_walls.clear();
  for (Fix *wall : SPHCompat::fixes_of_style(modify, "sph/wall/adami")) {
    wall_groupbit |= wall->groupbit;
    adami_walls.push_back((FixSPHWallAdami *) wall);
  }
  // a body moved by a fix rigid is a moving wall: its particles must be in
  // a fix sph/wall/adami group, or the flow would treat them as fluid
  for (int ifix = 0; ifix < modify->nfix; ifix++) {
    Fix *rigid = modify->fix[ifix];
    if (!utils::strmatch(rigid->style, "^rigid")) continue;
    tagint first = MAXTAGINT, first_all;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & rigid->groupbit) && !(atom->mask[i] & wall_groupbit))
        first = MIN(first, atom->tag[i]);
    MPI_Allreduce(&first, &first_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (first_all != MAXTAGINT)
      error->all(FLERR,
                 "Pair style sph/harmonic/visc: atom {} of fix {} ({}) is in no fix sph/wall/adami "
                 "group: the particles of a rigid body must be walls of fix sph/wall/adami, which "
                 "moves them with the body",
                 first_all, rigid->id, rigid->style);
  }
  // every particle that is not such a wall needs its fluid's properties
  tagint bad_tag = MAXTAGINT;
  int bad_type = 0, bad_missing = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->mask[i] & wall_groupbit) continue;
    const int t = atom->type[i];
    const int missing = !materials->eos(t) ? 1 : (!materials->viscosity(t) ? 2 : 0);
    if (missing && atom->tag[i] < bad_tag) bad_tag = atom->tag[i], bad_type = t, bad_missing = missing;
  }
  tagint bad_all;
  MPI_Allreduce(&bad_tag, &bad_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (bad_all != MAXTAGINT) {
    int info[2] = {bad_tag == bad_all ? bad_type : 0, bad_tag == bad_all ? bad_missing : 0};
    int info_all[2];
    MPI_Allreduce(info, info_all, 2, MPI_INT, MPI_MAX, world);
    error->all(FLERR,
               "Pair style sph/harmonic/visc: atom type {} has no {} in fix sph/materials (atom {} "
               "is a fluid particle; only the solid particles of fix sph/wall/adami may lack it)",
               info_all[0], info_all[1] == 1 ? "equation of state (eos)" : "viscosity", bad_all);
  }
  viscosity_varies = !materials->viscosity_constant();
  // the per-atom arrays are sized again with the diffused density
  if (materials->thermal_expansion() != thermal_expansion) {
    thermal_expansion = materials->thermal_expansion();
    nmax = 0;
  }
  SPHCheck::atom_state(lmp, FLERR, "Pair style sph/harmonic/visc", 0,
      SPHCheck::RHO |
          ((viscosity_varies || thermal_expansion) ? SPHCheck::CV | SPHCheck::ESPH : 0));

  // the hydrostatic diffusion reads the body force of the run, or assumes one
  body_force = SPHBodyForce::find(lmp, "Pair style sph/harmonic/visc");
  if (diffusion_form == DIFFUSION_MOLTENI) {
    hydrostatic = 0;
  } else if (diffusion_form == DIFFUSION_BODY_FORCE) {
    for (int k = 0; k < 3; k++) gravity[k] = body_force ? body_force[k] : 0.0;
    hydrostatic = (gravity[0] != 0.0 || gravity[1] != 0.0 || gravity[2] != 0.0);
  } else {
    int other_force = 0;
    for (int ifix = 0; ifix < modify->nfix; ifix++)
      if (utils::strmatch(modify->fix[ifix]->style, "^addforce")) other_force = 1;
    if (!body_force && !other_force)
      error->warning(FLERR,
                     "Pair style sph/harmonic/visc: fourtakas {} {} {} assumes gravity, but no fix "
                     "gravity or addforce is defined",
                     gravity[0], gravity[1], gravity[2]);
    else if (body_force && (body_force[0] != gravity[0] || body_force[1] != gravity[1] ||
                            body_force[2] != gravity[2]))
      error->warning(FLERR,
                     "Pair style sph/harmonic/visc: fourtakas {} {} {} differs from the body "
                     "force of fix gravity ({} {} {}); 'diffusion fourtakas' (the default) reads it",
                     gravity[0], gravity[1], gravity[2], body_force[0], body_force[1],
                     body_force[2]);
  }


  eta2 = init_kernel();
  eos_of.assign(atom->ntypes + 1, nullptr);
  for (int t = 1; t <= atom->ntypes; t++) eos_of[t] = materials->eos(t);
  // sph/cleary/heat decides at its init whether this loop evaluates its term
  heat = (PairSPHClearyHeat *) force->pair_match("^sph/cleary/heat", 0);
  // fix sph/shift asks again at its init
  shift_sums_wanted = 0;

  SPHCompat::request_half_list(neighbor, this, instance_me);
}

double PairSPHHarmonicVisc::init_one(int, int)
{
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::write_restart_settings(FILE *fp)
{
  const int ints[6] = {kernel_kind,    pressure_form,      viscosity_form,
                       diffusion_form, mean_pressure_held, gradient_correction};
  // xi_given only checks the command line
  const double doubles[9] = {cut_global, xi,         eta_factor, delta,        gravity[0],
                             gravity[1], gravity[2], heating,    mean_pressure};
  SPHCheck::write_restart_head(fp, RESTART_VERSION);
  fwrite(ints, sizeof(int), 6, fp);
  fwrite(doubles, sizeof(double), 9, fp);
}

void PairSPHHarmonicVisc::read_restart_settings(FILE *fp)
{
  SPHCheck::read_restart_head(lmp, fp, "pair sph/harmonic/visc", RESTART_VERSION);
  int ints[6];
  double doubles[9];
  if (comm->me == 0) {
    utils::sfread(FLERR, ints, sizeof(int), 6, fp, nullptr, error);
    utils::sfread(FLERR, doubles, sizeof(double), 9, fp, nullptr, error);
  }
  MPI_Bcast(ints, 6, MPI_INT, 0, world);
  MPI_Bcast(doubles, 9, MPI_DOUBLE, 0, world);
  // the body force is read again from fix gravity at init
  diffusion_form = ints[3];
  hydrostatic = (diffusion_form == DIFFUSION_GIVEN);
  for (int k = 0; k < 3; k++) gravity[k] = doubles[4 + k];
  kernel_kind = ints[0];
  pressure_form = ints[1];
  viscosity_form = ints[2];
  cut_global = doubles[0];
  xi = doubles[1];
  eta_factor = doubles[2];
  delta = doubles[3];
  heating = doubles[7];
  mean_pressure_held = ints[4];
  mean_pressure = doubles[8];
  gradient_correction = ints[5];
}

/* ---------------------------------------------------------------------- */

double PairSPHHarmonicVisc::memory_usage()
{
  return Pair::memory_usage() +
      (5.0 * nmax + 3.0 * nmax_shift + 6.0 * nmax_gradient) * sizeof(double);
}

/* ----------------------------------------------------------------------
   settings for styles that evaluate the same kernel (fix sph/wall/adami,
   the timestep fix)
------------------------------------------------------------------------- */

void *PairSPHHarmonicVisc::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "xi") == 0) return (void *) &xi;
  return PairSPHKernel::extract(name, dim);
}

/* ----------------------------------------------------------------------
   vest of the ghost atoms, at setup
------------------------------------------------------------------------- */

int PairSPHHarmonicVisc::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                           int * /*pbc*/)
{
  int m = 0;
  if (comm_stage == COMM_GRADIENT_INVERSE) {
    for (int k = 0; k < n; k++)
      for (int a = 0; a < 6; a++) buf[m++] = gradient_inverse[send[k]][a];
    return m;
  }
  for (int k = 0; k < n; k++)
    for (int d = 0; d < 3; d++) buf[m++] = atom->vest[send[k]][d];
  return m;
}

void PairSPHHarmonicVisc::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  if (comm_stage == COMM_GRADIENT_INVERSE) {
    for (int i = first; i < first + n; i++)
      for (int a = 0; a < 6; a++) gradient_inverse[i][a] = buf[m++];
    return;
  }
  for (int i = first; i < first + n; i++)
    for (int d = 0; d < 3; d++) atom->vest[i][d] = buf[m++];
}
