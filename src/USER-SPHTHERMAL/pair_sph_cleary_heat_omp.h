/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat/omp: the pair loop of sph/cleary/heat split over
   OpenMP threads (LAMMPS's OPENMP package: package omp, -sf omp). Built
   only where LAMMPS has the OPENMP package.
------------------------------------------------------------------------- */

#if __has_include("thr_omp.h")

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/cleary/heat/omp,PairSPHClearyHeatOMP);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_CLEARY_HEAT_OMP_H
#define LMP_PAIR_SPH_CLEARY_HEAT_OMP_H

#include "pair_sph_cleary_heat.h"
#include "thr_omp.h"

namespace LAMMPS_NS {

class PairSPHClearyHeatOMP : public PairSPHClearyHeat, public ThrOMP {
 public:
  PairSPHClearyHeatOMP(class LAMMPS *);
  void compute(int, int) override;
  double memory_usage() override;
};

}    // namespace LAMMPS_NS

#endif
#endif
#endif
