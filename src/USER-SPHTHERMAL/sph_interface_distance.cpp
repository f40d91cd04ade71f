/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   'mean interface' of pair sph/cleary/heat: each atom with a neighbour of
   another material (a type of another conductivity law) estimates its
   distance from the interface, which sphc_interface_conductance() turns
   into the pair's series conductance:
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

#include "sph_interface_distance.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "math_extra.h"
#include "memory.h"
#include "neigh_list.h"
#include "sph_checks.h"
#include "sph_consistent.h"
#include "sph_exchange.h"
#include "sph_support_pairs.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

constexpr double SPHInterfaceDistance::NONE;    // (C++11: a definition for its uses by reference)

SPHInterfaceDistance::SPHInterfaceDistance(LAMMPS *lmp, const std::string &given_name) :
    Pointers(lmp), crossing(nullptr), given_name(given_name), given_index(-1), nmax(0),
    distance(nullptr), near_of(nullptr), moment(nullptr), vector(nullptr), normal(nullptr),
    sum(nullptr)
{
}

SPHInterfaceDistance::~SPHInterfaceDistance()
{
  release();
}

void SPHInterfaceDistance::release()
{
  memory->destroy(distance);
  memory->destroy(near_of);
  memory->destroy(moment);
  memory->destroy(vector);
  memory->destroy(normal);
  memory->destroy(sum);
}

void SPHInterfaceDistance::init(int **crossing_types)
{
  crossing = crossing_types;
  grow();
  given_index = -1;
  if (given_name.empty()) return;
  int flag = -1, cols = -1;
  given_index = atom->find_custom(given_name.c_str() + 2, flag, cols);
  if (given_index < 0 || flag != 1 || cols != 0)
    error->all(FLERR,
               "Pair style sph/cleary/heat: distance: no per-atom double '{}' (define it with "
               "fix property/atom)",
               given_name);
}

void SPHInterfaceDistance::grow()
{
  if (atom->nmax <= nmax) return;
  nmax = atom->nmax;
  release();
  memory->create(near_of, nmax, "sph/cleary/heat:interface_near");
  memory->create(distance, nmax, "sph/cleary/heat:interface_distance");
  memory->create(moment, nmax, 6, "sph/cleary/heat:interface_moment");
  memory->create(vector, nmax, 3, "sph/cleary/heat:interface_vector");
  memory->create(normal, nmax, 3, "sph/cleary/heat:interface_normal");
  memory->create(sum, nmax, 3, "sph/cleary/heat:interface_sum");
}

void SPHInterfaceDistance::mark(const NeighList *list, double cutsq, SPHExchange &exchange)
{
  grow();
  const double *const *const x = atom->x;
  const int *const type = atom->type;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) near_of[i] = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *const crossing_i = crossing[type[i]];
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!crossing_i[type[j]]) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      if (delx * delx + dely * dely + delz * delz >= cutsq) continue;
      near_of[i] = near_of[j] = 1.0;
    }
  }
  const SPHCommStage stage = SPHCommStage().flat(near_of, 1, SPHCommStage::MAX);
  if (force->newton_pair) exchange.reverse(stage);
  exchange.forward(stage);
}

void SPHInterfaceDistance::refresh(const SPHSupportPairs &pairs, const double *volume,
                                   double w_self, double h, SPHExchange &exchange)
{
  if (given_index >= 0) {
    take_given(exchange);
    return;
  }
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;
  const int newton = force->newton_pair;
  const int *const type = atom->type;
  // a distance never below this: the pair's split stays finite
  const double closest = 1e-3 * h;
  auto gather_j = [&](int j) {
    return newton || j < nlocal;
  };
  const double *const near = near_of;
  using MathExtra::dot3;

  // 1. the kernel's second moments and the sum towards the other material
  for (int i = 0; i < nall; i++) {
    for (int k = 0; k < 6; k++) moment[i][k] = 0.0;
    for (int k = 0; k < 3; k++) vector[i][k] = 0.0;
  }
  for (int q : pairs.all()) {
    const int i = pairs.i[q], j = pairs.j[q];
    const double *const r = pairs.r_of(q);
    const double radial = -pairs.dwdr[q] / pairs.distance[q];
    if (near[i] != 0.0) sphc_moment_add(moment[i], volume[j] * radial, r);
    if (near[j] != 0.0 && gather_j(j)) sphc_moment_add(moment[j], volume[i] * radial, r);
    if (crossing[type[i]][type[j]]) {
      // V dW/dr e_ij points from i towards j
      for (int k = 0; k < 3; k++) vector[i][k] -= volume[j] * radial * r[k];
      if (gather_j(j))
        for (int k = 0; k < 3; k++) vector[j][k] += volume[i] * radial * r[k];
    }
  }
  if (newton) exchange.reverse(SPHCommStage().rows(moment, 6).rows(vector, 3));
  for (int i = 0; i < nlocal; i++) {
    double inverse[6], toward[3];
    for (int k = 0; k < 3; k++) toward[k] = vector[i][k];
    sphc_sym_inverse(dim, moment[i], inverse);    // I when singular
    sphc_sym_apply(inverse, toward, vector[i]);
  }
  exchange.forward(SPHCommStage().rows(vector, 3));

  // 2. the normal: the corrected gradients averaged over the own material;
  // only the direction is kept, so the Shepard weights' sum is not needed,
  // and an atom that is not near has no gradient to add
  for (int i = 0; i < nall; i++) {
    const double self = (i < nlocal) ? w_self * volume[i] : 0.0;
    for (int k = 0; k < 3; k++) sum[i][k] = self * vector[i][k];
  }
  for (int q : pairs.all()) {
    const int i = pairs.i[q], j = pairs.j[q];
    if (crossing[type[i]][type[j]] || near[i] == 0.0 || near[j] == 0.0) continue;
    const double weight_j = pairs.w[q] * volume[j];
    for (int k = 0; k < 3; k++) sum[i][k] += weight_j * vector[j][k];
    if (gather_j(j)) {
      const double weight_i = pairs.w[q] * volume[i];
      for (int k = 0; k < 3; k++) sum[j][k] += weight_i * vector[i][k];
    }
  }
  if (newton) exchange.reverse(SPHCommStage().rows(sum, 3));
  for (int i = 0; i < nlocal; i++) {
    const double length = sqrt(dot3(sum[i], sum[i]));
    for (int k = 0; k < 3; k++) normal[i][k] = (length > 0.0) ? sum[i][k] / length : 0.0;
  }
  exchange.forward(SPHCommStage().rows(normal, 3));

  // 3. the widest gap along the normal: sum holds the farthest own (0: the
  // atom itself) and the nearest other material
  for (int i = 0; i < nall; i++) {
    sum[i][0] = 0.0;
    sum[i][1] = HUGE_VAL;
  }
  for (int q : pairs.all()) {
    const int i = pairs.i[q], j = pairs.j[q];
    if (near[i] == 0.0 && near[j] == 0.0) continue;
    const double *const r = pairs.r_of(q);
    const double along_i = -dot3(normal[i], r);    // n_i . (x_j - x_i)
    const double along_j = dot3(normal[j], r);
    double *const gap_i = sum[i];
    double *const gap_j = sum[j];
    if (crossing[type[i]][type[j]]) {
      gap_i[1] = std::min(gap_i[1], along_i);
      if (gather_j(j)) gap_j[1] = std::min(gap_j[1], along_j);
    } else {
      gap_i[0] = std::max(gap_i[0], along_i);
      if (gather_j(j)) gap_j[0] = std::max(gap_j[0], along_j);
    }
  }
  // the farthest own-material atom and the nearest other one
  if (newton)
    exchange.reverse(
        SPHCommStage().rows(sum, 1, 0, SPHCommStage::MAX).rows(sum, 1, 1, SPHCommStage::MIN));
  for (int i = 0; i < nlocal; i++)
    distance[i] = std::isfinite(sum[i][1]) ? 0.5 * (sum[i][0] + sum[i][1]) : NONE;
  const SPHCommStage distance_stage = SPHCommStage().flat(distance, 1);
  exchange.forward(distance_stage);

  // 4. the plane averaged over the own material, seen along each atom's
  // normal (the atoms near an interface are those with a distance)
  for (int i = 0; i < nall; i++) {
    const double self = (i < nlocal && near[i] != 0.0) ? w_self * volume[i] : 0.0;
    sum[i][0] = self * distance[i];
    sum[i][1] = self;
  }
  for (int q : pairs.all()) {
    const int i = pairs.i[q], j = pairs.j[q];
    if (crossing[type[i]][type[j]] || near[i] == 0.0 || near[j] == 0.0) continue;
    const double *const r = pairs.r_of(q);
    const double weight_j = pairs.w[q] * volume[j];
    sum[i][0] += weight_j * (distance[j] - dot3(normal[i], r));
    sum[i][1] += weight_j;
    if (gather_j(j)) {
      const double weight_i = pairs.w[q] * volume[i];
      sum[j][0] += weight_i * (distance[i] + dot3(normal[j], r));
      sum[j][1] += weight_i;
    }
  }
  if (newton) exchange.reverse(SPHCommStage().rows(sum, 2));
  for (int i = 0; i < nlocal; i++)
    if (near[i] != 0.0) distance[i] = std::max(sum[i][0] / sum[i][1], closest);
  exchange.forward(distance_stage);
}

/* 'distance d_name': each atom near an interface takes its distance from
   the per-atom property (the geometry's, e.g. from tools/sph_boundary.py
   or a variable), which must be positive and finite there */

void SPHInterfaceDistance::take_given(SPHExchange &exchange)
{
  const double *const given = atom->dvector[given_index];
  // the lowest ID of an atom with a bad distance, on every rank (error->all:
  // error->one's message can be lost with the abort)
  SPHCheck::FirstBad bad;
  for (int i = 0; i < atom->nlocal; i++) {
    if (near_of[i] == 0.0) {
      distance[i] = NONE;
      continue;
    }
    if (!(given[i] > 0.0) || !std::isfinite(given[i])) bad.consider(atom->tag[i], given[i]);
    distance[i] = given[i];
  }
  if (bad.agree(lmp))
    error->all(FLERR,
               "Pair style sph/cleary/heat: atom {} has an atom of another conductivity within "
               "the kernel support, but its distance {} from the interface is {} (must be > 0)",
               bad.tag, given_name, bad.info[0]);
  exchange.forward(SPHCommStage().flat(distance, 1));
}

void SPHInterfaceDistance::report() const
{
  bigint near = 0, near_all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (distance[i] != NONE) near++;
  MPI_Allreduce(&near, &near_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "Pair style sph/cleary/heat: mean interface: {} atoms have an atom of "
                   "another conductivity within the kernel support\n",
                   near_all);
}
