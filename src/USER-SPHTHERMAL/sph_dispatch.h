/* -*- c++ -*- ----------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS.
   This software is distributed under the GNU General Public License.
------------------------------------------------------------------------- */

#ifndef LMP_SPH_DISPATCH_H
#define LMP_SPH_DISPATCH_H

// One dispatcher from run-time settings to the template parameters of a
// pair loop, so that the loop has no option branches and no style writes
// out the product of its options as nested switches. C++11 (the 2021
// release's plugin builds as C++11).
//
//   struct Loop {    // the call, with what the loop needs
//     template <int KERNEL, int MEAN, int FLAG> void run() { pair->eval<KERNEL, MEAN, FLAG>(...); }
//   };
//   const int settings[] = {kernel_kind, mean, flag};
//   SPHDispatch<SPHValues<A, B>, SPHValues<X, Y, Z>, SPHFlag>::to(loop, settings);
//
// A list's last value is taken when none before it equals the setting (a
// switch's default): the settings are checked where they are parsed.

#include "sph_kernels.h"

// A loop reached through SPHDispatch stays a function of its own: inlined
// into the chain of calls, the conduction loop with 'mean interface' and
// 'correction consistent' ran 17 % slower (bench/conduction/correction_cost.py)
#if defined(__GNUC__) || defined(__clang__)
#define SPH_LOOP __attribute__((noinline))
#else
#define SPH_LOOP
#endif

namespace LAMMPS_NS {

template <int... Values> struct SPHValues {};
typedef SPHValues<0, 1> SPHFlag;
typedef SPHValues<2, 3> SPHDimensions;
typedef SPHValues<SPHK_LUCY, SPHK_CUBIC, SPHK_QUINTIC, SPHK_WENDLAND> SPHKernelKinds;

template <class... Lists> struct SPHDispatch;

// every setting chosen: run the loop
template <> struct SPHDispatch<> {
  template <int... Chosen, class Call> static void to(Call &call, const int *)
  {
    call.template run<Chosen...>();
  }
};

// the first list: take its value that equals the setting, or try the next
template <int First, int Second, int... Rest, class... Lists>
struct SPHDispatch<SPHValues<First, Second, Rest...>, Lists...> {
  template <int... Chosen, class Call> static void to(Call &call, const int *setting)
  {
    if (*setting == First)
      SPHDispatch<Lists...>::template to<Chosen..., First>(call, setting + 1);
    else
      SPHDispatch<SPHValues<Second, Rest...>, Lists...>::template to<Chosen...>(call, setting);
  }
};

// the list's last value
template <int Last, class... Lists> struct SPHDispatch<SPHValues<Last>, Lists...> {
  template <int... Chosen, class Call> static void to(Call &call, const int *setting)
  {
    SPHDispatch<Lists...>::template to<Chosen..., Last>(call, setting + 1);
  }
};

}    // namespace LAMMPS_NS

#endif
