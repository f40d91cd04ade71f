/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/harmonic/visc,PairSPHHarmonicVisc);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_HARMONIC_VISC_H
#define LMP_PAIR_SPH_HARMONIC_VISC_H

#include "pair_sph_cleary_heat.h"
#include "pair_sph_kernel.h"
#include "sph_body_force.h"
#include "sph_build_stamp.h"
#include "sph_comm_stage.h"
#include "sph_consistent.h"
#include "sph_eos.h"
#include "sph_threads.h"

#include <vector>

namespace LAMMPS_NS {

class PairSPHHarmonicVisc : public PairSPHKernel {
 public:
  PairSPHHarmonicVisc(class LAMMPS *);
  ~PairSPHHarmonicVisc() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;
  bool conducts() const override { return false; }

  // fix sph/shift's sum_j V_j grad_i W_ij for the atoms of 'groupbit', made
  // in this style's pair loop from the next compute() on (asked at every
  // init, after this style's); false when this loop cannot: another
  // pressure form than the default (the sums are instantiated only with
  // it), the /omp style, a type pair of the group's types that is not this
  // style's, or an atom of the group that is a wall (wall-wall pairs skipped)
  virtual bool provide_shift_sums(int groupbit);
  const double *shift_sums() const { return shift_sum; }

  // The force that the atoms outside a group exert on it through this
  // style's momentum equation (compute sph/force): its pressure and viscous
  // parts and their moments about 'origin', this rank's share of the pairs
  // of the step's compute(). Made right after the pair loop, with the same
  // state, on the steps the asking compute will be invoked
  // (Compute::matchstep) and at set-up; asked again at every init, after
  // this style's.
  struct GroupForce {
    class Compute *compute;    // who asks: its group and its steps
    double origin[3];          // the next sums' moments are about it (kept near the group)
    double made_about[3];      // the origin of the moments in 'sums'
    double sums[12];           // pressure F, viscous F, their moments
    bigint step;               // the step they were made on (-1: none yet)
  };
  void make_group_force(GroupForce *request) { group_forces.push_back(request); }

 protected:
  int pressure_form;     // SPHF_P_* of sph_flow.h (also selects the continuity form)
  int viscosity_form;    // SPHF_V_* of sph_flow.h
  double xi;             // factor of the cleary viscosity
  int xi_given;          // xi was given (only the cleary form reads it)
  double delta;          // density diffusion (Ng et al. 2020, eq 5), 0: none
  double heating;        // fraction of the viscous work turned into heat, 0: none
  double artificial;     // alpha of Monaghan's artificial viscosity, 0: none
  // 'artificial' as the command gave it (-1: the scene's default at init)
  double artificial_request;
  int artificial_logged;
  // the command's pressure form and delta (-1: not given, the scene's
  // default at init) and the defaults last logged
  int pressure_request, pressure_logged;
  double delta_request;
  int delta_logged;
  int grain_forms_warned;    // choose_scene_forms() warned (once per style)
  void choose_scene_forms();
  // 1: the pair terms see the pressure less an offset (pvector[0], for
  // compute pair) that holds the fluid's volume-weighted mean pressure at
  // mean_pressure
  int mean_pressure_held;
  double mean_pressure;
  // 'correction gradient': the pressure force with the kernel gradient
  // normalised per particle (B = M^-1, sph_consistent.h), so that the
  // discrete pressure gradient has no first-order (moment) error; per atom
  // (owned and ghost) B in sph_consistent.h's storage,
  // I where the support is incomplete and for wall particles
  int gradient_correction;
  // the command's choice (-1: not given, the scene's default at init; 0
  // none, 1 gradient, GRADIENT_HOLD gradient/hold) and the default last logged
  int gradient_request, gradient_logged;
  static constexpr int GRADIENT_HOLD = 2;
  // when B was last made ('gradient/hold' keeps it until the next build)
  SPHBuildStamp gradient_made;
  double **gradient_inverse;
  int nmax_gradient;
  // the density diffusion: Fourtakas's (Reece et al. 2024, eq 39) with the
  // run's body force (the default), Molteni's (Ng et al. 2020, eq 5: no
  // gravity), or Fourtakas's with a vector given in the command
  enum { DIFFUSION_BODY_FORCE, DIFFUSION_MOLTENI, DIFFUSION_GIVEN };
  int diffusion_form;
  // 1: the diffusion leaves alone the density gradient that balances the
  // body force: 'gravity' plus, on buoyant atoms, fix sph/boussinesq's buoyancy
  int hydrostatic;
  double gravity[3];           // the uniform acceleration of the hydrostatic diffusion
  const double *body_force;    // the run's body force (fix gravity), nullptr when none
  const SPHBodyForce::Buoyancy *buoyancy;             // fix sph/boussinesq's, nullptr when none
  const SPHBodyForce::Buoyancy *pressure_buoyancy;    // its potential's pressure, any diffusion
  std::vector<double> body_accel;    // with hydrostatic: per atom (owned, ghost) its acceleration
  void read_body_force();            // gravity and hydrostatic of 'diffusion fourtakas'
  double eta2;                       // eta^2, regularises r -> 0
  class FixSPHMaterials *materials;
  int viscosity_varies;    // 1 when some viscosity depends on T
  int wall_groupbit;       // particles of every fix sph/wall/adami (no density diffusion)
  // every fix sph/wall/adami; those with solid particles (own density) give
  // the flow the fluid's state at the wall
  std::vector<class FixSPHWallAdami *> adami_walls;
  // per atom (owned and ghost), refreshed every step: what the flow sees
  // (a solid wall particle: the fluid's pressure, density and viscosity at
  // the wall, its own volume)
  double *pressure, *viscosity, *mass_of, *volume, *density;
  // with thermal expansion, rho - (rho0(T) - rho0): the density diffusion
  // leaves the thermal density differences alone (else atom->rho)
  double *diffused_density;
  const double *diffusion_rho;
  // the velocity the viscosity sees: atom->vest, or with solid wall particles
  // a copy with their no-slip velocity from the wall (their own vest is left alone)
  double **velocity_seen_store;
  const double *const *velocity_seen;
  int thermal_expansion;    // some equation of state depends on T
  int nmax;
  // pair sph/cleary/heat, when its term is evaluated in this style's loop
  class PairSPHClearyHeat *heat;
  PairSPHClearyHeat::FlowLoopTerm heat_term;
  // the heat term in eval(): on, per-atom conductivities, relax_rate
  // and the density diffusion
  // and fix sph/shift's sums
  // and the corrected pressure gradient
  enum {
    HEAT_ON = 1,
    HEAT_ATOM_K = 2,
    HEAT_RELAX = 4,
    DIFFUSION = 8,
    SHIFT_SUMS = 16,
    GRADIENT = 32
  };
  int shift_sums_wanted;
  double *shift_sum;    // per owned and ghost atom, 3 each (a copy per /omp thread)
  int nmax_shift;
  std::vector<const sphe_eos *> eos_of;    // per type (nullptr: none), for the diffusion
  int background_warned;                   // warn_background() warned (once per style)
  void warn_background();
  int soft_fluid_warned;    // warn_soft_fluid() warned (once per style)
  void warn_soft_fluid();

  // where the pair loops add their rates: the atom's arrays, or one
  // thread's copies of them (the /omp style; thread: its ThrData)
  struct Rates {
    double **f;
    double *drho, *desph, *relax_rate;
    double *shift_sum;    // fix sph/shift's sums (3 per atom), where wanted
    void *thread;
  };
  void begin_compute();
  void eval_pairs(int ifrom, int ito, const Rates &rates);
  void end_compute();
  // ev_tally_xyz for pair i, j (the /omp style tallies per thread)
  virtual void tally_pair(int i, int j, double fx, double fy, double fz, double delx, double dely,
                          double delz, void *thread);

  std::vector<GroupForce *> group_forces;
  void make_group_forces();    // those wanted on this step
  void group_force(GroupForce &request) const;
  // the pressure force's direction for pair i, j with 'correction gradient':
  // B grad W with the mean of both particles' B for a fluid pair, the fluid
  // particle's with a wall (one matrix per pair keeps the force
  // antisymmetric, so momentum is kept)
  static inline void corrected_direction(const double *const *gradient_inverse, int i, int j,
                                         int wall_i, int wall_j, const double del[3],
                                         double b_del[3])
  {
    if (wall_i || wall_j)
      sphc_sym_apply(gradient_inverse[wall_i ? j : i], del, b_del);
    else {
      double b_del_j[3];
      sphc_sym_apply(gradient_inverse[i], del, b_del);
      sphc_sym_apply(gradient_inverse[j], del, b_del_j);
      for (int k = 0; k < 3; k++) b_del[k] = 0.5 * (b_del[k] + b_del_j[k]);
    }
  }

  void update_atom_state();
  // the inverse moments for this step's positions
  // (pair_sph_harmonic_visc_state.cpp)
  void refresh_gradient_correction();
  SPHThreadSums gradient_sums;    // the threads' sums of the moments (package omp)
  template <int KERNEL, int DIM> void update_gradient_correction();
  double hold_mean_pressure();
  // the calls of the templates below for this run's settings (sph_dispatch.h)
  struct GradientCall;
  struct EvalCall;
  struct HeatingCall;
  struct ArtificialCall;
  // the run's corrected gradient and shift sums added to TERMS, then the dimension
  template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS>
  void eval_dimension(int ifrom, int ito, const Rates &rates);
  template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS>
  void eval_in_dimension(int ifrom, int ito, const Rates &rates);
  template <int KERNEL, int PRESSURE, int VISCOSITY, int TERMS, int DIM>
  void eval(int ifrom, int ito, const Rates &rates);
  // viscous heating, a pass of its own (only when on: the main loop's
  // instantiations stay as they are)
  template <int KERNEL> void eval_heating_kernel(int ifrom, int ito, const Rates &rates);
  template <int KERNEL, int VISCOSITY, int DIM>
  void eval_heating(int ifrom, int ito, const Rates &rates);
  // Monaghan's artificial viscosity, a pass of its own (only when on)
  template <int KERNEL, int DIM> void eval_artificial(int ifrom, int ito, const Rates &rates);
  double artificial_pair(int i, int j, double vr, double rsq, double dwdr_r) const;
  // the Shepard sum sum_j V_j W_ij of each owned and ghost atom (itself and
  // wall particles included), which tells the particles at a free surface
  // (below SPHF_SURFACE_SHEPARD) for the artificial viscosity; 1 for walls
  double *shepard;
  int nmax_shepard;
  int artificial_here;    // this rank has pairs the artificial viscosity acts on
  template <int KERNEL, int DIM> void update_shepard();
  struct ShepardCall;
};

}    // namespace LAMMPS_NS

#endif
#endif
