/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/nusselt,ComputeSPHNusselt);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_NUSSELT_H
#define LMP_COMPUTE_SPH_NUSSELT_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

// The Nusselt number of a wall of prescribed temperature, Nu = q L / (k dT)
// with q the heat flux from the wall into the medium: from the heat the
// wall fix tallies (the energy method of Cleary 1998, eq 10) and, for a
// wall with a surface, from the wall-normal temperature gradient on it
// (Reece et al. 2024, eq 37). Mean over the wall and local per wall atom.
class ComputeSPHNusselt : public Compute {
 public:
  ComputeSPHNusselt(class LAMMPS *, int, char **);
  ~ComputeSPHNusselt() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 protected:
  std::string wall_id;
  class FixSPHWallTally *wall;
  class FixSPHWallDirichlet *wall_surface;    // the wall, when it has a surface
  double delta_t, length, conductivity, area, spacing;
  int conductivity_type;    // > 0: the conductivity of this type in the materials hub
  int nmax;
  int surface_checked;    // 0 until the first evaluation of a run has looked at the surface
  int staircase_warned;   // the staircase warning was given (once per compute)
  double staircase_spacing;    // > 0: the wall is a staircase; its particles' spacing
  double **local;        // per atom, with a surface: local Nu from the heat, from the gradient
  double *local_heat;    // per atom, without: local Nu from the heat

  void find_wall();
  double first_layer_depth();
  double wall_spacing(double depth_min);
  void grow_local();
  void gradient_values(double depth_min);
  void check_surface(double depth_min);
};

}    // namespace LAMMPS_NS

#endif
#endif
