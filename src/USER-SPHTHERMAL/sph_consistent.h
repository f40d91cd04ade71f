/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: the consistency correction of the conduction pair term,
   in C99 (also C++).

   The pair term of sph_conduction.h is Brookshaw's form of the Laplacian,
     lap(T)_a ~ (2 / V_a) sum_b g_ab (T_b - T_a),
     g_ab = V_a V_b (-r dW/dr) / (r^2 + eta^2)   (symmetric, >= 0),
   which is exact for a quadratic field when the pair weights have the two
   moments of a lattice:
     (first)  sum_b g_ab r_ab = 0,
     (second) sum_b g_ab r_ab (x) r_ab = V_a I.
   On disordered particles the first fails by O(disorder / h) and the
   error of the Laplacian does not vanish with resolution: it is
   (2 / V_a) grad(T) . sum_b g_ab r_ab.

   The correction multiplies g_ab by a factor w_ab that is symmetric in a
   and b, so that the pair term stays antisymmetric and sum(m e) is kept to
   round-off:
     w_ab = 1/2 e_ab.(S_a + S_b).e_ab * (1 + (lambda_a - lambda_b).r_ab)
   with e_ab = r_ab / |r_ab|, r_ab = x_a - x_b;
   - S_a = V_a M_a^-1, M_a = sum_b g_ab r_ab (x) r_ab: the kernel-gradient
     normalisation of the second moment (Bonet & Lok 1999), symmetrised
     per pair;
   - lambda_a: the vector that makes the first moment of the corrected
     weights vanish. The conditions couple neighbours (lambda_b enters a's
     sum), so they are solved by Jacobi sweeps,
       lambda_a <- K_a^-1 (sum_b G_ab r_ab (x) r_ab lambda_b - s_a),
       G_ab = g_ab 1/2 e.(S_a + S_b).e,  s_a = sum_b G_ab r_ab,
       K_a = sum_b G_ab r_ab (x) r_ab,
     whose first sweeps remove most of the deficit, because s_a is local
     noise (a factor of about 100 in 10 sweeps on 0.2 dx jitter); the
     smooth remainder relaxes slowly, as in any Jacobi iteration, and
     matters little (the Laplacian of a quadratic field on that jitter:
     relative error 0.21 after 5 sweeps, 0.18 converged, 7 plain).
   Where a particle's kernel support is incomplete (a free edge) its first
   moment is not noise but the boundary's own face: there S = I and
   lambda = 0 (the plain term), and the boundary stays adiabatic.

   Symmetric 3 x 3 matrices are stored as {xx, yy, zz, xy, xz, yz}; in 2-D
   the z entries are 0 (zz = 1 where an inverse needs it).
------------------------------------------------------------------------- */

#ifndef SPH_CONSISTENT_H
#define SPH_CONSISTENT_H

#include <math.h>

enum { SPHC_XX = 0, SPHC_YY, SPHC_ZZ, SPHC_XY, SPHC_XZ, SPHC_YZ };

/* the geometric Brookshaw weight per unit V_a V_b: (-r dW/dr) / (r^2 + eta^2) */
static inline double sphc_brookshaw_weight(double r, double dwdr, double eta2)
{
  return -r * dwdr / (r * r + eta2);
}

/* m += g r (x) r; in 2-D (dim 2, r_z = 0) the z entries are left alone:
   with dim a constant the caller's loop does half the work */
static inline void sphc_moment_add_in(int dim, double m[6], double g, const double r[3])
{
  m[SPHC_XX] += g * r[0] * r[0];
  m[SPHC_YY] += g * r[1] * r[1];
  m[SPHC_XY] += g * r[0] * r[1];
  if (dim == 3) {
    m[SPHC_ZZ] += g * r[2] * r[2];
    m[SPHC_XZ] += g * r[0] * r[2];
    m[SPHC_YZ] += g * r[1] * r[2];
  }
}

static inline void sphc_moment_add(double m[6], double g, const double r[3])
{
  sphc_moment_add_in(3, m, g, r);
}

/* y = m x */
static inline void sphc_sym_apply(const double m[6], const double x[3], double y[3])
{
  y[0] = m[SPHC_XX] * x[0] + m[SPHC_XY] * x[1] + m[SPHC_XZ] * x[2];
  y[1] = m[SPHC_XY] * x[0] + m[SPHC_YY] * x[1] + m[SPHC_YZ] * x[2];
  y[2] = m[SPHC_XZ] * x[0] + m[SPHC_YZ] * x[1] + m[SPHC_ZZ] * x[2];
}

/* e.m.e for the unit vector e (the quadratic form) */
static inline double sphc_sym_quad(const double m[6], const double e[3])
{
  return m[SPHC_XX] * e[0] * e[0] + m[SPHC_YY] * e[1] * e[1] + m[SPHC_ZZ] * e[2] * e[2] +
      2.0 * (m[SPHC_XY] * e[0] * e[1] + m[SPHC_XZ] * e[0] * e[2] + m[SPHC_YZ] * e[1] * e[2]);
}

/* e.m.e of a dim-dimensional e (dim 2: e_z = 0, the z terms left out) */
static inline double sphc_sym_quad_in(int dim, const double m[6], const double e[3])
{
  if (dim == 3) return sphc_sym_quad(m, e);
  return m[SPHC_XX] * e[0] * e[0] + m[SPHC_YY] * e[1] * e[1] + 2.0 * m[SPHC_XY] * e[0] * e[1];
}

/* Inverse of the symmetric matrix m of a dim-dimensional moment (dim 2: the
   z row and column are ignored and the inverse has zz = 1, xz = yz = 0).
   Returns the reciprocal condition estimate det / (trace / dim)^dim, in
   (0, 1] for a positive definite m (1 for a multiple of I), <= 0 when m is
   singular or indefinite; inv is then left as I. */
static inline double sphc_sym_inverse(int dim, const double m[6], double inv[6])
{
  double det, scale;
  inv[SPHC_XX] = inv[SPHC_YY] = inv[SPHC_ZZ] = 1.0;
  inv[SPHC_XY] = inv[SPHC_XZ] = inv[SPHC_YZ] = 0.0;
  if (dim == 2) {
    det = m[SPHC_XX] * m[SPHC_YY] - m[SPHC_XY] * m[SPHC_XY];
    scale = 0.5 * (m[SPHC_XX] + m[SPHC_YY]);
    if (!(det > 0.0) || !(scale > 0.0)) return 0.0;
    inv[SPHC_XX] = m[SPHC_YY] / det;
    inv[SPHC_YY] = m[SPHC_XX] / det;
    inv[SPHC_XY] = -m[SPHC_XY] / det;
    return det / (scale * scale);
  } else {
    const double c_xx = m[SPHC_YY] * m[SPHC_ZZ] - m[SPHC_YZ] * m[SPHC_YZ];
    const double c_yy = m[SPHC_XX] * m[SPHC_ZZ] - m[SPHC_XZ] * m[SPHC_XZ];
    const double c_zz = m[SPHC_XX] * m[SPHC_YY] - m[SPHC_XY] * m[SPHC_XY];
    const double c_xy = m[SPHC_XZ] * m[SPHC_YZ] - m[SPHC_XY] * m[SPHC_ZZ];
    const double c_xz = m[SPHC_XY] * m[SPHC_YZ] - m[SPHC_XZ] * m[SPHC_YY];
    const double c_yz = m[SPHC_XY] * m[SPHC_XZ] - m[SPHC_XX] * m[SPHC_YZ];
    det = m[SPHC_XX] * c_xx + m[SPHC_XY] * c_xy + m[SPHC_XZ] * c_xz;
    scale = (m[SPHC_XX] + m[SPHC_YY] + m[SPHC_ZZ]) / 3.0;
    if (!(det > 0.0) || !(scale > 0.0) || !(c_zz > 0.0) || !(c_xx > 0.0)) return 0.0;
    inv[SPHC_XX] = c_xx / det;
    inv[SPHC_YY] = c_yy / det;
    inv[SPHC_ZZ] = c_zz / det;
    inv[SPHC_XY] = c_xy / det;
    inv[SPHC_XZ] = c_xz / det;
    inv[SPHC_YZ] = c_yz / det;
    return det / (scale * scale * scale);
  }
}

/* smallest eigenvalue of the symmetric matrix m of a dim-dimensional moment
   (dim 2: the z row and column are ignored); the closed form of the
   characteristic polynomial's roots */
static inline double sphc_sym_min_eigen(int dim, const double m[6])
{
  if (dim == 2) {
    const double mean = 0.5 * (m[SPHC_XX] + m[SPHC_YY]);
    const double half = 0.5 * (m[SPHC_XX] - m[SPHC_YY]);
    return mean - sqrt(half * half + m[SPHC_XY] * m[SPHC_XY]);
  } else {
    const double off = m[SPHC_XY] * m[SPHC_XY] + m[SPHC_XZ] * m[SPHC_XZ] + m[SPHC_YZ] * m[SPHC_YZ];
    const double q = (m[SPHC_XX] + m[SPHC_YY] + m[SPHC_ZZ]) / 3.0;
    const double dx = m[SPHC_XX] - q, dy = m[SPHC_YY] - q, dz = m[SPHC_ZZ] - q;
    const double p = sqrt((dx * dx + dy * dy + dz * dz + 2.0 * off) / 6.0);
    double det, c;
    if (p == 0.0) return q;
    /* det((m - q I) / p) / 2, the cosine of three times the angle */
    det = (dx * (dy * dz - m[SPHC_YZ] * m[SPHC_YZ]) -
           m[SPHC_XY] * (m[SPHC_XY] * dz - m[SPHC_YZ] * m[SPHC_XZ]) +
           m[SPHC_XZ] * (m[SPHC_XY] * m[SPHC_YZ] - dy * m[SPHC_XZ])) /
        (p * p * p);
    c = 0.5 * det;
    if (c < -1.0) c = -1.0;
    if (c > 1.0) c = 1.0;
    /* the smallest of q + 2 p cos(acos(c) / 3 + 2 pi k / 3) */
    return q + 2.0 * p * cos(acos(c) / 3.0 + 2.0 * 3.14159265358979323846 / 3.0);
  }
}

/* The normaliser of a kernel moment M (summed with V_b, so that M / V_a is
   I for a complete support): out = V_a M^-1 where the support is complete,
   i.e. the smallest eigenvalue of M / V_a is at least SPHC_FULL_SUPPORT and
   M is invertible; returns 1. Elsewhere (free edges and surfaces, too few
   neighbours) out = I and it returns 0: the plain form is kept there. The
   smallest eigenvalue is 1 on a lattice away from edges (0.974 for the
   gradient moment with Wendland C2 at h = 1.3 dx), 0.5 on a free edge's
   first row, 0.9 on its second, 0.74 to 1.07 inside particles jittered by
   0.2 dx. The conduction's and the pressure gradient's corrections share it. */
#define SPHC_FULL_SUPPORT 0.7
static inline int sphc_moment_normaliser(int dim, const double m[6], double volume, double out[6])
{
  double inverse[6];
  int k;
  const int full = sphc_sym_min_eigen(dim, m) / volume >= SPHC_FULL_SUPPORT &&
      sphc_sym_inverse(dim, m, inverse) > 0.0;
  for (k = 0; k < 6; k++) out[k] = full ? volume * inverse[k] : ((k < 3) ? 1.0 : 0.0);
  return full;
}

/* the second-moment factor of a pair: 1/2 e.(S_a + S_b).e */
static inline double sphc_second_factor(const double s_a[6], const double s_b[6], const double e[3])
{
  return 0.5 * (sphc_sym_quad(s_a, e) + sphc_sym_quad(s_b, e));
}

/* the same factor from r_ab itself, |r_ab|^2 = rsq, in dim dimensions: one
   division in place of three for e */
static inline double sphc_second_factor_of(int dim, const double s_a[6], const double s_b[6],
                                           const double r_ab[3], double rsq)
{
  return 0.5 * (sphc_sym_quad_in(dim, s_a, r_ab) + sphc_sym_quad_in(dim, s_b, r_ab)) / rsq;
}

/* the first-moment factor of a pair: 1 + (lambda_a - lambda_b).r_ab; never
   below 0, so that a pair never conducts against the temperature
   difference (a floor reached only on extreme disorder; it keeps the
   symmetry, so energy is still conserved) */
static inline double sphc_first_factor_in(int dim, const double lambda_a[3],
                                          const double lambda_b[3], const double r_ab[3])
{
  double f = 1.0 + (lambda_a[0] - lambda_b[0]) * r_ab[0] + (lambda_a[1] - lambda_b[1]) * r_ab[1];
  if (dim == 3) f += (lambda_a[2] - lambda_b[2]) * r_ab[2];
  return (f > 0.0) ? f : 0.0;
}

static inline double sphc_first_factor(const double lambda_a[3], const double lambda_b[3],
                                       const double r_ab[3])
{
  return sphc_first_factor_in(3, lambda_a, lambda_b, r_ab);
}

/* one Jacobi sweep for particle a: lambda_a = K_a^-1 (c_a - s_a) with the
   coupling c_a = sum_b G_ab r_ab (x) r_ab lambda_b gathered by the caller,
   K_a^-1 the inverse of K_a = sum_b G_ab r_ab (x) r_ab, s_a = sum_b G_ab r_ab */
static inline void sphc_first_update(const double k_inv[6], const double coupling[3],
                                     const double deficit[3], double lambda[3])
{
  const double rhs[3] = {coupling[0] - deficit[0], coupling[1] - deficit[1],
                         coupling[2] - deficit[2]};
  sphc_sym_apply(k_inv, rhs, lambda);
}

#endif
