/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: material laws (a property against temperature), C99.

   A law is a name, up to a few coefficients and an optional table:
     constant     p = c0
     linear       p = c0 + c1 (T - c2)
     exponential  p = c0 exp(c1 T)          (Cleary 1998, section 3.3: k = exp(4 T))
     table        p linear in T between (T_n, p_n), constant beyond the ends
   The same laws serve conductivity and, later, viscosity.
------------------------------------------------------------------------- */

#ifndef SPH_MATERIAL_LAWS_H
#define SPH_MATERIAL_LAWS_H

#include <float.h>
#include <math.h>
#include <string.h>

enum sphm_law_kind { SPHM_CONSTANT = 0, SPHM_LINEAR, SPHM_EXPONENTIAL, SPHM_TABLE, SPHM_NLAWS };

typedef struct {
  int kind;
  double c[3];           /* coefficients, as above */
  int ntable;            /* table: number of points, T increasing */
  const double *table_t; /* table: temperatures */
  const double *table_p; /* table: property values */
} sphm_law;

/* 1 when the two laws give the same property at every temperature (the
   same kind, coefficients and table): the atoms are one material for the
   property */
static inline int sphm_law_same(const sphm_law *a, const sphm_law *b)
{
  int n;
  if (a->kind != b->kind || a->c[0] != b->c[0] || a->c[1] != b->c[1] || a->c[2] != b->c[2] ||
      a->ntable != b->ntable)
    return 0;
  for (n = 0; n < a->ntable; n++)
    if (a->table_t[n] != b->table_t[n] || a->table_p[n] != b->table_p[n]) return 0;
  return 1;
}

static inline const char *sphm_law_name(int kind)
{
  static const char *const names[SPHM_NLAWS] = {"constant", "linear", "exponential", "table"};
  return (kind >= 0 && kind < SPHM_NLAWS) ? names[kind] : 0;
}

/* number of coefficients a law takes on its command line (table: variable) */
static inline int sphm_law_ncoeffs(int kind)
{
  static const int ncoeffs[SPHM_NLAWS] = {1, 3, 2, -1};
  return (kind >= 0 && kind < SPHM_NLAWS) ? ncoeffs[kind] : 0;
}

static inline int sphm_law_lookup(const char *name)
{
  for (int kind = 0; kind < SPHM_NLAWS; kind++)
    if (strcmp(name, sphm_law_name(kind)) == 0) return kind;
  return -1;
}

static inline double sphm_table_eval(const sphm_law *law, double T)
{
  const int n = law->ntable;
  const double *t = law->table_t, *p = law->table_p;
  if (T <= t[0]) return p[0];
  if (T >= t[n - 1]) return p[n - 1];
  int lo = 0, hi = n - 1; /* bisection: t[lo] <= T < t[hi] */
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (t[mid] <= T)
      lo = mid;
    else
      hi = mid;
  }
  return p[lo] + (p[hi] - p[lo]) * (T - t[lo]) / (t[hi] - t[lo]);
}

static inline double sphm_law_eval(const sphm_law *law, double T)
{
  switch (law->kind) {
    case SPHM_CONSTANT:
      return law->c[0];
    case SPHM_LINEAR:
      return law->c[0] + law->c[1] * (T - law->c[2]);
    case SPHM_EXPONENTIAL:
      return law->c[0] * exp(law->c[1] * T);
    case SPHM_TABLE:
      return sphm_table_eval(law, T);
    default:
      return 0.0;
  }
}

/* 1 when T lies inside the law's range of validity (a table: its first to
   last temperature; the other laws: any T) */
static inline int sphm_law_covers(const sphm_law *law, double T)
{
  if (law->kind != SPHM_TABLE) return 1;
  return T >= law->table_t[0] && T <= law->table_t[law->ntable - 1];
}

/* 1 when a conductivity or viscosity is a physical value: finite and >= 0
   (a linear law turns negative, an exponential one overflows) */
static inline int sphm_value_valid(double p)
{
  return p >= 0.0 && p <= DBL_MAX;
}

#endif
