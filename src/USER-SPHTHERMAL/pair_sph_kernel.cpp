/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The common part of the package's SPH pair styles (pair_sph_kernel.h).
------------------------------------------------------------------------- */

#include "pair_sph_kernel.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHKernel::PairSPHKernel(LAMMPS *lmp, const char *style, const char *from_materials) :
    Pair(lmp), style(style), from_materials(from_materials), kernel_kind(-1), cut_global(0.0),
    eta_factor(0.1)
{
  restartinfo = 1;
  single_enable = 0;
  memset(&kernel, 0, sizeof(kernel));
}

PairSPHKernel::~PairSPHKernel()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairSPHKernel::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
}

/* ---------------------------------------------------------------------- */

int PairSPHKernel::parse_kernel(int narg, char **arg)
{
  if (narg < 2)
    error->all(FLERR, "Illegal pair_style {} command: expected <kernel> <cutoff>", style);
  kernel_kind = sphk_lookup(arg[0]);
  if (kernel_kind < 0)
    error->all(FLERR,
               "Illegal pair_style {} command: unknown kernel '{}' (lucy, cubic, quintic or "
               "wendland)",
               style, arg[0]);
  cut_global = utils::numeric(FLERR, arg[1], false, lmp);
  if (cut_global <= 0.0)
    error->all(FLERR, "Illegal pair_style {} command: cutoff {} must be > 0", style, arg[1]);
  return 2;
}

double PairSPHKernel::init_kernel()
{
  kernel = sphk_make(kernel_kind, domain->dimension, cut_global);
  const double eta = eta_factor * kernel.h;
  return eta * eta;
}

/* ----------------------------------------------------------------------
   pair_coeff I J: no coefficients, the materials come from fix sph/materials
------------------------------------------------------------------------- */

void PairSPHKernel::coeff(int narg, char **arg)
{
  if (narg != 2)
    error->all(FLERR, "Illegal pair_coeff command for {}: expected I J only ({})", style,
               from_materials);
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Illegal pair_coeff command for {}: no type pair", style);
}

/* ---------------------------------------------------------------------- */

void PairSPHKernel::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) fwrite(&setflag[i][j], sizeof(int), 1, fp);
}

void PairSPHKernel::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (comm->me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
    }
}

/* ----------------------------------------------------------------------
   the kernel settings, for styles that evaluate the same kernel
------------------------------------------------------------------------- */

void *PairSPHKernel::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "kernel_kind") == 0) return (void *) &kernel_kind;
  if (strcmp(name, "cutoff") == 0) return (void *) &cut_global;
  if (strcmp(name, "eta_factor") == 0) return (void *) &eta_factor;
  return nullptr;
}
