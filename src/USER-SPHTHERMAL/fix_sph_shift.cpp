/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/shift: particle shifting (sph_shift.h). At the end of each step,
   with the positions of that step, either
     dr_i = -D h |v_i| dt sum_j V_j grad_i W_ij    (Reece et al. 2024, eq 38)
   or the delta-plus form (Sun et al. 2017; Ng et al. 2020, eqs 19-20)
     dr_i = -C (U dt / h) (2h)^2 sum_j [1 + R (W_ij / W(dx_i))^n] grad_i W_ij V_j
   with V_j = 2 m_j / (rho_i + rho_j) for a neighbour of the group (the
   fluid) and V_j = dx_i^d for any other (walls, solids), over every
   neighbour j (walls too, so that particles keep off them; each pair once,
   from a half list, or for the skillen sum alone from the flow pair's own
   loop, 'loop shared'), shortened to
   at most cap * dx_i (dx_i = V_i^(1/d)); then x_i += dr_i for the atoms of
   the group. With 'correct yes' the temperature follows (with 'correct
   all' the density and the velocity too, the same way):
     T_i += dr_i . grad T_i
   with the first-order corrected gradient (sph_gradient.h), exact for a
   linear field; the energy that adds is tallied. With 'continuity yes'
   the group's mean density follows the change the shift
   makes to the kernel sums of mass, as the continuity equation would for
   the displacement: to first order their total change is
     sum_i rho_i sum_j V_j (dr_i - dr_j) . grad_i W_ij
       = sum_i rho_i dr_i . sum_j s_j V_j grad_i W_ij
   (s_j = 2 for a neighbour in the group, which moves too; 1 for walls and
   solids, which do not), and every density of the group is scaled by the
   same factor (after each has followed its atom when correcting all), so
   that their sum changes by that total. Without it the mean density drifts
   wherever the flow shears the particles: the flow crowds them (the
   continuity equation sees it) and the shift spreads them again unseen
   (-0.9 % in 300 s in the channel at Re = 652, +0.08 % in 100 s at
   Re = 133), until the pressure leaves its background. Applied per
   particle, either form of the change fed back into the flow: the pairwise
   one raised |v| tenfold, the particle's own share broke the flow up. Even
   the common factor made the channels less stable than the drift does, so
   it is not the default.
------------------------------------------------------------------------- */

#include "fix_sph_shift.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_open.h"
#include "fix_sph_wall_adami.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_checks.h"
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_gradient.h"
#include "sph_hub.h"
#include "sph_kernels.h"
#include "sph_particle.h"
#include "sph_shift.h"
#include "sph_support.h"
#include "sph_threads.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the layout of the restart state: raise it when a value is added
// (1: the energy; 2: the energy, the group's name)
static constexpr int RESTART_VERSION = 2;

static const char cmd[] = "fix sph/shift";

// the spacing of a particle of this volume (sqrt and cbrt are cheaper than pow)
static inline double spacing_of(double volume, int dim)
{
  return dim == 2 ? sqrt(volume) : cbrt(volume);
}

/* ---------------------------------------------------------------------- */

// the form without one in the command: Reece et al. 2024's D (Table 2; their
// -2 with the sign of DualSPHysics), validated in the cavities and the tanks
static constexpr double DEFAULT_SKILLEN = 2.0;

FixSPHShift::FixSPHShift(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), form(SKILLEN), coefficient(0.0), speed(0.0), r_coeff(0.2), r_power(4),
    cap(0.1), correct(0), continuity(0), continuity_given(0), kernel_kind(0), cutoff(0.0),
    loop_own(0), from_pair(0), flow(nullptr), list(nullptr), energy(0.0), largest(0.0), capped(0),
    moved(0), warned_cap(0), sums_per_atom(3), who(fmt::format("Fix sph/shift {}", id))
{
  // without a form (nothing, or a keyword next), Reece et al.'s skillen D = 2
  const bool form_given = (narg > 3) && strcmp(arg[3], "cap") && strcmp(arg[3], "correct") &&
      strcmp(arg[3], "continuity") && strcmp(arg[3], "loop");
  int iarg = 3;
  if (!form_given) {
    coefficient = DEFAULT_SKILLEN;
    if (comm->me == 0)
      utils::logmesg(lmp, "{}: skillen {:g} (the default form: Reece et al. 2024, Table 2)\n", who,
                     coefficient);
  } else {
    if (strcmp(arg[3], "skillen") == 0)
      form = SKILLEN;
    else if (strcmp(arg[3], "delta-plus") == 0)
      form = DELTAPLUS;
    else
      error->all(FLERR,
                 "Illegal {} command: unknown form '{}' (known: skillen, delta-plus; without a "
                 "form, skillen {:g})",
                 cmd, arg[3], DEFAULT_SKILLEN);
    if (narg < 5) error->all(FLERR, "Illegal {} command: {} expects its coefficient", cmd, arg[3]);
    coefficient = utils::numeric(FLERR, arg[4], false, lmp);
    if (!(coefficient > 0.0) || !std::isfinite(coefficient))
      error->all(FLERR,
                 "Illegal {} command: coefficient {} must be > 0 (particles move away from where "
                 "they crowd; Reece et al.'s D = -2 is 2 here)",
                 cmd, arg[4]);
    iarg = 5;
  }
  if (form == DELTAPLUS) {
    if (narg < 6)
      error->all(FLERR,
                 "Illegal {} command: delta-plus expects <C> <U> (U: the flow's largest speed)",
                 cmd);
    speed = utils::numeric(FLERR, arg[5], false, lmp);
    if (!(speed > 0.0) || !std::isfinite(speed))
      error->all(FLERR, "Illegal {} command: delta-plus speed U {} must be > 0", cmd, arg[5]);
    iarg = 6;
  }
  while (iarg < narg) {
    if (form == DELTAPLUS && strcmp(arg[iarg], "R") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: missing value after 'R'", cmd);
      r_coeff = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      // R weighs a correction: at R = 1 the anti-pairing term already
      // doubles a pair's weight at one spacing (and grows as (W_ij/W(dx))^n
      // closer in); a larger R is not the delta-plus shift any more
      if (!(r_coeff >= 0.0) || !(r_coeff <= 1.0))
        error->all(FLERR,
                   "Illegal {} command: R {} must be 0 to 1 (the weight of the anti-pairing "
                   "term; Sun et al. 2017 use 0.2)",
                   cmd, arg[iarg + 1]);
      iarg += 2;
    } else if (form == DELTAPLUS && strcmp(arg[iarg], "n") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: missing value after 'n'", cmd);
      r_power = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (r_power < 1 || r_power > 16)
        error->all(FLERR, "Illegal {} command: n {} must be 1 to 16", cmd, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "cap") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: missing value after 'cap'", cmd);
      cap = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (!(cap > 0.0) || !(cap <= 0.5))
        error->all(FLERR, "Illegal {} command: cap {} must be > 0 and <= 0.5 (of the spacing)", cmd,
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "correct") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'correct'", cmd);
      // all: T, rho and v; yes: T only
      if (strcmp(arg[iarg + 1], "all") == 0)
        correct = CORRECT_ALL;
      else
        correct = SPHCompat::yes_no(error, FLERR, cmd, "correct", arg[iarg + 1]) ? CORRECT_T : 0;
      iarg += 2;
    } else if (strcmp(arg[iarg], "loop") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'loop'", cmd);
      if (strcmp(arg[iarg + 1], "shared") == 0)
        loop_own = 0;
      else if (strcmp(arg[iarg + 1], "own") == 0)
        loop_own = 1;
      else
        error->all(FLERR, "Illegal {} command: unknown loop '{}' (shared or own)", cmd,
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "continuity") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'continuity'", cmd);
      continuity = SPHCompat::yes_no(error, FLERR, cmd, "continuity", arg[iarg + 1]);
      continuity_given = 1;
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }
  if (!atom->rho_flag || (correct && (!atom->esph_flag || !atom->cv_flag)))
    error->all(FLERR, "Fix sph/shift requires atom style sph (rho{})", correct ? ", esph, cv" : "");
  scalar_flag = 1;
  extscalar = 1;
  vector_flag = 1;
  size_vector = 3;
  extvector = 0;
  global_freq = 1;
  nevery = 1;
  restart_global = 1;
  comm_forward = (correct == CORRECT_ALL) ? 5 : correct ? 2 : 1;
  size_sums();
}

// the neighbour sums of shift_group(), which the reverse communication carries
void FixSPHShift::size_sums()
{
  sums_per_atom = 3 + 3 * continuity + (correct ? 12 : 0) + (correct == CORRECT_ALL ? 21 : 0);
  comm_reverse = sums_per_atom;
}

/* ----------------------------------------------------------------------
   without 'continuity' in the command: yes for the fluid of an open
   boundary (fix sph/open), no otherwise. Between an inlet and an outlet
   the shift spreads the particles that the flow crowds, unseen by the
   density that the outlet holds, so the fluid lost particles and sped up
   (the heated channel at 10 across: 2.2 % of its particles in two
   flow-through times, the flow rate 2 % high; 0.7 % with it)
------------------------------------------------------------------------- */

void FixSPHShift::choose_continuity()
{
  if (continuity_given) return;
  int feeds_open = 0;
  for (int k = 0; k < modify->nfix; k++) {
    auto *open = dynamic_cast<FixSPHOpen *>(modify->fix[k]);
    if (open && SPHCheck::groups_overlap(lmp, groupbit, open->fluid_groupbit())) feeds_open = 1;
  }
  if (feeds_open != continuity && comm->me == 0)
    utils::logmesg(lmp, "{}: continuity {} (the default {} an open boundary's fluid)\n", who,
                   feeds_open ? "yes" : "no", feeds_open ? "for" : "without");
  continuity = feeds_open;
  size_sums();
}

int FixSPHShift::setmask()
{
  return END_OF_STEP;
}

/* ---------------------------------------------------------------------- */

void FixSPHShift::init()
{
  // the kernel of the flow
  flow = SPHHub(lmp).require_flow("Fix sph/shift");
  kernel_kind = flow->kernel_settings().kind;
  cutoff = flow->kernel_settings().cutoff;
  SPHCheck::atom_state(lmp, FLERR, cmd, 0, SPHCheck::RHO | (correct ? SPHCheck::CV : 0));
  check_group();
  choose_continuity();
  warned_cap = 0;
  const int was_from_pair = from_pair;
  // the pair loop makes the skillen sum alone, when it sees every pair of the group
  from_pair =
      !loop_own && form == SKILLEN && !correct && !continuity && flow->provide_shift_sums(groupbit);
  if (from_pair && !was_from_pair && comm->me == 0)
    utils::logmesg(lmp,
                   "Fix sph/shift: the sums are made in the pair loop of sph/harmonic/visc (loop "
                   "shared)\n");
  if (!from_pair) SPHCompat::request_half_list(neighbor, this, instance_me);
}

/* ----------------------------------------------------------------------
   the group at each run (it can change between definition and run): not
   empty, no wall particle of fix sph/wall/adami (shifting would move it
   out of its wall), no atom of another fix sph/shift (shifted twice)
------------------------------------------------------------------------- */

void FixSPHShift::check_group()
{
  const char *name = group->names[igroup];
  if (SPHCheck::group_count(lmp, groupbit) == 0)
    error->all(FLERR, "{}: group {} has no atoms; give the fluid's group", who, name);
  for (int k = 0; k < modify->nfix; k++) {
    Fix *other = modify->fix[k];
    if (other == this) continue;
    const bool adami = dynamic_cast<FixSPHWallAdami *>(other) != nullptr;
    const bool shift = dynamic_cast<FixSPHShift *>(other) != nullptr;
    if (!adami && !shift) continue;
    if (!SPHCheck::groups_overlap(lmp, groupbit, other->groupbit)) continue;
    if (adami)
      error->all(FLERR,
                 "{} and fix sph/wall/adami {} share atoms of groups {} and {}: the wall's "
                 "particles would be shifted out of the wall; leave them out of the shift's group",
                 who, other->id, name, group->names[other->igroup]);
    error->all(FLERR,
               "{} and fix sph/shift {} share atoms of groups {} and {}: they would be shifted "
               "twice in a step; give each fix its own atoms",
               who, other->id, name, group->names[other->igroup]);
  }
}

void FixSPHShift::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

void FixSPHShift::end_of_step()
{
  // the ghosts' rho (esph, v when correcting) as the step ended on their
  // owners' ranks; the pair loop's sums need none
  if (!from_pair) SPHCompat::forward_comm(comm, this);
  if (from_pair)
    shift_from_pair_sums();
  else
    form == DELTAPLUS ? shift_corrected<DELTAPLUS>() : shift_corrected<SKILLEN>();
  check_capped();
}

/* ----------------------------------------------------------------------
   a warning (once per run) when the cap shortened more than half of the
   group's shifts in this step: the shift is then the cap's, not the form's
------------------------------------------------------------------------- */

void FixSPHShift::check_capped()
{
  if (warned_cap) return;
  int counts[2] = {capped, moved}, all[2];
  MPI_Allreduce(counts, all, 2, MPI_INT, MPI_SUM, world);
  if (2 * (bigint) all[0] <= all[1]) return;
  warned_cap = 1;
  if (comm->me == 0)
    error->warning(FLERR,
                   "{}: the cap ({} of the spacing) shortened the shifts of {} of the {} atoms "
                   "of group {} at step {}: the coefficient {} {} {}is too large for this flow, "
                   "and the shifts are the cap's whatever it is; lower it (warned once per run)",
                   who, cap, all[0], all[1], group->names[igroup], update->ntimestep,
                   form == DELTAPLUS ? "C" : "D", coefficient,
                   form == DELTAPLUS ? fmt::format("(with U {}) ", speed) : "");
}

/* ----------------------------------------------------------------------
   the skillen form from the sums of the flow pair's loop of this step
------------------------------------------------------------------------- */

void FixSPHShift::shift_from_pair_sums()
{
  const SPHParticles particles(atom);
  double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int dim = domain->dimension;
  const double h = cutoff / sphk_support(kernel_kind);
  const double *const sums_of = flow->shift_sums();
  double largest_local = 0.0;
  int capped_local = 0, moved_local = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    moved_local++;
    double dr[3];
    displacement(i, &sums_of[3 * (size_t) i], spacing_of(particles.volume(i), dim), h, dim, dr,
                 largest_local, capped_local);
    for (int a = 0; a < 3; a++) x[i][a] += dr[a];
  }
  largest = largest_local;
  capped = capped_local;
  moved = moved_local;
}

/* ----------------------------------------------------------------------
   atom i's shift dr from its neighbour sum (of its form), shortened to the
   cap (along the sum even where the coefficient is so large that the
   shift's length overflows); the largest shift / spacing and the count of
   capped atoms follow. A shift that is not finite stops the run.
------------------------------------------------------------------------- */

void FixSPHShift::displacement(int i, const double *sum, double spacing, double h, int dim,
                               double *dr, double &largest_local, int &capped_local)
{
  const double *const v = atom->v[i];
  const double factor = form == DELTAPLUS
      ? sphs_deltaplus_factor(coefficient, h, speed, update->dt)
      : sphs_skillen_factor(coefficient, h, sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]),
                            update->dt);
  const double along[3] = {sum[0], sum[1], dim == 2 ? 0.0 : sum[2]};
  capped_local += sphs_cap_along(factor, along, cap * spacing, dr);
  if (!std::isfinite(dr[0] + dr[1] + dr[2])) stop_nonfinite(i, along, factor, spacing, dr);
  largest_local = MAX(largest_local, sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]) / spacing);
}

/* ----------------------------------------------------------------------
   the shift of atom i is not finite: stop (on this rank) naming the atom,
   the step and what made it so
------------------------------------------------------------------------- */

void FixSPHShift::stop_nonfinite(int i, const double *sum, double factor, double spacing,
                                 const double *dr)
{
  const char *coeff = form == DELTAPLUS ? "C" : "D";
  std::string why;
  if (!std::isfinite(sum[0] + sum[1] + sum[2])) {
    why = fmt::format("its sum over the neighbours is ({}, {}, {})", sum[0], sum[1], sum[2]);
    if (!(atom->rho[i] > 0.0) || !std::isfinite(atom->rho[i]))
      why += fmt::format(": its rho {} is not a density (it must be finite and > 0)", atom->rho[i]);
    else if (form == DELTAPLUS && i < (int) w_spacing.size() && !(w_spacing[i] > 0.0))
      why += fmt::format(
          ": W(dx) of the anti-pairing term (R {}, n {}) is 0 at its spacing (m/rho)^(1/d) = {}, "
          "beyond the kernel's support {} (its rho {} is too low for the kernel)",
          r_coeff, r_power, spacing, cutoff, atom->rho[i]);
    else
      why += fmt::format(
          " (a neighbour's volume m/rho or position is not finite{})",
          form == DELTAPLUS ? fmt::format(", or R {} n {} overflow", r_coeff, r_power) : "");
  } else
    why = fmt::format("the factor of its shift, {} = {}, is not finite: the coefficient {} {}{} "
                      "is too large; lower it",
                      form == DELTAPLUS ? "-C (U dt / h) (2h)^2" : "-D h |v| dt", factor, coeff,
                      coefficient, form == DELTAPLUS ? fmt::format(" (with U {})", speed) : "");
  SPHCheck::nonfinite(lmp, FLERR, who.c_str(), "shift", i,
                      sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]), why);
}

template <int FORM> void FixSPHShift::shift_corrected()
{
  if (correct == CORRECT_ALL)
    shift_continuity<FORM, CORRECT_ALL>();
  else if (correct == CORRECT_T)
    shift_continuity<FORM, CORRECT_T>();
  else
    shift_continuity<FORM, 0>();
}

template <int FORM, int CORRECT> void FixSPHShift::shift_continuity()
{
  continuity ? shift_group<FORM, CORRECT, 1>() : shift_group<FORM, CORRECT, 0>();
}

/* ----------------------------------------------------------------------
   FORM: SKILLEN or DELTAPLUS; CORRECT: 0, CORRECT_T (move T with the
   atoms, from the corrected gradient's sums) or CORRECT_ALL (T, rho, v);
   CONTINUITY: scale the group's densities by the shift's change of the
   kernel sums (after moving them with the atoms when CORRECT_ALL)
------------------------------------------------------------------------- */

template <int FORM, int CORRECT, int CONTINUITY> void FixSPHShift::shift_group()
{
  const SPHParticles particles(atom);
  double *const *const x = atom->x;
  double *const *const v = atom->v;
  double *const rho = atom->rho;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const int dim = domain->dimension;
  const sphk_kernel kernel = sphk_make(kernel_kind, dim, cutoff);
  const double h = cutoff / sphk_support(kernel_kind);
  const double cutsq = cutoff * cutoff;

  const double inv_h = kernel.inv_h;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;    // dW/dr / r = this f'(q) / q
  // every owned and ghost atom's volume (and W(dx), T), once rather than once per pair
  const int nall = nlocal + atom->nghost;
  volume.resize(nall);
  for (int i = 0; i < nall; i++) volume[i] = particles.volume(i);
  if (FORM == DELTAPLUS) {
    w_spacing.resize(nall);
    for (int i = 0; i < nall; i++)
      w_spacing[i] = (mask[i] & groupbit) ? sphk_w(&kernel, spacing_of(volume[i], dim)) : 0.0;
  }
  if (CORRECT) {
    temperature.resize(nall);
    particles.temperatures(temperature.data(), nall);
  }

  // the neighbour sums of an atom of the group, at these offsets:
  //   grad_c: sum_j V_j grad_i W_ij (delta-plus: with its pair weight);
  //   continuity yes: grad_volume = sum_j s_j V_j grad_i W_ij;
  //   correcting: g and L of T's corrected gradient (sph_gradient.h);
  //   CORRECT_ALL: those of rho, vx, vy, vz over the group's neighbours only
  //   (a wall's rho and v are not the fluid's), with their own L
  constexpr int at_volume = 3, at_g = 3 + 3 * CONTINUITY, at_l = at_g + 3, at_g_flow = at_l + 9,
                at_l_flow = at_g_flow + 12;
  constexpr int per_atom =
      3 + 3 * CONTINUITY + (CORRECT ? 12 : 0) + (CORRECT == CORRECT_ALL ? 21 : 0);
  sums.assign((size_t) per_atom * nall, 0.0);

  // one side of a pair: the sums s of atom 'self' gain neighbour 'other', with
  // del = r_self - r_other and grad_w = grad_self W
  auto add_neighbour = [&](double *s, int self, int other, const double *del, const double *grad_w,
                           double w_pair) {
    const int other_in_group = mask[other] & groupbit;
    const double volume_other = volume[other];
    if (FORM == DELTAPLUS) {
      const double weight = sphs_deltaplus_weight(w_pair, w_spacing[self], r_coeff, r_power) *
          (other_in_group ? 2.0 * particles.mass(other) / (rho[self] + rho[other]) : volume[self]);
      for (int a = 0; a < 3; a++) s[a] += weight * grad_w[a];
    } else
      for (int a = 0; a < 3; a++) s[a] += volume_other * grad_w[a];
    if (CONTINUITY) {
      const double share = other_in_group ? 2.0 * volume_other : volume_other;
      for (int a = 0; a < 3; a++) s[at_volume + a] += share * grad_w[a];
    }
    if (CORRECT) {
      sphg_add(s + at_g, s + at_l, del, grad_w, volume_other,
               temperature[other] - temperature[self]);
      if (CORRECT == CORRECT_ALL && other_in_group) {
        const double diff[4] = {rho[other] - rho[self], v[other][0] - v[self][0],
                                v[other][1] - v[self][1], v[other][2] - v[self][2]};
        for (int q = 0; q < 4; q++)
          for (int a = 0; a < 3; a++)
            s[at_g_flow + 3 * q + a] += volume_other * diff[q] * grad_w[a];
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) s[at_l_flow + 3 * a + b] -= volume_other * del[a] * grad_w[b];
      }
    }
  };

  // each pair once (half list): both atoms' sums, a ghost's sent to its owner
  // after; the entries inside the support first, their kernel values
  // together (sph_support.h). With package omp, each thread a slice of the
  // list, adding to its own copy of the sums (sph_threads.h)
  const int nthreads = comm->nthreads;
  std::vector<int> slices, before;
  sph_neighbour_slices(list->ilist, list->numneigh, list->inum, nthreads, slices, before);
  thread_sums.fit(sums.size(), nthreads);
  sph_parallel(nthreads, [&](int tid) {
    double *const sums_thr = thread_sums.of(sums.data(), tid);
    SPHSupport support;
    for (int ii = slices[tid]; ii < slices[tid + 1]; ii++) {
      const int i = list->ilist[ii];
      const int i_in_group = mask[i] & groupbit;
      // i's sums in locals: no store to reload in every pair
      double sums_i[per_atom];
      for (int q = 0; q < per_atom; q++) sums_i[q] = 0.0;
      const int nin =
          support.gather<3, true>(x[i], x, list->firstneigh[i], list->numneigh[i], cutsq);
      double *const f_in = support.a;
      double *const w_in = support.b;
      for (int k = 0; k < nin; k++) {
        const double r = sqrt(support.rsq[k]);
        // grad_i W_ij = dW/dr (r_i - r_j) / r = f (r_i - r_j), without dividing by r
        f_in[k] = dwdr_r_scale * sphk_df_over_q(kernel.kind, r * inv_h);
        if (FORM == DELTAPLUS) w_in[k] = sphk_w(&kernel, r);
      }
      for (int k = 0; k < nin; k++) {
        const int j = support.index[k];
        const int j_sums = (mask[j] & groupbit) && (newton || j < nlocal);
        if ((!i_in_group && !j_sums) || support.rsq[k] == 0.0) continue;
        const double *const del = support.del + 3 * k;
        const double f = f_in[k];
        const double grad_w[3] = {f * del[0], f * del[1], f * del[2]};
        const double w_pair = FORM == DELTAPLUS ? w_in[k] : 0.0;
        if (i_in_group) add_neighbour(sums_i, i, j, del, grad_w, w_pair);
        if (j_sums) {
          const double del_j[3] = {-del[0], -del[1], -del[2]};
          const double grad_w_j[3] = {-grad_w[0], -grad_w[1], -grad_w[2]};
          add_neighbour(sums_thr + (size_t) per_atom * j, j, i, del_j, grad_w_j, w_pair);
        }
      }
      double *const s_i = sums_thr + (size_t) per_atom * i;
      for (int q = 0; q < per_atom; q++) s_i[q] += sums_i[q];
    }
    thread_sums.reduce(sums.data(), nthreads, tid);
  });
  if (newton) SPHCompat::reverse_comm(comm, this);

  shift.assign(3 * (size_t) nlocal, 0.0);
  std::vector<double> dtemp(CORRECT ? nlocal : 0, 0.0);
  // CORRECT_ALL: the changes of rho, vx, vy, vz
  std::vector<double> dflow(CORRECT == CORRECT_ALL ? 4 * (size_t) nlocal : 0, 0.0);
  double largest_local = 0.0, rho_change_local = 0.0, rho_sum_local = 0.0, rho_follow_local = 0.0;
  int capped_local = 0, moved_local = 0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    moved_local++;
    const double *const s = &sums[(size_t) per_atom * i];
    const double spacing = spacing_of(volume[i], dim);
    double *dr = &shift[3 * (size_t) i];
    displacement(i, s, spacing, h, dim, dr, largest_local, capped_local);
    if (CONTINUITY) {
      const double *const grad_volume = s + at_volume;
      rho_change_local +=
          rho[i] * (dr[0] * grad_volume[0] + dr[1] * grad_volume[1] + dr[2] * grad_volume[2]);
      rho_sum_local += rho[i];
    }
    if (CORRECT) {
      double grad_t[3];
      sphg_solve_transposed(s + at_l, s + at_g, grad_t, dim);
      dtemp[i] = dr[0] * grad_t[0] + dr[1] * grad_t[1] + dr[2] * grad_t[2];
      if (CORRECT == CORRECT_ALL) {
        for (int q = 0; q < 4; q++) {
          double grad_q[3];
          sphg_solve_transposed(s + at_l_flow, s + at_g_flow + 3 * q, grad_q, dim);
          dflow[4 * (size_t) i + q] = dr[0] * grad_q[0] + dr[1] * grad_q[1] + dr[2] * grad_q[2];
        }
        if (CONTINUITY) rho_follow_local += dflow[4 * (size_t) i];
      }
    }
  }

  // continuity yes: the group's densities, moved with the atoms first when
  // correcting all, scale together so that their sum changes as the kernel
  // sums of mass do
  double rho_sums[3] = {rho_change_local, rho_sum_local, rho_follow_local};
  double rho_totals[3] = {0.0, 0.0, 0.0};
  if (CONTINUITY) MPI_Allreduce(rho_sums, rho_totals, 3, MPI_DOUBLE, MPI_SUM, world);
  const double rho_followed = rho_totals[1] + rho_totals[2];
  const double rho_scale = rho_followed > 0.0 ? (rho_totals[1] + rho_totals[0]) / rho_followed
                                              : 1.0;

  // move only after every shift is known: each used the positions of the step
  double energy_local = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int a = 0; a < 3; a++) x[i][a] += shift[3 * (size_t) i + a];
    if (CORRECT) {
      // (a melting atom's enthalpy moves with T by its mushy heat capacity)
      const double desph = particles.esph_per_temperature(i) * dtemp[i];
      atom->esph[i] += desph;
      energy_local += particles.mass(i) * desph;
    }
    if (CORRECT == CORRECT_ALL) {
      rho[i] += dflow[4 * (size_t) i];
      for (int a = 0; a < 3; a++) v[i][a] += dflow[4 * (size_t) i + 1 + a];
    }
    // after following its atom: the factor is of the followed densities' sum
    if (CONTINUITY) rho[i] *= rho_scale;
  }
  if (CORRECT) {
    double energy_all = 0.0;
    MPI_Allreduce(&energy_local, &energy_all, 1, MPI_DOUBLE, MPI_SUM, world);
    energy += energy_all;
  }
  largest = largest_local;
  capped = capped_local;
  moved = moved_local;
}

SPHCommStage FixSPHShift::forward_fields() const
{
  SPHCommStage stage;
  stage.flat(atom->rho, 1);
  if (correct) stage.flat(atom->esph, 1);
  if (correct == CORRECT_ALL) stage.rows(atom->v, 3);
  return stage;
}

int FixSPHShift::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  return forward_fields().pack(n, send, buf);
}

void FixSPHShift::unpack_forward_comm(int n, int first, double *buf)
{
  forward_fields().unpack_forward(n, first, buf);
}

// a ghost's neighbour sums go to its owner
int FixSPHShift::pack_reverse_comm(int n, int first, double *buf)
{
  return SPHCommStage().flat(sums.data(), sums_per_atom).pack(n, first, buf);
}

void FixSPHShift::unpack_reverse_comm(int n, int *list_send, double *buf)
{
  SPHCommStage().flat(sums.data(), sums_per_atom).unpack_reverse(n, list_send, buf);
}

/* ----------------------------------------------------------------------
   scalar: energy the temperature correction has added; vector: that
   energy, the largest shift of the last step over the atom's spacing, the
   atoms shortened to the cap in it
------------------------------------------------------------------------- */

double FixSPHShift::compute_scalar()
{
  return energy;
}

double FixSPHShift::compute_vector(int n)
{
  if (n == 0) return energy;
  // this rank's values of the last step, summed here rather than every step
  if (n == 1) {
    double largest_all = 0.0;
    MPI_Allreduce(&largest, &largest_all, 1, MPI_DOUBLE, MPI_MAX, world);
    return largest_all;
  }
  int capped_all = 0;
  MPI_Allreduce(&capped, &capped_all, 1, MPI_INT, MPI_SUM, world);
  return capped_all;
}

/* ----------------------------------------------------------------------
   the tallied energy carries across restarts, with the group it was of: a
   fix defined again on another group continues it, with a warning
------------------------------------------------------------------------- */

void FixSPHShift::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> state = {energy};
  SPHCheck::pack_name(state, group->names[igroup]);
  SPHCheck::write_restart_state(fp, RESTART_VERSION, state.data(), (int) state.size());
}

void FixSPHShift::restart(char *buf)
{
  const double *state = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  energy = state[0];
  int at = 1;
  const std::string written = SPHCheck::unpack_name(state, at);
  if (written != group->names[igroup] && comm->me == 0)
    error->warning(FLERR,
                   "{}: the restart file's state is of group {}, the fix is now of group {}: its "
                   "tallied energy ({}) continues from the other group's; give the fix another "
                   "ID to start it at 0",
                   who, written, group->names[igroup], energy);
}
