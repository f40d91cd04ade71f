/* Unit tests of sph_phase_laws.h, in C99. usage: test_phase_laws */

#include "sph_phase_laws.h"

#include <math.h>
#include <stdio.h>

static int failures = 0;

static void expect_near(double got, double want, double tol, const char *what)
{
  if (!(fabs(got - want) <= tol)) {
    failures++;
    printf("FAIL %s: got %.17g, expected %.17g (tolerance %g)\n", what, got, want, tol);
  }
}

/* the law as written out: e(T) = cv T + L f(T), f linear between Ts and Tl,
   and above Tl e(Tl) + cl (T - Tl), cl the liquid's specific heat */
static double energy_written_out(double T, double cv, double cl, double ts, double tl, double latent)
{
  if (T >= tl && T > ts) return cv * tl + latent + cl * (T - tl);   /* at Ts = Tl: the solid */
  double f = 0.0;
  if (tl > ts) f = (T - ts) / (tl - ts);
  else f = T > ts ? 1.0 : 0.0;
  if (f < 0.0) f = 0.0;
  if (f > 1.0) f = 1.0;
  return cv * T + latent * f;
}

/* cl: the liquid's specific heat given to the law, 0 for the solid's */
static void check_law(double cv, double cl, double ts, double tl, double latent, const char *name)
{
  const SPHPhaseLaw law = {ts, tl, latent, cl};
  const double liquid = cl > 0.0 ? cl : cv;
  char what[160];
  const double scale = cv * tl + latent;
  /* e(T) against the written-out law, and T(e(T)) = T, f(e(T)) = f(T) */
  for (int k = 0; k <= 400; k++) {
    const double T = ts - 5.0 + (tl - ts + 10.0) * k / 400.0;
    const double e = sphp_energy(T, cv, &law);
    snprintf(what, sizeof what, "%s: e(T = %g)", name, T);
    expect_near(e, energy_written_out(T, cv, liquid, ts, tl, latent), 1e-14 * scale, what);
    snprintf(what, sizeof what, "%s: T(e(T)) at T = %g", name, T);
    expect_near(sphp_temperature(e, cv, &law), T, 1e-12 * fabs(T) + 1e-12, what);
    if (tl > ts) {
      double f = (T - ts) / (tl - ts);
      f = f < 0.0 ? 0.0 : (f > 1.0 ? 1.0 : f);
      snprintf(what, sizeof what, "%s: f(e(T)) at T = %g", name, T);
      expect_near(sphp_liquid_fraction(e, cv, &law), f, 1e-12, what);
    }
  }
  /* the mushy zone holds the latent heat: from f = 0 to f = 1 the energy
     rises by L plus cv (Tl - Ts) */
  const double e_solid = cv * ts, e_liquid = cv * tl + latent;
  snprintf(what, sizeof what, "%s: f at the solidus's energy", name);
  expect_near(sphp_liquid_fraction(e_solid, cv, &law), 0.0, 0.0, what);
  snprintf(what, sizeof what, "%s: f at the liquidus's energy", name);
  expect_near(sphp_liquid_fraction(e_liquid, cv, &law), 1.0, 1e-15, what);
  snprintf(what, sizeof what, "%s: f halfway through the mushy energies", name);
  expect_near(sphp_liquid_fraction(0.5 * (e_solid + e_liquid), cv, &law), 0.5, 1e-14, what);
  snprintf(what, sizeof what, "%s: T halfway through the mushy energies", name);
  expect_near(sphp_temperature(0.5 * (e_solid + e_liquid), cv, &law), 0.5 * (ts + tl), 1e-12 * tl, what);
  /* e(T) continuous at the liquidus, and the phases' specific heats */
  snprintf(what, sizeof what, "%s: e continuous at the liquidus", name);
  expect_near(sphp_energy(tl * (1.0 + 1e-15), cv, &law), e_liquid, 1e-12 * scale, what);
  snprintf(what, sizeof what, "%s: the liquid's cv", name);
  expect_near(sphp_liquid_cv(cv, &law), liquid, 0.0, what);
  snprintf(what, sizeof what, "%s: the smallest cv", name);
  expect_near(sphp_smallest_cv(cv, &law), liquid < cv ? liquid : cv, 0.0, what);
  snprintf(what, sizeof what, "%s: the solid's sensible cv", name);
  expect_near(sphp_sensible_cv(sphp_energy(ts - 1.0, cv, &law), cv, &law), cv, 0.0, what);
  snprintf(what, sizeof what, "%s: the liquid's sensible cv", name);
  expect_near(sphp_sensible_cv(sphp_energy(tl + 1.0, cv, &law), cv, &law), liquid, 1e-12 * liquid, what);
  snprintf(what, sizeof what, "%s: the sensible cv halfway through the mushy energies", name);
  expect_near(sphp_sensible_cv(0.5 * (e_solid + e_liquid), cv, &law), 0.5 * (cv + liquid), 1e-12 * cv, what);
  /* de/dT against a centred difference of e(T), inside and outside */
  const double Ts[3] = {ts - 2.0, 0.5 * (ts + tl), tl + 2.0};
  for (int k = 0; k < 3; k++) {
    if (tl <= ts && k == 1) continue;
    const double dT = 1e-4, e = sphp_energy(Ts[k], cv, &law);
    const double slope = (sphp_energy(Ts[k] + dT, cv, &law) - sphp_energy(Ts[k] - dT, cv, &law)) / (2 * dT);
    snprintf(what, sizeof what, "%s: de/dT at T = %g", name, Ts[k]);
    expect_near(sphp_heat_capacity(e, cv, &law), slope, 1e-6 * slope, what);
  }
}

int main(void)
{
  /* a mushy zone (an alloy) and a pure substance (gallium's melting point
     and latent heat, 302.93 K and 80.16 kJ/kg, cv 381.5 J/(kg K)) */
  check_law(1000.0, 0.0, 300.0, 310.0, 3.0e5, "mushy");
  check_law(381.5, 0.0, 302.93, 302.93, 80160.0, "single melting temperature");
  /* the liquid's specific heat twice and half the solid's */
  check_law(1000.0, 2000.0, 300.0, 310.0, 3.0e5, "mushy, cl = 2 cv");
  check_law(1000.0, 500.0, 300.0, 310.0, 3.0e5, "mushy, cl = cv / 2");
  check_law(381.5, 763.0, 302.93, 302.93, 80160.0, "single melting temperature, cl = 2 cv");
  check_law(381.5, 190.75, 302.93, 302.93, 80160.0, "single melting temperature, cl = cv / 2");
  /* the same law with cl = cv given as a number: the same e and T to
     round-off as without it */
  const SPHPhaseLaw same = {300.0, 310.0, 3.0e5, 1000.0}, plain = {300.0, 310.0, 3.0e5, 0.0};
  for (int k = 0; k <= 20; k++) {
    const double T = 290.0 + k * 2.0;
    expect_near(sphp_energy(T, 1000.0, &same), sphp_energy(T, 1000.0, &plain), 1e-15 * 6.1e5,
                "cl = cv given: e(T)");
    const double e = sphp_energy(T, 1000.0, &plain);
    expect_near(sphp_temperature(e, 1000.0, &same), T, 1e-12 * T, "cl = cv given: T(e)");
  }
  /* the single melting temperature: the mushy particle holds T = Tm while
     its fraction moves; de/dT there is 0 (T does not move) */
  const SPHPhaseLaw ga = {302.93, 302.93, 80160.0, 0.0};
  const double e_half = 381.5 * 302.93 + 0.5 * 80160.0;
  expect_near(sphp_temperature(e_half, 381.5, &ga), 302.93, 0.0, "pure: T in the mushy state");
  expect_near(sphp_liquid_fraction(e_half, 381.5, &ga), 0.5, 1e-15, "pure: f in the mushy state");
  expect_near(sphp_heat_capacity(e_half, 381.5, &ga), 0.0, 0.0, "pure: de/dT in the mushy state");
  expect_near(sphp_energy(302.93, 381.5, &ga), 381.5 * 302.93, 0.0, "pure: e at Tm is the solid's");
  if (failures) {
    printf("%d failure(s)\n", failures);
    return 1;
  }
  printf("sph_phase_laws.h: all checks passed\n");
  return 0;
}
