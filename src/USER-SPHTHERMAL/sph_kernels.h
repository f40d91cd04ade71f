/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: smoothing kernels of SPH, in C99 (also valid C++).

   Every kernel is written on the dimensionless distance q = r / h:
     W(r, h)     = sigma_d / h^d     * f(q)
     dW/dr(r, h) = sigma_d / h^(d+1) * f'(q)
   and vanishes for q >= q_max (its support). LAMMPS's SPH pair styles take
   the support radius as the pair cutoff, so h = cutoff / q_max:
     lucy      q_max = 1  (h = cutoff, as in LAMMPS's SPH package)
     cubic     q_max = 2  (cubic B-spline, Monaghan 1992; Xu (LS-DYNA), eq 4)
     quintic   q_max = 3  (quintic spline, Morris et al. 1997; Ng et al. 2020)
     wendland  q_max = 2  (Wendland C2, Reece et al. 2024, eq 10)
   Wendland C2 uses the 2-D/3-D polynomial in 1-D as well (still positive
   and non-increasing); its 1-D constant normalises that polynomial.
------------------------------------------------------------------------- */

#ifndef SPH_KERNELS_H
#define SPH_KERNELS_H

#include <math.h>
#include <string.h>

#define SPHK_PI 3.14159265358979323846

enum sphk_kind { SPHK_LUCY = 0, SPHK_CUBIC, SPHK_QUINTIC, SPHK_WENDLAND, SPHK_NKINDS };

/* shape f(q) and its derivative f'(q); zero outside the support. Selects
   between values computed unconditionally rather than branches, so that
   loops over many pairs vectorise (see sphk_df_over_q) */

static inline double sphk_lucy_f(double q)
{
  const double u = 1.0 - q;
  return q < 1.0 ? (1.0 + 3.0 * q) * u * u * u : 0.0;
}

static inline double sphk_lucy_df(double q)
{
  const double u = 1.0 - q;
  return q < 1.0 ? -12.0 * q * u * u : 0.0;
}

static inline double sphk_cubic_f(double q)
{
  const double u = 2.0 - q;
  const double outer = 0.25 * u * u * u;
  return q < 1.0 ? 1.0 - 1.5 * q * q + 0.75 * q * q * q : (q < 2.0 ? outer : 0.0);
}

static inline double sphk_cubic_df(double q)
{
  const double u = 2.0 - q;
  const double outer = -0.75 * u * u;
  return q < 1.0 ? -3.0 * q + 2.25 * q * q : (q < 2.0 ? outer : 0.0);
}

/* (3-q)^5 - 6 (2-q)^5 + 15 (1-q)^5, each term only while its base is > 0 */
static inline double sphk_quintic_f(double q)
{
  const double u = 3.0 - q, u2 = u * u, v = 2.0 - q, v2 = v * v, w = 1.0 - q, w2 = w * w;
  const double f =
      u2 * u2 * u - (q < 2.0 ? 6.0 * v2 * v2 * v : 0.0) + (q < 1.0 ? 15.0 * w2 * w2 * w : 0.0);
  return q < 3.0 ? f : 0.0;
}

static inline double sphk_quintic_df(double q)
{
  const double u = 3.0 - q, u2 = u * u, v = 2.0 - q, v2 = v * v, w = 1.0 - q, w2 = w * w;
  const double df =
      -5.0 * u2 * u2 + (q < 2.0 ? 30.0 * v2 * v2 : 0.0) - (q < 1.0 ? 75.0 * w2 * w2 : 0.0);
  return q < 3.0 ? df : 0.0;
}

static inline double sphk_wendland_f(double q)
{
  const double u = 1.0 - 0.5 * q, u2 = u * u;
  return q < 2.0 ? u2 * u2 * (2.0 * q + 1.0) : 0.0;
}

static inline double sphk_wendland_df(double q)
{
  const double u = 1.0 - 0.5 * q;
  return q < 2.0 ? -5.0 * q * u * u * u : 0.0;
}

/* Dispatch on the kind. Called with a compile-time constant kind (as the
   templated pair loops do) the switch folds away. */

static inline double sphk_f(int kind, double q)
{
  switch (kind) {
    case SPHK_LUCY:
      return sphk_lucy_f(q);
    case SPHK_CUBIC:
      return sphk_cubic_f(q);
    case SPHK_QUINTIC:
      return sphk_quintic_f(q);
    case SPHK_WENDLAND:
      return sphk_wendland_f(q);
    default:
      return 0.0;
  }
}

static inline double sphk_df(int kind, double q)
{
  switch (kind) {
    case SPHK_LUCY:
      return sphk_lucy_df(q);
    case SPHK_CUBIC:
      return sphk_cubic_df(q);
    case SPHK_QUINTIC:
      return sphk_quintic_df(q);
    case SPHK_WENDLAND:
      return sphk_wendland_df(q);
    default:
      return 0.0;
  }
}

/* f'(q) / q, which pair loops use for dW/dr / r = sigma_d / h^(d+2) f'(q) / q:
   a polynomial without division where f' has the factor q (Lucy, Wendland
   C2, and the cubic and quintic splines for q < 1), f'(q) / q elsewhere
   (q >= 1 there), so that a loop need not divide by r. Written as selects
   between values computed unconditionally, without branches, so that a loop
   over many pairs vectorises (GCC needs -fno-math-errno -fno-trapping-math
   for that; the values are the same either way) */
static inline double sphk_df_over_q(int kind, double q)
{
  switch (kind) {
    case SPHK_LUCY: {
      const double u = 1.0 - q;
      return q < 1.0 ? -12.0 * u * u : 0.0;
    }
    case SPHK_CUBIC: {
      const double outer = sphk_cubic_df(q) / q; /* zero beyond the support */
      return q < 1.0 ? -3.0 + 2.25 * q : outer;
    }
    case SPHK_QUINTIC: {
      /* -5 (3-q)^4 + 30 (2-q)^4 - 75 (1-q)^4 = q (-120 + 120 q^2 - 50 q^3) */
      const double outer = sphk_quintic_df(q) / q;
      return q < 1.0 ? -120.0 + q * q * (120.0 - 50.0 * q) : outer;
    }
    case SPHK_WENDLAND: {
      const double u = 1.0 - 0.5 * q;
      return q < 2.0 ? -5.0 * u * u * u : 0.0;
    }
    default:
      return 0.0;
  }
}

/* name, support q_max and normalisation sigma_d for d = 1, 2, 3 */
static inline const char *sphk_name(int kind)
{
  static const char *const names[SPHK_NKINDS] = {"lucy", "cubic", "quintic", "wendland"};
  return (kind >= 0 && kind < SPHK_NKINDS) ? names[kind] : 0;
}

static inline double sphk_support(int kind)
{
  static const double q_max[SPHK_NKINDS] = {1.0, 2.0, 3.0, 2.0};
  return (kind >= 0 && kind < SPHK_NKINDS) ? q_max[kind] : 0.0;
}

static inline double sphk_sigma(int kind, int dim)
{
  static const double sigma[SPHK_NKINDS][3] = {
      {5.0 / 4.0, 5.0 / SPHK_PI, 105.0 / (16.0 * SPHK_PI)},
      {2.0 / 3.0, 10.0 / (7.0 * SPHK_PI), 1.0 / SPHK_PI},
      {1.0 / 120.0, 7.0 / (478.0 * SPHK_PI), 1.0 / (120.0 * SPHK_PI)},
      {3.0 / 4.0, 7.0 / (4.0 * SPHK_PI), 21.0 / (16.0 * SPHK_PI)}};
  if (kind < 0 || kind >= SPHK_NKINDS || dim < 1 || dim > 3) return 0.0;
  return sigma[kind][dim - 1];
}

/* kind from its name, -1 when unknown */
static inline int sphk_lookup(const char *name)
{
  for (int kind = 0; kind < SPHK_NKINDS; kind++)
    if (strcmp(name, sphk_name(kind)) == 0) return kind;
  return -1;
}

/* A kernel fixed to one dimension and one support radius (the cutoff). */
typedef struct {
  int kind, dim;
  double h;        /* smoothing length, cutoff / q_max */
  double inv_h;    /* 1 / h */
  double w_scale;  /* sigma_d / h^d */
  double dw_scale; /* sigma_d / h^(d+1) */
} sphk_kernel;

static inline sphk_kernel sphk_make(int kind, int dim, double cutoff)
{
  sphk_kernel k;
  k.kind = kind;
  k.dim = dim;
  k.h = cutoff / sphk_support(kind);
  k.inv_h = 1.0 / k.h;
  k.w_scale = sphk_sigma(kind, dim) * pow(k.inv_h, dim);
  k.dw_scale = k.w_scale * k.inv_h;
  return k;
}

static inline double sphk_w(const sphk_kernel *k, double r)
{
  return k->w_scale * sphk_f(k->kind, r * k->inv_h);
}

static inline double sphk_dwdr(const sphk_kernel *k, double r)
{
  return k->dw_scale * sphk_df(k->kind, r * k->inv_h);
}

#endif
