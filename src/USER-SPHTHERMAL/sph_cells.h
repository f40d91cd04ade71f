/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_CELLS_H
#define LMP_SPH_CELLS_H

#include <cmath>
#include <vector>

namespace LAMMPS_NS {

// Cells of a given side over a subset of a rank's atoms (owned and ghost),
// for styles that need the atoms near a few points (wall particles, their
// mirror points) without a neighbour list over every atom: the points ask
// at each neighbour-list build for the atoms within cutoff + skin and keep
// them until the next build, as LAMMPS's own lists do.
class SPHCells {
 public:
  // bins the atoms j < nall with (mask[j] & skip) == 0 for searches within
  // 'reach': in cells of half of it, 25 cells around a point in 2-D hold
  // 2.0 times the atoms within reach (cells of the reach: 2.9 times)
  void bin(const double *const *x, const int *mask, int nall, int skip, double reach)
  {
    side = 0.5 * reach;
    double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0};
    bool any = false;
    for (int j = 0; j < nall; j++) {
      if (mask[j] & skip) continue;
      for (int k = 0; k < 3; k++) {
        if (!any || x[j][k] < lo[k]) lo[k] = x[j][k];
        if (!any || x[j][k] > hi[k]) hi[k] = x[j][k];
      }
      any = true;
    }
    long total = 1;
    for (int k = 0; k < 3; k++) {
      origin[k] = lo[k];
      ncell[k] = 1 + static_cast<int>((hi[k] - lo[k]) / side);
      total *= ncell[k];
    }
    head.assign(total, -1);
    next.assign(nall, -1);
    for (int j = 0; j < nall; j++) {
      if (mask[j] & skip) continue;
      int c[3];
      for (int k = 0; k < 3; k++) c[k] = static_cast<int>((x[j][k] - origin[k]) / side);
      const long cell = (static_cast<long>(c[2]) * ncell[1] + c[1]) * ncell[0] + c[0];
      next[j] = head[cell];
      head[cell] = j;
    }
  }

  // the binned atoms within 'reach' of each point i < npoints (point(i):
  // its coordinates, nullptr for none) that accept(j), each atom once in
  // 'atoms': near[n] for n in [first[i], first[i + 1]) indexes it
  template <class Point, class Accept>
  void near_points(const double *const *x, int npoints, int nall, double reach, Point point,
                   Accept accept, std::vector<int> &first, std::vector<int> &near,
                   std::vector<int> &atoms) const
  {
    first.assign(npoints + 1, 0);
    near.clear();
    atoms.clear();
    std::vector<int> index(nall, -1);    // an atom's place in atoms, -1: not yet there
    for (int i = 0; i < npoints; i++) {
      first[i] = near.size();
      const double *p = point(i);
      if (!p) continue;
      within(x, p, reach, [&](int j) {
        if (!accept(j)) return;
        if (index[j] < 0) {
          index[j] = atoms.size();
          atoms.push_back(j);
        }
        near.push_back(index[j]);
      });
    }
    first[npoints] = near.size();
  }

  // visit(j) for each binned atom within 'reach' of p
  template <class Visit> void within(const double *const *x, const double *p, double reach,
                                     Visit visit) const
  {
    const double reachsq = reach * reach;
    int lo[3], hi[3];
    for (int k = 0; k < 3; k++) {
      lo[k] = static_cast<int>(std::floor((p[k] - reach - origin[k]) / side));
      hi[k] = static_cast<int>(std::floor((p[k] + reach - origin[k]) / side));
      if (lo[k] < 0) lo[k] = 0;
      if (hi[k] > ncell[k] - 1) hi[k] = ncell[k] - 1;
    }
    for (int cz = lo[2]; cz <= hi[2]; cz++)
      for (int cy = lo[1]; cy <= hi[1]; cy++)
        for (int cx = lo[0]; cx <= hi[0]; cx++)
          for (int j = head[(static_cast<long>(cz) * ncell[1] + cy) * ncell[0] + cx]; j >= 0;
               j = next[j]) {
            const double d[3] = {x[j][0] - p[0], x[j][1] - p[1], x[j][2] - p[2]};
            if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= reachsq) continue;
            visit(j);
          }
  }

 private:
  double side = 1.0;
  double origin[3] = {0.0, 0.0, 0.0};
  int ncell[3] = {1, 1, 1};
  std::vector<int> head, next;
};

}    // namespace LAMMPS_NS

#endif
