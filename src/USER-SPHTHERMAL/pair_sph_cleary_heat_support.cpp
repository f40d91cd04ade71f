/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: the support made anew when the particles move: the
   pairs within it, the factors of 'correction consistent' and 'second'
   (sph_conduction_weights.h) and the distances of 'mean interface'
   (sph_interface_distance.h).
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "sph_compat.h"
#include "sph_dispatch.h"
#include "update.h"

using namespace LAMMPS_NS;

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
  // the positions and densities the pairs are made for (pairs_current())
  if (atom->nmax > nmax_pairs) {
    nmax_pairs = atom->nmax;
    memory->destroy(pairs_x);
    memory->destroy(pairs_rho);
    memory->create(pairs_x, nmax_pairs, 3, "pair:pairs_x");
    memory->create(pairs_rho, nmax_pairs, "pair:pairs_rho");
  }
  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < 3; k++) pairs_x[i][k] = atom->x[i][k];
    pairs_rho[i] = atom->rho[i];
  }
  pairs_valid = 1;

  const double cutsq_kernel = cut_global * cut_global;
  if (interface) interface->mark(list, cutsq_kernel, *this);
  // without a correction only the interface needs pairs: those of the
  // atoms near it
  const double *const near = weights ? nullptr : interface->near();
  // 'warm hold' between builds: the factors from the held solution, no moments
  const bool held = weights && weights->held();
  double *const moments = (weights && !held) ? weights->moments_to_gather() : nullptr;
  const int nall = atom->nlocal + atom->nghost;
  if (domain->dimension == 3)
    support_pairs.gather<KERNEL, 3>(list, atom->x, kernel, cutsq_kernel, eta2, volume,
                                    interface != nullptr, near, moments, atom->nlocal, nall,
                                    force->newton_pair, comm->nthreads);
  else
    support_pairs.gather<KERNEL, 2>(list, atom->x, kernel, cutsq_kernel, eta2, volume,
                                    interface != nullptr, near, moments, atom->nlocal, nall,
                                    force->newton_pair, comm->nthreads);
  if (held)
    weights->reweigh(support_pairs);
  else if (weights)
    weights->refresh(support_pairs, volume, *this);
  if (interface)
    interface->refresh(support_pairs, volume, kernel.w_scale * sphk_f(KERNEL, 0.0), kernel.h,
                       *this);
}

/* whether the pairs, factors and distances were made for the owned atoms'
   positions and densities of this step (on every rank) */

int PairSPHClearyHeat::pairs_current()
{
  int moved = !pairs_valid || neighbor->ago == 0 || atom->nmax > nmax_pairs;
  const double *const *const x = atom->x;
  const double *const rho = atom->rho;
  for (int i = 0; i < atom->nlocal && !moved; i++)
    moved = x[i][0] != pairs_x[i][0] || x[i][1] != pairs_x[i][1] || x[i][2] != pairs_x[i][2] ||
        rho[i] != pairs_rho[i];
  int any = 0;
  MPI_Allreduce(&moved, &any, 1, MPI_INT, MPI_MAX, world);
  return !any;
}

/* at a run's setup: how many atoms are near an interface, and how many
   keep the plain term */

void PairSPHClearyHeat::report_setup()
{
  if (interface) interface->report();
  if (weights) weights->report();
}
