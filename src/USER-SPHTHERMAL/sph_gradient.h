/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: first-order corrected SPH gradients, in C99 (also C++).

   The kernel gradient estimate of grad f at particle i,
     g = sum_j V_j (f_j - f_i) grad_i W_ij,
   is exact for linear f only with a full kernel support. With the
   correction matrix
     L = sum_j V_j (r_j - r_i) (x) grad_i W_ij        (L_ab = sum V r_a g_b)
   L^T grad f = g holds for every linear f, also near walls and free
   surfaces (Bonet & Lok 1999), so grad f = L^-T g.
------------------------------------------------------------------------- */

#ifndef SPH_GRADIENT_H
#define SPH_GRADIENT_H

#include <math.h>

/* One neighbour j of i: del = r_i - r_j, grad_w = grad_i W_ij, volume
   V_j, df = f_j - f_i. Adds j's share to the kernel estimate g and to the
   correction matrix L (L_ab -= V_j del_a (grad_w)_b, i.e. + V_j (r_j -
   r_i)_a (grad_w)_b). */
static inline void sphg_add(double g[3], double L[9], const double del[3], const double grad_w[3],
                            double volume, double df)
{
  int a, b;
  for (b = 0; b < 3; b++) {
    g[b] += volume * df * grad_w[b];
    for (a = 0; a < 3; a++) L[3 * a + b] -= volume * del[a] * grad_w[b];
  }
}

/* Solve L^T x = g for a dim x dim block (dim 2 or 3) of the 3 x 3 row-major
   matrix L; returns 0 and leaves x = g when L is near singular (too few
   neighbours), 1 otherwise. */
static inline int sphg_solve_transposed(const double L[9], const double g[3], double x[3], int dim)
{
  if (dim == 2) {
    /* L^T = [[L0, L3], [L1, L4]] */
    const double det = L[0] * L[4] - L[1] * L[3];
    const double scale = fabs(L[0] * L[4]) + fabs(L[1] * L[3]);
    if (!(fabs(det) > 1e-6 * scale)) {
      x[0] = g[0], x[1] = g[1], x[2] = g[2];
      return 0;
    }
    x[0] = (L[4] * g[0] - L[3] * g[1]) / det;
    x[1] = (-L[1] * g[0] + L[0] * g[1]) / det;
    x[2] = 0.0;
    return 1;
  }
  /* A = L^T, A_ab = L_ba; Cramer's rule with the cofactors of A */
  const double a00 = L[0], a01 = L[3], a02 = L[6];
  const double a10 = L[1], a11 = L[4], a12 = L[7];
  const double a20 = L[2], a21 = L[5], a22 = L[8];
  const double c00 = a11 * a22 - a12 * a21, c01 = a12 * a20 - a10 * a22, c02 = a10 * a21 - a11 * a20;
  const double det = a00 * c00 + a01 * c01 + a02 * c02;
  const double scale = fabs(a00 * c00) + fabs(a01 * c01) + fabs(a02 * c02);
  if (!(fabs(det) > 1e-6 * scale)) {
    x[0] = g[0], x[1] = g[1], x[2] = g[2];
    return 0;
  }
  const double c10 = a02 * a21 - a01 * a22, c11 = a00 * a22 - a02 * a20, c12 = a01 * a20 - a00 * a21;
  const double c20 = a01 * a12 - a02 * a11, c21 = a02 * a10 - a00 * a12, c22 = a00 * a11 - a01 * a10;
  x[0] = (c00 * g[0] + c10 * g[1] + c20 * g[2]) / det;
  x[1] = (c01 * g[0] + c11 * g[1] + c21 * g[2]) / det;
  x[2] = (c02 * g[0] + c12 * g[1] + c22 * g[2]) / det;
  return 1;
}

#endif
