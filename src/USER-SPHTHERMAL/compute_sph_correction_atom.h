/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/correction/atom,ComputeSPHCorrectionAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_CORRECTION_ATOM_H
#define LMP_COMPUTE_SPH_CORRECTION_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

// Per atom: 1 where pair sph/cleary/heat's 'correction consistent' corrects
// the atom's pair terms, 0 where the atom keeps the plain term (incomplete
// kernel support), as of the pair's last evaluation; with 'interface' the
// atom's distance from the interface of 'mean interface' (-1: none within
// the kernel support).
class ComputeSPHCorrectionAtom : public Compute {
 public:
  ComputeSPHCorrectionAtom(class LAMMPS *, int, char **);
  ~ComputeSPHCorrectionAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 protected:
  int nmax;
  double *state;
  class PairSPHClearyHeat *pair;    // its per-atom states are shown
  int interface;          // 1: the pair's "interface_distance" instead
};

}    // namespace LAMMPS_NS

#endif
#endif
