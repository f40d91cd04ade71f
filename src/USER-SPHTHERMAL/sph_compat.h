/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

// The one place where the package meets the differences between the LAMMPS
// versions it supports: 29Sep2021 (Debian 12) and 4Feb2025 (Debian 13).
// Every style calls these instead of the version's own API, so one source
// tree compiles against both, as a plugin or in-tree (CMake or make).
//
// The version is recognised by a header: platform.h appeared after
// 29Sep2021 (27Oct2021), together with the neighbour-request and
// communication APIs used below. SPHTHERMAL_LAMMPS_NEW_API may also be
// given on the command line (1 or 0) to override the test.

#ifndef LMP_SPH_COMPAT_H
#define LMP_SPH_COMPAT_H

#ifndef SPHTHERMAL_LAMMPS_NEW_API
#if defined(__has_include)
#if __has_include("platform.h")
#define SPHTHERMAL_LAMMPS_NEW_API 1
#else
#define SPHTHERMAL_LAMMPS_NEW_API 0
#endif
#else
#error "USER-SPHTHERMAL: define SPHTHERMAL_LAMMPS_NEW_API (1 from LAMMPS 27Oct2021 on, 0 before)"
#endif
#endif

#include "atom.h"
#include "comm.h"
#include "compute.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair.h"
#include "region.h"
#include "utils.h"
#if SPHTHERMAL_LAMMPS_NEW_API
#include "platform.h"
#endif

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace SPHCompat {

  // ------------------------------------------------ neighbour requests
  // 'instance' is the style's instance_me (protected, so passed by the
  // caller), which only 29Sep2021 needs

  // a full list, built every step, for a fix; with a cutoff > 0, of every
  // pair closer than it (whatever the pair styles' cutoffs of the types)
  inline void request_full_list(Neighbor *neighbor, Fix *fix, int instance, double cutoff = 0.0)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    (void) instance;
    auto *request = neighbor->add_request(fix, NeighConst::REQ_FULL);
    if (cutoff > 0.0) request->set_cutoff(cutoff);
#else
    const int irequest = neighbor->request(fix, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    if (cutoff > 0.0) {
      neighbor->requests[irequest]->cut = 1;
      neighbor->requests[irequest]->cutoff = cutoff;
    }
#endif
  }

  // ------------------------------------------------ granular heat
  // the per-atom temperature and heat flow of LAMMPS's granular heat model
  // (fix property/atom temperature heatflow, integrated by fix heat/flow);
  // nullptr where the atoms have none, and always in 29Sep2021, which has
  // no such model
  inline double *granular_temperature(Atom *atom)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return atom->temperature_flag ? atom->temperature : nullptr;
#else
    (void) atom;
    return nullptr;
#endif
  }
  inline double *granular_heatflow(Atom *atom)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return atom->heatflow_flag ? atom->heatflow : nullptr;
#else
    (void) atom;
    return nullptr;
#endif
  }
  // whether this LAMMPS has the granular heat model
  inline bool has_granular_heat()
  {
    return SPHTHERMAL_LAMMPS_NEW_API != 0;
  }

  // a half list (newton as the pair styles have it), built every step, for a fix
  inline void request_half_list(Neighbor *neighbor, Fix *fix, int instance)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    (void) instance;
    neighbor->add_request(fix);
#else
    const int irequest = neighbor->request(fix, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->fix = 1;
#endif
  }

  // a full list, built when the compute asks (occasional), for a compute
  inline void request_occasional_full_list(Neighbor *neighbor, Compute *compute, int instance)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    (void) instance;
    neighbor->add_request(compute, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
#else
    const int irequest = neighbor->request(compute, instance);
    neighbor->requests[irequest]->pair = 0;
    neighbor->requests[irequest]->compute = 1;
    neighbor->requests[irequest]->half = 0;
    neighbor->requests[irequest]->full = 1;
    neighbor->requests[irequest]->occasional = 1;
#endif
  }

  // the default (half) list of a pair style
  inline void request_half_list(Neighbor *neighbor, Pair *pair, int instance)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    (void) instance;
    neighbor->add_request(pair);
#else
    neighbor->request(pair, instance);
#endif
  }

  // ----------------------------------------------------- communication
  inline void forward_comm(Comm *comm, Pair *pair)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    comm->forward_comm(pair);
#else
    comm->forward_comm_pair(pair);
#endif
  }

  inline void forward_comm(Comm *comm, Fix *fix)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    comm->forward_comm(fix);
#else
    comm->forward_comm_fix(fix);
#endif
  }

  inline void reverse_comm(Comm *comm, Pair *pair)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    comm->reverse_comm(pair);
#else
    comm->reverse_comm_pair(pair);
#endif
  }

  inline void reverse_comm(Comm *comm, Fix *fix)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    comm->reverse_comm(fix);
#else
    comm->reverse_comm_fix(fix);
#endif
  }

  // ------------------------------------------------------------ regions
  // the region of an ID, nullptr when there is none
  inline Region *find_region(Domain *domain, const std::string &id)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return domain->get_region_by_id(id);
#else
    const int iregion = domain->find_region(id);
    return (iregion < 0) ? nullptr : domain->regions[iregion];
#endif
  }

  // -------------------------------------------------------- file paths
  inline std::string path_basename(const std::string &path)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return platform::path_basename(path);
#else
    return utils::path_basename(path);
#endif
  }

  inline std::string path_dirname(const std::string &path)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return platform::path_dirname(path);
#else
    return utils::path_dirname(path);
#endif
  }

  inline std::string path_join(const std::string &a, const std::string &b)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return platform::path_join(a, b);
#else
    return utils::path_join(a, b);
#endif
  }

  inline bool file_is_readable(const std::string &path)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    return platform::file_is_readable(path);
#else
    return utils::file_is_readable(path);
#endif
  }

  // --------------------------------------------------- yes/no keywords
  // the words newer LAMMPS accepts for a logical value (utils::logical):
  // yes/no, on/off, true/false, 1/0; on both versions, and with an error
  // that names the command and the keyword (utils::logical names neither)
  inline bool yes_no(Error *error, const char *file, int line, const std::string &command,
                     const char *keyword, const char *value)
  {
    for (const char *word : {"yes", "on", "true", "1"})
      if (strcmp(value, word) == 0) return true;
    for (const char *word : {"no", "off", "false", "0"})
      if (strcmp(value, word) == 0) return false;
    error->all(file, line, "Illegal {} command: {} '{}' is not yes or no", command, keyword, value);
    return false;
  }

  // ------------------------------------------ occasional neighbour lists
  // build a compute's occasional list for the atoms of now: 29Sep2021 skips
  // the build when the list was made on the step of the last reneighboring
  // (also before atoms were deleted between runs, leaving indices of atoms
  // that are gone), unless asked as fix bond/create does; 4Feb2025's
  // reneighboring marks every occasional list as stale itself
  inline void build_occasional(Neighbor *neighbor, NeighList *list)
  {
#if SPHTHERMAL_LAMMPS_NEW_API
    neighbor->build_one(list);
#else
    neighbor->build_one(list, 1);
#endif
  }

  // ------------------------------------------------- finite numbers
  // a number of the command line that must be finite: LAMMPS 4Feb2025's
  // utils::numeric refuses an overflowing literal (1e400), 29Sep2021's
  // returns inf; both errors name the caller's line
  inline double finite_numeric(LAMMPS *lmp, const char *file, int line, const std::string &command,
                               const char *what, const char *value)
  {
    const double number = utils::numeric(file, line, value, false, lmp);
    if (!std::isfinite(number))
      lmp->error->all(file, line, "Illegal {} command: {} {} is not finite", command, what, value);
    return number;
  }

  // a direction along a box axis, '+x' .. '-z' (e.g. a flow's): its axis
  // (0, 1, 2) and sign (+1, -1); z refused in a 2d simulation. 'what' names
  // the argument, 'meaning' says what the direction is, in the message
  inline void signed_axis(LAMMPS *lmp, const char *file, int line, const std::string &command,
                          const char *what, const char *value, const char *meaning, int &axis,
                          int &sign)
  {
    if (strlen(value) != 2 || (value[0] != '+' && value[0] != '-') || value[1] < 'x' ||
        value[1] > 'z')
      lmp->error->all(file, line,
                      "Illegal {} command: {} '{}' must be one of +x -x +y -y +z -z ({})", command,
                      what, value, meaning);
    sign = (value[0] == '+') ? 1 : -1;
    axis = value[1] - 'x';
    if (lmp->domain->dimension == 2 && axis == 2)
      lmp->error->all(file, line, "Illegal {} command: {} along z in a 2d simulation", command,
                      what);
  }

}    // namespace SPHCompat
}    // namespace LAMMPS_NS

#endif
