/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_THREADS_H
#define LMP_SPH_THREADS_H

#if defined(_OPENMP)
#include <omp.h>
#endif

#include <algorithm>
#include <cstddef>
#include <vector>

namespace LAMMPS_NS {

// The package's passes outside the pair loops (the conduction's factors,
// the mirror walls) on the threads of 'package omp' (comm->nthreads, 1
// without it): sph_parallel() runs a pass on every thread, each taking a
// contiguous slice of the items. Without OpenMP (a LAMMPS with the package
// built in but without OpenMP) every pass runs on one thread.

inline int sph_thread_id()
{
#if defined(_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}

// the slice [from, to) of n items that thread tid of nthreads takes
template <typename Index>
inline void sph_thread_slice(Index n, int nthreads, int tid, Index &from, Index &to)
{
  const Index chunk = (n + nthreads - 1) / nthreads;
  from = std::min((Index) tid * chunk, n);
  to = std::min(from + chunk, n);
}

// slices of a neighbour list's entries with about as many neighbours each
// (wall atoms, whose wall neighbours are excluded, have few): thread t takes
// entries [bounds[t], bounds[t + 1]), whose neighbours come after
// before[t] neighbours of the entries before; returns the neighbours of all
inline int sph_neighbour_slices(const int *ilist, const int *numneigh, int inum, int nthreads,
                                std::vector<int> &bounds, std::vector<int> &before)
{
  int total = 0;
  for (int ii = 0; ii < inum; ii++) total += numneigh[ilist[ii]];
  bounds.assign(nthreads + 1, inum);
  before.assign(nthreads + 1, total);
  bounds[0] = before[0] = 0;
  int ii = 0, sum = 0;
  for (int t = 1; t < nthreads; t++) {
    const double target = (double) total * t / nthreads;
    while (ii < inum && sum < target) sum += numneigh[ilist[ii++]];
    bounds[t] = ii;
    before[t] = sum;
  }
  return total;
}

// slices of n items of about equal work, where item i's work is
// offset[i + 1] - offset[i]: thread t takes [bounds[t], bounds[t + 1])
inline void sph_work_slices(const int *offset, int n, int nthreads, std::vector<int> &bounds)
{
  bounds.assign(nthreads + 1, n);
  bounds[0] = 0;
  for (int t = 1; t < nthreads; t++)
    bounds[t] =
        std::lower_bound(offset, offset + n, (int) ((double) offset[n] * t / nthreads)) - offset;
}

// body(tid) on each of nthreads threads (on the caller's alone for one)
template <class Body> inline void sph_parallel(int nthreads, Body body)
{
  if (nthreads < 2) {
    body(0);
    return;
  }
#if defined(_OPENMP)
#pragma omp parallel num_threads(nthreads)
  body(sph_thread_id());
#else
  body(0);
#endif
}

// body(i) for i in [0, n), each thread its slice
template <class Body> inline void sph_parallel_for(int n, int nthreads, Body body)
{
  sph_parallel(nthreads, [&](int tid) {
    int from, to;
    sph_thread_slice(n, nthreads, tid, from, to);
    for (int i = from; i < to; i++) body(i);
  });
}

// Sums that every thread adds to at any atom (pair terms scattered to both
// atoms): thread 0 adds to the target itself, every other thread to a zeroed
// copy of its own, and reduce() then adds the copies to the target in
// thread order. A run on n threads repeats itself exactly; it differs from
// a run on one thread by round-off.
class SPHThreadSums {
 public:
  // outside the parallel region: room for 'size' values per thread
  void fit(std::size_t size, int nthreads)
  {
    this->size = size;
    if (nthreads > 1) copies.resize(size * (nthreads - 1));
  }
  // in thread tid: the values it adds to (tid 0: the target, which the
  // caller zeroes; the others: their own copy, zeroed here)
  double *of(double *target, int tid)
  {
    if (tid == 0) return target;
    double *const copy = copies.data() + (tid - 1) * size;
    std::fill(copy, copy + size, 0.0);
    return copy;
  }
  // in every thread, after its additions: the copies added to the target,
  // each thread a slice of it; the target is whole when this returns
  void reduce(double *target, int nthreads, int tid)
  {
    if (nthreads < 2) return;
#if defined(_OPENMP)
#pragma omp barrier
#endif
    std::size_t from, to;
    sph_thread_slice(size, nthreads, tid, from, to);
    for (int t = 1; t < nthreads; t++) {
      const double *const copy = copies.data() + (t - 1) * size;
      for (std::size_t k = from; k < to; k++) target[k] += copy[k];
    }
#if defined(_OPENMP)
#pragma omp barrier
#endif
  }
  double memory_usage() const
  {
    return (double) copies.capacity() * sizeof(double);
  }

 private:
  std::size_t size = 0;
  std::vector<double> copies;
};

}    // namespace LAMMPS_NS

#endif
