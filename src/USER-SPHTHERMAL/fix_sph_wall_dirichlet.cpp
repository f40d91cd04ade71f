/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/wall/dirichlet: wall (dummy) particles whose temperature is
   extrapolated so that the medium sees T_wall on the wall surface
   (Ng et al. 2020, eq 9 applied to T, after Adami et al. 2012):
     T_b = 2 T_wall - sum_f T_f W_bf / sum_f W_bf
   over the neighbours f of dummy particle b that are not dummies of any
   sph/wall/dirichlet fix (so walls held at different T meet at corners).
------------------------------------------------------------------------- */

#include "fix_sph_wall_dirichlet.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "sph_checks.h"
#include "sph_compat.h"
#include "sph_kernels.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixSPHWallDirichlet::FixSPHWallDirichlet(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), dummy_groupbit(0), kernel_kind(0), cutoff(0.0), list(nullptr)
{
  if (narg < 4) error->all(FLERR, "Illegal fix sph/wall/dirichlet command: expected <T>");
  if (narg > 4)
    error->all(FLERR, "Illegal fix sph/wall/dirichlet command: unknown keyword '{}'", arg[4]);
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/wall/dirichlet requires atom style sph (esph, desph, cv)");
  t_wall = utils::numeric(FLERR, arg[3], false, lmp);
  comm_forward = 1;
}

int FixSPHWallDirichlet::setmask()
{
  return PRE_FORCE;
}

/* ---------------------------------------------------------------------- */

void FixSPHWallDirichlet::init()
{
  // the kernel and its support are those of the conduction pair style
  Pair *pair = force->pair_match("^sph/cleary/heat", 0);
  if (!pair) error->all(FLERR, "Fix sph/wall/dirichlet requires pair style sph/cleary/heat");
  int dim;
  kernel_kind = *(int *) pair->extract("kernel_kind", dim);
  cutoff = *(double *) pair->extract("cutoff", dim);
  SPHCheck::group_of_kind(
      lmp, this, {"sph/wall/isothermal", "sph/wall/dirichlet", "sph/surface/flux"}, false, false);
  SPHCheck::atom_state(lmp, "Fix sph/wall/dirichlet", groupbit, SPHCheck::CV);

  dummy_groupbit = 0;
  for (Fix *wall : SPHCompat::fixes_of_style(modify, "sph/wall/dirichlet"))
    dummy_groupbit |= wall->groupbit;

  SPHCompat::request_full_list(neighbor, this, instance_me);
}

void FixSPHWallDirichlet::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

void FixSPHWallDirichlet::setup_pre_force(int vflag)
{
  pre_force(vflag);
}

/* ----------------------------------------------------------------------
   set the dummy temperatures of the owned wall particles, then of their
   ghost copies; a dummy with no medium neighbour keeps T_wall
------------------------------------------------------------------------- */

void FixSPHWallDirichlet::pre_force(int /*vflag*/)
{
  const double *const *const x = atom->x;
  const double *const cv = atom->cv;
  const int *const mask = atom->mask;
  double *const esph = atom->esph;
  const sphk_kernel kernel = sphk_make(kernel_kind, domain->dimension, cutoff);
  const double cutsq = cutoff * cutoff;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    double weight = 0.0, weighted_t = 0.0;
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (mask[j] & dummy_groupbit) continue;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq >= cutsq) continue;
      const double w = sphk_w(&kernel, sqrt(rsq));
      weight += w;
      weighted_t += w * esph[j] / cv[j];
    }
    const double t_dummy = (weight > 0.0) ? 2.0 * t_wall - weighted_t / weight : t_wall;
    esph[i] = cv[i] * t_dummy;
  }
  SPHCompat::forward_comm(comm, this);
}

/* ---------------------------------------------------------------------- */

int FixSPHWallDirichlet::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                          int * /*pbc*/)
{
  for (int k = 0; k < n; k++) buf[k] = atom->esph[send[k]];
  return n;
}

void FixSPHWallDirichlet::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) atom->esph[first + k] = buf[k];
}

/* ----------------------------------------------------------------------
   t_wall: pair sph/cleary/heat evaluates the dummies' conductivity there
------------------------------------------------------------------------- */

void *FixSPHWallDirichlet::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "t_wall") == 0) return (void *) &t_wall;
  return nullptr;
}
