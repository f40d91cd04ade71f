/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/surface/flux,FixSPHSurfaceFlux);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SURFACE_FLUX_H
#define LMP_FIX_SPH_SURFACE_FLUX_H

#include "fix.h"

namespace LAMMPS_NS {

class FixSPHSurfaceFlux : public Fix {
 public:
  FixSPHSurfaceFlux(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void reset_dt() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  double compute_scalar() override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  int convective;       // 0: q given; 1: q = h (T_inf - T)
  double q_given;       // prescribed flux into the surface (power/area)
  double h_transfer;    // heat transfer coefficient
  double t_ambient;     // T_inf
  double area;          // surface area per particle, spacing^(d-1)
  double spacing;
  double dt_half;
  double rate_previous, energy;
  class FixSPHMaterials *materials;    // the hub, when there is one

  void add_flux(int first);
};

}    // namespace LAMMPS_NS

#endif
#endif
