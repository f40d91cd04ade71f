/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/heatflux/atom,ComputeSPHHeatfluxAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_HEATFLUX_ATOM_H
#define LMP_COMPUTE_SPH_HEATFLUX_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeSPHHeatfluxAtom : public Compute {
 public:
  ComputeSPHHeatfluxAtom(class LAMMPS *, int, char **);
  ~ComputeSPHHeatfluxAtom() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void compute_peratom() override;
  double compute_scalar() override;
  double memory_usage() override;

 protected:
  int corrected;              // first-order corrected gradient
  int has_normals;            // wall flux of eq 9 wanted
  int normal_xyz[3];          // indices of the custom per-atom doubles holding the normal
  double spacing;             // particle spacing, for the wall heat rate
  int nmax;
  double **flux;
  class NeighList *list;
  class FixSPHMaterials *materials;
  int kernel_kind;
  double cutoff, eta2;
};

}    // namespace LAMMPS_NS

#endif
#endif
