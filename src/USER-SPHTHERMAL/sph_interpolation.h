/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: SPH interpolation of a field at a point, with the
   first-order correction of Liu & Liu, in C99 (also C++).

   At a point p (not a particle), the value f_p and gradient grad f_p solve
     sum_j V_j W_pj   [1, (r_j - r_p)] . [f_p, grad f_p] = sum_j V_j W_pj f_j
     sum_j V_j G_pj (x) [1, (r_j - r_p)] . [f_p, grad f_p] = sum_j V_j G_pj f_j
   with G_pj = grad_p W(|r_p - r_j|): every linear field is reproduced
   exactly, whatever the neighbourhood (M. B. Liu and G. R. Liu, Restoring
   particle consistency in smoothed particle hydrodynamics, Applied
   Numerical Mathematics 56 (2006) 19-36, eq 36; used for the ghost points
   of mDBC walls by English et al. 2022 and Reece et al. 2024, eqs 18-19).
   When the neighbourhood is too thin for the (dim+1) system, the Shepard
   value sum V W f / sum V W is used instead.
------------------------------------------------------------------------- */

#ifndef SPH_INTERPOLATION_H
#define SPH_INTERPOLATION_H

#include <math.h>

/* The determinant of the dimensionless system (rows and columns of the
   gradient scaled by h) is about 1 with a full kernel support and about
   0.1-0.3 at a flat wall; below this bound the correction is not trusted. */
#define SPHI_MIN_DETERMINANT 1e-3

enum sphi_result { SPHI_NONE = 0, SPHI_SHEPARD = 1, SPHI_CORRECTED = 2 };

typedef struct {
  int dim;             /* 2 or 3 */
  double a[4][4];      /* the moment matrix, row-major, (dim+1) x (dim+1) */
  double b[4];         /* the right-hand side */
} sphi_point;

static inline void sphi_begin(sphi_point *p, int dim)
{
  int r, c;
  p->dim = dim;
  for (r = 0; r < 4; r++) {
    p->b[r] = 0.0;
    for (c = 0; c < 4; c++) p->a[r][c] = 0.0;
  }
}

/* one neighbour j: d = r_j - r_p, w = W(|d|), g = -(dW/dr) / r (so that
   G_pj = g d; finite at r = 0 for the package's kernels, sphk_df_over_q),
   volume V_j = m_j / rho_j, value f_j */
static inline void sphi_add_g(sphi_point *p, const double d[3], double w, double g,
                              double volume, double f)
{
  const int n = p->dim;
  double row[4], col[4];
  int k, c;
  row[0] = w * volume;
  col[0] = 1.0;
  for (k = 0; k < n; k++) {
    row[k + 1] = g * d[k] * volume;
    col[k + 1] = d[k];
  }
  for (k = 0; k <= n; k++) {
    p->b[k] += row[k] * f;
    for (c = 0; c <= n; c++) p->a[k][c] += row[k] * col[c];
  }
}

/* the same given r = |d| and dwdr = dW/dr at r */
static inline void sphi_add(sphi_point *p, const double d[3], double r, double w, double dwdr,
                            double volume, double f)
{
  /* G = dW/dr (r_p - r_j) / r = -dW/dr d / r; zero at r = 0 */
  sphi_add_g(p, d, w, (r > 0.0) ? -dwdr / r : 0.0, volume, f);
}

/* Solve for the value (and the gradient, when grad is not NULL). h scales
   the gradient rows and columns so that the determinant test is free of
   units. Returns SPHI_CORRECTED, SPHI_SHEPARD (too thin: Shepard value,
   zero gradient) or SPHI_NONE (no neighbour: value untouched). */
static inline int sphi_solve(const sphi_point *p, double h, double *value, double grad[3])
{
  const int n = p->dim + 1;
  double m[4][5];
  double det = 1.0;
  int r, c, k;
  if (grad) grad[0] = grad[1] = grad[2] = 0.0;
  if (!(p->a[0][0] > 0.0)) return SPHI_NONE;
  /* unknowns [f, h grad f]; gradient rows multiplied by h */
  for (r = 0; r < n; r++) {
    const double rs = (r > 0) ? h : 1.0;
    for (c = 0; c < n; c++) m[r][c] = p->a[r][c] * rs * ((c > 0) ? 1.0 / h : 1.0);
    m[r][n] = p->b[r] * rs;
  }
  /* Gaussian elimination with partial pivoting */
  for (k = 0; k < n; k++) {
    int pivot = k;
    for (r = k + 1; r < n; r++)
      if (fabs(m[r][k]) > fabs(m[pivot][k])) pivot = r;
    if (pivot != k) {
      for (c = 0; c <= n; c++) {
        const double t = m[k][c];
        m[k][c] = m[pivot][c];
        m[pivot][c] = t;
      }
      det = -det;
    }
    det *= m[k][k];
    if (!(m[k][k] != 0.0)) break;
    for (r = k + 1; r < n; r++) {
      const double factor = m[r][k] / m[k][k];
      for (c = k; c <= n; c++) m[r][c] -= factor * m[k][c];
    }
  }
  if (!(fabs(det) > SPHI_MIN_DETERMINANT)) {
    *value = p->b[0] / p->a[0][0];
    return SPHI_SHEPARD;
  }
  {
    double u[4] = {0.0, 0.0, 0.0, 0.0};
    for (r = n - 1; r >= 0; r--) {
      double s = m[r][n];
      for (c = r + 1; c < n; c++) s -= m[r][c] * u[c];
      u[r] = s / m[r][r];
    }
    *value = u[0];
    if (grad)
      for (k = 1; k < n; k++) grad[k - 1] = u[k] / h;
  }
  return SPHI_CORRECTED;
}

#endif
