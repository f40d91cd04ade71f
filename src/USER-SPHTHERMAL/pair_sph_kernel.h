/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_SPH_KERNEL_H
#define LMP_PAIR_SPH_KERNEL_H

#include "pair.h"
#include "sph_kernels.h"

namespace LAMMPS_NS {

// What the package's SPH pair styles share (not a style itself): the kernel
// and its support radius from 'pair_style <style> <kernel> <cutoff> ...',
// 'pair_coeff * *' without coefficients (the materials come from fix
// sph/materials), restart of the type pairs, and the kernel settings that
// fixes and computes read through extract().
class PairSPHKernel : public Pair {
 public:
  PairSPHKernel(class LAMMPS *, const char *style, const char *from_materials);
  ~PairSPHKernel() override;
  void coeff(int, char **) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void *extract(const char *, int &) override;

 protected:
  const char *style;             // for messages: "sph/cleary/heat"
  const char *from_materials;    // for messages: what fix sph/materials supplies
  int kernel_kind;               // SPHK_* of sph_kernels.h
  double cut_global;             // kernel support radius
  double eta_factor;             // eta = eta_factor * h
  sphk_kernel kernel;            // fixed to the dimension and cutoff by init_kernel()

  virtual void allocate();
  // kernel and cutoff from arg[0], arg[1]; returns the index of the next argument
  int parse_kernel(int narg, char **arg);
  // the kernel of this run's dimension; returns eta^2
  double init_kernel();
};

}    // namespace LAMMPS_NS

#endif
