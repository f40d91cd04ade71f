/* Unit tests of sph_kernels.h, in C99 (also compiled as C++ to prove the
   header is valid C++). Usage: test_kernels <check> [dim]
   checks: normalisation <dim> | derivative | support | shape | over_q */

#include "sph_kernels.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double h_test = 0.37; /* any h: checks the h^d scaling too */

static int failures = 0;

static void expect(int ok, const char *kernel, const char *what, double got, double want)
{
  if (!ok) {
    failures++;
    printf("FAIL %-8s %s: got %.12g, expected %.12g\n", kernel, what, got, want);
  }
}

/* 5-point Gauss-Legendre on each of n sub-intervals of [a, b] */
static double integrate(double (*g)(const sphk_kernel *, double, int), const sphk_kernel *k,
                        int dim, double a, double b, int n)
{
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  double sum = 0.0, step = (b - a) / n;
  for (int i = 0; i < n; i++) {
    double mid = a + (i + 0.5) * step;
    for (int p = 0; p < 5; p++) sum += 0.5 * step * w[p] * g(k, mid + 0.5 * step * x[p], dim);
  }
  return sum;
}

/* W times the measure of a shell of radius r in dim dimensions */
static double shell_integrand(const sphk_kernel *k, double r, int dim)
{
  double w = sphk_w(k, r);
  if (dim == 1) return 2.0 * w;
  if (dim == 2) return 2.0 * SPHK_PI * r * w;
  return 4.0 * SPHK_PI * r * r * w;
}

static void check_normalisation(int dim)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++) {
    sphk_kernel k = sphk_make(kind, dim, sphk_support(kind) * h_test);
    /* the shapes are piecewise polynomial with breaks at integer q: integrate
       piece by piece so that the quadrature is exact up to round-off */
    double total = 0.0;
    for (int piece = 0; piece < (int) sphk_support(kind); piece++)
      total += integrate(shell_integrand, &k, dim, piece * h_test, (piece + 1) * h_test, 4);
    char what[64];
    snprintf(what, sizeof(what), "integral of W in %d-D", dim);
    expect(fabs(total - 1.0) < 1e-6, sphk_name(kind), what, total, 1.0);
  }
}

static void check_derivative(void)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++)
    for (int dim = 1; dim <= 3; dim++) {
      sphk_kernel k = sphk_make(kind, dim, sphk_support(kind) * h_test);
      double cut = sphk_support(kind) * h_test, scale = fabs(sphk_dwdr(&k, 0.3 * h_test));
      double worst = 0.0, at = 0.0;
      for (int i = 1; i < 1000; i++) {
        double r = cut * i / 1000.0, dr = 1e-6 * h_test;
        double fd = (sphk_w(&k, r + dr) - sphk_w(&k, r - dr)) / (2.0 * dr);
        double err = fabs(fd - sphk_dwdr(&k, r)) / scale;
        if (err > worst) worst = err, at = r;
      }
      char what[96];
      snprintf(what, sizeof(what), "dW/dr against finite differences in %d-D (worst at r/h = %g)",
               dim, at / h_test);
      expect(worst < 1e-6, sphk_name(kind), what, worst, 0.0);
    }
}

static void check_support(void)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++) {
    double cut = sphk_support(kind) * h_test;
    sphk_kernel k = sphk_make(kind, 2, cut);
    expect(fabs(k.h - h_test) < 1e-15, sphk_name(kind), "h = cutoff / support", k.h, h_test);
    const double at[4] = {cut, cut * (1.0 + 1e-12), 1.5 * cut, 10.0 * cut};
    for (int i = 0; i < 4; i++) {
      expect(sphk_w(&k, at[i]) == 0.0, sphk_name(kind), "W at or beyond the support",
             sphk_w(&k, at[i]), 0.0);
      expect(sphk_dwdr(&k, at[i]) == 0.0, sphk_name(kind), "dW/dr at or beyond the support",
             sphk_dwdr(&k, at[i]), 0.0);
    }
    /* vanishing smoothly: W just inside the support is tiny but positive */
    double inside = sphk_w(&k, cut * (1.0 - 1e-3));
    expect(inside > 0.0 && inside < 1e-6 * sphk_w(&k, 0.0), sphk_name(kind),
           "W just inside the support", inside, 0.0);
  }
  expect(sphk_lookup("cubic") == SPHK_CUBIC, "lookup", "cubic", sphk_lookup("cubic"), SPHK_CUBIC);
  expect(sphk_lookup("gaussian") == -1, "lookup", "unknown name", sphk_lookup("gaussian"), -1);
}

static void check_shape(void)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++) {
    double cut = sphk_support(kind) * h_test;
    sphk_kernel k = sphk_make(kind, 3, cut);
    double previous = sphk_w(&k, 0.0);
    expect(sphk_dwdr(&k, 0.0) == 0.0, sphk_name(kind), "dW/dr at r = 0", sphk_dwdr(&k, 0.0), 0.0);
    for (int i = 1; i < 2000; i++) {
      double r = cut * i / 2000.0, w = sphk_w(&k, r);
      if (!(w > 0.0) || w > previous || sphk_dwdr(&k, r) > 0.0) {
        expect(0, sphk_name(kind), "W positive and non-increasing inside the support", w, previous);
        break;
      }
      previous = w;
    }
  }
}

/* f'(q) / q (the pair loops' form, polynomial where it can be) equals
   f'(q) divided by q, through each piece's breaks and down to q = 0, where
   it tends to f''(0) (the polynomials are exact there, the quotient is not) */
static void check_over_q(void)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++) {
    const double support = sphk_support(kind);
    double worst = 0.0, at = 0.0;
    for (int i = 1; i <= 3000; i++) {
      const double q = support * i / 3000.0;
      const double want = sphk_df(kind, q) / q, got = sphk_df_over_q(kind, q);
      const double err = fabs(got - want) / (1.0 + fabs(want));
      if (err > worst) worst = err, at = q;
    }
    char what[96];
    snprintf(what, sizeof(what), "f'(q)/q against f'(q) / q (worst at q = %g)", at);
    expect(worst < 1e-12, sphk_name(kind), what, worst, 0.0);
    /* q -> 0: the second derivative of f at 0, by central differences of f' */
    const double dq = 1e-5, second = (sphk_df(kind, dq) - sphk_df(kind, -dq)) / (2.0 * dq);
    expect(fabs(sphk_df_over_q(kind, 0.0) - second) < 1e-6 * (1.0 + fabs(second)),
           sphk_name(kind), "f'(q)/q at q = 0 against f''(0)", sphk_df_over_q(kind, 0.0), second);
    expect(sphk_df_over_q(kind, support) == 0.0, sphk_name(kind), "f'(q)/q at the support",
           sphk_df_over_q(kind, support), 0.0);
    /* beyond it (the selects must not let a piece's polynomial through) */
    for (int i = 1; i <= 4; i++) {
      const double q = support * (1.0 + 0.5 * i);
      expect(sphk_df_over_q(kind, q) == 0.0, sphk_name(kind), "f'(q)/q beyond the support",
             sphk_df_over_q(kind, q), 0.0);
    }
  }
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: %s normalisation <dim> | derivative | support | shape | over_q\n", argv[0]);
    return 2;
  }
  if (strcmp(argv[1], "normalisation") == 0 && argc == 3)
    check_normalisation(atoi(argv[2]));
  else if (strcmp(argv[1], "derivative") == 0)
    check_derivative();
  else if (strcmp(argv[1], "support") == 0)
    check_support();
  else if (strcmp(argv[1], "shape") == 0)
    check_shape();
  else if (strcmp(argv[1], "over_q") == 0)
    check_over_q();
  else {
    fprintf(stderr, "unknown check %s\n", argv[1]);
    return 2;
  }
  if (failures == 0) printf("PASS %s\n", argv[1]);
  return failures ? 1 : 0;
}
