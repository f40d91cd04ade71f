/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/wall/adiabatic,FixSPHWallAdiabatic);
// clang-format on
#else

#ifndef LMP_FIX_SPH_WALL_ADIABATIC_H
#define LMP_FIX_SPH_WALL_ADIABATIC_H

#include "fix.h"

#include <vector>

namespace LAMMPS_NS {

// Wall particles that carry the temperature of the medium at their mirror
// points (Reece et al. 2024, eq 19), so the medium near the wall sees a full
// kernel and no heat crosses the wall surface.
class FixSPHWallAdiabatic : public Fix {
 public:
  FixSPHWallAdiabatic(class LAMMPS *, int, char **);
  ~FixSPHWallAdiabatic() override;
  int setmask() override;
  void setup_pre_neighbor() override;
  void pre_neighbor() override;
  void init() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

 protected:
  class SPHMirror *mirror;
  int conserve;       // 1: the heat the wall takes in goes back to the medium
  int deep_warned;    // the warning about wall atoms beyond reach was given
  bool wall_pairs_excluded() const;
  std::vector<double> t_ghost, rate;
  std::vector<int> ghost_how;
  double taken_local[2], taken_total[2];    // heat rate taken in now: away from, at corners
  int shepard_local, shepard_total;         // ghost points with too thin a neighbourhood
  int summed;
};

}    // namespace LAMMPS_NS

#endif
#endif
