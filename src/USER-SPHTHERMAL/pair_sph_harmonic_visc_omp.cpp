/* ----------------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.

   pair sph/harmonic/visc/omp: each thread takes a slice of the neighbour
   list and adds to its own copy of f, drho and desph (and of the heat
   style's relax_rate when the conduction term runs in this loop, and of
   fix sph/shift's sums when it takes them from this loop); the copies are
   summed after the loop, so results equal the serial style's to
   round-off whatever the number of threads.
------------------------------------------------------------------------- */

#if __has_include("thr_omp.h")

#include "pair_sph_harmonic_visc_omp.h"

#include "atom.h"
#include "comm.h"
#include "fix_omp.h"
#include "force.h"
#include "neigh_list.h"
#include "omp_compat.h"
#include "suffix.h"
#include "thr_data.h"
#include "timer.h"

#include <cstring>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

PairSPHHarmonicViscOMP::PairSPHHarmonicViscOMP(LAMMPS *lmp) :
    PairSPHHarmonicVisc(lmp), ThrOMP(lmp, THR_PAIR)
{
  suffix_flag |= Suffix::OMP;
  respa_enable = 0;
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicViscOMP::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  begin_compute();

  const int nall = atom->nlocal + atom->nghost;
  const int nthreads = comm->nthreads;
  const int inum = list->inum;
  double *const relax_rate = heat_term.relax_rate;
  double *const shift_sum_all = shift_sums_wanted ? shift_sum : nullptr;

#if defined(_OPENMP)
#pragma omp parallel LMP_DEFAULT_NONE LMP_SHARED(eflag, vflag, relax_rate, shift_sum_all)
#endif
  {
    int ifrom, ito, tid;
    loop_setup_thr(ifrom, ito, tid, inum, nthreads);
    ThrData *thr = fix->get_thr(tid);
    thr->timer(Timer::START);
    ev_setup_thr(eflag, vflag, nall, eatom, vatom, nullptr, thr);
    // fix omp clears the threads' f, drho and desph; the relaxation rates
    // (the heat style's, zeroed for thread 0) are this style's to clear
    double *const relax_thr = relax_rate ? relax_rate + (size_t) tid * nall : nullptr;
    if (relax_thr && tid > 0) memset(relax_thr, 0, nall * sizeof(double));
    // likewise fix sph/shift's sums, where this loop makes them
    double *const shift_thr = shift_sum_all ? shift_sum_all + (size_t) 3 * tid * nall : nullptr;
    if (shift_thr && tid > 0) memset(shift_thr, 0, 3 * nall * sizeof(double));
    const Rates rates = {thr->get_f(), thr->get_drho(), thr->get_de(), relax_thr, shift_thr, thr};
    eval_pairs(ifrom, ito, rates);
    thr->timer(Timer::PAIR);
    reduce_thr(this, eflag, vflag, thr);
    data_reduce_thr(atom->drho, nall, nthreads, 1, tid);
    data_reduce_thr(atom->desph, nall, nthreads, 1, tid);
    if (relax_rate) data_reduce_thr(relax_rate, nall, nthreads, 1, tid);
    if (shift_sum_all) data_reduce_thr(shift_sum_all, nall, nthreads, 3, tid);
  }    // end of omp parallel region

  end_compute();
}

/* ---------------------------------------------------------------------- */

void PairSPHHarmonicViscOMP::tally_pair(int i, int j, double fx, double fy, double fz, double delx,
                                        double dely, double delz, void *thread)
{
  ev_tally_xyz_thr(this, i, j, atom->nlocal, force->newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely,
                   delz, (ThrData *) thread);
}

/* ---------------------------------------------------------------------- */

double PairSPHHarmonicViscOMP::memory_usage()
{
  return PairSPHHarmonicVisc::memory_usage() + memory_usage_thr();
}

#endif
