/* Unit tests of sph_conduction.h with sph_kernels.h, in C99.
   usage: test_conduction_terms symmetry | limits | conservation | interface */

#include "sph_conduction.h"
#include "sph_kernels.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures = 0;

static void expect(int ok, const char *what, double got, double want)
{
  if (!ok) {
    failures++;
    printf("FAIL %s: got %.15g, expected %.15g\n", what, got, want);
  }
}

/* deterministic pseudo-random numbers in [lo, hi) */
static unsigned long long state = 88172645463325252ULL;
static double uniform(double lo, double hi)
{
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return lo + (hi - lo) * (double) (state >> 11) / 9007199254740992.0;
}

/* F_ba = -F_ab for any pair of materials: the pair exchanges, never creates, heat */
static void check_symmetry(void)
{
  sphk_kernel k = sphk_make(SPHK_CUBIC, 2, 0.026);
  for (int n = 0; n < 1000; n++) {
    double ka = uniform(0.01, 100.0), kb = uniform(0.01, 100.0);
    double rho_a = uniform(1.0, 8000.0), rho_b = uniform(1.0, 8000.0);
    double Ta = uniform(-10.0, 10.0), Tb = uniform(-10.0, 10.0), r = uniform(0.001, 0.026);
    double dwdr = sphk_dwdr(&k, r), eta2 = 0.01 * k.h * k.h;
    double f_ab = sphc_cleary_pair(sphc_harmonic_conductance(ka, kb), Ta - Tb, rho_a, rho_b, r, dwdr, eta2);
    double f_ba = sphc_cleary_pair(sphc_harmonic_conductance(kb, ka), Tb - Ta, rho_b, rho_a, r, dwdr, eta2);
    if (f_ab != -f_ba) {
      expect(0, "F_ba = -F_ab", f_ba, -f_ab);
      return;
    }
    /* heat flows from hot to cold */
    if ((Ta - Tb) * f_ab > 0.0) {
      expect(0, "sign of F_ab: particle a loses heat when hotter", f_ab, 0.0);
      return;
    }
  }
}

static void check_limits(void)
{
  /* equal conductivities: 4 k k / 2k = 2k, Monaghan's single-material form */
  expect(fabs(sphc_harmonic_conductance(3.0, 3.0) - 6.0) < 1e-15, "conductance(k, k) = 2k",
         sphc_harmonic_conductance(3.0, 3.0), 6.0);
  /* the harmonic mean follows the poorer conductor (series resistances) */
  double c = sphc_harmonic_conductance(1.0, 1000.0);
  expect(c > 3.99 && c < 4.0, "conductance(1, 1000) close to 4 (twice the smaller k)", c, 4.0);
  expect(sphc_harmonic_conductance(0.0, 5.0) == 0.0, "an adiabatic k = 0 material exchanges no heat",
         sphc_harmonic_conductance(0.0, 5.0), 0.0);
  expect(sphc_harmonic_conductance(0.0, 0.0) == 0.0, "two k = 0 materials (no 0/0)",
         sphc_harmonic_conductance(0.0, 0.0), 0.0);
  sphk_kernel k = sphk_make(SPHK_WENDLAND, 3, 0.02);
  double f = sphc_cleary_pair(2.0, 0.0, 1000.0, 500.0, 0.005, sphk_dwdr(&k, 0.005), 1e-6);
  expect(f == 0.0, "no exchange between equal temperatures", f, 0.0);
  f = sphc_cleary_pair(2.0, 1.0, 1000.0, 500.0, 0.0, sphk_dwdr(&k, 0.0), 1e-6);
  expect(f == 0.0 && !isnan(f), "finite at r = 0 (eta^2)", f, 0.0);
}

/* a 1-D chain of three materials, explicitly integrated: sum m e is
   constant to round-off and T relaxes to the heat-capacity-weighted mean */
static void check_conservation(void)
{
  enum { N = 30 };
  double x[N], m[N], rho[N], cv[N], kk[N], e[N], de[N];
  const double dx = 0.01;
  sphk_kernel k = sphk_make(SPHK_QUINTIC, 1, 3.0 * 1.3 * dx);
  for (int i = 0; i < N; i++) {
    int material = (3 * i) / N;
    x[i] = (i + 0.5) * dx + uniform(-0.1, 0.1) * dx;
    rho[i] = (material == 0) ? 1000.0 : (material == 1) ? 500.0 : 2000.0;
    cv[i] = (material == 0) ? 1000.0 : (material == 1) ? 2000.0 : 500.0;
    kk[i] = (material == 0) ? 1.0 : (material == 1) ? 3.0 : 2.0;
    m[i] = rho[i] * dx;
    e[i] = cv[i] * uniform(280.0, 380.0);
  }
  double energy0 = 0.0, capacity = 0.0;
  for (int i = 0; i < N; i++) energy0 += m[i] * e[i], capacity += m[i] * cv[i];
  const double eta2 = 0.01 * k.h * k.h, dt = 4.0; /* below 0.1 rho cv h^2 / k */
  for (int step = 0; step < 40000; step++) {
    memset(de, 0, sizeof(de));
    for (int i = 0; i < N; i++)
      for (int j = i + 1; j < N; j++) {
        double r = fabs(x[i] - x[j]);
        double f = sphc_cleary_pair(sphc_harmonic_conductance(kk[i], kk[j]), e[i] / cv[i] - e[j] / cv[j],
                                    rho[i], rho[j], r, sphk_dwdr(&k, r), eta2);
        de[i] += m[j] * f;
        de[j] -= m[i] * f;
      }
    for (int i = 0; i < N; i++) e[i] += dt * de[i];
  }
  double energy = 0.0, tmin = 1e300, tmax = -1e300;
  for (int i = 0; i < N; i++) {
    energy += m[i] * e[i];
    tmin = fmin(tmin, e[i] / cv[i]);
    tmax = fmax(tmax, e[i] / cv[i]);
  }
  expect(fabs(energy - energy0) < 1e-13 * fabs(energy0), "sum m e conserved (relative drift)",
         (energy - energy0) / energy0, 0.0);
  double tmean = energy0 / capacity;
  expect(tmax - tmin < 1e-3 && fabs(0.5 * (tmax + tmin) - tmean) < 1e-3,
         "T relaxes to the heat-capacity-weighted mean", 0.5 * (tmax + tmin), tmean);
}

/* sphc_interface_conductance: the pair carries the flux of a kinked linear
   profile exactly wherever the interface cuts it, is symmetric, reduces to
   the harmonic mean at the midpoint and without distances */
static void check_interface(void)
{
  for (int n = 0; n < 1000; n++) {
    double ka = uniform(0.01, 100.0), kb = uniform(0.01, 100.0);
    double da = uniform(0.001, 2.0), db = uniform(0.001, 2.0), q = uniform(-5.0, 5.0);
    /* steady flux q through both materials: T_a - T_b = q (d_a / k_a + d_b / k_b) */
    double c = sphc_interface_conductance(ka, kb, da, db);
    double carried = c * q * (da / ka + db / kb), exact = 2.0 * q * (da + db);
    if (fabs(carried - exact) > 1e-12 * fabs(exact)) {
      expect(0, "conductance x kinked profile's difference = 2 q (d_a + d_b)", carried, exact);
      return;
    }
    if (c != sphc_interface_conductance(kb, ka, db, da)) {
      expect(0, "symmetric in a and b", sphc_interface_conductance(kb, ka, db, da), c);
      return;
    }
    if (!(c >= 2.0 * fmin(ka, kb) * (1 - 1e-15) && c <= 2.0 * fmax(ka, kb) * (1 + 1e-15))) {
      expect(0, "between 2 min(k) and 2 max(k)", c, 2.0 * fmin(ka, kb));
      return;
    }
    double h = sphc_harmonic_conductance(ka, kb);
    if (fabs(sphc_interface_conductance(ka, kb, da, da) - h) > 1e-14 * h) {
      expect(0, "interface at the midpoint: the harmonic mean", sphc_interface_conductance(ka, kb, da, da), h);
      return;
    }
  }
  /* the closer a is to the interface, the more of the pair lies in b */
  expect(sphc_interface_conductance(1.0, 100.0, 0.1, 1.9) > sphc_interface_conductance(1.0, 100.0, 1.0, 1.0),
         "a near the interface: b's (better) conductor dominates", sphc_interface_conductance(1.0, 100.0, 0.1, 1.9),
         sphc_interface_conductance(1.0, 100.0, 1.0, 1.0));
  expect(sphc_interface_conductance(1.0, 100.0, -1.0, 1.0) == sphc_harmonic_conductance(1.0, 100.0),
         "no distance (-1): the harmonic mean", sphc_interface_conductance(1.0, 100.0, -1.0, 1.0),
         sphc_harmonic_conductance(1.0, 100.0));
  expect(sphc_interface_conductance(0.0, 100.0, 0.5, 1.0) == 0.0, "an adiabatic (k = 0) side conducts nothing",
         sphc_interface_conductance(0.0, 100.0, 0.5, 1.0), 0.0);
  expect(sphc_conductance(SPHC_INTERFACE, 1.0, 3.0) == sphc_harmonic_conductance(1.0, 3.0),
         "SPHC_INTERFACE without distances: the harmonic mean", sphc_conductance(SPHC_INTERFACE, 1.0, 3.0),
         sphc_harmonic_conductance(1.0, 3.0));
}

/* the one choice of conductance (sphc_pair_conductance) and Cleary's
   eq 9 (sphc_cleary_wall_flux) */
static void check_choice(void)
{
  const double ka = 2.0, kb = 6.0, table = 7.5, da = 0.3, db = 0.7;
  /* constant conductivities: the tabulated value, whatever the mean */
  expect(sphc_pair_conductance(SPHC_HARMONIC, 0, 0, ka, kb, table, da, db) == table,
         "constant k: the table's value", sphc_pair_conductance(SPHC_HARMONIC, 0, 0, ka, kb, table, da, db), table);
  /* varying: the mean of the two, harmonic or arithmetic */
  expect(sphc_pair_conductance(SPHC_HARMONIC, 1, 0, ka, kb, table, da, db) == 6.0,
         "varying k, harmonic: 2 ka kb / (ka + kb)", sphc_pair_conductance(SPHC_HARMONIC, 1, 0, ka, kb, table, da, db), 6.0);
  expect(sphc_pair_conductance(SPHC_ARITHMETIC, 1, 0, ka, kb, table, da, db) == sphc_arithmetic_conductance(ka, kb),
         "varying k, arithmetic", sphc_pair_conductance(SPHC_ARITHMETIC, 1, 0, ka, kb, table, da, db),
         sphc_arithmetic_conductance(ka, kb));
  /* across an interface: the series conductance, constant or varying; not
     across: as without the interface */
  for (int varying = 0; varying <= 1; varying++) {
    const double got = sphc_pair_conductance(SPHC_INTERFACE, varying, 1, ka, kb, table, da, db);
    expect(got == sphc_interface_conductance(ka, kb, da, db), "across an interface: series", got,
           sphc_interface_conductance(ka, kb, da, db));
  }
  expect(sphc_pair_conductance(SPHC_INTERFACE, 0, 0, ka, kb, table, da, db) == table,
         "interface mean, same material, constant k: the table's value",
         sphc_pair_conductance(SPHC_INTERFACE, 0, 0, ka, kb, table, da, db), table);
  /* the interface pair ignores the flag 'crosses' for the other means */
  expect(sphc_pair_conductance(SPHC_HARMONIC, 0, 1, ka, kb, table, da, db) == table,
         "crosses without mean interface: the table's value",
         sphc_pair_conductance(SPHC_HARMONIC, 0, 1, ka, kb, table, da, db), table);

  /* eq 9: 2 m_b k_b T_ab (r . n) r dW/dr / (r^2 + eta^2), odd in T_ab and
     in the normal, 0 for a neighbour in the wall's plane */
  const double m = 0.25, k = 3.0, T = 2.0, rn = 0.01, r = 0.02, dwdr = -50.0, eta2 = 1e-6;
  const double want = 2.0 * m * k * T * rn * r * dwdr / (r * r + eta2);
  const double flux = sphc_cleary_wall_flux(m, k, T, rn, r, dwdr, r * r, eta2);
  expect(fabs(flux - want) <= 1e-15 * fabs(want), "eq 9 as printed", flux, want);
  expect(sphc_cleary_wall_flux(m, k, -T, rn, r, dwdr, r * r, eta2) == -flux, "eq 9 odd in T_ab",
         sphc_cleary_wall_flux(m, k, -T, rn, r, dwdr, r * r, eta2), -flux);
  expect(sphc_cleary_wall_flux(m, k, T, 0.0, r, dwdr, r * r, eta2) == 0.0, "eq 9: no flux along the wall",
         sphc_cleary_wall_flux(m, k, T, 0.0, r, dwdr, r * r, eta2), 0.0);
  expect(flux < 0.0, "eq 9 is negative for heat into the wall (T_ab > 0, r . n > 0)", flux, -1.0);
}

int main(int argc, char **argv)
{
  if (argc != 2) {
    fprintf(stderr, "usage: %s symmetry | limits | conservation | interface | choice\n", argv[0]);
    return 2;
  }
  if (strcmp(argv[1], "symmetry") == 0)
    check_symmetry();
  else if (strcmp(argv[1], "limits") == 0)
    check_limits();
  else if (strcmp(argv[1], "conservation") == 0)
    check_conservation();
  else if (strcmp(argv[1], "interface") == 0)
    check_interface();
  else if (strcmp(argv[1], "choice") == 0)
    check_choice();
  else {
    fprintf(stderr, "unknown check %s\n", argv[1]);
    return 2;
  }
  if (failures == 0) printf("PASS %s\n", argv[1]);
  return failures ? 1 : 0;
}
