/* SPDX-License-Identifier: BSD-3-Clause */
/* How the GLib tests compare numbers (header-only, test code): the relative
 * error, and the worst error of a sweep with where it occurred. A mismatch
 * fails the running test with g_test_fail_printf() (GLib >= 2.70) naming
 * the record, the actual and expected values and the error, and the test
 * goes on: with `-k` (tests/meson.build) one failure hides nothing. */
#ifndef PW85_TESTS_WORST_H
#define PW85_TESTS_WORST_H

#include <glib.h>
#include <math.h>
#include <stddef.h>

/* |act − exp| / |exp|; |act − exp| when exp = 0 (then exact agreement is
 * expected, as for f(0) = f(1) = 0). NaN propagates. */
static inline double rel_err(double act, double exp) {
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

/* The failing records named in full by one sweep; the rest are counted. */
#define WORST_NAMED_FAILURES 10

static inline Worst worst_init(const char *what, double tol) {
  Worst w = {what, tol, 0.0, 0, 0, 0};
  return w;
}

/* Records one comparison of record `index` (err is its error, computed by
 * the caller, NaN counting as a failure); fails the test when err exceeds
 * the tolerance, naming the first WORST_NAMED_FAILURES such records. */
static inline void worst_check(Worst *w, size_t index, double act, double exp,
                               double err) {
  w->count++;
  if (err > w->err || (isnan(err) && !isnan(w->err))) {
    w->err = err;
    w->index = index;
  }
  if (!(err <= w->tol)) {
    if (w->failures < WORST_NAMED_FAILURES)
      g_test_fail_printf(
          "%s: record %zu: actual %.17g, expected %.17g, error %.3g > %.3g",
          w->what, index, act, exp, err, w->tol);
    else
      g_test_fail();
    w->failures++;
  }
}

/* Prints the worst error (a TAP comment) and fails when no case was read. */
static inline void worst_report(Worst const *w) {
  g_test_message(
      "%s: %zu cases, worst error %.3g at record %zu (tolerance "
      "%.3g), %zu above it",
      w->what, w->count, w->err, w->index, w->tol, w->failures);
  if (w->count == 0) g_test_fail_printf("%s: no case was read", w->what);
}

#endif /* PW85_TESTS_WORST_H */
