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
  void post_constructor() override;
  void init_list(int, class NeighList *) override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void setup(int) override;
  void post_force(int) override;
  double compute_vector(int) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;

 private:
  std::string fluid_name;    // the fluid group
  int fluid_groupbit;
  int drag_kind;                         // SPHG_DRAG_* of sph_grain_laws.h
  int heat_kind;                         // SPHG_HEAT_*
  int pressure_kind;                     // SPHG_PRESSURE_*: the fluid's force on a grain
  const double *body_force = nullptr;    // g of the hydrostatic form, nullptr: none
  class NeighList *list;
  class FixSPHMaterials *materials;
  sphk_kernel kernel;
  double cutsq;
  // per atom, owned and ghost: the force (3) and the heat (1) that the
  // grains give it and its share of their drag coefficients beta (1),
  // sent back to the owners
  static constexpr int REACTION_VALUES = 5;
  double **reaction;
  int nmax;
  // per atom, owned: a grain's slip u - v (3), porosity and the fluid's
  // temperature at it, this step's (zero for other atoms and for a grain
  // with no fluid around)
  double **at_grain;
  // the fluid neighbours of the grain in hand, their weights V_j W_ij in
  // the interpolation and the momentum's shares, and in the heat's (0 for
  // a neighbour across the plane of a periodic inlet)
  struct Share {
    int atom;
    double weight, heat_weight, temperature;
  };
  std::vector<Share> shares;
  int inlet_axis = -1;    // the flow axis of fix sph/inlet/temperature, -1 without one
  // this step's force of the fluid on the grains (3), the heat into them,
  // the grains with no fluid within the kernel's support, the smallest
  // porosity at a grain: this rank's, and all ranks' when asked
  double local[6], totals[6];
  bigint totals_step;

  // 'fill yes': the fluid around grains placed in it is given the pores'
  // share of its mass once (filled: done, also before a restart)
  int fill, filled;
  // the fluid's porosity (SPHParticles::POROSITY_VECTOR), of an internal
  // fix property/atom made by this fix
  double *porosity;
  int porosity_fix_made = 0;
  // what the reverse communication carries: the grains' volume fractions
  // (1 value) or the reactions (4)
  enum { REVERSE_REACTION, REVERSE_POROSITY } reverse_mode;

  std::string porosity_fix_id() const;
  void refresh_arrays();
  void update_porosity();
  void fill_pores();
  void exchange();
  void check_atom_style() const;
  void warn_weightless_fluid();
};

}    // namespace LAMMPS_NS

#endif
#endif
