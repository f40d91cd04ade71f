/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/force,ComputeSPHForce);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_FORCE_H
#define LMP_COMPUTE_SPH_FORCE_H

#include "compute.h"
#include "pair_sph_harmonic_visc.h"

namespace LAMMPS_NS {

// The force and torque that the rest of the particles exert on a group
// (a body, a wall) through pair style sph/harmonic/visc's momentum
// equation, with its pressure and viscous parts: drag and lift in one line.
class ComputeSPHForce : public Compute {
 public:
  ComputeSPHForce(class LAMMPS *, int, char **);
  void init() override;
  void compute_vector() override;

 protected:
  int center_given;    // 1: the torques about 'center'; 0: about the group's centre of mass
  double center[3];
  PairSPHHarmonicVisc::GroupForce request;    // what the pair sums for this compute
  double values[18];
  void centre_of_mass(double *point);
};

}    // namespace LAMMPS_NS

#endif
#endif
