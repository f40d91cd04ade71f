/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/mixing: the mixing measures of Reece, Rogers, Fourtakas &
   Lind 2024, Table 4 (from Reece, Rogers, Lind & Fourtakas 2020), of two
   components of a group: component A (a group or types) and the rest.
   Per particle: the kernel-weighted volume fraction F of A around it, the
   finite-time Lyapunov exponent (FTLE) of its initial neighbourhood,
   Robinson's local measure and the VF-FTLE measure. The initial
   neighbourhoods live in an internal fix (they move with the atoms and are
   written to restart files), taken at the setup of the first run.
------------------------------------------------------------------------- */

#include "compute_sph_mixing.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_mixing_reference.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "pair_sph_harmonic_visc.h"
#include "sph_particle.h"
#include "sph_hub.h"
#include "sph_compat.h"
#include "sph_kernels.h"
#include "sph_mixing.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

enum { MEAN_FRACTION, MIXTURE_FRACTION, ENTROPY_A, ENTROPY_B, VF_FTLE, ROBINSON, FTLE_MAX, FTLE_MEAN };
enum { COL_FRACTION, COL_FTLE, COL_ROBINSON, COL_VF_FTLE, NCOLUMNS };

/* ---------------------------------------------------------------------- */

ComputeSPHMixing::ComputeSPHMixing(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), component_groupbit(0), stretch_cutoff(0.0), reference(nullptr),
    list(nullptr), kernel_kind(0), cutoff(0.0), measured(-1), nmax(0), measures(nullptr)
{
  if (!atom->rho_flag) error->all(FLERR, "Compute sph/mixing requires atom style sph (rho)");
  if (domain->triclinic)
    error->all(FLERR, "Compute sph/mixing does not support triclinic boxes");
  if (narg < 4)
    error->all(FLERR,
               "Illegal compute sph/mixing command: missing component A (a group ID, or 'type' "
               "and a type range)");

  int iarg = 3;
  if (strcmp(arg[iarg], "type") == 0) {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal compute sph/mixing command: missing type range after 'type'");
    int lo, hi;
    utils::bounds(FLERR, arg[iarg + 1], 1, atom->ntypes, lo, hi, error);
    component_type.assign(atom->ntypes + 1, 0);
    for (int t = lo; t <= hi; t++) component_type[t] = 1;
    iarg += 2;
  } else {
    const int igroup_a = group->find(arg[iarg]);
    if (igroup_a < 0)
      error->all(FLERR, "Compute sph/mixing: no group '{}' for component A", arg[iarg]);
    component_groupbit = group->bitmask[igroup_a];
    iarg += 1;
  }
  while (iarg < narg) {
    if (strcmp(arg[iarg], "ftle/cutoff") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal compute sph/mixing command: missing value after 'ftle/cutoff'");
      stretch_cutoff = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (stretch_cutoff <= 0.0)
        error->all(FLERR, "Illegal compute sph/mixing command: ftle/cutoff {} must be > 0",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal compute sph/mixing command: unknown keyword '{}'", arg[iarg]);
  }

  peratom_flag = 1;
  size_peratom_cols = NCOLUMNS;
  scalar_flag = 1;
  extscalar = 0;
  vector_flag = 1;
  size_vector = FTLE_MEAN + 1;
  extvector = 0;
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;

  // the reference lives in a fix so that it migrates and restarts with the atoms
  id_reference = std::string(id) + "_reference";
  reference = dynamic_cast<FixSPHMixingReference *>(modify->add_fix(
      fmt::format("{} {} SPH/MIXING/REFERENCE", id_reference, group->names[igroup])));
}

ComputeSPHMixing::~ComputeSPHMixing()
{
  if (modify->nfix && modify->find_fix(id_reference) >= 0) modify->delete_fix(id_reference);
  delete[] vector;
  memory->destroy(measures);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHMixing::init()
{
  const int ifix = modify->find_fix(id_reference);
  if (ifix < 0)
    error->all(FLERR, "Compute sph/mixing {}: its fix {} was deleted", id, id_reference);
  reference = dynamic_cast<FixSPHMixingReference *>(modify->fix[ifix]);

  // the kernel of the flow (or of conduction)
  SPHHub hub(lmp);
  const PairSPHKernel *pair = hub.flow();
  if (!pair) pair = hub.heat();
  if (!pair)
    error->all(FLERR, "Compute sph/mixing requires pair style sph/harmonic/visc or sph/cleary/heat");
  kernel_kind = pair->kernel_settings().kind;
  cutoff = pair->kernel_settings().cutoff;
  if (stretch_cutoff > cutoff)
    error->all(FLERR, "Compute sph/mixing {}: ftle/cutoff {} exceeds the kernel's support {}", id,
               stretch_cutoff, cutoff);
  SPHCompat::request_occasional_full_list(neighbor, this, instance_me);
  measured = -1;
}

void ComputeSPHMixing::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

// the reference is taken at the setup of the first run (neighbour lists exist)
void ComputeSPHMixing::setup()
{
  if (!reference->captured)
    capture();
  else
    reference->settle_restart();
}

/* ---------------------------------------------------------------------- */

double ComputeSPHMixing::volume(int i) const
{
  return SPHParticles(atom).volume(i);
}

bool ComputeSPHMixing::in_component(int i) const
{
  return component_type.empty() ? (atom->mask[i] & component_groupbit) != 0
                                : component_type[atom->type[i]] != 0;
}

/* ----------------------------------------------------------------------
   F_i = sum_{j in A} V_j W_ij / sum_j V_j W_ij over the group, i itself
   included (Reece et al. 2024, Table 4 as intended); 0 outside the group.
   The ghosts' positions and densities are refreshed first: fixes at the
   end of a step (shifting, the integrator) change them on the owners only
------------------------------------------------------------------------- */

void ComputeSPHMixing::volume_fractions(double *fraction)
{
  comm->forward_comm();
  SPHCompat::build_occasional(neighbor, list);
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const sphk_kernel kernel = sphk_make(kernel_kind, domain->dimension, cutoff);
  const double w_self = sphk_w(&kernel, 0.0);
  const double cutsq = cutoff * cutoff;

  for (int i = 0; i < atom->nlocal; i++) fraction[i] = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    double all = volume(i) * w_self;
    double of_a = in_component(i) ? all : 0.0;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq) continue;
      const double vw = volume(j) * sphk_w(&kernel, sqrt(rsq));
      all += vw;
      if (in_component(j)) of_a += vw;
    }
    fraction[i] = of_a / all;
  }
}

/* ----------------------------------------------------------------------
   the volume fraction of A in the whole group and the group's atom count
------------------------------------------------------------------------- */

void ComputeSPHMixing::component_fraction(double &f_all, double &n_group)
{
  double local[3] = {0.0, 0.0, 0.0}, sums[3];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    local[0] += volume(i);
    if (in_component(i)) local[1] += volume(i);
    local[2] += 1.0;
  }
  MPI_Allreduce(local, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  f_all = (sums[0] > 0.0) ? sums[1] / sums[0] : 0.0;
  n_group = sums[2];
  if (!(f_all > 0.0 && f_all < 1.0))
    error->all(FLERR,
               "Compute sph/mixing {}: component A holds a fraction {} of group {}'s volume; the "
               "measures need both components",
               id, f_all, group->names[igroup]);
}

/* ----------------------------------------------------------------------
   every rank gets the group's unwrapped positions, sorted by the atoms'
   tags at the reference (which the neighbour lists hold; an atom keeps its
   own, so tags renumbered since change nothing): an initial neighbour may
   be anywhere by now. An atom created since the reference is no one's.
------------------------------------------------------------------------- */

void ComputeSPHMixing::gather_positions()
{
  const int nlocal = atom->nlocal;
  const tagint *const tag0 = reference->tag0;
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit) || tag0[i] == 0) continue;
    double xu[3];
    domain->unmap(atom->x[i], atom->image[i], xu);
    mine.push_back(ubuf(tag0[i]).d);
    mine.insert(mine.end(), xu, xu + 3);
  }
  const int nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  int nmine = (int) mine.size();
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> all(displs[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(mine.data(), nmine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, world);
  positions.resize(all.size() / 4);
  for (size_t n = 0; n < positions.size(); n++) {
    positions[n].tag = (tagint) ubuf(all[4 * n]).i;
    for (int k = 0; k < 3; k++) positions[n].x[k] = all[4 * n + 1 + k];
  }
  std::sort(positions.begin(), positions.end(),
            [](const Position &a, const Position &b) { return a.tag < b.tag; });
}

const ComputeSPHMixing::Position *ComputeSPHMixing::find_position(tagint tag) const
{
  auto found = std::lower_bound(positions.begin(), positions.end(), tag,
                                [](const Position &p, tagint t) { return p.tag < t; });
  return (found != positions.end() && found->tag == tag) ? &(*found) : nullptr;
}

/* ----------------------------------------------------------------------
   r_j - r_i now for the initial neighbour 'tag' of an atom at unwrapped xu, the
   periodic image it was a neighbour through included; found = false when
   the neighbour is gone (deleted or lost)
------------------------------------------------------------------------- */

void ComputeSPHMixing::separation(const double *xu, tagint tag, int packed_shift, double *del,
                                  bool &found) const
{
  const Position *p = find_position(tag);
  found = (p != nullptr);
  if (!found) return;
  int shift[3];
  FixSPHMixingReference::unpack_shift(packed_shift, shift);
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  for (int k = 0; k < 3; k++) del[k] = p->x[k] - xu[k] - shift[k] * prd[k];
}

/* ----------------------------------------------------------------------
   the reference: each group atom's group neighbours within the stretch
   cutoff, their image shifts and distances; the time; the entropies
------------------------------------------------------------------------- */

void ComputeSPHMixing::capture()
{
  // each atom keeps its tag of now: the neighbour lists name their atoms by it
  for (int i = 0; i < atom->nlocal; i++) reference->tag0[i] = atom->tag[i];
  std::vector<double> fraction(atom->nlocal);
  volume_fractions(fraction.data());    // also refreshes the ghosts and builds the list
  gather_positions();

  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const tagint *const tag = atom->tag;
  const double reach = (stretch_cutoff > 0.0) ? stretch_cutoff : cutoff;
  const double reachsq = reach * reach;
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};

  // two passes: the widest neighbourhood sets the lists' width
  int widest = 0;
  for (int pass = 0; pass < 2; pass++) {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      if (!(mask[i] & groupbit)) continue;
      int n = 0;
      double xu_i[3];
      domain->unmap(x[i], atom->image[i], xu_i);
      const int *const jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if (!(mask[j] & groupbit)) continue;
        const double del[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
        if (rsq >= reachsq || rsq == 0.0) continue;
        // a ghost whose group membership its owner no longer shares: not a neighbour
        const Position *p = find_position(tag[j]);
        if (!p) continue;
        if (pass == 1) {
          // the unwrapped separation differs from the neighbour's by whole box lengths
          int shift[3] = {0, 0, 0};
          for (int k = 0; k < 3; k++)
            if (periodic[k]) shift[k] = (int) lround((p->x[k] - xu_i[k] - del[k]) / prd[k]);
          reference->tags[i][n] = tag[j];
          reference->shifts[i][n] = FixSPHMixingReference::pack_shift(shift);
          reference->distance0[i][n] = sqrt(rsq);
        }
        n++;
      }
      if (pass == 0) widest = std::max(widest, n);
      else reference->count[i] = n;
    }
    if (pass == 0) {
      int width;
      MPI_Allreduce(&widest, &width, 1, MPI_INT, MPI_MAX, world);
      reference->resize(width);
    }
  }

  double f_all, n_group;
  component_fraction(f_all, n_group);
  entropies(fraction.data(), reference->entropy0);
  reference->time0 = reference->now();
  reference->captured = 1;
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "compute sph/mixing {}: reference at t = {} (step {}), {:.0f} particles, up to "
                   "{} neighbours each within {}, component A {:.6g} of the volume\n",
                   id, reference->time0, update->ntimestep, n_group, reference->width, reach,
                   f_all);
}

/* ----------------------------------------------------------------------
   the mixing entropies -sum F ln F of A and of the rest over the group
------------------------------------------------------------------------- */

void ComputeSPHMixing::entropies(const double *fraction, double *sums)
{
  double local[2] = {0.0, 0.0};
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    local[0] += sphmix_entropy_term(fraction[i]);
    local[1] += sphmix_entropy_term(1.0 - fraction[i]);
  }
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
}

/* ----------------------------------------------------------------------
   all measures, once per step
------------------------------------------------------------------------- */

void ComputeSPHMixing::measure()
{
  if (measured == update->ntimestep) return;
  // the setup of a run takes it first, unless some other setup invoked this compute earlier
  if (!reference->captured) capture();
  reference->settle_restart();
  measured = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(measures);
    memory->create(measures, nmax, NCOLUMNS, "sph/mixing:measures");
    array_atom = measures;
  }
  const int nlocal = atom->nlocal;
  const int *const mask = atom->mask;
  std::vector<double> fraction(nlocal);
  volume_fractions(fraction.data());
  double f_all, n_group;
  component_fraction(f_all, n_group);
  gather_positions();
  const double time = reference->now() - reference->time0;    // since the reference

  // F, FTLE and Robinson's measure; the sums of the global measures
  double local[3] = {0.0, 0.0, 0.0}, sums[3], entropy[2];
  double ftle_max_local = -INFINITY;
  for (int i = 0; i < nlocal; i++) {
    double *m = measures[i];
    for (int k = 0; k < NCOLUMNS; k++) m[k] = 0.0;
    if (!(mask[i] & groupbit)) continue;
    double stretch = 0.0, xu[3];
    domain->unmap(atom->x[i], atom->image[i], xu);
    for (int n = 0; n < reference->count[i]; n++) {
      double del[3];
      bool found;
      separation(xu, reference->tags[i][n], reference->shifts[i][n], del, found);
      if (!found) continue;
      const double r = sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
      stretch = std::max(stretch, r / reference->distance0[i][n]);
    }
    m[COL_FRACTION] = fraction[i];
    m[COL_FTLE] = sphmix_ftle(stretch, time);
    m[COL_ROBINSON] = sphmix_robinson(fraction[i], f_all);
    local[0] += fraction[i];
    local[1] += m[COL_ROBINSON];
    local[2] += m[COL_FTLE];
    ftle_max_local = std::max(ftle_max_local, m[COL_FTLE]);
  }
  MPI_Allreduce(local, sums, 3, MPI_DOUBLE, MPI_SUM, world);
  entropies(fraction.data(), entropy);
  double ftle_max;
  MPI_Allreduce(&ftle_max_local, &ftle_max, 1, MPI_DOUBLE, MPI_MAX, world);

  // the VF-FTLE measure: FTLE / its largest value times the normalised composition
  double vf_ftle_local = 0.0, vf_ftle_sum;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *m = measures[i];
    const double ftle_normalised = (ftle_max > 0.0) ? m[COL_FTLE] / ftle_max : 0.0;
    m[COL_VF_FTLE] = ftle_normalised * sphmix_composition(m[COL_FRACTION], f_all);
    vf_ftle_local += m[COL_VF_FTLE];
  }
  MPI_Allreduce(&vf_ftle_local, &vf_ftle_sum, 1, MPI_DOUBLE, MPI_SUM, world);

  vector[MEAN_FRACTION] = sums[0] / n_group;
  vector[MIXTURE_FRACTION] = f_all;
  vector[ENTROPY_A] = sphmix_entropy_normalised(entropy[0], reference->entropy0[0],
                                                sphmix_entropy_max(n_group, f_all));
  vector[ENTROPY_B] = sphmix_entropy_normalised(entropy[1], reference->entropy0[1],
                                                sphmix_entropy_max(n_group, 1.0 - f_all));
  vector[VF_FTLE] = vf_ftle_sum / n_group;
  vector[ROBINSON] = sums[1] / n_group;
  vector[FTLE_MAX] = ftle_max;
  vector[FTLE_MEAN] = sums[2] / n_group;
}

/* ---------------------------------------------------------------------- */

double ComputeSPHMixing::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  measure();
  scalar = vector[VF_FTLE];
  return scalar;
}

void ComputeSPHMixing::compute_vector()
{
  invoked_vector = update->ntimestep;
  measure();
}

void ComputeSPHMixing::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  measure();
}

double ComputeSPHMixing::memory_usage()
{
  return (double) nmax * NCOLUMNS * sizeof(double) + positions.capacity() * sizeof(Position);
}
