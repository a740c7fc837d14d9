/* SPDX-License-Identifier: BSD-3-Clause */
/* Helpers shared by the tests of libpw85_legacy (header-only, test code):
 * the worst error of a sweep and where it occurred, and the report of a
 * failed comparison. */
#ifndef PW85_TESTS_LEGACY_TESTUTIL_H
#define PW85_TESTS_LEGACY_TESTUTIL_H

#include <glib.h>
#include <math.h>
#include <stddef.h>

/* |act − exp| / |exp|; |act − exp| when exp = 0 (then exact agreement is
 * expected: f(0) = f(1) = 0). NaN propagates. */
static inline double legacy_rel_err(double act, double exp) {
  double const d = fabs(act - exp);
  return exp == 0.0 ? d : d / fabs(exp);
}

/* The worst error of a sweep, where it occurred, how many cases were read
 * and how many exceeded the tolerance. */
typedef struct {
  const char *what;
  double tol;
  double err;
  size_t index;
  size_t count;
  size_t failures;
} Worst;

static inline Worst worst_init(const char *what, double tol) {
  Worst w = {what, tol, 0.0, 0, 0, 0};
  return w;
}

/* Records one comparison; names the first few failing records (record,
 * actual, expected, relative error) and fails the test. */
static inline void worst_check(Worst *w, size_t index, double act, double exp,
                               double err) {
  w->count++;
  if (err > w->err || (isnan(err) && !isnan(w->err))) {
    w->err = err;
    w->index = index;
  }
  if (!(err <= w->tol)) {
    if (w->failures < 10)
      g_test_message(
          "%s: record %zu: actual %.17g, expected %.17g, relative "
          "error %.3g > %.3g",
          w->what, index, act, exp, err, w->tol);
    w->failures++;
    g_test_fail();
  }
}

/* Prints the worst error (a TAP comment) and fails when no case was read. */
static inline void worst_report(Worst const *w) {
  g_test_message(
      "%s: %zu cases, worst error %.3g at record %zu (tolerance "
      "%.3g), %zu above it",
      w->what, w->count, w->err, w->index, w->tol, w->failures);
  if (w->count == 0) {
    g_test_message("%s: no case was read", w->what);
    g_test_fail();
  }
}

#endif /* PW85_TESTS_LEGACY_TESTUTIL_H */
