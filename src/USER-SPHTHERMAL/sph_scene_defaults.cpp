/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The defaults that depend on the kind of scene (sph_scene_defaults.h).
   Why these: doc/src/Howto_settings.rst. In the differentially heated
   cavity (de Vahl Davis 1983) the pressure-gradient correction, the
   consistent conduction and shifting together keep the mean Nusselt number
   within the benchmark's bounds from Ra = 1e3 to 1e6, which no one or two
   of them do; a column at rest with a free surface is disturbed more with
   the gradient correction, so flows without buoyancy keep the plain forms.
------------------------------------------------------------------------- */

#include "sph_scene_defaults.h"

#include "comm.h"
#include "fix_sph_boussinesq.h"
#include "lammps.h"
#include "sph_conduction_weights.h"
#include "sph_hub.h"
#include "utils.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

std::string SPHSceneDefaults::buoyancy_fix(LAMMPS *lmp)
{
  const std::vector<FixSPHBoussinesq *> all = SPHHub(lmp).fixes<FixSPHBoussinesq>();
  return all.empty() ? std::string() : std::string(all.front()->id);
}

SPHSceneDefaults::Choice SPHSceneDefaults::flow_correction(LAMMPS *lmp, int averaged_pressure)
{
  const std::string buoyancy = buoyancy_fix(lmp);
  if (buoyancy.empty()) return {0, "the default without buoyancy"};
  if (!averaged_pressure)
    return {0,
            "the default with this pressure form; with buoyancy and the averaged form it is "
            "gradient"};
  return {1, "the default with buoyancy, fix sph/boussinesq " + buoyancy};
}

SPHSceneDefaults::Choice SPHSceneDefaults::heat_correction(LAMMPS *lmp)
{
  const std::string buoyancy = buoyancy_fix(lmp);
  if (buoyancy.empty() || !SPHHub(lmp).flow())
    return {SPHConductionWeights::NONE, "the default without a buoyancy-driven flow"};
  return {SPHConductionWeights::CONSISTENT,
          "the default with buoyancy, fix sph/boussinesq " + buoyancy};
}

void SPHSceneDefaults::log(LAMMPS *lmp, const char *style, const char *setting, const char *value,
                           const Choice &choice, int &last)
{
  if (choice.value == last) return;
  last = choice.value;
  if (lmp->comm->me == 0)
    utils::logmesg(lmp, "Pair style {}: {} {} ({})\n", style, setting, value, choice.why);
}
