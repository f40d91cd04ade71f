/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_INTERFACE_DISTANCE_H
#define LMP_SPH_INTERFACE_DISTANCE_H

#include "pointers.h"

#include <string>

namespace LAMMPS_NS {

class NeighList;
class SPHExchange;
class SPHSupportPairs;

// 'mean interface' of pair sph/cleary/heat: each atom's distance from the
// interface between materials of different conductivity laws, estimated
// from the pairs of the support or given per atom (fix property/atom),
// which sphc_interface_conductance() of sph_conduction.h turns into a
// pair's series conductance.
class SPHInterfaceDistance : protected Pointers {
 public:
  // no atom of another material within the support
  static constexpr double NONE = -1.0;

  SPHInterfaceDistance(LAMMPS *lmp, const std::string &given_name);
  ~SPHInterfaceDistance() override;

  // at the pair's init: per type pair, 1 where the two types differ in
  // conductivity law (the pair crosses an interface); the per-atom property
  // of the given distances, if one was named, looked up
  void init(int **crossing_types);
  // per atom (owned and ghost): 1 for the atoms with an atom of another
  // material within the support (of squared radius cutsq), the only ones
  // whose distance is estimated and whose pairs the estimate reads
  void mark(const NeighList *list, double cutsq, SPHExchange &exchange);
  const double *near() const { return near_of; }
  // the distances for this step's pairs (volume: m / rho of every owned and
  // ghost atom; w_self: W(0); h the kernel's smoothing length)
  void refresh(const SPHSupportPairs &pairs, const double *volume, double w_self, double h,
               SPHExchange &exchange);
  // per atom (owned and ghost): the distance, NONE where no atom of another
  // material is within the support; room from init on
  const double *distances() const { return distance; }
  // at a run's setup, on every rank: the log line
  void report() const;
  double memory_usage() const { return 17.0 * nmax * sizeof(double); }

 private:
  int **crossing;
  // 'distance d_name': the property's name and its index in atom->dvector
  // (-1: estimated)
  std::string given_name;
  int given_index;
  int nmax;
  double *distance, *near_of;
  double **moment, **vector, **normal, **sum;    // work arrays of the estimate
  void grow();
  void release();
  void take_given(SPHExchange &exchange);
};

}    // namespace LAMMPS_NS

#endif
