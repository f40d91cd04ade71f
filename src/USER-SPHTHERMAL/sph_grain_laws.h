/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: the exchange laws between a fluid and the unresolved
   grains in it (grains smaller than the kernel's support), in C99 (also
   C++). Each law is a small function chosen by name from a table; fix
   sph/grains evaluates them at each grain with the fluid's state
   interpolated there.

   Drag: F = beta (u - v), u the fluid's velocity at the grain, v the
   grain's, d its diameter, eps the porosity (fluid volume fraction) there,
   Re = eps rho d |u - v| / mu the particle Reynolds number.
     stokes   beta = 3 pi mu d (creeping flow around one sphere)
     difelice beta = (pi d^2 / 8) rho |u - v| Cd eps^(2 - chi),
              Cd = (0.63 + 4.8 / sqrt(Re))^2,
              chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2 / 2)
              (R. Di Felice, The voidage function for fluid-particle
              interaction systems, Int. J. Multiphase Flow 20 (1994)
              153-159; the drag of the SPH-DEM of Robinson, Ramaioli and
              Luding, Int. J. Multiphase Flow 59 (2014) 121-134). Cd's
              1/Re terms are expanded so that beta is finite at u = v.
     gidaspow beta = V beta_v / (1 - eps), V = pi d^3 / 6, with the
              momentum exchange coefficient per volume beta_v
              eps < 0.8:  Ergun's 150 (1 - eps)^2 mu / (eps d^2)
                          + 1.75 (1 - eps) rho |u - v| / d,
              eps >= 0.8: Wen and Yu's (3/4) Cd eps (1 - eps) rho |u - v|
                          eps^-2.65 / d, Cd = 24 (1 + 0.15 Re^0.687) / Re
                          (0.44 from Re = 1000 on)
              (D. Gidaspow, Multiphase Flow and Fluidization, Academic
              Press 1994; S. Ergun, Fluid flow through packed columns,
              Chem. Eng. Prog. 48 (1952) 89-94; C. Y. Wen and Y. H. Yu,
              Mechanics of fluidization, Chem. Eng. Prog. Symp. Ser. 62
              (1966) 100-111). A fixed bed with it has Ergun's pressure
              drop: eps dP/L = beta_v (u - v), U = eps (u - v).
   The fluid's force on the grain, in one of two forms (Zhou, Kuang, Chu and
   Yu, Discrete particle simulation of particle-fluid flow: model
   formulations and their applicability, J. Fluid Mech. 661 (2010)
   482-510: their models A and B, sets II and III):
     gradient    F = beta (u - v) - V grad P: the drag and the force of the
                 fluid's pressure gradient at the grain (model A);
     hydrostatic F = (beta / eps)(u - v) - V rho_f g: the pressure
                 gradient beyond the hydrostatic one carried by the drag,
                 the hydrostatic one's as buoyancy (model B).
   In a steady uniform bed, where eps grad P = -n beta (u - v) with n =
   (1 - eps) / V grains per volume (plus the weight of the fluid), they are
   the same force.
   Heat: Q = Nu k pi d (T_fluid - T_grain) (h = Nu k / d on the area pi d^2),
   Pr = mu cp / k.
     ranz-marshall Nu = 2 + 0.6 Re^(1/2) Pr^(1/3) (W. E. Ranz and W. R.
              Marshall, Evaporation from drops, Chem. Eng. Prog. 48 (1952)
              141-146 and 173-180)
     gunn     Nu = (7 - 10 eps + 5 eps^2)(1 + 0.7 Re^0.2 Pr^(1/3))
                   + (1.33 - 2.4 eps + 1.2 eps^2) Re^0.7 Pr^(1/3)
              (D. J. Gunn, Transfer of heat or mass to particles in fixed
              and fluidised beds, Int. J. Heat Mass Transfer 21 (1978)
              467-476)
------------------------------------------------------------------------- */

#ifndef SPH_GRAIN_LAWS_H
#define SPH_GRAIN_LAWS_H

#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum sphg_drag_kind {
  SPHG_DRAG_STOKES = 0,
  SPHG_DRAG_DIFELICE,
  SPHG_DRAG_GIDASPOW,
  SPHG_DRAG_NKINDS
};
enum sphg_heat_kind {
  SPHG_HEAT_NONE = 0,
  SPHG_HEAT_RANZ_MARSHALL,
  SPHG_HEAT_GUNN,
  SPHG_HEAT_NKINDS
};

enum sphg_pressure_kind {
  SPHG_PRESSURE_GRADIENT = 0,
  SPHG_PRESSURE_HYDROSTATIC,
  SPHG_PRESSURE_NKINDS
};

static inline const char *sphg_drag_name(int kind)
{
  static const char *names[SPHG_DRAG_NKINDS] = {"stokes", "difelice", "gidaspow"};
  return (kind >= 0 && kind < SPHG_DRAG_NKINDS) ? names[kind] : "?";
}

static inline const char *sphg_heat_name(int kind)
{
  static const char *names[SPHG_HEAT_NKINDS] = {"none", "ranz-marshall", "gunn"};
  return (kind >= 0 && kind < SPHG_HEAT_NKINDS) ? names[kind] : "?";
}

static inline const char *sphg_pressure_name(int kind)
{
  static const char *names[SPHG_PRESSURE_NKINDS] = {"gradient", "hydrostatic"};
  return (kind >= 0 && kind < SPHG_PRESSURE_NKINDS) ? names[kind] : "?";
}

/* -1 when the name is not a law */
static inline int sphg_drag_lookup(const char *name)
{
  int kind;
  for (kind = 0; kind < SPHG_DRAG_NKINDS; kind++)
    if (strcmp(name, sphg_drag_name(kind)) == 0) return kind;
  return -1;
}

static inline int sphg_heat_lookup(const char *name)
{
  int kind;
  for (kind = 0; kind < SPHG_HEAT_NKINDS; kind++)
    if (strcmp(name, sphg_heat_name(kind)) == 0) return kind;
  return -1;
}

static inline int sphg_pressure_lookup(const char *name)
{
  int kind;
  for (kind = 0; kind < SPHG_PRESSURE_NKINDS; kind++)
    if (strcmp(name, sphg_pressure_name(kind)) == 0) return kind;
  return -1;
}

/* the particle Reynolds number at slip speed w */
static inline double sphg_reynolds(double eps, double rho, double d, double w, double mu)
{
  return eps * rho * d * w / mu;
}

/* Di Felice's exponent of the porosity; 3.7 in the creeping limit */
static inline double sphg_difelice_chi(double re)
{
  double x;
  if (re <= 0.0) return 3.7;
  x = 1.5 - log10(re);
  return 3.7 - 0.65 * exp(-0.5 * x * x);
}

/* the drag coefficient beta (F = beta (u - v)) of a grain of diameter d at
   porosity eps, slip speed w >= 0, in a fluid of density rho and dynamic
   viscosity mu */
static inline double sphg_drag_beta(int kind, double d, double eps, double rho, double mu, double w)
{
  double scale, rho_w_cd, re;
  if (kind == SPHG_DRAG_STOKES) return 3.0 * M_PI * mu * d;
  if (kind == SPHG_DRAG_GIDASPOW) {
    const double volume = M_PI * d * d * d / 6.0;
    if (eps < 0.8) return volume * (150.0 * (1.0 - eps) * mu / (eps * d * d) + 1.75 * rho * w / d);
    /* rho w Cd, finite at w = 0 */
    re = sphg_reynolds(eps, rho, d, w, mu);
    rho_w_cd = (re < 1000.0) ? 24.0 * mu / (eps * d) * (1.0 + 0.15 * pow(re, 0.687))
                             : 0.44 * rho * w;
    return volume * 0.75 * rho_w_cd * pow(eps, -1.65) / d;
  }
  /* rho w Cd = rho w (0.63^2 + 2 (0.63)(4.8) / sqrt(Re) + 4.8^2 / Re) */
  scale = mu / (eps * d);
  rho_w_cd = 0.3969 * rho * w + 6.048 * sqrt(rho * w * scale) + 23.04 * scale;
  return 0.125 * M_PI * d * d * rho_w_cd *
      pow(eps, 2.0 - sphg_difelice_chi(sphg_reynolds(eps, rho, d, w, mu)));
}

/* the coefficient of the slip in the force of the given form: beta, or
   beta / eps when the drag carries the pressure gradient */
static inline double sphg_slip_coefficient(int pressure_kind, double beta, double eps)
{
  return pressure_kind == SPHG_PRESSURE_HYDROSTATIC ? beta / eps : beta;
}

/* the fluid's force f on a grain of volume V with drag coefficient beta,
   slip u - v and porosity eps: 'gradient' reads the fluid's pressure
   gradient grad_p, 'hydrostatic' its density rho_f and the body force's
   acceleration g (which may be NULL: none) */
static inline void sphg_fluid_force(int pressure_kind, double beta, double eps,
                                    const double slip[3], double volume, const double grad_p[3],
                                    double rho_f, const double *g, double f[3])
{
  const double c = sphg_slip_coefficient(pressure_kind, beta, eps);
  int k;
  for (k = 0; k < 3; k++) {
    f[k] = c * slip[k];
    if (pressure_kind == SPHG_PRESSURE_HYDROSTATIC) {
      if (g) f[k] -= volume * rho_f * g[k];
    } else
      f[k] -= volume * grad_p[k];
  }
}

/* the Nusselt number of a grain (0 for 'none') */
static inline double sphg_nusselt(int kind, double eps, double re, double pr)
{
  const double pr3 = cbrt(pr);
  switch (kind) {
    case SPHG_HEAT_RANZ_MARSHALL:
      return 2.0 + 0.6 * sqrt(re) * pr3;
    case SPHG_HEAT_GUNN:
      return (7.0 - 10.0 * eps + 5.0 * eps * eps) * (1.0 + 0.7 * pow(re, 0.2) * pr3) +
          (1.33 - 2.4 * eps + 1.2 * eps * eps) * pow(re, 0.7) * pr3;
    default:
      return 0.0;
  }
}

/* the conductance h A = Nu k pi d of a grain (Q = conductance (T_f - T_g)) */
static inline double sphg_conductance(int kind, double d, double eps, double rho, double mu,
                                      double k, double cp, double w)
{
  return sphg_nusselt(kind, eps, sphg_reynolds(eps, rho, d, w, mu), mu * cp / k) * k * M_PI * d;
}

#endif
