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

int SPHCommStage::pack_atom(int i, double *buf) const
{
  int m = 0;
  for (int f = 0; f < nfields; f++) {
    const double *const values = fields[f].values(i);
    for (int c = 0; c < fields[f].width; c++) buf[m++] = values[c];
  }
  return m;
}

int SPHCommStage::pack(int n, const int *list, double *buf) const
{
  int m = 0;
  for (int k = 0; k < n; k++) m += pack_atom(list[k], buf + m);
  return m;
}

int SPHCommStage::pack(int n, int first, double *buf) const
{
  int m = 0;
  for (int i = first; i < first + n; i++) m += pack_atom(i, buf + m);
  return m;
}

void SPHCommStage::unpack_forward(int n, int first, const double *buf) const
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (int f = 0; f < nfields; f++) {
      double *const values = fields[f].values(i);
      for (int c = 0; c < fields[f].width; c++) values[c] = buf[m++];
    }
}

void SPHCommStage::unpack_reverse(int n, const int *list, const double *buf) const
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (int f = 0; f < nfields; f++) {
      double *const values = fields[f].values(list[k]);
      const Combine combine = fields[f].combine;
      for (int c = 0; c < fields[f].width; c++, m++) {
        if (combine == SUM)
          values[c] += buf[m];
        else if (combine == MAX)
          values[c] = std::max(values[c], buf[m]);
        else
          values[c] = std::min(values[c], buf[m]);
      }
    }
}
