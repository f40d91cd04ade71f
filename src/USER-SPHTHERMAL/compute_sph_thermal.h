/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/thermal,ComputeSPHThermal);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_THERMAL_H
#define LMP_COMPUTE_SPH_THERMAL_H

#include "compute.h"

namespace LAMMPS_NS {

// The thermal books of a group: its thermal energy, heat capacity,
// heat-capacity-weighted mean temperature and heating rate, for thermo;
// and per atom its temperature, for dumps (sph_particle.h: MACHDYN solids
// included, whose T is not esph / cv).
class ComputeSPHThermal : public Compute {
 public:
  ComputeSPHThermal(class LAMMPS *, int, char **);
  ~ComputeSPHThermal() override;
  void init() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 protected:
  int nmax;
  double *temperature;    // per atom
};

}    // namespace LAMMPS_NS

#endif
#endif
