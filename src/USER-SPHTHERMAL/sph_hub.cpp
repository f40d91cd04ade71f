/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   How the package's styles find each other (sph_hub.h).
------------------------------------------------------------------------- */

#include "sph_hub.h"

#include "compute.h"
#include "error.h"
#include "fix_sph_dt_reset.h"
#include "fix_sph_materials.h"
#include "fix_sph_surface_flux.h"
#include "fix_sph_timestep_check.h"
#include "fix_sph_wall_adami.h"
#include "fix_sph_wall_isothermal.h"
#include "force.h"
#include "pair.h"
#include "pair_sph_cleary_heat.h"
#include "pair_sph_harmonic_visc.h"
#include "utils.h"

#include <algorithm>
#include <cstring>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   LAMMPS lists a hybrid's sub-styles only through Force::pair_match; every
   style of this package is named sph/..., so one pattern reaches them all
   (and LAMMPS's SPH pairs, which the type test leaves out)
------------------------------------------------------------------------- */

std::vector<PairSPHKernel *> SPHHub::pairs() const
{
  std::vector<PairSPHKernel *> found;
  if (!force->pair) return found;
  if (!utils::strmatch(force->pair_style, "^hybrid")) {
    if (auto *pair = dynamic_cast<PairSPHKernel *>(force->pair)) found.push_back(pair);
    return found;
  }
  std::vector<Pair *> seen;
  for (int n = 1;; n++) {
    Pair *sub = force->pair_match("^sph/", 0, n);
    // past the last match, pair_match gives nothing, or the only one again
    if (!sub || std::find(seen.begin(), seen.end(), sub) != seen.end()) break;
    seen.push_back(sub);
    if (auto *pair = dynamic_cast<PairSPHKernel *>(sub)) found.push_back(pair);
  }
  return found;
}

PairSPHClearyHeat *SPHHub::heat() const
{
  for (PairSPHKernel *pair : pairs())
    if (auto *heat = dynamic_cast<PairSPHClearyHeat *>(pair)) return heat;
  return nullptr;
}

PairSPHHarmonicVisc *SPHHub::flow() const
{
  for (PairSPHKernel *pair : pairs())
    if (auto *flow = dynamic_cast<PairSPHHarmonicVisc *>(pair)) return flow;
  return nullptr;
}

PairSPHClearyHeat *SPHHub::require_heat(const char *who) const
{
  PairSPHClearyHeat *pair = heat();
  if (!pair) error->all(FLERR, "{} requires pair style sph/cleary/heat", who);
  return pair;
}

PairSPHHarmonicVisc *SPHHub::require_flow(const char *who) const
{
  PairSPHHarmonicVisc *pair = flow();
  if (!pair) error->all(FLERR, "{} requires pair style sph/harmonic/visc", who);
  return pair;
}

/* ----------------------------------------------------------------------
   the package's styles are named sph/... and, internal ones, SPH/...
------------------------------------------------------------------------- */

bool SPHHub::ours(const Fix *fix)
{
  return utils::strmatch(fix->style, "^sph/") || utils::strmatch(fix->style, "^SPH/");
}

/* ----------------------------------------------------------------------
   LAMMPS's own fixes: their classes live in packages whose headers the
   plugin does not see, so by name
------------------------------------------------------------------------- */

bool SPHHub::fix_sph_moves(const Fix *fix) const
{
  return strcmp(fix->style, "sph") == 0;
}

int SPHHub::moved_by_fix_sph() const
{
  int bits = 0;
  for (int i = 0; i < modify->nfix; i++)
    if (fix_sph_moves(modify->fix[i])) bits |= modify->fix[i]->groupbit;
  return bits;
}

int SPHHub::held_by_fix_sph_stationary() const
{
  int bits = 0;
  for (int i = 0; i < modify->nfix; i++)
    if (strcmp(modify->fix[i]->style, "sph/stationary") == 0) bits |= modify->fix[i]->groupbit;
  return bits;
}

Fix *SPHHub::timestep_resetter(const Fix *self) const
{
  for (int i = 0; i < modify->nfix; i++)
    if (modify->fix[i] != self &&
        (dynamic_cast<FixSPHDtReset *>(modify->fix[i]) ||
         strcmp(modify->fix[i]->style, "dt/reset") == 0))
      return modify->fix[i];
  return nullptr;
}

bool SPHHub::rigid(const Fix *fix) const
{
  return utils::strmatch(fix->style, "^rigid");
}

bool SPHHub::moves_bodies(const Fix *fix) const
{
  // (MACHDYN's integrators move and deform its solids)
  return rigid(fix) || utils::strmatch(fix->style, "^move") ||
      utils::strmatch(fix->style, "^smd/integrate");
}

bool SPHHub::adds_force(const Fix *fix) const
{
  return utils::strmatch(fix->style, "^addforce");
}

int SPHHub::heat_flow_integrated() const
{
  int bits = 0;
  for (int i = 0; i < modify->nfix; i++)
    if (strcmp(modify->fix[i]->style, "heat/flow") == 0) bits |= modify->fix[i]->groupbit;
  return bits;
}

/* ----------------------------------------------------------------------
   MACHDYN's solids (sph_machdyn.h): LAMMPS's pair smd/tlsph by name; the
   package's styles that follow the solids' energy convention by type
------------------------------------------------------------------------- */

Pair *SPHHub::machdyn_solids_pair() const
{
  return force->pair_match("^smd/tlsph", 0);
}

const double *SPHHub::machdyn_deformation_det() const
{
  Pair *tlsph = machdyn_solids_pair();
  int dim = 0;
  return tlsph ? static_cast<const double *>(tlsph->extract("smd/tlsph/detF_ptr", dim)) : nullptr;
}

bool SPHHub::may_act_on_machdyn(const Fix *fix) const
{
  if (is_any<FixSPHMaterials, FixSPHWallIsothermal, FixSPHSurfaceFlux, FixSPHTimestepCheck,
             FixSPHWallAdami>(fix))
    return true;
  return !(ours(fix) || fix_sph_moves(fix) || strcmp(fix->style, "sph/stationary") == 0);
}

bool SPHHub::may_act_on_machdyn(const Compute *compute) const
{
  // compute sph/thermal follows the convention; sph/e/atom and sph/rho/atom
  // only show esph and rho
  if (strcmp(compute->style, "sph/thermal") == 0 || strcmp(compute->style, "sph/e/atom") == 0 ||
      strcmp(compute->style, "sph/rho/atom") == 0)
    return true;
  return !utils::strmatch(compute->style, "^sph/");
}
