/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/wall/adami,FixSPHWallAdami);
// clang-format on
#else

#ifndef LMP_FIX_SPH_WALL_ADAMI_H
#define LMP_FIX_SPH_WALL_ADAMI_H

#include "atom.h"
#include "fix.h"
#include "sph_body_force.h"
#include "sph_cells.h"
#include "sph_kernels.h"

#include <vector>

namespace LAMMPS_NS {

class FixSPHWallAdami : public Fix {
 public:
  FixSPHWallAdami(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_neighbor() override;
  void pre_neighbor() override;
  void setup_pre_force(int) override;
  void pre_force(int) override;
  // the walls' pressure and velocity extrapolated again (fix sph/boussinesq,
  // when it has solved its potential after this fix's set-up)
  void extrapolate_again() { pre_force_walls(); }
  void setup(int) override;
  void post_force(int) override;
  ~FixSPHWallAdami() override;

  // a solid wall particle (its type has no equation of state) keeps its own
  // density, mass and heat capacity for conduction; the flow sees it with
  // the pressure, density and viscosity extrapolated from the fluid, for
  // owned and ghost atoms, valid after pre_force; its no-slip velocity too,
  // which is not written to vest (a MACHDYN solid's vest is its own
  // velocity, which pair smd/tlsph reads)
  int has_solids() const { return any_solid; }
  int solid(int i) const { return solid_type[atom->type[i]]; }
  double pressure(int i) const { return solid_state[i][0]; }
  double fluid_density(int i) const { return solid_state[i][1]; }
  double viscosity(int i) const { return solid_state[i][2]; }
  double compression(int i) const { return solid_state[i][3]; }
  const double *no_slip_velocity(int i) const { return &solid_state[i][SOLID_VELOCITY]; }
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  // the velocity of the last sample travels and restarts with each atom
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  double memory_usage() override;
  // 1 when the wall particles move (fix rigid, fix move, or 'moving yes'):
  // their acceleration enters the pressure (Adami et al. 2012)
  int is_moving() const { return moving; }

 protected:
  class SPHCommStage forward_fields() const;    // what the forward comm carries
  double body[3];    // body acceleration of the fluid minus that of the wall
  int body_given;    // 1: 'body' in the command; 0: the run's body force
  // moving walls: each particle's acceleration a_w, from its velocity at
  // successive force evaluations (fix rigid and fix move set v at the half
  // step, fix sph/wall/adami samples it in pre_force)
  int moving_keyword;    // -1 auto (a fix rigid* or move on the group), 0 no, 1 yes
  int moving;
  double **v_sampled;          // per atom: v at the last sample
  double **accel;              // per atom: a_w of this step (owned wall atoms)
  double remaining_sampled;    // time from the last sample to the end of its step
  int sampled;                 // 1 when v_sampled holds a sample of every wall atom
  void sample_acceleration(double half_dt);
  void pre_force_walls();
  const double *body_force;    // the run's body force (fix gravity), nullptr when none
  const SPHBodyForce::Buoyancy *buoyancy;    // fix sph/boussinesq, nullptr when none
  int wall_groupbit;                         // particles of every sph/wall/adami fix
  int kernel_kind;
  double cutoff;
  class FixSPHMaterials *materials;
  int thermal_expansion;    // some equation of state depends on T
  // the fluid within cutoff + skin of each owned wall particle, found at
  // each neighbour-list build and kept until the next: fluid_near[n] for n
  // in [first_fluid[i], first_fluid[i + 1]) indexes fluid_atoms, whose
  // pressure and rho times body acceleration are found once per step
  SPHCells cells;
  std::vector<int> first_fluid, fluid_near, fluid_atoms;
  std::vector<double> fluid_pressure, fluid_rho_accel;
  bool fluid_near_valid;
  void find_fluid_near();
  // a fluid atom much nearer to a wall atom than the wall's spacing has
  // gone into the wall (the extrapolated pressure no longer pushes it out):
  // warn, once a run, at the neighbour build that finds it
  int entered_warned;
  void warn_entered_wall();
  int *solid_type;    // per type: 1 when the type has no equation of state
  // per thread (package omp) and type: the kernel weight of its fluid
  // around one solid particle
  std::vector<double> fluid_weights;
  template <int KERNEL>
  void pre_force_atoms(int from, int to, double *fluid_weight, const sphk_kernel &kernel,
                       int &below_eos);
  struct AtomsCall;
  int any_solid;    // 1 when some wall particle of this fix is solid
  // per atom (owned and ghost): P, rho, viscosity, rho0/rho and the no-slip
  // velocity (3) seen by the flow
  double **solid_state;
  static constexpr int SOLID_VELOCITY = 4, SOLID_STATE_SIZE = 7;
  int nmax;
  // with 'surface': the mirror points, the fluid's velocity and its
  // gradient there (12 per owned atom, SPHMirror::interpolate_velocity) and
  // how they were found (sphi_result)
  class SPHMirror *mirror;
  std::vector<double> ghost_velocity;
  std::vector<int> ghost_how;
};

}    // namespace LAMMPS_NS

#endif
#endif
