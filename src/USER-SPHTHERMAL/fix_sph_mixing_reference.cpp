/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix SPH/MIXING/REFERENCE: the per-atom neighbour lists that compute
   sph/mixing takes at its reference time, for the finite-time Lyapunov
   exponent. Created and deleted by the compute.
------------------------------------------------------------------------- */

#include "fix_sph_mixing_reference.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "sph_checks.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

// the layout of the restart state: raise it when a value is added (also
// one of the atoms' records; 2: each atom's own tag at the reference added)
static constexpr int RESTART_VERSION = 2;

static constexpr int SHIFT_BITS = 10;
static constexpr int SHIFT_MASK = (1 << SHIFT_BITS) - 1;
static constexpr int SHIFT_ZERO = 1 << (SHIFT_BITS - 1);

/* ---------------------------------------------------------------------- */

FixSPHMixingReference::FixSPHMixingReference(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), captured(0), width(0), time0(0.0), tag0(nullptr), count(nullptr),
    tags(nullptr), shifts(nullptr), distance0(nullptr), restart_pending(0), elapsed_restart(0.0)
{
  if (narg != 3)
    error->all(FLERR, "Illegal fix SPH/MIXING/REFERENCE command: it is created by compute sph/mixing");
  entropy0[0] = entropy0[1] = 0.0;
  restart_global = 1;
  restart_peratom = 1;
  maxexchange_dynamic = 1;    // the lists' width is known only once captured
  maxexchange = values_per_atom();
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nmax; i++) tag0[i] = count[i] = 0;
}

FixSPHMixingReference::~FixSPHMixingReference()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(tag0);
  memory->destroy(count);
  memory->destroy(tags);
  memory->destroy(shifts);
  memory->destroy(distance0);
}

/* ---------------------------------------------------------------------- */

void FixSPHMixingReference::resize(int new_width)
{
  width = new_width;
  maxexchange = values_per_atom();
  memory->destroy(tags);
  memory->destroy(shifts);
  memory->destroy(distance0);
  grow_arrays(atom->nmax);
  for (int i = 0; i < atom->nmax; i++) count[i] = 0;
}

int FixSPHMixingReference::pack_shift(const int shift[3])
{
  int packed = 0;
  for (int k = 0; k < 3; k++) packed |= ((shift[k] + SHIFT_ZERO) & SHIFT_MASK) << (k * SHIFT_BITS);
  return packed;
}

void FixSPHMixingReference::unpack_shift(int packed, int shift[3])
{
  for (int k = 0; k < 3; k++) shift[k] = ((packed >> (k * SHIFT_BITS)) & SHIFT_MASK) - SHIFT_ZERO;
}

/* ---------------------------------------------------------------------- */

void FixSPHMixingReference::grow_arrays(int nmax)
{
  memory->grow(tag0, nmax, "sph/mixing:tag0");
  memory->grow(count, nmax, "sph/mixing:count");
  memory->grow(tags, nmax, slots(), "sph/mixing:tags");
  memory->grow(shifts, nmax, slots(), "sph/mixing:shifts");
  memory->grow(distance0, nmax, slots(), "sph/mixing:distance0");
}

void FixSPHMixingReference::copy_arrays(int i, int j, int /*delflag*/)
{
  tag0[j] = tag0[i];
  count[j] = count[i];
  for (int k = 0; k < count[i]; k++) {
    tags[j][k] = tags[i][k];
    shifts[j][k] = shifts[i][k];
    distance0[j][k] = distance0[i][k];
  }
}

// an atom created after the reference has no initial neighbourhood
void FixSPHMixingReference::set_arrays(int i)
{
  tag0[i] = 0;
  count[i] = 0;
}

int FixSPHMixingReference::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = ubuf(tag0[i]).d;
  buf[m++] = ubuf(count[i]).d;
  for (int k = 0; k < count[i]; k++) {
    buf[m++] = ubuf(tags[i][k]).d;
    buf[m++] = ubuf(shifts[i][k]).d;
    buf[m++] = distance0[i][k];
  }
  return m;
}

int FixSPHMixingReference::unpack_exchange(int i, double *buf)
{
  int m = 0;
  tag0[i] = (tagint) ubuf(buf[m++]).i;
  count[i] = (int) ubuf(buf[m++]).i;
  for (int k = 0; k < count[i]; k++) {
    tags[i][k] = (tagint) ubuf(buf[m++]).i;
    shifts[i][k] = (int) ubuf(buf[m++]).i;
    distance0[i][k] = buf[m++];
  }
  return m;
}

/* ----------------------------------------------------------------------
   per-atom restart: the number of values (itself included), then the atom's
   exchange record
------------------------------------------------------------------------- */

int FixSPHMixingReference::pack_restart(int i, double *buf)
{
  const int n = 1 + pack_exchange(i, buf + 1);
  buf[0] = n;
  return n;
}

void FixSPHMixingReference::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  unpack_exchange(nlocal, &extra[nlocal][m + 1]);
}

int FixSPHMixingReference::size_restart(int i)
{
  return 3 + 3 * count[i];
}

int FixSPHMixingReference::maxsize_restart()
{
  return 1 + values_per_atom();
}

/* ---------------------------------------------------------------------- */

double FixSPHMixingReference::now() const
{
  return update->atime + (double) (update->ntimestep - update->atimestep) * update->dt;
}

void FixSPHMixingReference::settle_restart()
{
  if (!restart_pending) return;
  time0 = now() - elapsed_restart;
  restart_pending = 0;
}

/* ----------------------------------------------------------------------
   global restart: captured, width, the time since the reference and the
   entropies. restart() runs before the atoms' unpack_restart, so the arrays
   get their width here
------------------------------------------------------------------------- */

void FixSPHMixingReference::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double elapsed = restart_pending ? elapsed_restart : now() - time0;
  const double list[5] = {(double) captured, (double) width, elapsed, entropy0[0], entropy0[1]};
  SPHCheck::write_restart_state(fp, RESTART_VERSION, list, 5);
}

void FixSPHMixingReference::restart(char *buf)
{
  const double *list = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION);
  captured = (int) list[0];
  resize((int) list[1]);
  elapsed_restart = list[2];
  restart_pending = 1;
  entropy0[0] = list[3];
  entropy0[1] = list[4];
}

double FixSPHMixingReference::memory_usage()
{
  return (double) atom->nmax *
      (sizeof(tagint) + sizeof(int) + slots() * (sizeof(tagint) + sizeof(int) + sizeof(double)));
}
