/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMMAND_CLASS
// clang-format off
CommandStyle(sph/faces,SPHFaces);
// clang-format on
#else

#ifndef LMP_SPH_FACES_H
#define LMP_SPH_FACES_H

#include "command.h"

namespace LAMMPS_NS {

// Groups of a box scene in one line: the atoms of a group inside a region,
// those outside it, and those outside it by the faces of its bounding box
// (the hot, cold and adiabatic walls of a cavity).
class SPHFaces : public Command {
 public:
  SPHFaces(class LAMMPS *lmp) : Command(lmp) {}
  void command(int, char **) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
