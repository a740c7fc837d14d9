/* SPDX-License-Identifier: BSD-3-Clause */
/* Helpers shared by the GLib test programs (header-only, test code). */
#ifndef PW85_TESTUTIL_H
#define PW85_TESTUTIL_H

#include <glib.h>
#include <gsl/gsl_errno.h>
#include <math.h>

/* Relative error |act − exp| / |exp|; the absolute error when exp = 0. */
static inline double rel_err(double act, double exp) {
  double const d = fabs(act - exp);
  return exp == 0.0 ? d : d / fabs(exp);
}

/* Fails the current test, naming the case, when rel_err(act, exp) > tol. */
#define assert_close(what, act, exp, tol)                                    \
  do {                                                                       \
    double const act_ = (act), exp_ = (exp), tol_ = (tol);                   \
    double const err_ = rel_err(act_, exp_);                                 \
    if (!(err_ <= tol_))                                                     \
      g_error("%s: actual %.17g, expected %.17g, relative error %.3g > %.3g", \
              (what), act_, exp_, err_, tol_);                               \
  } while (0)

/* pw85 must never reach GSL's error handler (whose default aborts). The
 * tests install this one, as an application may: reaching it fails the
 * test that is running. */
static inline void failing_gsl_handler(const char *reason, const char *file,
                                       int line, int gsl_errno) {
  g_test_message("GSL error handler reached: %s (%s:%d, error %d)", reason,
                 file, line, gsl_errno);
  g_test_fail();
}

static inline void install_failing_gsl_handler(void) {
  gsl_set_error_handler(&failing_gsl_handler);
}

#endif /* PW85_TESTUTIL_H */
