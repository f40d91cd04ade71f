/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#include "sph_comm_stage.h"

#include <algorithm>

using namespace LAMMPS_NS;

SPHCommStage &SPHCommStage::add(const Field &field)
{
  // a style's own stage lists: more fields is a bug in the style
  if (nfields < MAX_FIELDS) fields[nfields++] = field;
  return *this;
}

SPHCommStage &SPHCommStage::rows(double **array, int width, int offset, Combine combine)
{
  return add({array, nullptr, width, offset, combine});
}

SPHCommStage &SPHCommStage::flat(double *array, int width, Combine combine)
{
  return add({nullptr, array, width, 0, combine});
}

int SPHCommStage::size() const
{
  int n = 0;
  for (int f = 0; f < nfields; f++) n += fields[f].width;
  return n;
}

// Values travel field after field (all atoms' values of the first field,
// then of the second): the loops over atoms stay tight, and pack and unpack
// agree on the order.

// one field's values of n atoms; WIDTH > 0: the width known to the compiler
// (the common ones), so that the copies of an atom's values unroll
template <int WIDTH, class Field, class AtomOf, class Visit>
static void walk_field(const Field &field, int n, AtomOf atom_of, Visit visit, int &m)
{
  const int width = WIDTH ? WIDTH : field.width;
  if (field.rows)
    for (int k = 0; k < n; k++, m += width)
      visit(field, field.rows[atom_of(k)] + field.offset, m, width);
  else
    for (int k = 0; k < n; k++, m += width)
      visit(field, field.flat + (long) atom_of(k) * width, m, width);
}

template <class AtomOf, class Visit>
void SPHCommStage::walk(int n, AtomOf atom_of, Visit visit) const
{
  int m = 0;
  for (int f = 0; f < nfields; f++) {
    const Field &field = fields[f];
    if (field.width == 1)
      walk_field<1>(field, n, atom_of, visit, m);
    else if (field.width == 3)
      walk_field<3>(field, n, atom_of, visit, m);
    else if (field.width == 6)
      walk_field<6>(field, n, atom_of, visit, m);
    else
      walk_field<0>(field, n, atom_of, visit, m);
  }
}

int SPHCommStage::pack(int n, const int *list, double *buf) const
{
  walk(
      n,
      [list](int k) {
        return list[k];
      },
      [buf](const Field &, const double *values, int m, int width) {
        for (int c = 0; c < width; c++) buf[m + c] = values[c];
      });
  return n * size();
}

int SPHCommStage::pack(int n, int first, double *buf) const
{
  walk(
      n,
      [first](int k) {
        return first + k;
      },
      [buf](const Field &, const double *values, int m, int width) {
        for (int c = 0; c < width; c++) buf[m + c] = values[c];
      });
  return n * size();
}

void SPHCommStage::unpack_forward(int n, int first, const double *buf) const
{
  walk(
      n,
      [first](int k) {
        return first + k;
      },
      [buf](const Field &, double *values, int m, int width) {
        for (int c = 0; c < width; c++) values[c] = buf[m + c];
      });
}

void SPHCommStage::unpack_reverse(int n, const int *list, const double *buf) const
{
  walk(
      n,
      [list](int k) {
        return list[k];
      },
      [buf](const Field &field, double *values, int m, int width) {
        if (field.combine == SUM)
          for (int c = 0; c < width; c++) values[c] += buf[m + c];
        else if (field.combine == MAX)
          for (int c = 0; c < width; c++) values[c] = std::max(values[c], buf[m + c]);
        else
          for (int c = 0; c < width; c++) values[c] = std::min(values[c], buf[m + c]);
      });
}
