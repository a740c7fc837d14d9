/* SPDX-License-Identifier: BSD-3-Clause */
/* The contact function and the overlap test on general ellipsoid pairs,
 * read from the file PW85_GENERAL_PAIRS names (data/README.md; references
 * correctly rounded from exact arithmetic). Run twice by meson:
 * general-pairs on data/pw85_general_pairs.h5, 2000 seeded triaxial pairs
 * with aspect ratios to 1e4 and random orientations, 800 at generic
 * distances and 1200 nearly tangent (|μ² − 1| = 1e-14 … 1e-3);
 * finish-pairs on data/pw85_finish_pairs.h5, pairs (aspect ratios to 1e6)
 * on which removing a step of the compensated finish (the compensated
 * step, the quadratic-model gain or the f_lo carry) changes μ². */
#include <float.h>
#include <pw85.h>

#include "refdata.h"
#include "testutil.h"

static GeneralPairs pairs;

static double const *r12(size_t n) { return pairs.r12 + 3 * n; }
static double const *q1(size_t n) { return pairs.q1 + 6 * n; }
static double const *q2(size_t n) { return pairs.q2 + 6 * n; }

/* μ² correctly rounded (as the README and the docs claim: the reference is
 * the correctly rounded μ², so any difference is at least an ulp; issue 6
 * asks for one ulp) and λ to 1e-9 (issue 6); measured worst errors
 * printed. */
static void test_contact_function(void) {
  Worst wmu = worst_init("mu^2 vs MU2", 0.);
  Worst wl = worst_init("|lambda - LAMBDA|", 1e-9);
  for (size_t n = 0; n < pairs.count; n++) {
    double out[2];
    int const status = pw85_contact_function(r12(n), q1(n), q2(n), out);
    if (status != PW85_SUCCESS) {
      test_mismatch("case %zu: status %d (%s)", n, status,
                    pw85_strerror(status));
      continue;
    }
    worst_check(&wmu, n, out[0], pairs.MU2[n], rel_err(out[0], pairs.MU2[n]));
    worst_check(&wl, n, out[1], pairs.LAMBDA[n],
                fabs(out[1] - pairs.LAMBDA[n]));
  }
  worst_report(&wmu);
  worst_report(&wl);
}

/* pw85_overlap never contradicts the exact μ²: −1 when μ² < 1, +1 when
 * μ² > 1, and 0 only within 4 ulps of 1. */
static void test_overlap(void) {
  size_t zero = 0;
  for (size_t n = 0; n < pairs.count; n++) {
    int result = 42;
    g_assert_cmpint(pw85_overlap(r12(n), q1(n), q2(n), &result), ==,
                    PW85_SUCCESS);
    double const d = pairs.MU2_MINUS_1[n];
    int const expected = fabs(d) <= 4. * DBL_EPSILON ? 0 : (d < 0. ? -1 : 1);
    if (result == 0) zero++;
    if (result != expected && !(result == 0 && fabs(d) <= 4. * DBL_EPSILON))
      test_mismatch("case %zu: pw85_overlap gives %d, expected %d "
                    "(mu^2 - 1 = %.3g)",
                    n, result, expected, d);
  }
  g_test_message("%zu cases, %zu reported tangent", pairs.count, zero);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  general_pairs_load_or_fail(&pairs);
  g_test_add_func("/pw85/general_pairs/contact_function",
                  test_contact_function);
  g_test_add_func("/pw85/general_pairs/overlap", test_overlap);
  int const status = g_test_run();
  general_pairs_clear(&pairs);
  return status;
}
