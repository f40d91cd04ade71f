/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The heat taken up by a wall of prescribed temperature (Cleary 1998,
   section 2.6 and eq 10: the energy-method estimate of the wall heat flux).
------------------------------------------------------------------------- */

#include "fix_sph_wall_tally.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "sph_checks.h"
#include "sph_particle.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// the layout of the restart state: raise it when a value is added
static constexpr int RESTART_VERSION = 1;

/* ---------------------------------------------------------------------- */

FixSPHWallTally::FixSPHWallTally(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), spacing(0.0), rate_previous(0.0), rate(0.0), energy(0.0), wall(nullptr),
    callbacks_added(0)
{
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 2;
  extscalar = 1;
  extvector = 1;
  global_freq = 1;
  peratom_flag = 1;
  peratom_freq = 1;
  // atoms created in a run (fix sph/open) start with nothing tallied
  create_attribute = 1;
  restart_global = 1;
  restart_peratom = 1;
  energy_global_flag = 0;
}

void FixSPHWallTally::tally_arrays()
{
  size_peratom_cols = (spacing > 0.0) ? 3 : 2;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  callbacks_added = 1;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < size_peratom_cols; k++) wall[i][k] = 0.0;
}

FixSPHWallTally::~FixSPHWallTally()
{
  // a derived constructor that stops on bad input has added none
  if (callbacks_added) {
    atom->delete_callback(id, Atom::GROW);
    atom->delete_callback(id, Atom::RESTART);
  }
  memory->destroy(wall);
}

/* ----------------------------------------------------------------------
   The heat rate into wall particle i is m_i desph_i; with zero_rates,
   desph_i is then zeroed so that fix sph or sph/stationary keep the wall's
   esph.
   Those integrators apply each rate for half a step twice (at the end of
   the step that computed it and the start of the next), so the wall's
   energy grows by dt/2 (rate before + rate now) per step; then the wall's
   energy plus sum(m esph) of the other particles is constant to round-off.
   At a run's setup the rates are only recorded.
------------------------------------------------------------------------- */

void FixSPHWallTally::tally(int first, int zero_rates)
{
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  double *const desph = atom->desph;
  const int nlocal = atom->nlocal;
  const double area = (spacing > 0.0) ? pow(spacing, domain->dimension - 1) : 1.0;
  // the half-step weight of fix sph and fix sph/stationary (with ftm2v as
  // they have it)
  const double dt_half = 0.5 * update->dt * force->ftm2v;

  // the energy taken up as the wall's integrator would have taken it: fix
  // sph's two half steps, or for a MACHDYN solid the one whole step of fix
  // smd/integrate_tlsph (sph_particle.h)
  double local[2] = {0.0, 0.0};    // rate into particles of fix sph, into MACHDYN solids
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double rate_i = particles.heating_rate(i, desph);
    const bool solid = particles.machdyn(i);
    if (!first) wall[i][1] += solid ? update->dt * rate_i : dt_half * (wall[i][0] + rate_i);
    wall[i][0] = rate_i;
    if (spacing > 0.0) wall[i][2] = rate_i / area;
    local[solid ? 1 : 0] += rate_i;
    if (zero_rates) desph[i] = 0.0;
  }

  double sums[2];
  MPI_Allreduce(local, sums, 2, MPI_DOUBLE, MPI_SUM, world);
  if (!first) energy += dt_half * (rate_previous + sums[0]) + update->dt * sums[1];
  rate = sums[0] + sums[1];
  rate_previous = sums[0];
}

/* ----------------------------------------------------------------------
   scalar: energy taken up by the wall; vector: heat rate into the wall
   now, energy taken up
------------------------------------------------------------------------- */

double FixSPHWallTally::compute_scalar()
{
  return energy;
}

double FixSPHWallTally::compute_vector(int n)
{
  return (n == 0) ? rate : energy;
}

/* ---------------------------------------------------------------------- */

void FixSPHWallTally::write_restart(FILE *fp)
{
  if (comm->me == 0) SPHCheck::write_restart_state(fp, RESTART_VERSION, &energy, 1);
}

void FixSPHWallTally::restart(char *buf)
{
  energy = SPHCheck::read_restart_state(lmp, FLERR, this, buf, RESTART_VERSION)[0];
}

/* ---------------------------------------------------------------------- */

void FixSPHWallTally::grow_arrays(int nmax)
{
  memory->grow(wall, nmax, size_peratom_cols, "sph/wall:wall");
  array_atom = wall;
}

void FixSPHWallTally::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < size_peratom_cols; k++) wall[j][k] = wall[i][k];
}

void FixSPHWallTally::set_arrays(int i)
{
  for (int k = 0; k < size_peratom_cols; k++) wall[i][k] = 0.0;
}

int FixSPHWallTally::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < size_peratom_cols; k++) buf[k] = wall[i][k];
  return size_peratom_cols;
}

int FixSPHWallTally::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < size_peratom_cols; k++) wall[nlocal][k] = buf[k];
  return size_peratom_cols;
}

/* ----------------------------------------------------------------------
   per-atom restart: the energy each particle took up (the rates are
   recomputed at setup)
------------------------------------------------------------------------- */

int FixSPHWallTally::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = wall[i][1];
  return 2;
}

void FixSPHWallTally::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < size_peratom_cols; k++) wall[nlocal][k] = 0.0;
  wall[nlocal][1] = extra[nlocal][m];
}

int FixSPHWallTally::size_restart(int /*nlocal*/)
{
  return 2;
}

int FixSPHWallTally::maxsize_restart()
{
  return 2;
}

/* ---------------------------------------------------------------------- */

double FixSPHWallTally::memory_usage()
{
  return (double) atom->nmax * size_peratom_cols * sizeof(double);
}
