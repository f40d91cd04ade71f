/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: particle shifting, in C99 (also C++).

   The shift of Skillen et al. 2013 as Reece et al. 2024 use it (eq 38):
     dr_i = -D h |v_i| dt grad C_i,   grad C_i = sum_j V_j grad_i W_ij
   with C the kernel sum of the particles' volumes, so that particles move
   from where they crowd to where they are sparse when D > 0. Reece et al.
   print the term with a leading minus and D = -2 (their Table 2); with
   both signs the particles would move towards crowding: D = -2 is the
   coefficient of DualSPHysics, whose formula has no leading minus, so
   D = 2 here is their setting.

   The delta-plus shift of Sun, Colagrossi, Marrone & Zhang 2017 (as Ng,
   Ng, Sheu & Mukhtar 2020 use it, eqs 19-20, whose printed prefactor lacks
   the (2h)^2 that gives it units of length squared):
     dr_i = -C CFL Ma (2h)^2 sum_j [1 + R (W_ij / W(dx))^n] grad_i W_ij V_j
   with CFL Ma = (c0 dt / h) (U / c0) = U dt / h for a reference speed U;
   R = 0.2 and n = 4 as in Monaghan's artificial pressure, which keeps
   particles from pairing.
------------------------------------------------------------------------- */

#ifndef SPH_SHIFT_H
#define SPH_SHIFT_H

#include <math.h>

/* the factor s of dr = s grad_c: -D h |v| dt */
static inline double sphs_skillen_factor(double coefficient, double h, double speed, double dt)
{
  return -coefficient * h * speed * dt;
}

/* dr = -D h |v| dt grad_c */
static inline void sphs_skillen(double coefficient, double h, double speed, double dt,
                                const double grad_c[3], double dr[3])
{
  const double s = sphs_skillen_factor(coefficient, h, speed, dt);
  dr[0] = s * grad_c[0];
  dr[1] = s * grad_c[1];
  dr[2] = s * grad_c[2];
}

/* the delta-plus pair weight 1 + R (W_ij / W(dx))^n */
static inline double sphs_deltaplus_weight(double w_ij, double w_spacing, double r_coeff,
                                           int n)
{
  /* R = 0: no term, even where the ratio is not finite (W(dx) = 0) */
  if (r_coeff == 0.0) return 1.0;
  const double ratio = w_ij / w_spacing;
  double power = 1.0;
  for (int k = 0; k < n; k++) power *= ratio;
  return 1.0 + r_coeff * power;
}

/* the factor s of dr = s sum_grad: -C (U dt / h) (2h)^2 */
static inline double sphs_deltaplus_factor(double coefficient, double h, double speed, double dt)
{
  return -coefficient * speed * dt / h * 4.0 * h * h;
}

/* dr = -C (U dt / h) (2h)^2 sum_grad, sum_grad = sum_j weight_ij grad_i W_ij V_j */
static inline void sphs_deltaplus(double coefficient, double h, double speed, double dt,
                                  const double sum_grad[3], double dr[3])
{
  const double s = sphs_deltaplus_factor(coefficient, h, speed, dt);
  dr[0] = s * sum_grad[0];
  dr[1] = s * sum_grad[1];
  dr[2] = s * sum_grad[2];
}

/* shorten dr to at most 'limit' long; returns 1 when it was shortened */
static inline int sphs_cap(double dr[3], double limit)
{
  const double length = sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]);
  if (!(length > limit)) return 0;
  const double s = limit / length;
  dr[0] *= s;
  dr[1] *= s;
  dr[2] *= s;
  return 1;
}

/* dr = s g shortened to at most 'limit' long; returns 1 when it was
   shortened. Where s g or the square of its length overflows (a huge
   coefficient), the capped shift still runs along sign(s) g at the limit:
   g is scaled by its largest component first. (Without that the length is
   inf, limit / inf = 0, and every capped shift would be 0.) A NaN s or g,
   or an infinite g, leaves dr not finite, for the caller to see. */
static inline int sphs_cap_along(double s, const double g[3], double limit, double dr[3])
{
  /* a zero component stays 0 even for an infinite s */
  for (int a = 0; a < 3; a++) dr[a] = (g[a] == 0.0) ? 0.0 : s * g[a];
  if (!isinf(sqrt(dr[0] * dr[0] + dr[1] * dr[1] + dr[2] * dr[2]))) return sphs_cap(dr, limit);
  /* the length overflowed: |g| from g / max |g_a|, whose length is 1 to sqrt(3) */
  const double m = fmax(fabs(g[0]), fmax(fabs(g[1]), fabs(g[2])));
  if (!isfinite(m)) return 0;
  const double u[3] = {g[0] / m, g[1] / m, g[2] / m};
  const double k = (s < 0.0 ? -limit : limit) / sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (int a = 0; a < 3; a++) dr[a] = k * u[a];
  return 1;
}

#endif
