/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_SPH_KERNEL_H
#define LMP_PAIR_SPH_KERNEL_H

#include "pair.h"
#include "sph_comm_stage.h"
#include "sph_exchange.h"
#include "sph_hub.h"
#include "sph_kernels.h"

#include <string>

namespace LAMMPS_NS {

// What the package's SPH pair styles share (not a style itself): the kernel
// and its support radius from 'pair_style <style> <kernel> <cutoff> ...',
// 'pair_coeff * *' without coefficients (the materials come from fix
// sph/materials), restart of the type pairs, and the kernel settings that
// fixes and computes read (found through SPHHub); the communication of the
// styles' and their components' per-atom values, one stage at a time.
class PairSPHKernel : public Pair, protected SPHExchange {
 public:
  PairSPHKernel(class LAMMPS *, const char *style, const char *from_materials);
  ~PairSPHKernel() override;
  void coeff(int, char **) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  // the stage being communicated (forward() and reverse())
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  // the kernel as given, for the styles that evaluate the same kernel
  SPHKernelSettings kernel_settings() const { return {kernel_kind, cut_global, eta_factor}; }
  // the conduction pair (sph/cleary/heat and its /omp) or the flow pair
  virtual bool conducts() const = 0;
  bool same_family(const PairSPHKernel *other) const { return other->conducts() == conducts(); }
  // the same kernel on the same support (two styles can share a pair loop)
  int same_kernel(const PairSPHKernel *other) const
  {
    return other->kernel_kind == kernel_kind && other->cut_global == cut_global;
  }

 protected:
  const char *style;             // for messages: "sph/cleary/heat"
  const char *from_materials;    // for messages: what fix sph/materials supplies
  int kernel_kind;               // SPHK_* of sph_kernels.h
  double cut_global;             // kernel support radius
  double eta_factor;             // eta = eta_factor * h
  // 'same' in place of kernel and cutoff: those of the other pair (flow or
  // conduction), resolved at init
  int kernel_same;
  sphk_kernel kernel;
  // SPHExchange: the stage's values sent now (comm_forward and comm_reverse,
  // set by each style, bound the largest)
  SPHCommStage active_stage;
  void forward(const SPHCommStage &stage) override;
  void reverse(
      const SPHCommStage &stage) override;    // fixed to the dimension and cutoff by init_kernel()

  virtual void allocate();
  // kernel and cutoff from arg[0], arg[1], or 'same' in arg[0]; returns the
  // index of the next argument
  int parse_kernel(int narg, char **arg);
  void resolve_same_kernels();
  // the kernel of this run's dimension; returns eta^2. Also the checks of
  // the cutoff against the box and of the other SPH pair styles of a hybrid
  double init_kernel();
  // at a run's setup: an error when two particles share a position; a
  // warning when the cutoff leaves the particles fewer than one neighbour
  // each on average (no interaction to speak of)
  void check_neighbours();
  // after the pair loop: the first owned atom with a non-finite rate stops
  // the run, naming it and, by diagnose(), why
  void check_rates(const double *rate, const char *quantity);
  void check_rates3(double *const *rate, const char *quantity);
  // what makes atom i's rate non-finite: its own state or a neighbour's
  virtual std::string diagnose(int i);
};

}    // namespace LAMMPS_NS

#endif
