/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/wall/dirichlet: wall (dummy) particles whose temperature is
   extrapolated so that the medium sees T_wall on the wall surface, and
   the heat they exchange with it (Cleary 1998, eq 10). Either
     T_b = 2 T_wall - sum_f T_f W_bf / sum_f W_bf
   over the neighbours f of dummy particle b that are not dummies of any
   sph/wall/dirichlet fix (Ng et al. 2020, eq 9 applied to T, after Adami
   et al. 2012; so walls held at different T meet at corners), or, with a
   'surface', through the ghost point g of b mirrored across it (the mDBC
   construction of Reece et al. 2024, eqs 18-19, sph_mirror.h):
     T_b = 2 T_wall - T(g)
   which puts T_wall on the surface for every linear temperature field.
------------------------------------------------------------------------- */

#include "fix_sph_wall_dirichlet.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_sph_surface_flux.h"
#include "fix_sph_wall_adiabatic.h"
#include "fix_sph_wall_isothermal.h"
#include "force.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "sph_checks.h"
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_kernels.h"
#include "sph_mirror.h"
#include "sph_particle.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

/* ---------------------------------------------------------------------- */

FixSPHWallDirichlet::FixSPHWallDirichlet(LAMMPS *lmp, int narg, char **arg) :
    FixSPHWallTally(lmp, narg, arg), dummy_groupbit(0), kernel_kind(0), cutoff(0.0),
    list(nullptr), mirror(nullptr)
{
  static const char cmd[] = "fix sph/wall/dirichlet";
  if (narg < 4) error->all(FLERR, "Illegal {} command: expected <T>", cmd);
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Fix sph/wall/dirichlet requires atom style sph (esph, desph, cv)");
  t_wall = utils::numeric(FLERR, arg[3], false, lmp);
  int iarg = 4;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "surface") == 0) {
      delete mirror;
      mirror = new SPHMirror(lmp, cmd, false);
      iarg += mirror->parse(narg, arg, iarg);
    } else if (strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg) error->all(FLERR, "Illegal {} command: missing value after 'spacing'", cmd);
      spacing = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (spacing <= 0.0)
        error->all(FLERR, "Illegal {} command: spacing {} must be > 0", cmd, arg[iarg + 1]);
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }
  comm_forward = 1;
  tally_arrays();
}

FixSPHWallDirichlet::~FixSPHWallDirichlet()
{
  delete mirror;
}

int FixSPHWallDirichlet::setmask()
{
  return PRE_NEIGHBOR | PRE_FORCE | POST_FORCE;
}

// atoms were exchanged and sorted: the mirror's neighbour candidates are stale
void FixSPHWallDirichlet::setup_pre_neighbor()
{
  pre_neighbor();
}

void FixSPHWallDirichlet::pre_neighbor()
{
  if (mirror) mirror->neighbours_changed();
}

/* ---------------------------------------------------------------------- */

void FixSPHWallDirichlet::init()
{
  // the kernel and its support are those of the conduction pair style
  SPHHub hub(lmp);
  const SPHKernelSettings given = hub.require_heat("Fix sph/wall/dirichlet")->kernel_settings();
  kernel_kind = given.kind;
  cutoff = given.cutoff;
  SPHCheck::group_of_kind(lmp, FLERR, this,
                          SPHHub(lmp)
                              .fixes_of_any<FixSPHWallIsothermal, FixSPHWallDirichlet,
                                            FixSPHWallAdiabatic, FixSPHSurfaceFlux>(),
                          false, false);
  // (the cv of its group: the pair, required above, has checked every atom's
  // at its init, which comes before the fixes')
  if (mirror) mirror->init(groupbit, kernel_kind, cutoff, id);

  dummy_groupbit = hub.groupbits<FixSPHWallDirichlet>();

  if (!mirror) SPHCompat::request_full_list(neighbor, this, instance_me);
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
  // the atoms' own state before the wall mirrors it
  SPHCheck::particles(lmp, FLERR, "Fix sph/wall/dirichlet", SPHCheck::RHO | SPHCheck::ESPH);
  if (mirror)
    dummies_mirrored();
  else
    dummies_shepard();
  SPHCompat::forward_comm(comm, this);
}

void FixSPHWallDirichlet::dummies_mirrored()
{
  mirror->interpolate(t_ghost, ghost_how, &ghost_depth);
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const esph = atom->esph;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      esph[i] =
          particles.energy_at(i, (ghost_how[i] != SPHI_NONE) ? 2.0 * t_wall - t_ghost[i] : t_wall);
}

void FixSPHWallDirichlet::dummies_shepard()
{
  const SPHParticles particles(atom);
  const double *const *const x = atom->x;
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
      weighted_t += w * particles.temperature(j);
    }
    const double t_dummy = (weight > 0.0) ? 2.0 * t_wall - weighted_t / weight : t_wall;
    esph[i] = particles.energy_at(i, t_dummy);
  }
}

int FixSPHWallDirichlet::surface_gradient(int i, double &gradient, double &depth) const
{
  if (!mirror || i >= (int) ghost_how.size() || ghost_how[i] == SPHI_NONE) return 0;
  depth = ghost_depth[i];
  if (!(depth > 0.0)) return 0;
  gradient = (t_ghost[i] - t_wall) / depth;
  return 1;
}

/* ----------------------------------------------------------------------
   the heat the dummies exchange with the medium; their esph is set anew
   before each force evaluation, so their desph is left to the integrator
------------------------------------------------------------------------- */

void FixSPHWallDirichlet::setup(int /*vflag*/)
{
  tally(1, 0);
}

void FixSPHWallDirichlet::post_force(int /*vflag*/)
{
  tally(0, 0);
}

/* ---------------------------------------------------------------------- */

int FixSPHWallDirichlet::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                          int * /*pbc*/)
{
  return SPHCommStage().flat(atom->esph, 1).pack(n, send, buf);
}

void FixSPHWallDirichlet::unpack_forward_comm(int n, int first, double *buf)
{
  SPHCommStage().flat(atom->esph, 1).unpack_forward(n, first, buf);
}

