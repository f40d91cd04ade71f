/* Unit tests of sph_consistent.h (the consistency correction of the
   conduction pair term) with sph_kernels.h, in C99 (test_consistent_terms_cxx.cpp
   compiles the same checks as C++).
   and of sph_second_moment.h (the weights exact to the second moment).
   usage: test_consistent_terms inverse | eigen | factors | cholesky
          test_consistent_terms linear | quadratic | conservation | second | regularised 2|3
   The last four build a jittered lattice, correct its pair weights as
   pair sph/cleary/heat does with 'correction consistent' (or 'correction
   second') and check the corrected Laplacian against the plain one. */

#include "sph_consistent.h"
#include "sph_kernels.h"
#include "sph_second_moment.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

static void expect(int ok, const char *what, double got, double want)
{
  if (!ok) {
    failures++;
    printf("FAIL %s: got %.15g, expected %.15g\n", what, got, want);
  }
}

/* deterministic pseudo-random numbers in [lo, hi): a 64-bit LCG (Knuth's
   MMIX constants), its top 53 bits */
static unsigned long long lcg_state = 1;
static double uniform(double lo, double hi)
{
  lcg_state = lcg_state * 6364136223846793005ULL + 1442695040888963407ULL;
  return lo + (hi - lo) * (double) (lcg_state >> 11) / 9007199254740992.0;
}

/* ------------------------------------------------ symmetric 3 x 3 matrices */

static void sym_to_full(const double m[6], double full[3][3])
{
  full[0][0] = m[SPHC_XX];
  full[1][1] = m[SPHC_YY];
  full[2][2] = m[SPHC_ZZ];
  full[0][1] = full[1][0] = m[SPHC_XY];
  full[0][2] = full[2][0] = m[SPHC_XZ];
  full[1][2] = full[2][1] = m[SPHC_YZ];
}

/* largest |(m inv - I)_ij| over the dim x dim block */
static double inverse_residual(int dim, const double m[6], const double inv[6])
{
  double a[3][3], b[3][3], worst = 0.0;
  sym_to_full(m, a);
  sym_to_full(inv, b);
  for (int i = 0; i < dim; i++)
    for (int j = 0; j < dim; j++) {
      double product = 0.0;
      for (int k = 0; k < dim; k++) product += a[i][k] * b[k][j];
      worst = fmax(worst, fabs(product - (i == j ? 1.0 : 0.0)));
    }
  return worst;
}

static int is_identity(const double m[6])
{
  return m[SPHC_XX] == 1.0 && m[SPHC_YY] == 1.0 && m[SPHC_ZZ] == 1.0 && m[SPHC_XY] == 0.0 &&
      m[SPHC_XZ] == 0.0 && m[SPHC_YZ] == 0.0;
}

/* a random symmetric positive definite matrix B B^T + 0.1 I (dim 2: z row and column 0) */
static void random_spd(int dim, double m[6])
{
  double b[3][3] = {{0.0}};
  for (int i = 0; i < dim; i++)
    for (int j = 0; j < dim; j++) b[i][j] = uniform(-1.0, 1.0);
  for (int k = 0; k < 6; k++) m[k] = 0.0;
  for (int j = 0; j < dim; j++) {
    const double column[3] = {b[0][j], b[1][j], b[2][j]};
    sphc_moment_add(m, 1.0, column);
  }
  m[SPHC_XX] += 0.1;
  m[SPHC_YY] += 0.1;
  if (dim == 3) m[SPHC_ZZ] += 0.1;
}

/* R diag(d) R^T, R a rotation by the angles a (about z), b (about y), c
   (about x); in 2-D only a is used, and d[2] is ignored */
static void rotated_diagonal(int dim, const double d[3], double a, double b, double c, double m[6])
{
  double rz[3][3] = {{cos(a), -sin(a), 0.0}, {sin(a), cos(a), 0.0}, {0.0, 0.0, 1.0}};
  double ry[3][3] = {{cos(b), 0.0, sin(b)}, {0.0, 1.0, 0.0}, {-sin(b), 0.0, cos(b)}};
  double rx[3][3] = {{1.0, 0.0, 0.0}, {0.0, cos(c), -sin(c)}, {0.0, sin(c), cos(c)}};
  double ryx[3][3], r[3][3];
  if (dim == 2) {
    ry[0][0] = ry[2][2] = rx[1][1] = rx[2][2] = 1.0;
    ry[0][2] = ry[2][0] = rx[1][2] = rx[2][1] = 0.0;
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      ryx[i][j] = 0.0;
      for (int k = 0; k < 3; k++) ryx[i][j] += ry[i][k] * rx[k][j];
    }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      r[i][j] = 0.0;
      for (int k = 0; k < 3; k++) r[i][j] += rz[i][k] * ryx[k][j];
    }
  /* sum_k d_k (R e_k) (x) (R e_k) */
  for (int k = 0; k < 6; k++) m[k] = 0.0;
  for (int k = 0; k < dim; k++) {
    const double column[3] = {r[0][k], r[1][k], r[2][k]};
    sphc_moment_add(m, d[k], column);
  }
}

/* m inv = I for random positive definite m; a singular or indefinite m
   gives <= 0 and inv = I; a multiple of I has condition estimate 1 */
static void check_inverse(void)
{
  for (int dim = 2; dim <= 3; dim++) {
    double worst = 0.0, estimate_min = 1.0, estimate_max = 0.0;
    for (int n = 0; n < 1000; n++) {
      double m[6], inv[6];
      random_spd(dim, m);
      const double estimate = sphc_sym_inverse(dim, m, inv);
      worst = fmax(worst, inverse_residual(dim, m, inv));
      estimate_min = fmin(estimate_min, estimate);
      estimate_max = fmax(estimate_max, estimate);
      if (dim == 2 && !(inv[SPHC_ZZ] == 1.0 && inv[SPHC_XZ] == 0.0 && inv[SPHC_YZ] == 0.0)) {
        expect(0, "2-D inverse: zz = 1, xz = yz = 0", inv[SPHC_ZZ], 1.0);
        return;
      }
    }
    expect(worst < 1e-12, dim == 2 ? "2-D: m inv = I" : "3-D: m inv = I", worst, 0.0);
    expect(estimate_min > 0.0 && estimate_max <= 1.0 + 1e-15,
           "condition estimate in (0, 1] for a positive definite m", estimate_min, 1.0);
  }

  /* exactly singular (integer entries, so det is exactly 0) and indefinite */
  const double singular_2d[6] = {1.0, 4.0, 0.0, 2.0, 0.0, 0.0}; /* (1, 2) (x) (1, 2) */
  const double indefinite_2d[6] = {1.0, -1.0, 0.0, 0.0, 0.0, 0.0};
  /* (1, 2, 3) (x) (1, 2, 3) + (0, 1, 1) (x) (0, 1, 1): rank 2 */
  const double singular_3d[6] = {1.0, 5.0, 10.0, 2.0, 3.0, 7.0};
  const double indefinite_3d[6] = {2.0, 1.0, -1.0, 0.0, 0.0, 0.0};
  /* positive det and trace, but not positive definite: diag(-1, -1, 4) */
  const double two_negative_3d[6] = {-1.0, -1.0, 4.0, 0.0, 0.0, 0.0};
  const double *bad[5] = {singular_2d, indefinite_2d, singular_3d, indefinite_3d, two_negative_3d};
  const int bad_dim[5] = {2, 2, 3, 3, 3};
  const char *bad_what[5] = {"2-D singular", "2-D indefinite", "3-D singular", "3-D indefinite",
                             "3-D diag(-1, -1, 4)"};
  for (int n = 0; n < 5; n++) {
    double inv[6] = {7.0, 7.0, 7.0, 7.0, 7.0, 7.0};
    const double estimate = sphc_sym_inverse(bad_dim[n], bad[n], inv);
    char what[128];
    snprintf(what, sizeof(what), "%s: estimate <= 0", bad_what[n]);
    expect(estimate <= 0.0, what, estimate, 0.0);
    snprintf(what, sizeof(what), "%s: inverse left as I", bad_what[n]);
    expect(is_identity(inv), what, inv[SPHC_XY], 0.0);
  }

  /* a multiple of I: estimate 1, inverse I / 2.5 */
  for (int dim = 2; dim <= 3; dim++) {
    const double m[6] = {2.5, 2.5, dim == 3 ? 2.5 : 0.0, 0.0, 0.0, 0.0};
    double inv[6];
    const double estimate = sphc_sym_inverse(dim, m, inv);
    expect(fabs(estimate - 1.0) < 1e-15, "2.5 I: condition estimate 1", estimate, 1.0);
    expect(fabs(inv[SPHC_XX] - 0.4) < 1e-15 && fabs(inv[SPHC_YY] - 0.4) < 1e-15,
           "2.5 I: inverse 0.4 I", inv[SPHC_XX], 0.4);
  }
}

/* the smallest eigenvalue against matrices built from known ones */
static void check_eigen(void)
{
  struct {
    int dim;
    double d[3], a, b, c, want, tolerance;
    const char *what;
  } cases[] = {
      {2, {4.0, 1.0, 0.0}, 0.0, 0.0, 0.0, 1.0, 1e-12, "2-D diag(4, 1)"},
      {2, {3.0, 3.0, 0.0}, 0.0, 0.0, 0.0, 3.0, 1e-12, "2-D 3 I"},
      {2, {1.0, 3.0, 0.0}, 0.3, 0.0, 0.0, 1.0, 1e-12, "2-D diag(1, 3) rotated by 0.3"},
      {2, {-2.0, 0.5, 0.0}, 1.1, 0.0, 0.0, -2.0, 1e-12, "2-D diag(-2, 0.5) rotated by 1.1"},
      {3, {3.0, 1.0, 2.0}, 0.0, 0.0, 0.0, 1.0, 1e-12, "3-D diag(3, 1, 2)"},
      {3, {2.0, 2.0, 2.0}, 0.0, 0.0, 0.0, 2.0, 1e-12, "3-D 2 I"},
      {3, {1.0, 2.0, 5.0}, 0.4, -0.7, 1.2, 1.0, 1e-12, "3-D R diag(1, 2, 5) R^T"},
      {3, {5.0, 2.0, 1.0}, 2.0, 0.3, -0.5, 1.0, 1e-12, "3-D R diag(5, 2, 1) R^T"},
      {3, {0.5, -3.0, 4.0}, -1.0, 0.9, 0.2, -3.0, 1e-12, "3-D R diag(0.5, -3, 4) R^T"},
      {3, {1.0, 5.0, 5.0}, 0.4, -0.7, 1.2, 1.0, 1e-12, "3-D R diag(1, 5, 5) R^T"},
      /* a double smallest eigenvalue is the root where acos has infinite
         slope: round-off of 1e-16 in its argument moves the root by
         sqrt(1e-16) relative (harmless next to the pair style's test
         against 0.7, but not 1e-12) */
      {3, {1.0, 1.0, 5.0}, 0.4, -0.7, 1.2, 1.0, 1e-7, "3-D R diag(1, 1, 5) R^T"},
  };
  for (size_t n = 0; n < sizeof(cases) / sizeof(cases[0]); n++) {
    double m[6];
    rotated_diagonal(cases[n].dim, cases[n].d, cases[n].a, cases[n].b, cases[n].c, m);
    const double got = sphc_sym_min_eigen(cases[n].dim, m);
    expect(fabs(got - cases[n].want) < cases[n].tolerance, cases[n].what, got, cases[n].want);
  }
  /* 2-D ignores the z row and column */
  const double with_z[6] = {4.0, 1.0, -9.0, 0.0, 5.0, 5.0};
  expect(sphc_sym_min_eigen(2, with_z) == 1.0, "2-D ignores z", sphc_sym_min_eigen(2, with_z), 1.0);
}

/* the pair factors: the same from either side of the pair (r and e change
   sign), known values, and the floor of the first-moment factor at 0 */
static void check_factors(void)
{
  for (int n = 0; n < 1000; n++) {
    double s_a[6], s_b[6], lambda_a[3], lambda_b[3], r[3], e[3], minus_r[3], minus_e[3];
    random_spd(3, s_a);
    random_spd(3, s_b);
    for (int k = 0; k < 3; k++) {
      lambda_a[k] = uniform(-0.5, 0.5);
      lambda_b[k] = uniform(-0.5, 0.5);
      r[k] = uniform(-2.0, 2.0);
    }
    const double length = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++) {
      e[k] = r[k] / length;
      minus_r[k] = -r[k];
      minus_e[k] = -e[k];
    }
    const double second_ab = sphc_second_factor(s_a, s_b, e);
    const double second_ba = sphc_second_factor(s_b, s_a, minus_e);
    const double first_ab = sphc_first_factor(lambda_a, lambda_b, r);
    const double first_ba = sphc_first_factor(lambda_b, lambda_a, minus_r);
    if (fabs(second_ab - second_ba) > 1e-15 * fabs(second_ab)) {
      expect(0, "second factor: a, b, e -> b, a, -e", second_ba, second_ab);
      return;
    }
    if (fabs(first_ab - first_ba) > 1e-15 * fabs(first_ab)) {
      expect(0, "first factor: a, b, r -> b, a, -r", first_ba, first_ab);
      return;
    }
    if (first_ab < 0.0) {
      expect(0, "first factor never below 0", first_ab, 0.0);
      return;
    }
  }

  /* known values: 1/2 (e.S_a.e + e.S_b.e), 1 + (lambda_a - lambda_b).r */
  const double s_a[6] = {1.0, 2.0, 3.0, 0.5, 0.0, 0.0}, identity[6] = {1, 1, 1, 0, 0, 0};
  const double along_y[3] = {0.0, 1.0, 0.0}, diagonal[3] = {sqrt(0.5), sqrt(0.5), 0.0};
  double got = sphc_second_factor(s_a, identity, along_y);
  expect(fabs(got - 1.5) < 1e-15, "second factor along y: (2 + 1) / 2", got, 1.5);
  got = sphc_second_factor(s_a, identity, diagonal);
  expect(fabs(got - 1.5) < 1e-15, "second factor along (1, 1, 0): ((1 + 2) / 2 + 0.5 + 1) / 2", got,
         1.5);
  const double lambda_a[3] = {0.1, 0.2, 0.0}, lambda_b[3] = {0.0, 0.0, 0.3}, r[3] = {1.0, 2.0, 3.0};
  got = sphc_first_factor(lambda_a, lambda_b, r);
  expect(fabs(got - 0.6) < 1e-15, "first factor: 1 + 0.1 + 0.4 - 0.9", got, 0.6);
  /* (lambda_a - lambda_b).r = -2: floored at 0, from both sides */
  const double zero[3] = {0.0, 0.0, 0.0}, against[3] = {-2.0 / 14.0, -4.0 / 14.0, -6.0 / 14.0};
  const double minus_r[3] = {-1.0, -2.0, -3.0};
  got = sphc_first_factor(against, zero, r);
  expect(got == 0.0, "first factor floored at 0", got, 0.0);
  got = sphc_first_factor(zero, against, minus_r);
  expect(got == 0.0, "first factor floored at 0, from b's side", got, 0.0);
}

/* the forms for a known dimension that the pair loops call: in 3-D the
   general forms' values (the second factor from r and |r|^2 in place of e),
   in 2-D (r_z = 0) those values with the z entries of the moments left alone */
static void check_dimension_forms(void)
{
  for (int n = 0; n < 1000; n++) {
    double s_a[6], s_b[6], lambda_a[3], lambda_b[3], r[3], e[3];
    const int dim = 2 + (n % 2);
    random_spd(3, s_a);
    random_spd(3, s_b);
    for (int k = 0; k < 3; k++) {
      lambda_a[k] = uniform(-0.5, 0.5);
      lambda_b[k] = uniform(-0.5, 0.5);
      r[k] = (k < dim) ? uniform(-2.0, 2.0) : 0.0;
    }
    const double rsq = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int k = 0; k < 3; k++) e[k] = r[k] / sqrt(rsq);
    const double second = sphc_second_factor(s_a, s_b, e);
    const double second_of = sphc_second_factor_of(dim, s_a, s_b, r, rsq);
    if (fabs(second_of - second) > 1e-14 * fabs(second)) {
      expect(0, dim == 2 ? "2-D second factor from r" : "3-D second factor from r", second_of,
             second);
      return;
    }
    const double first = sphc_first_factor(lambda_a, lambda_b, r);
    const double first_in = sphc_first_factor_in(dim, lambda_a, lambda_b, r);
    if (fabs(first_in - first) > 1e-15 * fabs(first)) {
      expect(0, dim == 2 ? "2-D first factor" : "3-D first factor", first_in, first);
      return;
    }
    /* the moments: the 3-D sum's entries; in 2-D the z entries untouched */
    double general[6] = {0, 0, 0, 0, 0, 0}, in[6] = {7, 7, 7, 7, 7, 7};
    sphc_moment_add(general, 0.75, r);
    sphc_moment_add_in(dim, in, 0.75, r);
    for (int k = 0; k < 6; k++) {
      const int z_entry = (k == SPHC_ZZ || k == SPHC_XZ || k == SPHC_YZ);
      const double want = (dim == 2 && z_entry) ? 7.0 : 7.0 + general[k];
      if (fabs(in[k] - want) > 1e-15 * fabs(want)) {
        expect(0, dim == 2 ? "2-D moment entry" : "3-D moment entry", in[k], want);
        return;
      }
    }
  }
}

/* ----------------------------------------------- a jittered particle set */

enum { MAX_ATOMS = 1800, MAX_NEIGH = 128 };
/* spacing 1, jitter up to 0.2 per coordinate; cubic spline with h = 1.3 */
static const double JITTER = 0.2, CUTOFF = 2.6;
/* interior (corrected): at least EDGE lattice spacings from the set's
   edge; deep (asserted on): at least DEEP spacings from the nearest plain
   (non-interior) particles' lattice row */
enum { EDGE = 3, DEEP = 2 };

typedef struct {
  int dim, side, n;
  double x[MAX_ATOMS][3], volume[MAX_ATOMS];
  int interior[MAX_ATOMS], deep[MAX_ATOMS];
  int nneigh[MAX_ATOMS], neigh[MAX_ATOMS][MAX_NEIGH];
  double r[MAX_ATOMS][MAX_NEIGH][3];  /* r_ab = x_a - x_b */
  double g[MAX_ATOMS][MAX_NEIGH];     /* plain Brookshaw weight g_ab */
  double big_g[MAX_ATOMS][MAX_NEIGH]; /* G_ab = g_ab * second factor */
  double s[MAX_ATOMS][6], k_inv[MAX_ATOMS][6];
  double deficit[MAX_ATOMS][3], lambda[MAX_ATOMS][3];
} particle_set;

static particle_set particles;

/* a side^dim square (cubic) lattice of spacing 1 from the origin, each
   coordinate jittered by up to JITTER; the same set on every call */
static void make_jittered_lattice(particle_set *p, int dim, int side)
{
  lcg_state = 20250204ULL;
  p->dim = dim;
  p->side = side;
  p->n = 0;
  const int nz = (dim == 3) ? side : 1;
  for (int i = 0; i < side; i++)
    for (int j = 0; j < side; j++)
      for (int l = 0; l < nz; l++) {
        const int a = p->n++;
        const int index[3] = {i, j, l};
        int from_edge = side;
        for (int k = 0; k < 3; k++) {
          if (k < dim) {
            p->x[a][k] = index[k] + uniform(-JITTER, JITTER);
            from_edge = (index[k] < from_edge) ? index[k] : from_edge;
            from_edge = (side - 1 - index[k] < from_edge) ? side - 1 - index[k] : from_edge;
          } else
            p->x[a][k] = 0.0;
        }
        p->volume[a] = 1.0;
        p->interior[a] = from_edge >= EDGE;
        p->deep[a] = from_edge >= EDGE - 1 + DEEP;
      }
}

/* all pairs within the support, both ways, with g_ab = V_a V_b (-r dW/dr) / (r^2 + eta^2) */
static int gather_pairs(particle_set *p)
{
  const sphk_kernel kernel = sphk_make(SPHK_CUBIC, p->dim, CUTOFF);
  const double eta2 = 0.01 * kernel.h * kernel.h;
  for (int a = 0; a < p->n; a++) {
    p->nneigh[a] = 0;
    for (int b = 0; b < p->n; b++) {
      double r[3];
      for (int k = 0; k < 3; k++) r[k] = p->x[a][k] - p->x[b][k];
      const double length = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
      if (b == a || length >= CUTOFF) continue;
      if (p->nneigh[a] == MAX_NEIGH) return 0;
      const int k = p->nneigh[a]++;
      p->neigh[a][k] = b;
      for (int c = 0; c < 3; c++) p->r[a][k][c] = r[c];
      p->g[a][k] = p->volume[a] * p->volume[b] *
          sphc_brookshaw_weight(length, sphk_dwdr(&kernel, length), eta2);
    }
  }
  return 1;
}

static void unit_vector(const double r[3], double e[3])
{
  const double length = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
  for (int k = 0; k < 3; k++) e[k] = r[k] / length;
}

/* S, G, the deficits s, K^-1 and lambda by Jacobi sweeps, as the pair
   style's update_correction; non-interior particles keep S = I and
   lambda = 0. Returns 0 if an interior moment is not invertible. */
static int correct(particle_set *p, int sweeps)
{
  static double next[MAX_ATOMS][3];
  const double identity[6] = {1.0, 1.0, 1.0, 0.0, 0.0, 0.0};
  int ok = 1;
  for (int a = 0; a < p->n; a++) {
    double moment[6] = {0.0}, inverse[6];
    for (int k = 0; k < p->nneigh[a]; k++) sphc_moment_add(moment, p->g[a][k], p->r[a][k]);
    const int invertible = sphc_sym_inverse(p->dim, moment, inverse) > 0.0;
    ok &= invertible || !p->interior[a];
    for (int c = 0; c < 6; c++)
      p->s[a][c] = p->interior[a] ? p->volume[a] * inverse[c] : identity[c];
  }
  for (int a = 0; a < p->n; a++) {
    double k_moment[6] = {0.0};
    for (int c = 0; c < 3; c++) p->deficit[a][c] = p->lambda[a][c] = 0.0;
    for (int k = 0; k < p->nneigh[a]; k++) {
      double e[3];
      unit_vector(p->r[a][k], e);
      p->big_g[a][k] = p->g[a][k] * sphc_second_factor(p->s[a], p->s[p->neigh[a][k]], e);
      for (int c = 0; c < 3; c++) p->deficit[a][c] += p->big_g[a][k] * p->r[a][k][c];
      sphc_moment_add(k_moment, p->big_g[a][k], p->r[a][k]);
    }
    const int invertible = sphc_sym_inverse(p->dim, k_moment, p->k_inv[a]) > 0.0;
    ok &= invertible || !p->interior[a];
    if (!p->interior[a])
      for (int c = 0; c < 6; c++) p->k_inv[a][c] = 0.0;
  }
  /* each sweep with the neighbours' lambda of the sweep before */
  for (int sweep = 0; sweep < sweeps; sweep++) {
    for (int a = 0; a < p->n; a++) {
      double coupling[3] = {0.0, 0.0, 0.0};
      for (int k = 0; k < p->nneigh[a]; k++) {
        const double *r = p->r[a][k], *lambda_b = p->lambda[p->neigh[a][k]];
        const double along =
            p->big_g[a][k] * (r[0] * lambda_b[0] + r[1] * lambda_b[1] + r[2] * lambda_b[2]);
        for (int c = 0; c < 3; c++) coupling[c] += along * r[c];
      }
      sphc_first_update(p->k_inv[a], coupling, p->deficit[a], next[a]);
    }
    memcpy(p->lambda, next, sizeof(double) * 3 * p->n);
  }
  return ok;
}

/* w_ab of a's k-th neighbour b: 1 for the plain term */
static double pair_factor(const particle_set *p, int a, int k, int corrected)
{
  if (!corrected) return 1.0;
  const int b = p->neigh[a][k];
  double e[3];
  unit_vector(p->r[a][k], e);
  return sphc_second_factor(p->s[a], p->s[b], e) *
      sphc_first_factor(p->lambda[a], p->lambda[b], p->r[a][k]);
}

/* |sum_b g_ab w_ab r_ab| */
static double first_moment(const particle_set *p, int a, int corrected)
{
  double m[3] = {0.0, 0.0, 0.0};
  for (int k = 0; k < p->nneigh[a]; k++) {
    const double gw = p->g[a][k] * pair_factor(p, a, k, corrected);
    for (int c = 0; c < 3; c++) m[c] += gw * p->r[a][k][c];
  }
  return sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
}

/* (2 / V_a) sum_b g_ab w_ab (T_b - T_a) */
static double laplacian(const particle_set *p, int a, int corrected, const double *t)
{
  double sum = 0.0;
  for (int k = 0; k < p->nneigh[a]; k++)
    sum += p->g[a][k] * pair_factor(p, a, k, corrected) * (t[p->neigh[a][k]] - t[a]);
  return 2.0 * sum / p->volume[a];
}

/* the test set of each dimension: 30 x 30 in 2-D, 12^3 in 3-D, corrected
   with enough sweeps to converge. The first sweeps take out the deficit's
   noise (a factor 100 in 10 sweeps), but the smooth part of lambda
   relaxes slowly across the interior, as in any Jacobi iteration
   (measured in 2-D, interior 24 across: first moment 2e-4 of the plain
   after 200 sweeps, 1e-8 after 800, 4e-14 after 1600; 3-D, 6 across:
   2e-15 after 200) */
enum { SWEEPS = 1500 };

static int build_corrected_set(particle_set *p, int dim)
{
  make_jittered_lattice(p, dim, dim == 2 ? 30 : 12);
  if (!gather_pairs(p)) {
    expect(0, "neighbours within MAX_NEIGH", MAX_NEIGH + 1, MAX_NEIGH);
    return 0;
  }
  if (!correct(p, SWEEPS)) {
    expect(0, "interior moments M and K invertible", 0.0, 1.0);
    return 0;
  }
  return 1;
}

/* the first moment of the corrected weights vanishes (the Laplacian of a
   linear field is 0), while the plain one's is the disorder's. The plain
   reference is taken on the deep interior; the corrected one is held to it
   on every interior particle, next to the plain ones too, since their
   lambda = 0 enters the sweeps as any other neighbour's */
static void check_linear(int dim)
{
  particle_set *p = &particles;
  if (!build_corrected_set(p, dim)) return;
  static double t[MAX_ATOMS];
  for (int a = 0; a < p->n; a++) t[a] = 2.0 * p->x[a][0] - 3.0 * p->x[a][1] + p->x[a][2];
  double plain = 0.0, corrected = 0.0, plain_lap = 0.0, corrected_lap = 0.0;
  int interior = 0, deep = 0;
  for (int a = 0; a < p->n; a++) {
    if (!p->interior[a]) continue;
    interior++;
    corrected = fmax(corrected, first_moment(p, a, 1));
    corrected_lap = fmax(corrected_lap, fabs(laplacian(p, a, 1, t)));
    if (!p->deep[a]) continue;
    deep++;
    plain = fmax(plain, first_moment(p, a, 0));
    plain_lap = fmax(plain_lap, fabs(laplacian(p, a, 0, t)));
  }
  printf("%d-D: largest |first moment| plain %.3e (%d deep), corrected %.3e (%d interior)\n", dim,
         plain, deep, corrected, interior);
  printf("%d-D: largest |Laplacian of a linear field| plain %.3e, corrected %.3e\n", dim, plain_lap,
         corrected_lap);
  /* measured: plain 0.26 in 2-D, 0.17 in 3-D (0 to round-off on a lattice) */
  expect(plain > 0.1, "the plain first moment shows the disorder", plain, 0.1);
  expect(corrected < 1e-8 * plain, "corrected first moment below 1e-8 of the plain", corrected,
         1e-8 * plain);
  expect(corrected_lap < 1e-8 * plain_lap,
         "corrected Laplacian of a linear field below 1e-8 of the plain", corrected_lap,
         1e-8 * plain_lap);
}

/* the Laplacian of T = x^2 + 0.5 y^2 + 0.3 x y (+ 0.25 z^2 - 0.4 x z in
   3-D): not exact on a disordered set (only the first moment is; the
   second is normalised per particle, then symmetrised), so the measured
   bound with a margin */
static void check_quadratic(int dim)
{
  particle_set *p = &particles;
  if (!build_corrected_set(p, dim)) return;
  static double t[MAX_ATOMS];
  for (int a = 0; a < p->n; a++) {
    const double x = p->x[a][0], y = p->x[a][1], z = p->x[a][2];
    t[a] = x * x + 0.5 * y * y + 0.3 * x * y + 0.25 * z * z - 0.4 * x * z;
  }
  const double exact = (dim == 2) ? 3.0 : 3.5;
  double plain = 0.0, corrected = 0.0;
  for (int a = 0; a < p->n; a++) {
    if (!p->deep[a]) continue;
    plain = fmax(plain, fabs(laplacian(p, a, 0, t) - exact) / exact);
    corrected = fmax(corrected, fabs(laplacian(p, a, 1, t) - exact) / exact);
  }
  printf("%d-D: largest relative error of the quadratic's Laplacian: plain %.3e, corrected %.3e\n",
         dim, plain, corrected);
  /* measured: 2-D plain 7.0, corrected 0.179; 3-D plain 0.90, corrected
     0.098. The plain error is (2 / V) grad(T).(first moment), so it grows
     with |grad T| (up to 60 here in 2-D, 20 in 3-D); the corrected one does
     not depend on it */
  const double bound = (dim == 2) ? 0.25 : 0.14;
  expect(corrected < bound, "corrected Laplacian of a quadratic: relative error", corrected, bound);
  expect(corrected < 0.2 * plain, "corrected error below 1/5 of the plain", corrected, 0.2 * plain);
}

/* w_ab = w_ba from either side of every pair, and the corrected pair term
   exchanges energy: sum_a m_a de_a = 0 to round-off with two materials */
static void check_conservation(int dim)
{
  particle_set *p = &particles;
  if (!build_corrected_set(p, dim)) return;
  static double t[MAX_ATOMS], mass[MAX_ATOMS], de[MAX_ATOMS];
  for (int a = 0; a < p->n; a++) {
    const int dense = p->x[a][0] > 0.5 * (p->side - 1);
    const double rho = dense ? 3.0 : 1.0, cv = dense ? 0.5 : 2.0;
    mass[a] = rho * p->volume[a];
    t[a] = uniform(0.0, 100.0) / cv;
  }
  double asymmetry = 0.0;
  for (int a = 0; a < p->n; a++)
    for (int k = 0; k < p->nneigh[a]; k++) {
      const int b = p->neigh[a][k];
      int back = 0;
      while (back < p->nneigh[b] && p->neigh[b][back] != a) back++;
      if (back == p->nneigh[b]) {
        expect(0, "every pair in both neighbour lists", a, b);
        return;
      }
      const double w_ab = pair_factor(p, a, k, 1), w_ba = pair_factor(p, b, back, 1);
      asymmetry = fmax(asymmetry, fabs(w_ab - w_ba) / fabs(w_ab));
    }
  expect(asymmetry < 1e-14, "w_ab = w_ba", asymmetry, 0.0);

  /* de_a = (1 / m_a) sum_b 2 g_ab w_ab (T_b - T_a), the pair term with k = 1 */
  double total = 0.0, magnitude = 0.0;
  for (int a = 0; a < p->n; a++) {
    double sum = 0.0;
    for (int k = 0; k < p->nneigh[a]; k++) {
      const double term = 2.0 * p->g[a][k] * pair_factor(p, a, k, 1) * (t[p->neigh[a][k]] - t[a]);
      sum += term;
      magnitude += fabs(term);
    }
    de[a] = sum / mass[a];
  }
  for (int a = 0; a < p->n; a++) total += mass[a] * de[a];
  printf("%d-D: |w_ab - w_ba| / w_ab %.3e; sum m de %.3e of sum |terms| %.3e\n", dim, asymmetry,
         total, magnitude);
  expect(fabs(total) < 1e-12 * magnitude, "sum_a m_a de_a = 0", total, 0.0);
}

/* --------------------------------------------- sph_second_moment.h */

/* L L^T x = b for random positive definite matrices of 5 and 9 rows; a
   matrix that is not positive definite is refused; the pair argument is
   the same from either side of the pair */
static void check_cholesky(void)
{
  for (int n = 5; n <= 9; n += 4) {
    double worst = 0.0;
    for (int trial = 0; trial < 200; trial++) {
      double b[SPHS_MAX][SPHS_MAX], a[SPHS_MAX * SPHS_MAX], l[SPHS_MAX * SPHS_MAX];
      double x[SPHS_MAX], want[SPHS_MAX], rhs[SPHS_MAX];
      for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) b[i][j] = uniform(-1.0, 1.0);
      for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
          double s = (i == j) ? 0.1 : 0.0;
          for (int k = 0; k < n; k++) s += b[i][k] * b[j][k];
          a[i * n + j] = l[i * n + j] = s;
        }
      for (int i = 0; i < n; i++) want[i] = uniform(-1.0, 1.0);
      for (int i = 0; i < n; i++) {
        rhs[i] = 0.0;
        for (int j = 0; j < n; j++) rhs[i] += a[i * n + j] * want[j];
      }
      if (!sphs_cholesky(n, l)) {
        expect(0, "Cholesky of a positive definite matrix", 0.0, 1.0);
        return;
      }
      sphs_cholesky_solve(n, l, rhs, x);
      for (int i = 0; i < n; i++) worst = fmax(worst, fabs(x[i] - want[i]));
    }
    expect(worst < 1e-9, n == 5 ? "5 x 5: L L^T x = b" : "9 x 9: L L^T x = b", worst, 0.0);
  }
  double indefinite[4] = {1.0, 2.0, 2.0, 1.0}; /* eigenvalues 3 and -1 */
  expect(!sphs_cholesky(2, indefinite), "Cholesky refuses an indefinite matrix", 1.0, 0.0);

  for (int dim = 2; dim <= 3; dim++) {
    const int n = sphs_count(dim);
    double worst = 0.0;
    for (int trial = 0; trial < 1000; trial++) {
      double r[3] = {uniform(-2, 2), uniform(-2, 2), dim == 3 ? uniform(-2, 2) : 0.0};
      double minus_r[3] = {-r[0], -r[1], -r[2]}, nu_a[SPHS_MAX], nu_b[SPHS_MAX];
      double f_ab[SPHS_MAX], f_ba[SPHS_MAX];
      for (int k = 0; k < n; k++) {
        nu_a[k] = uniform(-0.3, 0.3);
        nu_b[k] = uniform(-0.3, 0.3);
      }
      sphs_basis(dim, r, 1.0 / 1.3, f_ab);
      sphs_basis(dim, minus_r, 1.0 / 1.3, f_ba);
      const double ab = sphs_argument(dim, f_ab, nu_a, nu_b);
      const double ba = sphs_argument(dim, f_ba, nu_b, nu_a);
      worst = fmax(worst, fabs(ab - ba));
      if (sphs_factor(dim, f_ab, nu_a, nu_b) < 0.0) {
        expect(0, "second-moment factor never below 0", sphs_factor(dim, f_ab, nu_a, nu_b), 0.0);
        return;
      }
    }
    expect(worst < 1e-14, "second-moment argument: a, b, r -> b, a, -r", worst, 0.0);
  }
  /* a known argument: r = (1, 2) h, nu_a = (0.1, 0, 0.01, 0, 0), nu_b = (0, 0.1, 0, 0.02, 0):
     1 + (0.1 - 0) 1 + (0 - 0.1) 2 + 0.01 1 + 0.02 (2 1 2) = 0.99 */
  const double r[3] = {1.3, 2.6, 0.0}, nu_a[5] = {0.1, 0.0, 0.01, 0.0, 0.0};
  const double nu_b[5] = {0.0, 0.1, 0.0, 0.02, 0.0};
  double f[SPHS_MAX];
  sphs_basis(2, r, 1.0 / 1.3, f);
  const double got = sphs_argument(2, f, nu_a, nu_b);
  expect(fabs(got - 0.99) < 1e-14, "second-moment argument, known value", got, 0.99);
}

/* the serial run of the solver: no ghosts, one rank */
static void no_exchange(void *context, double *values, int n)
{
  (void) context;
  (void) values;
  (void) n;
}
static double own_value(void *context, double value)
{
  (void) context;
  return value;
}
static void own_values(void *context, double *values, int n)
{
  (void) context;
  (void) values;
  (void) n;
}

static sphs_pair second_pairs[MAX_ATOMS * MAX_NEIGH / 2];
static double second_nu[MAX_ATOMS * SPHS_MAX];

/* the serial problem of the interior particles of the set (pairs in
   second_pairs), the coarse grid's spacing in h (0: one level) */
static sphs_problem second_problem(particle_set *p, double regularization, double coarse)
{
  static int constrained[MAX_ATOMS];
  int npairs = 0;
  for (int a = 0; a < p->n; a++) {
    constrained[a] = p->interior[a];
    for (int k = 0; k < p->nneigh[a]; k++) {
      const int b = p->neigh[a][k];
      if (b < a) continue; /* each pair once */
      sphs_pair *pair = &second_pairs[npairs++];
      pair->i = a;
      pair->j = b;
      for (int c = 0; c < 3; c++) pair->r[c] = p->r[a][k][c];
      pair->g = p->g[a][k];
    }
  }
  sphs_problem problem;
  problem.dim = p->dim;
  problem.nlocal = problem.nall = p->n;
  problem.newton = 1;
  problem.npairs = npairs;
  problem.pairs = second_pairs;
  problem.volume = p->volume;
  problem.constrained = constrained;
  problem.h = CUTOFF / 2.0;
  problem.tolerance = 1e-11;
  problem.regularization = regularization;
  problem.max_newton = 50;
  problem.max_cg = 2000;
  problem.exchange.context = NULL;
  problem.exchange.forward = no_exchange;
  problem.exchange.reverse = no_exchange;
  problem.exchange.sum = own_value;
  problem.exchange.max = own_value;
  problem.exchange.sum_array = own_values;
  problem.x = &p->x[0][0];
  problem.coarse = coarse;
  problem.max_coarse = 2000;
  return problem;
}

/* the multipliers of the interior particles of the set by sph_second_moment.h */
static sphs_result solve_second(particle_set *p, double regularization, double coarse)
{
  const sphs_problem problem = second_problem(p, regularization, coarse);
  double *work = (double *) malloc(sphs_work_size(&problem) * sizeof(double));
  for (int k = 0; k < p->n * SPHS_MAX; k++) second_nu[k] = 0.0;
  const sphs_result result = sphs_solve(&problem, second_nu, work);
  free(work);
  return result;
}

static double second_factor(const particle_set *p, int a, int k)
{
  const int n = sphs_count(p->dim);
  double f[SPHS_MAX];
  sphs_basis(p->dim, p->r[a][k], 2.0 / CUTOFF, f);
  return sphs_factor(p->dim, f, second_nu + a * n, second_nu + p->neigh[a][k] * n);
}

/* 'correction second' on the jittered set: the solver converges; every
   interior particle's Laplacian of a linear field is 0 and that of a
   quadratic field exact (regularisation 0), or close to it (the pair
   style's 1e-6; 'consistent' is off by 0.18 in 2-D, 0.098 in 3-D); the
   factors are symmetric and never negative, and energy is kept */
static void check_second(int dim, double regularization, double coarse)
{
  const int exact = regularization == 0.0;
  particle_set *p = &particles;
  make_jittered_lattice(p, dim, dim == 2 ? 30 : 12);
  if (!gather_pairs(p)) {
    expect(0, "neighbours within MAX_NEIGH", MAX_NEIGH + 1, MAX_NEIGH);
    return;
  }
  sphs_result one_level = {0, 0, 0, 0, 0.0, 0.0, 0};
  if (coarse > 0.0) one_level = solve_second(p, regularization, 0.0);
  const sphs_result result = solve_second(p, regularization, coarse);
  printf("%d-D, regularisation %g, coarse dimension %d: %d Newton steps, %d CG steps, residual "
         "%.2e, moments to %.2e, %d pairs at factor 0\n",
         dim, regularization, result.coarse_size, result.newton_steps, result.cg_steps,
         result.residual, result.moments, result.clipped);
  expect(result.converged, "the multipliers converge", result.residual, 1e-11);
  if (coarse > 0.0) {
    printf("%d-D: one level %d CG steps, two levels %d\n", dim, one_level.cg_steps,
           result.cg_steps);
    expect(result.coarse_size > 0, "a coarse space", result.coarse_size, 1.0);
    expect(one_level.converged, "one level converges too", one_level.residual, 1e-11);
    /* measured: 460 of 8,577 (2-D, 30 x 30), 54 of 221 (3-D, 12^3) */
    const int fewer = (dim == 2) ? 10 : 3;
    expect(fewer * result.cg_steps < one_level.cg_steps, "two levels: far fewer CG steps",
           result.cg_steps, (double) one_level.cg_steps / fewer);
  }

  static double linear[MAX_ATOMS], quadratic[MAX_ATOMS], t[MAX_ATOMS];
  for (int a = 0; a < p->n; a++) {
    const double x = p->x[a][0], y = p->x[a][1], z = p->x[a][2];
    linear[a] = 2.0 * x - 3.0 * y + z;
    quadratic[a] = x * x + 0.5 * y * y + 0.3 * x * y + 0.25 * z * z - 0.4 * x * z;
  }
  const double want = (dim == 2) ? 3.0 : 3.5;
  double plain_linear = 0.0, second_linear = 0.0, plain_quadratic = 0.0, second_quadratic = 0.0;
  for (int a = 0; a < p->n; a++) {
    if (!p->interior[a]) continue;
    double lap_linear = 0.0, lap_quadratic = 0.0;
    for (int k = 0; k < p->nneigh[a]; k++) {
      const double gw = p->g[a][k] * second_factor(p, a, k);
      const int b = p->neigh[a][k];
      lap_linear += 2.0 * gw * (linear[b] - linear[a]) / p->volume[a];
      lap_quadratic += 2.0 * gw * (quadratic[b] - quadratic[a]) / p->volume[a];
    }
    second_linear = fmax(second_linear, fabs(lap_linear));
    second_quadratic = fmax(second_quadratic, fabs(lap_quadratic - want) / want);
    if (!p->deep[a]) continue;
    plain_linear = fmax(plain_linear, fabs(laplacian(p, a, 0, linear)));
    plain_quadratic = fmax(plain_quadratic, fabs(laplacian(p, a, 0, quadratic) - want) / want);
  }
  printf("%d-D: |Laplacian of a linear field| plain %.3e, second %.3e; relative error of the "
         "quadratic's: plain %.3e, second %.3e\n",
         dim, plain_linear, second_linear, plain_quadratic, second_quadratic);
  expect(plain_linear > 0.1, "the plain Laplacian of a linear field shows the disorder",
         plain_linear, 0.1);
  /* measured with 1e-6: linear 9.3e-4 (2-D), quadratic 4.4e-3 */
  const double linear_bound = exact ? 1e-8 * plain_linear : 2e-3 * plain_linear;
  const double quadratic_bound = exact ? 1e-9 : 1e-2;
  expect(second_linear < linear_bound, "second: Laplacian of a linear field", second_linear,
         linear_bound);
  expect(second_quadratic < quadratic_bound, "second: Laplacian of a quadratic field",
         second_quadratic, quadratic_bound);
  expect(exact || result.moments > 1e-6,
         "the regularised moments are not exact (the regularisation acts)", result.moments, 1e-6);

  /* symmetric and non-negative factors, energy kept with two materials */
  double asymmetry = 0.0, lowest = 1.0, total = 0.0, magnitude = 0.0;
  for (int a = 0; a < p->n; a++) t[a] = uniform(0.0, 100.0);
  for (int a = 0; a < p->n; a++) {
    double sum = 0.0;
    for (int k = 0; k < p->nneigh[a]; k++) {
      const int b = p->neigh[a][k];
      int back = 0;
      while (back < p->nneigh[b] && p->neigh[b][back] != a) back++;
      const double w_ab = second_factor(p, a, k), w_ba = second_factor(p, b, back);
      asymmetry = fmax(asymmetry, fabs(w_ab - w_ba));
      lowest = fmin(lowest, w_ab);
      const double term = 2.0 * p->g[a][k] * w_ab * (t[b] - t[a]);
      sum += term;
      magnitude += fabs(term);
    }
    total += sum; /* m_a de_a, the pair term with k = 1 */
  }
  printf("%d-D: |w_ab - w_ba| %.3e, smallest factor %.3e, sum m de %.3e of %.3e\n", dim, asymmetry,
         lowest, total, magnitude);
  expect(asymmetry < 1e-13, "second: w_ab = w_ba", asymmetry, 0.0);
  expect(lowest >= 0.0, "second: no factor below 0", lowest, 0.0);
  expect(fabs(total) < 1e-12 * magnitude, "second: sum_a m_a de_a = 0", total, 0.0);
}

/* The coarse space holds the exact null fields of the pair arguments: a
   linear mu(x) on the grid's nodes with the second-moment part the columns
   attach (-(h/2) sym(grad mu)) leaves every pair's argument at 1; without
   that part it does not */
static void check_coarse(int dim)
{
  particle_set *p = &particles;
  make_jittered_lattice(p, dim, dim == 2 ? 20 : 10);
  if (!gather_pairs(p)) {
    expect(0, "neighbours within MAX_NEIGH", MAX_NEIGH + 1, MAX_NEIGH);
    return;
  }
  const sphs_problem problem = second_problem(p, 0.0, 2.0);
  sphs_coarse coarse;
  if (!sphs_coarse_setup(&problem, &coarse)) {
    expect(0, "a coarse grid", 0.0, 1.0);
    return;
  }
  const int n = coarse.n;
  printf("%d-D: coarse grid %d x %d x %d, dimension %d\n", dim, coarse.count[0], coarse.count[1],
         coarse.count[2], coarse.size);
  expect(coarse.count[0] > 2, "more than two nodes across", coarse.count[0], 3.0);
  const double b[3] = {0.3, -0.2, 0.1},
               slope[3][3] = {{0.05, -0.02, 0.03}, {0.01, 0.04, -0.03}, {-0.02, 0.02, 0.06}};
  static double nu[MAX_ATOMS * SPHS_MAX];
  static double bare[MAX_ATOMS * SPHS_MAX];
  static int index[27 * 3];
  static double columns[27 * 3 * SPHS_MAX];
  for (int a = 0; a < p->n; a++) {
    for (int l = 0; l < n; l++) nu[a * n + l] = bare[a * n + l] = 0.0;
    const int na = sphs_coarse_columns(&coarse, a, index, columns);
    for (int u = 0; u < na; u++) {
      const int node = index[u] / dim, k = index[u] % dim;
      const int at[3] = {node % coarse.count[0], (node / coarse.count[0]) % coarse.count[1],
                         node / (coarse.count[0] * coarse.count[1])};
      double value = b[k];
      for (int d = 0; d < dim; d++) value += slope[k][d] * at[d];
      for (int l = 0; l < n; l++) nu[a * n + l] += value * columns[u * n + l];
      bare[a * n + k] += value * columns[u * n + k];
    }
  }
  double worst = 0.0, worst_bare = 0.0;
  int checked = 0;
  for (int a = 0; a < p->n; a++) {
    if (!p->interior[a]) continue;
    for (int k = 0; k < p->nneigh[a]; k++) {
      const int c = p->neigh[a][k];
      if (!p->interior[c]) continue;
      double f[SPHS_MAX];
      sphs_basis(dim, p->r[a][k], 1.0 / problem.h, f);
      worst = fmax(worst, fabs(sphs_linear(dim, f, nu + a * n, nu + c * n)));
      worst_bare = fmax(worst_bare, fabs(sphs_linear(dim, f, bare + a * n, bare + c * n)));
      checked++;
    }
  }
  sphs_coarse_free(&coarse);
  printf("%d-D: %d pairs, |F.nu_a + F.nu_b| %.3e with the attached L, %.3e without\n", dim, checked,
         worst, worst_bare);
  expect(checked > 0, "pairs between constrained atoms", checked, 1.0);
  expect(worst < 1e-13, "a linear mu with L = -(h/2) sym(grad mu): arguments stay 1", worst, 0.0);
  expect(worst_bare > 1e-3, "without the attached L the arguments change", worst_bare, 1e-3);
}

int main(int argc, char **argv)
{
  const char *usage =
      "inverse | eigen | factors | cholesky | linear 2|3 | quadratic 2|3 | conservation 2|3 | "
      "second 2|3 | regularised 2|3 | coarse 2|3 | two-level 2|3";
  const int dim = (argc == 3) ? atoi(argv[2]) : 0;
  if (argc < 2 || argc > 3 || (argc == 3 && dim != 2 && dim != 3)) {
    fprintf(stderr, "usage: %s %s\n", argv[0], usage);
    return 2;
  }
  const char *check = argv[1];
  if (strcmp(check, "inverse") == 0 && argc == 2)
    check_inverse();
  else if (strcmp(check, "eigen") == 0 && argc == 2)
    check_eigen();
  else if (strcmp(check, "factors") == 0 && argc == 2) {
    check_factors();
    check_dimension_forms();
  } else if (strcmp(check, "cholesky") == 0 && argc == 2)
    check_cholesky();
  else if (strcmp(check, "second") == 0 && argc == 3)
    check_second(dim, 0.0, 0.0);
  else if (strcmp(check, "regularised") == 0 && argc == 3)
    check_second(dim, 1e-6, 0.0);
  else if (strcmp(check, "two-level") == 0 && argc == 3)
    check_second(dim, 0.0, 2.0);
  else if (strcmp(check, "coarse") == 0 && argc == 3)
    check_coarse(dim);
  else if (strcmp(check, "linear") == 0 && argc == 3)
    check_linear(dim);
  else if (strcmp(check, "quadratic") == 0 && argc == 3)
    check_quadratic(dim);
  else if (strcmp(check, "conservation") == 0 && argc == 3)
    check_conservation(dim);
  else {
    fprintf(stderr, "usage: %s %s\n", argv[0], usage);
    return 2;
  }
  if (failures == 0) printf("PASS %s\n", check);
  return failures ? 1 : 0;
}
