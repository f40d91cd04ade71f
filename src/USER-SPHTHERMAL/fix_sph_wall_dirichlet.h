/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/wall/dirichlet,FixSPHWallDirichlet);
// clang-format on
#else

#ifndef LMP_FIX_SPH_WALL_DIRICHLET_H
#define LMP_FIX_SPH_WALL_DIRICHLET_H

#include "fix_sph_wall_tally.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHWallDirichlet : public FixSPHWallTally {
 public:
  FixSPHWallDirichlet(class LAMMPS *, int, char **);
  ~FixSPHWallDirichlet() override;
  int setmask() override;
  void setup_pre_neighbor() override;
  void pre_neighbor() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void setup(int) override;
  void post_force(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

  // T_wall (pair sph/cleary/heat evaluates the dummies' conductivity there)
  double wall_temperature() const { return t_wall; }
  // with a surface: the temperature gradient along the surface normal
  // (into the medium) on the surface next to owned wall atom i, between
  // T_wall there and T at i's ghost point at 'depth' from it, as found in
  // this step's pre_force; 0 when i has no ghost point
  bool has_surface() const { return mirror != nullptr; }
  int surface_gradient(int i, double &gradient, double &depth) const;

 protected:
  double t_wall;
  int dummy_groupbit;    // particles of every sph/wall/dirichlet fix
  int kernel_kind;
  double cutoff;
  class NeighList *list;
  class SPHMirror *mirror;    // with 'surface': the ghost points; nullptr: Shepard
  std::vector<double> t_ghost;
  std::vector<int> ghost_how;
  std::vector<double> ghost_depth;

  void dummies_shepard();
  void dummies_mirrored();
};

}    // namespace LAMMPS_NS

#endif
#endif
