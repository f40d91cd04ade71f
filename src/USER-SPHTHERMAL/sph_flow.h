/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: pair terms of weakly compressible SPH flow, C99.

   For a pair a, b at distance r (r_ab = x_a - x_b, v_ab = v_a - v_b) with
   dW/dr = dwdr (<= 0) the terms below return scalars s such that
     pressure:   force on a  = s * r_ab           (force on b = -that)
     viscosity:  force on a  = s * r_ab  (cleary) or s * v_ab (morris, adami)
     continuity: drho_a/dt  += s * (v_ab . r_ab)
   so every pair conserves momentum exactly. m = mass, rho = density,
   P = pressure, mu = dynamic viscosity, eta2 = eta^2 regularises r -> 0.

   Pressure (the paper's continuity equation goes with each form):
     symmetric  Cleary 1998, eq 4: -m_a m_b (P_a / rho_a^2 + P_b / rho_b^2) grad W;
                eq 3: drho_a = sum m_b v_ab . grad W
     sum        Reece et al. 2024, eq 8: -m_a m_b (P_a + P_b) / (rho_a rho_b) grad W;
                eq 7: drho_a = rho_a sum V_b v_ab . grad W
     averaged   Ng et al. 2020, eq 7: -(V_a^2 + V_b^2) (P_a rho_b + P_b rho_a) /
                (rho_a + rho_b) grad W, V = m / rho (stable for large density
                ratios); eq 5: as Reece et al. 2024, eq 7
   Viscosity:
     cleary     Cleary 1998, eq 4: xi m_a m_b / (rho_a rho_b) 4 mu_a mu_b /
                (mu_a + mu_b) (v_ab . r_ab) / (r^2 + eta^2) grad W
     adami      Ng et al. 2020, eq 7: (V_a^2 + V_b^2) 2 mu_a mu_b / (mu_a + mu_b)
                v_ab dW/dr r / (r^2 + eta^2)   (harmonic mean)
     morris     Reece et al. 2024, eq 12 (the form of eq 14 with a consistent
                operator): m_a m_b 2 (nu_a + nu_b) / (rho_a + rho_b)
                v_ab dW/dr r / (r^2 + eta^2), nu = mu / rho (arithmetic mean)
------------------------------------------------------------------------- */

#ifndef SPH_FLOW_H
#define SPH_FLOW_H

#include <string.h>

enum sphf_pressure_form { SPHF_P_SYMMETRIC = 0, SPHF_P_SUM, SPHF_P_AVERAGED, SPHF_P_NFORMS };
enum sphf_viscosity_form { SPHF_V_CLEARY = 0, SPHF_V_ADAMI, SPHF_V_MORRIS, SPHF_V_NFORMS };

/* xi of Cleary 1998, eq 4, calibrated by Cleary on transient Couette flow */
#define SPHF_XI_CLEARY 4.96333

static inline const char *sphf_pressure_name(int form)
{
  static const char *const names[SPHF_P_NFORMS] = {"symmetric", "sum", "averaged"};
  return (form >= 0 && form < SPHF_P_NFORMS) ? names[form] : 0;
}

static inline const char *sphf_viscosity_name(int form)
{
  static const char *const names[SPHF_V_NFORMS] = {"cleary", "adami", "morris"};
  return (form >= 0 && form < SPHF_V_NFORMS) ? names[form] : 0;
}

static inline int sphf_pressure_lookup(const char *name)
{
  for (int form = 0; form < SPHF_P_NFORMS; form++)
    if (strcmp(name, sphf_pressure_name(form)) == 0) return form;
  return -1;
}

static inline int sphf_viscosity_lookup(const char *name)
{
  for (int form = 0; form < SPHF_V_NFORMS; form++)
    if (strcmp(name, sphf_viscosity_name(form)) == 0) return form;
  return -1;
}

/* s with force on a = s r_ab; dwdr_r = dW/dr / r */
static inline double sphf_pressure_pair(int form, double m_a, double m_b, double rho_a,
                                        double rho_b, double p_a, double p_b, double dwdr_r)
{
  if (form == SPHF_P_SYMMETRIC)
    return -m_a * m_b * (p_a / (rho_a * rho_a) + p_b / (rho_b * rho_b)) * dwdr_r;
  if (form == SPHF_P_SUM) return -m_a * m_b * (p_a + p_b) / (rho_a * rho_b) * dwdr_r;
  const double v_a = m_a / rho_a, v_b = m_b / rho_b;
  const double p_avg = (p_a * rho_b + p_b * rho_a) / (rho_a + rho_b);
  return -(v_a * v_a + v_b * v_b) * p_avg * dwdr_r;
}

/* cleary: s with force on a = s r_ab; adami, morris: s with force on a = s v_ab.
   vr = v_ab . r_ab (used by cleary only); dwdr_rr = dW/dr r / (r^2 + eta^2);
   dwdr_r = dW/dr / r */
static inline double sphf_viscosity_pair(int form, double xi, double m_a, double m_b,
                                         double rho_a, double rho_b, double mu_a, double mu_b,
                                         double vr, double dwdr_r, double inv_r2eta2,
                                         double dwdr_rr)
{
  const double mu_sum = mu_a + mu_b;
  if (form == SPHF_V_CLEARY) {
    const double mu_h = (mu_sum > 0.0) ? 4.0 * mu_a * mu_b / mu_sum : 0.0;
    return xi * m_a * m_b / (rho_a * rho_b) * mu_h * vr * inv_r2eta2 * dwdr_r;
  }
  if (form == SPHF_V_ADAMI) {
    const double v_a = m_a / rho_a, v_b = m_b / rho_b;
    const double mu_h = (mu_sum > 0.0) ? 2.0 * mu_a * mu_b / mu_sum : 0.0;
    return (v_a * v_a + v_b * v_b) * mu_h * dwdr_rr;
  }
  return m_a * m_b * 2.0 * (mu_a / rho_a + mu_b / rho_b) / (rho_a + rho_b) * dwdr_rr;
}

/* drho_a/dt += s (v_ab . r_ab): symmetric m_b dW/dr / r; the others
   rho_a m_b / rho_b dW/dr / r */
static inline double sphf_continuity_pair(int form, double m_b, double rho_a, double rho_b,
                                          double dwdr_r)
{
  if (form == SPHF_P_SYMMETRIC) return m_b * dwdr_r;
  return rho_a * m_b / rho_b * dwdr_r;
}

/* viscous heating (the viscous term of Reece et al. 2024, eq 4, which they
   neglect; Xu's fraction of the mechanical work converted to heat scales
   it): the pair's viscous force on a, F = s_rv r_ab + s_v v_ab (s_rv, s_v of
   sphf_pair; v_ab the velocities it was evaluated with), removes kinetic
   energy at the rate P = -F . u_ab, u_ab the difference of the velocities
   the particles actually move with; the caller gives P to a and b as heat,
   so kinetic plus thermal energy is conserved pairwise. P >= 0 when u = v. */
static inline double sphf_viscous_power(double s_rv, double s_v, const double r_ab[3],
                                        const double v_ab[3], const double u_ab[3])
{
  const double r_u = r_ab[0] * u_ab[0] + r_ab[1] * u_ab[1] + r_ab[2] * u_ab[2];
  const double v_u = v_ab[0] * u_ab[0] + v_ab[1] * u_ab[1] + v_ab[2] * u_ab[2];
  return -(s_rv * r_u + s_v * v_u);
}

/* density diffusion of Molteni & Colagrossi (Ng et al. 2020, eqs 5-6):
   drho_a/dt += 2 delta h c0 sum (rho_b - rho_a) V_b (r_ba . grad_a W) / r^2
             =  s (rho_b - rho_a) with s = -2 delta h c0 V_b dW/dr / r */
static inline double sphf_diffusion_pair(double delta_h_c0, double volume_b, double dwdr_r)
{
  return -2.0 * delta_h_c0 * volume_b * dwdr_r;
}

/* artificial viscosity of Monaghan (1992; used for free-surface flows in
   Monaghan 1994): Pi_ab = -alpha h c_ab mu_ab / rho_ab for approaching
   pairs (v_ab . r_ab < 0), 0 otherwise, mu_ab = (v_ab . r_ab) / (r^2 +
   0.01 h^2), c_ab and rho_ab the pair's mean speed of sound and density;
   dv_a/dt += -m_b Pi_ab grad_a W. Returns s with force on a = s r_ab
   (>= 0: it only pushes approaching particles apart). alpha_h_c = alpha h
   c_ab; vr = v_ab . r_ab; h2 = h^2; dwdr_r = dW/dr / r. */
/* The package applies it only to pairs with a particle at a free surface,
   one whose Shepard sum sum_b V_b W_ab (itself and wall particles
   included) is below SPHF_SURFACE_SHEPARD, and to pairs of a fluid and a
   wall particle: where a free surface or its splash strikes a wall. The
   sum is about 1 inside the fluid and next to walls, which complete the
   kernel's support, and about 0.5 on a free surface, so the term acts
   over the outer rows and at walls and leaves the bulk alone. A free
   surface's particles lack the pressure and the density diffusion that
   damp the bulk: without it a thin film on a wall oscillates against it
   and goes through, and an impact on a wall blows up. */
#define SPHF_SURFACE_SHEPARD 0.9

static inline double sphf_artificial_pair(double alpha_h_c, double m_a, double m_b, double rho_a,
                                          double rho_b, double vr, double rsq, double h2,
                                          double dwdr_r)
{
  if (!(vr < 0.0)) return 0.0;
  const double mu_ab = vr / (rsq + 0.01 * h2);
  const double pi_ab = -alpha_h_c * mu_ab * 2.0 / (rho_a + rho_b);
  return -m_a * m_b * pi_ab * dwdr_r;
}

/* The pair loop's form of the terms above, with one division per pair
   instead of six (the divisions dominate the cost of a pair): the
   denominators of pressure, viscosity and 1/(r^2 + eta^2) are multiplied
   and inverted once, and that division does not wait for the square root
   of the pair's distance (it takes r^2 and dW/dr / r, which sph_kernels.h
   gives without dividing by r). Particle state: m, rho, V = m / rho, P, mu.
   Returns through the pointers: s_r (force on a along r_ab: pressure and
   the cleary viscosity), s_rv (the cleary viscosity's share of s_r, 0 for
   the other forms), s_v (force on a along v_ab: adami and morris
   viscosity), c_a and c_b (drho_a += c_a (v_ab . r_ab), drho_b += c_b
   (v_ab . r_ab)), and inv_other = 1 / other_den from the same division,
   for a caller that evaluates another pair term in the same loop (the
   conduction of sph_conduction.h; 1 when none). Equal to the separate terms
   to round-off (test_flow_terms fused). */
typedef struct {
  double m, rho, vol, p, mu;
} sphf_particle;

static inline void sphf_pair(int pform, int vform, double xi, const sphf_particle *a,
                             const sphf_particle *b, double rsq, double dwdr_r, double eta2,
                             double vr, double other_den, double *s_r, double *s_rv, double *s_v,
                             double *c_a, double *c_b, double *inv_other)
{
  const double rho_ab = a->rho * b->rho;
  double num_p, den_p;
  if (pform == SPHF_P_AVERAGED) {
    num_p = (a->vol * a->vol + b->vol * b->vol) * (a->p * b->rho + b->p * a->rho);
    den_p = a->rho + b->rho;
  } else if (pform == SPHF_P_SUM) {
    num_p = a->m * b->m * (a->p + b->p);
    den_p = rho_ab;
  } else {
    num_p = a->m * b->m * (a->p * b->rho * b->rho + b->p * a->rho * a->rho);
    den_p = rho_ab * rho_ab;
  }
  double num_v, den_v;
  const double mu_sum = a->mu + b->mu;
  if (vform == SPHF_V_MORRIS) {
    num_v = a->m * b->m * 2.0 * (a->mu * b->rho + b->mu * a->rho);
    den_v = rho_ab * (a->rho + b->rho);
  } else {
    const double ok = (mu_sum > 0.0);
    num_v = ok * ((vform == SPHF_V_ADAMI) ? (a->vol * a->vol + b->vol * b->vol) * 2.0
                                           : xi * a->m * b->m * 4.0) *
        a->mu * b->mu;
    den_v = ok ? ((vform == SPHF_V_ADAMI) ? mu_sum : rho_ab * mu_sum) : 1.0;
  }
  const double r2eta2 = rsq + eta2;
  const double inv_all = 1.0 / (den_p * den_v * r2eta2 * other_den);
  const double inv_p = den_v * r2eta2 * other_den * inv_all;    /* 1 / den_p */
  const double inv_v = den_p * other_den * inv_all;             /* 1 / (den_v (r^2 + eta^2)) */
  *inv_other = den_p * den_v * r2eta2 * inv_all;
  *s_r = -num_p * dwdr_r * inv_p;
  *s_rv = 0.0;
  *s_v = 0.0;
  if (vform == SPHF_V_CLEARY) {
    *s_rv = num_v * vr * dwdr_r * inv_v;
    *s_r += *s_rv;
  } else
    *s_v = num_v * rsq * dwdr_r * inv_v;
  if (pform == SPHF_P_SYMMETRIC) {
    *c_a = b->m * dwdr_r;
    *c_b = a->m * dwdr_r;
  } else {
    *c_a = a->rho * b->vol * dwdr_r;
    *c_b = b->rho * a->vol * dwdr_r;
  }
}

#endif
