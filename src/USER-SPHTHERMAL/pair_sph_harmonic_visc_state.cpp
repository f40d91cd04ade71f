/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/harmonic/visc: the per-atom state its loops read, made once per force
   evaluation for owned and ghost atoms: pressure, viscosity, volume, the
   held mean pressure, and the inverse moments of 'correction gradient'.
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
#include "sph_particle.h"
#include "sph_support.h"
#include "sph_threads.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

struct PairSPHHarmonicVisc::GradientCall {
  PairSPHHarmonicVisc *pair;
  template <int KERNEL> void run()
  {
    if (pair->domain->dimension == 3)
      pair->update_gradient_correction<KERNEL, 3>();
    else
      pair->update_gradient_correction<KERNEL, 2>();
  }
};

void PairSPHHarmonicVisc::refresh_gradient_correction()
{
  GradientCall call = {this};
  SPHDispatch<SPHKernelKinds>::to(call, &kernel_kind);
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
   an even arrangement as in the plain form. Atoms whose support is
   incomplete (sphc_moment_normaliser: a free surface) and wall particles
   keep B = I.
------------------------------------------------------------------------- */

template <int KERNEL, int DIM> void PairSPHHarmonicVisc::update_gradient_correction()
{
  const int dim = DIM;
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  if (atom->nmax > nmax_gradient) {
    nmax_gradient = atom->nmax;
    memory->destroy(gradient_inverse);
    memory->create(gradient_inverse, nmax_gradient, 6, "pair:gradient_inverse");
    gradient_made.forget();
  }
  if (gradient_request == GRADIENT_HOLD && gradient_made.current(update, neighbor)) return;
  gradient_made.stamp(update);
  double **const moment = gradient_inverse;    // M until B replaces it
  const int nthreads = comm->nthreads;
  sph_parallel_for(nall, nthreads, [&](int i) {
    for (int k = 0; k < 6; k++) moment[i][k] = 0.0;
  });
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;
  // each thread a slice of the list, adding to its own copy of the moments
  gradient_sums.fit(6 * (size_t) nall, nthreads);
  std::vector<int> slices, before;
  sph_neighbour_slices(ilist, numneigh, list->inum, nthreads, slices, before);
  sph_parallel(nthreads, [&](int tid) {
    double *const moment_thr = gradient_sums.of(moment[0], tid);
    const int from = slices[tid], to = slices[tid + 1];
    // the entries inside the support first, their kernel values together
    // (sph_support.h)
    SPHSupport support;
    for (int ii = from; ii < to; ii++) {
      const int i = ilist[ii];
      const int wall_i = mask[i] & wall_groupbit;
      const int nin = support.gather<DIM, true>(x[i], x, firstneigh[i], numneigh[i], cutsq_kernel);
      const double *const rsq_in = support.rsq;
      double *const g_in = support.a;
      for (int k = 0; k < nin; k++)
        g_in[k] = -dwdr_r_scale * sphk_df_over_q(KERNEL, sqrt(rsq_in[k]) * inv_h);
      // i's row in registers over its neighbours (none of them adds to it):
      // the same sums, without a store and reload per pair
      double *const row_i = moment_thr + 6 * (size_t) i;
      double moment_i[6];
      for (int k = 0; k < 6; k++) moment_i[k] = row_i[k];
      for (int k = 0; k < nin; k++) {
        const int j = support.index[k];
        const int wall_j = mask[j] & wall_groupbit;
        if (wall_i && wall_j) continue;
        const double *const del = support.del + 3 * k;
        if (!wall_i) sphc_moment_add_in(DIM, moment_i, g_in[k] * volume[j], del);
        if (!wall_j && (newton_pair || j < nlocal))
          sphc_moment_add_in(DIM, moment_thr + 6 * (size_t) j, g_in[k] * volume[i], del);
      }
      for (int k = 0; k < 6; k++) row_i[k] = moment_i[k];
    }
    gradient_sums.reduce(moment[0], nthreads, tid);
  });
  if (newton_pair) reverse(SPHCommStage().rows(moment, 6));
  // the atoms that keep the plain gradient, counted by each thread
  std::vector<bigint> plain_of(nthreads, 0), fluid_of(nthreads, 0);
  sph_parallel(nthreads, [&](int tid) {
    int from, to;
    sph_thread_slice(nlocal, nthreads, tid, from, to);
    for (int i = from; i < to; i++) {
      double inverse[6] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
      if (!(mask[i] & wall_groupbit)) {
        fluid_of[tid]++;
        // M is summed with V_j: the unit volume
        if (!sphc_moment_normaliser(dim, moment[i], 1.0, inverse)) plain_of[tid]++;
      }
      for (int k = 0; k < 6; k++) moment[i][k] = inverse[k];
    }
  });
  bigint plain = 0, fluid = 0;
  for (int t = 0; t < nthreads; t++) {
    plain += plain_of[t];
    fluid += fluid_of[t];
  }
  forward(SPHCommStage().rows(moment, 6));
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

/* ----------------------------------------------------------------------
   pressure, viscosity and mass of every owned and ghost atom as the flow
   sees them (ghosts carry rho, esph, cv: no communication is needed):
   those of the material from fix sph/materials's store, but for the solid
   particles of fix sph/wall/adami, which take the fluid's state that the
   wall extrapolates
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::update_atom_state()
{
  SPHAtomState &state = materials->atom_state();
  state.fill(SPHAtomState::MASS |
                 ((thermal_expansion || viscosity_varies || (hydrostatic && buoyancy))
                      ? SPHAtomState::TEMPERATURE
                      : 0),
             "Pair style sph/harmonic/visc");
  const double *const temperature = state.temperature();
  // the walls that hold solid particles (known after the walls' init)
  std::vector<FixSPHWallAdami *> solid_walls;
  for (auto wall : adami_walls)
    if (wall->has_solids()) solid_walls.push_back(wall);
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(pressure);
    memory->destroy(viscosity);
    memory->destroy(mass_of);
    memory->destroy(volume);
    memory->destroy(density);
    memory->destroy(diffused_density);
    memory->destroy(velocity_seen_store);
    memory->create(volume, nmax, "pair:volume");
    memory->create(diffused_density, nmax, "pair:diffused_density");
    memory->create(pressure, nmax, "pair:pressure");
    memory->create(viscosity, nmax, "pair:viscosity");
    memory->create(mass_of, nmax, "pair:mass_of");
    memory->create(density, nmax, "pair:density");
  }
  if (!solid_walls.empty() && !velocity_seen_store)
    memory->create(velocity_seen_store, nmax, 3, "pair:velocity_seen");
  const double *const rho = atom->rho;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nall = atom->nlocal + atom->nghost;
  // among grains (fix sph/grains) rho is the superficial density eps rho_f
  // (sph_particle.h): the equation of state sees rho / eps, the density
  // diffusion the departure of rho from eps rho_ref
  const double *const porosity = SPHParticles::porosity_of(atom);
  const bool diffuse_departure = thermal_expansion || porosity;
  diffusion_rho = diffuse_departure ? diffused_density : rho;
  std::copy(state.mass(), state.mass() + nall, mass_of);
  // the viscosity's velocity: vest, but the solid wall particles' no-slip one
  double **const seen = solid_walls.empty() ? nullptr : velocity_seen_store;
  velocity_seen = seen ? seen : atom->vest;
  const double *const *const vest = atom->vest;
  for (int i = 0; i < nall; i++) {
    FixSPHWallAdami *solid = nullptr;
    for (auto wall : solid_walls)
      if ((mask[i] & wall->groupbit) && wall->solid(i)) solid = wall;
    if (seen) {
      const double *const from = solid ? solid->no_slip_velocity(i) : vest[i];
      for (int k = 0; k < 3; k++) seen[i][k] = from[k];
    }
    if (solid) {
      // its own volume, filled with the fluid as the wall extrapolates it and
      // compressed with it (so that wall and fluid particles keep their share)
      volume[i] = mass_of[i] / rho[i] * solid->compression(i);
      pressure[i] = solid->pressure(i);
      density[i] = solid->fluid_density(i);
      viscosity[i] = solid->viscosity(i);
      mass_of[i] = density[i] * volume[i];
      if (diffuse_departure) diffused_density[i] = rho[i];
      continue;
    }
    const sphe_eos *eos = materials->eos(type[i]);
    if (!eos) {
      // a type this style does not cover (init checked the others), e.g. the
      // grains of fix sph/grains in a hybrid: no pair of it is evaluated
      pressure[i] = viscosity[i] = 0.0;
      density[i] = rho[i];
      volume[i] = mass_of[i] / rho[i];
      if (diffuse_departure) diffused_density[i] = rho[i];
      continue;
    }
    const double eps = porosity ? porosity[i] : 1.0;
    const double fluid_rho = rho[i] / eps;
    if (eos->thermal) {
      const double t = temperature[i];
      const double rho_ref = sphe_reference_density(eos, t);
      if (!(rho_ref > 0.0) || !std::isfinite(rho_ref))
        SPHCheck::stop(
            lmp, FLERR,
            fmt::format(
                "Pair style sph/harmonic/visc: atom {} (type {}) at T = {} has no reference "
                "density: 1 + beta (T - T0) = {} of its equation of state's thermal "
                "expansion must be > 0",
                atom->tag[i], type[i], t, 1.0 + eos->beta * (t - eos->t0)));
      pressure[i] = sphe_pressure_ref(eos, fluid_rho, rho_ref);
      diffused_density[i] = rho[i] - (eps * rho_ref - eos->rho0);
    } else {
      // with the buoyancy's potential: its pressure rho0 phi, carried without compression
      pressure[i] = sphe_pressure(eos, fluid_rho) +
          eos->rho0 * SPHBodyForce::potential_of(pressure_buoyancy, mask[i], i);
      if (diffuse_departure) diffused_density[i] = rho[i] - (eps - 1.0) * eos->rho0;
    }
    viscosity[i] = materials->viscosity_at(type[i], viscosity_varies ? temperature[i] : 0.0,
                                           "Pair style sph/harmonic/visc");
    density[i] = rho[i];
    volume[i] = mass_of[i] / rho[i];
  }
  if (hydrostatic) {
    body_accel.resize(3 * (size_t) nall);
    // the buoyancy that its potential balances does not stratify the density
    const SPHBodyForce::Buoyancy *stratifying = SPHBodyForce::has_potential(buoyancy) ? nullptr
                                                                                      : buoyancy;
    for (int i = 0; i < nall; i++)
      SPHBodyForce::acceleration(gravity, stratifying, mask[i], type[i],
                                 buoyancy ? temperature[i] : 0.0, atom->x[i],
                                 &body_accel[3 * (size_t) i]);
  }
  pvector[0] = mean_pressure_held ? hold_mean_pressure() : 0.0;
}

/* ----------------------------------------------------------------------
   'mean_pressure P': every particle's pressure, owned or ghost, wall or
   fluid, less one offset such that the volume-weighted mean over the
   fluid (the atoms of no wall group with an eos) is P. The pair terms then do not see
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
  const int *const type = atom->type;
  for (int i = 0; i < nlocal; i++)
    if (!(mask[i] & wall_groupbit) && materials->eos(type[i])) {
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
