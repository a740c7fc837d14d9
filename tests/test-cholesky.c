/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85__cholesky_decomp and pw85__cholesky_solve on matrices whose factor
 * and solution are small integers, so that every step is exact. */
#include <pw85.h>

#include "testutil.h"

/* L = [[2, 0, 0], [1, 3, 0], [-1, 2, 4]], A = L·Lᵀ. */
static double const a_int[PW85_SYM] = {4., 2., -2., 10., 5., 21.};
static double const l_int[PW85_SYM] = {2., 1., -1., 3., 2., 4.};

static void test_decomp_exact(void) {
  double l[PW85_SYM];
  pw85__cholesky_decomp(a_int, l);
  for (int i = 0; i < PW85_SYM; i++) g_assert_cmpfloat(l[i], ==, l_int[i]);
}

static void test_decomp_diagonal(void) {
  double const a[PW85_SYM] = {9., 0., 0., 0.25, 0., 1e-300};
  double l[PW85_SYM];
  pw85__cholesky_decomp(a, l);
  double const expected[PW85_SYM] = {3., 0., 0., 0.5, 0., 1e-150};
  for (int i = 0; i < PW85_SYM; i++)
    assert_close("diagonal factor, l[%d]", l[i], expected[i], 0.0, i);
}

static void test_decomp_in_place(void) {
  double a[PW85_SYM];
  for (int i = 0; i < PW85_SYM; i++) a[i] = a_int[i];
  pw85__cholesky_decomp(a, a);
  for (int i = 0; i < PW85_SYM; i++) g_assert_cmpfloat(a[i], ==, l_int[i]);
}

static void test_decomp_not_posdef(void) {
  /* Indefinite: the second pivot is 1 − 4 < 0. */
  double const a[PW85_SYM] = {1., 2., 0., 1., 0., 1.};
  double l[PW85_SYM] = {0};
  pw85__cholesky_decomp(a, l);
  for (int i = 0; i < PW85_SYM; i++) g_assert_true(isnan(l[i]));
}

static void test_solve_exact(void) {
  /* A·(1, 2, 3) = (2, 37, 71). */
  double const b[PW85_DIM] = {2., 37., 71.};
  double x[PW85_DIM];
  pw85__cholesky_solve(l_int, b, x);
  g_assert_cmpfloat(x[0], ==, 1.);
  g_assert_cmpfloat(x[1], ==, 2.);
  g_assert_cmpfloat(x[2], ==, 3.);
}

static void test_solve_in_place(void) {
  double x[PW85_DIM] = {2., 37., 71.};
  pw85__cholesky_solve(l_int, x, x);
  g_assert_cmpfloat(x[0], ==, 1.);
  g_assert_cmpfloat(x[1], ==, 2.);
  g_assert_cmpfloat(x[2], ==, 3.);
}

static void test_roundtrip(void) {
  /* A = L·Lᵀ for a non-integer L: decomposition then solve recovers x to
   * a few ulps (measured: 2.2e-16; tolerance 4 ulps). */
  double const l0[PW85_SYM] = {1.5, 0.3, -0.7, 2.25, 0.125, 0.8};
  double const a[PW85_SYM] = {
      l0[0] * l0[0],          l0[0] * l0[1],
      l0[0] * l0[2],          l0[1] * l0[1] + l0[3] * l0[3],
      l0[1] * l0[2] + l0[3] * l0[4],
      l0[2] * l0[2] + l0[4] * l0[4] + l0[5] * l0[5]};
  double const x0[PW85_DIM] = {0.5, -1.25, 3.0};
  double const b[PW85_DIM] = {a[0] * x0[0] + a[1] * x0[1] + a[2] * x0[2],
                              a[1] * x0[0] + a[3] * x0[1] + a[4] * x0[2],
                              a[2] * x0[0] + a[4] * x0[1] + a[5] * x0[2]};
  double l[PW85_SYM], x[PW85_DIM];
  pw85__cholesky_decomp(a, l);
  for (int i = 0; i < PW85_SYM; i++)
    assert_close("factor, l[%d]", l[i], l0[i], 8.9e-16, i);
  pw85__cholesky_solve(l, b, x);
  for (int i = 0; i < PW85_DIM; i++)
    assert_close("solution, x[%d]", x[i], x0[i], 8.9e-16, i);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  g_test_add_func("/pw85/cholesky/decomp/exact", test_decomp_exact);
  g_test_add_func("/pw85/cholesky/decomp/diagonal", test_decomp_diagonal);
  g_test_add_func("/pw85/cholesky/decomp/in-place", test_decomp_in_place);
  g_test_add_func("/pw85/cholesky/decomp/not-posdef", test_decomp_not_posdef);
  g_test_add_func("/pw85/cholesky/solve/exact", test_solve_exact);
  g_test_add_func("/pw85/cholesky/solve/in-place", test_solve_in_place);
  g_test_add_func("/pw85/cholesky/roundtrip", test_roundtrip);
  return g_test_run();
}
