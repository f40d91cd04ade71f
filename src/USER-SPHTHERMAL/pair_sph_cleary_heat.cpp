/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: SPH heat conduction of Cleary 1998 (eq 6), with a
   harmonic-mean conductivity so that the heat flux stays continuous
   across material interfaces.
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "sph_conduction.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::PairSPHClearyHeat(LAMMPS *lmp) :
    Pair(lmp), kernel_kind(-1), cut_global(0.0), eta_factor(0.1), eta2(0.0), conductivity(nullptr),
    conductivity_set(nullptr), conductance(nullptr)
{
  restartinfo = 1;
  writedata = 1;
  single_enable = 0;
  memset(&kernel, 0, sizeof(kernel));
}

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::~PairSPHClearyHeat()
{
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(conductivity);
    memory->destroy(conductivity_set);
    memory->destroy(conductance);
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  switch (kernel_kind) {
    case SPHK_LUCY:
      eval_kernel<SPHK_LUCY>();
      break;
    case SPHK_CUBIC:
      eval_kernel<SPHK_CUBIC>();
      break;
    case SPHK_QUINTIC:
      eval_kernel<SPHK_QUINTIC>();
      break;
    case SPHK_WENDLAND:
      eval_kernel<SPHK_WENDLAND>();
      break;
  }
}

template <int KERNEL> void PairSPHClearyHeat::eval_kernel()
{
  const int newton_pair = force->newton_pair;
  const int rmass = (atom->rmass_flag && atom->rmass) ? 1 : 0;
  if (newton_pair) {
    if (rmass)
      eval<KERNEL, 1, 1>();
    else
      eval<KERNEL, 1, 0>();
  } else {
    if (rmass)
      eval<KERNEL, 0, 1>();
    else
      eval<KERNEL, 0, 0>();
  }
}

/* ----------------------------------------------------------------------
   de_i/dt += m_j F_ij and de_j/dt -= m_i F_ij for every pair within the
   kernel support (sph_conduction.h); T = esph / cv
------------------------------------------------------------------------- */

template <int KERNEL, int NEWTON_PAIR, int RMASS> void PairSPHClearyHeat::eval()
{
  const double *const *const x = atom->x;
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const double *const rho = atom->rho;
  const double *const mass = atom->mass;
  const double *const rmass = atom->rmass;
  const int *const type = atom->type;
  double *const desph = atom->desph;
  const int nlocal = atom->nlocal;

  const double cutsq_kernel = cut_global * cut_global;
  const double inv_h = kernel.inv_h;
  const double dw_scale = kernel.dw_scale;

  const int inum = list->inum;
  const int *const ilist = list->ilist;
  const int *const numneigh = list->numneigh;
  int **const firstneigh = list->firstneigh;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int itype = type[i];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double temp_i = esph[i] / cv[i];
    const double rho_i = rho[i];
    const double mass_i = RMASS ? rmass[i] : mass[itype];
    const double *const conductance_i = conductance[itype];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double desph_i = 0.0;

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq_kernel) continue;

      const int jtype = type[j];
      const double r = sqrt(rsq);
      const double dwdr = dw_scale * sphk_df(KERNEL, r * inv_h);
      const double f_ij = sphc_cleary_pair(conductance_i[jtype], temp_i - esph[j] / cv[j], rho_i,
                                           rho[j], r, dwdr, eta2);
      desph_i += (RMASS ? rmass[j] : mass[jtype]) * f_ij;
      if (NEWTON_PAIR || j < nlocal) desph[j] -= mass_i * f_ij;
    }
    desph[i] += desph_i;
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  memory->create(conductance, n + 1, n + 1, "pair:conductance");
  memory->create(conductivity, n + 1, "pair:conductivity");
  memory->create(conductivity_set, n + 1, "pair:conductivity_set");
  for (int i = 0; i <= n; i++) {
    conductivity[i] = 0.0;
    conductivity_set[i] = 0;
    for (int j = 0; j <= n; j++) setflag[i][j] = 0;
  }
}

/* ----------------------------------------------------------------------
   pair_style sph/cleary/heat kernel cutoff [eta factor]
------------------------------------------------------------------------- */

void PairSPHClearyHeat::settings(int narg, char **arg)
{
  if (narg < 2)
    error->all(FLERR, "Illegal pair_style sph/cleary/heat command: expected <kernel> <cutoff>");

  kernel_kind = sphk_lookup(arg[0]);
  if (kernel_kind < 0)
    error->all(FLERR,
               "Illegal pair_style sph/cleary/heat command: unknown kernel '{}' "
               "(lucy, cubic, quintic or wendland)",
               arg[0]);

  cut_global = utils::numeric(FLERR, arg[1], false, lmp);
  if (cut_global <= 0.0)
    error->all(FLERR, "Illegal pair_style sph/cleary/heat command: cutoff {} must be > 0", arg[1]);

  eta_factor = 0.1;
  int iarg = 2;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eta") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: missing value after 'eta'");
      eta_factor = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (eta_factor <= 0.0)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: eta {} must be > 0",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal pair_style sph/cleary/heat command: unknown keyword '{}'",
                 arg[iarg]);
  }
}

/* ----------------------------------------------------------------------
   pair_coeff I I k: conductivity of the types I (a range or * is allowed);
   pairs of unlike types use the harmonic mean, so only I I is accepted
------------------------------------------------------------------------- */

void PairSPHClearyHeat::coeff(int narg, char **arg)
{
  if (narg != 3)
    error->all(FLERR,
               "Illegal pair_coeff command for sph/cleary/heat: expected I I <conductivity>");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  if (ilo != jlo || ihi != jhi)
    error->all(FLERR,
               "Illegal pair_coeff command for sph/cleary/heat: conductivity is per type, "
               "use I I (or * *), not {} {}",
               arg[0], arg[1]);

  const double k = utils::numeric(FLERR, arg[2], false, lmp);
  if (k < 0.0)
    error->all(FLERR, "Illegal pair_coeff command for sph/cleary/heat: conductivity {} is negative",
               arg[2]);

  for (int i = ilo; i <= ihi; i++) {
    conductivity[i] = k;
    conductivity_set[i] = 1;
  }

  // unlike pairs follow from the per-type values; a missing type is reported by init_style
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) setflag[i][j] = 1;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::init_style()
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Pair style sph/cleary/heat requires atom style sph (esph, desph, cv, rho)");

  for (int i = 1; i <= atom->ntypes; i++)
    if (!conductivity_set[i])
      error->all(
          FLERR,
          "Pair style sph/cleary/heat: no conductivity for atom type {} (pair_coeff {} {} <k>)", i,
          i, i);

  kernel = sphk_make(kernel_kind, domain->dimension, cut_global);
  const double eta = eta_factor * kernel.h;
  eta2 = eta * eta;

  neighbor->request(this, instance_me);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::init_one(int i, int j)
{
  conductance[i][j] = conductance[j][i] = sphc_cleary_conductance(conductivity[i], conductivity[j]);
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::write_restart_settings(FILE *fp)
{
  fwrite(&kernel_kind, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&eta_factor, sizeof(double), 1, fp);
}

void PairSPHClearyHeat::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &kernel_kind, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &eta_factor, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&kernel_kind, 1, MPI_INT, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&eta_factor, 1, MPI_DOUBLE, 0, world);
}

void PairSPHClearyHeat::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++) {
    fwrite(&conductivity_set[i], sizeof(int), 1, fp);
    fwrite(&conductivity[i], sizeof(double), 1, fp);
  }
}

void PairSPHClearyHeat::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  for (int i = 1; i <= atom->ntypes; i++) {
    if (comm->me == 0) {
      utils::sfread(FLERR, &conductivity_set[i], sizeof(int), 1, fp, nullptr, error);
      utils::sfread(FLERR, &conductivity[i], sizeof(double), 1, fp, nullptr, error);
    }
    MPI_Bcast(&conductivity_set[i], 1, MPI_INT, 0, world);
    MPI_Bcast(&conductivity[i], 1, MPI_DOUBLE, 0, world);
  }
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++) setflag[i][j] = 1;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::write_data(FILE *fp)
{
  for (int i = 1; i <= atom->ntypes; i++) fprintf(fp, "%d %.17g\n", i, conductivity[i]);
}
