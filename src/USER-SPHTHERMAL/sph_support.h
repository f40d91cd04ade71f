/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_SUPPORT_H
#define LMP_SPH_SUPPORT_H

#include "lmptype.h"

#include <cstddef>
#include <vector>

namespace LAMMPS_NS {

// Room for the entries of a neighbour (or candidate) list that lie inside
// the kernel's support, gathered before the pair terms. About a third of a
// list's entries lie in the skin, and a branch per entry on the cutoff is
// mispredicted that often: a loop writes every entry at position n and
// advances n only for those inside, then computes the square roots and
// kernel values of the n kept entries together, which the compiler
// vectorises (sph_kernels.h). A loop keeps one per call: OpenMP styles
// call their loops once per thread.
class SPHSupport {
 public:
  int *index = nullptr;     // per entry: the atom (or candidate) index
  double *del = nullptr;    // its separation, 3 per entry
  double *rsq = nullptr;    // its square
  double *a = nullptr;      // two kernel values per entry, as the loop
  double *b = nullptr;      // needs them

  // the entries j of a neighbour list with |x_i - x_j|^2 < cutsq: their
  // index and rsq, and x_i - x_j when DEL; returns how many
  template <int DIM, bool DEL>
  int gather(const double *xi, const double *const *x, const int *jlist, int jnum, double cutsq)
  {
    fit(jnum);
    int *const j_of = index;
    double *const del_of = del;
    double *const rsq_of = rsq;
    int n = 0;
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xi[0] - x[j][0];
      const double dely = xi[1] - x[j][1];
      const double delz = (DIM == 3) ? xi[2] - x[j][2] : 0.0;
      const double r2 = delx * delx + dely * dely + delz * delz;
      // written at every entry, kept (n advanced) only inside the support
      j_of[n] = j;
      if (DEL) {
        del_of[3 * n] = delx;
        del_of[3 * n + 1] = dely;
        del_of[3 * n + 2] = delz;
      }
      rsq_of[n] = r2;
      n += (r2 < cutsq);
    }
    return n;
  }

  // room for n entries
  void fit(int n)
  {
    if ((int) index_store.size() >= n) return;
    index_store.resize(n);
    del_store.resize(3 * (size_t) n);
    rsq_store.resize(n);
    a_store.resize(n);
    b_store.resize(n);
    index = index_store.data();
    del = del_store.data();
    rsq = rsq_store.data();
    a = a_store.data();
    b = b_store.data();
  }

 private:
  std::vector<int> index_store;
  std::vector<double> del_store, rsq_store, a_store, b_store;
};

}    // namespace LAMMPS_NS

#endif
