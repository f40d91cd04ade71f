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
#include "sph_dispatch.h"
#include "sph_flow.h"
#include "sph_hub.h"
#include "sph_support.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHHarmonicVisc::PairSPHHarmonicVisc(LAMMPS *lmp) :
    PairSPHKernel(lmp, "sph/harmonic/visc",
                  "viscosities and equations of state come from fix sph/materials"),
    pressure_form(SPHF_P_AVERAGED), viscosity_form(SPHF_V_ADAMI), xi(SPHF_XI_CLEARY), delta(0.1),
    heating(0.0), artificial(0.0), artificial_request(-1.0), artificial_logged(-1),
    pressure_request(-1), pressure_logged(-1), delta_request(-1.0), delta_logged(-1),
    grain_forms_warned(0), mean_pressure_held(0), mean_pressure(0.0), gradient_correction(0),
    gradient_request(-1), gradient_logged(-1), gradient_inverse(nullptr), nmax_gradient(0),
    diffusion_form(DIFFUSION_BODY_FORCE), hydrostatic(0), body_force(nullptr), buoyancy(nullptr),
    pressure_buoyancy(nullptr), eta2(0.0), materials(nullptr), viscosity_varies(0),
    wall_groupbit(0), pressure(nullptr), viscosity(nullptr), mass_of(nullptr), volume(nullptr),
    density(nullptr), diffused_density(nullptr), diffusion_rho(nullptr),
    velocity_seen_store(nullptr), velocity_seen(nullptr), thermal_expansion(0), nmax(0),
    heat(nullptr), shift_sums_wanted(0), shift_sum(nullptr), nmax_shift(0), background_warned(0),
    soft_fluid_warned(0), shepard(nullptr), nmax_shepard(0), artificial_here(0)
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
  memory->destroy(shepard);
  memory->destroy(viscosity);
  memory->destroy(mass_of);
  memory->destroy(volume);
  memory->destroy(density);
  memory->destroy(diffused_density);
  memory->destroy(velocity_seen_store);
  memory->destroy(shift_sum);
  memory->destroy(gradient_inverse);
  delete[] pvector;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  begin_compute();
  const Rates rates = {atom->f,
                       atom->drho,
                       atom->desph,
                       heat_term.relax_rate,
                       shift_sums_wanted ? shift_sum : nullptr,
                       nullptr};
  eval_pairs(0, list->inum, rates);
  end_compute();
  if (vflag_fdotr) virial_fdotr_compute();
}

struct PairSPHHarmonicVisc::ShepardCall {
  PairSPHHarmonicVisc *pair;
  template <int KERNEL, int DIM> void run() { pair->update_shepard<KERNEL, DIM>(); }
};

/* ----------------------------------------------------------------------
   before the pair loops: the per-atom state they read
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::begin_compute()
{
  SPHCheck::particles(lmp, FLERR, "Pair style sph/harmonic/visc", SPHCheck::RHO | SPHCheck::ESPH);
  // fix sph sets vest = v on owned atoms at setup without updating their
  // ghosts: refresh them, or results depend on newton and the rank count
  if (update->setupflag) forward(SPHCommStage().rows(atom->vest, 3));
  // fix gravity may vary its acceleration in time
  if (diffusion_form == DIFFUSION_BODY_FORCE) read_body_force();
  update_atom_state();
  if (update->setupflag) check_neighbours();
  if (gradient_correction) refresh_gradient_correction();
  if (artificial > 0.0) {
    ShepardCall call = {this};
    const int settings[] = {kernel_kind, domain->dimension};
    SPHDispatch<SPHKernelKinds, SPHDimensions>::to(call, settings);
  }
  heat_term = PairSPHClearyHeat::FlowLoopTerm();
  if (heat && heat->term_in_flow_loop()) heat_term = heat->begin_flow_loop_term();
  if (shift_sums_wanted) {
    // room for one copy per thread (the /omp style)
    if (atom->nmax * comm->nthreads > nmax_shift) {
      nmax_shift = atom->nmax * comm->nthreads;
      memory->destroy(shift_sum);
      memory->create(shift_sum, 3 * nmax_shift, "pair:shift_sum");
    }
    memset(shift_sum, 0, 3 * sizeof(double) * (atom->nlocal + atom->nghost));
  }
}

/* ----------------------------------------------------------------------
   the pair loops over ilist[ifrom..ito), adding to 'rates'
------------------------------------------------------------------------- */

struct PairSPHHarmonicVisc::EvalCall {
  PairSPHHarmonicVisc *pair;
  int ifrom, ito;
  const Rates *rates;
  template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS> void run()
  {
    pair->eval_dimension<KERNEL, PRESSURE, VISCOSITY, TERMS>(ifrom, ito, *rates);
  }
};

struct PairSPHHarmonicVisc::ArtificialCall {
  PairSPHHarmonicVisc *pair;
  int ifrom, ito;
  const Rates *rates;
  template <int KERNEL, int DIM> void run()
  {
    pair->eval_artificial<KERNEL, DIM>(ifrom, ito, *rates);
  }
};

struct PairSPHHarmonicVisc::HeatingCall {
  PairSPHHarmonicVisc *pair;
  int ifrom, ito;
  const Rates *rates;
  template <int KERNEL> void run() { pair->eval_heating_kernel<KERNEL>(ifrom, ito, *rates); }
};

void PairSPHHarmonicVisc::eval_pairs(int ifrom, int ito, const Rates &rates)
{
  int terms = (delta > 0.0) ? DIFFUSION : 0;
  if (heat && heat->term_in_flow_loop())
    terms |= HEAT_ON | (heat_term.conductivity ? HEAT_ATOM_K : 0) |
        (heat_term.relax_rate ? HEAT_RELAX : 0);
  EvalCall call = {this, ifrom, ito, &rates};
  const int settings[] = {kernel_kind, pressure_form, viscosity_form, terms};
  SPHDispatch<SPHKernelKinds, SPHValues<SPHF_P_SYMMETRIC, SPHF_P_SUM, SPHF_P_AVERAGED>,
              SPHValues<SPHF_V_CLEARY, SPHF_V_MORRIS, SPHF_V_ADAMI>,
              SPHValues<0, HEAT_ON, HEAT_ON | HEAT_ATOM_K, HEAT_ON | HEAT_RELAX,
                        HEAT_ON | HEAT_ATOM_K | HEAT_RELAX, DIFFUSION, DIFFUSION | HEAT_ON,
                        DIFFUSION | HEAT_ON | HEAT_ATOM_K, DIFFUSION | HEAT_ON | HEAT_RELAX,
                        DIFFUSION | HEAT_ON | HEAT_ATOM_K | HEAT_RELAX>>::to(call, settings);
  // Monaghan's artificial viscosity: a pass of its own, only on a rank
  // with fluid particles at a free surface or wall particles
  if (artificial > 0.0 && artificial_here) {
    ArtificialCall artificial_call = {this, ifrom, ito, &rates};
    const int artificial_settings[] = {kernel_kind, domain->dimension};
    SPHDispatch<SPHKernelKinds, SPHDimensions>::to(artificial_call, artificial_settings);
  }
  // viscous heating: a pass of its own, only when asked for
  if (heating > 0.0) {
    HeatingCall heating_call = {this, ifrom, ito, &rates};
    SPHDispatch<SPHKernelKinds>::to(heating_call, &kernel_kind);
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
  if (shift_sums_wanted && force->newton_pair) reverse(SPHCommStage().flat(shift_sum, 3));
  if (!group_forces.empty()) make_group_forces();
}

void PairSPHHarmonicVisc::tally_pair(int i, int j, double fx, double fy, double fz, double delx,
                                     double dely, double delz, void * /*thread*/)
{
  ev_tally_xyz(i, j, atom->nlocal, force->newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
}

template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS>
void PairSPHHarmonicVisc::eval_dimension(int ifrom, int ito, const Rates &rates)
{
  // the shift sums only with the default pressure form (else SHIFT is 0 and
  // both branches are the same instantiation)
  constexpr int SHIFT = (PRESSURE == SPHF_P_AVERAGED) ? SHIFT_SUMS : 0;
  // likewise the corrected gradient
  constexpr int CORRECTED = (PRESSURE == SPHF_P_AVERAGED) ? GRADIENT : 0;
  const bool corrected = CORRECTED && gradient_correction;
  const bool shift = SHIFT && shift_sums_wanted;
  if (corrected && shift)
    eval_in_dimension<KERNEL, PRESSURE, VISCOSITY, TERMS | CORRECTED | SHIFT>(ifrom, ito, rates);
  else if (corrected)
    eval_in_dimension<KERNEL, PRESSURE, VISCOSITY, TERMS | CORRECTED>(ifrom, ito, rates);
  else if (shift)
    eval_in_dimension<KERNEL, PRESSURE, VISCOSITY, TERMS | SHIFT>(ifrom, ito, rates);
  else
    eval_in_dimension<KERNEL, PRESSURE, VISCOSITY, TERMS>(ifrom, ito, rates);
}

// 2-D: the z components are zero, and so are their terms
template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS>
void PairSPHHarmonicVisc::eval_in_dimension(int ifrom, int ito, const Rates &rates)
{
  if (domain->dimension == 2)
    eval<KERNEL, PRESSURE, VISCOSITY, TERMS, 2>(ifrom, ito, rates);
  else
    eval<KERNEL, PRESSURE, VISCOSITY, TERMS, 3>(ifrom, ito, rates);
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
  const double *const *const vest = velocity_seen;
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
  const double *const body_accel = this->body_accel.data();
  // the tait offsets' series, per type, of this step's EOS
  const int nseries = ((TERMS & DIFFUSION) && hydrostatic) ? atom->ntypes + 1 : 0;
  std::vector<sphe_tait_series> series_of(nseries);
  for (int t = 1; t < nseries; t++)
    if (eos_of[t] && eos_of[t]->kind == SPHE_TAIT) sphe_tait_series_of(eos_of[t], &series_of[t]);
  const PairSPHClearyHeat::FlowLoopTerm term = heat_term;
  double *const shift_sum = rates.shift_sum;
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
      // (the flow loop takes the term only with the harmonic mean, no interface)
      const double conductance_ij =
          sphc_pair_conductance(SPHC_HARMONIC, (TERMS & HEAT_ATOM_K) != 0, 0, k_i,
                                (TERMS & HEAT_ATOM_K) ? term.conductivity[j] : 0.0,
                                (TERMS & HEAT_ATOM_K) ? 0.0 : conductance_i[type[j]], 0.0, 0.0);
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
      const double vr_est = (VISCOSITY == SPHF_V_CLEARY) ? dvx * delx + dvy * dely + dvz * delz
                                                         : 0.0;
      double s_r, s_rv, s_v, c_i, c_j, inv_heat;
      // the heat term's denominator shares the flow's one division
      const double heat_den =
          (TERMS & HEAT_ON) ? sphc_cleary_denominator(rho_i, term.rho[j], rsq, term.eta2) : 1.0;
      sphf_pair(PRESSURE, VISCOSITY, xi, &a, &b, rsq, dwdr_r, eta2, vr_est, heat_den, &s_r, &s_rv,
                &s_v, &c_i, &c_j, &inv_heat);
      double fx, fy, fz;
      if (TERMS & GRADIENT) {
        const double del[3] = {delx, dely, delz};
        double b_del[3];
        corrected_direction(gradient_inverse, i, j, wall_i, wall_j, del, b_del);
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
      const sphe_eos *const eos_j = (TERMS & DIFFUSION) ? eos_of[type[j]] : nullptr;
      if ((TERMS & DIFFUSION) && !wall_i && !wall_j && eos_j->rho0 == eos_i->rho0) {
        // one coefficient per pair: the mean speed of sound of the two
        const double delta_h_c0 = delta_h_half * (eos_i->c0 + eos_j->c0);
        double drho_ji = atom_rho[j] - atom_rho[i], drho_ij = -drho_ji;
        if (hydrostatic) {
          // the pressure difference that balances the body force across the
          // pair: the mean of both accelerations (buoyancy varies with T)
          const double *const a_i = body_accel + 3 * i, *const a_j = body_accel + 3 * j;
          const double g_r = 0.5 *
              ((a_i[0] + a_j[0]) * delx + (a_i[1] + a_j[1]) * dely +
               ((DIM == 3) ? (a_i[2] + a_j[2]) * delz : 0.0));
          // i's at -dp and j's at +dp (one evaluation where i and j share the EOS)
          double up, down;
          sphe_hydrostatic_offsets(eos_i, &series_of[type[i]], eos_i->rho0 * g_r, &up, &down);
          drho_ji -= down;
          if (eos_j != eos_i)
            sphe_hydrostatic_offsets(eos_j, &series_of[type[j]], eos_j->rho0 * g_r, &up, &down);
          drho_ij -= up;
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

/* a pair's dissipated work as heat: a fluid pair halves it; with a wall
   particle the fluid particle takes it all. i's share is summed in
   desph_i (the caller divides it by i's mass), j's goes to desph_j where
   j is counted here. */
static inline void share_pair_heat(double heat, int wall_i, int wall_j, int j_counted,
                                   double mass_j, double &desph_i, double &desph_j)
{
  desph_i += (wall_i ? 0.0 : (wall_j ? 1.0 : 0.5)) * heat;
  if (!wall_j && j_counted) desph_j += (wall_i ? 1.0 : 0.5) * heat / mass_j;
}

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
  const double *const *const vest = velocity_seen;
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
      share_pair_heat(heating * sphf_viscous_power(s_rv, s_v, del, dv, du), wall_i, wall_j,
                      newton_pair || j < nlocal, mass_of[j], desph_i, desph[j]);
    }
    if (!wall_i) desph[i] += desph_i / mass_of[i];
  }
}

/* ----------------------------------------------------------------------
   Monaghan's artificial viscosity (sph_flow.h, sphf_artificial_pair) of
   the pair i, j where one of them is at a free surface (its Shepard sum
   below SPHF_SURFACE_SHEPARD) or a wall particle, 0 otherwise: s with
   force on i = s r_ij, vr = v_ij . r_ij with the fluid's vest and a wall
   particle's own velocity (its no-slip mirror velocity would make the term
   a friction twice as strong on a thin layer sliding along the wall: a dam
   break's front fell 12 % behind the experiment); c_ij the mean speed of
   sound of the two (a solid wall's, which has none, is the fluid's).
------------------------------------------------------------------------- */

double PairSPHHarmonicVisc::artificial_pair(int i, int j, double vr, double rsq,
                                            double dwdr_r) const
{
  // only where one of the two is at a free surface or a wall particle
  const int *const mask = atom->mask;
  if (!((mask[i] | mask[j]) & wall_groupbit) && !(shepard[i] < SPHF_SURFACE_SHEPARD) &&
      !(shepard[j] < SPHF_SURFACE_SHEPARD))
    return 0.0;
  const int *const type = atom->type;
  const sphe_eos *const eos_i = eos_of[type[i]], *const eos_j = eos_of[type[j]];
  if (!eos_i && !eos_j) return 0.0;    // two solids: no flow between them
  const double c_i = eos_i ? eos_i->c0 : eos_j->c0;
  const double c_j = eos_j ? eos_j->c0 : c_i;
  return sphf_artificial_pair(artificial * kernel.h * 0.5 * (c_i + c_j), mass_of[i], mass_of[j],
                              density[i], density[j], vr, rsq, kernel.h * kernel.h, dwdr_r);
}

/* ----------------------------------------------------------------------
   the artificial viscosity's forces, and with 'heating' its work as heat
   (shared as eval_heating() shares the viscous work)
------------------------------------------------------------------------- */

template <int KERNEL, int DIM>
void PairSPHHarmonicVisc::eval_artificial(int ifrom, int ito, const Rates &rates)
{
  const int newton_pair = force->newton_pair;
  const double *const *const x = atom->x;
  const double *const *const v = atom->v;
  const double *const *const vest = velocity_seen;
  double *const *const f = rates.f;
  double *const desph = rates.desph;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int wall_groupbit = this->wall_groupbit;
  const double heating = this->heating;
  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;

  const double *const shepard = this->shepard;
  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const int wall_i = mask[i] & wall_groupbit;
    // i a wall particle or at a free surface: every neighbour may pair with it
    const int acts_i = wall_i || shepard[i] < SPHF_SURFACE_SHEPARD;
    const double *const u_i = wall_i ? v[i] : vest[i];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double fx_i = 0.0, fy_i = 0.0, fz_i = 0.0, desph_i = 0.0;
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) continue;
      // (artificial_pair() returns 0 for the others: skipped before any work)
      if (!acts_i && !wall_j && !(shepard[j] < SPHF_SURFACE_SHEPARD)) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1],
                             (DIM == 3) ? x[i][2] - x[j][2] : 0.0};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq_kernel) continue;
      const double *const u_j = wall_j ? v[j] : vest[j];
      const double du[3] = {u_i[0] - u_j[0], u_i[1] - u_j[1], (DIM == 3) ? u_i[2] - u_j[2] : 0.0};
      const double vr = du[0] * del[0] + du[1] * del[1] + du[2] * del[2];
      if (!(vr < 0.0)) continue;
      const double dwdr_r = dwdr_r_scale * sphk_df_over_q(KERNEL, sqrt(rsq) * inv_h);
      const double s = artificial_pair(i, j, vr, rsq, dwdr_r);
      const double fx = s * del[0], fy = s * del[1], fz = (DIM == 3) ? s * del[2] : 0.0;
      fx_i += fx;
      fy_i += fy;
      fz_i += fz;
      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        if (DIM == 3) f[j][2] -= fz;
      }
      if (heating > 0.0) {
        const double zero[3] = {0.0, 0.0, 0.0};
        share_pair_heat(heating * sphf_viscous_power(s, 0.0, del, zero, du), wall_i, wall_j,
                        newton_pair || j < nlocal, mass_of[j], desph_i, desph[j]);
      }
      if (evflag) tally_pair(i, j, fx, fy, fz, del[0], del[1], del[2], rates.thread);
    }
    f[i][0] += fx_i;
    f[i][1] += fy_i;
    if (DIM == 3) f[i][2] += fz_i;
    if (heating > 0.0 && !wall_i) desph[i] += desph_i / mass_of[i];
  }
}

/* ----------------------------------------------------------------------
   the Shepard sum S_i = sum_j V_j W_ij of every owned and ghost atom, i
   itself and wall particles included: about 1 inside the fluid and next to
   walls (which complete the support), about 0.5 on a free surface and
   below SPHF_SURFACE_SHEPARD over the outer rows, where the artificial
   viscosity acts; and whether this rank has any such atom
------------------------------------------------------------------------- */

template <int KERNEL, int DIM> void PairSPHHarmonicVisc::update_shepard()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > nmax_shepard) {
    nmax_shepard = atom->nmax;
    memory->destroy(shepard);
    memory->create(shepard, nmax_shepard, "pair:shepard");
  }
  const double *const *const x = atom->x;
  const double *const volume = this->volume;
  const int newton_pair = force->newton_pair;
  const double w0 = kernel.w_scale * sphk_f(KERNEL, 0.0);
  for (int i = 0; i < nall; i++) shepard[i] = (i < nlocal) ? volume[i] * w0 : 0.0;
  const double cutsq_kernel = cut_global * cut_global;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;
  const int *const mask = atom->mask;
  const int wall_groupbit = this->wall_groupbit;
  SPHSupport support;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = ilist[ii];
    const int wall_i = mask[i] & wall_groupbit;
    const int nin = support.gather<DIM, true>(x[i], x, firstneigh[i], numneigh[i], cutsq_kernel);
    double sum_i = 0.0;
    for (int k = 0; k < nin; k++) {
      const int j = support.index[k];
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) continue;
      const double w = kernel.w_scale * sphk_f(KERNEL, sqrt(support.rsq[k]) * kernel.inv_h);
      sum_i += volume[j] * w;
      if (newton_pair || j < nlocal) shepard[j] += volume[i] * w;
    }
    shepard[i] += sum_i;
  }
  if (newton_pair) reverse(SPHCommStage().flat(shepard, 1));
  forward(SPHCommStage().flat(shepard, 1));
  // only fluid particles can be at a free surface: wall particles (their
  // own sums are not complete behind the wall) take part with every fluid
  // neighbour, and atoms of types without an equation of state (the grains
  // of fix sph/grains, solids) are not in the flow's pairs at all
  bigint surface_owned = 0;
  artificial_here = 0;
  const int *const type = atom->type;
  for (int i = 0; i < nall; i++) {
    if (mask[i] & wall_groupbit) {
      shepard[i] = 1.0;
      artificial_here = 1;
    } else if (!eos_of[type[i]]) {
      shepard[i] = 1.0;
    } else if (shepard[i] < SPHF_SURFACE_SHEPARD) {
      artificial_here = 1;
      if (i < nlocal) surface_owned++;
    }
  }
  if (!update->setupflag) return;
  bigint surface_all = 0;
  MPI_Allreduce(&surface_owned, &surface_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  // the scene's default: none where a run starts without a free surface
  // (a closed container full of fluid, under weight)
  if (surface_all == 0 && artificial_request < 0.0) {
    artificial = 0.0;
    artificial_here = 0;
  }
  if (comm->me == 0) {
    if (artificial > 0.0)
      utils::logmesg(lmp,
                     "Pair style sph/harmonic/visc: artificial viscosity {} on pairs with one of "
                     "{} atoms now at a free surface and between fluid and wall particles\n",
                     artificial, surface_all);
    else
      utils::logmesg(lmp,
                     "Pair style sph/harmonic/visc: artificial 0 (the default under weight when "
                     "the run starts without a free surface)\n");
  }
}
