/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/heatflow,FixSPHHeatflow);
// clang-format on
#else

#ifndef LMP_FIX_SPH_HEATFLOW_H
#define LMP_FIX_SPH_HEATFLOW_H

#include "fix.h"

#include <string>

namespace LAMMPS_NS {

// The heat conducted into a group from another (pair sph/cleary/heat):
// the power now and the energy since the fix was defined.
class FixSPHHeatflow : public Fix {
 public:
  FixSPHHeatflow(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void reset_dt() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 protected:
  std::string from_name;
  int from_groupbit;
  class PairSPHClearyHeat *pair;
  int flow_index;
  double dt_half;
  double power_previous, power, energy;

  void tally(int first);
};

}    // namespace LAMMPS_NS

#endif
#endif
