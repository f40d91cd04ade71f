/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The conduction weights of pair sph/cleary/heat: the factors of
   'correction consistent' and 'correction second' for the pairs of the
   support, made anew when the particles move.
------------------------------------------------------------------------- */

#include "sph_conduction_weights.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "sph_consistent.h"
#include "sph_exchange.h"
#include "sph_support_pairs.h"
#include "sph_threads.h"
#include "update.h"

using namespace LAMMPS_NS;

// a . b of the first DIM components
template <int DIM> static inline double dot(const double *a, const double *b)
{
  return (DIM == 3) ? a[0] * b[0] + a[1] * b[1] + a[2] * b[2] : a[0] * b[0] + a[1] * b[1];
}

// a Jacobi sweep's coupling of pair (i, j) with weight G = gq at r = r_ij:
// i gains G (r . lambda_j) r (into coupling_i, its row or a copy of it), and
// j (where j_side) G (r . lambda_i) r
template <int DIM>
static inline void add_coupling(double *coupling_i, double *coupling, const double *lambda, int i,
                                int j, bool j_side, double gq, const double *r)
{
  const double along_j = gq * dot<DIM>(r, lambda + 3 * j);
  for (int k = 0; k < DIM; k++) coupling_i[k] += along_j * r[k];
  if (j_side) {
    const double along_i = gq * dot<DIM>(r, lambda + 3 * i);
    for (int k = 0; k < DIM; k++) coupling[3 * j + k] += along_i * r[k];
  }
}

// the consistent factor of a pair from its atoms' S and lambda at r = r_ij,
// |r|^2 = rsq (sph_consistent.h)
template <int DIM>
static inline double consistent_factor(const double *s_i, const double *s_j, const double *lambda_i,
                                       const double *lambda_j, const double *r, double rsq)
{
  return sphc_second_factor_of(DIM, s_i, s_j, r, rsq) *
      sphc_first_factor_in(DIM, lambda_i, lambda_j, r);
}

SPHConductionWeights *SPHConductionWeights::create(LAMMPS *lmp, int kind, double inv_h, int sweeps,
                                                   int warm_sweeps)
{
  SPHConductionWeights *made = nullptr;
  if (kind == CONSISTENT) made = new SPHConsistentWeights(lmp, sweeps, warm_sweeps);
  if (kind == SECOND) made = new SPHSecondWeights(lmp, inv_h, warm_sweeps == HOLD);
  if (made) made->grow();
  return made;
}

SPHConductionWeights::SPHConductionWeights(LAMMPS *lmp, int kind, int hold) :
    Pointers(lmp), kind(kind), hold(hold), nmax(0), s(nullptr), state(nullptr)
{
}

SPHConductionWeights::~SPHConductionWeights()
{
  memory->destroy(s);
  memory->destroy(state);
}

void SPHConductionWeights::grow()
{
  if (atom->nmax <= nmax) return;
  nmax = atom->nmax;
  memory->destroy(s);
  memory->destroy(state);
  memory->create(s, nmax, 6, "sph/cleary/heat:correction_s");
  memory->create(state, nmax, "sph/cleary/heat:correction_state");
  made.forget();
  grow_more();
}

bool SPHConductionWeights::held() const
{
  return hold && made.current(update, neighbor) && atom->nmax <= nmax;
}

void SPHConductionWeights::reweigh(SPHSupportPairs &pairs)
{
  for (int q : pairs.all())
    pairs.weight[q] = factor(pairs.i[q], pairs.j[q], pairs.r_of(q), pairs.distance[q]);
}

double SPHConductionWeights::memory_usage() const
{
  return 7.0 * nmax * sizeof(double);
}

/* ----------------------------------------------------------------------
   the rows of the second moments M of the plain weights, zeroed on every
   owned and ghost atom, for SPHSupportPairs::gather to sum before refresh()
------------------------------------------------------------------------- */

double *SPHConductionWeights::moments_to_gather()
{
  grow();
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < 6; k++) s[i][k] = 0.0;
  return s[0];
}

/* ----------------------------------------------------------------------
   M summed on the owners; atoms whose smallest eigenvalue of M / V is below
   full support (a free edge, where the missing first moment is the
   boundary's adiabatic face) keep the plain term, the others get S = V M^-1
------------------------------------------------------------------------- */

void SPHConductionWeights::normalise(const double *volume, SPHExchange &exchange)
{
  const int nlocal = atom->nlocal;
  const int dim = domain->dimension;
  if (force->newton_pair) exchange.reverse(SPHCommStage().rows(s, 6));
  sph_parallel_for(nlocal, comm->nthreads, [&](int i) {
    state[i] = sphc_moment_normaliser(dim, s[i], volume[i], s[i]);
  });
  exchange.forward(SPHCommStage().rows(s, 6).flat(state, 1));
}

void SPHConductionWeights::report() const
{
  bigint plain = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (state[i] == 0.0) plain++;
  bigint plain_all = 0;
  MPI_Allreduce(&plain, &plain_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: correction {} on {} of {} atoms; {} keep "
                   "the plain term (incomplete kernel support: free edges or too few neighbours)\n",
                   name(), atom->natoms - plain_all, atom->natoms, plain_all);
}

/* ----------------------------------------------------------------------
   'correction consistent': S, then lambda from Jacobi sweeps on the first
   moment of the weights with S (sph_consistent.h): 'sweeps' of them from
   lambda = 0 at a neighbour-list build, 'warm_sweeps' between builds from
   the last step's lambda (the atoms keep their indices then, ghosts
   included). The particles move little in a step, so the iteration goes on
   where it stopped and, a few steps after a build, has had more sweeps
   than a start from 0 would take. Builds fall on the same steps on any
   number of ranks (the skin test is global), so the factors do not depend
   on the ranks; a run's setup always starts from 0.
------------------------------------------------------------------------- */

SPHConsistentWeights::SPHConsistentWeights(LAMMPS *lmp, int sweeps, int warm_sweeps) :
    SPHConductionWeights(lmp, CONSISTENT, warm_sweeps == HOLD), sweeps(sweeps),
    warm_sweeps(warm_sweeps), kinv(nullptr), lambda(nullptr), deficit(nullptr), coupling(nullptr)
{
}

SPHConsistentWeights::~SPHConsistentWeights()
{
  release();
}

void SPHConsistentWeights::release()
{
  memory->destroy(kinv);
  memory->destroy(lambda);
  memory->destroy(deficit);
  memory->destroy(coupling);
}

void SPHConsistentWeights::grow_more()
{
  release();
  memory->create(kinv, nmax, 6, "sph/cleary/heat:correction_kinv");
  memory->create(lambda, nmax, 3, "sph/cleary/heat:correction_lambda");
  memory->create(deficit, nmax, 3, "sph/cleary/heat:correction_deficit");
  memory->create(coupling, nmax, 3, "sph/cleary/heat:correction_coupling");
}

double SPHConsistentWeights::memory_usage() const
{
  return SPHConductionWeights::memory_usage() + 15.0 * nmax * sizeof(double) +
      kinv_sums.memory_usage() + deficit_sums.memory_usage() + coupling_sums.memory_usage();
}

void SPHConsistentWeights::refresh(SPHSupportPairs &pairs, const double *volume,
                                   SPHExchange &exchange)
{
  normalise(volume, exchange);
  if (domain->dimension == 3)
    refresh_in<3>(pairs, exchange);
  else
    refresh_in<2>(pairs, exchange);
}

template <int DIM>
void SPHConsistentWeights::refresh_in(SPHSupportPairs &pairs, SPHExchange &exchange)
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = DIM;
  const int newton = force->newton_pair;
  // the threads of the gather, each over its block of pairs
  const int nthreads = pairs.threads();
  const int *const pair_i = pairs.i.data();
  const int *const pair_j = pairs.j.data();
  const double *const pair_r = pairs.r.data();
  double *const g = pairs.g.data();
  double *const weight = pairs.weight.data();
  // the per-atom rows, flat (one load fewer per access)
  double *const kinv_flat = kinv[0];
  double *const lambda_flat = lambda[0];
  double *const deficit_flat = deficit[0];
  double *const coupling_flat = coupling[0];
  // (no build since the last refresh: the atoms kept their indices)
  const bool warm = warm_sweeps > 0 && made.current(update, neighbor);

  // the weights with S from here on, and their first moments s and K; on a
  // warm start the first sweep's coupling too, from the last step's lambda
  // (the ghosts' as forwarded then): one pass over the pairs fewer
  sph_parallel_for(nall, nthreads, [&](int i) {
    for (int k = 0; k < 6; k++) kinv_flat[6 * i + k] = 0.0;
    for (int k = 0; k < 3; k++) deficit_flat[3 * i + k] = 0.0;
    if (warm)
      for (int k = 0; k < 3; k++) coupling_flat[3 * i + k] = 0.0;
  });
  kinv_sums.fit(6 * (size_t) nall, nthreads);
  deficit_sums.fit(3 * (size_t) nall, nthreads);
  coupling_sums.fit(3 * (size_t) nall, nthreads);
  sph_parallel(nthreads, [&](int tid) {
    double *const kinv_thr = kinv_sums.of(kinv_flat, tid);
    double *const deficit_thr = deficit_sums.of(deficit_flat, tid);
    double *const coupling_thr = warm ? coupling_sums.of(coupling_flat, tid) : nullptr;
    if (warm)
      weigh_pairs<DIM, true>(pairs, pairs.blocks[tid], newton, kinv_thr, deficit_thr, coupling_thr);
    else
      weigh_pairs<DIM, false>(pairs, pairs.blocks[tid], newton, kinv_thr, deficit_thr, nullptr);
    kinv_sums.reduce(kinv_flat, nthreads, tid);
    deficit_sums.reduce(deficit_flat, nthreads, tid);
    if (warm) coupling_sums.reduce(coupling_flat, nthreads, tid);
  });
  if (newton) {
    SPHCommStage moments = SPHCommStage().rows(kinv, 6).rows(deficit, 3);
    if (warm) moments.rows(coupling, 3);
    exchange.reverse(moments);
  }
  sph_parallel_for(nlocal, nthreads, [&](int i) {
    double inverse[6];
    double *const kinv_i = kinv_flat + 6 * i;
    if (state[i] == 0.0 || sphc_sym_inverse(dim, kinv_i, inverse) <= 0.0)
      for (int k = 0; k < 6; k++) inverse[k] = 0.0;    // lambda stays 0
    for (int k = 0; k < 6; k++) kinv_i[k] = inverse[k];
  });

  // the first sweep: from lambda = 0 (no coupling), or on a warm start with
  // the coupling summed above
  const double none[3] = {0.0, 0.0, 0.0};
  if (!warm)
    for (int i = 0; i < nall; i++)
      for (int k = 0; k < 3; k++) lambda_flat[3 * i + k] = 0.0;
  sph_parallel_for(nlocal, nthreads, [&](int i) {
    sphc_first_update(kinv_flat + 6 * i, warm ? coupling_flat + 3 * i : none, deficit_flat + 3 * i,
                      lambda_flat + 3 * i);
  });
  const int remaining = (warm ? warm_sweeps : sweeps) - 1;

  // the further Jacobi sweeps: each with the neighbours' lambda of the sweep before
  const SPHCommStage lambda_stage = SPHCommStage().rows(lambda, 3);
  for (int sweep = 0; sweep < remaining; sweep++) {
    exchange.forward(lambda_stage);
    sph_parallel(nthreads, [&](int tid) {
      int from, to;
      sph_thread_slice(nall, nthreads, tid, from, to);
      for (int i = from; i < to; i++)
        for (int k = 0; k < 3; k++) coupling_flat[3 * i + k] = 0.0;
      double *const coupling_thr = coupling_sums.of(coupling_flat, tid);
      // (thread 0 adds to the coupling itself: all of it zeroed first)
      if (nthreads > 1) {
#if defined(_OPENMP)
#pragma omp barrier
#endif
      }
      const SPHSupportPairs::Block block = pairs.blocks[tid];
      for (int q = block.begin; q < block.end; q++)
        add_coupling<DIM>(coupling_thr + 3 * pair_i[q], coupling_thr, lambda_flat, pair_i[q],
                          pair_j[q], newton || pair_j[q] < nlocal, g[q], pair_r + 3 * q);
      coupling_sums.reduce(coupling_flat, nthreads, tid);
    });
    if (newton) exchange.reverse(SPHCommStage().rows(coupling, 3));
    sph_parallel_for(nlocal, nthreads, [&](int i) {
      sphc_first_update(kinv_flat + 6 * i, coupling_flat + 3 * i, deficit_flat + 3 * i,
                        lambda_flat + 3 * i);
    });
  }
  exchange.forward(lambda_stage);
  made.stamp(update);
  sph_parallel(nthreads, [&](int tid) {
    const SPHSupportPairs::Block block = pairs.blocks[tid];
    for (int q = block.begin; q < block.end; q++)
      weight[q] *= sphc_first_factor_in(DIM, lambda_flat + 3 * pair_i[q],
                                        lambda_flat + 3 * pair_j[q], pair_r + 3 * q);
  });
}

/* each pair of a block: its weight with S (its factor so far) and its
   plain weight g made that weight's; the moments K and s of its atoms, and
   with WARM the coupling of the first Jacobi sweep from the lambda in place
   (into one thread's sums) */

template <int DIM, bool WARM>
void SPHConsistentWeights::weigh_pairs(SPHSupportPairs &pairs, SPHSupportPairs::Block block,
                                       int newton, double *kinv_flat, double *deficit_flat,
                                       double *coupling_flat)
{
  const int nlocal = atom->nlocal;
  const int *const pair_i = pairs.i.data();
  const int *const pair_j = pairs.j.data();
  const double *const pair_r = pairs.r.data();
  const double *const distance = pairs.distance.data();
  double *const g = pairs.g.data();
  double *const weight = pairs.weight.data();
  const double *const s_flat = s[0];
  const double *const lambda_flat = lambda[0];
  int q = block.begin;
  while (q < block.end) {
    // atom i's pairs are consecutive and none has i as its j: i's sums
    // stay in registers over them (the same additions in the same order),
    // without a store and reload per pair
    const int i = pair_i[q];
    double kinv_i[6], deficit_i[3], coupling_i[3];
    for (int k = 0; k < 6; k++) kinv_i[k] = kinv_flat[6 * i + k];
    for (int k = 0; k < 3; k++) deficit_i[k] = deficit_flat[3 * i + k];
    if (WARM)
      for (int k = 0; k < 3; k++) coupling_i[k] = coupling_flat[3 * i + k];
    for (; q < block.end && pair_i[q] == i; q++) {
      const int j = pair_j[q];
      const double *const r = pair_r + 3 * q;
      weight[q] =
          sphc_second_factor_of(DIM, s_flat + 6 * i, s_flat + 6 * j, r, distance[q] * distance[q]);
      const double gq = g[q] * weight[q];
      g[q] = gq;
      const bool j_side = newton || j < nlocal;
      sphc_moment_add_in(DIM, kinv_i, gq, r);
      for (int k = 0; k < DIM; k++) deficit_i[k] += gq * r[k];
      if (j_side) {
        sphc_moment_add_in(DIM, kinv_flat + 6 * j, gq, r);
        for (int k = 0; k < DIM; k++) deficit_flat[3 * j + k] -= gq * r[k];
      }
      if (WARM) add_coupling<DIM>(coupling_i, coupling_flat, lambda_flat, i, j, j_side, gq, r);
    }
    for (int k = 0; k < 6; k++) kinv_flat[6 * i + k] = kinv_i[k];
    for (int k = 0; k < 3; k++) deficit_flat[3 * i + k] = deficit_i[k];
    if (WARM)
      for (int k = 0; k < 3; k++) coupling_flat[3 * i + k] = coupling_i[k];
  }
}

/* 'warm hold' between builds: S and lambda of the last refresh, each
   pair's factor at its current separation */

void SPHConsistentWeights::reweigh(SPHSupportPairs &pairs)
{
  if (domain->dimension == 3)
    reweigh_in<3>(pairs);
  else
    reweigh_in<2>(pairs);
}

template <int DIM> void SPHConsistentWeights::reweigh_in(SPHSupportPairs &pairs)
{
  const int *const pair_i = pairs.i.data();
  const int *const pair_j = pairs.j.data();
  const double *const pair_r = pairs.r.data();
  const double *const distance = pairs.distance.data();
  double *const weight = pairs.weight.data();
  const double *const s_flat = s[0];
  const double *const lambda_flat = lambda[0];
  sph_parallel(pairs.threads(), [&](int tid) {
    const SPHSupportPairs::Block block = pairs.blocks[tid];
    for (int q = block.begin; q < block.end; q++) {
      const int i = pair_i[q], j = pair_j[q];
      weight[q] =
          consistent_factor<DIM>(s_flat + 6 * i, s_flat + 6 * j, lambda_flat + 3 * i,
                                 lambda_flat + 3 * j, pair_r + 3 * q, distance[q] * distance[q]);
    }
  });
}

double SPHConsistentWeights::factor(int i, int j, const double r_ij[3], double r) const
{
  if (domain->dimension == 3)
    return consistent_factor<3>(s[i], s[j], lambda[i], lambda[j], r_ij, r * r);
  return consistent_factor<2>(s[i], s[j], lambda[i], lambda[j], r_ij, r * r);
}

/* ----------------------------------------------------------------------
   'correction second': the multipliers nu of sph_second_moment.h for this
   step's pairs, and each pair's factor; the atoms of incomplete support
   (state 0) keep nu = 0. The solve starts from the last solution while
   the atoms keep their indices (no neighbour-list build since; for
   moving particles), else from nu = 0, which every run's setup does: the
   start is the same on any number of ranks, and a run split by a restart
   repeats the factors exactly where the split falls on a build and to
   the solver's tolerance elsewhere
------------------------------------------------------------------------- */

// the regularisation epsilon of sph_second_moment.h: the value of the
// disordered two-material slab's best accuracy at 10 t1 for its cost among
// 1e-4 to 1e-6 (doc/src/Howto_sph_theory.rst)
static constexpr double SECOND_REGULARIZATION = 1e-6;
// The regularisation leaves the moments off by epsilon nu, and near free
// edges nu carries a large smooth part (a nearly constant first-moment
// multiplier that changes no interior pair), which errs the Laplacian deep
// inside (test robust.second_rotated). So the regularised solution starts
// a solve of the unregularised problem, taken if it converges within these
// Newton steps; otherwise (no weights with the exact moments, where the
// unregularised multipliers grow without bound) the regularised one stays
static constexpr int SECOND_EXACT_NEWTON_STEPS = 20;
// the solver's limits: residual of Phi's gradient relative to V / h^2, and
// step counts far above what converging cases take (under 20 Newton
// steps; conjugate gradients of the order of (width / h)^2 per step)
static constexpr double SECOND_TOLERANCE = 1e-13;
static constexpr int SECOND_NEWTON_STEPS = 50;
static constexpr int SECOND_CG_STEPS = 100000;
// the coarse space of the two-level preconditioner: grid spacing in h and
// the largest coarse dimension (a dense factor of that many rows). The
// slab of 80 x 20 jittered by 0.2 spacings, h = 1.3 spacings, needed the
// fewest conjugate-gradient steps for the least time with a grid of 2 h
// (one level: 28 times the steps)
static constexpr double SECOND_COARSE_SPACING = 2.0;
static constexpr int SECOND_COARSE_SIZE = 2000;

SPHSecondWeights::SPHSecondWeights(LAMMPS *lmp, double inv_h, int hold) :
    SPHConductionWeights(lmp, SECOND, hold), inv_h(inv_h), result(), exact(-1), warned(0),
    exchange(nullptr)
{
}

double SPHSecondWeights::memory_usage() const
{
  return SPHConductionWeights::memory_usage() +
      (double) (nu.capacity() + work.capacity() + volume_owned.capacity() + kept.capacity()) *
      sizeof(double) +
      (double) constrained.capacity() * sizeof(int) +
      (double) solver_pairs.capacity() * sizeof(sphs_pair);
}

void SPHSecondWeights::refresh(SPHSupportPairs &pairs, const double *volume, SPHExchange &exchange)
{
  normalise(volume, exchange);
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const int n = sphs_count(dim);
  const int npairs = pairs.count();

  solver_pairs.resize(npairs);
  int stored = 0;
  for (int q : pairs.all()) {
    sphs_pair &to = solver_pairs[stored++];
    to.i = pairs.i[q];
    to.j = pairs.j[q];
    for (int c = 0; c < 3; c++) to.r[c] = pairs.r_of(q)[c];
    to.g = pairs.g[q];
  }
  volume_owned.assign(volume, volume + nlocal);
  constrained.resize(nlocal);
  for (int i = 0; i < nlocal; i++) constrained[i] = state[i] != 0.0;

  sphs_problem problem;
  problem.dim = dim;
  problem.nlocal = nlocal;
  problem.nall = nall;
  problem.newton = force->newton_pair;
  problem.npairs = npairs;
  problem.pairs = solver_pairs.data();
  problem.volume = volume_owned.data();
  problem.constrained = constrained.data();
  problem.h = 1.0 / inv_h;
  problem.tolerance = SECOND_TOLERANCE;
  problem.regularization = SECOND_REGULARIZATION;
  problem.max_newton = SECOND_NEWTON_STEPS;
  problem.max_cg = SECOND_CG_STEPS;
  problem.exchange.context = this;
  problem.exchange.forward = forward;
  problem.exchange.reverse = reverse;
  problem.exchange.sum = sum;
  problem.exchange.max = max;
  problem.exchange.sum_array = sum_array;
  problem.x = atom->x[0];
  problem.coarse = SECOND_COARSE_SPACING;
  problem.max_coarse = SECOND_COARSE_SIZE;
  this->exchange = &exchange;
  work.resize(sphs_work_size(&problem));
  const int warm =
      neighbor->ago > 0 && made.since_build(neighbor) && nu.size() == (size_t) nall * n;
  if (!warm) nu.assign((size_t) nall * n, 0.0);
  result = sphs_solve(&problem, nu.data(), work.data());
  exact = -1;
  if (result.converged && result.moments > SECOND_TOLERANCE) {
    kept = nu;
    sphs_problem unregularised = problem;
    unregularised.regularization = 0.0;
    unregularised.max_newton = SECOND_EXACT_NEWTON_STEPS;
    sphs_result refined = sphs_solve(&unregularised, nu.data(), work.data());
    exact = refined.converged;
    if (refined.converged) {
      refined.newton_steps += result.newton_steps;
      refined.cg_steps += result.cg_steps;
      result = refined;
    } else
      nu = kept;    // ghosts included
  }
  this->exchange = nullptr;
  made.stamp(update);

  for (int q : pairs.all()) {
    double f[SPHS_MAX];
    sphs_basis(dim, pairs.r_of(q), inv_h, f);
    pairs.weight[q] =
        sphs_factor(dim, f, &nu[(size_t) pairs.i[q] * n], &nu[(size_t) pairs.j[q] * n]);
  }
  if (!result.converged && !warned && comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/cleary/heat: correction second: the multipliers reached a "
                   "residual of {:.3g} (of V / h^2) after {} Newton and {} conjugate-gradient "
                   "steps, not {:.3g}; the Laplacian is less accurate for quadratic fields",
                   result.residual, result.newton_steps, result.cg_steps, SECOND_TOLERANCE);
  if (!result.converged) warned = 1;
}

double SPHSecondWeights::factor(int i, int j, const double r_ij[3], double /*r*/) const
{
  const int dim = domain->dimension;
  const int n = sphs_count(dim);
  double f[SPHS_MAX];
  sphs_basis(dim, r_ij, inv_h, f);
  return sphs_factor(dim, f, &nu[(size_t) i * n], &nu[(size_t) j * n]);
}

void SPHSecondWeights::report() const
{
  SPHConductionWeights::report();
  bigint clipped = result.clipped, clipped_all = 0;
  MPI_Allreduce(&clipped, &clipped_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: correction second: moments to {:.2g} of V / h^2 "
                   "({}) in {} Newton and {} conjugate-gradient steps (coarse space of {}); {} "
                   "pairs at factor 0\n",
                   result.moments,
                   exact == 1       ? "unregularised problem solved"
                       : exact == 0 ? "regularised problem solved, unregularised one not converged"
                                    : fmt::format("regularised problem to {:.2g}", result.residual),
                   result.newton_steps, result.cg_steps, result.coarse_size, clipped_all);
}

// the solver's exchanges: n values per atom of 'values', the owners' to
// their ghosts (forward) or the ghosts' added to their owners' (reverse)
void SPHSecondWeights::forward(void *context, double *values, int n)
{
  static_cast<SPHSecondWeights *>(context)->exchange->forward(SPHCommStage().flat(values, n));
}

void SPHSecondWeights::reverse(void *context, double *values, int n)
{
  static_cast<SPHSecondWeights *>(context)->exchange->reverse(SPHCommStage().flat(values, n));
}

double SPHSecondWeights::sum(void *context, double value)
{
  double total = 0.0;
  MPI_Allreduce(&value, &total, 1, MPI_DOUBLE, MPI_SUM,
                static_cast<SPHSecondWeights *>(context)->world);
  return total;
}

void SPHSecondWeights::sum_array(void *context, double *values, int n)
{
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM,
                static_cast<SPHSecondWeights *>(context)->world);
}

double SPHSecondWeights::max(void *context, double value)
{
  double largest = 0.0;
  MPI_Allreduce(&value, &largest, 1, MPI_DOUBLE, MPI_MAX,
                static_cast<SPHSecondWeights *>(context)->world);
  return largest;
}
