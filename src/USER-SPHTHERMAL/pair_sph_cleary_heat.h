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

#include "pair.h"
#include "sph_kernels.h"

namespace LAMMPS_NS {

class PairSPHClearyHeat : public Pair {
 public:
  PairSPHClearyHeat(class LAMMPS *);
  ~PairSPHClearyHeat() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void write_data(FILE *) override;

 protected:
  int kernel_kind;          // SPHK_* of sph_kernels.h
  double cut_global;        // kernel support radius
  double eta_factor;        // eta = eta_factor * h
  sphk_kernel kernel;       // kernel fixed to this dimension and cutoff
  double eta2;              // eta^2, regularises r -> 0
  double *conductivity;     // per type
  int *conductivity_set;    // per type: 1 once pair_coeff gave it
  double **conductance;     // per type pair: 4 k_i k_j / (k_i + k_j)

  void allocate();
  template <int KERNEL, int NEWTON_PAIR, int RMASS> void eval();
  template <int KERNEL> void eval_kernel();
};

}    // namespace LAMMPS_NS

#endif
#endif
