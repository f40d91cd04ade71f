/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/phase,FixSPHPhase);
// clang-format on
#else

#ifndef LMP_FIX_SPH_PHASE_H
#define LMP_FIX_SPH_PHASE_H

#include "fix.h"
#include "sph_phase_laws.h"

#include <vector>

namespace LAMMPS_NS {

// Melting and solidification by the enthalpy method (sph_phase_laws.h):
// the phase laws of the atom types that change phase, put on their atoms
// in the per-atom vectors that SPHParticles reads the temperature through
// (sph_particle.h); the liquid fraction per atom, the group's liquid mass
// fraction and the latent heat it holds.
class FixSPHPhase : public Fix {
 public:
  FixSPHPhase(class LAMMPS *, int, char **);
  ~FixSPHPhase() override;
  void post_constructor() override;
  int setmask() override;
  void init() override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void setup(int) override;
  void post_force(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  double memory_usage() override;
  void grow_arrays(int) override;

  // the phase law of type t, or nullptr where it does not change phase
  const SPHPhaseLaw *law(int t) const { return changes[t] ? &laws[t] : nullptr; }

 protected:
  std::vector<SPHPhaseLaw> laws;    // per type (1..ntypes)
  std::vector<int> changes;         // per type: 1 where a law is given
  std::vector<double> mushy;        // per type: Carman-Kozeny constant C (0: no damping)
  double mushy_eps;                 // its epsilon
  int damps;                        // some type has a C
  int order_warned;
  int vectors_made;
  int nmax;
  double *fraction;    // per atom: the liquid fraction (0 for the other types)
  double totals[2];    // the group's liquid mass fraction, its latent heat
  int totals_current;

  void parse_type(int narg, char **arg, int &iarg);
  void mark();
  void update_fraction();
};

}    // namespace LAMMPS_NS

#endif
#endif
