/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(sph/set,SPHSet);
// clang-format on
#else

#ifndef LMP_SPH_SET_H
#define LMP_SPH_SET_H

#include "command.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// The initial state of SPH particles from fix sph/materials, in a line:
// masses, densities and specific heats of the materials, temperatures,
// and a fluid at hydrostatic rest under the run's body force.
class SPHSet : public Command {
 public:
  SPHSet(class LAMMPS *lmp) : Command(lmp), groupbit(0) {}
  void command(int, char **) override;

 private:
  int groupbit;
  std::string group_name;
  class FixSPHMaterials *materials;

  void set_materials(double volume);
  void set_temperature(const std::string &value);
  std::vector<int> machdyn_solid_types();
  void set_hydrostatic(double level, bool move);
  int types_in_group(int *present);
};

}    // namespace LAMMPS_NS

#endif
#endif
