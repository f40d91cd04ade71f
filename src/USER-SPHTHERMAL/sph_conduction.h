/* -*- c -*- -------------------------------------------------------------
   USER-SPHTHERMAL: pair terms of SPH heat conduction, in C99 (also C++).

   A pair term returns the factor F_ab of the specific-energy rates
     de_a/dt += m_b F_ab,   de_b/dt -= m_a F_ab,
   so that m_a de_a + m_b de_b = 0: the pair conserves thermal energy
   exactly whatever the kernel, the masses or the conductivities.
------------------------------------------------------------------------- */

#ifndef SPH_CONDUCTION_H
#define SPH_CONDUCTION_H

/* 4 k_a k_b / (k_a + k_b), twice the harmonic mean; 0 when both are 0
   (an adiabatic k = 0 material) */
static inline double sphc_cleary_conductance(double k_a, double k_b)
{
  const double sum = k_a + k_b;
  return (sum > 0.0) ? 4.0 * k_a * k_b / sum : 0.0;
}

/* Cleary 1998 (seed 000) eq 6:
     F_ab = conductance / (rho_a rho_b) * T_ab * r dW/dr / (r^2 + eta^2)
   with conductance = sphc_cleary_conductance(k_a, k_b), T_ab = T_a - T_b,
   r dW/dr = r_ab . grad_a W_ab, and eta^2 keeping the term finite as r -> 0. */
static inline double sphc_cleary_pair(double conductance, double T_ab, double rho_a, double rho_b,
                                      double r, double dwdr, double eta2)
{
  return conductance * T_ab * r * dwdr / (rho_a * rho_b * (r * r + eta2));
}

#endif
