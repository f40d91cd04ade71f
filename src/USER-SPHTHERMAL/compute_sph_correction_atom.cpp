/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/correction/atom: where pair sph/cleary/heat's consistency
   correction applies (1) and where the atom keeps the plain term (0); with
   'interface', the distance from the interface that its 'mean interface'
   estimates (-1 where none is within the kernel support).
------------------------------------------------------------------------- */

#include "compute_sph_correction_atom.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair_sph_cleary_heat.h"
#include "sph_hub.h"
#include "sph_checks.h"
#include "sph_conduction.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeSPHCorrectionAtom::ComputeSPHCorrectionAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), state(nullptr), pair(nullptr), interface(0)
{
  if (narg == 4 && strcmp(arg[3], "interface") == 0)
    interface = 1;
  else if (narg != 3)
    error->all(FLERR,
               "Illegal compute sph/correction/atom command: after the group only 'interface' "
               "(got '{}')",
               (narg > 3 && strcmp(arg[3], "interface") == 0) ? arg[4] : arg[3]);
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeSPHCorrectionAtom::~ComputeSPHCorrectionAtom()
{
  memory->destroy(state);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHCorrectionAtom::init()
{
  pair = SPHHub(lmp).require_heat("Compute sph/correction/atom");
  SPHCheck::warn_empty(lmp, FLERR, fmt::format("Compute sph/correction/atom {}", id).c_str(),
                       igroup);
  if (interface ? !pair->interface_mean() : !pair->corrects())
    error->all(FLERR, "Compute sph/correction/atom: pair style sph/cleary/heat runs without '{}'",
               interface ? "mean interface" : "correction consistent or second");
}

/* ---------------------------------------------------------------------- */

void ComputeSPHCorrectionAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(state);
    memory->create(state, nmax, "sph/correction/atom:state");
    vector_atom = state;
  }
  // the pair's array exists from its init on and is filled at its first
  // evaluation of a run, which comes before any compute of the run
  const int *const mask = atom->mask;
  const double outside = interface ? -1.0 : 0.0;
  const double *const pair_state =
      interface ? pair->interface_distances() : pair->correction_states();
  for (int i = 0; i < atom->nlocal; i++) state[i] = (mask[i] & groupbit) ? pair_state[i] : outside;
}

/* ---------------------------------------------------------------------- */

double ComputeSPHCorrectionAtom::memory_usage()
{
  return (double) nmax * sizeof(double);
}
