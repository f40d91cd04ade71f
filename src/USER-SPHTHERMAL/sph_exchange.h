/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_EXCHANGE_H
#define LMP_SPH_EXCHANGE_H

#include "sph_comm_stage.h"

namespace LAMMPS_NS {

// How a component that is not a style (the conduction weights) moves its
// per-atom values between owners and ghosts: LAMMPS communicates for pairs
// and fixes only, so the style that holds the component does it for the
// component's stages.
class SPHExchange {
 public:
  // the owners' values of 'stage' copied to their ghosts
  virtual void forward(const SPHCommStage &stage) = 0;
  // the ghosts' values of 'stage' combined into their owners' (newton on)
  virtual void reverse(const SPHCommStage &stage) = 0;

 protected:
  ~SPHExchange() = default;
};

}    // namespace LAMMPS_NS

#endif
