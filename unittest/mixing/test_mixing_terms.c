/* Unit tests of the mixing measures' terms (sph_mixing.h), in C99: the
   values the definitions fix exactly (a single component, the mixture's
   own composition), their symmetry and monotony.
   Usage: test_mixing_terms robinson | composition | ftle | entropy */

#include "sph_mixing.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

static void check(int ok, const char *what, double got, double want)
{
  printf("%s %s: got %.17g, want %.17g\n", ok ? "ok  " : "FAIL", what, got, want);
  if (!ok) failures++;
}

/* 0 for a single component, 1 at the mixture's composition, the same with
   the components swapped, rising towards the composition */
static void test_robinson(void)
{
  const double compositions[3] = {0.5, 0.3, 0.8};
  for (int c = 0; c < 3; c++) {
    const double f_all = compositions[c];
    check(sphmix_robinson(0.0, f_all) == 0.0, "only the rest: 0", sphmix_robinson(0.0, f_all), 0.0);
    check(sphmix_robinson(1.0, f_all) == 0.0, "only A: 0", sphmix_robinson(1.0, f_all), 0.0);
    check(fabs(sphmix_robinson(f_all, f_all) - 1.0) < 1e-15, "the mixture's composition: 1",
          sphmix_robinson(f_all, f_all), 1.0);
    const double f = 0.2 * f_all;
    check(fabs(sphmix_robinson(f, f_all) - sphmix_robinson(1.0 - f, 1.0 - f_all)) < 1e-15,
          "A and the rest swapped", sphmix_robinson(1.0 - f, 1.0 - f_all), sphmix_robinson(f, f_all));
    int rising = 1;
    for (int k = 1; k <= 20; k++)
      rising &= sphmix_robinson(f_all * k / 20.0, f_all) > sphmix_robinson(f_all * (k - 1) / 20.0, f_all);
    check(rising, "rises from 0 to the composition", (double) rising, 1.0);
  }
  /* a = 2 b: (3 / sqrt 5 - 1) (sqrt 2 + 1), by hand */
  const double want = (3.0 / sqrt(5.0) - 1.0) * (sqrt(2.0) + 1.0);
  const double got = sphmix_robinson(0.5, 1.0 / 3.0);    /* a = 1.5, b = 0.75 */
  check(fabs(got - want) < 1e-15, "F = 1/2 in a mixture of 1/3: (3/sqrt5 - 1)(sqrt2 + 1)", got, want);
}

static void test_composition(void)
{
  const double f_all = 0.3;
  check(sphmix_composition(0.0, f_all) == 0.0, "only the rest: 0", sphmix_composition(0.0, f_all), 0.0);
  check(sphmix_composition(1.0, f_all) == 0.0, "only A: 0", sphmix_composition(1.0, f_all), 0.0);
  check(sphmix_composition(f_all, f_all) == 1.0, "the composition: 1", sphmix_composition(f_all, f_all), 1.0);
  check(fabs(sphmix_composition(0.15, f_all) - 0.5) < 1e-15, "half the composition: 1/2",
        sphmix_composition(0.15, f_all), 0.5);
  check(fabs(sphmix_composition(0.65, f_all) - 0.5) < 1e-15, "half-way from it to 1: 1/2",
        sphmix_composition(0.65, f_all), 0.5);
}

static void test_ftle(void)
{
  check(fabs(sphmix_ftle(exp(2.0), 2.0) - 1.0) < 1e-15, "stretch e^2 over T = 2: 1",
        sphmix_ftle(exp(2.0), 2.0), 1.0);
  check(sphmix_ftle(1.0, 5.0) == 0.0, "no stretch: 0", sphmix_ftle(1.0, 5.0), 0.0);
  check(sphmix_ftle(0.5, 1.0) < 0.0, "compression: negative", sphmix_ftle(0.5, 1.0), log(0.5));
  check(sphmix_ftle(3.0, 0.0) == 0.0, "T = 0: 0", sphmix_ftle(3.0, 0.0), 0.0);
  check(sphmix_ftle(0.0, 1.0) == 0.0, "no neighbour left (stretch 0): 0", sphmix_ftle(0.0, 1.0), 0.0);
}

static void test_entropy(void)
{
  check(sphmix_entropy_term(0.0) == 0.0, "0 ln 0 = 0", sphmix_entropy_term(0.0), 0.0);
  check(sphmix_entropy_term(1.0) == 0.0, "1 ln 1 = 0", sphmix_entropy_term(1.0), 0.0);
  check(fabs(sphmix_entropy_term(exp(-1.0)) - exp(-1.0)) < 1e-16, "-F ln F at 1/e: 1/e",
        sphmix_entropy_term(exp(-1.0)), exp(-1.0));
  check(fabs(sphmix_entropy_max(10.0, 0.25) - 10.0 * 0.25 * log(4.0)) < 1e-14,
        "largest S of 10 particles at 1/4: 10 (1/4) ln 4", sphmix_entropy_max(10.0, 0.25),
        10.0 * 0.25 * log(4.0));
  /* any F of the same mean has less: two particles at 0 and 1/2 against 1/4 each */
  const double spread = sphmix_entropy_term(0.0) + sphmix_entropy_term(0.5);
  check(spread < sphmix_entropy_max(2.0, 0.25), "an uneven F of the same mean has less", spread,
        sphmix_entropy_max(2.0, 0.25));
  check(sphmix_entropy_normalised(1.0, 1.0, 3.0) == 0.0, "S* at the reference: 0",
        sphmix_entropy_normalised(1.0, 1.0, 3.0), 0.0);
  check(sphmix_entropy_normalised(3.0, 1.0, 3.0) == 1.0, "S* at the maximum: 1",
        sphmix_entropy_normalised(3.0, 1.0, 3.0), 1.0);
  check(sphmix_entropy_normalised(2.0, 1.0, 3.0) == 0.5, "S* half-way: 1/2",
        sphmix_entropy_normalised(2.0, 1.0, 3.0), 0.5);
  check(sphmix_entropy_normalised(2.0, 3.0, 3.0) == 0.0, "reference already at the maximum: 0",
        sphmix_entropy_normalised(2.0, 3.0, 3.0), 0.0);
}

int main(int argc, char **argv)
{
  const char *which = (argc > 1) ? argv[1] : "";
  if (strcmp(which, "robinson") == 0)
    test_robinson();
  else if (strcmp(which, "composition") == 0)
    test_composition();
  else if (strcmp(which, "ftle") == 0)
    test_ftle();
  else if (strcmp(which, "entropy") == 0)
    test_entropy();
  else {
    fprintf(stderr, "usage: test_mixing_terms robinson | composition | ftle | entropy\n");
    return 2;
  }
  return failures ? 1 : 0;
}
