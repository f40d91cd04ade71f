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

#include <string>
#include <vector>

namespace LAMMPS_NS {

// Buoyancy of a fluid in the Boussinesq approximation: f = -m g beta (T - T0)
// on every atom of the group, beta per type from fix sph/materials.
class FixSPHBoussinesq : public Fix {
 public:
  FixSPHBoussinesq(class LAMMPS *, int, char **);
  ~FixSPHBoussinesq() override;
  void post_constructor() override;
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
  enum { REFERENCE_GIVEN, REFERENCE_MEAN, REFERENCE_LAYERS };
  int reference_kind;              // T0 given, 'mean' or 'layers' (updated every step)
  double layer_given;              // the 'layer' keyword's thickness, 0 when not given
  double spacing;                  // the group's mean spacing (T0 'layers'), 0 until known
  std::vector<double> layer_t0;    // T0 'layers': the value at each layer's centre
  double *beta;                    // expansion coefficient per type
  SPHBodyForce::Buoyancy buoyancy;
  double force_local[3], force_total[3];
  int force_summed;
  int zero_warned;            // the warning of fix gravity's magnitude 0 given
  int compression_checked;    // check_compression() done (at the first setup)
  int hold_request;           // 'hold': 1 yes, 0 no, -1 the scene's default
  int hold_logged;            // the hold last logged (-1 before the first)
  std::string id_hold;        // its fix sph/hold/volume, empty with 'hold no'
  void choose_hold();
  int compression_scale(double &gnorm, double &dt_max, double &extent);
  void derive_sound_speeds(class FixSPHMaterials *materials);
  void check_compression();
  void update_mean_reference();
  double checked_mean(const double sum[3], const std::string &head);
  void update_layer_reference();
  void update_reference();
  double mean_spacing();
};

}    // namespace LAMMPS_NS

#endif
#endif
