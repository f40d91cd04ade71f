/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

// pair style sph/harmonic/visc: the force on a group (compute sph/force)

#include "pair_sph_harmonic_visc.h"

#include "atom.h"
#include "compute.h"
#include "domain.h"
#include "force.h"
#include "neigh_list.h"
#include "sph_flow.h"
#include "sph_kernels.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicVisc::make_group_forces()
{
  const bigint step = update->ntimestep;
  for (GroupForce *request : group_forces)
    if (update->setupflag || request->compute->matchstep(step)) {
      group_force(*request);
      request->step = step;
    }
}

/* ----------------------------------------------------------------------
   every pair of the loop with one atom in the group and one outside: the
   main loop's force on the atom in the group (sph_flow.h's sphf_pair with
   the same state), its pressure part (s_r less the cleary viscosity's
   share, along B grad W with the gradient correction) and viscous part;
   once per pair over all ranks, as the loop adds it
------------------------------------------------------------------------- */

void PairSPHHarmonicVisc::group_force(GroupForce &request) const
{
  const int groupbit = request.compute->groupbit;
  const int newton_pair = force->newton_pair;
  const int dim3 = domain->dimension == 3;
  const double *const *const x = atom->x;
  // (the velocity of the last evaluation's loop)
  const double *const *const vest = velocity_seen ? velocity_seen : atom->vest;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double cutsq_kernel = cut_global * cut_global;
  const double dwdr_r_scale = kernel.dw_scale * kernel.inv_h;
  // as eval_dimension() chooses the corrected loop
  const int corrected = gradient_correction && pressure_form == SPHF_P_AVERAGED;

  double *const sums = request.sums;
  for (int k = 0; k < 12; k++) sums[k] = 0.0;
  for (int k = 0; k < 3; k++) request.made_about[k] = request.origin[k];

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int in_i = mask[i] & groupbit;
    const int wall_i = mask[i] & wall_groupbit;
    const sphf_particle a = {mass_of[i], density[i], volume[i], pressure[i], viscosity[i]};
    const int *const jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int in_j = mask[j] & groupbit;
      if (!in_i == !in_j) continue;
      // a ghost's force is its owner's to count when newton is off
      if (!in_i && !newton_pair && j >= nlocal) continue;
      const int wall_j = mask[j] & wall_groupbit;
      if (wall_i && wall_j) continue;
      const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], dim3 ? x[i][2] - x[j][2] : 0.0};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      if (rsq >= cutsq_kernel) continue;
      const double dwdr_r = dwdr_r_scale * sphk_df_over_q(kernel_kind, sqrt(rsq) * kernel.inv_h);
      const sphf_particle b = {mass_of[j], density[j], volume[j], pressure[j], viscosity[j]};
      const double dv[3] = {vest[i][0] - vest[j][0], vest[i][1] - vest[j][1],
                            dim3 ? vest[i][2] - vest[j][2] : 0.0};
      const double vr_est = (viscosity_form == SPHF_V_CLEARY)
          ? dv[0] * del[0] + dv[1] * del[1] + dv[2] * del[2]
          : 0.0;
      double s_r, s_rv, s_v, c_i, c_j, inv_other;
      sphf_pair(pressure_form, viscosity_form, xi, &a, &b, rsq, dwdr_r, eta2, vr_est, 1.0, &s_r,
                &s_rv, &s_v, &c_i, &c_j, &inv_other);
      // the artificial viscosity is a viscous force along r_ij (its own pass)
      if (artificial > 0.0) {
        // (with a wall particle's own velocity, as eval_artificial())
        const double *const u_i = wall_i ? atom->v[i] : vest[i];
        const double *const u_j = wall_j ? atom->v[j] : vest[j];
        double vr_u = 0.0;
        for (int k = 0; k < 3; k++) vr_u += (u_i[k] - u_j[k]) * del[k];
        const double s_a = artificial_pair(i, j, vr_u, rsq, dwdr_r);
        s_r += s_a;
        s_rv += s_a;
      }
      double direction[3] = {del[0], del[1], del[2]};
      if (corrected) corrected_direction(gradient_inverse, i, j, wall_i, wall_j, del, direction);
      // the force on the group's atom: F_ij on i, -F_ij on j
      const double sign = in_i ? 1.0 : -1.0;
      const double s_p = sign * (s_r - s_rv);
      const double f_p[3] = {s_p * direction[0], s_p * direction[1], s_p * direction[2]};
      double f_v[3];
      for (int k = 0; k < 3; k++) f_v[k] = sign * (s_rv * del[k] + s_v * dv[k]);
      // its moment about the origin, from the atom's nearest image
      const int atom_in = in_i ? i : j;
      double arm[3] = {x[atom_in][0] - request.origin[0], x[atom_in][1] - request.origin[1],
                       x[atom_in][2] - request.origin[2]};
      domain->minimum_image(arm);
      if (!dim3) arm[2] = 0.0;
      for (int k = 0; k < 3; k++) {
        sums[k] += f_p[k];
        sums[3 + k] += f_v[k];
      }
      sums[6] += arm[1] * f_p[2] - arm[2] * f_p[1];
      sums[7] += arm[2] * f_p[0] - arm[0] * f_p[2];
      sums[8] += arm[0] * f_p[1] - arm[1] * f_p[0];
      sums[9] += arm[1] * f_v[2] - arm[2] * f_v[1];
      sums[10] += arm[2] * f_v[0] - arm[0] * f_v[2];
      sums[11] += arm[0] * f_v[1] - arm[1] * f_v[0];
    }
  }
}
