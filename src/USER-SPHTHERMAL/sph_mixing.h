/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: measures of the mixing of two components, in C99 (also
   C++). The measures of Reece, Rogers, Fourtakas & Lind 2024 (Int. J. Heat
   Mass Transfer 233, 125904), Table 4, which collects those of Reece,
   Rogers, Lind & Fourtakas 2020 (J. Hydrodyn. 32, 684-698). The table is
   garbled in print; the forms below are the ones whose limits the text
   describes (1 where fully mixed, 0 where a single component).

   F      volume fraction of component A around a particle (kernel-weighted,
          sum_{j in A} V_j W_ij / sum_j V_j W_ij, computed by the caller)
   f_all  volume fraction of A in the whole mixture
------------------------------------------------------------------------- */

#ifndef SPH_MIXING_H
#define SPH_MIXING_H

#include <math.h>

/* Robinson & Cleary 2011's local measure: with the concentrations
   a = F / f_all and b = (1 - F) / (1 - f_all) normalised by the mixture's,
   M = (sqrt 2 + 1) ((a + b) / |(a, b)| - 1), i.e. how close (a, b) is to
   the diagonal a = b: 0 for a single component, 1 for the mixture's own
   composition. Needs 0 < f_all < 1. */
static inline double sphmix_robinson(double fraction, double f_all)
{
  const double a = fraction / f_all;
  const double b = (1.0 - fraction) / (1.0 - f_all);
  return (sqrt(2.0) + 1.0) * ((a + b) / sqrt(a * a + b * b) - 1.0);
}

/* Reece et al. 2020's normalised composition: F / f_all up to the mixture's
   composition, (1 - F) / (1 - f_all) above it; 1 there, 0 for a single
   component */
static inline double sphmix_composition(double fraction, double f_all)
{
  return (fraction <= f_all) ? fraction / f_all : (1.0 - fraction) / (1.0 - f_all);
}

/* the finite-time Lyapunov exponent ln(d_max) / T from the largest stretch
   d_max = max_j r_ij(T) / r_ij(0) of a particle's initial neighbourhood;
   0 when no time has passed or no neighbour is left (stretch 0) */
static inline double sphmix_ftle(double stretch_max, double elapsed)
{
  return (elapsed > 0.0 && stretch_max > 0.0) ? log(stretch_max) / elapsed : 0.0;
}

/* a particle's term of the mixing entropy S = -sum_j F_j ln F_j (0 ln 0 = 0) */
static inline double sphmix_entropy_term(double fraction)
{
  return (fraction > 0.0) ? -fraction * log(fraction) : 0.0;
}

/* the entropy of n particles all at the mixture's composition: the largest
   S can be for a fixed mean of F (-F ln F is concave) */
static inline double sphmix_entropy_max(double n, double f_all)
{
  return n * sphmix_entropy_term(f_all);
}

/* S* = (S - S_0) / (S_max - S_0): 0 at the reference state, 1 when fully
   mixed; 0 when the reference is already at the maximum (nothing to gain) */
static inline double sphmix_entropy_normalised(double entropy, double entropy_initial,
                                               double entropy_max)
{
  const double span = entropy_max - entropy_initial;
  return (span > 0.0) ? (entropy - entropy_initial) / span : 0.0;
}

#endif
