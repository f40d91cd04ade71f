/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The stability limits of the timestep (sph_timestep.h).
------------------------------------------------------------------------- */

#include "sph_particle.h"
#include "sph_timestep.h"

#include "atom.h"
#include "fix_sph_materials.h"
#include "force.h"
#include "pair_sph_kernel.h"
#include "sph_hub.h"
#include "sph_eos.h"
#include "sph_kernels.h"

#include <cfloat>
#include <string>

using namespace LAMMPS_NS;

const char *SPHTimestep::name(int limit)
{
  static const char *const names[NLIMITS] = {"acoustic", "force", "viscous", "thermal"};
  return (limit >= 0 && limit < NLIMITS) ? names[limit] : "no";
}

/* ---------------------------------------------------------------------- */

void SPHTimestep::local_limits(LAMMPS *lmp, const Scan &scan, double none, double local[NLIMITS],
                               int bad[NLIMITS])
{
  Atom *atom = lmp->atom;
  const SPHParticles particles(atom);
  const double *const *const v = atom->v;
  const double *const *const f = atom->f;
  const double *const rho = atom->rho;
  const int *const type = atom->type;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double s = lmp->force->ftm2v;
  const double h = scan.h;
  const double *const coeff = scan.coeff;
  const double *const lambda = scan.relax_rate;

  for (int k = 0; k < NLIMITS; k++) local[k] = none, bad[k] = 0;
  // a limit of 0 or not a number (zero rho, overflow, ...) is bad
  auto take = [&](int k, double dt) {
    if (!(dt > 0.0))
      bad[k] = 1;
    else if (dt < local[k])
      local[k] = dt;
  };

  // the acoustic, force and thermal limits fall as one per-atom quantity
  // rises: its largest gives their smallest dt with one division
  double fastest = 0.0, largest_accel = 0.0, largest_relax = 0.0;
  auto rises = [&](int k, double value, double &largest) {
    if (!(value >= 0.0 && value <= DBL_MAX))    // not a number, infinite or negative: dt <= 0
      bad[k] = 1;
    else if (value > largest)
      largest = value;
  };
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & scan.groupbit)) continue;
    const int itype = type[i];
    const double vsq = v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
    const double fsq = f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2];

    // a limit whose property the type lacks does not apply to the particle
    if (coeff[ACOUSTIC] > 0.0) {
      const sphe_eos *eos = scan.materials->eos(itype);
      if (eos) rises(ACOUSTIC, signal_speed(sphe_sound_speed(eos, rho[i]), sqrt(vsq), s), fastest);
    }
    if (coeff[FORCE] > 0.0 && fsq != 0.0) {    // a non-finite force counts
      const double m = particles.mass(i);
      rises(FORCE, acceleration(sqrt(fsq), m, s), largest_accel);
    }
    if (coeff[VISCOUS] > 0.0) {
      const double mu = scan.materials->viscosity(itype)
          ? scan.materials->viscosity_at(itype, particles.temperature(i), scan.who)
          : 0.0;
      if (mu > 0.0) take(VISCOUS, viscous(coeff[VISCOUS], h, rho[i], mu, s));
    }
    if (coeff[THERMAL] > 0.0 && lambda && lambda[i] > 0.0)
      rises(THERMAL, relaxation(lambda[i], s), largest_relax);
  }
  if (fastest > 0.0) take(ACOUSTIC, acoustic(coeff[ACOUSTIC], h, fastest));
  if (largest_accel > 0.0) take(FORCE, force(coeff[FORCE], h, largest_accel));
  if (largest_relax > 0.0) take(THERMAL, thermal(coeff[THERMAL], largest_relax));
  // the body force alone, as read from its fix: it counts from the first
  // step even when that fix adds it after the forces were looked at
  if (coeff[FORCE] > 0.0 && scan.body_force) {
    const double *g = scan.body_force;
    const double gmag = acceleration(sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]), 1.0, s);
    if (gmag > 0.0) take(FORCE, force(coeff[FORCE], h, gmag));
  }
}

/* ---------------------------------------------------------------------- */

double SPHTimestep::smoothing_length(LAMMPS *lmp)
{
  // the package's pair styles (each knows its kernel)
  double hmin = 0.0;
  for (const PairSPHKernel *pair : SPHHub(lmp).pairs()) {
    const SPHKernelSettings given = pair->kernel_settings();
    if (sphk_support(given.kind) <= 0.0) continue;
    const double hpair = given.cutoff / sphk_support(given.kind);
    if (hmin == 0.0 || hpair < hmin) hmin = hpair;
  }
  return hmin;
}
