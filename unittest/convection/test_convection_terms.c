/* Unit tests of the convection terms, in C99: the Boussinesq acceleration
   (sph_buoyancy.h) and the first-order corrected interpolation at a point
   (sph_interpolation.h) that the mirror walls use at their ghost points,
   and particle shifting (sph_shift.h), and the quadratic fit at a point
   (sph_interpolation.h) of the flow walls' 'surface'.
   Usage: test_convection_terms buoyancy | linear | thin | shift | deltaplus |
   gradient | quadratic | moments */

#include "sph_buoyancy.h"
#include "sph_gradient.h"
#include "sph_interpolation.h"
#include "sph_kernels.h"
#include "sph_shift.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

static void check(int ok, const char *what, double got, double want)
{
  printf("%s %s: got %.17g, want %.17g\n", ok ? "ok  " : "FAIL", what, got, want);
  if (!ok) failures++;
}

/* sign (hot fluid rises against g), magnitude, zero at T0, linear in beta */
static void test_buoyancy(void)
{
  const double g[3] = {0.0, -9.81, 0.0};
  double a[3];
  sphb_acceleration(g, 3.43e-3, 303.0, 293.0, a);
  check(a[1] > 0.0, "hot fluid accelerates upwards (against g)", a[1], 9.81 * 3.43e-3 * 10.0);
  check(fabs(a[1] - 9.81 * 3.43e-3 * 10.0) < 1e-15, "magnitude g beta (T - T0)", a[1],
        9.81 * 3.43e-3 * 10.0);
  check(a[0] == 0.0 && a[2] == 0.0, "along g only", a[0] + a[2], 0.0);
  sphb_acceleration(g, 3.43e-3, 283.0, 293.0, a);
  check(a[1] < 0.0, "cold fluid sinks", a[1], -9.81 * 3.43e-3 * 10.0);
  sphb_acceleration(g, 3.43e-3, 293.0, 293.0, a);
  check(a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0, "no force at T0", a[1], 0.0);
  {
    const double tilted[3] = {1.0, -2.0, 0.5};
    double b[3];
    sphb_acceleration(tilted, 0.5, 3.0, 1.0, a);
    sphb_acceleration(tilted, 1.0, 3.0, 1.0, b);
    check(fabs(b[0] - 2.0 * a[0]) < 1e-15 && fabs(b[1] - 2.0 * a[1]) < 1e-15 &&
              fabs(a[0] + 1.0) < 1e-15 && fabs(a[1] - 2.0) < 1e-15 && fabs(a[2] + 0.5) < 1e-15,
          "any direction of g, linear in beta", a[1], 2.0);
  }
}

/* 0: neighbours added with sphi_add (r, dW/dr); 1: with sphi_add_g (the
   fix's form, -dW/dr / r from sphk_df_over_q) */
static int add_form = 0;

/* Sum the neighbours of point p on a unit square lattice (spacing 1,
   particles at i + 1/2) restricted to x > xwall, y > ywall, with a field
   f = c0 + cx x + cy y; returns the sphi_solve result. */
static int interpolate_lattice(int kind, double hdx, const double p[2], double xwall,
                               double ywall, const double c[3], double *value, double grad[3])
{
  const double cutoff = hdx * sphk_support(kind);
  const sphk_kernel k = sphk_make(kind, 2, cutoff);
  sphi_point point;
  int i, j;
  sphi_begin(&point, 2);
  for (i = -20; i < 20; i++)
    for (j = -20; j < 20; j++) {
      const double x = i + 0.5, y = j + 0.5;
      const double d[3] = {x - p[0], y - p[1], 0.0};
      const double r = sqrt(d[0] * d[0] + d[1] * d[1]);
      if (x < xwall || y < ywall || r >= cutoff) continue;
      if (add_form)
        sphi_add_g(&point, d, sphk_w(&k, r), -k.dw_scale * k.inv_h * sphk_df_over_q(kind, r * k.inv_h),
                   1.0, c[0] + c[1] * x + c[2] * y);
      else
        sphi_add(&point, d, r, sphk_w(&k, r), sphk_dwdr(&k, r), 1.0, c[0] + c[1] * x + c[2] * y);
    }
  return sphi_solve(&point, hdx, value, grad);
}

/* a linear field is reproduced exactly in the bulk, next to a straight
   wall and in a corner, for every kernel; the Shepard value is not */
static void test_linear(void)
{
  const double c[3] = {0.3, -1.7, 2.9};
  const double points[4][2] = {{0.25, 0.1}, {0.5, 3.0}, {0.5, 0.5}, {2.5, 1.5}};
  const char *where[4] = {"corner (ghost near the vertex)", "straight wall", "corner (on a particle)",
                          "corner, deeper ghost"};
  const char *forms[2] = {"sphi_add", "sphi_add_g"};
  int kind, n;
  for (add_form = 0; add_form < 2; add_form++)
    for (kind = 0; kind < SPHK_NKINDS; kind++)
      for (n = 0; n < 4; n++) {
        double value = 0.0, grad[3];
        char what[200];
        const double want = c[0] + c[1] * points[n][0] + c[2] * points[n][1];
        const double hdx = (kind == SPHK_LUCY) ? 3.0 : 1.3;
        const int how = interpolate_lattice(kind, hdx, points[n], 0.0, 0.0, c, &value, grad);
        snprintf(what, sizeof what, "%s, %s kernel, %s: corrected value", forms[add_form],
                 sphk_name(kind), where[n]);
        check(how == SPHI_CORRECTED && fabs(value - want) < 1e-12, what, value, want);
        snprintf(what, sizeof what, "%s, %s kernel, %s: gradient", forms[add_form],
                 sphk_name(kind), where[n]);
        check(fabs(grad[0] - c[1]) < 1e-11 && fabs(grad[1] - c[2]) < 1e-11, what, grad[0], c[1]);
      }
  add_form = 0;
  {
    /* the test can fail: a Shepard average at a wall is off for a linear field */
    const double p[2] = {0.5, 3.0};
    const sphk_kernel k = sphk_make(SPHK_QUINTIC, 2, 3.0);
    double sw = 0.0, swf = 0.0;
    int i, j;
    for (i = 0; i < 20; i++)
      for (j = -20; j < 20; j++) {
        const double x = i + 0.5, y = j + 0.5, r = hypot(x - p[0], y - p[1]);
        if (r >= 3.0) continue;
        sw += sphk_w(&k, r);
        swf += sphk_w(&k, r) * (c[0] + c[1] * x + c[2] * y);
      }
    check(fabs(swf / sw - (c[0] + c[1] * p[0] + c[2] * p[1])) > 1e-2,
          "Shepard value at a wall misses a linear field (by more than 1e-2)", swf / sw,
          c[0] + c[1] * p[0] + c[2] * p[1]);
  }
}

/* too few neighbours for the correction: the Shepard value; none: untouched */
static void test_thin(void)
{
  const double c[3] = {1.0, 2.0, 3.0};
  double value = -7.0, grad[3];
  /* one row of particles only (y in (0,1)): the y moments vanish */
  sphi_point point;
  const sphk_kernel k = sphk_make(SPHK_QUINTIC, 2, 3.0);
  int i, how;
  double sw = 0.0, swf = 0.0;
  sphi_begin(&point, 2);
  for (i = -5; i <= 5; i++) {
    const double d[3] = {i + 0.5, 0.0, 0.0};
    const double r = fabs(d[0]);
    const double f = c[0] + c[1] * (i + 0.5);
    if (r >= 3.0) continue;
    sphi_add(&point, d, r, sphk_w(&k, r), sphk_dwdr(&k, r), 1.0, f);
    sw += sphk_w(&k, r);
    swf += sphk_w(&k, r) * f;
  }
  how = sphi_solve(&point, 1.0, &value, grad);
  check(how == SPHI_SHEPARD, "a single row: Shepard (result code)", how, SPHI_SHEPARD);
  check(fabs(value - swf / sw) < 1e-14, "a single row: the Shepard value", value, swf / sw);
  sphi_begin(&point, 2);
  value = -7.0;
  how = sphi_solve(&point, 1.0, &value, grad);
  check(how == SPHI_NONE && value == -7.0, "no neighbour: value untouched", value, -7.0);
}

/* the shift runs down grad C, scales with D h |v| dt, and the cap shortens
   it to the limit without turning it */
/* delta-plus: the pair weight is 1 + R at one spacing, tends to 1 far
   out, grows as (W_ij/W(dx))^n close in; the shift runs down the weighted
   sum with the length C (U dt / h) (2h)^2 |sum| */
static void test_deltaplus(void)
{
  const double w_dx = 2.5;
  check(fabs(sphs_deltaplus_weight(w_dx, w_dx, 0.2, 4) - 1.2) < 1e-15, "weight 1 + R at r = dx",
        sphs_deltaplus_weight(w_dx, w_dx, 0.2, 4), 1.2);
  check(sphs_deltaplus_weight(0.0, w_dx, 0.2, 4) == 1.0, "weight 1 where W = 0",
        sphs_deltaplus_weight(0.0, w_dx, 0.2, 4), 1.0);
  check(fabs(sphs_deltaplus_weight(2.0 * w_dx, w_dx, 0.2, 4) - (1.0 + 0.2 * 16.0)) < 1e-14,
        "weight 1 + R 2^n at W = 2 W(dx)", sphs_deltaplus_weight(2.0 * w_dx, w_dx, 0.2, 4), 4.2);
  const double sum[3] = {-6.0, 8.0, 0.0};
  double dr[3];
  const double c = 0.5, h = 0.2, u = 3.0, dt = 1e-3;
  sphs_deltaplus(c, h, u, dt, sum, dr);
  const double length = c * u * dt / h * 4.0 * h * h * 10.0;
  check(dr[0] > 0.0 && dr[1] < 0.0 && dr[2] == 0.0, "down the weighted sum",
        dr[0] * sum[0] + dr[1] * sum[1], -1.0);
  check(fabs(sqrt(dr[0] * dr[0] + dr[1] * dr[1]) - length) < 1e-17,
        "length C (U dt / h) (2h)^2 |sum|", sqrt(dr[0] * dr[0] + dr[1] * dr[1]), length);
}

static void test_shift(void)
{
  const double grad_c[3] = {3.0, -4.0, 0.0};
  double dr[3];
  sphs_skillen(2.0, 0.1, 5.0, 1e-3, grad_c, dr);
  check(dr[0] < 0.0 && dr[1] > 0.0 && dr[2] == 0.0, "down the gradient of C",
        dr[0] * grad_c[0] + dr[1] * grad_c[1], -1.0);
  check(fabs(dr[0] + 2.0 * 0.1 * 5.0 * 1e-3 * 3.0) < 1e-17 &&
            fabs(dr[1] - 2.0 * 0.1 * 5.0 * 1e-3 * 4.0) < 1e-17,
        "magnitude D h |v| dt |grad C|", sqrt(dr[0] * dr[0] + dr[1] * dr[1]), 5e-3);
  sphs_skillen(2.0, 0.1, 0.0, 1e-3, grad_c, dr);
  check(dr[0] == 0.0 && dr[1] == 0.0, "no shift at rest", dr[0], 0.0);
  sphs_skillen(2.0, 0.1, 5.0, 1e-3, grad_c, dr);
  check(!sphs_cap(dr, 1.0) && fabs(dr[0] + 3e-3) < 1e-17, "below the cap: unchanged", dr[0], -3e-3);
  check(sphs_cap(dr, 1e-3) && fabs(sqrt(dr[0] * dr[0] + dr[1] * dr[1]) - 1e-3) < 1e-18 &&
            fabs(dr[0] / dr[1] + 0.75) < 1e-15,
        "capped: the limit's length, the same direction", dr[0] / dr[1], -0.75);
  /* a factor so large that the square of the length overflows (or the
     shift itself): still the limit's length down the gradient, not 0 */
  const double huge[2] = {-1e300, -INFINITY};
  for (int k = 0; k < 2; k++) {
    check(sphs_cap_along(huge[k], grad_c, 1e-3, dr) &&
              fabs(sqrt(dr[0] * dr[0] + dr[1] * dr[1]) - 1e-3) < 1e-18 &&
              fabs(dr[0] / dr[1] + 0.75) < 1e-15 && dr[0] < 0.0 && dr[2] == 0.0,
          "overflowing factor: capped at the limit along -grad C", sqrt(dr[0] * dr[0] + dr[1] * dr[1]),
          1e-3);
  }
  /* a finite factor: as sphs_skillen and sphs_cap */
  const double factor = sphs_skillen_factor(2.0, 0.1, 5.0, 1e-3);
  double plain[3];
  sphs_skillen(2.0, 0.1, 5.0, 1e-3, grad_c, plain);
  check(!sphs_cap_along(factor, grad_c, 1.0, dr) && dr[0] == plain[0] && dr[1] == plain[1],
        "finite factor below the cap: the same shift, bit for bit", dr[0], plain[0]);
  sphs_cap(plain, 1e-3);
  check(sphs_cap_along(factor, grad_c, 1e-3, dr) && dr[0] == plain[0] && dr[1] == plain[1],
        "finite factor above the cap: the same shift, bit for bit", dr[0], plain[0]);
  /* a sum that is not finite stays so, for the caller to stop */
  const double nan_sum[3] = {NAN, 1.0, 0.0};
  sphs_cap_along(-1.0, nan_sum, 1e-3, dr);
  check(isnan(dr[0]), "a NaN sum gives a NaN shift", dr[0], NAN);
}

/* the corrected gradient (sph_gradient.h) of a linear field at a particle
   of a unit lattice in the bulk, next to a straight wall and in a corner
   (the support cut at x < 0 and y < 0) is exact; the kernel estimate alone
   is not at the wall */
static void test_gradient(void)
{
  const double c[3] = {0.3, -1.7, 2.9};
  const double at[3][2] = {{0.5, 0.5}, {0.5, 10.5}, {10.5, 10.5}};
  const char *where[3] = {"corner", "wall", "bulk"};
  const sphk_kernel k = sphk_make(SPHK_WENDLAND, 2, 2.6);
  int p, i, j;
  for (p = 0; p < 3; p++) {
    double g[3] = {0.0, 0.0, 0.0}, L[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, grad[3];
    const double f_i = c[0] + c[1] * at[p][0] + c[2] * at[p][1];
    char what[80];
    int solved;
    for (i = 0; i < 30; i++)
      for (j = 0; j < 30; j++) {
        const double x = i + 0.5, y = j + 0.5;
        const double del[3] = {at[p][0] - x, at[p][1] - y, 0.0};
        const double r = sqrt(del[0] * del[0] + del[1] * del[1]);
        double grad_w[3];
        if (r == 0.0 || r >= 2.6) continue;
        grad_w[0] = sphk_dwdr(&k, r) * del[0] / r;
        grad_w[1] = sphk_dwdr(&k, r) * del[1] / r;
        grad_w[2] = 0.0;
        sphg_add(g, L, del, grad_w, 1.0, c[0] + c[1] * x + c[2] * y - f_i);
      }
    solved = sphg_solve_transposed(L, g, grad, 2);
    snprintf(what, sizeof what, "corrected gradient exact (%s)", where[p]);
    check(solved && fabs(grad[0] - c[1]) < 1e-12 && fabs(grad[1] - c[2]) < 1e-12, what, grad[1],
          c[2]);
    if (p < 2) {
      snprintf(what, sizeof what, "kernel estimate off (%s)", where[p]);
      check(fabs(g[1] - c[2]) > 1e-2, what, g[1], c[2]);
    }
  }
}

/* the quadratic fit reproduces a quadratic field's value and gradient at a
   point whatever the neighbourhood (a jittered lattice on one side of a
   wall, 2-D and 3-D, two fields at once), where the first-order
   correction misses the value by the kernel's second moment times the
   curvature; a neighbourhood on one line is refused */
static double jitter_of(int i, int k)
{
  /* a fixed pseudo-random number in [-0.2, 0.2] */
  const unsigned u = (unsigned) (i * 2654435761u + k * 40503u + 12345u);
  return 0.4 * ((u % 10007u) / 10006.0) - 0.2;
}

/* sphi_add_g's sums, written out term by term, are the definition's
   a[k][c] = sum_j row_k col_c and b[k] = sum_j row_k f_j with
   row = V [w, g d], col = [1, d], to the last bit, in 2-d and 3-d (a wrong
   or missing term fails), and a linear field in 3-d is reproduced */
static void test_moments(void)
{
  int dim;
  for (dim = 2; dim <= 3; dim++) {
    const int n = dim + 1;
    sphi_point point;
    double a[4][4] = {{0.0}}, b[4] = {0.0};
    int j, k, c, same = 1;
    char what[120];
    sphi_begin(&point, dim);
    for (j = 0; j < 37; j++) {
      /* neighbours spread irregularly about the point */
      const double d[3] = {sin(1.3 * j + 0.2), cos(2.1 * j) * 0.8,
                           (dim == 3) ? sin(0.7 * j - 1.0) : 0.0};
      const double w = 0.1 + 0.05 * (j % 7), g = 0.3 + 0.02 * (j % 5), volume = 0.9 + 0.01 * j;
      const double f = 1.0 + 0.5 * d[0] - 2.0 * d[1] + 0.25 * d[2];
      double row[4], col[4];
      row[0] = w * volume;
      col[0] = 1.0;
      for (k = 0; k < dim; k++) {
        row[k + 1] = g * d[k] * volume;
        col[k + 1] = d[k];
      }
      for (k = 0; k < n; k++) {
        b[k] += row[k] * f;
        for (c = 0; c < n; c++) a[k][c] += row[k] * col[c];
      }
      sphi_add_g(&point, d, w, g, volume, f);
    }
    for (k = 0; k < 4; k++) {
      same = same && point.b[k] == ((k < n) ? b[k] : 0.0);
      for (c = 0; c < 4; c++) same = same && point.a[k][c] == ((k < n && c < n) ? a[k][c] : 0.0);
    }
    snprintf(what, sizeof what, "%d-d: sphi_add_g's moments equal the definition's, bit for bit",
             dim);
    check(same, what, point.a[n - 1][n - 1], a[n - 1][n - 1]);
  }
  {
    /* 3-d: a linear field at a point next to a plane wall (a cubic lattice,
       spacing 1, z > 0 only), Wendland kernel, h = 1.3 */
    const double c[4] = {0.3, -1.7, 2.9, 0.6}, p[3] = {0.2, -0.1, 0.3};
    const double cutoff = 1.3 * sphk_support(SPHK_WENDLAND);
    const sphk_kernel k = sphk_make(SPHK_WENDLAND, 3, cutoff);
    sphi_point point;
    double value = 0.0, grad[3];
    int i, j, l, how;
    sphi_begin(&point, 3);
    for (i = -6; i < 6; i++)
      for (j = -6; j < 6; j++)
        for (l = 0; l < 6; l++) {
          const double x = i + 0.5, y = j + 0.5, z = l + 0.5;
          const double d[3] = {x - p[0], y - p[1], z - p[2]};
          const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          if (r >= cutoff) continue;
          sphi_add_g(&point, d, sphk_w(&k, r),
                     -k.dw_scale * k.inv_h * sphk_df_over_q(SPHK_WENDLAND, r * k.inv_h), 1.0,
                     c[0] + c[1] * x + c[2] * y + c[3] * z);
        }
    how = sphi_solve(&point, 1.3, &value, grad);
    const double want = c[0] + c[1] * p[0] + c[2] * p[1] + c[3] * p[2];
    check(how == SPHI_CORRECTED && fabs(value - want) < 1e-12,
          "3-d, Wendland kernel, at a plane wall: corrected value", value, want);
    check(fabs(grad[0] - c[1]) < 1e-11 && fabs(grad[1] - c[2]) < 1e-11 &&
              fabs(grad[2] - c[3]) < 1e-11,
          "3-d, Wendland kernel, at a plane wall: gradient", grad[2], c[3]);
  }
}

static void test_quadratic(void)
{
  const double h = 1.0;
  int dim;
  for (dim = 2; dim <= 3; dim++) {
    const sphk_kernel kernel = sphk_make(SPHK_WENDLAND, dim, 2.0 * h);
    const double p[3] = {0.1, 0.35, (dim == 3) ? -0.2 : 0.0};
    sphi_quadratic fit;
    sphi_point linear;
    double value[2], grad[6], first = 0.0;
    int i, j, k, n = 0;
    char what[128];
    sphi_quadratic_begin(&fit, dim, 2, h);
    sphi_begin(&linear, dim);
    /* points of a lattice of spacing 0.5 h with y >= 0 (a wall at y = 0),
       each moved by up to 0.2 spacing */
    for (i = -4; i <= 4; i++)
      for (j = 0; j <= 5; j++)
        for (k = (dim == 3) ? -4 : 0; k <= ((dim == 3) ? 4 : 0); k++) {
          const double x[3] = {0.5 * (i + jitter_of(n, 0)), 0.5 * (j + 0.5 + jitter_of(n, 1)),
                               (dim == 3) ? 0.5 * (k + jitter_of(n, 2)) : 0.0};
          const double d[3] = {x[0] - p[0], x[1] - p[1], x[2] - p[2]};
          const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          /* u = 1 + 2x - y + 3x^2 - 2xy + 0.5y^2 + z^2 - xz, and v = 3 y^2 */
          const double f[2] = {1.0 + 2.0 * x[0] - x[1] + 3.0 * x[0] * x[0] - 2.0 * x[0] * x[1] +
                                   0.5 * x[1] * x[1] + x[2] * x[2] - x[0] * x[2],
                               3.0 * x[1] * x[1]};
          const double w = sphk_w(&kernel, r);
          n++;
          if (w <= 0.0) continue;
          sphi_quadratic_add(&fit, d, 0.25 * w, f);
          sphi_add(&linear, d, r, w, sphk_dwdr(&kernel, r), 0.25, f[0]);
        }
    {
      const double u = 1.0 + 2.0 * p[0] - p[1] + 3.0 * p[0] * p[0] - 2.0 * p[0] * p[1] +
          0.5 * p[1] * p[1] + p[2] * p[2] - p[0] * p[2];
      const double du[3] = {2.0 + 6.0 * p[0] - 2.0 * p[1] - p[2], -1.0 - 2.0 * p[0] + p[1],
                            2.0 * p[2] - p[0]};
      const int how = sphi_quadratic_solve(&fit, value, grad);
      snprintf(what, sizeof what, "%d-D quadratic fit: solved", dim);
      check(how == SPHI_CORRECTED, what, how, SPHI_CORRECTED);
      snprintf(what, sizeof what, "%d-D quadratic fit: value of u", dim);
      check(fabs(value[0] - u) < 1e-11, what, value[0], u);
      for (k = 0; k < dim; k++) {
        snprintf(what, sizeof what, "%d-D quadratic fit: d u / d x_%d", dim, k);
        check(fabs(grad[k] - du[k]) < 1e-10, what, grad[k], du[k]);
      }
      snprintf(what, sizeof what, "%d-D quadratic fit: v and d v / d y, the second field", dim);
      check(fabs(value[1] - 3.0 * p[1] * p[1]) < 1e-11 && fabs(grad[4] - 6.0 * p[1]) < 1e-10, what,
            value[1], 3.0 * p[1] * p[1]);
      sphi_solve(&linear, h, &first, NULL);
      snprintf(what, sizeof what, "%d-D first-order value misses u by the curvature", dim);
      check(fabs(first - u) > 1e-3, what, first, u);
    }
  }
  {
    /* points on one line: no quadratic in the other direction */
    sphi_quadratic fit;
    double value[1] = {-7.0}, grad[3];
    int i;
    sphi_quadratic_begin(&fit, 2, 1, 1.0);
    for (i = -3; i <= 3; i++) {
      const double d[3] = {0.5 * i, 0.0, 0.0};
      const double f[1] = {1.0};
      sphi_quadratic_add(&fit, d, 1.0, f);
    }
    check(sphi_quadratic_solve(&fit, value, grad) == SPHI_NONE && value[0] == -7.0,
          "quadratic fit on one line: refused, value untouched", value[0], -7.0);
  }
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s buoyancy|linear|thin|shift|deltaplus|gradient|quadratic|moments\n",
            argv[0]);
    return 2;
  }
  if (strcmp(argv[1], "buoyancy") == 0)
    test_buoyancy();
  else if (strcmp(argv[1], "linear") == 0)
    test_linear();
  else if (strcmp(argv[1], "thin") == 0)
    test_thin();
  else if (strcmp(argv[1], "shift") == 0)
    test_shift();
  else if (strcmp(argv[1], "deltaplus") == 0)
    test_deltaplus();
  else if (strcmp(argv[1], "gradient") == 0)
    test_gradient();
  else if (strcmp(argv[1], "quadratic") == 0)
    test_quadratic();
  else if (strcmp(argv[1], "moments") == 0)
    test_moments();
  else {
    fprintf(stderr, "unknown test %s\n", argv[1]);
    return 2;
  }
  return failures ? 1 : 0;
}
