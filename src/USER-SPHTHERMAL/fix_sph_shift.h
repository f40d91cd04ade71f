/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/shift,FixSPHShift);
// clang-format on
#else

#ifndef LMP_FIX_SPH_SHIFT_H
#define LMP_FIX_SPH_SHIFT_H

#include "fix.h"
#include "sph_threads.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// Particle shifting at the end of each step: the atoms of the group move
// down the gradient of the kernel sum of the particles' volumes (Skillen
// et al. 2013; Reece et al. 2024, eq 38) or of its delta-plus form (Sun et
// al. 2017; Ng et al. 2020, eqs 19-20), by at most a fraction of their
// spacing; optionally their temperature (and velocity) follow, to first
// order, and the group's mean density the change of the kernel sums.
class FixSPHShift : public Fix {
 public:
  FixSPHShift(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  void restart(char *) override;
  // whether the temperature follows the shift ('correct yes')
  bool corrects() const { return correct != 0; }

 protected:
  class SPHCommStage forward_fields() const;    // what the forward comm carries
  void size_sums();
  void choose_continuity();
  enum { SKILLEN, DELTAPLUS };
  int form;
  double coefficient;    // D (skillen) or C (delta-plus)
  double speed;          // delta-plus: the reference speed U of CFL Ma = U dt / h
  double r_coeff;        // delta-plus: R and n of the pair weight
  int r_power;
  double cap;    // largest shift / spacing
  enum { CORRECT_T = 1, CORRECT_ALL = 2 };
  int correct;             // 0, CORRECT_T: T_i += dr_i . grad T_i, CORRECT_ALL: T, rho and v
  int continuity;          // the group's mean rho follows the shift's change of the kernel sums
  int continuity_given;    // 1: 'continuity' in the command; 0: the default of init()
  int kernel_kind;
  double cutoff;
  int loop_own;     // 1: always the fix's own neighbour pass ('loop own')
  int from_pair;    // 1: this run takes the sums from the flow pair's loop
  class PairSPHHarmonicVisc *flow;
  class NeighList *list;
  std::vector<double> shift;     // per owned atom, 3 each
  std::vector<double> volume;    // per owned and ghost atom, m / rho
  // per owned and ghost atom: the spacing's kernel value W(dx) (delta-plus), T (correcting)
  std::vector<double> w_spacing, temperature;
  // per owned and ghost atom, sums_per_atom each: the neighbour sums, ghosts' sent home
  std::vector<double> sums;
  SPHThreadSums thread_sums;    // the threads' copies of sums (package omp)
  double energy;                // energy the correction has added since the fix was defined
  double largest;               // largest shift / spacing of the last step, on this rank
  int capped;                   // atoms shortened to the cap in the last step, on this rank
  int moved;                    // atoms of the group shifted in the last step, on this rank
  int warned_cap;               // 1 once this run has warned that most shifts were capped
  int sums_per_atom;            // length of an atom's neighbour sums
  std::string who;              // "Fix sph/shift <ID>", for messages

  void shift_from_pair_sums();
  void displacement(int i, const double *sum, double spacing, double h, int dim, double *dr,
                    double &largest_local, int &capped_local);
  void stop_nonfinite(int i, const double *sum, double factor, double spacing, const double *dr);
  void check_capped();
  void check_group();
  template <int FORM> void shift_corrected();
  template <int FORM, int CORRECT> void shift_continuity();
  template <int FORM, int CORRECT, int CONTINUITY> void shift_group();
};

}    // namespace LAMMPS_NS

#endif
#endif
