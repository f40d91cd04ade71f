/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: SPH heat conduction of Cleary 1998 (eq 6), with a
   harmonic-mean (or arithmetic-mean) conductivity from fix sph/materials.
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "math_extra.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "sph_consistent.h"
#include "sph_support.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// the layout of the restart settings: raise it when a setting is added
static constexpr int RESTART_VERSION = 2;

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::PairSPHClearyHeat(LAMMPS *lmp) :
    PairSPHKernel(lmp, "sph/cleary/heat", "conductivities come from fix sph/materials"),
    mean(SPHC_HARMONIC), loop_own(0), in_flow_loop(0), temperature(nullptr), mass_of(nullptr),
    nmax_flow_loop(0), eta2(0.0), materials(nullptr), conductivity_varies(0),
    conductance(nullptr), loop_conductance(nullptr), conductivity(nullptr), nmax(0),
    relax_wanted(0), relax_rate(nullptr), nmax_relax(0), correct(CORRECT_NONE), sweeps(5),
    nmax_correct(0), corr_s(nullptr), corr_kinv(nullptr), corr_lambda(nullptr),
    corr_deficit(nullptr), corr_coupling(nullptr), corr_state(nullptr), second_result(),
    second_exact(-1),
    second_warned(0), second_solved_at(-1), comm_values(nullptr), comm_count(0),
    comm_stage(COMM_RELAX), interface_types(nullptr), type_conductivity(nullptr), nmax_interface(0),
    iface_distance(nullptr), iface_moment(nullptr), iface_vector(nullptr), iface_normal(nullptr),
    iface_sum(nullptr), iface_near(nullptr), distance_index(-1), nmax_pairs(0), corr_x(nullptr),
    corr_rho(nullptr), corr_valid(0), refresh_pairs(0)
{
  // S and the state of the correction; the interface's estimate; nu of 'correction second'
  comm_forward = SPHS_MAX;
  // the moments of the correction and the interface; relax_rate (init_style()
  // makes room for the Hessian blocks of 'correction second')
  comm_reverse = COMM_REVERSE_MOMENTS;
}

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::~PairSPHClearyHeat()
{
  memory->destroy(conductance);
  memory->destroy(loop_conductance);
  memory->destroy(conductivity);
  memory->destroy(relax_rate);
  memory->destroy(temperature);
  memory->destroy(mass_of);
  memory->destroy(corr_s);
  memory->destroy(corr_kinv);
  memory->destroy(corr_lambda);
  memory->destroy(corr_deficit);
  memory->destroy(corr_coupling);
  memory->destroy(corr_state);
  memory->destroy(corr_x);
  memory->destroy(corr_rho);
  memory->destroy(interface_types);
  memory->destroy(type_conductivity);
  memory->destroy(iface_distance);
  memory->destroy(iface_moment);
  memory->destroy(iface_vector);
  memory->destroy(iface_normal);
  memory->destroy(iface_sum);
  memory->destroy(iface_near);
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  // pair sph/harmonic/visc evaluates the term (begin_flow_loop_term)
  if (in_flow_loop) return;
  begin_compute();
  eval_pairs(0, list->inum, atom->desph, relax_wanted ? relax_rate : nullptr);
  end_compute();
}

/* ----------------------------------------------------------------------
   before the pair loop: the per-atom state it reads, the correction's and
   the interface's factors when the particles have moved, relax_rate zeroed
------------------------------------------------------------------------- */

void PairSPHClearyHeat::begin_compute()
{
  SPHCheck::particles(lmp, FLERR, "Pair style sph/cleary/heat", SPHCheck::RHO | SPHCheck::ESPH);
  if (conductivity_varies) update_conductivity();
  if (update->setupflag) check_neighbours();
  update_temperature();
  refresh_pairs = (correct || mean == SPHC_INTERFACE) && !pairs_current();
  if (relax_wanted) zero_relax_rate();
  if (refresh_pairs) {
    switch (kernel_kind) {
      case SPHK_LUCY:
        update_pairs<SPHK_LUCY>();
        break;
      case SPHK_CUBIC:
        update_pairs<SPHK_CUBIC>();
        break;
      case SPHK_QUINTIC:
        update_pairs<SPHK_QUINTIC>();
        break;
      case SPHK_WENDLAND:
        update_pairs<SPHK_WENDLAND>();
        break;
    }
  }
}

/* ----------------------------------------------------------------------
   relax_rate of every owned and ghost atom zeroed, room for one copy per
   thread (the /omp styles)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::zero_relax_rate()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax * comm->nthreads > nmax_relax) {
    nmax_relax = atom->nmax * comm->nthreads;
    memory->destroy(relax_rate);
    memory->create(relax_rate, nmax_relax, "pair:relax_rate");
  }
  for (int i = 0; i < nall; i++) relax_rate[i] = 0.0;
}

/* ----------------------------------------------------------------------
   the pair loop over ilist[ifrom..ito), adding to desph (and relax_rate)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::eval_pairs(int ifrom, int ito, double *desph, double *relax)
{
  switch (kernel_kind) {
    case SPHK_LUCY:
      eval_kernel<SPHK_LUCY>(ifrom, ito, desph, relax);
      break;
    case SPHK_CUBIC:
      eval_kernel<SPHK_CUBIC>(ifrom, ito, desph, relax);
      break;
    case SPHK_QUINTIC:
      eval_kernel<SPHK_QUINTIC>(ifrom, ito, desph, relax);
      break;
    case SPHK_WENDLAND:
      eval_kernel<SPHK_WENDLAND>(ifrom, ito, desph, relax);
      break;
  }
}

/* ----------------------------------------------------------------------
   after the pair loop (the rates summed)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::end_compute()
{
  check_rates(atom->desph, "desph");
  if (refresh_pairs && update->setupflag) report_setup();
  if (!flows.empty()) tally_flows();
  if (relax_wanted) finish_relax();
}

/* ----------------------------------------------------------------------
   lambda_i of the ghosts to their owners, divided by cv
------------------------------------------------------------------------- */

void PairSPHClearyHeat::finish_relax()
{
  comm_stage = COMM_RELAX;
  if (force->newton_pair) SPHCompat::reverse_comm(comm, this);
  const double *const cv = atom->cv;
  for (int i = 0; i < atom->nlocal; i++) relax_rate[i] /= cv[i];
}

/* ----------------------------------------------------------------------
   the term in pair sph/harmonic/visc's loop: possible when that style is
   the only flow pair and this the only heat pair, both with one kernel and
   cutoff on the same type pairs (so on the same neighbour list), and the
   term needs only the pair: no correction, no interface distances, a mean
   of per-atom conductivities only when harmonic (per type pair otherwise)
------------------------------------------------------------------------- */

int PairSPHClearyHeat::flow_loop_possible()
{
  if (loop_own || correct || mean == SPHC_INTERFACE) return 0;
  if (conductivity_varies && mean != SPHC_HARMONIC) return 0;
  // (the /omp styles too, named as such in the hybrid)
  if (force->pair_match("^sph/cleary/heat", 0) != this) return 0;
  auto flow = (PairSPHKernel *) force->pair_match("^sph/harmonic/visc", 0);
  if (!flow || !same_kernel(flow)) return 0;
  // the flow's list holds every pair of this style's; on type pairs only
  // the flow covers, a zero conductance (per type pair) keeps the term out
  int same_pairs = 1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (setflag[i][j] && !flow->setflag[i][j]) return 0;
      if (setflag[i][j] != flow->setflag[i][j]) same_pairs = 0;
    }
  return same_pairs || !conductivity_varies;
}

/* ----------------------------------------------------------------------
   this step's temperature and mass of every owned and ghost atom (and
   conductivity, and zeroed relax_rate) for the flow pair's loop
------------------------------------------------------------------------- */

PairSPHClearyHeat::FlowLoopTerm PairSPHClearyHeat::begin_flow_loop_term()
{
  if (conductivity_varies) update_conductivity();
  if (update->setupflag) check_neighbours();
  update_temperature();
  if (relax_wanted) zero_relax_rate();
  // the heat style's mass of every atom (the flow's differs for solids)
  const int nall = atom->nlocal + atom->nghost;
  if (atom->rmass_flag && atom->rmass)
    memcpy(mass_of, atom->rmass, nall * sizeof(double));
  else
    for (int i = 0; i < nall; i++) mass_of[i] = atom->mass[atom->type[i]];
  FlowLoopTerm term;
  term.temperature = temperature;
  term.mass = mass_of;
  term.rho = atom->rho;
  term.conductivity = conductivity_varies ? conductivity : nullptr;
  term.conductance = loop_conductance;
  term.relax_rate = relax_wanted ? relax_rate : nullptr;
  term.eta2 = eta2;
  return term;
}

/* ----------------------------------------------------------------------
   T = esph / cv of every owned and ghost atom, once per step rather than
   once per pair (and room for the masses of the flow pair's loop)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::update_temperature()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > nmax_flow_loop) {
    nmax_flow_loop = atom->nmax;
    memory->destroy(temperature);
    memory->destroy(mass_of);
    memory->create(temperature, nmax_flow_loop, "pair:temperature");
    memory->create(mass_of, nmax_flow_loop, "pair:mass_of");
  }
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  for (int i = 0; i < nall; i++) temperature[i] = esph[i] / cv[i];
}

void PairSPHClearyHeat::end_flow_loop_term()
{
  check_rates(atom->desph, "desph");
  if (!flows.empty()) tally_flows();
  if (relax_wanted) finish_relax();
}

template <int KERNEL> void PairSPHClearyHeat::update_pairs()
{
  if (mean == SPHC_INTERFACE) mark_interface_atoms();
  gather_support_pairs<KERNEL>();
  if (correct) update_correction<KERNEL>();
  if (mean == SPHC_INTERFACE) update_interface<KERNEL>();
}

template <int KERNEL>
void PairSPHClearyHeat::eval_kernel(int ifrom, int ito, double *desph, double *relax)
{
  if (mean == SPHC_ARITHMETIC)
    eval_mean<KERNEL, SPHC_ARITHMETIC>(ifrom, ito, desph, relax);
  else if (mean == SPHC_INTERFACE)
    eval_mean<KERNEL, SPHC_INTERFACE>(ifrom, ito, desph, relax);
  else
    eval_mean<KERNEL, SPHC_HARMONIC>(ifrom, ito, desph, relax);
}

template <int KERNEL, int MEAN>
void PairSPHClearyHeat::eval_mean(int ifrom, int ito, double *desph, double *relax)
{
  if (correct)
    eval_flags<KERNEL, MEAN, 1>(ifrom, ito, desph, relax);
  else
    eval_flags<KERNEL, MEAN, 0>(ifrom, ito, desph, relax);
}

template <int KERNEL, int MEAN, int CORRECT>
void PairSPHClearyHeat::eval_flags(int ifrom, int ito, double *desph, double *relax)
{
  const int flags = (relax_wanted ? 8 : 0) | (conductivity_varies ? 4 : 0) |
      (force->newton_pair ? 2 : 0) | ((atom->rmass_flag && atom->rmass) ? 1 : 0);
  switch (flags) {
    case 0: eval<KERNEL, MEAN, CORRECT, 0, 0, 0, 0>(ifrom, ito, desph, relax); break;
    case 1: eval<KERNEL, MEAN, CORRECT, 0, 0, 1, 0>(ifrom, ito, desph, relax); break;
    case 2: eval<KERNEL, MEAN, CORRECT, 0, 1, 0, 0>(ifrom, ito, desph, relax); break;
    case 3: eval<KERNEL, MEAN, CORRECT, 0, 1, 1, 0>(ifrom, ito, desph, relax); break;
    case 4: eval<KERNEL, MEAN, CORRECT, 1, 0, 0, 0>(ifrom, ito, desph, relax); break;
    case 5: eval<KERNEL, MEAN, CORRECT, 1, 0, 1, 0>(ifrom, ito, desph, relax); break;
    case 6: eval<KERNEL, MEAN, CORRECT, 1, 1, 0, 0>(ifrom, ito, desph, relax); break;
    case 7: eval<KERNEL, MEAN, CORRECT, 1, 1, 1, 0>(ifrom, ito, desph, relax); break;
    case 8: eval<KERNEL, MEAN, CORRECT, 0, 0, 0, 1>(ifrom, ito, desph, relax); break;
    case 9: eval<KERNEL, MEAN, CORRECT, 0, 0, 1, 1>(ifrom, ito, desph, relax); break;
    case 10: eval<KERNEL, MEAN, CORRECT, 0, 1, 0, 1>(ifrom, ito, desph, relax); break;
    case 11: eval<KERNEL, MEAN, CORRECT, 0, 1, 1, 1>(ifrom, ito, desph, relax); break;
    case 12: eval<KERNEL, MEAN, CORRECT, 1, 0, 0, 1>(ifrom, ito, desph, relax); break;
    case 13: eval<KERNEL, MEAN, CORRECT, 1, 0, 1, 1>(ifrom, ito, desph, relax); break;
    case 14: eval<KERNEL, MEAN, CORRECT, 1, 1, 0, 1>(ifrom, ito, desph, relax); break;
    case 15: eval<KERNEL, MEAN, CORRECT, 1, 1, 1, 1>(ifrom, ito, desph, relax); break;
  }
}

/* ----------------------------------------------------------------------
   conductivity of every owned and ghost atom at its temperature
   (ghosts carry esph, cv and mask, so no communication is needed); a dummy
   of fix sph/wall/dirichlet takes the wall temperature, since its
   extrapolated one is no state of the material and can lie far outside the
   range of the law (k = exp(4 T) would choke the wall)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::update_conductivity()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(conductivity);
    memory->create(conductivity, nmax, "pair:conductivity");
  }
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) {
    double temperature = esph[i] / cv[i];
    for (const auto &wall : dummy_walls)
      if (mask[i] & wall.first) temperature = wall.second;
    conductivity[i] = materials->conductivity_at(type[i], temperature, "Pair style sph/cleary/heat");
  }
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

// the regularisation epsilon of sph_second_moment.h: measured on the
// two-material slab jittered by 0.2 spacings (examples/conduction-disorder,
// distances given), largest error at t1 / 10 t1 and run time (tolerance
// 1e-10): 1e-4 0.588 / 0.111 %, 2.5 s; 1e-5 0.577 / 0.085 %, 4.4 s; 1e-6
// 0.611 / 0.064 %, 7.2 s; unregularised 0.657 / 0.061 % (the numpy model,
// tools/disorder_second_order.py), a 108 s solve here; the lattice 0.444 /
// 0.046 %
static constexpr double SECOND_REGULARIZATION = 1e-6;
// The regularisation leaves the moments off by epsilon nu, and near free
// edges nu carries a large smooth part (on a lattice a first-moment
// multiplier of about 100, nearly constant through the interior, that
// changes no interior pair): a first-moment residual of 1e-4 of V / h,
// which errs the Laplacian by 2e-4 |grad T| / h. On a 54 x 54 lattice
// rotated by atan(1/2) with free edges (unittest/robust/test_second_rotated.py)
// the quadratic field's Laplacian was off by 1.1e-3 deep inside, where the
// plain term is off by 1.6e-4. So the regularised solution is the start of
// a second solve of the unregularised problem (the coarse space keeps its
// smooth part cheap to find: there 9 more Newton and 355 more
// conjugate-gradient steps, 16 and 606 in all, moments to 1e-14 and the
// Laplacian exact to 3e-13), which is taken if it converges within these
// Newton steps; otherwise (no weights with the exact moments, where the
// unregularised multipliers grow without bound) the regularised one stays
static constexpr int SECOND_EXACT_NEWTON_STEPS = 20;
// the solver's limits: residual of Phi's gradient relative to V / h^2, and
// step counts far above what converging cases take (15 Newton steps;
// conjugate gradients of the order of (width / h)^2 per step)
static constexpr double SECOND_TOLERANCE = 1e-13;
static constexpr int SECOND_NEWTON_STEPS = 50;
static constexpr int SECOND_CG_STEPS = 100000;
// the coarse space of the two-level preconditioner: grid spacing in h and
// the largest coarse dimension (a dense factor of that many rows). The
// slab of 80 x 20 jittered by 0.2 spacings, h = 1.3 spacings, CG steps
// with the coarse matrix made anew each Newton step (a loaded machine:
// the times compare only with each other): one level 20,348, 9.9 s; grid
// of 4 h 4,050, 9.9 s; 3 h 2,055, 5.5 s; 2 h 733, 3.7 s; 1.5 h 325, 4.5 s.
// Made once per solve, as now, 2 h takes 546 steps, 2.3 s on an idle core.
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
  tagint bad = MAXTAGINT;
  double bad_value = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (near[i] == 0.0) {
      iface_distance[i] = NO_INTERFACE;
      continue;
    }
    if ((!(given[i] > 0.0) || !std::isfinite(given[i])) && atom->tag[i] < bad) {
      bad = atom->tag[i];
      bad_value = given[i];
    }
    iface_distance[i] = given[i];
  }
  tagint bad_all = MAXTAGINT;
  MPI_Allreduce(&bad, &bad_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (bad_all != MAXTAGINT) {
    double value = (bad == bad_all) ? bad_value : 0.0, value_all = 0.0;
    MPI_Allreduce(&value, &value_all, 1, MPI_DOUBLE, MPI_SUM, world);
    error->all(FLERR,
               "Pair style sph/cleary/heat: atom {} has an atom of another conductivity within "
               "the kernel support, but its distance {} from the interface is {} (must be > 0)",
               bad_all, distance_name, value_all);
  }
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
  const double mass_i = (atom->rmass_flag && atom->rmass) ? atom->rmass[i] : atom->mass[atom->type[i]];
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

/* ----------------------------------------------------------------------
   de_i/dt += m_j F_ij and de_j/dt -= m_i F_ij for every pair within the
   kernel support (sph_conduction.h); T = esph / cv
------------------------------------------------------------------------- */

template <int KERNEL, int MEAN, int CORRECT, int VARYING_K, int NEWTON_PAIR, int RMASS,
          int RELAX>
void PairSPHClearyHeat::eval(int ifrom, int ito, double *desph, double *relax_rate)
{
  const double *const *const x = atom->x;
  const double *const temperature = this->temperature;
  const double *const rho = atom->rho;
  // the mass by type: one array fewer to stream than a per-atom copy
  const double *const mass = atom->mass;
  const double *const rmass = atom->rmass;
  const int *const type = atom->type;
  const int nlocal = atom->nlocal;

  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dw_scale = kernel.dw_scale;

  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;
  // the correction's pairs are stored in list order: only the whole list
  // (one thread) reads them
  size_t npair = 0;
  // the entries of each list inside the support (sph_support.h)
  SPHSupport support;

  for (int ii = ifrom; ii < ito; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double temp_i = temperature[i];
    const double rho_i = rho[i];
    const double mass_i = RMASS ? rmass[i] : mass[itype];
    const double k_i = VARYING_K ? conductivity[i] : 0.0;
    const double distance_i = (MEAN == SPHC_INTERFACE) ? iface_distance[i] : 0.0;
    const int *const interface_i = (MEAN == SPHC_INTERFACE) ? interface_types[itype] : nullptr;
    const double *const conductance_i = conductance[itype];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double desph_i = 0.0, relax_i = 0.0;

    // 3-D distances, as the loop always took them (z = 0 in 2-D)
    const int nin = support.gather<3, false>(x[i], x, jlist, jnum, cutsq_kernel);
    const int *const jin = support.index;
    const double *const rsq_in = support.rsq;
    double *const r_dwdr_in = support.a;
    for (int k = 0; k < nin; k++) {
      const double r = sqrt(rsq_in[k]);
      r_dwdr_in[k] = r * dw_scale * sphk_df(KERNEL, r * inv_h);
    }

    for (int k = 0; k < nin; k++) {
      const int j = jin[k];
      const double rsq = rsq_in[k];
      const int jtype = type[j];
      const double r_dwdr = r_dwdr_in[k];
      double conductance_ij =
          VARYING_K ? sphc_conductance(MEAN, k_i, conductivity[j]) : conductance_i[jtype];
      if (MEAN == SPHC_INTERFACE && interface_i[jtype])
        conductance_ij = VARYING_K
            ? sphc_interface_conductance(k_i, conductivity[j], distance_i, iface_distance[j])
            : sphc_interface_conductance(type_conductivity[itype], type_conductivity[jtype],
                                         distance_i, iface_distance[j]);
      const double temp_ij = temp_i - temperature[j];
      const double mass_j = RMASS ? rmass[j] : mass[jtype];
      // the pairs within the support come in the order update_correction() stored them
      const double weight = CORRECT ? support_pairs[npair++].weight : 1.0;
      // with RELAX, F_ij per unit temperature difference (<= 0, as dW/dr) is
      // needed too: one evaluation serves both
      const double inv_den = 1.0 / sphc_cleary_denominator(rho_i, rho[j], rsq, eta2);
      const double g_ij =
          RELAX ? weight * sphc_cleary_pair_inv(conductance_ij, 1.0, r_dwdr, inv_den) : 0.0;
      const double f_ij = RELAX
          ? g_ij * temp_ij
          : weight * sphc_cleary_pair_inv(conductance_ij, temp_ij, r_dwdr, inv_den);
      desph_i += mass_j * f_ij;
      if (NEWTON_PAIR || j < nlocal) desph[j] -= mass_i * f_ij;
      if (RELAX) {
        relax_i -= mass_j * g_ij;
        if (NEWTON_PAIR || j < nlocal) relax_rate[j] -= mass_i * g_ij;
      }
    }
    desph[i] += desph_i;
    if (RELAX) relax_rate[i] += relax_i;
  }
}

/* ----------------------------------------------------------------------
   the heat flows asked for: the pair terms of eval() between atoms of the
   two groups, with the energy each side receives (the j side only where
   eval() gives it to an atom of this rank), summed over the ranks
------------------------------------------------------------------------- */

int PairSPHClearyHeat::request_heat_flow(int to_groupbit, int from_groupbit)
{
  flows.push_back({to_groupbit, from_groupbit, 0.0});
  return (int) flows.size() - 1;
}

double PairSPHClearyHeat::pair_term(int i, int j, double rsq, double temp_ij) const
{
  const double r = sqrt(rsq);
  const double dwdr = kernel_dwdr(r);
  return pair_weight(i, j, r) *
      sphc_cleary_pair(pair_conductance(i, j), temp_ij, atom->rho[i], atom->rho[j], r, dwdr, eta2);
}

double PairSPHClearyHeat::pair_conductance(int i, int j) const
{
  const int *const type = atom->type;
  const double k_i = conductivity_varies ? conductivity[i] : type_conductivity[type[i]];
  const double k_j = conductivity_varies ? conductivity[j] : type_conductivity[type[j]];
  if (mean == SPHC_INTERFACE && interface_types[type[i]][type[j]])
    return sphc_interface_conductance(k_i, k_j, iface_distance[i], iface_distance[j]);
  return conductivity_varies ? sphc_conductance(mean, k_i, k_j) : conductance[type[i]][type[j]];
}

double PairSPHClearyHeat::pair_weight(int i, int j, double r) const
{
  if (!correct) return 1.0;
  const double *const *const x = atom->x;
  const double r_ij[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  if (correct == CORRECT_SECOND) {
    const int dim = domain->dimension;
    const int n = sphs_count(dim);
    double f[SPHS_MAX];
    sphs_basis(dim, r_ij, kernel.inv_h, f);
    return sphs_factor(dim, f, &second_nu[(size_t) i * n], &second_nu[(size_t) j * n]);
  }
  const double e_ij[3] = {r_ij[0] / r, r_ij[1] / r, r_ij[2] / r};
  return sphc_second_factor(corr_s[i], corr_s[j], e_ij) *
      sphc_first_factor(corr_lambda[i], corr_lambda[j], r_ij);
}

void PairSPHClearyHeat::tally_flows()
{
  const double *const *const x = atom->x;
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const double *const mass = atom->mass;
  const double *const rmass = (atom->rmass_flag && atom->rmass) ? atom->rmass : nullptr;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const double cutsq_kernel = cut_global * cut_global;
  int either = 0;
  for (const auto &flow : flows) either |= flow.to | flow.from;

  std::vector<double> local(flows.size(), 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & either)) continue;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & either)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq_kernel) continue;
      const double f_ij = pair_term(i, j, rsq, esph[i] / cv[i] - esph[j] / cv[j]);
      const double energy = (rmass ? rmass[i] : mass[type[i]]) *
          (rmass ? rmass[j] : mass[type[j]]) * f_ij;    // into i, out of j
      for (size_t k = 0; k < flows.size(); k++) {
        if ((mask[i] & flows[k].to) && (mask[j] & flows[k].from)) local[k] += energy;
        if ((mask[j] & flows[k].to) && (mask[i] & flows[k].from) && (newton || j < nlocal))
          local[k] -= energy;
      }
    }
  }
  std::vector<double> total(flows.size(), 0.0);
  MPI_Allreduce(local.data(), total.data(), (int) flows.size(), MPI_DOUBLE, MPI_SUM, world);
  for (size_t k = 0; k < flows.size(); k++) flows[k].power = total[k];
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::allocate()
{
  PairSPHKernel::allocate();
  const int n = atom->ntypes;
  memory->create(conductance, n + 1, n + 1, "pair:conductance");
  memory->create(loop_conductance, n + 1, n + 1, "pair:loop_conductance");
  memory->create(interface_types, n + 1, n + 1, "pair:interface_types");
  memory->create(type_conductivity, n + 1, "pair:type_conductivity");
  for (int i = 0; i <= n; i++) {
    type_conductivity[i] = 0.0;
    for (int j = 0; j <= n; j++) {
      conductance[i][j] = 0.0;
      interface_types[i][j] = 0;
    }
  }
}

/* ----------------------------------------------------------------------
   pair_style sph/cleary/heat kernel cutoff [mean harmonic|arithmetic|interface] [distance d_name] [eta f]
     [correction none|consistent|second] [sweeps n] [loop shared|own]
------------------------------------------------------------------------- */

void PairSPHClearyHeat::settings(int narg, char **arg)
{
  int iarg = parse_kernel(narg, arg);
  eta_factor = 0.1;
  mean = SPHC_HARMONIC;
  correct = CORRECT_NONE;
  sweeps = 5;
  distance_name.clear();
  loop_own = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eta") != 0 && strcmp(arg[iarg], "mean") != 0 &&
        strcmp(arg[iarg], "correction") != 0 && strcmp(arg[iarg], "sweeps") != 0 &&
        strcmp(arg[iarg], "loop") != 0 && strcmp(arg[iarg], "distance") != 0)
      error->all(FLERR,
                 "Illegal pair_style sph/cleary/heat command: unknown keyword '{}' (after the "
                 "kernel and cutoff: eta, mean, distance, correction, sweeps or loop)",
                 arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style sph/cleary/heat command: missing value after '{}'",
                 arg[iarg]);
    if (strcmp(arg[iarg], "eta") == 0) {
      eta_factor = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (eta_factor < 0.0)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: eta {} must be >= 0",
                   arg[iarg + 1]);
      // eta = f h in r^2 + eta^2: a pair at r = h conducts 1 / (1 + f^2) of its heat
      if (eta_factor > 1.0)
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: eta {} must be <= 1 (a fraction "
                   "of h: eta 1 already halves the conduction at r = h; Cleary's 0.1 is the "
                   "default)",
                   arg[iarg + 1]);
      if (eta_factor > 0.3 && comm->me == 0)
        error->warning(FLERR,
                       "Pair style sph/cleary/heat: eta {} lowers the conduction of a pair at "
                       "r = h by {:.0f} %, and the conductance of the particles by about as "
                       "much (eta is a fraction of h; the default 0.1 lowers it by 1 %)",
                       arg[iarg + 1], 100.0 * (1.0 - 1.0 / (1.0 + eta_factor * eta_factor)));
    } else if (strcmp(arg[iarg], "correction") == 0) {
      if (strcmp(arg[iarg + 1], "none") == 0)
        correct = CORRECT_NONE;
      else if (strcmp(arg[iarg + 1], "consistent") == 0)
        correct = CORRECT_CONSISTENT;
      else if (strcmp(arg[iarg + 1], "second") == 0)
        correct = CORRECT_SECOND;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown correction '{}' "
                   "(none, consistent or second)",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "loop") == 0) {
      if (strcmp(arg[iarg + 1], "shared") == 0)
        loop_own = 0;
      else if (strcmp(arg[iarg + 1], "own") == 0)
        loop_own = 1;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown loop '{}' (shared or own)",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "distance") == 0) {
      if (strncmp(arg[iarg + 1], "d_", 2) != 0 || !arg[iarg + 1][2])
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: distance '{}' is not a d_name "
                   "of fix property/atom",
                   arg[iarg + 1]);
      distance_name = arg[iarg + 1];
    } else if (strcmp(arg[iarg], "sweeps") == 0) {
      sweeps = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (sweeps < 1)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: sweeps {} must be >= 1",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "mean") == 0) {
      if (strcmp(arg[iarg + 1], "harmonic") == 0)
        mean = SPHC_HARMONIC;
      else if (strcmp(arg[iarg + 1], "arithmetic") == 0)
        mean = SPHC_ARITHMETIC;
      else if (strcmp(arg[iarg + 1], "interface") == 0)
        mean = SPHC_INTERFACE;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown mean '{}' "
                   "(harmonic, arithmetic or interface)",
                   arg[iarg + 1]);
    }
    iarg += 2;
  }
  if (!distance_name.empty() && mean != SPHC_INTERFACE)
    error->all(FLERR,
               "Illegal pair_style sph/cleary/heat command: distance {} needs mean interface",
               distance_name);
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::init_style()
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Pair style sph/cleary/heat requires atom style sph (esph, desph, cv, rho)");

  materials = FixSPHMaterials::find(lmp, "Pair style sph/cleary/heat");
  flows.clear();    // the fixes that want them ask again at their init
  for (int i = 1; i <= atom->ntypes; i++)
    if (!materials->conductivity(i))
      error->all(FLERR,
                 "Pair style sph/cleary/heat: atom type {} has no conductivity in fix "
                 "sph/materials",
                 i);
  conductivity_varies = !materials->conductivity_constant();
  // the type pairs that cross an interface: two conductivity laws
  for (int i = 1; i <= atom->ntypes; i++) {
    type_conductivity[i] = conductivity_varies ? 0.0 : materials->conductivity(i)->c[0];
    for (int j = 1; j <= atom->ntypes; j++)
      interface_types[i][j] =
          !sphm_law_same(materials->conductivity(i), materials->conductivity(j));
  }
  if (mean == SPHC_INTERFACE) grow_interface();
  distance_index = -1;
  if (!distance_name.empty()) {
    int flag = -1, cols = -1;
    distance_index = atom->find_custom(distance_name.c_str() + 2, flag, cols);
    if (distance_index < 0 || flag != 1 || cols != 0)
      error->all(FLERR,
                 "Pair style sph/cleary/heat: distance: no per-atom double '{}' (define it with "
                 "fix property/atom)",
                 distance_name);
  }
  int interfaces = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) interfaces |= interface_types[i][j];
  if (mean == SPHC_INTERFACE && !interfaces && comm->me == 0)
    error->warning(FLERR,
                   "Pair style sph/cleary/heat: mean interface has no effect: every atom type has "
                   "the same conductivity law in fix sph/materials");
  // the Hessian blocks of 'correction second' are the largest reverse
  // communication; Comm sizes its buffers after this (LAMMPS::init)
  comm_reverse = (correct == CORRECT_SECOND) ? SPHS_MAX * SPHS_MAX : COMM_REVERSE_MOMENTS;
  relax_wanted = 0;    // set again by the styles that want it, at their init
  corr_valid = 0;      // the correction's factors are made anew at the first step
  second_warned = 0;
  // the per-atom state exists from here on, for compute sph/correction/atom
  if (correct) grow_correction();
  SPHCheck::atom_state(lmp, FLERR, "Pair style sph/cleary/heat", 0,
                       SPHCheck::RHO | SPHCheck::CV | SPHCheck::ESPH);

  dummy_walls.clear();
  for (Fix *wall : SPHCompat::fixes_of_style(modify, "sph/wall/dirichlet")) {
    int dim;
    const double *t_wall = (const double *) wall->extract("t_wall", dim);
    dummy_walls.emplace_back(wall->groupbit, *t_wall);
  }

  eta2 = init_kernel();
  for (int i = 0; i <= atom->ntypes; i++)
    for (int j = 0; j <= atom->ntypes; j++) loop_conductance[i][j] = 0.0;
  const int was_in_flow_loop = in_flow_loop;
  in_flow_loop = flow_loop_possible();
  if (in_flow_loop && !was_in_flow_loop && comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: the term is evaluated in the pair loop of "
                   "sph/harmonic/visc (loop shared)\n");

  SPHCompat::request_half_list(neighbor, this, instance_me);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::init_one(int i, int j)
{
  // with constant conductivities the conductance is a property of the type
  // pair; the flow pair's loop sees it on this style's type pairs only (the
  // others keep the 0 of init_style)
  if (!conductivity_varies)
    conductance[i][j] = conductance[j][i] = loop_conductance[i][j] = loop_conductance[j][i] =
        sphc_conductance(mean, materials->conductivity(i)->c[0],
                         materials->conductivity(j)->c[0]);
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::write_restart_settings(FILE *fp)
{
  SPHCheck::write_restart_head(fp, RESTART_VERSION);
  fwrite(&kernel_kind, sizeof(int), 1, fp);
  fwrite(&mean, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&eta_factor, sizeof(double), 1, fp);
  fwrite(&correct, sizeof(int), 1, fp);
  fwrite(&sweeps, sizeof(int), 1, fp);
  fwrite(&loop_own, sizeof(int), 1, fp);
  const int length = (int) distance_name.size();
  fwrite(&length, sizeof(int), 1, fp);
  fwrite(distance_name.data(), sizeof(char), length, fp);
}

void PairSPHClearyHeat::read_restart_settings(FILE *fp)
{
  SPHCheck::read_restart_head(lmp, fp, "pair sph/cleary/heat", RESTART_VERSION);
  int length = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &kernel_kind, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mean, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &eta_factor, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &correct, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &sweeps, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &loop_own, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &length, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&length, 1, MPI_INT, 0, world);
  std::vector<char> name(length + 1, '\0');
  if (comm->me == 0) utils::sfread(FLERR, name.data(), sizeof(char), length, fp, nullptr, error);
  MPI_Bcast(name.data(), length, MPI_CHAR, 0, world);
  distance_name = name.data();
  MPI_Bcast(&kernel_kind, 1, MPI_INT, 0, world);
  MPI_Bcast(&mean, 1, MPI_INT, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&eta_factor, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&correct, 1, MPI_INT, 0, world);
  MPI_Bcast(&sweeps, 1, MPI_INT, 0, world);
  MPI_Bcast(&loop_own, 1, MPI_INT, 0, world);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::memory_usage()
{
  return Pair::memory_usage() +
      (double) (nmax + nmax_relax + 22 * nmax_correct + 16 * nmax_interface + 4 * nmax_pairs) *
      sizeof(double) +
      (double) support_pairs.capacity() * sizeof(SupportPair) +
      (double) (second_nu.capacity() + second_work.capacity() + second_volume.capacity()) *
      sizeof(double) +
      (double) second_constrained.capacity() * sizeof(int) +
      (double) second_pairs.capacity() * sizeof(sphs_pair);
}

/* ----------------------------------------------------------------------
   relax_rate: per-atom array (owned atoms valid after compute()), filled
   from the next compute() on once relax_rate_wanted is set to 1
------------------------------------------------------------------------- */

void *PairSPHClearyHeat::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "relax_rate_wanted") == 0) return (void *) &relax_wanted;
  if (strcmp(name, "relax_rate") == 0) {
    dim = 1;
    return (void *) &relax_rate;
  }
  // whether 'correction consistent' is on
  if (strcmp(name, "correction") == 0) return (void *) &correct;
  // per atom, from init on with the correction (filled by compute()): 1 where
  // it corrects the atom's pair terms, 0 where the atom keeps the plain term
  // (incomplete support)
  if (strcmp(name, "correction_state") == 0) {
    dim = 1;
    return (void *) &corr_state;
  }
  // the mean (enum sphc_mean of sph_conduction.h); per atom, from init on
  // with 'mean interface' (filled by compute()): the distance from the
  // interface, -1 where no atom of another material is within the support
  if (strcmp(name, "mean") == 0) return (void *) &mean;
  if (strcmp(name, "interface_distance") == 0) {
    dim = 1;
    return (void *) &iface_distance;
  }
  return PairSPHKernel::extract(name, dim);
}

int PairSPHClearyHeat::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                         int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = send[k];
    if (comm_stage == COMM_STATE) {
      for (int c = 0; c < 6; c++) buf[m++] = corr_s[i][c];
      buf[m++] = corr_state[i];
    } else if (comm_stage == COMM_IFACE_VECTOR) {
      for (int c = 0; c < 3; c++) buf[m++] = iface_vector[i][c];
    } else if (comm_stage == COMM_IFACE_NORMAL) {
      for (int c = 0; c < 3; c++) buf[m++] = iface_normal[i][c];
    } else if (comm_stage == COMM_IFACE_DISTANCE) {
      buf[m++] = iface_distance[i];
    } else if (comm_stage == COMM_IFACE_NEAR) {
      buf[m++] = iface_near[i];
    } else if (comm_stage == COMM_SECOND) {
      for (int c = 0; c < comm_count; c++) buf[m++] = comm_values[(size_t) i * comm_count + c];
    } else {    // COMM_LAMBDA
      for (int c = 0; c < 3; c++) buf[m++] = corr_lambda[i][c];
    }
  }
  return m;
}

void PairSPHClearyHeat::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_stage == COMM_STATE) {
      for (int c = 0; c < 6; c++) corr_s[i][c] = buf[m++];
      corr_state[i] = buf[m++];
    } else if (comm_stage == COMM_IFACE_VECTOR) {
      for (int c = 0; c < 3; c++) iface_vector[i][c] = buf[m++];
    } else if (comm_stage == COMM_IFACE_NORMAL) {
      for (int c = 0; c < 3; c++) iface_normal[i][c] = buf[m++];
    } else if (comm_stage == COMM_IFACE_DISTANCE) {
      iface_distance[i] = buf[m++];
    } else if (comm_stage == COMM_IFACE_NEAR) {
      iface_near[i] = buf[m++];
    } else if (comm_stage == COMM_SECOND) {
      for (int c = 0; c < comm_count; c++) comm_values[(size_t) i * comm_count + c] = buf[m++];
    } else {
      for (int c = 0; c < 3; c++) corr_lambda[i][c] = buf[m++];
    }
  }
}

int PairSPHClearyHeat::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_stage == COMM_RELAX) {
      buf[m++] = relax_rate[i];
    } else if (comm_stage == COMM_MOMENT) {
      for (int c = 0; c < 6; c++) buf[m++] = corr_s[i][c];
    } else if (comm_stage == COMM_FIRST) {
      for (int c = 0; c < 6; c++) buf[m++] = corr_kinv[i][c];
      for (int c = 0; c < 3; c++) buf[m++] = corr_deficit[i][c];
    } else if (comm_stage == COMM_IFACE_MOMENT) {
      for (int c = 0; c < 6; c++) buf[m++] = iface_moment[i][c];
      for (int c = 0; c < 3; c++) buf[m++] = iface_vector[i][c];
    } else if (comm_stage == COMM_IFACE_SMOOTH) {
      for (int c = 0; c < 3; c++) buf[m++] = iface_sum[i][c];
    } else if (comm_stage == COMM_IFACE_MARGIN || comm_stage == COMM_IFACE_PLANE) {
      for (int c = 0; c < 2; c++) buf[m++] = iface_sum[i][c];
    } else if (comm_stage == COMM_IFACE_NEAR) {
      buf[m++] = iface_near[i];
    } else if (comm_stage == COMM_SECOND) {
      for (int c = 0; c < comm_count; c++) buf[m++] = comm_values[(size_t) i * comm_count + c];
    } else {    // COMM_COUPLING
      for (int c = 0; c < 3; c++) buf[m++] = corr_coupling[i][c];
    }
  }
  return m;
}

void PairSPHClearyHeat::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int i = list[k];
    if (comm_stage == COMM_RELAX) {
      relax_rate[i] += buf[m++];
    } else if (comm_stage == COMM_MOMENT) {
      for (int c = 0; c < 6; c++) corr_s[i][c] += buf[m++];
    } else if (comm_stage == COMM_FIRST) {
      for (int c = 0; c < 6; c++) corr_kinv[i][c] += buf[m++];
      for (int c = 0; c < 3; c++) corr_deficit[i][c] += buf[m++];
    } else if (comm_stage == COMM_IFACE_MOMENT) {
      for (int c = 0; c < 6; c++) iface_moment[i][c] += buf[m++];
      for (int c = 0; c < 3; c++) iface_vector[i][c] += buf[m++];
    } else if (comm_stage == COMM_IFACE_SMOOTH) {
      for (int c = 0; c < 3; c++) iface_sum[i][c] += buf[m++];
    } else if (comm_stage == COMM_IFACE_MARGIN) {
      // the farthest own-material atom and the nearest other one
      iface_sum[i][0] = std::max(iface_sum[i][0], buf[m++]);
      iface_sum[i][1] = std::min(iface_sum[i][1], buf[m++]);
    } else if (comm_stage == COMM_IFACE_PLANE) {
      for (int c = 0; c < 2; c++) iface_sum[i][c] += buf[m++];
    } else if (comm_stage == COMM_IFACE_NEAR) {
      iface_near[i] = std::max(iface_near[i], buf[m++]);
    } else if (comm_stage == COMM_SECOND) {
      for (int c = 0; c < comm_count; c++) comm_values[(size_t) i * comm_count + c] += buf[m++];
    } else {
      for (int c = 0; c < 3; c++) corr_coupling[i][c] += buf[m++];
    }
  }
}

/* ----------------------------------------------------------------------
   beyond the state every SPH pair reads: the conductivity of atom i
------------------------------------------------------------------------- */

std::string PairSPHClearyHeat::diagnose(int i)
{
  std::string why = PairSPHKernel::diagnose(i);
  if (why.empty() && conductivity_varies && !std::isfinite(conductivity[i]))
    why = fmt::format("its conductivity is {}", conductivity[i]);
  return why;
}
