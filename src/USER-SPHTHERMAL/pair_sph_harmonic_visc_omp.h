/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/harmonic/visc/omp: the pair loops of sph/harmonic/visc split
   over OpenMP threads (LAMMPS's OPENMP package: package omp, -sf omp).
   Built only where LAMMPS has the OPENMP package.
------------------------------------------------------------------------- */

#if __has_include("thr_omp.h")

#ifdef PAIR_CLASS
// clang-format off
PairStyle(sph/harmonic/visc/omp,PairSPHHarmonicViscOMP);
// clang-format on
#else

#ifndef LMP_PAIR_SPH_HARMONIC_VISC_OMP_H
#define LMP_PAIR_SPH_HARMONIC_VISC_OMP_H

#include "pair_sph_harmonic_visc.h"
#include "thr_omp.h"

namespace LAMMPS_NS {

class PairSPHHarmonicViscOMP : public PairSPHHarmonicVisc, public ThrOMP {
 public:
  PairSPHHarmonicViscOMP(class LAMMPS *);
  void compute(int, int) override;
  double memory_usage() override;

 protected:
  void tally_pair(int i, int j, double fx, double fy, double fz, double delx, double dely,
                  double delz, void *thread) override;
};

}    // namespace LAMMPS_NS

#endif
#endif
#endif
