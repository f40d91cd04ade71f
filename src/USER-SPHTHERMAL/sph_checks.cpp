/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   The checks every style of the package shares (sph_checks.h).
------------------------------------------------------------------------- */

#include "sph_checks.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "modify.h"
#include "sph_hub.h"
#include "update.h"
#include "utils.h"

#include <algorithm>

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
// the atoms particles() last found sound: a style that asks again in the same
// step, of the same arrays, costs nothing (one pass per step, whichever of the
// walls and pairs asks first); set-up always checks
struct CheckedState {
  const LAMMPS *lmp = nullptr;
  bigint step = -1;
  const double *x = nullptr;
  int nlocal = -1;
  int needs = 0;
};
CheckedState last_sound;
}    // namespace

/* ---------------------------------------------------------------------- */

void SPHCheck::atom_state(LAMMPS *lmp, const char *file, int line, const char *who, int groupbit,
                          int needs)
{
  Atom *atom = lmp->atom;
  const int *const mask = atom->mask;
  const int nlocal = atom->nlocal;
  // the first bad quantity of an atom: 0 none, 1 rho, 2 cv, 3 esph
  FirstBad bad;    // quantity, type, value
  for (int i = 0; i < nlocal; i++) {
    if (groupbit && !(mask[i] & groupbit)) continue;
    int quantity = 0;
    double value = 0.0;
    if ((needs & RHO) && !(std::isfinite(atom->rho[i]) && atom->rho[i] > 0.0))
      quantity = 1, value = atom->rho[i];
    else if ((needs & CV) && !(std::isfinite(atom->cv[i]) && atom->cv[i] > 0.0))
      quantity = 2, value = atom->cv[i];
    else if ((needs & ESPH) && !std::isfinite(atom->esph[i]))
      quantity = 3, value = atom->esph[i];
    if (quantity) bad.consider(atom->tag[i], quantity, atom->type[i], value);
  }
  if (!bad.agree(lmp)) return;
  static const char *const names[] = {"", "rho", "cv", "esph"};
  static const char *const wants[] = {"", "finite and > 0", "finite and > 0", "finite"};
  const int quantity = (int) bad.info[0];
  lmp->error->all(file, line, "{}: {} of atom {} (type {}) is {}; it must be {}", who,
                  names[quantity], bad.tag, (int) bad.info[1], bad.info[2], wants[quantity]);
}

/* ---------------------------------------------------------------------- */

void SPHCheck::particles(LAMMPS *lmp, const char *file, int line, const char *who, int needs)
{
  Atom *atom = lmp->atom;
  const int nlocal = atom->nlocal;
  if (nlocal == 0) return;
  const double *const x = atom->x[0];
  const double *const v = atom->v[0];
  const double *const rho = (needs & RHO) ? atom->rho : nullptr;
  const double *const esph = (needs & ESPH) ? atom->esph : nullptr;
  const bigint step = lmp->update->ntimestep;
  if (!lmp->update->setupflag && last_sound.lmp == lmp && last_sound.step == step &&
      last_sound.x == x && last_sound.nlocal == nlocal && (last_sound.needs & needs) == needs)
    return;

  // the fast pass, every step: a NaN or inf anywhere makes a sum non-finite,
  // and the smallest rho must be > 0; x and v are each one run of 3 nlocal
  // values, summed in four independent partial sums (which the compiler
  // makes vector adds); the slow pass below only once something is wrong
  const int n3 = 3 * nlocal;
  double sum[4] = {0.0, 0.0, 0.0, 0.0}, low[4] = {INFINITY, INFINITY, INFINITY, INFINITY};
  int k = 0;
  for (; k + 4 <= n3; k += 4)
    for (int l = 0; l < 4; l++) sum[l] += x[k + l] + v[k + l];
  for (; k < n3; k++) sum[0] += x[k] + v[k];
  if (rho) {
    int i = 0;
    for (; i + 4 <= nlocal; i += 4)
      for (int l = 0; l < 4; l++) {
        sum[l] += rho[i + l];
        low[l] = rho[i + l] < low[l] ? rho[i + l] : low[l];
      }
    for (; i < nlocal; i++) {
      sum[0] += rho[i];
      low[0] = rho[i] < low[0] ? rho[i] : low[0];
    }
  }
  if (esph) {
    int i = 0;
    for (; i + 4 <= nlocal; i += 4)
      for (int l = 0; l < 4; l++) sum[l] += esph[i + l];
    for (; i < nlocal; i++) sum[0] += esph[i];
  }
  // a NaN rho fails 'low > 0' as well as the sum
  if (std::isfinite(sum[0] + sum[1] + sum[2] + sum[3]) &&
      (!rho || (low[0] > 0.0 && low[1] > 0.0 && low[2] > 0.0 && low[3] > 0.0))) {
    // (field by field: LAMMPS 29Sep2021 builds as C++11, where a struct
    // with member initialisers is no aggregate)
    last_sound.lmp = lmp;
    last_sound.step = step;
    last_sound.x = x;
    last_sound.nlocal = nlocal;
    last_sound.needs = needs;
    return;
  }

  for (int i = 0; i < nlocal; i++) {
    const char *quantity = nullptr;
    double value = 0.0;
    if (!std::isfinite(x[3 * i] + x[3 * i + 1] + x[3 * i + 2]))
      quantity = "position", value = x[3 * i] + x[3 * i + 1] + x[3 * i + 2];
    else if (!std::isfinite(v[3 * i] + v[3 * i + 1] + v[3 * i + 2]))
      quantity = "velocity", value = v[3 * i] + v[3 * i + 1] + v[3 * i + 2];
    else if (rho && !(std::isfinite(rho[i]) && rho[i] > 0.0))
      quantity = "rho", value = rho[i];
    else if (esph && !std::isfinite(esph[i]))
      quantity = "esph", value = esph[i];
    if (!quantity) continue;
    stop(lmp, file, line,
         fmt::format("{}: {} of atom {} (type {}) is {} at step {}{}", who, quantity, atom->tag[i],
                     atom->type[i], value, lmp->update->ntimestep,
                     strcmp(quantity, "rho") == 0 ? "; it must be finite and > 0" : ""));
  }
}

/* ---------------------------------------------------------------------- */

int SPHCheck::first_nonfinite(const double *values, int n)
{
  for (int i = 0; i < n; i++)
    if (!std::isfinite(values[i])) return i;
  return -1;
}

int SPHCheck::first_nonfinite3(double *const *values, int n)
{
  for (int i = 0; i < n; i++)
    if (!std::isfinite(values[i][0] + values[i][1] + values[i][2])) return i;
  return -1;
}

/* ---------------------------------------------------------------------- */

void SPHCheck::stop(LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  // one rank: a clean stop with the output flushed
  if (lmp->comm->nprocs == 1) lmp->error->all(file, line, message);
  // error->one prints on rank 0 only and may abort before stdout is
  // flushed: stderr is unbuffered
  fmt::print(stderr, "ERROR on proc {}: {}\n", lmp->comm->me, message);
  lmp->error->one(file, line, message);
}

void SPHCheck::nonfinite(LAMMPS *lmp, const char *file, int line, const char *who,
                         const char *quantity, int i, double value, const std::string &why)
{
  stop(lmp, file, line,
       fmt::format("{}: {} of atom {} (type {}) is {} at step {}{}{}", who, quantity,
                   lmp->atom->tag[i], lmp->atom->type[i], value, lmp->update->ntimestep,
                   why.empty() ? "" : ": ", why));
}

/* ---------------------------------------------------------------------- */

int SPHCheck::groups_overlap(LAMMPS *lmp, int groupbit1, int groupbit2)
{
  const int *const mask = lmp->atom->mask;
  int local = 0, any;
  for (int i = 0; i < lmp->atom->nlocal && !local; i++)
    if ((mask[i] & groupbit1) && (mask[i] & groupbit2)) local = 1;
  MPI_Allreduce(&local, &any, 1, MPI_INT, MPI_MAX, lmp->world);
  return any;
}

bigint SPHCheck::group_count(LAMMPS *lmp, int groupbit)
{
  const int *const mask = lmp->atom->mask;
  bigint local = 0, all;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (mask[i] & groupbit) local++;
  MPI_Allreduce(&local, &all, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  return all;
}

std::vector<int> SPHCheck::group_types(LAMMPS *lmp, int groupbit)
{
  const int ntypes = lmp->atom->ntypes;
  std::vector<int> local(ntypes + 1, 0), present(ntypes + 1, 0);
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if (lmp->atom->mask[i] & groupbit) local[lmp->atom->type[i]] = 1;
  MPI_Allreduce(local.data(), present.data(), ntypes + 1, MPI_INT, MPI_MAX, lmp->world);
  return present;
}

void SPHCheck::warn_empty(LAMMPS *lmp, const char *file, int line, const char *who, int igroup)
{
  if (group_count(lmp, lmp->group->bitmask[igroup]) == 0 && lmp->comm->me == 0)
    lmp->error->warning(file, line, "{}: group {} has no atoms, so its values are all 0", who,
                        lmp->group->names[igroup]);
}

/* ---------------------------------------------------------------------- */

// "SPTH": no setting a head-less file starts with (a kernel or form index)
static constexpr int RESTART_TAG = 0x53505448;

void SPHCheck::write_restart_head(FILE *fp, int version)
{
  const int head[2] = {RESTART_TAG, version};
  fwrite(head, sizeof(int), 2, fp);
}

// the errors for a head read as (tag, version); collective
static void check_restart_head(LAMMPS *lmp, const char *file, int line, const int *head,
                               const std::string &who, const char *what, int version)
{
  if (head[0] != RESTART_TAG)
    lmp->error->all(file, line,
                    "{}: the restart file's {} have no version head: it was written by a "
                    "USER-SPHTHERMAL older than this one, whose layout it cannot read; "
                    "start from a data file (write_data) of that run instead",
                    who, what);
  if (head[1] != version)
    lmp->error->all(file, line,
                    "{}: the restart file's {} are of version {}, this build reads "
                    "version {}; start from a data file (write_data) of that run instead",
                    who, what, head[1], version);
}

void SPHCheck::read_restart_head(LAMMPS *lmp, const char *file, int line, FILE *fp, const char *who,
                                 int version)
{
  int head[2] = {0, 0};
  if (lmp->comm->me == 0) {
    // a head-less file's first setting is read as the tag; it cannot match
    utils::sfread(FLERR, head, sizeof(int), 1, fp, nullptr, lmp->error);
    if (head[0] == RESTART_TAG)
      utils::sfread(FLERR, head + 1, sizeof(int), 1, fp, nullptr, lmp->error);
  }
  MPI_Bcast(head, 2, MPI_INT, 0, lmp->world);
  check_restart_head(lmp, file, line, head, who, "settings", version);
}

void SPHCheck::write_restart_state(FILE *fp, int version, const double *state, int n)
{
  const int size = 2 * sizeof(int) + n * sizeof(double);
  fwrite(&size, sizeof(int), 1, fp);
  write_restart_head(fp, version);
  fwrite(state, sizeof(double), n, fp);
}

const double *SPHCheck::read_restart_state(LAMMPS *lmp, const char *file, int line, Fix *fix,
                                           const char *buf, int version)
{
  // every rank holds the same block, so the check needs no communication
  int head[2];
  memcpy(head, buf, sizeof(head));
  check_restart_head(lmp, file, line, head, std::string("Fix ") + fix->style + " " + fix->id,
                     "state data", version);
  return (const double *) (buf + sizeof(head));
}

void SPHCheck::pack_name(std::vector<double> &state, const std::string &name)
{
  state.push_back((double) name.size());
  for (const char c : name) state.push_back((double) (unsigned char) c);
}

std::string SPHCheck::unpack_name(const double *state, int &at)
{
  const int length = (int) state[at++];
  std::string name;
  for (int k = 0; k < length; k++) name += (char) (int) state[at++];
  return name;
}

/* ---------------------------------------------------------------------- */

void SPHCheck::group_of_kind(LAMMPS *lmp, const char *file, int line, Fix *fix,
                             const std::vector<Fix *> &exclusive, bool every_ok, bool moving_ok)
{
  Error *error = lmp->error;
  const char *group = lmp->group->names[fix->igroup];
  const bigint count = group_count(lmp, fix->groupbit);
  if (count == 0)
    error->all(file, line, "Fix {} (style {}): group {} has no atoms", fix->id, fix->style, group);
  if (!every_ok && count == lmp->atom->natoms)
    error->all(
        file, line,
        "Fix {} (style {}): group {} holds every atom, so no particle is left for the medium "
        "it bounds",
        fix->id, fix->style, group);

  Modify *modify = lmp->modify;
  for (int i = 0; i < modify->nfix; i++) {
    Fix *other = modify->fix[i];
    if (other == fix) continue;
    const bool clash = std::find(exclusive.begin(), exclusive.end(), other) != exclusive.end();
    if (clash && groups_overlap(lmp, fix->groupbit, other->groupbit))
      error->all(file, line,
                 "Fix {} (style {}) and fix {} (style {}) share atoms of groups {} and {}: a "
                 "particle can be one of them only",
                 fix->id, fix->style, other->id, other->style, group,
                 lmp->group->names[other->igroup]);
    if (SPHHub(lmp).fix_sph_moves(other) && groups_overlap(lmp, fix->groupbit, other->groupbit)) {
      if (!moving_ok)
        error->all(file, line,
                   "Fix {} (style {}): atoms of group {} are also moved by fix {} (style sph); "
                   "integrate them with fix sph/stationary, or not at all",
                   fix->id, fix->style, group, other->id);
      else if (lmp->comm->me == 0)
        error->warning(file, line,
                       "Fix {} (style {}): atoms of group {} are also moved by fix {} (style sph)",
                       fix->id, fix->style, group, other->id);
    }
  }
}

/* ----------------------------------------------------------------------
   the lowest bad ID over the ranks; its owner (IDs are unique) tells
   every rank what it recorded
------------------------------------------------------------------------- */

int SPHCheck::FirstBad::agree(LAMMPS *lmp)
{
  tagint first = MAXTAGINT;
  MPI_Allreduce(&tag, &first, 1, MPI_LMP_TAGINT, MPI_MIN, lmp->world);
  if (first == MAXTAGINT) return 0;
  double mine[4] = {0.0, 0.0, 0.0, 0.0};
  if (tag == first)
    for (int k = 0; k < 4; k++) mine[k] = info[k];
  MPI_Allreduce(mine, info, 4, MPI_DOUBLE, MPI_SUM, lmp->world);
  tag = first;
  return 1;
}
