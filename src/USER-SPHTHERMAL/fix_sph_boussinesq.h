/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/boussinesq,FixSPHBoussinesq);
// clang-format on
#else

#ifndef LMP_FIX_SPH_BOUSSINESQ_H
#define LMP_FIX_SPH_BOUSSINESQ_H

#include "fix.h"
#include "sph_body_force.h"

namespace LAMMPS_NS {

// Buoyancy of a fluid in the Boussinesq approximation: f = -m g beta (T - T0)
// on every atom of the group, beta per type from fix sph/materials.
class FixSPHBoussinesq : public Fix {
 public:
  FixSPHBoussinesq(class LAMMPS *, int, char **);
  ~FixSPHBoussinesq() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  // the buoyancy it adds: read by the styles that need the body force of
  // each atom (SPHBodyForce::find_buoyancy)
  const SPHBodyForce::Buoyancy &added_buoyancy() const { return buoyancy; }

 protected:
  double gravity_given[3];    // the 'gravity' keyword's vector
  int gravity_keyword;        // 1 when given
  int reference_mean;         // T0 'mean': updated every step (update_mean_reference)
  double *beta;               // expansion coefficient per type
  SPHBodyForce::Buoyancy buoyancy;
  double force_local[3], force_total[3];
  int force_summed;
  int zero_warned;            // the warning of fix gravity's magnitude 0 given
  int compression_checked;    // check_compression() done (at the first setup)
  void check_compression();
  void update_mean_reference();
};

}    // namespace LAMMPS_NS

#endif
#endif
