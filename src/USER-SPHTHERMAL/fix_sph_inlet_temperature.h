/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/inlet/temperature,FixSPHInletTemperature);
// clang-format on
#else

#ifndef LMP_FIX_SPH_INLET_TEMPERATURE_H
#define LMP_FIX_SPH_INLET_TEMPERATURE_H

#include "domain.h"
#include "fix.h"

#include <cmath>

namespace LAMMPS_NS {

// The inlet temperature of a channel that is periodic along the flow (Ng et
// al. 2020, section 3.2): a particle of the group that leaves through the
// outlet re-enters at the inlet with T_inlet; heat crosses the periodic
// plane only into the group's particles on the inlet side, which see every
// neighbour across the plane at T_inlet (held) or at its mirror value
// 2 T_inlet - T(mirror point) (mirror); nothing else crosses it.
class FixSPHInletTemperature : public Fix {
 public:
  FixSPHInletTemperature(class LAMMPS *, int, char **);
  ~FixSPHInletTemperature() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup_pre_reverse(int, int) override;
  void pre_reverse(int, int) override;
  void post_integrate() override;
  void post_run() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  // 0, 1, 2 for the flow along x, y, z (the styles that interpolate near
  // the plane keep to one side of it)
  int flow_axis() const { return axis; }

  // the periodic image of the box that a coordinate along 'axis' lies in
  // (ghost images across the plane lie in the next ones): which side of the
  // inlet plane a point is on, for this fix and the styles that keep to one
  // side of it
  static double periodic_cell(const Domain *domain, double coord, int axis)
  {
    return floor((coord - domain->boxlo[axis]) / domain->prd[axis]);
  }
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  double memory_usage() override;

 protected:
  double t_inlet;
  int axis;                         // 0, 1, 2: x, y, z
  int downstream;                   // +1 or -1: the flow's direction along the axis
  int cuts_plane;                   // 1 for the first fix of this style: it removes the pairs across
  int mirror;                       // 1: the neighbours across are mirrored, 0: held at T_inlet
  class NeighList *list;            // full: the inlet side's neighbours, both sides of the plane
  class PairSPHClearyHeat *pair;
  double rate_previous, rate;       // heat rate through the inlet plane (all ranks)
  double energy_reset;              // energy the re-entering particles' resets added
  double energy_plane;              // energy that came in through the inlet plane
  // per atom: how often it has passed the outlet (image flag plus periodic
  // cell along the axis, unchanged when LAMMPS wraps it), when last looked
  double *passes;
  // the passes of this run through the plane along the flow (resets) and
  // against it, this rank; whether the group's mean velocity against the
  // flow was reported
  bigint crossed_along, crossed_against;
  int against_warned;

  double passes_now(int i) const;

  void correct_pairs(int first);
  void remove_plane_pairs();
  template <int MIRROR> double inlet_terms();
  void temperature_gradient(int i, double cell_i, double *grad) const;
  void check_direction();
};

}    // namespace LAMMPS_NS

#endif
#endif
