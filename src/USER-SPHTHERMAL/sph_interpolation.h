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

#include "sph_inline.h"

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
   volume V_j = m_j / rho_j, value f_j: a[k][c] += row_k col_c and
   b[k] += row_k f with row = V [w, g d], col = [1, d]. Written out term by
   term: with row and col as arrays the compiler stored them and read them
   back in wider loads than it wrote, a stall on every neighbour (the mirror
   walls call this once per neighbour of every ghost point and step), and
   inlined always, so that the sums stay in registers across neighbours. */
static inline SPH_ALWAYS_INLINE void sphi_add_g(sphi_point *p, const double d[3], double w,
                                                double g, double volume, double f)
{
  const double r0 = w * volume;
  const double r1 = g * d[0] * volume;
  const double r2 = g * d[1] * volume;
  p->b[0] += r0 * f;
  p->b[1] += r1 * f;
  p->b[2] += r2 * f;
  p->a[0][0] += r0;
  p->a[0][1] += r0 * d[0];
  p->a[0][2] += r0 * d[1];
  p->a[1][0] += r1;
  p->a[1][1] += r1 * d[0];
  p->a[1][2] += r1 * d[1];
  p->a[2][0] += r2;
  p->a[2][1] += r2 * d[0];
  p->a[2][2] += r2 * d[1];
  if (p->dim == 3) {
    const double r3 = g * d[2] * volume;
    p->b[3] += r3 * f;
    p->a[0][3] += r0 * d[2];
    p->a[1][3] += r1 * d[2];
    p->a[2][3] += r2 * d[2];
    p->a[3][0] += r3;
    p->a[3][1] += r3 * d[0];
    p->a[3][2] += r3 * d[1];
    p->a[3][3] += r3 * d[2];
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

/* Quadratic moving least squares at a point p, for fields whose curvature
   matters (the no-slip velocity of fix sph/wall/adami 'surface'): with the
   basis P(d) = [1, d/h, (d d)/h^2] (2-D: 6 terms, 3-D: 10) and the weights
   V_j W_pj, the coefficients c solve
     sum_j V_j W_pj P(d_j) P(d_j)^T c = sum_j V_j W_pj P(d_j) f_j
   so that every quadratic field is reproduced exactly with its value and
   gradient at p, which the first-order correction above is not: its value
   carries the kernel's second moment times the curvature. Up to
   SPHI_QUADRATIC_FIELDS fields share the matrix. */
#define SPHI_QUADRATIC_TERMS 10
#define SPHI_QUADRATIC_FIELDS 3
/* the smallest pivot of the scaled system, relative to its first
   diagonal element, below which the fit is not trusted (too few or too
   thin neighbours) */
#define SPHI_QUADRATIC_MIN_PIVOT 1e-9

typedef struct {
  int dim, nterms, nfields;
  double h, inv_h;
  double a[SPHI_QUADRATIC_TERMS][SPHI_QUADRATIC_TERMS];
  double b[SPHI_QUADRATIC_FIELDS][SPHI_QUADRATIC_TERMS];
} sphi_quadratic;

static inline void sphi_quadratic_begin(sphi_quadratic *q, int dim, int nfields, double h)
{
  int r, c;
  q->dim = dim;
  q->nterms = (dim == 3) ? 10 : 6;
  q->nfields = nfields;
  q->h = h;
  q->inv_h = 1.0 / h;
  for (r = 0; r < SPHI_QUADRATIC_TERMS; r++) {
    for (c = 0; c < SPHI_QUADRATIC_TERMS; c++) q->a[r][c] = 0.0;
    for (c = 0; c < SPHI_QUADRATIC_FIELDS; c++) q->b[c][r] = 0.0;
  }
}

/* the basis at d = r_j - r_p, scaled by h */
static inline void sphi_quadratic_basis(const sphi_quadratic *q, const double d[3], double *basis)
{
  const double x = d[0] * q->inv_h, y = d[1] * q->inv_h, z = d[2] * q->inv_h;
  basis[0] = 1.0;
  basis[1] = x;
  basis[2] = y;
  if (q->dim == 3) {
    basis[3] = z;
    basis[4] = x * x;
    basis[5] = x * y;
    basis[6] = x * z;
    basis[7] = y * y;
    basis[8] = y * z;
    basis[9] = z * z;
  } else {
    basis[3] = x * x;
    basis[4] = x * y;
    basis[5] = y * y;
  }
}

/* the sums of one neighbour, for nterms basis terms and nfields fields:
   sphi_quadratic_add passes constants where it can, so that the loops
   unroll (the mirror walls' fit, once per neighbour of every wall
   particle and step, is that much cheaper) */
static inline void sphi_quadratic_accumulate(sphi_quadratic *q, const double *basis, int nterms,
                                             int nfields, double weight, const double *f)
{
  int r, c;
  for (r = 0; r < nterms; r++) {
    const double wr = weight * basis[r];
    for (c = r; c < nterms; c++) q->a[r][c] += wr * basis[c];
    for (c = 0; c < nfields; c++) q->b[c][r] += wr * f[c];
  }
}

/* one neighbour j given its basis (sphi_quadratic_basis), weight = V_j W_pj
   and f[nfields] its values. A caller with many neighbours makes all their
   bases first: the sums read each basis in pairs, and a basis just written
   term by term cannot be read so until its stores have gone through (a
   stall per neighbour). */
static inline void sphi_quadratic_add_basis(sphi_quadratic *q, const double *basis, double weight,
                                            const double *f)
{
  if (q->nterms == 6 && q->nfields == 2)
    sphi_quadratic_accumulate(q, basis, 6, 2, weight, f);
  else if (q->nterms == 10 && q->nfields == 3)
    sphi_quadratic_accumulate(q, basis, 10, 3, weight, f);
  else
    sphi_quadratic_accumulate(q, basis, q->nterms, q->nfields, weight, f);
}

/* one neighbour j: d = r_j - r_p, weight = V_j W_pj, f[nfields] its values */
static inline void sphi_quadratic_add(sphi_quadratic *q, const double d[3], double weight,
                                      const double *f)
{
  double basis[SPHI_QUADRATIC_TERMS];
  sphi_quadratic_basis(q, d, basis);
  sphi_quadratic_add_basis(q, basis, weight, f);
}

/* value[k] and grad[3 k .. 3 k + 2] of each field k; returns
   SPHI_CORRECTED, or SPHI_NONE (outputs untouched) when the system is too
   thin for a quadratic fit */
static inline int sphi_quadratic_solve(const sphi_quadratic *q, double *value, double *grad)
{
  const int n = q->nterms, nf = q->nfields, nd = q->dim;
  double m[SPHI_QUADRATIC_TERMS][SPHI_QUADRATIC_TERMS + SPHI_QUADRATIC_FIELDS];
  double u[SPHI_QUADRATIC_TERMS];
  int r, c, k;
  if (!(q->a[0][0] > 0.0)) return SPHI_NONE;
  for (r = 0; r < n; r++) {
    for (c = 0; c < n; c++) m[r][c] = (c >= r) ? q->a[r][c] : q->a[c][r];
    for (c = 0; c < nf; c++) m[r][n + c] = q->b[c][r];
  }
  for (k = 0; k < n; k++) {
    int pivot = k;
    for (r = k + 1; r < n; r++)
      if (fabs(m[r][k]) > fabs(m[pivot][k])) pivot = r;
    if (pivot != k)
      for (c = 0; c < n + nf; c++) {
        const double t = m[k][c];
        m[k][c] = m[pivot][c];
        m[pivot][c] = t;
      }
    if (!(fabs(m[k][k]) > SPHI_QUADRATIC_MIN_PIVOT * q->a[0][0])) return SPHI_NONE;
    for (r = k + 1; r < n; r++) {
      const double factor = m[r][k] / m[k][k];
      for (c = k; c < n + nf; c++) m[r][c] -= factor * m[k][c];
    }
  }
  for (k = 0; k < nf; k++) {
    for (r = n - 1; r >= 0; r--) {
      double s = m[r][n + k];
      for (c = r + 1; c < n; c++) s -= m[r][c] * u[c];
      u[r] = s / m[r][r];
    }
    value[k] = u[0];
    for (c = 0; c < 3; c++) grad[3 * k + c] = (c < nd) ? u[1 + c] / q->h : 0.0;
  }
  return SPHI_CORRECTED;
}

#endif
