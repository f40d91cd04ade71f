/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/wall/isothermal: hold the temperature of a group of (solid)
   particles and tally the heat they take up (Cleary 1998, section 2.6 and
   eq 10: the energy-method estimate of the wall heat flux).
------------------------------------------------------------------------- */

#include "fix_sph_wall_isothermal.h"

#include "atom.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "fix_sph_wall_adiabatic.h"
#include "fix_sph_wall_dirichlet.h"
#include "sph_checks.h"
#include "sph_hub.h"
#include "sph_particle.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixSPHWallIsothermal::FixSPHWallIsothermal(LAMMPS *lmp, int narg, char **arg) :
    FixSPHWallTally(lmp, narg, arg)
{
  if (narg < 4) error->all(FLERR, "Illegal fix sph/wall/isothermal command: expected <T>");
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/wall/isothermal requires atom style sph (esph, desph, cv)");

  t_wall = utils::numeric(FLERR, arg[3], false, lmp);
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal fix sph/wall/isothermal command: missing value after 'spacing'");
      spacing = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (spacing <= 0.0)
        error->all(FLERR, "Illegal fix sph/wall/isothermal command: spacing {} must be > 0",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal fix sph/wall/isothermal command: unknown keyword '{}'", arg[iarg]);
  }

  tally_arrays();
}

/* ---------------------------------------------------------------------- */

int FixSPHWallIsothermal::setmask()
{
  return POST_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixSPHWallIsothermal::init()
{
  SPHCheck::group_of_kind(
      lmp, FLERR, this,
      SPHHub(lmp).fixes_of_any<FixSPHWallIsothermal, FixSPHWallDirichlet, FixSPHWallAdiabatic>(),
      false, true);
  SPHCheck::atom_state(lmp, FLERR, "Fix sph/wall/isothermal", groupbit, SPHCheck::CV);
  // the wall is at its temperature before the first force evaluation
  for (FixSPHMaterials *materials : SPHHub(lmp).fixes<FixSPHMaterials>())
    materials->prepare_solids();
  hold();
}

/* ---------------------------------------------------------------------- */

void FixSPHWallIsothermal::setup(int /*vflag*/)
{
  hold_and_tally(1);
}

void FixSPHWallIsothermal::post_force(int /*vflag*/)
{
  hold_and_tally(0);
}

/* ----------------------------------------------------------------------
   tally the heat the wall took up, then hold its temperature
------------------------------------------------------------------------- */

void FixSPHWallIsothermal::hold_and_tally(int first)
{
  tally(first, 1);
  hold();
}

/* ----------------------------------------------------------------------
   every atom of the group at the wall temperature
------------------------------------------------------------------------- */

void FixSPHWallIsothermal::hold()
{
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const esph = atom->esph;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) esph[i] = particles.energy_at(i, t_wall);
}
