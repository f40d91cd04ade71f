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
#include "sph_conduction_weights.h"
#include "sph_dispatch.h"
#include "sph_exchange.h"
#include "sph_interface_distance.h"
#include "sph_support_pairs.h"

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
  bool corrects() const { return weights != nullptr; }
  const double *correction_states() const { return weights ? weights->states() : nullptr; }
  // 'mean interface', and per atom (from init on, filled by compute()) the
  // distance from the interface, -1 where no atom of another material is
  // within the support
  bool interface_mean() const { return mean == SPHC_INTERFACE; }
  const double *interface_distances() const { return interface ? interface->distances() : nullptr; }

 protected:
  int mean;            // SPHC_HARMONIC, SPHC_ARITHMETIC or SPHC_INTERFACE
  int loop_own;        // 'loop own': never in the flow pair's loop
  int in_flow_loop;    // this run's term is evaluated by the flow pair
  // this force evaluation's T, mass, volume and conductivity of every owned
  // and ghost atom (fix sph/materials's store)
  const double *temperature, *mass_of, *volume, *conductivity;
  double eta2;    // eta^2, regularises r -> 0
  class FixSPHMaterials *materials;
  int conductivity_varies;      // 1 when some conductivity depends on T
  double **conductance;         // per type pair, when no conductivity varies
  double **loop_conductance;    // the same for the flow pair's loop, 0 where this style has no pair
  // per atom: the rate at which T relaxes towards the neighbours,
  //   lambda_i = sum_j m_j |F_ij / T_ij| / cv_i
  // (F_ij of sph_conduction.h), the diagonal of the explicit conduction
  // update; computed only when a style asks for it (fix sph/dt/reset)
  int relax_wanted;
  double *relax_rate;
  int nmax_relax;
  // desph of the owned MACHDYN solid atoms before the pair loop: the loop
  // adds rates per unit mass, which end_compute() turns into theirs
  // (sph_particle.h; pair smd/tlsph needs newton pair off, so no ghost
  // holds a share)
  std::vector<double> solid_desph_before;
  void begin_solid_rates();
  void end_solid_rates();
  struct HeatFlow {
    int to, from;    // group bits
    double power;
  };
  std::vector<HeatFlow> flows;

  // 'correction none', 'consistent' or 'second' (SPHConductionWeights::Kind)
  // and the Jacobi sweeps of 'consistent' (from lambda = 0 at a neighbour
  // build, and warm between builds); their weights (nullptr for none).
  // The command's request (-1: the scene's default, SPHSceneDefaults), what
  // init made of it, and the value last logged
  double eta_request;    // eta given in the command, -1: the scene's default
  int eta_logged;
  int correct_request;
  int correct;
  int correct_logged;
  int sweeps, warm_sweeps;
  SPHConductionWeights *weights;
  // values per atom of the largest reverse communication but that of
  // 'correction second': the moments of the correction and, on a warm
  // start, the first sweep's coupling (6, 3 and 3)
  static constexpr int COMM_REVERSE_MOMENTS = 12;
  // 'mean interface': per type pair, 1 when the two types differ in
  // conductivity law (the pair crosses an interface); per type, the
  // conductivity when all are constant; the distances (nullptr without)
  int **interface_types;
  double *type_conductivity;
  // 'distance d_name': the distances given per atom (fix property/atom)
  // instead of the estimate
  std::string distance_name;
  SPHInterfaceDistance *interface;
  // the pairs within the support with their plain weight g and their factor
  // w_ij (1 without a correction), stored with the neighbour list
  SPHSupportPairs support_pairs;
  // positions and densities of the owned atoms at the last update: the
  // factors depend on nothing else, so particles that keep them (solids,
  // fix sph/stationary) keep their factors without a new update
  int nmax_pairs;
  double **pairs_x;
  double *pairs_rho;
  int pairs_valid;
  int refresh_pairs;    // this step's compute() makes the factors and distances anew
  int pairs_current();
  void report_setup();    // at a run's setup: atoms near an interface, plain atoms
  // the conductance of the pair i j (owned or ghost) for pair_term()
  double pair_conductance(int i, int j) const;
  // the factor w_ij between atoms i and j at distance r, for pair_term()
  // (1 without a correction)
  double pair_weight(int i, int j, double r) const;

  void allocate() override;
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
  template <int KERNEL, int MEAN, int CORRECT, int VARYING_K, int NEWTON_PAIR, int RMASS, int RELAX>
  SPH_LOOP void eval(int ifrom, int ito, double *desph, double *relax);
  void tally_flows();
  int flow_loop_possible();
  void fill_atom_state(bool flow_loop);    // the state for the flow loop's term, or the own loop's
  void finish_relax();
  std::string diagnose(int) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
