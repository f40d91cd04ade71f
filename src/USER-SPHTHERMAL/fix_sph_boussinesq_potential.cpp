/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   fix sph/boussinesq 'potential': the buoyancy's potential phi, whose
   pressure rho0 phi the flow adds to its equation of state's (the rest of
   the fix: fix_sph_boussinesq.cpp)
------------------------------------------------------------------------- */

#include "fix_sph_boussinesq.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_sph_wall_adami.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "sph_buoyancy.h"
#include "sph_compat.h"
#include "sph_hub.h"
#include "sph_particle.h"
#include "utils.h"

#include <cmath>
#include <vector>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   'potential': the pressure rho0 phi balances the curl-free part of the
   buoyancy f, grad phi = f - (its solenoidal part), so the fluid need not
   compress to carry it. phi solves
     lap phi = div f   in the group,   d phi / dn = f . n   at the walls
   by Jacobi sweeps on Morris's SPH Laplacian with the flow's kernel,
   warm-started from the last step's phi. The atoms of fix sph/wall/adami
   take phi as those walls extrapolate a pressure, which carries the
   Neumann condition:
     phi_w = sum_f W_wf (phi_f + f_f . (x_w - x_f)) / sum_f W_wf
   and, in div f, the fluid's f as a Shepard mean. phi is defined up to a
   constant: the group's mean is 0.
------------------------------------------------------------------------- */

void FixSPHBoussinesq::init_list(int /*id*/, NeighList *ptr)
{
  list = ptr;
}

// the first run (without phi from a restart file) sweeps to convergence:
// a change per sweep below this part of max|phi| (Jacobi's error is then
// about n^2 / 10 times that, n the particles across)
static constexpr double SETUP_TOLERANCE = 1e-9;
static constexpr int SETUP_SWEEPS_MAX = 20000;

void FixSPHBoussinesq::setup_pre_force(int /*vflag*/)
{
  int solved = potential_solved;
  MPI_Allreduce(&potential_solved, &solved, 1, MPI_INT, MPI_MAX, world);
  if (solved) {
    // phi of the last step or the restart file, as the run left it
    comm_what = COMM_POTENTIAL;
    SPHCompat::forward_comm(comm, this);
    return;
  }
  prepare_potential();
  // the change of phi less its mean's (which drifts as far as the discrete
  // div f and f . n do not balance)
  const int nlocal = atom->nlocal;
  const int *const mask = atom->mask;
  std::vector<double> previous(potential, potential + nlocal);
  double change = 0.0, largest = 0.0;
  int sweeps = 0;
  while (sweeps < SETUP_SWEEPS_MAX) {
    sweeps++;
    sweep_potential();
    largest = remove_mean_potential();
    double local = 0.0;
    for (int i = 0; i < nlocal; i++)
      if (mask[i] & groupbit) {
        local = fmax(local, fabs(potential[i] - previous[i]));
        previous[i] = potential[i];
      }
    MPI_Allreduce(&local, &change, 1, MPI_DOUBLE, MPI_MAX, world);
    if (change <= SETUP_TOLERANCE * largest) break;
  }
  potential_solved = 1;
  // the walls defined before this fix extrapolated their pressure at their
  // set-up without phi: again, with it (later steps lag by one sweep)
  const int me_index = modify->find_fix(id);
  for (FixSPHWallAdami *wall : SPHHub(lmp).fixes<FixSPHWallAdami>())
    if (modify->find_fix(wall->id) < me_index) wall->extrapolate_again();
  if (change > SETUP_TOLERANCE * largest) {
    if (comm->me == 0)
      error->warning(FLERR,
                     "Fix sph/boussinesq {}: the buoyancy's potential changed by {:.3g} of "
                     "max|phi| = {:.6g} in the last of {} sweeps at set-up; the {} per step go "
                     "on converging it",
                     id, largest > 0.0 ? change / largest : change, largest, sweeps,
                     potential_sweeps);
  } else if (comm->me == 0) {
    utils::logmesg(lmp,
                   "Fix sph/boussinesq {}: the buoyancy's potential converged in {} sweeps "
                   "(max|phi| = {:.6g}); {} per step\n",
                   id, sweeps, largest, potential_sweeps);
  }
}

void FixSPHBoussinesq::pre_force(int /*vflag*/)
{
  prepare_potential();
  for (int k = 0; k < potential_sweeps; k++) sweep_potential();
  remove_mean_potential();
}

/* ----------------------------------------------------------------------
   the buoyancy per unit mass of each group atom and (a Shepard mean of the
   fluid's) of each wall atom, the diagonal of the Laplacian and div f
------------------------------------------------------------------------- */

void FixSPHBoussinesq::prepare_potential()
{
  const SPHParticles particles(atom);
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  const double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int *const type = atom->type;
  const double *const g = buoyancy.gravity;

  accel.assign(3 * (size_t) nall, 0.0);
  for (int i = 0; i < nall; i++)
    if (mask[i] & groupbit)
      sphb_acceleration(g, beta[type[i]], particles.temperature(i),
                        SPHBodyForce::reference(buoyancy, x[i]), &accel[3 * (size_t) i]);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & wall_bits) || (mask[i] & groupbit)) continue;
    double w_sum = 0.0, fw[3] = {0.0, 0.0, 0.0};
    visit_neighbours(i, groupbit, [&](int j, const double *, double r) {
      const double w = sphk_w(&kernel, r);
      w_sum += w;
      for (int k = 0; k < 3; k++) fw[k] += w * accel[3 * (size_t) j + k];
    });
    for (int k = 0; k < 3; k++) wall_force[i][k] = w_sum > 0.0 ? fw[k] / w_sum : 0.0;
  }
  comm_what = COMM_WALL_FORCE;
  SPHCompat::forward_comm(comm, this);
  for (int i = 0; i < nall; i++)
    if ((mask[i] & wall_bits) && !(mask[i] & groupbit))
      for (int k = 0; k < 3; k++) accel[3 * (size_t) i + k] = wall_force[i][k];

  diag.assign(nlocal, 0.0);
  source.assign(nlocal, 0.0);
  next.assign(nlocal, 0.0);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const double *fi = &accel[3 * (size_t) i];
    visit_neighbours(i, groupbit | wall_bits, [&](int j, const double *del, double r) {
      if (r == 0.0) return;
      const double weight = particles.volume(j) * sphk_dwdr(&kernel, r) / r;
      const double *fj = &accel[3 * (size_t) j];
      diag[i] -= 2.0 * weight;
      source[i] += weight *
          ((fj[0] - fi[0]) * del[0] + (fj[1] - fi[1]) * del[1] + (fj[2] - fi[2]) * del[2]);
    });
  }
}

/* ----------------------------------------------------------------------
   one Jacobi sweep: the walls' phi from the fluid's, then the fluid's
------------------------------------------------------------------------- */

void FixSPHBoussinesq::sweep_potential()
{
  const SPHParticles particles(atom);
  const int *const mask = atom->mask;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & wall_bits) || (mask[i] & groupbit)) continue;
    double w_sum = 0.0, p = 0.0;
    visit_neighbours(i, groupbit, [&](int j, const double *del, double r) {
      const double w = sphk_w(&kernel, r);
      const double *fj = &accel[3 * (size_t) j];
      w_sum += w;
      p += w * (potential[j] + fj[0] * del[0] + fj[1] * del[1] + fj[2] * del[2]);
    });
    potential[i] = w_sum > 0.0 ? p / w_sum : 0.0;
  }
  comm_what = COMM_POTENTIAL;
  SPHCompat::forward_comm(comm, this);
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(mask[i] & groupbit) || !(diag[i] > 0.0)) continue;
    double off = 0.0;
    visit_neighbours(i, groupbit | wall_bits, [&](int j, const double *, double r) {
      if (r > 0.0) off -= 2.0 * particles.volume(j) * sphk_dwdr(&kernel, r) / r * potential[j];
    });
    next[i] = (off - source[i]) / diag[i];
  }
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if ((mask[i] & groupbit) && diag[i] > 0.0) potential[i] = next[i];
  }
}

/* ----------------------------------------------------------------------
   the group's mean phi set to 0 (the walls' shifted with it) and the
   ghosts' phi sent; returns max|phi| of the group (all ranks)
------------------------------------------------------------------------- */

double FixSPHBoussinesq::remove_mean_potential()
{
  const int nlocal = atom->nlocal;
  const int *const mask = atom->mask;
  double local[2] = {0.0, 0.0}, all[2];
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) {
      local[0] += potential[i];
      local[1] += 1.0;
    }
  MPI_Allreduce(local, all, 2, MPI_DOUBLE, MPI_SUM, world);
  const double mean = all[1] > 0.0 ? all[0] / all[1] : 0.0;
  double largest = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & (groupbit | wall_bits)) {
      potential[i] -= mean;
      if (mask[i] & groupbit) largest = fmax(largest, fabs(potential[i]));
    }
  comm_what = COMM_POTENTIAL;
  SPHCompat::forward_comm(comm, this);
  double largest_all = 0.0;
  MPI_Allreduce(&largest, &largest_all, 1, MPI_DOUBLE, MPI_MAX, world);
  return largest_all;
}

/* ----------------------------------------------------------------------
   phi per atom: migrates with it, goes in restart files (a restarted run
   goes on from it), 0 for a new atom
------------------------------------------------------------------------- */

void FixSPHBoussinesq::grow_arrays(int nmax)
{
  memory->grow(potential, nmax, "sph/boussinesq:potential");
  memory->grow(wall_force, nmax, 3, "sph/boussinesq:wall_force");
  for (int i = nmax_potential; i < nmax; i++) potential[i] = 0.0;
  nmax_potential = nmax;
  vector_atom = potential;
}

void FixSPHBoussinesq::copy_arrays(int i, int j, int /*delflag*/)
{
  potential[j] = potential[i];
}

void FixSPHBoussinesq::set_arrays(int i)
{
  potential[i] = 0.0;
}

int FixSPHBoussinesq::pack_exchange(int i, double *buf)
{
  buf[0] = potential[i];
  return 1;
}

int FixSPHBoussinesq::unpack_exchange(int i, double *buf)
{
  potential[i] = buf[0];
  return 1;
}

int FixSPHBoussinesq::pack_restart(int i, double *buf)
{
  buf[0] = 2;
  buf[1] = potential[i];
  return 2;
}

void FixSPHBoussinesq::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  potential[nlocal] = extra[nlocal][m + 1];
  potential_solved = 1;
}

int FixSPHBoussinesq::size_restart(int /*i*/)
{
  return 2;
}

int FixSPHBoussinesq::maxsize_restart()
{
  return 2;
}

int FixSPHBoussinesq::pack_forward_comm(int n, int *send, double *buf, int /*pbc_flag*/,
                                        int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = send[k];
    if (comm_what == COMM_POTENTIAL)
      buf[m++] = potential[j];
    else
      for (int d = 0; d < 3; d++) buf[m++] = wall_force[j][d];
  }
  return m;
}

void FixSPHBoussinesq::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    if (comm_what == COMM_POTENTIAL)
      potential[i] = buf[m++];
    else
      for (int d = 0; d < 3; d++) wall_force[i][d] = buf[m++];
  }
}
