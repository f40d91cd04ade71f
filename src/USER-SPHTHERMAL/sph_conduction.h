/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: pair terms of SPH heat conduction, in C99 (also C++).

   A pair term returns the factor F_ab of the specific-energy rates
     de_a/dt += m_b F_ab,   de_b/dt -= m_a F_ab,
   so that m_a de_a + m_b de_b = 0: the pair conserves thermal energy
   exactly whatever the kernel, the masses or the conductivities.
------------------------------------------------------------------------- */

#ifndef SPH_CONDUCTION_H
#define SPH_CONDUCTION_H

/* The conductance is twice a mean of the two conductivities, so that both
   reduce to 2 k for a single material.
   Harmonic (Cleary 1998, eq 6; Ng et al. 2020, eq 10;
   Reece et al. 2024, eq 9): 4 k_a k_b / (k_a + k_b),
   0 when both are 0 (an adiabatic k = 0 material); keeps the heat flux
   continuous across interfaces.
   Arithmetic (Xu (LS-DYNA), eq 11 with its erratum, Brookshaw): k_a + k_b.
   References: doc/src/Bibliography_sphthermal.rst. */
static inline double sphc_harmonic_conductance(double k_a, double k_b)
{
  const double sum = k_a + k_b;
  return (sum > 0.0) ? 4.0 * k_a * k_b / sum : 0.0;
}

static inline double sphc_arithmetic_conductance(double k_a, double k_b)
{
  return k_a + k_b;
}

/* The harmonic mean is the series conductance of a pair whose interface lies
   halfway between the two particles. Where the particles tell where it lies
   (d_a, d_b: the distances of a and b from the interface), the conductance
   of the pair's two segments in series,
     2 / (f_a / k_a + f_b / k_b),   f_a = d_a / (d_a + d_b), f_b = 1 - f_a,
   makes the pair carry the flux of the kinked linear profile of a steady
   interface exactly, wherever the interface cuts the pair (f_a = 1/2 gives
   the harmonic mean). Without two positive distances: the harmonic mean. */
static inline double sphc_interface_conductance(double k_a, double k_b, double d_a, double d_b)
{
  double resistance;
  if (!(d_a > 0.0) || !(d_b > 0.0)) return sphc_harmonic_conductance(k_a, k_b);
  if (!(k_a > 0.0) || !(k_b > 0.0)) return 0.0;
  resistance = (d_a / k_a + d_b / k_b) / (d_a + d_b);
  return 2.0 / resistance;
}

/* SPHC_INTERFACE: the harmonic mean between atoms of one material, the
   interface conductance above between two materials */
enum sphc_mean { SPHC_HARMONIC = 0, SPHC_ARITHMETIC, SPHC_INTERFACE };

/* called with a compile-time constant mean (templated pair loops) the
   switch folds; SPHC_INTERFACE gives the harmonic mean (the distances are
   the caller's) */
static inline double sphc_conductance(int mean, double k_a, double k_b)
{
  return (mean == SPHC_ARITHMETIC) ? sphc_arithmetic_conductance(k_a, k_b)
                                   : sphc_harmonic_conductance(k_a, k_b);
}

/* the conductance of a pair a b, the one choice that every evaluation of
   the term makes: across an interface (crosses, with SPHC_INTERFACE) the
   series conductance from the distances d_a, d_b; otherwise the mean of
   the per-atom conductivities when they vary with T (varying), or the
   per-type-pair value 'tabulated' (the mean of constant conductivities,
   made once). With compile-time mean and varying the choice folds. */
static inline double sphc_pair_conductance(int mean, int varying, int crosses, double k_a,
                                           double k_b, double tabulated, double d_a, double d_b)
{
  if (mean == SPHC_INTERFACE && crosses) return sphc_interface_conductance(k_a, k_b, d_a, d_b);
  return varying ? sphc_conductance(mean, k_a, k_b) : tabulated;
}

/* Cleary 1998, eq 6:
     F_ab = conductance / (rho_a rho_b) * T_ab * r dW/dr / (r^2 + eta^2)
   with a conductance above, T_ab = T_a - T_b, r dW/dr = r_ab . grad_a W_ab,
   and eta^2 = 0.01 h^2 keeping the term finite as r -> 0. The variants of
   the other papers differ only in the mean and in eta: Ng et al. 2020,
   eq 10, is the same; Reece et al. 2024, eq 9, and Xu (LS-DYNA), eq 11,
   have eta = 0. */
static inline double sphc_cleary_denominator(double rho_a, double rho_b, double rsq, double eta2)
{
  return rho_a * rho_b * (rsq + eta2);
}

/* F_ab given r dW/dr and 1 / sphc_cleary_denominator (for a pair loop
   that shares one division between several terms, sph_flow.h) */
static inline double sphc_cleary_pair_inv(double conductance, double T_ab, double r_dwdr,
                                          double inv_denominator)
{
  return conductance * T_ab * r_dwdr * inv_denominator;
}

static inline double sphc_cleary_pair(double conductance, double T_ab, double rho_a, double rho_b,
                                      double r, double dwdr, double eta2)
{
  return sphc_cleary_pair_inv(conductance, T_ab, r * dwdr,
                              1.0 / sphc_cleary_denominator(rho_a, rho_b, r * r, eta2));
}

/* Cleary 1998, eq 9: the heat flux into wall particle a from its neighbour
   b along a's outward normal n_a,
     2 m_b k_b T_ab (r_ab . n_a) (r_ab . grad_a W_ab) / (r_ab^2 + eta^2)
   with r_ab . grad_a W_ab = r dW/dr; negative for heat flowing into the
   wall as printed (the caller reports the inflow) */
static inline double sphc_cleary_wall_flux(double mass_b, double k_b, double T_ab, double r_dot_n,
                                           double r, double dwdr, double rsq, double eta2)
{
  return 2.0 * mass_b * k_b * T_ab * r_dot_n * r * dwdr / (rsq + eta2);
}

#endif
