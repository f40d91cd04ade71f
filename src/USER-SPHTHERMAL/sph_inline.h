/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: thermal SPH for LAMMPS, in C99 (also C++).

   SPH_ALWAYS_INLINE for the per-pair terms of the C99 headers: GCC and
   Clang otherwise keep some of them out of line in the large pair loops
   that call them, and their sums and out-parameters then go through
   memory once per pair.
------------------------------------------------------------------------- */

#ifndef SPH_INLINE_H
#define SPH_INLINE_H

#if defined(__GNUC__)
#define SPH_ALWAYS_INLINE __attribute__((always_inline))
#else
#define SPH_ALWAYS_INLINE
#endif

#endif
