/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   sph/faces: groups by a region and the faces of its bounding box
   (sph_faces.h).
------------------------------------------------------------------------- */

#include "sph_faces.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "region.h"
#include "sph_compat.h"

#include <string>
#include <vector>

using namespace LAMMPS_NS;

static const char cmd[] = "sph/faces";

namespace {

// the keywords: where an atom of the group lies relative to the region
enum Place { INSIDE, OUTSIDE, XLO, XHI, YLO, YHI, ZLO, ZHI, OTHERS, NPLACES };
const char *const place_names[NPLACES] = {"inside", "outside", "xlo", "xhi",   "ylo",
                                          "yhi",    "zlo",     "zhi", "others"};

bool is_face(int place)
{
  return place >= XLO && place <= ZHI;
}

// true when x lies beyond the face of the region's bounding box
bool beyond(const Region *region, int face, const double *x)
{
  switch (face) {
    case XLO:
      return x[0] < region->extent_xlo;
    case XHI:
      return x[0] > region->extent_xhi;
    case YLO:
      return x[1] < region->extent_ylo;
    case YHI:
      return x[1] > region->extent_yhi;
    case ZLO:
      return x[2] < region->extent_zlo;
    default:
      return x[2] > region->extent_zhi;
  }
}

double face_position(const Region *region, int face)
{
  const double where[6] = {region->extent_xlo, region->extent_xhi, region->extent_ylo,
                           region->extent_yhi, region->extent_zlo, region->extent_zhi};
  return where[face - XLO];
}

}    // namespace

/* ----------------------------------------------------------------------
   sph/faces group-ID region-ID keyword group ...: every atom of group-ID
   is added to the group of each keyword that holds for it; an atom outside
   the region goes to the first face given (in the order of the line) that
   it lies beyond, or to 'others' when it lies beyond none of them
------------------------------------------------------------------------- */

void SPHFaces::command(int narg, char **arg)
{
  if (narg < 4 || narg % 2 != 0)
    error->all(FLERR,
               "Illegal {} command: expected 'sph/faces <group> <region> <keyword> <group> ...' "
               "(keywords inside, outside, xlo, xhi, ylo, yhi, zlo, zhi, others)",
               cmd);
  const int igroup = group->find(arg[0]);
  if (igroup < 0) error->all(FLERR, "Illegal {} command: no group {}", cmd, arg[0]);
  Region *region = SPHCompat::find_region(domain, arg[1]);
  if (!region) error->all(FLERR, "Illegal {} command: no region {}", cmd, arg[1]);
  if (region->dynamic_check())
    error->all(FLERR,
               "Illegal {} command: region {} moves or changes shape: its faces are not fixed", cmd,
               arg[1]);

  std::vector<int> target(NPLACES, -1);    // the group of each keyword given, -1 if not given
  std::vector<int> faces;                  // the faces given, in the order of the line
  for (int iarg = 2; iarg < narg; iarg += 2) {
    int place = 0;
    while (place < NPLACES && arg[iarg] != std::string(place_names[place])) place++;
    if (place == NPLACES)
      error->all(FLERR,
                 "Illegal {} command: unknown keyword '{}' (inside, outside, xlo, xhi, ylo, yhi, "
                 "zlo, zhi or others)",
                 cmd, arg[iarg]);
    if (target[place] >= 0)
      error->all(FLERR, "Illegal {} command: keyword '{}' given twice", cmd, arg[iarg]);
    if ((place == ZLO || place == ZHI) && domain->dimension == 2)
      error->all(FLERR, "Illegal {} command: face {} in a 2-d simulation", cmd, arg[iarg]);
    if (is_face(place) && !region->bboxflag)
      error->all(FLERR, "Illegal {} command: region {} has no bounding box, so no face {}", cmd,
                 arg[1], arg[iarg]);
    const std::string name = arg[iarg + 1];
    if (name == "all" || !utils::is_id(name))
      error->all(FLERR,
                 "Illegal {} command: {} {}: a group must be named by letters, digits and "
                 "underscores, and not 'all'",
                 cmd, arg[iarg], name);
    target[place] = group->find_or_create(name.c_str());
    if (is_face(place)) faces.push_back(place);
  }

  // every atom of the group to the groups of the places it is in
  const int groupbit = group->bitmask[igroup];
  std::vector<bigint> local(NPLACES, 0), counts(NPLACES, 0);
  double **x = atom->x;
  int *mask = atom->mask;
  region->prematch();
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    int places[2], nplaces = 0;
    if (region->match(x[i][0], x[i][1], x[i][2]))
      places[nplaces++] = INSIDE;
    else {
      places[nplaces++] = OUTSIDE;
      int where = OTHERS;
      for (int face : faces)
        if (beyond(region, face, x[i])) {
          where = face;
          break;
        }
      places[nplaces++] = where;
    }
    for (int k = 0; k < nplaces; k++)
      if (target[places[k]] >= 0) {
        mask[i] |= group->bitmask[target[places[k]]];
        local[places[k]]++;
      }
  }
  MPI_Allreduce(local.data(), counts.data(), NPLACES, MPI_LMP_BIGINT, MPI_SUM, world);

  // each keyword must select atoms: an empty one is a mistaken region or face
  for (int place = 0; place < NPLACES; place++) {
    if (target[place] < 0) continue;
    std::string where;
    if (place == INSIDE || place == OUTSIDE)
      where = fmt::format("{} region {}", place_names[place], arg[1]);
    else if (place == OTHERS)
      where = fmt::format("outside region {} beyond none of the faces given", arg[1]);
    else
      where = fmt::format("beyond face {} of region {} (at {})", place_names[place], arg[1],
                          face_position(region, place));
    if (counts[place] == 0)
      error->all(FLERR, "{}: no atom of group {} lies {}: group {} would be empty", cmd, arg[0],
                 where, group->names[target[place]]);
    if (comm->me == 0)
      utils::logmesg(lmp, "{}: {} atoms of group {} {} added to group {}\n", cmd, counts[place],
                     arg[0], where, group->names[target[place]]);
  }
}
