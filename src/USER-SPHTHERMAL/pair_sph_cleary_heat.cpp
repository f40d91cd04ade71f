/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat: SPH heat conduction of Cleary 1998 (eq 6), with a
   harmonic-mean (or arithmetic-mean) conductivity from fix sph/materials.
------------------------------------------------------------------------- */

#include "pair_sph_cleary_heat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_conduction.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::PairSPHClearyHeat(LAMMPS *lmp) :
    PairSPHKernel(lmp, "sph/cleary/heat", "conductivities come from fix sph/materials"),
    mean(SPHC_HARMONIC), eta2(0.0), materials(nullptr), conductivity_varies(0),
    conductance(nullptr), conductivity(nullptr), nmax(0), relax_wanted(0), relax_rate(nullptr),
    nmax_relax(0)
{
  comm_reverse = 1;    // relax_rate, when wanted
}

/* ---------------------------------------------------------------------- */

PairSPHClearyHeat::~PairSPHClearyHeat()
{
  memory->destroy(conductance);
  memory->destroy(conductivity);
  memory->destroy(relax_rate);
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (conductivity_varies) update_conductivity();
  if (update->setupflag) check_neighbours();
  if (relax_wanted) {
    if (atom->nmax > nmax_relax) {
      nmax_relax = atom->nmax;
      memory->destroy(relax_rate);
      memory->create(relax_rate, nmax_relax, "pair:relax_rate");
    }
    const int nall = atom->nlocal + atom->nghost;
    for (int i = 0; i < nall; i++) relax_rate[i] = 0.0;
  }

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
  check_rates(atom->desph, "desph");

  if (!flows.empty()) tally_flows();

  if (relax_wanted) {
    if (force->newton_pair) SPHCompat::reverse_comm(comm, this);
    const double *const cv = atom->cv;
    for (int i = 0; i < atom->nlocal; i++) relax_rate[i] /= cv[i];
  }
}

template <int KERNEL> void PairSPHClearyHeat::eval_kernel()
{
  if (mean == SPHC_ARITHMETIC)
    eval_mean<KERNEL, SPHC_ARITHMETIC>();
  else
    eval_mean<KERNEL, SPHC_HARMONIC>();
}

template <int KERNEL, int MEAN> void PairSPHClearyHeat::eval_mean()
{
  const int flags = (relax_wanted ? 8 : 0) | (conductivity_varies ? 4 : 0) |
      (force->newton_pair ? 2 : 0) | ((atom->rmass_flag && atom->rmass) ? 1 : 0);
  switch (flags) {
    case 0: eval<KERNEL, MEAN, 0, 0, 0, 0>(); break;
    case 1: eval<KERNEL, MEAN, 0, 0, 1, 0>(); break;
    case 2: eval<KERNEL, MEAN, 0, 1, 0, 0>(); break;
    case 3: eval<KERNEL, MEAN, 0, 1, 1, 0>(); break;
    case 4: eval<KERNEL, MEAN, 1, 0, 0, 0>(); break;
    case 5: eval<KERNEL, MEAN, 1, 0, 1, 0>(); break;
    case 6: eval<KERNEL, MEAN, 1, 1, 0, 0>(); break;
    case 7: eval<KERNEL, MEAN, 1, 1, 1, 0>(); break;
    case 8: eval<KERNEL, MEAN, 0, 0, 0, 1>(); break;
    case 9: eval<KERNEL, MEAN, 0, 0, 1, 1>(); break;
    case 10: eval<KERNEL, MEAN, 0, 1, 0, 1>(); break;
    case 11: eval<KERNEL, MEAN, 0, 1, 1, 1>(); break;
    case 12: eval<KERNEL, MEAN, 1, 0, 0, 1>(); break;
    case 13: eval<KERNEL, MEAN, 1, 0, 1, 1>(); break;
    case 14: eval<KERNEL, MEAN, 1, 1, 0, 1>(); break;
    case 15: eval<KERNEL, MEAN, 1, 1, 1, 1>(); break;
  }
}

/* ----------------------------------------------------------------------
   conductivity of every owned and ghost atom at its temperature
   (ghosts carry esph, cv and mask, so no communication is needed); a dummy
   of fix sph/wall/dirichlet takes the wall temperature, since its
   extrapolated one is no state of the material and can lie far outside the
   range of the law (k = exp(4 T) would choke the wall)
------------------------------------------------------------------------- */

void PairSPHClearyHeat::update_conductivity()
{
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(conductivity);
    memory->create(conductivity, nmax, "pair:conductivity");
  }
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) {
    double temperature = esph[i] / cv[i];
    for (const auto &wall : dummy_walls)
      if (mask[i] & wall.first) temperature = wall.second;
    conductivity[i] = materials->conductivity_at(type[i], temperature, "Pair style sph/cleary/heat");
  }
}

/* ----------------------------------------------------------------------
   de_i/dt += m_j F_ij and de_j/dt -= m_i F_ij for every pair within the
   kernel support (sph_conduction.h); T = esph / cv
------------------------------------------------------------------------- */

template <int KERNEL, int MEAN, int VARYING_K, int NEWTON_PAIR, int RMASS, int RELAX>
void PairSPHClearyHeat::eval()
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
    const double k_i = VARYING_K ? conductivity[i] : 0.0;
    const double *const conductance_i = conductance[itype];
    const int *const jlist = firstneigh[i];
    const int jnum = numneigh[i];
    double desph_i = 0.0, relax_i = 0.0;

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
      const double conductance_ij =
          VARYING_K ? sphc_conductance(MEAN, k_i, conductivity[j]) : conductance_i[jtype];
      const double temp_ij = temp_i - esph[j] / cv[j];
      const double mass_j = RMASS ? rmass[j] : mass[jtype];
      // with RELAX, F_ij per unit temperature difference (<= 0, as dW/dr) is
      // needed too: one evaluation serves both
      const double g_ij = RELAX ? sphc_cleary_pair(conductance_ij, 1.0, rho_i, rho[j], r, dwdr, eta2)
                                : 0.0;
      const double f_ij = RELAX
          ? g_ij * temp_ij
          : sphc_cleary_pair(conductance_ij, temp_ij, rho_i, rho[j], r, dwdr, eta2);
      desph_i += mass_j * f_ij;
      if (NEWTON_PAIR || j < nlocal) desph[j] -= mass_i * f_ij;
      if (RELAX) {
        relax_i -= mass_j * g_ij;
        if (NEWTON_PAIR || j < nlocal) relax_rate[j] -= mass_i * g_ij;
      }
    }
    desph[i] += desph_i;
    if (RELAX) relax_rate[i] += relax_i;
  }
}

/* ----------------------------------------------------------------------
   the heat flows asked for: the pair terms of eval() between atoms of the
   two groups, with the energy each side receives (the j side only where
   eval() gives it to an atom of this rank), summed over the ranks
------------------------------------------------------------------------- */

int PairSPHClearyHeat::request_heat_flow(int to_groupbit, int from_groupbit)
{
  flows.push_back({to_groupbit, from_groupbit, 0.0});
  return (int) flows.size() - 1;
}

double PairSPHClearyHeat::pair_term(int i, int j, double rsq, double temp_ij) const
{
  const double r = sqrt(rsq);
  const double dwdr = kernel_dwdr(r);
  const int *const type = atom->type;
  const double conductance_ij = conductivity_varies
      ? sphc_conductance(mean, conductivity[i], conductivity[j])
      : conductance[type[i]][type[j]];
  return sphc_cleary_pair(conductance_ij, temp_ij, atom->rho[i], atom->rho[j], r, dwdr, eta2);
}

void PairSPHClearyHeat::tally_flows()
{
  const double *const *const x = atom->x;
  const double *const esph = atom->esph;
  const double *const cv = atom->cv;
  const double *const mass = atom->mass;
  const double *const rmass = (atom->rmass_flag && atom->rmass) ? atom->rmass : nullptr;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int newton = force->newton_pair;
  const double cutsq_kernel = cut_global * cut_global;
  int either = 0;
  for (const auto &flow : flows) either |= flow.to | flow.from;

  std::vector<double> local(flows.size(), 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & either)) continue;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & either)) continue;
      const double delx = x[i][0] - x[j][0];
      const double dely = x[i][1] - x[j][1];
      const double delz = x[i][2] - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      if (rsq >= cutsq_kernel) continue;
      const double f_ij = pair_term(i, j, rsq, esph[i] / cv[i] - esph[j] / cv[j]);
      const double energy = (rmass ? rmass[i] : mass[type[i]]) *
          (rmass ? rmass[j] : mass[type[j]]) * f_ij;    // into i, out of j
      for (size_t k = 0; k < flows.size(); k++) {
        if ((mask[i] & flows[k].to) && (mask[j] & flows[k].from)) local[k] += energy;
        if ((mask[j] & flows[k].to) && (mask[i] & flows[k].from) && (newton || j < nlocal))
          local[k] -= energy;
      }
    }
  }
  std::vector<double> total(flows.size(), 0.0);
  MPI_Allreduce(local.data(), total.data(), (int) flows.size(), MPI_DOUBLE, MPI_SUM, world);
  for (size_t k = 0; k < flows.size(); k++) flows[k].power = total[k];
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::allocate()
{
  PairSPHKernel::allocate();
  const int n = atom->ntypes;
  memory->create(conductance, n + 1, n + 1, "pair:conductance");
  for (int i = 0; i <= n; i++)
    for (int j = 0; j <= n; j++) conductance[i][j] = 0.0;
}

/* ----------------------------------------------------------------------
   pair_style sph/cleary/heat kernel cutoff [mean harmonic|arithmetic] [eta f]
------------------------------------------------------------------------- */

void PairSPHClearyHeat::settings(int narg, char **arg)
{
  int iarg = parse_kernel(narg, arg);
  eta_factor = 0.1;
  mean = SPHC_HARMONIC;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "eta") != 0 && strcmp(arg[iarg], "mean") != 0)
      error->all(FLERR,
                 "Illegal pair_style sph/cleary/heat command: unknown keyword '{}' (after the "
                 "kernel and cutoff: eta or mean)",
                 arg[iarg]);
    if (iarg + 1 >= narg)
      error->all(FLERR, "Illegal pair_style sph/cleary/heat command: missing value after '{}'",
                 arg[iarg]);
    if (strcmp(arg[iarg], "eta") == 0) {
      eta_factor = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (eta_factor < 0.0)
        error->all(FLERR, "Illegal pair_style sph/cleary/heat command: eta {} must be >= 0",
                   arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "mean") == 0) {
      if (strcmp(arg[iarg + 1], "harmonic") == 0)
        mean = SPHC_HARMONIC;
      else if (strcmp(arg[iarg + 1], "arithmetic") == 0)
        mean = SPHC_ARITHMETIC;
      else
        error->all(FLERR,
                   "Illegal pair_style sph/cleary/heat command: unknown mean '{}' "
                   "(harmonic or arithmetic)",
                   arg[iarg + 1]);
    }
    iarg += 2;
  }
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::init_style()
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Pair style sph/cleary/heat requires atom style sph (esph, desph, cv, rho)");

  materials = FixSPHMaterials::find(lmp, "Pair style sph/cleary/heat");
  flows.clear();    // the fixes that want them ask again at their init
  for (int i = 1; i <= atom->ntypes; i++)
    if (!materials->conductivity(i))
      error->all(FLERR,
                 "Pair style sph/cleary/heat: atom type {} has no conductivity in fix "
                 "sph/materials",
                 i);
  conductivity_varies = !materials->conductivity_constant();
  relax_wanted = 0;    // set again by the styles that want it, at their init
  SPHCheck::atom_state(lmp, "Pair style sph/cleary/heat", 0,
                       SPHCheck::RHO | SPHCheck::CV | SPHCheck::ESPH);

  dummy_walls.clear();
  for (Fix *wall : SPHCompat::fixes_of_style(modify, "sph/wall/dirichlet")) {
    int dim;
    const double *t_wall = (const double *) wall->extract("t_wall", dim);
    dummy_walls.emplace_back(wall->groupbit, *t_wall);
  }

  eta2 = init_kernel();

  SPHCompat::request_half_list(neighbor, this, instance_me);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::init_one(int i, int j)
{
  // with constant conductivities the conductance is a property of the type pair
  if (!conductivity_varies)
    conductance[i][j] = conductance[j][i] = sphc_conductance(
        mean, materials->conductivity(i)->c[0], materials->conductivity(j)->c[0]);
  return cut_global;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeat::write_restart_settings(FILE *fp)
{
  fwrite(&kernel_kind, sizeof(int), 1, fp);
  fwrite(&mean, sizeof(int), 1, fp);
  fwrite(&cut_global, sizeof(double), 1, fp);
  fwrite(&eta_factor, sizeof(double), 1, fp);
}

void PairSPHClearyHeat::read_restart_settings(FILE *fp)
{
  if (comm->me == 0) {
    utils::sfread(FLERR, &kernel_kind, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &mean, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &cut_global, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &eta_factor, sizeof(double), 1, fp, nullptr, error);
  }
  MPI_Bcast(&kernel_kind, 1, MPI_INT, 0, world);
  MPI_Bcast(&mean, 1, MPI_INT, 0, world);
  MPI_Bcast(&cut_global, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&eta_factor, 1, MPI_DOUBLE, 0, world);
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeat::memory_usage()
{
  return Pair::memory_usage() + (double) (nmax + nmax_relax) * sizeof(double);
}

/* ----------------------------------------------------------------------
   relax_rate: per-atom array (owned atoms valid after compute()), filled
   from the next compute() on once relax_rate_wanted is set to 1
------------------------------------------------------------------------- */

void *PairSPHClearyHeat::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "relax_rate_wanted") == 0) return (void *) &relax_wanted;
  if (strcmp(name, "relax_rate") == 0) {
    dim = 1;
    return (void *) &relax_rate;
  }
  return PairSPHKernel::extract(name, dim);
}

int PairSPHClearyHeat::pack_reverse_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) buf[k] = relax_rate[first + k];
  return n;
}

void PairSPHClearyHeat::unpack_reverse_comm(int n, int *list, double *buf)
{
  for (int k = 0; k < n; k++) relax_rate[list[k]] += buf[k];
}

/* ----------------------------------------------------------------------
   beyond the state every SPH pair reads: the conductivity of atom i
------------------------------------------------------------------------- */

std::string PairSPHClearyHeat::diagnose(int i)
{
  std::string why = PairSPHKernel::diagnose(i);
  if (why.empty() && conductivity_varies && !std::isfinite(conductivity[i]))
    why = fmt::format("its conductivity is {}", conductivity[i]);
  return why;
}
