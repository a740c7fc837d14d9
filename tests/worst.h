/* SPDX-License-Identifier: BSD-3-Clause */
/* How the GLib tests compare numbers (header-only, test code): the relative
 * error, the report of a mismatch, and the worst error of a sweep with
 * where it occurred. A mismatch never aborts: it is printed (a TAP comment,
 * in meson's test log) and fails the running test, which goes on; with
 * `-k` (tests/meson.build) the program goes on to the next test too. */
#ifndef PW85_TESTS_WORST_H
#define PW85_TESTS_WORST_H

#include <glib.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>

/* |act − exp| / |exp|; |act − exp| when exp = 0 (then exact agreement is
 * expected, as for f(0) = f(1) = 0). NaN propagates. */
static inline double rel_err(double act, double exp) {
  double const d = fabs(act - exp);
  return exp == 0.0 ? d : d / fabs(exp);
}

/* Reports one mismatch (printf format and arguments): prints it, so that
 * every mismatch reaches the log (g_test_fail_printf keeps only the last
 * message of a test), and fails the running test with it (GLib >= 2.70),
 * so that the test's "not ok" line names it too. */
static inline void test_mismatch(const char *format, ...) G_GNUC_PRINTF(1, 2);
static inline void test_mismatch(const char *format, ...) {
  va_list args;
  va_start(args, format);
  char *message = g_strdup_vprintf(format, args);
  va_end(args);
  g_test_message("%s", message);
  g_test_fail_printf("%s", message);
  g_free(message);
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
    /* Past the first few the test has failed already: counted only. */
    if (w->failures < WORST_NAMED_FAILURES)
      test_mismatch(
          "%s: record %zu: actual %.17g, expected %.17g, error %.3g > %.3g",
          w->what, index, act, exp, err, w->tol);
    w->failures++;
  }
}

/* Prints the worst error (a TAP comment); fails with a summary when a case
 * exceeded the tolerance, and when no case was read. */
static inline void worst_report(Worst const *w) {
  g_test_message(
      "%s: %zu cases, worst error %.3g at record %zu (tolerance "
      "%.3g), %zu above it",
      w->what, w->count, w->err, w->index, w->tol, w->failures);
  if (w->failures > 0)
    g_test_fail_printf("%s: %zu of %zu records above %.3g, worst %.3g at "
                       "record %zu",
                       w->what, w->failures, w->count, w->tol, w->err,
                       w->index);
  if (w->count == 0) g_test_fail_printf("%s: no case was read", w->what);
}

#endif /* PW85_TESTS_WORST_H */
