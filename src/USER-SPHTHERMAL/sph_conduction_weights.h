/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_CONDUCTION_WEIGHTS_H
#define LMP_SPH_CONDUCTION_WEIGHTS_H

#include "pointers.h"
#include "sph_build_stamp.h"
#include "sph_second_moment.h"
#include "sph_support_pairs.h"
#include "sph_threads.h"

#include <vector>

namespace LAMMPS_NS {

class SPHExchange;

// The factors w_ij by which a correction of pair sph/cleary/heat multiplies
// each pair's conduction term, behind one interface: 'correction
// consistent' (sph_consistent.h) and 'second' (sph_second_moment.h);
// 'none' has no object (every factor 1). Both start from the same
// normalised second moment, which also decides where an atom's support is
// complete (corrected) or not (the plain term).
class SPHConductionWeights : protected Pointers {
 public:
  enum Kind { NONE = 0, CONSISTENT = 1, SECOND = 2 };
  // warm_sweeps of create(): no sweeps between builds, the per-atom
  // solution of the last build held and each pair's factor made from it at
  // the pair's current separation ('warm hold')
  static constexpr int HOLD = -1;
  // the weights of 'kind' (nullptr for NONE); inv_h the inverse of the
  // kernel's smoothing length; sweeps the Jacobi sweeps of CONSISTENT from
  // lambda = 0 (at a neighbour-list build), warm_sweeps those that go on
  // from the last step's lambda between builds (0: from lambda = 0 always;
  // HOLD: the solution held, for either kind)
  static SPHConductionWeights *create(LAMMPS *lmp, int kind, double inv_h, int sweeps,
                                      int warm_sweeps);
  ~SPHConductionWeights() override;

  // the rows (6 per owned and ghost atom, zeroed) into which
  // SPHSupportPairs::gather sums the pairs' second moments for refresh()
  double *moments_to_gather();
  // the factors of this step's pairs, gathered with moments_to_gather(), into
  // pairs.weight (volume: m / rho of every owned and ghost atom), with the
  // states of every owned and ghost atom
  virtual void refresh(SPHSupportPairs &pairs, const double *volume, SPHExchange &exchange) = 0;
  // with HOLD, whether this step's factors come from the held solution
  // (reweigh) instead of refresh: no neighbour-list build since the last
  // refresh, and not a run's setup; then moments_to_gather() is not called
  bool held() const;
  // pairs.weight from the held solution at this step's pairs (as gathered,
  // without moments)
  virtual void reweigh(SPHSupportPairs &pairs);
  // the factor between atoms i and j (owned or ghost) at r_ij = x_i - x_j,
  // |r_ij| = r, for the last refresh
  virtual double factor(int i, int j, const double r_ij[3], double r) const = 0;
  // at a run's setup, on every rank: the log lines of the last update
  virtual void report() const;
  virtual double memory_usage() const;
  // a new run: the solvers' once-per-run warnings may be given again
  virtual void rearm() {}

  // per atom (owned and ghost, room from construction on, filled by
  // refresh()): 1 where the atom's pair terms are corrected, 0 where it keeps
  // the plain term (incomplete support)
  const double *states() const { return state; }
  const char *name() const { return kind == SECOND ? "second" : "consistent"; }
  // room for atom->nmax atoms
  void grow();

 protected:
  SPHConductionWeights(LAMMPS *lmp, int kind, int hold);
  const int kind;
  const int hold;    // 'warm hold'
  int nmax;
  // the last refresh, whose solution (owned and ghost atoms) a warm start
  // or a hold goes on from (forgotten when the arrays are made anew)
  SPHBuildStamp made;
  double **s;       // the normalised second moment S = V M^-1 (6 per atom)
  double *state;    // 1: corrected, 0: plain
  // from the gathered M of the plain weights: S and the states, on every atom
  void normalise(const double *volume, SPHExchange &exchange);
  virtual void grow_more() {}
};

// 'correction consistent': S and the first-moment vector lambda from Jacobi sweeps
class SPHConsistentWeights : public SPHConductionWeights {
 public:
  SPHConsistentWeights(LAMMPS *lmp, int sweeps, int warm_sweeps);
  ~SPHConsistentWeights() override;
  void refresh(SPHSupportPairs &pairs, const double *volume, SPHExchange &exchange) override;
  void reweigh(SPHSupportPairs &pairs) override;
  double factor(int i, int j, const double r_ij[3], double r) const override;
  double memory_usage() const override;

 private:
  const int sweeps, warm_sweeps;
  double **kinv, **lambda, **deficit, **coupling;
  void grow_more() override;
  void release();
  template <int DIM> void refresh_in(SPHSupportPairs &pairs, SPHExchange &exchange);
  template <int DIM> void reweigh_in(SPHSupportPairs &pairs);
  template <int DIM, bool WARM>
  void weigh_pairs(SPHSupportPairs &pairs, SPHSupportPairs::Block block, int newton,
                   double *kinv_flat, double *deficit_flat, double *coupling_flat);
  // the threads' sums of K, s and the coupling (sph_threads.h)
  SPHThreadSums kinv_sums, deficit_sums, coupling_sums;
};

// 'correction second': the multipliers nu of sph_second_moment.h's solve
class SPHSecondWeights : public SPHConductionWeights {
 public:
  SPHSecondWeights(LAMMPS *lmp, double inv_h, int hold);
  void refresh(SPHSupportPairs &pairs, const double *volume, SPHExchange &exchange) override;
  double factor(int i, int j, const double r_ij[3], double r) const override;
  void report() const override;
  double memory_usage() const override;
  void rearm() override { warned = 0; }

 private:
  const double inv_h;
  std::vector<double> nu, work, volume_owned, kept;
  std::vector<int> constrained;
  std::vector<sphs_pair> solver_pairs;
  sphs_result result;    // of the last solve
  // the last solve's second stage (the unregularised problem): 1 taken,
  // 0 not converged (the regularised multipliers kept), -1 not tried
  int exact;
  int warned;
  SPHExchange *exchange;    // during refresh()
  static void forward(void *context, double *values, int n);
  static void reverse(void *context, double *values, int n);
  static double sum(void *context, double value);
  static double max(void *context, double value);
  static void sum_array(void *context, double *values, int n);
};

}    // namespace LAMMPS_NS

#endif
