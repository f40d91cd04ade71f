/* Unit tests of sph_grain_laws.h, in C99. usage: test_grain_laws */

#include "sph_grain_laws.h"

#include <stdio.h>

static int failures = 0;

static void expect_near(double got, double want, double rel, const char *what)
{
  if (!(fabs(got - want) <= rel * fabs(want))) {
    failures++;
    printf("FAIL %s: got %.15g, expected %.15g\n", what, got, want);
  }
}

/* Di Felice's drag written as published, F = Cd rho (pi d^2 / 4) eps^2
   w^2 eps^-chi / 2, with Cd from Re directly (not finite at w = 0) */
static double difelice_force(double d, double eps, double rho, double mu, double w)
{
  const double re = eps * rho * d * w / mu;
  const double cd = (0.63 + 4.8 / sqrt(re)) * (0.63 + 4.8 / sqrt(re));
  const double chi = 3.7 - 0.65 * exp(-0.5 * (1.5 - log10(re)) * (1.5 - log10(re)));
  return 0.5 * cd * rho * 0.25 * M_PI * d * d * eps * eps * w * w * pow(eps, -chi);
}

/* Gidaspow's momentum exchange per volume of the mixture as published,
   beta_v (Ergun below eps = 0.8, Wen and Yu above), and the force on one
   grain beta_v w V / (1 - eps) */
static double gidaspow_force(double d, double eps, double rho, double mu, double w)
{
  const double volume = M_PI * d * d * d / 6.0;
  double beta_v;
  if (eps < 0.8) {
    beta_v = 150.0 * (1.0 - eps) * (1.0 - eps) * mu / (eps * d * d) + 1.75 * (1.0 - eps) * rho * w / d;
  } else {
    const double re = eps * rho * d * w / mu;
    const double cd = (re < 1000.0) ? 24.0 / re * (1.0 + 0.15 * pow(re, 0.687)) : 0.44;
    beta_v = 0.75 * cd * eps * (1.0 - eps) * rho * w * pow(eps, -2.65) / d;
  }
  return beta_v * w * volume / (1.0 - eps);
}

/* Ergun's pressure drop per length at superficial velocity U */
static double ergun_gradient(double d, double eps, double rho, double mu, double U)
{
  const double e3 = eps * eps * eps;
  return 150.0 * (1.0 - eps) * (1.0 - eps) * mu * U / (e3 * d * d) +
      1.75 * (1.0 - eps) * rho * U * U / (e3 * d);
}

int main(void)
{
  const double d = 1e-3, rho = 1000.0, mu = 1e-3;
  const double speeds[5] = {1e-6, 1e-3, 3e-2, 1.0, 30.0};
  const double porosities[3] = {1.0, 0.6, 0.4};
  int a, b;

  expect_near(sphg_drag_beta(SPHG_DRAG_STOKES, d, 0.5, rho, mu, 1.0), 3.0 * M_PI * mu * d, 1e-15,
              "stokes");
  /* the expanded Cd against the published form, over five decades of Re */
  for (a = 0; a < 5; a++)
    for (b = 0; b < 3; b++) {
      char what[64];
      const double w = speeds[a], eps = porosities[b];
      snprintf(what, sizeof what, "difelice at w %g eps %g", w, eps);
      expect_near(sphg_drag_beta(SPHG_DRAG_DIFELICE, d, eps, rho, mu, w) * w,
                  difelice_force(d, eps, rho, mu, w), 1e-12, what);
    }
  /* the creeping limit: 23.04 / 24 of Stokes's drag at eps = 1, finite at w = 0 */
  expect_near(sphg_drag_beta(SPHG_DRAG_DIFELICE, d, 1.0, rho, mu, 0.0), 0.96 * 3.0 * M_PI * mu * d,
              1e-14, "difelice at rest");
  expect_near(sphg_difelice_chi(pow(10.0, 1.5)), 3.05, 1e-15, "chi at its dip");

  /* gidaspow as published, both branches and Cd's, over five decades */
  {
    const double gidaspow_eps[4] = {0.4, 0.7, 0.85, 0.99};
    for (a = 0; a < 5; a++)
      for (b = 0; b < 4; b++) {
        char what[64];
        const double w = speeds[a], eps = gidaspow_eps[b];
        snprintf(what, sizeof what, "gidaspow at w %g eps %g", w, eps);
        expect_near(sphg_drag_beta(SPHG_DRAG_GIDASPOW, d, eps, rho, mu, w) * w,
                    gidaspow_force(d, eps, rho, mu, w), 1e-12, what);
      }
  }
  /* a fixed bed: the grains' drag per volume over eps is Ergun's pressure
     gradient, n beta w / eps with n = (1 - eps) / V and w = U / eps */
  for (a = 0; a < 5; a++) {
    const double eps = 0.45, U = 1e-2 * speeds[a], w = U / eps;
    const double n = (1.0 - eps) / (M_PI * d * d * d / 6.0);
    expect_near(n * sphg_drag_beta(SPHG_DRAG_GIDASPOW, d, eps, rho, mu, w) * w / eps,
                ergun_gradient(d, eps, rho, mu, U), 1e-13, "gidaspow: ergun's bed");
  }
  /* one grain in a wide fluid: Stokes's drag as eps -> 1, finite at w = 0 */
  expect_near(sphg_drag_beta(SPHG_DRAG_GIDASPOW, d, 1.0, rho, mu, 0.0), 3.0 * M_PI * mu * d, 1e-14,
              "gidaspow at rest, eps 1");
  expect_near(sphg_difelice_chi(0.0), 3.7, 0.0, "chi at rest");

  /* the fluid's force in both forms. A steady uniform bed under gravity g:
     the fluid's pressure gradient is its weight less the drag per fluid
     volume, grad P = rho g - n beta w / eps (n = (1 - eps) / V), and both
     forms give the grain the drag over eps and the buoyancy -V rho g */
  {
    const double eps = 0.42, volume = M_PI * d * d * d / 6.0, n = (1.0 - eps) / volume;
    const double beta = sphg_drag_beta(SPHG_DRAG_GIDASPOW, d, eps, rho, mu, 0.01);
    const double slip[3] = {0.002, -0.004, 0.01}, g[3] = {0.0, 0.0, -9.81};
    double grad_p[3], gradient_form[3], hydrostatic_form[3];
    for (a = 0; a < 3; a++) grad_p[a] = rho * g[a] - n * beta * slip[a] / eps;
    sphg_fluid_force(SPHG_PRESSURE_GRADIENT, beta, eps, slip, volume, grad_p, rho, g, gradient_form);
    sphg_fluid_force(SPHG_PRESSURE_HYDROSTATIC, beta, eps, slip, volume, grad_p, rho, g,
                     hydrostatic_form);
    for (a = 0; a < 3; a++) {
      expect_near(hydrostatic_form[a], gradient_form[a], 1e-13, "the two forms in a uniform bed");
      expect_near(hydrostatic_form[a], beta * slip[a] / eps - volume * rho * g[a], 1e-15,
                  "hydrostatic form");
    }
    /* no body force: no buoyancy */
    sphg_fluid_force(SPHG_PRESSURE_HYDROSTATIC, beta, eps, slip, volume, grad_p, rho, NULL,
                     hydrostatic_form);
    expect_near(hydrostatic_form[2], beta * slip[2] / eps, 1e-15, "hydrostatic form without g");
    expect_near(sphg_slip_coefficient(SPHG_PRESSURE_GRADIENT, beta, eps), beta, 0.0,
                "slip coefficient, gradient");
    if (sphg_pressure_lookup("hydrostatic") != SPHG_PRESSURE_HYDROSTATIC ||
        sphg_pressure_lookup("gradient") != SPHG_PRESSURE_GRADIENT || sphg_pressure_lookup("B") != -1) {
      failures++;
      printf("FAIL the pressure forms' names\n");
    }
  }

  /* heat: a sphere at rest conducts with Nu = 2, both laws (gunn at eps = 1) */
  expect_near(sphg_nusselt(SPHG_HEAT_RANZ_MARSHALL, 0.5, 0.0, 7.0), 2.0, 1e-15, "ranz-marshall at rest");
  expect_near(sphg_nusselt(SPHG_HEAT_GUNN, 1.0, 0.0, 7.0), 2.0, 1e-15, "gunn at rest, eps 1");
  expect_near(sphg_nusselt(SPHG_HEAT_RANZ_MARSHALL, 1.0, 100.0, 8.0), 2.0 + 0.6 * 10.0 * 2.0, 1e-15,
              "ranz-marshall at Re 100, Pr 8");
  expect_near(sphg_nusselt(SPHG_HEAT_GUNN, 0.4, 32.0, 8.0),
              (7.0 - 4.0 + 0.8) * (1.0 + 0.7 * 2.0 * 2.0) + (1.33 - 0.96 + 0.192) * pow(32.0, 0.7) * 2.0,
              1e-14, "gunn at eps 0.4, Re 32, Pr 8");
  expect_near(sphg_nusselt(SPHG_HEAT_NONE, 0.4, 32.0, 8.0) + 1.0, 1.0, 0.0, "none");
  /* h A = Nu k pi d with Re and Pr from the fluid */
  expect_near(sphg_conductance(SPHG_HEAT_RANZ_MARSHALL, d, 1.0, rho, mu, 0.6, 4200.0, 0.1),
              (2.0 + 0.6 * sqrt(100.0) * cbrt(7.0)) * 0.6 * M_PI * d, 1e-14, "conductance");

  /* names and look-ups */
  for (a = 0; a < SPHG_DRAG_NKINDS; a++)
    if (sphg_drag_lookup(sphg_drag_name(a)) != a) failures++, printf("FAIL drag name %d\n", a);
  for (a = 0; a < SPHG_HEAT_NKINDS; a++)
    if (sphg_heat_lookup(sphg_heat_name(a)) != a) failures++, printf("FAIL heat name %d\n", a);
  if (sphg_drag_lookup("wen-yu") != -1 || sphg_heat_lookup("whitaker") != -1)
    failures++, printf("FAIL unknown names found\n");

  printf("grain laws: %s (%d failures)\n", failures ? "FAILED" : "passed", failures);
  return failures != 0;
}
