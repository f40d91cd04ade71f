/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   compute sph/force: the force and torque on a group from every atom
   outside it through pair style sph/harmonic/visc (pressure and viscous
   parts), summed by the pair right after its loop with the loop's own
   state, on the steps this compute will be invoked.
------------------------------------------------------------------------- */

#include "compute_sph_force.h"

#include "domain.h"
#include "error.h"
#include "group.h"
#include "sph_checks.h"
#include "sph_hub.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeSPHForce::ComputeSPHForce(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), center_given(0)
{
  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "center") == 0) {
      if (iarg + 4 > narg)
        error->all(FLERR, "Compute sph/force {}: keyword center needs 3 values (x y z)", id);
      for (int k = 0; k < 3; k++) center[k] = utils::numeric(FLERR, arg[iarg + 1 + k], false, lmp);
      center_given = 1;
      iarg += 4;
    } else
      error->all(FLERR, "Compute sph/force {}: unknown keyword {} (expected center)", id,
                 arg[iarg]);
  }
  if (igroup == 0)
    error->all(FLERR,
               "Compute sph/force {}: group all has no atoms outside it to feel a force from", id);
  vector_flag = 1;
  size_vector = 18;
  extvector = 1;    // sums over the group
  timeflag = 1;     // the pair makes the sums on the steps this compute lists
  vector = values;
  request.compute = this;
  request.step = -1;
  for (int k = 0; k < 3; k++) request.origin[k] = request.made_about[k] = 0.0;
  for (double &s : request.sums) s = 0.0;
  for (double &v : values) v = 0.0;
}

/* ---------------------------------------------------------------------- */

void ComputeSPHForce::init()
{
  const std::string who = fmt::format("Compute sph/force {}", id);
  PairSPHHarmonicVisc *flow = SPHHub(lmp).require_flow(who.c_str());
  SPHCheck::warn_empty(lmp, FLERR, who.c_str(), igroup);
  centre_of_mass(request.origin);
  request.step = -1;
  flow->make_group_force(&request);
}

/* ----------------------------------------------------------------------
   the group's centre of mass now (unwrapped: a body that crossed a periodic
   boundary keeps its place), the origin of the pair's moments, which are
   then taken from each atom's nearest image of it; 0 for an empty group
------------------------------------------------------------------------- */

void ComputeSPHForce::centre_of_mass(double *point)
{
  const double mass = group->mass(igroup);
  point[0] = point[1] = point[2] = 0.0;
  if (mass > 0.0) group->xcm(igroup, mass, point);
}

/* ----------------------------------------------------------------------
   1-3 force, 4-6 its pressure part, 7-9 its viscous part, 10-12 torque,
   13-15 its pressure part, 16-18 its viscous part
------------------------------------------------------------------------- */

void ComputeSPHForce::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (request.step != update->ntimestep)
    error->all(FLERR,
               "Compute sph/force {}: pair sph/harmonic/visc made no sums on step {} (the "
               "compute is invoked between the steps that thermo, dump or a fix ave/* asked "
               "for, e.g. from a variable in a run every or print command)",
               id, update->ntimestep);
  double sums[12];
  MPI_Allreduce(request.sums, sums, 12, MPI_DOUBLE, MPI_SUM, world);
  // the moments about the origin the pair used, moved to the point asked
  // for (as given, no periodic image of it): T_point = T_origin - (point -
  // origin) x F
  double mass_centre[3];
  centre_of_mass(mass_centre);
  const double *point = center_given ? center : mass_centre;
  double shift[3] = {point[0] - request.made_about[0], point[1] - request.made_about[1],
                     point[2] - request.made_about[2]};
  if (domain->dimension == 2) shift[2] = 0.0;
  for (int part = 0; part < 2; part++) {
    const double *f = sums + 3 * part;
    double *t = sums + 6 + 3 * part;
    t[0] -= shift[1] * f[2] - shift[2] * f[1];
    t[1] -= shift[2] * f[0] - shift[0] * f[2];
    t[2] -= shift[0] * f[1] - shift[1] * f[0];
  }
  for (int k = 0; k < 3; k++) {
    values[3 + k] = sums[k];
    values[6 + k] = sums[3 + k];
    values[k] = sums[k] + sums[3 + k];
    values[12 + k] = sums[6 + k];
    values[15 + k] = sums[9 + k];
    values[9 + k] = sums[6 + k] + sums[9 + k];
  }
  // the next sums about the centre of mass: it moves with the group
  for (int k = 0; k < 3; k++) request.origin[k] = mass_centre[k];
}
