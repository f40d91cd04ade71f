/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/cleary/heat/omp: each thread takes a slice of the neighbour
   list and adds to its own copy of desph (and relax_rate); the copies are
   summed after the loop, so results equal the serial style's to round-off
   whatever the number of threads. The factors of a correction are made
   before the threads start and stored with the neighbour list, so each
   thread reads its slice's; when sph/harmonic/visc evaluates the term
   (loop shared) that style's threads do.
------------------------------------------------------------------------- */

#if __has_include("thr_omp.h")

#include "pair_sph_cleary_heat_omp.h"

#include "atom.h"
#include "comm.h"
#include "fix_omp.h"
#include "neigh_list.h"
#include "omp_compat.h"
#include "suffix.h"
#include "thr_data.h"
#include "timer.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHClearyHeatOMP::PairSPHClearyHeatOMP(LAMMPS *lmp) :
    PairSPHClearyHeat(lmp), ThrOMP(lmp, THR_PAIR)
{
  suffix_flag |= Suffix::OMP;
  respa_enable = 0;
}

/* ---------------------------------------------------------------------- */

void PairSPHClearyHeatOMP::compute(int eflag, int vflag)
{
  if (in_flow_loop) {
    PairSPHClearyHeat::compute(eflag, vflag);
    // the threads' forces are summed by the last /omp style of a hybrid,
    // which this one may be
    const int nall = atom->nlocal + atom->nghost;
#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag)
#endif
    {
      int ifrom, ito, tid;
      loop_setup_thr(ifrom, ito, tid, 0, comm->nthreads);
      ThrData *thr = fix->get_thr(tid);
      ev_setup_thr(eflag, vflag, nall, eatom, vatom, nullptr, thr);
      reduce_thr(this, eflag, vflag, thr);
    }
    return;
  }
  ev_init(eflag, vflag);
  begin_compute();

  const int nall = atom->nlocal + atom->nghost;
  const int nthreads = comm->nthreads;
  const int inum = list->inum;
  double *const relax = relax_wanted ? relax_rate : nullptr;

#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag, relax)
#endif
  {
    int ifrom, ito, tid;
    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, eatom, vatom, nullptr, thr);
    // fix omp clears the threads' desph; relax_rate (zeroed for thread 0)
    // is this style's to clear
    double *const relax_thr = relax ? relax + (size_t) tid * nall : nullptr;
    if (relax_thr && tid > 0) memset(relax_thr, 0, nall * sizeof(double));
    eval_pairs(ifrom, ito, thr->get_de(), relax_thr);
    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
    data_reduce_thr(atom->desph, nall, nthreads, 1, tid);
    if (relax) data_reduce_thr(relax, nall, nthreads, 1, tid);
  }    // end of omp parallel region

  end_compute();
}

/* ---------------------------------------------------------------------- */

double PairSPHClearyHeatOMP::memory_usage()
{
  return PairSPHClearyHeat::memory_usage() + memory_usage_thr();
}

#endif
