/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: the weights of the support, made anew when the particles
   move: the pairs within the support, the factors of 'correction
   consistent' and 'second', and the distances of 'mean interface'.
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_dirichlet.h"
#include "force.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_particle.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "sph_dispatch.h"
#include "sph_consistent.h"
#include "sph_hub.h"
#include "sph_support.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   the pairs, factors and distances for this step's positions
------------------------------------------------------------------------- */

struct PairSPHClearyHeat::SupportCall {
  PairSPHClearyHeat *pair;
  template <int KERNEL> void run() { pair->update_pairs<KERNEL>(); }
};

void PairSPHClearyHeat::refresh_support()
{
  SupportCall call = {this};
  SPHDispatch<SPHKernelKinds>::to(call, &kernel_kind);
}

template <int KERNEL> void PairSPHClearyHeat::update_pairs()
{
  if (mean == SPHC_INTERFACE) mark_interface_atoms();
  gather_support_pairs<KERNEL>();
  if (correct) update_correction<KERNEL>();
  if (mean == SPHC_INTERFACE) update_interface<KERNEL>();
}

/* ----------------------------------------------------------------------
   'correction consistent': the per-atom S and lambda of sph_consistent.h
   for this step's positions. A pass gathers the second moments M of the
   Brookshaw weights; atoms whose smallest eigenvalue of M / V is below
   full_support (a free edge, where the missing first moment is the
   boundary's adiabatic face) keep the plain term; the others get
   S = V M^-1 and lambda from 'sweeps' Jacobi sweeps on the first moment.
------------------------------------------------------------------------- */

// smallest eigenvalue of M / V that counts as complete support: 1 on a
// lattice away from edges, 0.5 on a free edge's first row, 0.9 on its
// second, 0.74 to 1.07 inside particles jittered by 0.2 dx
static constexpr double FULL_SUPPORT = 0.7;

int PairSPHClearyHeat::pairs_current()
{
  int moved = !corr_valid || neighbor->ago == 0 || atom->nmax > nmax_pairs;
  const double *const *const x = atom->x;
  const double *const rho = atom->rho;
  for (int i = 0; i < atom->nlocal && !moved; i++)
    moved = x[i][0] != corr_x[i][0] || x[i][1] != corr_x[i][1] || x[i][2] != corr_x[i][2] ||
        rho[i] != corr_rho[i];
  int any = 0;
  MPI_Allreduce(&moved, &any, 1, MPI_INT, MPI_MAX, world);
  return !any;
}

void PairSPHClearyHeat::grow_correction()
{
  if (atom->nmax > nmax_correct) {
    nmax_correct = atom->nmax;
    memory->destroy(corr_s);
    memory->destroy(corr_kinv);
    memory->destroy(corr_lambda);
    memory->destroy(corr_deficit);
    memory->destroy(corr_coupling);
    memory->destroy(corr_state);
    memory->create(corr_s, nmax_correct, 6, "pair:corr_s");
    memory->create(corr_kinv, nmax_correct, 6, "pair:corr_kinv");
    memory->create(corr_lambda, nmax_correct, 3, "pair:corr_lambda");
    memory->create(corr_deficit, nmax_correct, 3, "pair:corr_deficit");
    memory->create(corr_coupling, nmax_correct, 3, "pair:corr_coupling");
    memory->create(corr_state, nmax_correct, "pair:corr_state");
  }
}

template <int KERNEL> void PairSPHClearyHeat::update_correction()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const int newton = force->newton_pair;
  // each pair is gathered by both its atoms (the j side where it is this
  // rank's to gather, the rest by reverse communication)
  auto gather_j = [&](int j) { return newton || j < nlocal; };

  // the second moments M of the plain weights, kept in corr_s until S replaces them
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < 6; k++) corr_s[i][k] = 0.0;
  for (const auto &p : support_pairs) {
    sphc_moment_add(corr_s[p.i], p.g, p.r);
    if (gather_j(p.j)) sphc_moment_add(corr_s[p.j], p.g, p.r);
  }
  comm_stage = COMM_MOMENT;
  if (newton) SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++) {
    const double volume = volume_of(i);
    double inverse[6];
    const double smallest = sphc_sym_min_eigen(dim, corr_s[i]) / volume;
    const int full = smallest >= FULL_SUPPORT && sphc_sym_inverse(dim, corr_s[i], inverse) > 0.0;
    corr_state[i] = full ? 1.0 : 0.0;
    for (int k = 0; k < 6; k++) corr_s[i][k] = full ? volume * inverse[k] : ((k < 3) ? 1.0 : 0.0);
  }
  comm_stage = COMM_STATE;
  SPHCompat::forward_comm(comm, this);
  if (correct == CORRECT_SECOND) {
    solve_second();
    return;
  }

  // the weights with S from here on; their first moments s and K
  for (auto &p : support_pairs) {
    const double e[3] = {p.r[0] / p.distance, p.r[1] / p.distance, p.r[2] / p.distance};
    p.weight = sphc_second_factor(corr_s[p.i], corr_s[p.j], e);
    p.g *= p.weight;
  }
  for (int i = 0; i < nall; i++) {
    for (int k = 0; k < 6; k++) corr_kinv[i][k] = 0.0;
    for (int k = 0; k < 3; k++) corr_deficit[i][k] = corr_lambda[i][k] = 0.0;
  }
  for (const auto &p : support_pairs) {
    sphc_moment_add(corr_kinv[p.i], p.g, p.r);
    for (int k = 0; k < 3; k++) corr_deficit[p.i][k] += p.g * p.r[k];
    if (gather_j(p.j)) {
      sphc_moment_add(corr_kinv[p.j], p.g, p.r);
      for (int k = 0; k < 3; k++) corr_deficit[p.j][k] -= p.g * p.r[k];
    }
  }
  comm_stage = COMM_FIRST;
  if (newton) SPHCompat::reverse_comm(comm, this);
  const double none[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < nlocal; i++) {
    double inverse[6];
    if (corr_state[i] == 0.0 || sphc_sym_inverse(dim, corr_kinv[i], inverse) <= 0.0)
      for (int k = 0; k < 6; k++) inverse[k] = 0.0;    // lambda stays 0
    for (int k = 0; k < 6; k++) corr_kinv[i][k] = inverse[k];
    sphc_first_update(corr_kinv[i], none, corr_deficit[i], corr_lambda[i]);
  }

  // Jacobi sweeps: each with the neighbours' lambda of the sweep before
  for (int sweep = 1; sweep < sweeps; sweep++) {
    comm_stage = COMM_LAMBDA;
    SPHCompat::forward_comm(comm, this);
    for (int i = 0; i < nall; i++)
      for (int k = 0; k < 3; k++) corr_coupling[i][k] = 0.0;
    for (const auto &p : support_pairs) {
      const double *const lambda_i = corr_lambda[p.i];
      const double *const lambda_j = corr_lambda[p.j];
      const double along_j =
          p.g * (p.r[0] * lambda_j[0] + p.r[1] * lambda_j[1] + p.r[2] * lambda_j[2]);
      for (int k = 0; k < 3; k++) corr_coupling[p.i][k] += along_j * p.r[k];
      if (gather_j(p.j)) {
        const double along_i =
            p.g * (p.r[0] * lambda_i[0] + p.r[1] * lambda_i[1] + p.r[2] * lambda_i[2]);
        for (int k = 0; k < 3; k++) corr_coupling[p.j][k] += along_i * p.r[k];
      }
    }
    comm_stage = COMM_COUPLING;
    if (newton) SPHCompat::reverse_comm(comm, this);
    for (int i = 0; i < nlocal; i++)
      sphc_first_update(corr_kinv[i], corr_coupling[i], corr_deficit[i], corr_lambda[i]);
  }
  comm_stage = COMM_LAMBDA;
  SPHCompat::forward_comm(comm, this);
  for (auto &p : support_pairs)
    p.weight *= sphc_first_factor(corr_lambda[p.i], corr_lambda[p.j], p.r);
}

/* ----------------------------------------------------------------------
   'correction second': the multipliers nu of sph_second_moment.h for this
   step's pairs, and each pair's factor; the atoms of incomplete support
   (corr_state 0) keep nu = 0. The solve starts from the last solution
   while the atoms keep their indices (no neighbour-list build since; for
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

void PairSPHClearyHeat::solve_second()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const int n = sphs_count(dim);

  second_pairs.resize(support_pairs.size());
  for (size_t q = 0; q < support_pairs.size(); q++) {
    const SupportPair &from = support_pairs[q];
    sphs_pair &to = second_pairs[q];
    to.i = from.i;
    to.j = from.j;
    for (int c = 0; c < 3; c++) to.r[c] = from.r[c];
    to.g = from.g;
  }
  second_volume.resize(nlocal);
  second_constrained.resize(nlocal);
  for (int i = 0; i < nlocal; i++) {
    second_volume[i] = volume_of(i);
    second_constrained[i] = corr_state[i] != 0.0;
  }

  sphs_problem problem;
  problem.dim = dim;
  problem.nlocal = nlocal;
  problem.nall = nall;
  problem.newton = force->newton_pair;
  problem.npairs = (int) second_pairs.size();
  problem.pairs = second_pairs.data();
  problem.volume = second_volume.data();
  problem.constrained = second_constrained.data();
  problem.h = 1.0 / kernel.inv_h;
  problem.tolerance = SECOND_TOLERANCE;
  problem.regularization = SECOND_REGULARIZATION;
  problem.max_newton = SECOND_NEWTON_STEPS;
  problem.max_cg = SECOND_CG_STEPS;
  problem.exchange.context = this;
  problem.exchange.forward = second_forward;
  problem.exchange.reverse = second_reverse;
  problem.exchange.sum = second_sum;
  problem.exchange.max = second_max;
  problem.exchange.sum_array = second_sum_array;
  problem.x = atom->x[0];
  problem.coarse = SECOND_COARSE_SPACING;
  problem.max_coarse = SECOND_COARSE_SIZE;
  second_work.resize(sphs_work_size(&problem));
  const int warm = neighbor->ago > 0 && second_solved_at >= neighbor->lastcall &&
      second_nu.size() == (size_t) nall * n;
  if (!warm) second_nu.assign((size_t) nall * n, 0.0);
  second_result = sphs_solve(&problem, second_nu.data(), second_work.data());
  second_exact = -1;
  if (second_result.converged && second_result.moments > SECOND_TOLERANCE) {
    second_kept = second_nu;
    sphs_problem exact = problem;
    exact.regularization = 0.0;
    exact.max_newton = SECOND_EXACT_NEWTON_STEPS;
    sphs_result refined = sphs_solve(&exact, second_nu.data(), second_work.data());
    second_exact = refined.converged;
    if (refined.converged) {
      refined.newton_steps += second_result.newton_steps;
      refined.cg_steps += second_result.cg_steps;
      second_result = refined;
    } else
      second_nu = second_kept;    // ghosts included
  }
  second_solved_at = update->ntimestep;

  for (auto &p : support_pairs) {
    double f[SPHS_MAX];
    sphs_basis(dim, p.r, kernel.inv_h, f);
    p.weight = sphs_factor(dim, f, &second_nu[(size_t) p.i * n], &second_nu[(size_t) p.j * n]);
  }
  if (!second_result.converged && !second_warned && comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/cleary/heat: correction second: the multipliers reached a "
                   "residual of {:.3g} (of V / h^2) after {} Newton and {} conjugate-gradient "
                   "steps, not {:.3g}; the Laplacian is less accurate for quadratic fields",
                   second_result.residual, second_result.newton_steps, second_result.cg_steps,
                   SECOND_TOLERANCE);
  if (!second_result.converged) second_warned = 1;
}

// n values per atom of 'values': the owners' to their ghosts (forward) or
// the ghosts' added to their owners' (reverse)
void PairSPHClearyHeat::second_exchange(void *context, double *values, int n, bool reverse)
{
  auto self = static_cast<PairSPHClearyHeat *>(context);
  self->comm_stage = COMM_SECOND;
  self->comm_values = values;
  self->comm_count = n;
  if (reverse)
    SPHCompat::reverse_comm(self->comm, self);
  else
    SPHCompat::forward_comm(self->comm, self);
}

void PairSPHClearyHeat::second_forward(void *context, double *values, int n)
{
  second_exchange(context, values, n, false);
}

void PairSPHClearyHeat::second_reverse(void *context, double *values, int n)
{
  second_exchange(context, values, n, true);
}

double PairSPHClearyHeat::second_sum(void *context, double value)
{
  auto self = static_cast<PairSPHClearyHeat *>(context);
  double total = 0.0;
  MPI_Allreduce(&value, &total, 1, MPI_DOUBLE, MPI_SUM, self->world);
  return total;
}

void PairSPHClearyHeat::second_sum_array(void *context, double *values, int n)
{
  auto self = static_cast<PairSPHClearyHeat *>(context);
  MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, self->world);
}

double PairSPHClearyHeat::second_max(void *context, double value)
{
  auto self = static_cast<PairSPHClearyHeat *>(context);
  double largest = 0.0;
  MPI_Allreduce(&value, &largest, 1, MPI_DOUBLE, MPI_MAX, self->world);
  return largest;
}

/* ----------------------------------------------------------------------
   'mean interface': each atom with a neighbour of another material (a
   type of another conductivity law) estimates its distance from the
   interface, which sphc_interface_conductance() turns into the pair's
   series conductance:
   1. the normal: the gradient of the other material's colour, corrected
      with the inverse of the kernel's second moment, averaged (Shepard)
      over the atom and its neighbours of its own material;
   2. the plane halfway between the atom's own-material neighbour farthest
      along the normal (or the atom itself) and its other-material
      neighbour nearest along it (the widest gap between the materials);
   3. that plane averaged (Shepard) over the atom and its own-material
      neighbours that have one, each seen along the atom's normal.
   On a lattice cut by a plane this finds the plane exactly; on a rotated
   or disordered one it is within a fifth of a spacing, where the harmonic
   mean is off by up to half a spacing.
------------------------------------------------------------------------- */

void PairSPHClearyHeat::grow_interface()
{
  if (atom->nmax > nmax_interface) {
    nmax_interface = atom->nmax;
    memory->destroy(iface_distance);
    memory->destroy(iface_moment);
    memory->destroy(iface_vector);
    memory->destroy(iface_normal);
    memory->destroy(iface_sum);
    memory->destroy(iface_near);
    memory->create(iface_near, nmax_interface, "pair:iface_near");
    memory->create(iface_distance, nmax_interface, "pair:iface_distance");
    memory->create(iface_moment, nmax_interface, 6, "pair:iface_moment");
    memory->create(iface_vector, nmax_interface, 3, "pair:iface_vector");
    memory->create(iface_normal, nmax_interface, 3, "pair:iface_normal");
    memory->create(iface_sum, nmax_interface, 3, "pair:iface_sum");
  }
}

// no interface within the support
static constexpr double NO_INTERFACE = -1.0;

/* iface_near (owned and ghost): 1 for the atoms with an atom of another
   conductivity law within the support, the only ones whose distance is
   estimated and whose pairs the estimate reads */

void PairSPHClearyHeat::mark_interface_atoms()
{
  grow_interface();
  const double *const *const x = atom->x;
  const int *const type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  const double cutsq_kernel = cut_global * cut_global;
  for (int i = 0; i < nall; i++) iface_near[i] = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *const interface_i = interface_types[type[i]];
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!interface_i[type[j]]) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      if (delx * delx + dely * dely + delz * delz >= cutsq_kernel) continue;
      iface_near[i] = iface_near[j] = 1.0;
    }
  }
  comm_stage = COMM_IFACE_NEAR;
  if (force->newton_pair) SPHCompat::reverse_comm(comm, this);
  SPHCompat::forward_comm(comm, this);
}

template <int KERNEL> void PairSPHClearyHeat::update_interface()
{
  if (distance_index >= 0) {
    given_interface();
    return;
  }
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const int newton = force->newton_pair;
  const int *const type = atom->type;
  const double w_self = kernel.w_scale * sphk_f(KERNEL, 0.0);
  // a distance never below this: the pair's split stays finite
  const double closest = 1e-3 * kernel.h;
  auto gather_j = [&](int j) { return newton || j < nlocal; };
  auto crosses = [&](const SupportPair &p) { return interface_types[type[p.i]][type[p.j]]; };
  const double *const near = iface_near;
  using MathExtra::dot3;

  // 1. the kernel's second moments and the sum towards the other material
  for (int i = 0; i < nall; i++) {
    for (int k = 0; k < 6; k++) iface_moment[i][k] = 0.0;
    for (int k = 0; k < 3; k++) iface_vector[i][k] = 0.0;
  }
  for (const auto &p : support_pairs) {
    const double volume_i = volume_of(p.i), volume_j = volume_of(p.j);
    const double radial = -p.dwdr / p.distance;
    if (near[p.i] != 0.0) sphc_moment_add(iface_moment[p.i], volume_j * radial, p.r);
    if (near[p.j] != 0.0 && gather_j(p.j))
      sphc_moment_add(iface_moment[p.j], volume_i * radial, p.r);
    if (crosses(p)) {
      // V dW/dr e_ij points from i towards j
      for (int k = 0; k < 3; k++) iface_vector[p.i][k] -= volume_j * radial * p.r[k];
      if (gather_j(p.j))
        for (int k = 0; k < 3; k++) iface_vector[p.j][k] += volume_i * radial * p.r[k];
    }
  }
  comm_stage = COMM_IFACE_MOMENT;
  if (newton) SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++) {
    double inverse[6], toward[3];
    for (int k = 0; k < 3; k++) toward[k] = iface_vector[i][k];
    sphc_sym_inverse(dim, iface_moment[i], inverse);    // I when singular
    sphc_sym_apply(inverse, toward, iface_vector[i]);
  }
  comm_stage = COMM_IFACE_VECTOR;
  SPHCompat::forward_comm(comm, this);

  // 2. the normal: the corrected gradients averaged over the own material;
  // only the direction is kept, so the Shepard weights' sum is not needed,
  // and an atom that is not near has no gradient to add
  for (int i = 0; i < nall; i++) {
    const double self = (i < nlocal) ? w_self * volume_of(i) : 0.0;
    for (int k = 0; k < 3; k++) iface_sum[i][k] = self * iface_vector[i][k];
  }
  for (const auto &p : support_pairs) {
    if (crosses(p) || near[p.i] == 0.0 || near[p.j] == 0.0) continue;
    const double weight_j = p.w * volume_of(p.j);
    for (int k = 0; k < 3; k++) iface_sum[p.i][k] += weight_j * iface_vector[p.j][k];
    if (gather_j(p.j)) {
      const double weight_i = p.w * volume_of(p.i);
      for (int k = 0; k < 3; k++) iface_sum[p.j][k] += weight_i * iface_vector[p.i][k];
    }
  }
  comm_stage = COMM_IFACE_SMOOTH;
  if (newton) SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++) {
    const double length = sqrt(dot3(iface_sum[i], iface_sum[i]));
    for (int k = 0; k < 3; k++)
      iface_normal[i][k] = (length > 0.0) ? iface_sum[i][k] / length : 0.0;
  }
  comm_stage = COMM_IFACE_NORMAL;
  SPHCompat::forward_comm(comm, this);

  // 3. the widest gap along the normal: iface_sum holds the farthest own
  // (0: the atom itself) and the nearest other material
  for (int i = 0; i < nall; i++) {
    iface_sum[i][0] = 0.0;
    iface_sum[i][1] = HUGE_VAL;
  }
  for (const auto &p : support_pairs) {
    if (near[p.i] == 0.0 && near[p.j] == 0.0) continue;
    const double along_i = -dot3(iface_normal[p.i], p.r);    // n_i . (x_j - x_i)
    const double along_j = dot3(iface_normal[p.j], p.r);
    const int slot = crosses(p) ? 1 : 0;
    double *const gap_i = iface_sum[p.i];
    double *const gap_j = iface_sum[p.j];
    if (slot) {
      gap_i[1] = std::min(gap_i[1], along_i);
      if (gather_j(p.j)) gap_j[1] = std::min(gap_j[1], along_j);
    } else {
      gap_i[0] = std::max(gap_i[0], along_i);
      if (gather_j(p.j)) gap_j[0] = std::max(gap_j[0], along_j);
    }
  }
  comm_stage = COMM_IFACE_MARGIN;
  if (newton) SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++)
    iface_distance[i] = std::isfinite(iface_sum[i][1]) ? 0.5 * (iface_sum[i][0] + iface_sum[i][1])
                                                       : NO_INTERFACE;
  comm_stage = COMM_IFACE_DISTANCE;
  SPHCompat::forward_comm(comm, this);

  // 4. the plane averaged over the own material, seen along each atom's
  // normal (the atoms near an interface are those with a distance)
  for (int i = 0; i < nall; i++) {
    const double self = (i < nlocal && near[i] != 0.0) ? w_self * volume_of(i) : 0.0;
    iface_sum[i][0] = self * iface_distance[i];
    iface_sum[i][1] = self;
  }
  for (const auto &p : support_pairs) {
    if (crosses(p) || near[p.i] == 0.0 || near[p.j] == 0.0) continue;
    const double weight_j = p.w * volume_of(p.j);
    iface_sum[p.i][0] += weight_j * (iface_distance[p.j] - dot3(iface_normal[p.i], p.r));
    iface_sum[p.i][1] += weight_j;
    if (gather_j(p.j)) {
      const double weight_i = p.w * volume_of(p.i);
      iface_sum[p.j][0] += weight_i * (iface_distance[p.i] + dot3(iface_normal[p.j], p.r));
      iface_sum[p.j][1] += weight_i;
    }
  }
  comm_stage = COMM_IFACE_PLANE;
  if (newton) SPHCompat::reverse_comm(comm, this);
  for (int i = 0; i < nlocal; i++)
    if (near[i] != 0.0) iface_distance[i] = std::max(iface_sum[i][0] / iface_sum[i][1], closest);
  comm_stage = COMM_IFACE_DISTANCE;
  SPHCompat::forward_comm(comm, this);
}

/* 'distance d_name': each atom near an interface takes its distance from
   the per-atom property (the geometry's, e.g. from tools/sph_boundary.py
   or a variable), which must be positive and finite there */

void PairSPHClearyHeat::given_interface()
{
  const double *const given = atom->dvector[distance_index];
  const double *const near = iface_near;
  // the lowest ID of an atom with a bad distance, on every rank (error->all:
  // error->one's message can be lost with the abort)
  SPHCheck::FirstBad bad;
  for (int i = 0; i < atom->nlocal; i++) {
    if (near[i] == 0.0) {
      iface_distance[i] = NO_INTERFACE;
      continue;
    }
    if (!(given[i] > 0.0) || !std::isfinite(given[i])) bad.consider(atom->tag[i], given[i]);
    iface_distance[i] = given[i];
  }
  if (bad.agree(lmp))
    error->all(FLERR,
               "Pair style sph/cleary/heat: atom {} has an atom of another conductivity within "
               "the kernel support, but its distance {} from the interface is {} (must be > 0)",
               bad.tag, distance_name, bad.info[0]);
  comm_stage = COMM_IFACE_DISTANCE;
  SPHCompat::forward_comm(comm, this);
}

/* at a run's setup: how many atoms are near an interface, and how many
   keep the plain term */

void PairSPHClearyHeat::report_setup()
{
  if (mean == SPHC_INTERFACE) {
    bigint near = 0, near_all = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if (iface_distance[i] != NO_INTERFACE) near++;
    MPI_Allreduce(&near, &near_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (comm->me == 0)
      utils::logmesg(lmp,
                     "Pair style sph/cleary/heat: mean interface: {} atoms have an atom of "
                     "another conductivity within the kernel support\n",
                     near_all);
  }
  if (!correct) return;
  bigint plain = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (corr_state[i] == 0.0) plain++;
  bigint plain_all = 0;
  MPI_Allreduce(&plain, &plain_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: correction {} on {} of {} atoms; {} keep "
                   "the plain term (incomplete kernel support: free edges or too few neighbours)\n",
                   correct == CORRECT_SECOND ? "second" : "consistent", atom->natoms - plain_all,
                   atom->natoms, plain_all);
  if (correct != CORRECT_SECOND) return;
  bigint clipped = second_result.clipped, clipped_all = 0;
  MPI_Allreduce(&clipped, &clipped_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: correction second: moments to {:.2g} of V / h^2 "
                   "({}) in {} Newton and {} conjugate-gradient steps (coarse space of {}); {} "
                   "pairs at factor 0\n",
                   second_result.moments,
                   second_exact == 1 ? "unregularised problem solved"
                       : second_exact == 0
                       ? "regularised problem solved, unregularised one not converged"
                       : fmt::format("regularised problem to {:.2g}", second_result.residual),
                   second_result.newton_steps, second_result.cg_steps, second_result.coarse_size,
                   clipped_all);
}

/* the pairs of the neighbour list within the support, with their plain
   weight g = V_i V_j (-r dW/dr) / (r^2 + eta^2) */

double PairSPHClearyHeat::volume_of(int i) const
{
  const double mass_i = SPHParticles(atom).mass(i);
  return mass_i / atom->rho[i];
}

template <int KERNEL> void PairSPHClearyHeat::gather_support_pairs()
{
  const double *const *const x = atom->x;
  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dw_scale = kernel.dw_scale;
  const double w_scale = kernel.w_scale;

  // the positions and densities the pairs are made for (pairs_current())
  if (correct) grow_correction();
  if (mean == SPHC_INTERFACE) grow_interface();
  if (atom->nmax > nmax_pairs) {
    nmax_pairs = atom->nmax;
    memory->destroy(corr_x);
    memory->destroy(corr_rho);
    memory->create(corr_x, nmax_pairs, 3, "pair:corr_x");
    memory->create(corr_rho, nmax_pairs, "pair:corr_rho");
  }
  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < 3; k++) corr_x[i][k] = x[i][k];
    corr_rho[i] = atom->rho[i];
  }
  corr_valid = 1;

  // without the correction only the interface needs pairs: those of the
  // atoms near it
  const double *const near = correct ? nullptr : iface_near;
  support_pairs.clear();
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const double volume_i = volume_of(i);
    const int *const jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (near && near[i] == 0.0 && near[j] == 0.0) continue;
      SupportPair p;
      p.r[0] = x[i][0] - x[j][0];
      p.r[1] = x[i][1] - x[j][1];
      p.r[2] = x[i][2] - x[j][2];
      const double rsq = p.r[0] * p.r[0] + p.r[1] * p.r[1] + p.r[2] * p.r[2];
      if (rsq >= cutsq_kernel) continue;
      p.i = i;
      p.j = j;
      p.distance = sqrt(rsq);
      p.dwdr = dw_scale * sphk_df(KERNEL, p.distance * inv_h);
      p.w = w_scale * sphk_f(KERNEL, p.distance * inv_h);
      p.g = volume_i * volume_of(j) * sphc_brookshaw_weight(p.distance, p.dwdr, eta2);
      support_pairs.push_back(p);
    }
  }
}
