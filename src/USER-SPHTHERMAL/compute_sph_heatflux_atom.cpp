/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/heatflux/atom: conductive heat flux -k grad T of each
   particle (first-order corrected kernel gradient), and the heat flux into
   wall particles with normals by the direct estimate of Cleary 1998, eq 9.
------------------------------------------------------------------------- */

#include "compute_sph_heatflux_atom.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "sph_hub.h"
#include "sph_checks.h"
#include "sph_conduction.h"
#include "sph_compat.h"
#include "sph_gradient.h"
#include "sph_kernels.h"
#include "update.h"
#include "sph_particle.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeSPHHeatfluxAtom::ComputeSPHHeatfluxAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), corrected(1), has_normals(0), spacing(0.0), nmax(0), flux(nullptr),
    list(nullptr), materials(nullptr), kernel_kind(0), cutoff(0.0), eta2(0.0)
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Compute sph/heatflux/atom requires atom style sph (esph, cv, rho)");

  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "correction") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal compute sph/heatflux/atom command: missing value after 'correction'");
      corrected = SPHCompat::yes_no(error, FLERR, "compute sph/heatflux/atom", "correction",
                                    arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "normals") == 0) {
      if (iarg + 3 >= narg)
        error->all(FLERR,
                   "Illegal compute sph/heatflux/atom command: 'normals' needs three per-atom "
                   "properties (d_nx d_ny d_nz)");
      for (int k = 0; k < 3; k++) {
        const char *name = arg[iarg + 1 + k];
        if (strncmp(name, "d_", 2) != 0)
          error->all(FLERR,
                     "Illegal compute sph/heatflux/atom command: normal component '{}' is not a "
                     "d_name of fix property/atom",
                     name);
        int flag = -1, cols = -1;
        normal_xyz[k] = atom->find_custom(name + 2, flag, cols);
        if (normal_xyz[k] < 0 || flag != 1 || cols != 0)
          error->all(FLERR,
                     "Compute sph/heatflux/atom: no per-atom double '{}' (define it with fix "
                     "property/atom)",
                     name);
      }
      has_normals = 1;
      iarg += 4;
    } else if (strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal compute sph/heatflux/atom command: missing value after 'spacing'");
      spacing = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (spacing <= 0.0)
        error->all(FLERR, "Illegal compute sph/heatflux/atom command: spacing {} must be > 0",
                   arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal compute sph/heatflux/atom command: unknown keyword '{}'", arg[iarg]);
  }
  if (spacing > 0.0 && !has_normals)
    error->all(FLERR, "Illegal compute sph/heatflux/atom command: 'spacing' needs 'normals'");

  peratom_flag = 1;
  size_peratom_cols = has_normals ? 4 : 3;
  if (has_normals && spacing > 0.0) {
    scalar_flag = 1;
    extscalar = 1;
  }
}

/* ---------------------------------------------------------------------- */

ComputeSPHHeatfluxAtom::~ComputeSPHHeatfluxAtom()
{
  memory->destroy(flux);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHHeatfluxAtom::init()
{
  // kernel, cutoff and eta are those of the conduction pair style
  const SPHKernelSettings given =
      SPHHub(lmp).require_heat("Compute sph/heatflux/atom")->kernel_settings();
  SPHCheck::warn_empty(lmp, FLERR, fmt::format("Compute sph/heatflux/atom {}", id).c_str(), igroup);
  kernel_kind = given.kind;
  cutoff = given.cutoff;
  const double eta = given.eta_factor * cutoff / sphk_support(kernel_kind);
  eta2 = eta * eta;
  materials = FixSPHMaterials::find(lmp, "Compute sph/heatflux/atom");

  SPHCompat::request_occasional_full_list(neighbor, this, instance_me);
}

void ComputeSPHHeatfluxAtom::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

/* ---------------------------------------------------------------------- */

void ComputeSPHHeatfluxAtom::compute_peratom()
{
  const SPHParticles particles(atom);
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(flux);
    memory->create(flux, nmax, size_peratom_cols, "sph/heatflux/atom:flux");
    array_atom = flux;
  }
  // the ghosts' esph and rho are those of the step's start: the integrator
  // updates them on the owners only (with the atoms split over ranks, a
  // neighbour across the boundary would be half a step behind)
  comm->forward_comm();
  SPHCompat::build_occasional(neighbor, list);

  const double *const *const x = atom->x;
  const double *const rho = atom->rho;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int dim = domain->dimension;
  const double cutsq = cutoff * cutoff;
  const sphk_kernel kernel = sphk_make(kernel_kind, dim, cutoff);
  double *normal[3] = {nullptr, nullptr, nullptr};
  if (has_normals)
    for (int k = 0; k < 3; k++) normal[k] = atom->dvector[normal_xyz[k]];

  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < size_peratom_cols; k++) flux[i][k] = 0.0;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const double temp_i = particles.temperature(i);
    const double k_i = materials->conductivity_at(type[i], temp_i, "Compute sph/heatflux/atom");
    const int *const jlist = list->firstneigh[i];
    const int jnum = list->numneigh[i];
    double g[3] = {0.0, 0.0, 0.0}, L[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double wall = 0.0;

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq || rsq == 0.0) continue;
      const double r = sqrt(rsq);
      const double dwdr = sphk_dwdr(&kernel, r);
      const double mass_j = particles.mass(j);
      const double volume_j = mass_j / rho[j];
      const double temp_j = particles.temperature(j);
      double grad_w[3];    // grad_i W_ij = (r_i - r_j) / r dW/dr
      for (int a = 0; a < 3; a++) grad_w[a] = del[a] * dwdr / r;
      sphg_add(g, L, del, grad_w, volume_j, temp_j - temp_i);
      if (has_normals) {
        const double k_j = materials->conductivity_at(type[j], temp_j, "Compute sph/heatflux/atom");
        const double r_dot_n = del[0] * normal[0][i] + del[1] * normal[1][i] + del[2] * normal[2][i];
        wall += sphc_cleary_wall_flux(mass_j, k_j, temp_i - temp_j, r_dot_n, r, dwdr, rsq, eta2);
      }
    }

    double grad_t[3] = {g[0], g[1], g[2]};
    if (corrected) sphg_solve_transposed(L, g, grad_t, dim);
    for (int a = 0; a < 3; a++) flux[i][a] = -k_i * grad_t[a];
    // eq 9 as printed is negative for heat flowing into the wall: report the inflow
    if (has_normals) flux[i][3] = -wall / rho[i];
  }
}

/* ----------------------------------------------------------------------
   heat rate through the group's wall particles: sum of flux * spacing^(d-1)
------------------------------------------------------------------------- */

double ComputeSPHHeatfluxAtom::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (invoked_peratom != update->ntimestep) compute_peratom();
  const double area = pow(spacing, domain->dimension - 1);
  double local = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->mask[i] & groupbit) local += flux[i][3] * area;
  MPI_Allreduce(&local, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  return scalar;
}

/* ---------------------------------------------------------------------- */

double ComputeSPHHeatfluxAtom::memory_usage()
{
  return (double) nmax * size_peratom_cols * sizeof(double);
}
