/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: equations of state of weakly compressible SPH, C99.

   An EOS is a name and its coefficients, with the reference density rho0
   of the material:
     tait    P = B ((rho / rho0)^gamma - 1) + P_b,  B = rho0 c0^2 / gamma
             (Reece et al. 2024, eq 11; Cleary 1998, eq 8 with P0 = B)
     linear  P = c0^2 (rho - rho0) + P_b            (Ng et al. 2020, eq 4)
   c0 is the speed of sound at rho0 and P_b a background pressure (default 0).
   With thermal expansion (Xu's thermal expansion, applied to a weakly
   compressible fluid) the reference density depends on temperature,
     rho0(T) = rho0 / (1 + beta (T - T0)),
   and takes the place of rho0 in both forms (B keeps rho0: the stiffness
   does not change with T), so that gravity alone makes hot fluid rise.
------------------------------------------------------------------------- */

#ifndef SPH_EOS_H
#define SPH_EOS_H

#include "sph_inline.h"

#include <math.h>
#include <string.h>

enum sphe_kind { SPHE_TAIT = 0, SPHE_LINEAR, SPHE_NKINDS };

typedef struct {
  int kind;
  double rho0;         /* reference density */
  double c0;           /* speed of sound at rho0 */
  double gamma;        /* tait: polytropic index */
  double p_background; /* added to the pressure */
  int thermal;         /* 1: the reference density depends on T */
  double beta;         /* thermal: volumetric expansion coefficient */
  double t0;           /* thermal: temperature at which it is rho0 */
} sphe_eos;

static inline const char *sphe_name(int kind)
{
  static const char *const names[SPHE_NKINDS] = {"tait", "linear"};
  return (kind >= 0 && kind < SPHE_NKINDS) ? names[kind] : 0;
}

static inline int sphe_lookup(const char *name)
{
  for (int kind = 0; kind < SPHE_NKINDS; kind++)
    if (strcmp(name, sphe_name(kind)) == 0) return kind;
  return -1;
}

/* coefficients on the command line after the name: tait c0 gamma, linear c0 */
static inline int sphe_ncoeffs(int kind)
{
  static const int ncoeffs[SPHE_NKINDS] = {2, 1};
  return (kind >= 0 && kind < SPHE_NKINDS) ? ncoeffs[kind] : 0;
}

/* x^gamma; small integer exponents (gamma = 7 is usual) by multiplication,
   several times faster than pow, which showed in the profile of a flow step */
static inline double sphe_power(double x, double gamma)
{
  const int n = (int) gamma;
  if (n == gamma && n >= 1 && n <= 8) {
    double result = x;
    for (int k = 1; k < n; k++) result *= x;
    return result;
  }
  return pow(x, gamma);
}

/* the bulk modulus at rho0, rho0 c0^2 (dP/drho = c0^2 at rho0 for both
   kinds): the pressure a relative compression costs */
static inline double sphe_bulk_modulus(const sphe_eos *eos)
{
  return eos->rho0 * eos->c0 * eos->c0;
}

/* the reference density at temperature T: rho0 without thermal expansion;
   not positive (or not finite) when 1 + beta (T - T0) <= 0, which callers
   must refuse */
static inline double sphe_reference_density(const sphe_eos *eos, double t)
{
  if (!eos->thermal) return eos->rho0;
  return eos->rho0 / (1.0 + eos->beta * (t - eos->t0));
}

/* pressure at density rho with the reference density rho_ref */
static inline double sphe_pressure_ref(const sphe_eos *eos, double rho, double rho_ref)
{
  const double c2 = eos->c0 * eos->c0;
  if (eos->kind == SPHE_TAIT)
    return eos->rho0 * c2 / eos->gamma * (sphe_power(rho / rho_ref, eos->gamma) - 1.0) +
        eos->p_background;
  return c2 * (rho - rho_ref) + eos->p_background;
}

static inline double sphe_pressure(const sphe_eos *eos, double rho)
{
  return sphe_pressure_ref(eos, rho, eos->rho0);
}

/* pressure at density rho and temperature T */
static inline double sphe_pressure_at(const sphe_eos *eos, double rho, double t)
{
  return sphe_pressure_ref(eos, rho, sphe_reference_density(eos, t));
}

/* the inverse: density at pressure P with the reference density rho_ref
   (walls of Adami et al. 2012); the tait form is clamped at rho = 0 for
   pressures below -B + P_b */
static inline double sphe_density_ref(const sphe_eos *eos, double p, double rho_ref)
{
  const double c2 = eos->c0 * eos->c0;
  if (eos->kind == SPHE_TAIT) {
    const double ratio = 1.0 + (p - eos->p_background) * eos->gamma / (eos->rho0 * c2);
    return (ratio > 0.0) ? rho_ref * pow(ratio, 1.0 / eos->gamma) : 0.0;
  }
  return rho_ref + (p - eos->p_background) / c2;
}

static inline double sphe_density(const sphe_eos *eos, double p)
{
  return sphe_density_ref(eos, p, eos->rho0);
}

/* sphe_density(eos, P_b + dp) - rho0: the density a pressure dp above the
   background adds (the hydrostatic part of Fourtakas's density diffusion),
   x = gamma dp / B: (1 + x)^(1/gamma) - 1 without cancellation, by its
   binomial series for |x| < 1e-2 (eight terms, the next below 1e-16 of the
   sum), else expm1(log1p(x) / gamma). A pair of one material needs it at
   +dp and -dp: the series' odd and even parts are summed once (Horner in
   x^2), from coefficients made once per material and step (pow here took
   half of a tait scene's step, and the coefficients' divisions made per
   call a third: bench/profile) */
typedef struct {
  double x_per_dp; /* gamma / B */
  double c[9];     /* binomial(1 / gamma, k) */
} sphe_tait_series;

static inline void sphe_tait_series_of(const sphe_eos *eos, sphe_tait_series *s)
{
  s->x_per_dp = eos->gamma / (eos->rho0 * eos->c0 * eos->c0);
  const double a = 1.0 / eos->gamma;
  s->c[0] = 1.0;
  for (int k = 1; k <= 8; k++) s->c[k] = s->c[k - 1] * (a - (k - 1)) / k;
}

/* the offset at x = gamma dp / B beyond the series */
static inline double sphe_tait_offset_far(const sphe_eos *eos, double x)
{
  if (x <= -1.0) return -eos->rho0;
  return eos->rho0 * expm1(log1p(x) / eos->gamma);
}

/* the offsets at +dp (up) and -dp (down); series: sphe_tait_series_of(eos)
   for tait (unused for linear) */
static inline SPH_ALWAYS_INLINE void sphe_hydrostatic_offsets(const sphe_eos *eos,
                                                              const sphe_tait_series *series,
                                                              double dp, double *up, double *down)
{
  if (eos->kind != SPHE_TAIT) {
    *up = dp / (eos->c0 * eos->c0);
    *down = -*up;
    return;
  }
  const double x = dp * series->x_per_dp;
  if (fabs(x) >= 1e-2) {
    *up = sphe_tait_offset_far(eos, x);
    *down = sphe_tait_offset_far(eos, -x);
    return;
  }
  const double *const c = series->c;
  const double x2 = x * x;
  const double odd = x * (c[1] + x2 * (c[3] + x2 * (c[5] + x2 * c[7])));
  const double even = x2 * (c[2] + x2 * (c[4] + x2 * (c[6] + x2 * c[8])));
  *up = eos->rho0 * (even + odd);
  *down = eos->rho0 * (even - odd);
}

/* the offset at dp alone */
static inline double sphe_hydrostatic_offset(const sphe_eos *eos, double dp)
{
  sphe_tait_series series;
  double up, down;
  if (eos->kind == SPHE_TAIT) sphe_tait_series_of(eos, &series);
  sphe_hydrostatic_offsets(eos, &series, dp, &up, &down);
  return up;
}

/* density at pressure P and temperature T */
static inline double sphe_density_at(const sphe_eos *eos, double p, double t)
{
  return sphe_density_ref(eos, p, sphe_reference_density(eos, t));
}

/* speed of sound sqrt(dP/drho) at rho (every atom every step, for the
   timestep: gamma = 7 takes the cube by multiplication) */
static inline double sphe_sound_speed(const sphe_eos *eos, double rho)
{
  if (eos->kind == SPHE_TAIT)
    return eos->c0 * sphe_power(rho / eos->rho0, 0.5 * (eos->gamma - 1.0));
  return eos->c0;
}

/* a column at rest under gravity g (> 0), as a Lagrangian column: the
   particle whose depth below the free surface is d0 when every particle has
   the density rho0 carries the weight of the mass above it, rho0 g d0 per
   unit area, so its pressure is P_b + rho0 g d0 and its density is that of
   the EOS at that pressure. Compressed, it sits at the depth
   d = int_0^d0 rho0 / rho(s) ds (closed forms below). d0 <= 0 (above the
   surface) gives rho0 and d = d0. */
static inline void sphe_hydrostatic(const sphe_eos *eos, double g, double d0, double *rho,
                                    double *d)
{
  if (d0 <= 0.0) {
    *rho = eos->rho0;
    *d = d0;
    return;
  }
  const double c2 = eos->c0 * eos->c0;
  if (eos->kind == SPHE_TAIT) {
    /* rho / rho0 = (1 + a s)^(1/gamma), a = gamma g / c0^2 */
    const double a = eos->gamma * g / c2;
    const double expo = 1.0 - 1.0 / eos->gamma;
    *rho = eos->rho0 * pow(1.0 + a * d0, 1.0 / eos->gamma);
    *d = (pow(1.0 + a * d0, expo) - 1.0) / (a * expo);
  } else {
    /* rho / rho0 = 1 + a s, a = g / c0^2 */
    const double a = g / c2;
    *rho = eos->rho0 * (1.0 + a * d0);
    *d = log1p(a * d0) / a;
  }
}

#endif
