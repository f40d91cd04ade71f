/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/thermal: thermal energy E = sum m e, heat capacity
   C = sum m cv, mean temperature sum m cv T / C and heating rate
   sum m de/dt of a group (without a change of phase e = cv T: the mean
   temperature is E / C, the temperature the group would reach if its heat
   were spread evenly).
------------------------------------------------------------------------- */

#include "compute_sph_thermal.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "sph_checks.h"
#include "sph_particle.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeSPHThermal::ComputeSPHThermal(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), temperature(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Illegal compute sph/thermal command: it takes no arguments after the style");
  if (!atom->esph_flag || !atom->cv_flag)
    error->all(FLERR, "Compute sph/thermal requires atom style sph (esph, desph, cv)");
  scalar_flag = 1;    // the mean temperature
  extscalar = 0;
  vector_flag = 1;
  size_vector = 4;
  extvector = 0;    // intensive: thermo does not divide by the atom count
  vector = new double[size_vector];
  for (int k = 0; k < size_vector; k++) vector[k] = 0.0;
  peratom_flag = 1;    // the temperature of each atom (0 outside the group)
  size_peratom_cols = 0;
}

ComputeSPHThermal::~ComputeSPHThermal()
{
  delete[] vector;
  memory->destroy(temperature);
}

/* ---------------------------------------------------------------------- */

void ComputeSPHThermal::init()
{
  SPHCheck::warn_empty(lmp, FLERR, fmt::format("Compute sph/thermal {}", id).c_str(), igroup);
}

/* ---------------------------------------------------------------------- */

double ComputeSPHThermal::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  compute_vector();
  scalar = vector[2];
  return scalar;
}

/* ----------------------------------------------------------------------
   1 thermal energy, 2 heat capacity, 3 mean temperature, 4 heating rate
------------------------------------------------------------------------- */

void ComputeSPHThermal::compute_vector()
{
  const SPHParticles particles(atom);
  invoked_vector = update->ntimestep;
  const int *const mask = atom->mask;
  // energy, heat capacity, heating rate, sum of m cv T
  double local[4] = {0.0, 0.0, 0.0, 0.0};
  const double half_step = 0.5 * update->dt;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    // fix smd/integrate_tlsph has applied the whole of this step's heating,
    // fix sph half of it (the rest at the next step's start): the books count
    // a MACHDYN particle at fix sph's stage, so that what the two kinds
    // exchange sums to zero at every step
    const double energy = particles.thermal_energy(i) -
        (particles.machdyn(i) ? half_step * particles.heating_rate(i, atom->desph) : 0.0);
    const double capacity = particles.mass(i) * particles.sensible_cv(i);
    local[0] += energy;
    local[1] += capacity;
    local[2] += particles.heating_rate(i, atom->desph);
    // the energy of a melting particle includes its latent heat: its share
    // of the mean temperature is its own temperature's
    local[3] += particles.changes_phase(i) ? capacity * particles.temperature(i) : energy;
  }
  double sums[4];
  MPI_Allreduce(local, sums, 4, MPI_DOUBLE, MPI_SUM, world);
  vector[0] = sums[0];
  vector[1] = sums[1];
  vector[2] = (sums[1] > 0.0) ? sums[3] / sums[1] : 0.0;
  vector[3] = sums[2];
}

/* ---------------------------------------------------------------------- */

void ComputeSPHThermal::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    memory->destroy(temperature);
    memory->create(temperature, nmax, "sph/thermal:temperature");
    vector_atom = temperature;
  }
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    temperature[i] = (mask[i] & groupbit) ? particles.temperature(i) : 0.0;
}

double ComputeSPHThermal::memory_usage()
{
  return (double) nmax * sizeof(double);
}
