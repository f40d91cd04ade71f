/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(sph/open,FixSPHOpen);
// clang-format on
#else

#ifndef LMP_FIX_SPH_OPEN_H
#define LMP_FIX_SPH_OPEN_H

#include "fix.h"
#include "sph_cells.h"

#include <vector>

namespace LAMMPS_NS {

// An open boundary of the fluid: a plane normal to a box axis and a buffer
// of particles (the fix's group) behind it, in the way of Tafuni et al.
// 2018 (buffer zones; the quantities not prescribed are extrapolated from
// the fluid at each buffer particle's mirror point across the plane).
// Inlet: the buffer moves at a prescribed velocity (and temperature); its
// density is extrapolated (first order); a buffer particle that crosses the
// plane joins the fluid's group, and a copy of it enters at the buffer's
// back. Outlet: the buffer's density follows a prescribed pressure; its
// velocity and temperature are the fluid's at the mirror point; a fluid
// particle that crosses the plane joins the buffer, and leaves the box at
// the buffer's back. Atoms are created and deleted at the next step's
// neighbour build, which the fix asks for.
class FixSPHOpen : public Fix {
 public:
  FixSPHOpen(class LAMMPS *, int, char **);

  int setmask() override;
  void init() override;
  void setup_pre_exchange() override;
  void setup_pre_force(int) override;
  void setup(int) override;
  void initial_integrate(int) override;
  void pre_exchange() override;
  void pre_force(int) override;
  void end_of_step() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  // the group bit of the fluid the boundary feeds or drains
  int fluid_groupbit() const { return fluidbit; }

 protected:
  enum Kind { INLET, OUTLET };
  enum Profile { UNIFORM, PARABOLIC };
  int kind;
  int axis;           // 0, 1, 2: the plane's normal
  int direction;      // +1 or -1: the flow's direction along the axis
  double position;    // the plane's coordinate along the axis
  int fluid_group, fluidbit;
  // inlet: the velocity profile and temperature
  int profile;
  double speed;        // uniform speed, or the parabola's largest
  int profile_axis;    // parabolic: the axis across the channel
  double profile_lo, profile_hi;
  int temperature_given;
  double temperature;
  // outlet: the pressure (by default the equation of state's background)
  int pressure_given;
  double pressure;

  double length;    // the buffer's depth behind the plane (a multiple of the spacing)
  double spacing;
  int kernel_kind;
  double cutoff;
  class FixSPHMaterials *materials;

  // entering copies waiting for the next neighbour build (inlet), packed
  // as records of RECORD values
  std::vector<double> pending;
  int extrapolated;    // the buffer's quantities were found at a set-up before
  // since the first run (kept in restart files), into the fluid (inlet) or
  // out of it (outlet): the atoms, mass, momentum (3) and thermal energy
  // that crossed the plane; the momentum (3) and heat that the buffer's
  // forces and conduction gave the fluid across it
  enum {
    CROSSED_ATOMS,
    CROSSED_MASS,
    CROSSED_MOMENTUM,
    CROSSED_ENERGY = 5,
    FORCE_MOMENTUM,
    CONDUCTED_HEAT = 9,
    NTALLY
  };
  double crossed[NTALLY];
  // this rank's half-step of the buffer's force and heat rate taken at the
  // step's start, reduced with the end of the step's
  double start_half[4];

  // add to 'half' (fx, fy, fz, heat) dt/2 times what the buffer's atoms
  // take from the rest through forces and heat
  void add_buffer_half_step(double *half) const;
  // signed distance of a point downstream of the plane
  double downstream_of_plane(const double *x) const { return direction * (x[axis] - position); }
  void inlet_velocity(const double *x, double *v) const;
  void find_length();
  void check_sides();
  void extrapolate();
  // 'moved_for': the time the buffer has moved since the copies were recorded
  void create_pending(double moved_for);
  void delete_passed();
  SPHCells cells;
  std::vector<int>
      not_near;    // per atom (owned and ghost): 1 unless fluid within reach of the mirror points
};

}    // namespace LAMMPS_NS

#endif
#endif
