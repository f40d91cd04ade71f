/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The common part of the package's SPH pair styles (pair_sph_kernel.h).
------------------------------------------------------------------------- */

#include "pair_sph_kernel.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_timestep_check.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHKernel::PairSPHKernel(LAMMPS *lmp, const char *style, const char *from_materials) :
    Pair(lmp), style(style), from_materials(from_materials), kernel_kind(-1), cut_global(0.0),
    eta_factor(0.1), kernel_same(0)
{
  restartinfo = 1;
  single_enable = 0;
  memset(&kernel, 0, sizeof(kernel));
}

PairSPHKernel::~PairSPHKernel()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairSPHKernel::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
}

/* ---------------------------------------------------------------------- */

int PairSPHKernel::parse_kernel(int narg, char **arg)
{
  // 'same': the other pair's, known at init (its settings may come later)
  kernel_same = narg >= 1 && strcmp(arg[0], "same") == 0;
  if (kernel_same) {
    kernel_kind = -1;
    cut_global = 0.0;
    return 1;
  }
  if (narg < 2)
    error->all(FLERR, "Illegal pair_style {} command: expected <kernel> <cutoff>", style);
  kernel_kind = sphk_lookup(arg[0]);
  if (kernel_kind < 0)
    error->all(FLERR,
               "Illegal pair_style {} command: unknown kernel '{}' (lucy, cubic, quintic, "
               "wendland, or same)",
               style, arg[0]);
  cut_global = utils::numeric(FLERR, arg[1], false, lmp);
  if (cut_global <= 0.0)
    error->all(FLERR, "Illegal pair_style {} command: cutoff {} must be > 0", style, arg[1]);
  return 2;
}

/* the kernel and cutoff of every pair given 'same' from the pair of the
   other kind (conduction or flow), for all the package's pairs at the
   first of their inits, so that each sees the others' resolved */

void PairSPHKernel::resolve_same_kernels()
{
  const std::vector<PairSPHKernel *> pairs = SPHHub(lmp).pairs();
  for (PairSPHKernel *pair : pairs) {
    if (!pair->kernel_same) continue;
    const PairSPHKernel *other = nullptr;
    for (PairSPHKernel *candidate : pairs)
      if (!candidate->same_family(pair)) other = candidate;
    const char *other_style = pair->conducts() ? "sph/harmonic/visc" : "sph/cleary/heat";
    if (!other)
      error->all(FLERR,
                 "Pair style {}: kernel 'same' takes the kernel and cutoff of pair style {}, "
                 "which pair_style {} does not have",
                 pair->style, other_style, force->pair_style);
    if (other->kernel_same)
      error->all(FLERR,
                 "Pair styles {} and {} are both given kernel 'same': give one of them a kernel "
                 "and cutoff",
                 pair->style, other->style);
    pair->kernel_kind = other->kernel_kind;
    pair->cut_global = other->cut_global;
  }
}

double PairSPHKernel::init_kernel()
{
  resolve_same_kernels();
  // a support beyond the whole box is a typo (e.g. 1e10 for 1e-2), not a
  // kernel: say so here, not as a neighbour-binning error at 'run'
  double extent = 0.0;
  for (int d = 0; d < domain->dimension; d++) extent = MAX(extent, domain->prd[d]);
  if (cut_global > extent)
    error->all(
        FLERR,
        "Pair style {}: cutoff {} is larger than the simulation box (largest extent {}); the "
        "cutoff is the kernel support, a few particle spacings",
        style, cut_global, extent);

  // in hybrid/overlay: no type pair twice in this style (its heat or force
  // would count twice); one instance only; the flow pair with the heat
  // pair's kernel
  const std::vector<PairSPHKernel *> pairs = SPHHub(lmp).pairs();
  int instances = 0;
  for (PairSPHKernel *other : pairs) {
    if (!same_family(other)) continue;
    instances++;
    if (other == this) continue;
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++)
        if (setflag[i][j] && other->setflag && other->setflag[i][j])
          error->all(FLERR,
                     "Pair style {} is used twice in pair_style {} for atom types {} {}: its rates "
                     "would be counted twice",
                     style, force->pair_style, i, j);
  }
  if (instances > 1)
    error->all(FLERR,
               "Pair style {} appears more than once in pair_style {}: give all its type pairs to "
               "one instance (the styles that read its kernel, conductivity or forces find only "
               "one)",
               style, force->pair_style);
  const PairSPHHarmonicVisc *flow = SPHHub(lmp).flow();
  if (conducts() && flow && !same_kernel(flow))
    error->warning(FLERR,
                   "Pair styles sph/cleary/heat ({} kernel, cutoff {}) and sph/harmonic/visc ({} "
                   "kernel, cutoff {}) differ: the flow and the heat see different neighbourhoods",
                   sphk_name(kernel_kind), cut_global, sphk_name(flow->kernel_kind),
                   flow->cut_global);

  // the check of a fixed timestep against the pairs' stability limits
  FixSPHTimestepCheck::ensure(lmp);

  kernel = sphk_make(kernel_kind, domain->dimension, cut_global);
  const double eta = eta_factor * kernel.h;
  return eta * eta;
}

/* ----------------------------------------------------------------------
   pair_coeff I J: no coefficients, the materials come from fix sph/materials
------------------------------------------------------------------------- */

void PairSPHKernel::coeff(int narg, char **arg)
{
  if (narg != 2)
    error->all(FLERR, "Illegal pair_coeff command for {}: expected I J only ({})", style,
               from_materials);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Illegal pair_coeff command for {}: no type pair", style);
}

/* ---------------------------------------------------------------------- */

void PairSPHKernel::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) fwrite(&setflag[i][j], sizeof(int), 1, fp);
}

void PairSPHKernel::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
    }
}

/* ----------------------------------------------------------------------
   at a run's setup: pairs of particles within the cutoff, against atoms
------------------------------------------------------------------------- */

void PairSPHKernel::check_neighbours()
{
  const double *const *const x = atom->x;
  const double cutsq_kernel = cut_global * cut_global;
  bigint local = 0, pairs;
  // two particles at one point (created twice, or an atom on a periodic
  // boundary and its image): no direction between them, so every term that
  // needs one (pressure, the corrections' unit vectors) is undefined
  tagint same[2] = {MAXTAGINT, MAXTAGINT};
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < cutsq_kernel) local++;
      if (rsq == 0.0 && std::min(atom->tag[i], atom->tag[j]) < same[0])
        same[0] = std::min(atom->tag[i], atom->tag[j]),
        same[1] = std::max(atom->tag[i], atom->tag[j]);
    }
  }
  tagint first_same;
  MPI_Allreduce(&same[0], &first_same, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (first_same != MAXTAGINT) {
    tagint other = (same[0] == first_same) ? same[1] : MAXTAGINT, first_other;
    MPI_Allreduce(&other, &first_other, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    error->all(FLERR,
               "Pair style {}: atoms {} and {} are at the same position (created twice at one "
               "point, or an atom on a periodic boundary and its image); no particle may overlap "
               "another",
               style, first_same, first_other);
  }
  MPI_Allreduce(&local, &pairs, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  // a half list holds each pair once with newton on, on both of its ranks with newton off
  if (!force->newton_pair && comm->nprocs > 1) pairs /= 2;
  if (comm->me == 0 && atom->natoms > 1 && 2 * pairs < atom->natoms)
    error->warning(FLERR,
                   "Pair style {}: cutoff {} gives {} pairs of particles in range for {} atoms "
                   "(less than one neighbour each): is it below the particle spacing?",
                   style, cut_global, pairs, atom->natoms);
}

/* ---------------------------------------------------------------------- */

void PairSPHKernel::check_rates(const double *rate, const char *quantity)
{
  const int i = SPHCheck::first_nonfinite(rate, atom->nlocal);
  if (i >= 0)
    SPHCheck::nonfinite(lmp, FLERR, fmt::format("Pair style {}", style).c_str(), quantity, i,
                        rate[i], diagnose(i));
}

void PairSPHKernel::check_rates3(double *const *rate, const char *quantity)
{
  const int i = SPHCheck::first_nonfinite3(rate, atom->nlocal);
  if (i >= 0)
    SPHCheck::nonfinite(lmp, FLERR, fmt::format("Pair style {}", style).c_str(), quantity, i,
                        rate[i][0] + rate[i][1] + rate[i][2], diagnose(i));
}

/* ----------------------------------------------------------------------
   the state every SPH pair reads: rho and, when the atom has them, cv and
   esph; of atom i, then of the atoms within the cutoff (also a neighbour
   at distance 0 when eta = 0)
------------------------------------------------------------------------- */

std::string PairSPHKernel::diagnose(int i)
{
  auto state = [this](int j) -> std::string {
    if (!(atom->rho[j] > 0.0 && std::isfinite(atom->rho[j])))
      return fmt::format("its rho is {}", atom->rho[j]);
    if (atom->cv && !(atom->cv[j] > 0.0 && std::isfinite(atom->cv[j])))
      return fmt::format("its cv is {}", atom->cv[j]);
    if (atom->esph && !std::isfinite(atom->esph[j]))
      return fmt::format("its esph is {}", atom->esph[j]);
    if (!std::isfinite(atom->x[j][0] + atom->x[j][1] + atom->x[j][2]))
      return "its position is not finite";
    if (atom->v && !std::isfinite(atom->v[j][0] + atom->v[j][1] + atom->v[j][2]))
      return "its velocity is not finite";
    return "";
  };
  std::string why = state(i);
  if (!why.empty()) return why;
  const double *const *const x = atom->x;
  const double cutsq_kernel = cut_global * cut_global;
  const int nall = atom->nlocal + atom->nghost;
  for (int j = 0; j < nall; j++) {
    if (j == i) continue;
    const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
    const double rsq = dx * dx + dy * dy + dz * dz;
    if (!(rsq < cutsq_kernel)) continue;
    why = state(j);
    if (!why.empty())
      return fmt::format("its neighbour atom {} (type {}): {}", atom->tag[j], atom->type[j], why);
    if (rsq == 0.0 && eta_factor == 0.0)
      return fmt::format("atom {} lies at distance 0 and eta is 0 (give eta > 0)", atom->tag[j]);
  }
  return "";
}

/* ----------------------------------------------------------------------
   the per-atom values of one stage between owners and ghosts (SPHExchange)
------------------------------------------------------------------------- */

void PairSPHKernel::forward(const SPHCommStage &stage)
{
  active_stage = stage;
  SPHCompat::forward_comm(comm, this);
}

void PairSPHKernel::reverse(const SPHCommStage &stage)
{
  active_stage = stage;
  SPHCompat::reverse_comm(comm, this);
}

int PairSPHKernel::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  return active_stage.pack(n, send, buf);
}

void PairSPHKernel::unpack_forward_comm(int n, int first, double *buf)
{
  active_stage.unpack_forward(n, first, buf);
}

int PairSPHKernel::pack_reverse_comm(int n, int first, double *buf)
{
  return active_stage.pack(n, first, buf);
}

void PairSPHKernel::unpack_reverse_comm(int n, int *list, double *buf)
{
  active_stage.unpack_reverse(n, list, buf);
}
