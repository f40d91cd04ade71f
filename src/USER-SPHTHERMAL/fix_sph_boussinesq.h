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

#include "atom.h"
#include "fix.h"
#include "neigh_list.h"
#include "sph_body_force.h"
#include "sph_kernels.h"

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
  // the buoyancy's potential (keyword 'potential'): Jacobi sweeps before the forces
  void init_list(int, class NeighList *) override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
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
  // 'potential': phi of the buoyancy's curl-free part (grad phi = f - solenoidal),
  // per atom, owned and ghost; the flow pair adds rho0 phi to the pressure
  int potential_sweeps;     // Jacobi sweeps per step, 0: off
  int potential_solved;     // phi converged (at a set-up, or read from a restart file)
  int nmax_potential;       // the length of potential
  double *potential;        // phi per atom
  double **wall_force;      // the buoyancy extrapolated to the wall atoms
  enum { COMM_POTENTIAL, COMM_WALL_FORCE };
  int comm_what;
  class NeighList *list;
  int wall_bits;    // the atoms of fix sph/wall/adami
  sphk_kernel kernel;
  double cutsq_potential;
  std::vector<double> accel, diag, source, next;    // per step: f, the Laplacian's diagonal, div f
  // visit(j, x_i - x_j, r) for each neighbour j of i within the kernel's
  // support whose mask has one of bits
  template <class Visit> void visit_neighbours(int i, int bits, Visit visit) const
  {
    const double *const *const x = atom->x;
    const int *const mask = atom->mask;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & bits)) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq < cutsq_potential) visit(j, del, sqrt(rsq));
    }
  }
  void prepare_potential();
  void sweep_potential();
  double remove_mean_potential();
  double mean_spacing();
};

}    // namespace LAMMPS_NS

#endif
#endif
