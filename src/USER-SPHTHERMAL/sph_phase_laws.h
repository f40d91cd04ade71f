/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: melting and solidification by the enthalpy method, in
   C99 (also C++). A particle of a type that changes phase keeps integrating
   its specific energy e (esph), which then includes the latent heat, so
   that energy stays conserved to round-off through the change of phase;
   its temperature and liquid fraction follow from e.

   With cv the solid's specific heat, cl the liquid's (cl = cv unless the
   law gives it), L the latent heat per mass and the mushy zone between the
   solidus Ts and the liquidus Tl, where the liquid fraction rises linearly
   in T (the enthalpy form of V. R. Voller and C. Prakash, A fixed grid
   numerical modelling methodology for convection-diffusion mushy region
   phase-change problems, Int. J. Heat Mass Transfer 30 (1987) 1709-1719,
   with their linear liquid fraction):
     e(T) = cv T                     T <= Ts
            cv T + L f(T)            Ts < T < Tl, f(T) = (T - Ts) / (Tl - Ts)
            cv Tl + L + cl (T - Tl)  T >= Tl
   (the mushy zone's sensible heat is the solid's: the latent heat
   dominates there); so, from e:
     e <= cv Ts             solid:  T = e / cv,                 f = 0
     e >= cv Tl + L         liquid: T = Tl + (e - cv Tl - L) / cl, f = 1
     between                mushy:  f = (e - cv Ts) / (cv (Tl - Ts) + L),
                                    T = Ts + f (Tl - Ts).
   Ts = Tl is a pure substance's single melting temperature: there the mushy
   particle holds T = Ts while its fraction f = (e - cv Ts) / L moves, and
   e(Ts) is the solid's (a particle set to the melting point starts solid).
------------------------------------------------------------------------- */

#ifndef SPH_PHASE_LAWS_H
#define SPH_PHASE_LAWS_H

typedef struct SPHPhaseLaw {
  double solidus;     /* Ts (temperature units) */
  double liquidus;    /* Tl >= Ts */
  double latent;      /* L (energy / mass units), > 0 */
  double liquid_cv;   /* cl, the liquid's specific heat; 0: the solid's cv */
} SPHPhaseLaw;

/* the liquid's specific heat, cv the solid's */
static inline double sphp_liquid_cv(double cv, const SPHPhaseLaw *law)
{
  return law->liquid_cv > 0.0 ? law->liquid_cv : cv;
}

/* the liquid fraction of specific energy e (cv the specific heat) */
static inline double sphp_liquid_fraction(double e, double cv, const SPHPhaseLaw *law)
{
  const double start = cv * law->solidus;
  if (e <= start) return 0.0;
  const double width = cv * (law->liquidus - law->solidus) + law->latent;
  const double f = (e - start) / width;
  return f < 1.0 ? f : 1.0;
}

/* the temperature of specific energy e */
static inline double sphp_temperature(double e, double cv, const SPHPhaseLaw *law)
{
  const double start = cv * law->solidus;
  if (e <= start) return e / cv;
  const double melted = cv * law->liquidus + law->latent;
  if (e >= melted) /* (e - L) / cv where cl = cv, its simpler round-off */
    return law->liquid_cv > 0.0 ? law->liquidus + (e - melted) / law->liquid_cv
                                : (e - law->latent) / cv;
  return law->solidus + sphp_liquid_fraction(e, cv, law) * (law->liquidus - law->solidus);
}

/* the specific energy at temperature T (at T = Ts = Tl: the solid's) */
static inline double sphp_energy(double T, double cv, const SPHPhaseLaw *law)
{
  if (T <= law->solidus) return cv * T;
  if (T >= law->liquidus)
    return law->liquid_cv > 0.0
        ? cv * law->liquidus + law->latent + law->liquid_cv * (T - law->liquidus)
        : cv * T + law->latent;
  return cv * T + law->latent * (T - law->solidus) / (law->liquidus - law->solidus);
}

/* de/dT at specific energy e: cv in the solid, cl in the liquid, cv + L /
   (Tl - Ts) in the mushy zone (0 for a single melting temperature: T does
   not move there, so no change of T maps to a change of e) */
static inline double sphp_heat_capacity(double e, double cv, const SPHPhaseLaw *law)
{
  const double f = sphp_liquid_fraction(e, cv, law);
  if (f <= 0.0) return cv;
  if (f >= 1.0) return sphp_liquid_cv(cv, law);
  if (law->liquidus <= law->solidus) return 0.0;
  return cv + law->latent / (law->liquidus - law->solidus);
}

/* the specific heat of the phases at specific energy e, without the latent
   heat: (1 - f) cv + f cl, the weight of the particle's temperature in a
   mean by heat capacity */
static inline double sphp_sensible_cv(double e, double cv, const SPHPhaseLaw *law)
{
  if (!(law->liquid_cv > 0.0)) return cv;
  const double f = sphp_liquid_fraction(e, cv, law);
  return (1.0 - f) * cv + f * law->liquid_cv;
}

/* the smaller of the two phases' specific heats: the one that bounds the
   explicit conduction's timestep whatever the particle's phase */
static inline double sphp_smallest_cv(double cv, const SPHPhaseLaw *law)
{
  const double cl = sphp_liquid_cv(cv, law);
  return cl < cv ? cl : cv;
}

#endif
