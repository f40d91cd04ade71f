/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(sph/mixing,ComputeSPHMixing);
// clang-format on
#else

#ifndef LMP_COMPUTE_SPH_MIXING_H
#define LMP_COMPUTE_SPH_MIXING_H

#include "compute.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// How well two components of a group are mixed (Reece et al. 2024, Table
// 4): per particle the volume fraction of component A around it, the
// finite-time Lyapunov exponent since the reference time, Robinson's local
// measure and the combined VF-FTLE measure; globally their means, the
// mixture's composition and the normalised mixing entropies.
class ComputeSPHMixing : public Compute {
 public:
  ComputeSPHMixing(class LAMMPS *, int, char **);
  ~ComputeSPHMixing() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup() override;
  double compute_scalar() override;
  void compute_vector() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int component_groupbit;            // component A as a group, or
  std::vector<int> component_type;   // as types (1 for each type in A)
  double stretch_cutoff;             // radius of the initial neighbourhood (0: the kernel's)
  std::string id_reference;
  class FixSPHMixingReference *reference;
  class NeighList *list;
  int kernel_kind;
  double cutoff;
  bigint measured;                   // step of the last evaluation
  int nmax;
  double **measures;                 // per atom: F, FTLE, Robinson, VF-FTLE

  // the whole group's unwrapped positions by tag at the reference, gathered on every rank
  struct Position {
    tagint tag;
    double x[3];
  };
  std::vector<Position> positions;

  double volume(int i) const;    // m / rho
  bool in_component(int i) const;
  void measure();
  void volume_fractions(double *fraction);
  void gather_positions();
  const Position *find_position(tagint tag) const;
  void separation(const double *xu, tagint tag, int packed_shift, double *del, bool &found) const;
  void capture();
  void component_fraction(double &f_all, double &n_group);
  void entropies(const double *fraction, double *sums);
};

}    // namespace LAMMPS_NS

#endif
#endif
