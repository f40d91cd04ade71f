/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: the Boussinesq buoyancy term, in C99 (also C++).

   Body force per unit mass of a fluid of expansion coefficient beta at
   temperature T, with g the gravity vector and T0 the reference
   temperature (Reece et al. 2024, eq 15; Cleary 1998, section 4, replaces
   g by beta g (T - T0) with the opposite sign, a misprint):
     a = -g beta (T - T0)
   so fluid warmer than T0 rises against g.
------------------------------------------------------------------------- */

#ifndef SPH_BUOYANCY_H
#define SPH_BUOYANCY_H

static inline void sphb_acceleration(const double g[3], double beta, double t, double t0,
                                     double a[3])
{
  const double s = -beta * (t - t0);
  a[0] = s * g[0];
  a[1] = s * g[1];
  a[2] = s * g[2];
}

#endif
