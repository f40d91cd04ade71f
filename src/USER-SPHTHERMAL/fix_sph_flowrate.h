/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/flowrate,FixSPHFlowRate);
// clang-format on
#else

#ifndef LMP_FIX_SPH_FLOWRATE_H
#define LMP_FIX_SPH_FLOWRATE_H

#include "fix.h"

namespace LAMMPS_NS {

// A body force along one axis on a group (the fluid of a periodic
// channel) that holds the group's mass-weighted mean velocity along that
// axis at a prescribed value: a proportional-integral controller with one
// time constant, critically damped for a free group.
class FixSPHFlowRate : public Fix {
 public:
  FixSPHFlowRate(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  int axis;           // 0, 1, 2: x, y, z
  double target;      // the mean velocity held
  double tau;         // the controller's time constant, 0 until set
  int tau_given;      // 1: given with 'relax'; 0: 100 steps of the first run
  double integral;    // the integral part of the acceleration (kept across restarts)
  double accel;       // the acceleration applied at the next force evaluation
  double mean;        // the group's mean velocity along the axis, last measured
  void measure();     // mean
  void update_accel(double dt);
};

}    // namespace LAMMPS_NS

#endif
#endif
