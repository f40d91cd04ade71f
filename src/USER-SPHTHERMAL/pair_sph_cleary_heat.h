/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/cleary/heat,PairSPHClearyHeat);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_CLEARY_HEAT_H
#define LMP_PAIR_SPH_CLEARY_HEAT_H

#include "pair_sph_kernel.h"
#include "sph_comm_stage.h"
#include "sph_conduction.h"
#include "sph_dispatch.h"
#include "sph_second_moment.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairSPHClearyHeat : public PairSPHKernel {
 public:
  PairSPHClearyHeat(class LAMMPS *);
  ~PairSPHClearyHeat() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;
  bool conducts() const override { return true; }
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;

  // heat flows between two groups, tallied in compute() on request (fix
  // sph/heatflow, after this style's init): the index of the flow into the
  // group 'to' from the group 'from'
  int request_heat_flow(int to_groupbit, int from_groupbit);
  // power into 'to' from 'from' at the last force evaluation (every rank)
  double heat_flow(int index) const { return flows[index].power; }

  // F_ij of sph_conduction.h between atoms i and j (owned or ghost) at the
  // squared distance rsq (inside the support) for the temperature
  // difference temp_ij = T_i - T_j: compute() adds m_j F_ij to de_i/dt and
  // takes m_i F_ij from de_j/dt. For the styles that change a few pairs
  // after compute() (fix sph/inlet/temperature), with this style's list.
  double pair_term(int i, int j, double rsq, double temp_ij) const;
  // dW/dr of this style's kernel at distance r (for the styles that take
  // gradients with the same kernel)
  double kernel_dwdr(double r) const { return sphk_dwdr(&kernel, r); }
  class NeighList *pair_list() const { return list; }
  double support() const { return cut_global; }

  // pair sph/harmonic/visc evaluates this style's term in its own pair loop
  // (one neighbour pass, square root and division per pair for both) when
  // both see the same pairs with the same kernel and the term needs only
  // the pair (no correction, no interface distances): decided at init
  int term_in_flow_loop() const { return in_flow_loop; }
  // what the flow loop reads, made for this step's state
  struct FlowLoopTerm {
    const double *temperature, *mass, *rho;    // per atom, owned and ghost
    const double *conductivity;    // per atom when some conductivity varies (harmonic mean)
    double **conductance;          // per type pair otherwise
    double *relax_rate;            // per atom when a style asks for it, else nullptr
    double eta2;
  };
  FlowLoopTerm begin_flow_loop_term();
  void end_flow_loop_term();

  // each atom's relaxation rate (owned atoms, after compute()), made from
  // the next compute() on while wanted (the timestep's thermal limit);
  // nullptr before
  void want_relax_rates(bool wanted) { relax_wanted = wanted ? 1 : 0; }
  const double *relax_rates() const { return relax_rate; }
  // 'correction consistent' or 'second' on, and per atom (from init on,
  // filled by compute()): 1 where it corrects the atom's pair terms, 0 where
  // the atom keeps the plain term (incomplete support)
  bool corrects() const { return correct != 0; }
  const double *correction_states() const { return corr_state; }
  // 'mean interface', and per atom (from init on, filled by compute()) the
  // distance from the interface, -1 where no atom of another material is
  // within the support
  bool interface_mean() const { return mean == SPHC_INTERFACE; }
  const double *interface_distances() const { return iface_distance; }

 protected:
  int mean;                   // SPHC_HARMONIC, SPHC_ARITHMETIC or SPHC_INTERFACE
  int loop_own;               // 'loop own': never in the flow pair's loop
  int in_flow_loop;           // this run's term is evaluated by the flow pair
  double *temperature, *mass_of;    // per atom (owned and ghost), refreshed every step
  int nmax_flow_loop;
  double eta2;                // eta^2, regularises r -> 0
  class FixSPHMaterials *materials;
  int conductivity_varies;    // 1 when some conductivity depends on T
  double **conductance;       // per type pair, when no conductivity varies
  double **loop_conductance;  // the same for the flow pair's loop, 0 where this style has no pair
  double *conductivity;       // per atom (owned and ghost), when some varies
  int nmax;
  // per atom: the rate at which T relaxes towards the neighbours,
  //   lambda_i = sum_j m_j |F_ij / T_ij| / cv_i
  // (F_ij of sph_conduction.h), the diagonal of the explicit conduction
  // update; computed only when a style asks for it (fix sph/dt/reset)
  int relax_wanted;
  double *relax_rate;
  int nmax_relax;
  // dummy particles of fix sph/wall/dirichlet: group bit and wall temperature
  std::vector<std::pair<int, double>> dummy_walls;
  struct HeatFlow {
    int to, from;    // group bits
    double power;
  };
  std::vector<HeatFlow> flows;

  // 'correction consistent' (sph_consistent.h): per atom (owned and ghost)
  // the second-moment normaliser S (6), the first-moment vector lambda (3)
  // and whether the atom is corrected (1) or keeps the plain term (0,
  // incomplete support); work arrays for the Jacobi sweeps.
  // 'correction second' (sph_second_moment.h): the same state flag, the
  // multipliers nu of every owned and ghost atom and the solver's pairs,
  // per-atom input and work space
  enum { CORRECT_NONE = 0, CORRECT_CONSISTENT = 1, CORRECT_SECOND = 2 };
  int correct;
  int sweeps;
  int nmax_correct;
  double **corr_s, **corr_kinv, **corr_lambda, **corr_deficit, **corr_coupling;
  double *corr_state;
  std::vector<double> second_nu, second_work, second_volume;
  std::vector<int> second_constrained;
  std::vector<sphs_pair> second_pairs;
  sphs_result second_result;    // of the last solve, for report_setup()
  // the last solve's second stage (the unregularised problem): 1 taken,
  // 0 not converged (the regularised multipliers kept), -1 not tried
  int second_exact;
  std::vector<double> second_kept;
  int second_warned;
  bigint second_solved_at;    // step of the last solve, -1 before the first
  void solve_second();
  // the solver's communication (sph_second_moment.h's sphs_exchange): n
  // values per atom of the array comm_values
  double *comm_values;
  int comm_count;
  // values per atom of the largest reverse communication but that of
  // 'correction second': the moments of the correction (6 and 3)
  static constexpr int COMM_REVERSE_MOMENTS = 9;
  static void second_exchange(void *context, double *values, int n, bool reverse);
  static void second_forward(void *context, double *values, int n);
  static void second_reverse(void *context, double *values, int n);
  static double second_sum(void *context, double value);
  static double second_max(void *context, double value);
  static void second_sum_array(void *context, double *values, int n);
  enum {
    COMM_RELAX,
    COMM_MOMENT,
    COMM_FIRST,
    COMM_STATE,
    COMM_LAMBDA,
    COMM_COUPLING,
    COMM_SECOND,    // comm_count values per atom of comm_values
    COMM_IFACE_MOMENT,
    COMM_IFACE_VECTOR,
    COMM_IFACE_SMOOTH,
    COMM_IFACE_NORMAL,
    COMM_IFACE_MARGIN,
    COMM_IFACE_DISTANCE,
    COMM_IFACE_PLANE,
    COMM_IFACE_NEAR
  };
  int comm_stage;
  SPHCommStage comm_fields() const;    // the per-atom values of comm_stage
  // 'mean interface': per type pair, 1 when the two types differ in
  // conductivity law (the pair crosses an interface); per type, the
  // conductivity when all are constant; per atom (owned and ghost) the
  // distance from the interface (-1 where no atom of another material is
  // within the support) and work arrays of its estimate
  int **interface_types;
  double *type_conductivity;
  int nmax_interface;
  double *iface_distance;
  double **iface_moment, **iface_vector, **iface_normal, **iface_sum;
  double *iface_near;    // 1: an atom of another material within the support
  // 'distance d_name': the distances given per atom (fix property/atom)
  // instead of the estimate; its index in atom->dvector (-1: estimated)
  std::string distance_name;
  int distance_index;
  void given_interface();
  // the pairs within the support, in the order of the neighbour list, with
  // their plain weight g (sph_consistent.h), r_ij, dW/dr and W, gathered by
  // the first pass and read by the others, and their factor w_ij
  struct SupportPair {
    int i, j;
    double g, r[3], distance, dwdr, w;
    double weight;    // w_ij, which compute() applies
  };
  std::vector<SupportPair> support_pairs;
  // positions and densities of the owned atoms at the last update: the
  // factors depend on nothing else, so particles that keep them (solids,
  // fix sph/stationary) keep their factors without a new update
  int nmax_pairs;
  double **corr_x;
  double *corr_rho;
  int corr_valid;
  int refresh_pairs;    // this step's compute() makes the factors and distances anew
  int pairs_current();
  void grow_correction();
  template <int KERNEL> void update_correction();
  void report_setup();    // at a run's setup: atoms near an interface, plain atoms
  void grow_interface();
  void mark_interface_atoms();
  template <int KERNEL> void update_interface();
  // the conductance of the pair i j (owned or ghost) for pair_term()
  double pair_conductance(int i, int j) const;
  template <int KERNEL> void gather_support_pairs();
  double volume_of(int i) const;    // m / rho
  // the factor w_ij of sph_consistent.h between atoms i and j at distance r,
  // for pair_term() (1 without 'correction consistent')
  double pair_weight(int i, int j, double r) const;

  void allocate() override;
  void update_conductivity();
  void begin_compute();
  void eval_pairs(int ifrom, int ito, double *desph, double *relax);
  void end_compute();
  void zero_relax_rate();
  // the support's pairs, factors and distances for this step's positions
  // (pair_sph_cleary_heat_support.cpp)
  void refresh_support();
  template <int KERNEL> void update_pairs();
  struct SupportCall;    // update_pairs<KERNEL> for this run's kernel (sph_dispatch.h)
  struct EvalCall;       // eval<...> for this run's settings
  template <int KERNEL, int MEAN, int CORRECT, int VARYING_K, int NEWTON_PAIR, int RMASS,
            int RELAX>
  SPH_LOOP void eval(int ifrom, int ito, double *desph, double *relax);
  void tally_flows();
  int flow_loop_possible();
  void update_temperature();
  void finish_relax();
  std::string diagnose(int) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
