/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/wall/adiabatic: the higher-order adiabatic wall of Reece et al.
   2024 (eqs 18-19). Each wall particle is mirrored across the wall surface
   (through the vertex at a corner) to a ghost point in the medium; the
   medium's temperature there, interpolated with the first-order correction
   of Liu & Liu (Shepard's when the neighbourhood is too thin), becomes the
   wall particle's, so every particle of the medium sees a full kernel of
   the evenly reflected temperature field.
   The wall particles exchange heat with the medium like any other; what
   they take in (zero for an exactly reflected field, small otherwise) is
   given back to the medium around their ghost points, so a closed box with
   adiabatic walls keeps its energy to round-off ('conserve yes'). Next to
   a wall that holds a temperature (a corner) the heat a wall particle takes
   in is the exchange with the medium that the held wall's particles
   complete, so it is not given back.
------------------------------------------------------------------------- */

#include "fix_sph_wall_adiabatic.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_surface_flux.h"
#include "fix_sph_wall_dirichlet.h"
#include "fix_sph_wall_isothermal.h"
#include "force.h"
#include "group.h"
#include "neighbor.h"
#include "pair_sph_cleary_heat.h"
#include "sph_checks.h"
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_mirror.h"
#include "sph_particle.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static const char cmd[] = "fix sph/wall/adiabatic";

/* ---------------------------------------------------------------------- */

FixSPHWallAdiabatic::FixSPHWallAdiabatic(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), mirror(nullptr), conserve(1), deep_warned(0), shepard_local(0),
    shepard_total(0), summed(0)
{
  if (!atom->esph_flag || !atom->cv_flag || !atom->rho_flag)
    error->all(FLERR, "Fix sph/wall/adiabatic requires atom style sph (rho, esph, desph, cv)");
  mirror = new SPHMirror(lmp, cmd, true);
  int iarg = 3;
  int surface_given = 0;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "surface") == 0) {
      iarg += mirror->parse(narg, arg, iarg);
      surface_given = 1;
    } else if (strcmp(arg[iarg], "conserve") == 0) {
      if (iarg + 1 >= narg)
        error->all(FLERR, "Illegal {} command: missing value after 'conserve'", cmd);
      conserve = SPHCompat::yes_no(error, FLERR, cmd, "conserve", arg[iarg + 1]) ? 1 : 0;
      iarg += 2;
    } else
      error->all(FLERR, "Illegal {} command: unknown keyword '{}'", cmd, arg[iarg]);
  }
  if (!surface_given)
    error->all(FLERR,
               "Illegal {} command: 'surface <region-ID>' is required (the region of the medium, "
               "whose boundary is the wall surface)",
               cmd);
  comm_forward = 1;
  comm_reverse = 1;
  vector_flag = 1;
  size_vector = 3;
  taken_local[0] = taken_local[1] = taken_total[0] = taken_total[1] = 0.0;
  global_freq = 1;
  extvector = 1;
}

FixSPHWallAdiabatic::~FixSPHWallAdiabatic()
{
  delete mirror;
}

int FixSPHWallAdiabatic::setmask()
{
  return PRE_NEIGHBOR | PRE_FORCE | POST_FORCE;
}

// atoms were exchanged and sorted: the mirror's neighbour candidates are stale
void FixSPHWallAdiabatic::setup_pre_neighbor()
{
  pre_neighbor();
}

void FixSPHWallAdiabatic::pre_neighbor()
{
  if (mirror) mirror->neighbours_changed();
}

/* ---------------------------------------------------------------------- */

void FixSPHWallAdiabatic::init()
{
  // the kernel and its support are those of the conduction pair style
  const SPHKernelSettings given =
      SPHHub(lmp).require_heat("Fix sph/wall/adiabatic")->kernel_settings();
  const int kernel_kind = given.kind;
  const double cutoff = given.cutoff;
  SPHCheck::group_of_kind(lmp, FLERR, this,
                          SPHHub(lmp)
                              .fixes_of_any<FixSPHWallIsothermal, FixSPHWallDirichlet,
                                            FixSPHWallAdiabatic, FixSPHSurfaceFlux>(),
                          false, false);
  mirror->init(groupbit, kernel_kind, cutoff, id);

  // a wall atom beyond the kernel's reach of the surface (deep in a thick
  // wall, or at a corner) has no ghost point and keeps its temperature; its
  // exchange with the wall atoms within reach is counted in what they take
  // in, which 'conserve yes' charges to the medium: a leak, unless pairs of
  // wall atoms are left out of the neighbour lists
  if (conserve && !deep_warned && mirror->beyond_reach() > 0 && !wall_pairs_excluded()) {
    deep_warned = 1;
    if (comm->me == 0)
      error->warning(FLERR,
                     "Fix {} sph/wall/adiabatic: {} of its wall atoms (atom {} first) lie beyond "
                     "the kernel's reach of surface {}: they keep their temperature, and the heat "
                     "they exchange with the wall atoms within reach would be given to the "
                     "medium ('conserve yes'): add 'neigh_modify exclude group {} {}' (or "
                     "delete those atoms)",
                     id, mirror->beyond_reach(), mirror->first_beyond_reach(), mirror->region_id(),
                     group->names[igroup], group->names[igroup]);
  }
}

/* ----------------------------------------------------------------------
   whether neigh_modify exclude leaves out every pair of this fix's wall
   atoms: a group pair whose groups both hold the whole wall group, or type
   pairs covering every pair of the wall group's types (collective)
------------------------------------------------------------------------- */

bool FixSPHWallAdiabatic::wall_pairs_excluded() const
{
  const int *const mask = atom->mask;
  for (int k = 0; k < neighbor->nex_group; k++) {
    const int both =
        group->bitmask[neighbor->ex1_group[k]] & group->bitmask[neighbor->ex2_group[k]];
    int outside_local = 0, outside = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((mask[i] & groupbit) && !((mask[i] & both) == both)) outside_local = 1;
    MPI_Allreduce(&outside_local, &outside, 1, MPI_INT, MPI_MAX, world);
    if (!outside) return true;
  }
  const std::vector<int> present = SPHCheck::group_types(lmp, groupbit);
  auto excluded = [&](int t1, int t2) {
    for (int k = 0; k < neighbor->nex_type; k++)
      if ((neighbor->ex1_type[k] == t1 && neighbor->ex2_type[k] == t2) ||
          (neighbor->ex1_type[k] == t2 && neighbor->ex2_type[k] == t1))
        return true;
    return false;
  };
  int any = 0;
  for (int t1 = 1; t1 <= atom->ntypes; t1++) {
    if (!present[t1]) continue;
    any = 1;
    for (int t2 = t1; t2 <= atom->ntypes; t2++)
      if (present[t2] && !excluded(t1, t2)) return false;
  }
  return any;
}

/* ----------------------------------------------------------------------
   the wall particles' temperatures, owned then ghost; a particle beyond
   the kernel's reach of the surface keeps its own
------------------------------------------------------------------------- */

void FixSPHWallAdiabatic::setup_pre_force(int vflag)
{
  pre_force(vflag);
}

void FixSPHWallAdiabatic::pre_force(int /*vflag*/)
{
  // the atoms' own state before the wall mirrors it
  SPHCheck::particles(lmp, FLERR, "Fix sph/wall/adiabatic", SPHCheck::RHO | SPHCheck::ESPH);
  mirror->interpolate(t_ghost, ghost_how);
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const esph = atom->esph;
  shepard_local = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || ghost_how[i] == SPHI_NONE) continue;
    esph[i] = particles.energy_at(i, t_ghost[i]);
    if (ghost_how[i] == SPHI_SHEPARD) shepard_local++;
  }
  summed = 0;
  SPHCompat::forward_comm(comm, this);
}

/* ----------------------------------------------------------------------
   the heat the wall particles took in goes back to the medium
------------------------------------------------------------------------- */

void FixSPHWallAdiabatic::setup(int vflag)
{
  post_force(vflag);
}

void FixSPHWallAdiabatic::post_force(int /*vflag*/)
{
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const desph = atom->desph;
  const int nlocal = atom->nlocal;
  rate.assign(nlocal, 0.0);
  taken_local[0] = taken_local[1] = 0.0;
  mirror->find_junctions();
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || ghost_how[i] == SPHI_NONE) continue;
    rate[i] = particles.mass(i) * desph[i];
    taken_local[mirror->at_junction(i)] += rate[i];
    if (conserve) desph[i] = 0.0;
  }
  if (conserve) mirror->return_heat(rate, this);
  summed = 0;
}

/* ----------------------------------------------------------------------
   vector: heat rate the wall particles took in now, away from corners
   (given back with 'conserve yes') and at corners with a wall that holds a
   temperature (never given back: there the heat belongs to that wall);
   number of wall particles whose ghost point needed Shepard's value
------------------------------------------------------------------------- */

double FixSPHWallAdiabatic::compute_vector(int n)
{
  if (!summed) {
    MPI_Allreduce(taken_local, taken_total, 2, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(&shepard_local, &shepard_total, 1, MPI_INT, MPI_SUM, world);
    summed = 1;
  }
  if (n < 2) return taken_total[n];
  return (double) shepard_total;
}

/* ---------------------------------------------------------------------- */

int FixSPHWallAdiabatic::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                           int * /*pbc*/)
{
  return SPHCommStage().flat(atom->esph, 1).pack(n, send, buf);
}

void FixSPHWallAdiabatic::unpack_forward_comm(int n, int first, double *buf)
{
  SPHCommStage().flat(atom->esph, 1).unpack_forward(n, first, buf);
}

int FixSPHWallAdiabatic::pack_reverse_comm(int n, int first, double *buf)
{
  return mirror->pack_reverse_comm(n, first, buf);
}

void FixSPHWallAdiabatic::unpack_reverse_comm(int n, int *list, double *buf)
{
  mirror->unpack_reverse_comm(n, list, buf);
}
