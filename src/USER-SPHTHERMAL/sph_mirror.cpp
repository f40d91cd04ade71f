/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   Mirror points of wall particles and the temperature or velocity there
   (sph_mirror.h).
------------------------------------------------------------------------- */

#include "sph_mirror.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_sph_inlet_temperature.h"
#include "fix_sph_wall_adami.h"
#include "fix_sph_wall_adiabatic.h"
#include "fix_sph_wall_dirichlet.h"
#include "fix_sph_wall_isothermal.h"
#include "modify.h"
#include "neighbor.h"
#include "region.h"
#include "sph_checks.h"
#include "sph_comm_stage.h"
#include "sph_compat.h"
#include "sph_dispatch.h"
#include "sph_hub.h"
#include "sph_interpolation.h"
#include "sph_kernels.h"
#include "sph_particle.h"
#include "sph_threads.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

SPHMirror::SPHMirror(LAMMPS *lmp, const std::string &cmd, bool returns, Field what) :
    Pointers(lmp), command(cmd), returns_heat(returns), field(what), region(nullptr), groupbit(0),
    medium_exclude(0), held_walls(0), kernel_kind(0), cutoff(0.0), inlet_axis(-1),
    candidates_valid(false), medium_check_pending(false), crossing_check_pending(false),
    crossing_warned(false), first_row_depth(0.0)
{
}

SPHMirror::~SPHMirror() = default;

int SPHMirror::parse(int narg, char **arg, int iarg)
{
  if (iarg + 1 >= narg)
    error->all(FLERR, "Illegal {} command: 'surface' needs a region ID (the region of the medium)",
               command);
  region_name = arg[iarg + 1];
  return 2;
}

/* ---------------------------------------------------------------------- */

void SPHMirror::init(int groupbit_in, int kind, double cut, const char *id)
{
  fix_id = id ? id : "";
  // the region is checked at every run's start: strictly against the scene
  // as set up (step 0); later a fluid particle next to the wall may have
  // moved past the surface by a fraction of a spacing (an impact pushes it
  // there), which is the flow's, not the region's, doing: up to the depth
  // of the nearest wall atom, the first wall row
  medium_check_pending = true;
  groupbit = groupbit_in;
  kernel_kind = kind;
  cutoff = cut;
  region = SPHCompat::find_region(domain, region_name);
  if (!region) error->all(FLERR, "{}: surface region {} does not exist", command, region_name);
  if (region->dynamic || region->varshape)
    error->all(FLERR,
               "{}: surface region {} moves or changes shape; the wall surface must be fixed",
               command, region_name);

  // the interpolation reads the volume and temperature (or velocity) of the
  // medium: pair sph/cleary/heat, which the mirror walls require, has
  // checked every atom's rho, cv and esph at its init, which comes before
  // the fixes' (pair sph/harmonic/visc every atom's rho for the flow walls)

  SPHHub hub(lmp);
  inlet_axis = -1;
  held_walls = 0;
  if (field == VELOCITY) {
    // the flow's medium: the fluid, the atoms of no flow wall
    medium_exclude = hub.groupbits<FixSPHWallAdami>();
  } else {
    for (FixSPHInletTemperature *inlet : hub.fixes<FixSPHInletTemperature>())
      inlet_axis = inlet->flow_axis();
    // the thermal walls' particles are not part of the medium; those that
    // hold a temperature are not the medium's either way
    held_walls = hub.groupbits<FixSPHWallDirichlet>() | hub.groupbits<FixSPHWallIsothermal>();
    medium_exclude = held_walls | hub.groupbits<FixSPHWallAdiabatic>();
  }

  // every wall atom lies outside the region; the farthest one within the
  // kernel's reach sets how far the ghost points lie from their wall atoms
  double *const *const x = atom->x;
  double dmax_local = 0.0, dmin_local = INFINITY;
  SPHCheck::FirstBad inside, deep;
  bigint deep_local = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double g[3];
    const int found = ghost_point(x[i], g);
    if (found < 0) inside.consider(atom->tag[i]);
    if (found == 0) {
      deep.consider(atom->tag[i]);
      deep_local++;
    }
    if (found > 0) {
      const double d = 0.5 *
          sqrt((g[0] - x[i][0]) * (g[0] - x[i][0]) + (g[1] - x[i][1]) * (g[1] - x[i][1]) +
               (g[2] - x[i][2]) * (g[2] - x[i][2]));
      dmax_local = MAX(dmax_local, d);
      dmin_local = MIN(dmin_local, d);
    }
  }
  if (inside.agree(lmp))
    error->all(FLERR,
               "{}: wall atom {} lies inside surface region {} (side {}); the region holds the "
               "medium and its boundary is the wall surface, so wall atoms lie outside it (side "
               "in: outside its shape; side out, the medium around an obstacle: inside it)",
               command, inside.tag, region_name, region->interior ? "in" : "out");
  MPI_Allreduce(&deep_local, &deep_count, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  deep_first = deep.agree(lmp) ? deep.tag : 0;
  double dmax = 0.0, dmin = INFINITY;
  MPI_Allreduce(&dmax_local, &dmax, 1, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&dmin_local, &dmin, 1, MPI_DOUBLE, MPI_MIN, world);
  first_row_depth = std::isfinite(dmin) ? dmin : 0.0;
  crossing_check_pending = false;
  crossing_warned = false;

  // the medium around a ghost point up to 2 dmax away, also on other ranks
  const double needed = cutoff + 2.0 * dmax + neighbor->skin;
  if (comm->cutghostuser < needed) {
    if (comm->me == 0 && comm->cutghostuser < needed * (1.0 - 1e-12))
      utils::logmesg(lmp,
                     "{}: communication cutoff raised to {:.8g} for the ghost points of wall atoms "
                     "up to {:.8g} from the surface\n",
                     command, needed, dmax);
    comm->cutghostuser = needed;
  }
}

/* ----------------------------------------------------------------------
   the ghost point of a wall atom at x: 1 and the point, 0 when the atom is
   beyond the kernel's reach of the surface, -1 when it is inside the region
   (on the medium's side). The wall atoms lie off the medium's side of the
   region's surface: outside its shape for a region 'side in' (the medium
   in a container), inside it for 'side out' (the medium around an
   obstacle); LAMMPS's surface_exterior() and surface_interior() give the
   surface points within reach of such points (contact: del = x - surface
   point). surface_interior() gives one per face within reach: the nearest
   is the mirror plane.
------------------------------------------------------------------------- */

int SPHMirror::ghost_point(const double *x, double *ghost, double *depth)
{
  double xs[3] = {x[0], x[1], x[2]};
  const int ncontact = region->interior ? region->surface_exterior(xs, cutoff)
                                        : region->surface_interior(xs, cutoff);
  if (ncontact > 0) {
    int nearest = 0;
    for (int k = 1; k < ncontact; k++)
      if (region->contact[k].r < region->contact[nearest].r) nearest = k;
    const auto &c = region->contact[nearest];
    if (depth) *depth = c.r;
    ghost[0] = x[0] - 2.0 * c.delx;
    ghost[1] = x[1] - 2.0 * c.dely;
    ghost[2] = x[2] - 2.0 * c.delz;
    return 1;
  }
  return region->match(x[0], x[1], x[2]) ? -1 : 0;
}

/* ----------------------------------------------------------------------
   once after each init, with this step's ghost points and candidates: every
   medium atom within the kernel's reach of a wall atom of the group or of
   a ghost point (those the wall reads) must lie in the region (after step
   0: or past its surface by at most first_row_depth), the
   medium's side of the surface; one that does not means a region too small
   (or on the wrong side), whose surface is not the wall's: a collective
   error naming the lowest such atom ID. Ghost images are taken back into
   the periodic box first, where the region is.
------------------------------------------------------------------------- */

void SPHMirror::check_medium(bool during_run)
{
  if (during_run) {
    crossing_check_pending = false;
    if (crossing_warned || first_row_depth <= 0.0) return;
  } else
    medium_check_pending = false;
  // strict for the scene as set up (step 0)
  const double tolerance = (during_run || update->ntimestep > 0) ? first_row_depth : 0.0;
  double *const *const x = atom->x;
  const tagint *const tag = atom->tag;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double cutsq = cutoff * cutoff;
  tagint first_local = MAXTAGINT;
  double info[4] = {-INFINITY, -INFINITY, -INFINITY, -INFINITY};    // type, x, y, z
  auto consider = [&](int j, const double *p) {
    if ((mask[j] & medium_exclude) || tag[j] >= first_local) return;
    const double d[3] = {x[j][0] - p[0], x[j][1] - p[1], x[j][2] - p[2]};
    if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] >= cutsq) return;
    double at[3] = {x[j][0], x[j][1], x[j][2]};
    domain->remap(at);
    if (region->match(at[0], at[1], at[2])) return;
    // just past the surface (on the wall's side, within the tolerance)
    if (tolerance > 0.0 &&
        (region->interior ? region->surface_exterior(at, tolerance)
                          : region->surface_interior(at, tolerance)) > 0)
      return;
    first_local = tag[j];
    info[0] = atom->type[j];
    info[1] = at[0], info[2] = at[1], info[3] = at[2];
  };
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    cells.within(x, x[i], cutoff, [&](int j) {
      consider(j, x[i]);
    });
    if (!has_ghost[i]) continue;
    const double *const g = &ghost_at[3 * (size_t) i];
    for (int n = first_candidate[i]; n < first_candidate[i + 1]; n++)
      consider(medium_atoms[candidates[n]], g);
  }
  tagint first = MAXTAGINT;
  MPI_Allreduce(&first_local, &first, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  if (first == MAXTAGINT) return;
  if (first_local != first) info[0] = info[1] = info[2] = info[3] = -INFINITY;
  double where[4];
  MPI_Allreduce(info, where, 4, MPI_DOUBLE, MPI_MAX, world);
  if (during_run) {
    // the flow pushed a particle through the surface, past the first wall
    // atoms: the wall's values around it no longer hold it (a warning, once
    // a run: the run may recover)
    crossing_warned = true;
    if (comm->me == 0)
      error->warning(FLERR,
                     "{}: medium atom {} (type {}) at ({:.8g} {:.8g} {:.8g}) has crossed the "
                     "surface of region {} to the first wall atoms' depth ({:.4g}) or beyond at "
                     "step {}: the flow pushed it into the wall, whose values there do not hold "
                     "it (a larger speed of sound or a finer resolution keeps it out)",
                     who(), first, (int) where[0], where[1], where[2], where[3], region_name,
                     first_row_depth, update->ntimestep);
    return;
  }
  error->all(FLERR,
             "{}: medium atom {} (type {}) at ({:.8g} {:.8g} {:.8g}), within the kernel's reach "
             "of the wall atoms or their ghost points, lies outside surface region {} (side {}); "
             "the region holds all the medium next to the wall, its boundary is the wall's "
             "surface: make the region reach the medium's edge (or put the atom in a {} fix's "
             "group)",
             who(), first, (int) where[0], where[1], where[2], where[3], region_name,
             region->interior ? "in" : "out",
             field == VELOCITY ? "sph/wall/adami" : "thermal wall");
}

/* ----------------------------------------------------------------------
   the medium atoms within cutoff + skin of each ghost point of this step,
   and the particles of held walls within it of each wall particle
------------------------------------------------------------------------- */

void SPHMirror::find_candidates()
{
  double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const double reach = cutoff + neighbor->skin;
  cells.bin(x, mask, nall, groupbit, reach);
  candidates_at = ghost_at;
  cells.near_points(
      x, nlocal, nall, reach,
      [&](int i) {
        return has_ghost[i] ? &ghost_at[3 * (size_t) i] : nullptr;
      },
      [&](int j) {
        return !(mask[j] & medium_exclude);
      },
      first_candidate, candidates, medium_atoms);
  // the particles of walls that hold a temperature near each wall particle
  cells.near_points(
      x, nlocal, nall, reach,
      [&](int i) {
        return (held_walls && (mask[i] & groupbit)) ? x[i] : nullptr;
      },
      [&](int j) {
        return (mask[j] & held_walls) != 0;
      },
      first_held, held_near, held_atoms);
  candidates_valid = true;
}

/* ---------------------------------------------------------------------- */

struct SPHMirror::PointsCall {
  SPHMirror *mirror;
  std::vector<double> *ghost;
  std::vector<int> *how;
  template <int DIM, int KERNEL> void run()
  {
    const sphk_kernel kernel = sphk_make(KERNEL, DIM, mirror->cutoff);
    mirror->interpolate_points<DIM, KERNEL>(*ghost, *how, kernel);
  }
};

void SPHMirror::interpolate(std::vector<double> &ghost, std::vector<int> &how,
                            std::vector<double> *depth)
{
  interpolate_field(ghost, how, depth);
}

void SPHMirror::interpolate_velocity(std::vector<double> &ghost_v, std::vector<int> &how)
{
  interpolate_field(ghost_v, how, nullptr);
}

void SPHMirror::interpolate_field(std::vector<double> &out, std::vector<int> &how,
                                  std::vector<double> *depth)
{
  // the temperature, or the velocity and its gradient
  const size_t per_atom = (field == VELOCITY) ? 12 : 1;
  out.assign(per_atom * atom->nlocal, 0.0);
  prepare(how, depth);
  PointsCall call = {this, &out, &how};
  const int settings[] = {domain->dimension, kernel_kind};
  SPHDispatch<SPHDimensions, SPHKernelKinds>::to(call, settings);
}

void SPHMirror::prepare(std::vector<int> &how, std::vector<double> *depth)
{
  const SPHParticles particles(atom);
  double *const *const x = atom->x;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  how.assign(nlocal, SPHI_NONE);
  if (depth) depth->assign(nlocal, 0.0);
  first_neighbour.assign(nlocal + 1, 0);
  neighbours.clear();
  weights.clear();

  // this step's ghost points; the candidates of the last neighbour build
  // serve while no ghost point has moved by half the skin since
  ghost_at.assign(3 * (size_t) nlocal, 0.0);
  has_ghost.assign(nlocal, 0);
  bool stale = !candidates_valid || (int) first_candidate.size() != nlocal + 1;
  const double half_skin_sq = 0.25 * neighbor->skin * neighbor->skin;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *const g = &ghost_at[3 * (size_t) i];
    has_ghost[i] = ghost_point(x[i], g, depth ? &(*depth)[i] : nullptr) > 0;
    if (stale || !has_ghost[i]) continue;
    const double *const g_then = &candidates_at[3 * (size_t) i];
    const double d[3] = {g[0] - g_then[0], g[1] - g_then[1], g[2] - g_then[2]};
    if (first_candidate[i] == first_candidate[i + 1] ||
        d[0] * d[0] + d[1] * d[1] + d[2] * d[2] > half_skin_sq)
      stale = true;
  }
  if (stale || medium_check_pending) find_candidates();
  if (medium_check_pending)
    check_medium();
  else if (crossing_check_pending)
    check_medium(true);
  const int nmedium = medium_atoms.size();
  medium_volume.resize(nmedium);
  medium_x.resize(3 * (size_t) nmedium);
  const int components = (field == VELOCITY) ? 3 : 1;
  medium_values.resize(components * (size_t) nmedium);
  const double *const *const v = atom->v;
  for (int m = 0; m < nmedium; m++) {
    const int j = medium_atoms[m];
    medium_volume[m] = particles.volume(j);
    for (int k = 0; k < 3; k++) medium_x[3 * (size_t) m + k] = x[j][k];
    if (field == TEMPERATURE)
      medium_values[m] = particles.temperature(j);
    else
      for (int k = 0; k < 3; k++) medium_values[3 * (size_t) m + k] = v[j][k];
  }
}

/* ----------------------------------------------------------------------
   the corrected interpolation at every ghost point of this step; DIM: the
   moment sums' size known to the compiler, so that they stay in registers
------------------------------------------------------------------------- */

template <int DIM, int KERNEL>
void SPHMirror::interpolate_points(std::vector<double> &ghost, std::vector<int> &how,
                                   const sphk_kernel &kernel)
{
  const int nlocal = atom->nlocal;
  // each thread a slice of the atoms with a ghost point (of even work,
  // wherever the wall atoms lie in the atom order): thread 0 keeps its
  // neighbours and weights in place, the others theirs apart, appended
  // after in order
  with_ghost.clear();
  for (int i = 0; i < nlocal; i++)
    if (has_ghost[i]) with_ghost.push_back(i);
  neighbour_count.assign(nlocal, 0);
  const int nthreads = comm->nthreads;
  threads.resize(nthreads);
  sph_parallel(nthreads, [&](int tid) {
    int from, to;
    sph_thread_slice((int) with_ghost.size(), nthreads, tid, from, to);
    PointScratch &scratch = threads[tid];
    if (tid > 0) {
      scratch.neighbours.clear();
      scratch.weights.clear();
    }
    interpolate_slice<DIM, KERNEL>(from, to, ghost, how, kernel, scratch.support, scratch.basis,
                                   tid ? scratch.neighbours : neighbours,
                                   tid ? scratch.weights : weights);
  });
  for (int t = 1; t < nthreads; t++) {
    neighbours.insert(neighbours.end(), threads[t].neighbours.begin(), threads[t].neighbours.end());
    weights.insert(weights.end(), threads[t].weights.begin(), threads[t].weights.end());
  }
  first_neighbour[0] = 0;
  for (int i = 0; i < nlocal; i++) first_neighbour[i + 1] = first_neighbour[i] + neighbour_count[i];
}

/* the ghost points of the atoms with_ghost[from, to), with the candidates
   inside the support in 'support' (and the quadratic fit's basis of each in
   'basis') and, where heat is returned, the Shepard
   neighbours and weights appended to 'near' and 'near_weights' (and their
   count per atom in neighbour_count) */

template <int DIM, int KERNEL>
void SPHMirror::interpolate_slice(int from, int to, std::vector<double> &ghost,
                                  std::vector<int> &how, const sphk_kernel &kernel,
                                  SPHSupport &support, std::vector<double> &basis,
                                  std::vector<int> &near, std::vector<double> &near_weights)
{
  const double h = kernel.h;
  const double cutsq = cutoff * cutoff;
  // -(dW/dr) / r = this f'(q) / q, without a division
  const double minus_dwdr_r_scale = -kernel.dw_scale * kernel.inv_h;
  // local copies: the stores into the support's int and double arrays could
  // alias the members, which the loops would then read again per candidate
  const int axis = inlet_axis;
  const int *const candidate = candidates.data();
  const double *const candidate_x = medium_x.data();
  const double *const volume_of = medium_volume.data();
  const double *const value_of = medium_values.data();
  const bool heat_back = returns_heat;

  for (int n_ghost = from; n_ghost < to; n_ghost++) {
    const int i = with_ghost[n_ghost];
    const double *const g = &ghost_at[3 * (size_t) i];
    const int first = first_candidate[i], last = first_candidate[i + 1];
    // the candidates inside the support (sph_support.h)
    support.fit(last - first);
    int *const m_in = support.index;
    double *const d_in = support.del;
    double *const rsq_in = support.rsq;
    double *const w_in = support.a;
    double *const g_in = support.b;
    const double side =
        (axis < 0) ? 0.0 : FixSPHInletTemperature::periodic_cell(domain, g[axis], axis);
    // candidate m's separation from the ghost point, d = x_m - g
    auto separation = [&](int m, double d[3]) {
      const double *const x_m = &candidate_x[3 * (size_t) m];
      for (int c = 0; c < 3; c++) d[c] = x_m[c] - g[c];
    };
    auto inside = [&](int m, double rsq) {
      return rsq < cutsq &&
          (axis < 0 ||
           FixSPHInletTemperature::periodic_cell(domain, candidate_x[3 * (size_t) m + axis],
                                                 axis) == side);
    };

    // the candidates inside the support, then their kernel values: storing
    // every candidate and keeping those inside (no branch) was faster than
    // summing each as it comes (a mispredicted branch, and the square root's
    // latency in the chain)
    int nin = 0;
    for (int n = first; n < last; n++) {
      const int m = candidate[n];
      double d[3];
      separation(m, d);
      const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      m_in[nin] = m;
      rsq_in[nin] = rsq;
      nin += inside(m, rsq);
    }
    for (int k = 0; k < nin; k++) {
      const double q = sqrt(rsq_in[k]) * kernel.inv_h;
      w_in[k] = kernel.w_scale * sphk_f(KERNEL, q);
      g_in[k] = minus_dwdr_r_scale * sphk_df_over_q(KERNEL, q);
    }

    if (field == TEMPERATURE) {
      // the temperature: first-order corrected
      sphi_point point;
      sphi_begin(&point, DIM);
      for (int k = 0; k < nin; k++) {
        const int m = m_in[k];
        // the separation again (the gather has just read the position):
        // cheaper than storing it there
        double d[3];
        separation(m, d);
        sphi_add_g(&point, d, w_in[k], g_in[k], volume_of[m], value_of[m]);
      }
      if (heat_back) {
        // the Shepard weights that return the wall's heat to the medium
        const size_t start = near_weights.size();
        near.resize(start + nin);
        near_weights.resize(start + nin);
        int *const near_atom = near.data() + start;
        double *const near_weight = near_weights.data() + start;
        double shepard = 0.0;
        for (int k = 0; k < nin; k++) {
          const int m = m_in[k];
          near_atom[k] = medium_atoms[m];
          near_weight[k] = w_in[k] * volume_of[m];
          shepard += near_weight[k];
        }
        for (int k = 0; k < nin; k++) near_weight[k] /= shepard;
        neighbour_count[i] = nin;
      }
      how[i] = sphi_solve(&point, h, &ghost[i], nullptr);
      continue;
    }

    for (int k = 0; k < nin; k++) separation(m_in[k], &d_in[3 * k]);
    // the velocity: its curvature matters to the wall's viscous force, so
    // a quadratic fit (value and gradient of a quadratic field exact), or
    // where the neighbourhood is too thin for one, the first-order value
    // alone (how SPHI_SHEPARD)
    double *const out = &ghost[12 * (size_t) i];
    sphi_quadratic fit;
    sphi_quadratic_begin(&fit, DIM, DIM, h);
    // every neighbour's basis first (sph_interpolation.h says why)
    const int nterms = fit.nterms;
    basis.resize((size_t) nterms * nin);
    for (int k = 0; k < nin; k++)
      sphi_quadratic_basis(&fit, &d_in[3 * k], &basis[(size_t) nterms * k]);
    for (int k = 0; k < nin; k++) {
      const int m = m_in[k];
      sphi_quadratic_add_basis(&fit, &basis[(size_t) nterms * k], w_in[k] * volume_of[m],
                               &value_of[3 * (size_t) m]);
    }
    how[i] = sphi_quadratic_solve(&fit, out, out + 3);
    if (how[i] == SPHI_CORRECTED) continue;
    for (int c = 0; c < DIM; c++) {
      sphi_point point;
      sphi_begin(&point, DIM);
      for (int k = 0; k < nin; k++) {
        const int m = m_in[k];
        sphi_add_g(&point, &d_in[3 * k], w_in[k], g_in[k], volume_of[m],
                   value_of[3 * (size_t) m + c]);
      }
      how[i] = (sphi_solve(&point, h, &out[c], nullptr) == SPHI_NONE) ? SPHI_NONE : SPHI_SHEPARD;
    }
  }
}

/* ----------------------------------------------------------------------
   the owned wall atoms next to a wall that holds a temperature
------------------------------------------------------------------------- */

void SPHMirror::find_junctions()
{
  double *const *const x = atom->x;
  const double cutsq = cutoff * cutoff;
  junction.assign(atom->nlocal, 0);
  if (!held_walls) return;
  for (int i = 0; i < atom->nlocal; i++)
    for (int n = first_held[i]; n < first_held[i + 1]; n++) {
      const int j = held_atoms[held_near[n]];
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < cutsq) {
        junction[i] = 1;
        break;
      }
    }
}

/* ---------------------------------------------------------------------- */

void SPHMirror::return_heat(const std::vector<double> &rate, Fix *owner)
{
  const SPHParticles particles(atom);
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  returned.assign(nall, 0.0);
  for (int i = 0; i < nlocal; i++)
    if (!junction[i])
      for (int n = first_neighbour[i]; n < first_neighbour[i + 1]; n++)
        returned[neighbours[n]] += weights[n] * rate[i];
  SPHCompat::reverse_comm(comm, owner);
  double *const desph = atom->desph;
  for (int j = 0; j < nlocal; j++)
    if (returned[j] != 0.0)
      desph[j] += returned[j] / particles.mass(j) * particles.esph_per_specific(j);
}

int SPHMirror::pack_reverse_comm(int n, int first, double *buf)
{
  return SPHCommStage().flat(returned.data(), 1).pack(n, first, buf);
}

void SPHMirror::unpack_reverse_comm(int n, int *list, double *buf)
{
  SPHCommStage().flat(returned.data(), 1).unpack_reverse(n, list, buf);
}
