/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_BUILD_STAMP_H
#define LMP_SPH_BUILD_STAMP_H

#include "lmptype.h"
#include "neighbor.h"
#include "update.h"

namespace LAMMPS_NS {

// The step at which per-atom values (owned and ghost atoms) were made. They
// stay the atoms' own until the next neighbour-list build, which may
// re-index the atoms, ghosts included; a run's setup makes them anew.
class SPHBuildStamp {
 public:
  void forget() { step = -1; }
  void stamp(const Update *update) { step = update->ntimestep; }
  // made at or after the last build
  bool since_build(const Neighbor *neighbor) const
  {
    return step >= 0 && step >= neighbor->lastcall;
  }
  // ... and this is not a run's setup: the values may be kept (warm starts, holds)
  bool current(const Update *update, const Neighbor *neighbor) const
  {
    return !update->setupflag && since_build(neighbor);
  }

 private:
  bigint step = -1;
};

}    // namespace LAMMPS_NS

#endif
