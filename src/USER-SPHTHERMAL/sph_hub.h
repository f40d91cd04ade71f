/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_HUB_H
#define LMP_SPH_HUB_H

#include "fix.h"
#include "modify.h"
#include "pointers.h"

#include <vector>

namespace LAMMPS_NS {

class Compute;
class Pair;
class PairSPHKernel;
class PairSPHClearyHeat;
class PairSPHHarmonicVisc;

// The kernel a pair style was given: 'pair_style <style> <kernel> <cutoff>'
// and its eta keyword (eta = eta_factor * h)
struct SPHKernelSettings {
  int kind;             // SPHK_* of sph_kernels.h
  double cutoff;        // the kernel's support radius
  double eta_factor;    // eta = eta_factor * h
};

// How the package's styles find each other: by their C++ type, through
// LAMMPS's own lists (force->pair, alone or in a hybrid; modify->fix), so a
// derived style (the /omp pairs) or a pair in a hybrid is found as its base
// and no style looks another up by name. The look-ups of LAMMPS's own
// styles, which have no type the plugin can see, are here too, in one place.
// A view, not a store: it holds nothing that could outlive a style.
class SPHHub : protected Pointers {
 public:
  explicit SPHHub(LAMMPS *lmp) : Pointers(lmp) {}

  // the package's pair styles of the run, in the order of the hybrid
  std::vector<PairSPHKernel *> pairs() const;
  // the conduction and flow pair styles (nullptr without one; a second
  // instance of one is an error at the pair's init, which comes first)
  PairSPHClearyHeat *heat() const;
  PairSPHHarmonicVisc *flow() const;
  // as above; without one, an error '<who> requires pair style ...'
  PairSPHClearyHeat *require_heat(const char *who) const;
  PairSPHHarmonicVisc *require_flow(const char *who) const;

  // the fixes of type T (and of types derived from it), in the order they
  // were defined
  template <class T> std::vector<T *> fixes() const
  {
    std::vector<T *> found;
    for (int i = 0; i < modify->nfix; i++)
      if (auto *fix = dynamic_cast<T *>(modify->fix[i])) found.push_back(fix);
    return found;
  }
  // the union of their groups
  template <class T> int groupbits() const
  {
    int bits = 0;
    for (T *fix : fixes<T>()) bits |= fix->groupbit;
    return bits;
  }
  // the fixes of any of the types T..., in the order they were defined
  template <class T, class... More> std::vector<Fix *> fixes_of_any() const
  {
    std::vector<Fix *> found;
    for (int i = 0; i < modify->nfix; i++)
      if (is_any<T, More...>(modify->fix[i])) found.push_back(modify->fix[i]);
    return found;
  }
  // whether the fix is one of the package's
  static bool ours(const Fix *fix);

  // LAMMPS's own styles
  // the atoms that fix sph moves, and those that fix sph/stationary holds
  int moved_by_fix_sph() const;
  int held_by_fix_sph_stationary() const;
  bool fix_sph_moves(const Fix *fix) const;
  // a fix other than 'self' that resets the timestep (dt/reset, sph/dt/reset)
  Fix *timestep_resetter(const Fix *self) const;
  // fixes that move atoms as bodies, along a prescribed path or as MACHDYN
  // solids (rigid*, move, smd/integrate_*)
  bool moves_bodies(const Fix *fix) const;
  bool rigid(const Fix *fix) const;
  // fix addforce (a force that the pressure of a hydrostatic start cannot know)
  bool adds_force(const Fix *fix) const;
  // the atoms whose temperature fix heat/flow of LAMMPS's GRANULAR integrates
  int heat_flow_integrated() const;
  // pair smd/tlsph of LAMMPS's MACHDYN, alone or in a hybrid (nullptr without one)
  Pair *machdyn_solids_pair() const;
  // its determinant of the deformation gradient of each owned atom at the
  // last force evaluation (nullptr without the pair)
  const double *machdyn_deformation_det() const;
  // whether a fix or compute may act on the particles of MACHDYN solids:
  // false for the package's styles that do not follow their energy
  // convention (sph_particle.h) and for LAMMPS's SPH styles that integrate
  // or read esph as atom style sph holds it; true for every other style
  bool may_act_on_machdyn(const Fix *fix) const;
  bool may_act_on_machdyn(const Compute *compute) const;

 private:
  template <class T> static bool is_any(const Fix *fix)
  {
    return dynamic_cast<const T *>(fix) != nullptr;
  }
  template <class T, class Next, class... More> static bool is_any(const Fix *fix)
  {
    return dynamic_cast<const T *>(fix) != nullptr || is_any<Next, More...>(fix);
  }
};

}    // namespace LAMMPS_NS

#endif
