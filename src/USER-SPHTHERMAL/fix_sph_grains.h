/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/grains,FixSPHGrains);
// clang-format on
#else

#ifndef LMP_FIX_SPH_GRAINS_H
#define LMP_FIX_SPH_GRAINS_H

#include "fix.h"
#include "sph_kernels.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

// Unresolved grains (LAMMPS's granular particles, smaller than the kernel's
// support) in an SPH fluid: at each grain the fluid's velocity,
// temperature, properties and pressure gradient interpolated by the flow's
// kernel, the drag, the pressure-gradient force and the heat exchange of
// sph_grain_laws.h on the grain, and each of them, with the opposite sign,
// shared among the fluid particles around it in proportion to V_j W_ij, so
// that the momentum and the heat of fluid plus grains are exchanged to
// round-off.
class FixSPHGrains : public Fix {
 public:
  FixSPHGrains(class LAMMPS *, int, char **);
  ~FixSPHGrains() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;

 private:
  std::string fluid_name;    // the fluid group
  int fluid_groupbit;
  int drag_kind;    // SPHG_DRAG_* of sph_grain_laws.h
  int heat_kind;    // SPHG_HEAT_*
  class NeighList *list;
  class FixSPHMaterials *materials;
  sphk_kernel kernel;
  double cutsq;
  // per atom, owned and ghost: the force (3) and the heat (1) that the
  // grains give it, sent back to the owners
  double **reaction;
  int nmax;
  // per atom, owned: a grain's slip u - v (3), porosity and the fluid's
  // temperature at it, this step's (zero for other atoms and for a grain
  // with no fluid around)
  double **at_grain;
  // the fluid neighbours of the grain in hand and their weights V_j W_ij
  std::vector<std::pair<int, double>> shares;
  // this step's force of the fluid on the grains (3), the heat into them,
  // the grains with no fluid within the kernel's support, the smallest
  // porosity at a grain: this rank's, and all ranks' when asked
  double local[6], totals[6];
  bigint totals_step;

  void exchange();
  void check_atom_style() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
