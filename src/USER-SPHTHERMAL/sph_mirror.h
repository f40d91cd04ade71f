/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_MIRROR_H
#define LMP_SPH_MIRROR_H

#include "pointers.h"
#include "sph_cells.h"
#include "sph_kernels.h"
#include "sph_support.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

// Mirror points of wall particles (the mDBC construction of English et al.
// 2022 used for temperature by Reece et al. 2024, eqs 18-19): the surface of
// the wall is the boundary of a region that holds the medium (side in: a
// container; side out: the medium around an obstacle); each wall
// particle is reflected through its nearest surface point (the vertex at a
// corner) to a ghost point in the medium, where the temperature of the
// medium is interpolated with the first-order correction of Liu & Liu
// (sph_interpolation.h). The wall fixes set their particles' temperature
// from it: T_w = T_ghost (adiabatic), T_w = 2 T_surface - T_ghost (Dirichlet).
// The medium's particles are those in no thermal wall group; with fix
// sph/inlet/temperature, those on the ghost point's side of its plane.
// The flow walls of fix sph/wall/adami ('surface') read the medium's
// velocity and its gradient at the ghost points instead, from a quadratic
// fit (sph_interpolation.h); their medium is the fluid, the atoms of no
// such fix.
class SPHMirror : protected Pointers {
 public:
  enum Field { TEMPERATURE, VELOCITY };
  // returns_heat: the owner gives heat back to the medium (return_heat),
  // so the neighbours and weights of each ghost point are kept
  SPHMirror(class LAMMPS *, const std::string &command, bool returns_heat,
            Field field = TEMPERATURE);
  ~SPHMirror() override;

  // 'surface <region-ID>' at arg[iarg]: returns the words read
  int parse(int narg, char **arg, int iarg);
  const std::string &region_id() const { return region_name; }

  // at the owning fix's init, after the kernel is known: checks the wall
  // atoms of 'groupbit' against the surface and widens the ghost cutoff so
  // that the ghost points' neighbours are present on every rank
  // (fix_id: the owning fix's ID, for the messages). The first
  // interpolate() after it checks that the medium next to the wall lies in
  // the region.
  void init(int groupbit, int kernel_kind, double cutoff, const char *fix_id = nullptr);

  // the temperature at the ghost point of every owned atom of the group,
  // and how it was found (sphi_result); ghost[i], how[i] for owned atoms;
  // how = SPHI_NONE for wall atoms beyond the kernel's reach of the surface;
  // depth (when given): the distance from the surface to the ghost point
  void interpolate(std::vector<double> &ghost, std::vector<int> &how,
                   std::vector<double> *depth = nullptr);
  // (field VELOCITY) the medium's velocity there and its gradient: 12
  // values per owned atom, v then d v_c / d x_k at 3 + 3 c + k
  void interpolate_velocity(std::vector<double> &ghost_v, std::vector<int> &how);
  // this step's ghost point of owned atom i (after an interpolation)
  const double *ghost_point_of(int i) const { return &ghost_at[3 * (size_t) i]; }
  // after init(): the number of wall atoms beyond the kernel's reach of the
  // surface (no ghost point) and the lowest ID among them
  bigint beyond_reach() const { return deep_count; }
  tagint first_beyond_reach() const { return deep_first; }

  // after atoms were exchanged or sorted (the owner's pre_neighbor): the
  // candidates kept from the last neighbour build are stale
  void neighbours_changed()
  {
    candidates_valid = false;
    crossing_check_pending = true;
  }

  // mark the owned wall atoms within the kernel's reach of a particle of a
  // wall that holds a temperature (a corner with a Dirichlet or isothermal
  // wall), after interpolate() in the same step; then at_junction(i)
  void find_junctions();
  int at_junction(int i) const { return junction[i]; }

  // give heat rates back to the medium: rate[i] (energy per time) of the
  // owned wall atom i, unless at a junction, goes to the medium around its
  // ghost point with the Shepard weights of its last interpolate(); the
  // result is added to desph of the owned medium atoms (needs the fix's
  // reverse comm)
  void return_heat(const std::vector<double> &rate, class Fix *owner);
  int pack_reverse_comm(int n, int first, double *buf);
  void unpack_reverse_comm(int n, int *list, double *buf);

 protected:
  std::string command, region_name, fix_id;
  bool returns_heat;
  Field field;
  class Region *region;
  int groupbit, medium_exclude;
  int held_walls;    // walls that hold a temperature (Dirichlet, isothermal)
  int kernel_kind;
  double cutoff;
  // the axis of the inlet plane of fix sph/inlet/temperature (-1: none):
  // medium across that plane is not interpolated from
  int inlet_axis;
  // the medium atoms near each ghost point and their Shepard weights
  std::vector<int> first_neighbour, neighbours;
  std::vector<double> weights;
  std::vector<double> returned;    // per atom (owned and ghost), energy rate
  std::vector<int> junction;       // per owned atom: next to another kind of wall
  // the atoms not in the group (owned and ghost) in cells of side cutoff,
  // binned at each neighbour build
  SPHCells cells;
  // per owned wall atom, kept from one neighbour build to the next: the
  // medium atoms within cutoff + skin of its ghost point as it was then
  // (candidates_at); the medium moves less than half the skin in that time
  // candidates[n] indexes medium_atoms, the atoms near some ghost point,
  // whose volume and temperature are found once per step
  std::vector<int> first_candidate, candidates, medium_atoms;
  // per owned wall atom: the atoms of held walls within cutoff + skin of
  // it (held_near indexes held_atoms)
  std::vector<int> first_held, held_near, held_atoms;
  std::vector<double> candidates_at;    // 3 per owned atom
  bigint deep_count = 0;
  tagint deep_first = 0;
  bool candidates_valid;
  bool medium_check_pending;      // check_medium() at the next interpolate()
  bool crossing_check_pending;    // check_medium(true) at the next interpolate()
  bool crossing_warned;           // a medium atom was found in the wall this run
  double first_row_depth;         // the depth of the nearest wall atom
  // per medium atom: its volume and the field (T, or the 3 components of v)
  std::vector<double> medium_volume, medium_values;
  // their positions this step, 3 per medium atom: the candidate loop reads
  // them in one load rather than through the atom index
  std::vector<double> medium_x;
  // this step's ghost points: 3 per owned atom, and whether there is one
  std::vector<double> ghost_at;
  std::vector<int> has_ghost;

  int ghost_point(const double *x, double *ghost, double *depth = nullptr);
  void check_medium(bool during_run = false);
  // "Fix <ID> <style>", or the command when the ID is not known
  std::string who() const
  {
    return fix_id.empty() ? command : "Fix " + fix_id + " " + command.substr(command.find(' ') + 1);
  }
  void find_candidates();
  // the ghost points, their candidates and the medium's values of the
  // field (its temperature or velocity) of this step
  void prepare(std::vector<int> &how, std::vector<double> *depth);
  // prepare() and the interpolation at every ghost point (1 value per
  // owned atom for the temperature, 12 for the velocity)
  void interpolate_field(std::vector<double> &out, std::vector<int> &how,
                         std::vector<double> *depth);
  // per thread (package omp): the candidates of one ghost point inside the
  // support, and the Shepard neighbours and weights of its slice of atoms
  // (thread 0's are first_neighbour's)
  struct PointScratch {
    SPHSupport support;
    std::vector<int> neighbours;
    std::vector<double> weights;
    std::vector<double> basis;    // the quadratic fit's basis of each neighbour
  };
  std::vector<PointScratch> threads;
  // the owned atoms with a ghost point this step, and how many Shepard
  // neighbours each has (per owned atom)
  std::vector<int> with_ghost, neighbour_count;
  struct PointsCall;    // interpolate_points for this run's settings (sph_dispatch.h)
  template <int DIM, int KERNEL>
  void interpolate_points(std::vector<double> &ghost, std::vector<int> &how,
                          const sphk_kernel &kernel);
  template <int DIM, int KERNEL>
  void interpolate_slice(int from, int to, std::vector<double> &ghost, std::vector<int> &how,
                         const sphk_kernel &kernel, SPHSupport &support, std::vector<double> &basis,
                         std::vector<int> &near, std::vector<double> &near_weights);
};

}    // namespace LAMMPS_NS

#endif
