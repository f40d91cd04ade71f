/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/wall/adami,FixSPHWallAdami);
// clang-format on
#else

#ifndef LMP_FIX_SPH_WALL_ADAMI_H
#define LMP_FIX_SPH_WALL_ADAMI_H

#include "fix.h"

namespace LAMMPS_NS {

class FixSPHWallAdami : public Fix {
 public:
  FixSPHWallAdami(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

 protected:
  double body[3];            // body acceleration of the fluid minus that of the wall
  int body_given;            // 1: 'body' in the command; 0: the run's body force
  const double *body_force;  // the run's body force (fix gravity), nullptr when none
  int wall_groupbit;      // particles of every sph/wall/adami fix
  int kernel_kind;
  double cutoff;
  class FixSPHMaterials *materials;
  class NeighList *list;
};

}    // namespace LAMMPS_NS

#endif
#endif
