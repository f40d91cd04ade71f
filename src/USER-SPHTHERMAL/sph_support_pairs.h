/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SUPPORT_PAIRS_H
#define LMP_SPH_SUPPORT_PAIRS_H

#include "neigh_list.h"
#include "sph_consistent.h"
#include "sph_kernels.h"
#include "sph_threads.h"

#include <cmath>
#include <vector>

namespace LAMMPS_NS {

// The pairs of a half neighbour list that lie inside the kernel support,
// stored with the list: entry ii of the list owns the pairs
// [first[ii], stop[ii]), in the order of its neighbours. Made when the
// particles move and read by the conduction weights, the interface
// estimate and the pair loop, which finds the pairs of its slice of the
// list (a thread's) at first[ii]. One array per quantity, so that a pass
// streams only what it reads (the loop: the weights). With threads, each
// gathers the pairs of its slice of the list into a block of its own;
// passes over all pairs go block by block (each thread its block).
class SPHSupportPairs {
 public:
  struct Block {
    int begin, end;
  };
  std::vector<int> first, stop;    // per list entry
  std::vector<Block> blocks;       // one per thread of the gather, in list order
  std::vector<int> i, j;
  std::vector<double> r;           // x_i - x_j, 3 per pair
  std::vector<double> distance;    // |r|
  std::vector<double> dwdr, w;     // the kernel's dW/dr and W at that distance (W: with_w)
  std::vector<double> g;           // the plain weight V_i V_j (-r dW/dr) / (r^2 + eta^2)
  std::vector<double> weight;      // the factor w_ij of a correction (SPHConductionWeights)

  int count() const
  {
    int n = 0;
    for (const Block &b : blocks) n += b.end - b.begin;
    return n;
  }
  int threads() const { return (int) blocks.size(); }

  // every pair's index, block by block: for (int q : pairs.all()) (the
  // passes that stay on one thread)
  class Indices {
   public:
    class iterator {
     public:
      iterator(const std::vector<Block> &blocks, size_t b) : blocks(blocks), b(b), q(0)
      {
        settle();
      }
      int operator*() const { return q; }
      iterator &operator++()
      {
        if (++q == blocks[b].end) {
          b++;
          settle();
        }
        return *this;
      }
      bool operator!=(const iterator &other) const { return b != other.b || q != other.q; }

     private:
      const std::vector<Block> &blocks;
      size_t b;
      int q;
      // at the first pair of block b or a later one, or at the end (b = size, q = 0)
      void settle()
      {
        while (b < blocks.size() && blocks[b].begin == blocks[b].end) b++;
        q = (b < blocks.size()) ? blocks[b].begin : 0;
      }
    };
    explicit Indices(const std::vector<Block> &blocks) : blocks(blocks) {}
    iterator begin() const { return iterator(blocks, 0); }
    iterator end() const { return iterator(blocks, blocks.size()); }

   private:
    const std::vector<Block> &blocks;
  };
  Indices all() const { return Indices(blocks); }
  const double *r_of(int q) const { return &r[3 * (size_t) q]; }

  // the pairs of 'list' within 'cutsq' for positions x, with volume V of
  // every owned and ghost atom, and W where 'with_w' (its only reader is the
  // interface estimate); where 'near' is given, only the pairs with
  // near[i] or near[j] non-zero (the factors are a correction's to write).
  // Where 'moments' is given (6 per owned and ghost atom, zeroed), each
  // pair's second moment g r (x) r is added to its atoms' rows (j's where
  // j < nlocal or with newton), while the atom's pairs are in cache; DIM
  // the dimension (2: the moments' z entries left alone); on nthreads threads
  template <int KERNEL, int DIM>
  void gather(const NeighList *list, const double *const *x, const sphk_kernel &kernel,
              double cutsq, double eta2, const double *volume, bool with_w, const double *near,
              double *moments = nullptr, int nlocal = 0, int nall = 0, int newton = 1,
              int nthreads = 1)
  {
    const int inum = list->inum;
    // each thread's slice of the list, and room for its pairs: its atoms' neighbours
    fit(sph_neighbour_slices(list->ilist, list->numneigh, inum, nthreads, slices, before));
    blocks.resize(nthreads);
    for (int t = 0; t < nthreads; t++) blocks[t].begin = before[t];
    first.resize(inum);
    stop.resize(inum);
    if (moments) moment_sums.fit(6 * (size_t) nall, nthreads);
    sph_parallel(nthreads, [&](int tid) {
      double *const moments_thr = moments ? moment_sums.of(moments, tid) : nullptr;
      blocks[tid].end = gather_slice<KERNEL, DIM>(list, slices[tid], slices[tid + 1],
                                                  blocks[tid].begin, x, kernel, cutsq, eta2, volume,
                                                  with_w, near, moments_thr, nlocal, newton);
      if (moments) moment_sums.reduce(moments, nthreads, tid);
    });
  }

  double memory_usage() const
  {
    return (double) i.capacity() * (2 * sizeof(int) + 9 * sizeof(double)) +
        (double) (first.capacity() + stop.capacity()) * sizeof(int) + moment_sums.memory_usage();
  }

 private:
  SPHThreadSums moment_sums;
  std::vector<int> slices, before;    // the threads' slices of the list (sph_threads.h)

  // the pairs of list entries [from, to) from position n on; returns the
  // position after the last
  template <int KERNEL, int DIM>
  int gather_slice(const NeighList *list, int from, int to, int n, const double *const *x,
                   const sphk_kernel &kernel, double cutsq, double eta2, const double *volume,
                   bool with_w, const double *near, double *moments, int nlocal, int newton)
  {
    for (int ii = from; ii < to; ii++) {
      const int atom_i = list->ilist[ii];
      const int *const jlist = list->firstneigh[atom_i];
      const int jnum = list->numneigh[atom_i];
      first[ii] = n;
      // with 'near', the atoms far from it skip their neighbours that are
      // too (most pairs, with the interface alone: an early branch is cheaper)
      const bool skip_far = near && near[atom_i] == 0.0;
      // every entry written at position n, kept (n advanced) only inside
      for (int jj = 0; jj < jnum; jj++) {
        const int atom_j = jlist[jj] & NEIGHMASK;
        if (skip_far && near[atom_j] == 0.0) continue;
        double *const r_n = &r[3 * (size_t) n];
        r_n[0] = x[atom_i][0] - x[atom_j][0];
        r_n[1] = x[atom_i][1] - x[atom_j][1];
        r_n[2] = x[atom_i][2] - x[atom_j][2];
        const double rsq = r_n[0] * r_n[0] + r_n[1] * r_n[1] + r_n[2] * r_n[2];
        i[n] = atom_i;
        j[n] = atom_j;
        distance[n] = rsq;
        n += (rsq < cutsq);
      }
      stop[ii] = n;
      // the kernel values of this atom's pairs together (vectorised)
      for (int q = first[ii]; q < n; q++) {
        const double rr = sqrt(distance[q]);
        distance[q] = rr;
        dwdr[q] = kernel.dw_scale * sphk_df(KERNEL, rr * kernel.inv_h);
        g[q] = volume[i[q]] * volume[j[q]] * sphc_brookshaw_weight(rr, dwdr[q], eta2);
      }
      if (with_w)
        for (int q = first[ii]; q < n; q++)
          w[q] = kernel.w_scale * sphk_f(KERNEL, distance[q] * kernel.inv_h);
      if (moments) {
        // atom_i's row in registers over its pairs (no other pair adds to
        // it here): the same sums, without a store and reload per pair
        double *const row_i = moments + 6 * (size_t) atom_i;
        double moment_i[6];
        for (int k = 0; k < 6; k++) moment_i[k] = row_i[k];
        for (int q = first[ii]; q < n; q++) {
          sphc_moment_add_in(DIM, moment_i, g[q], r_of(q));
          if (newton || j[q] < nlocal)
            sphc_moment_add_in(DIM, moments + 6 * (size_t) j[q], g[q], r_of(q));
        }
        for (int k = 0; k < 6; k++) row_i[k] = moment_i[k];
      }
    }
    return n;
  }

  void fit(int n)
  {
    if ((int) i.size() >= n) return;
    i.resize(n);
    j.resize(n);
    r.resize(3 * (size_t) n);
    distance.resize(n);
    dwdr.resize(n);
    w.resize(n);
    g.resize(n);
    weight.resize(n);
  }
};

}    // namespace LAMMPS_NS

#endif
