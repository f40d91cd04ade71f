/* Unit tests of sph_material_laws.h, in C99. usage: test_material_laws */

#include "sph_material_laws.h"

#include <stdio.h>

static int failures = 0;

static void expect_near(double got, double want, double tol, const char *what)
{
  if (!(fabs(got - want) <= tol)) {
    failures++;
    printf("FAIL %s: got %.15g, expected %.15g\n", what, got, want);
  }
}

int main(void)
{
  sphm_law law = {SPHM_CONSTANT, {2.5, 0.0, 0.0}, 0, 0, 0};
  expect_near(sphm_law_eval(&law, 123.0), 2.5, 0.0, "constant");

  law.kind = SPHM_LINEAR; /* k = 2 + 0.5 (T - 300) */
  law.c[0] = 2.0, law.c[1] = 0.5, law.c[2] = 300.0;
  expect_near(sphm_law_eval(&law, 300.0), 2.0, 1e-15, "linear at T0");
  expect_near(sphm_law_eval(&law, 310.0), 7.0, 1e-14, "linear slope");

  law.kind = SPHM_EXPONENTIAL; /* Cleary 1998, section 3.3: k = exp(4 T) */
  law.c[0] = 1.0, law.c[1] = 4.0;
  expect_near(sphm_law_eval(&law, 0.0), 1.0, 1e-15, "exponential at 0");
  expect_near(sphm_law_eval(&law, 1.0), exp(4.0), 1e-12, "exponential at 1");

  const double t[4] = {250.0, 300.0, 350.0, 400.0}, p[4] = {0.0223, 0.0263, 0.0300, 0.0338};
  law.kind = SPHM_TABLE, law.ntable = 4, law.table_t = t, law.table_p = p;
  expect_near(sphm_law_eval(&law, 300.0), 0.0263, 1e-15, "table at a point");
  expect_near(sphm_law_eval(&law, 325.0), 0.02815, 1e-15, "table between points");
  expect_near(sphm_law_eval(&law, 390.0), 0.0300 + 0.8 * 0.0038, 1e-15, "table in the last interval");
  expect_near(sphm_law_eval(&law, 100.0), 0.0223, 0.0, "table below the first point");
  expect_near(sphm_law_eval(&law, 900.0), 0.0338, 0.0, "table above the last point");

  for (int kind = 0; kind < SPHM_NLAWS; kind++)
    expect_near(sphm_law_lookup(sphm_law_name(kind)), kind, 0.0, "name and lookup agree");
  expect_near(sphm_law_lookup("quadratic"), -1, 0.0, "unknown law");
  expect_near(sphm_law_ncoeffs(SPHM_LINEAR), 3, 0.0, "linear takes 3 coefficients");

  /* one material for mean interface: same kind, coefficients and table */
  {
    const double t2[4] = {250.0, 300.0, 350.0, 400.0}, p2[4] = {0.0223, 0.0263, 0.0301, 0.0338};
    sphm_law same = law, other = law;
    same.table_t = t2; /* equal values, another copy */
    expect_near(sphm_law_same(&law, &same), 1, 0.0, "a copy of a table is the same law");
    other.table_p = p2;
    expect_near(sphm_law_same(&law, &other), 0, 0.0, "one table value differs");
    other = law;
    other.ntable = 3;
    expect_near(sphm_law_same(&law, &other), 0, 0.0, "a shorter table differs");
    sphm_law a = {SPHM_CONSTANT, {2.5, 0.0, 0.0}, 0, 0, 0}, b = a;
    expect_near(sphm_law_same(&a, &b), 1, 0.0, "equal constants are one material");
    b.c[0] = 2.5000001;
    expect_near(sphm_law_same(&a, &b), 0, 0.0, "different constants");
    b = a;
    b.kind = SPHM_LINEAR;
    expect_near(sphm_law_same(&a, &b), 0, 0.0, "constant and linear with the same c0");
    b = a;
    b.c[1] = 0.1;
    b.kind = SPHM_EXPONENTIAL;
    a.kind = SPHM_EXPONENTIAL;
    expect_near(sphm_law_same(&a, &b), 0, 0.0, "exponentials with different rates");
  }

  if (failures == 0) printf("PASS material laws\n");
  return failures ? 1 : 0;
}
