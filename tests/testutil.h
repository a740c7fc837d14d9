/* SPDX-License-Identifier: BSD-3-Clause */
/* Helpers shared by the GLib test programs (header-only, test code). */
#ifndef PW85_TESTUTIL_H
#define PW85_TESTUTIL_H

#include <glib.h>
#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdarg.h>

#include "worst.h"

/* Compares act with exp: on a relative error (tests/worst.h) above tol
 * (or NaN), reports the mismatch (test_mismatch: printed, and the running
 * test failed with g_test_fail_printf) naming the case (what, a printf
 * format whose arguments follow tol), the actual and expected values and
 * the error, and returns FALSE. The test goes on: with `-k`
 * (tests/meson.build) one failure hides nothing. */
static inline gboolean assert_close(const char *what, double act, double exp,
                                    double tol, ...) G_GNUC_PRINTF(1, 5);
static inline gboolean assert_close(const char *what, double act, double exp,
                                    double tol, ...) {
  double const err = rel_err(act, exp);
  if (err <= tol) return TRUE;
  va_list args;
  va_start(args, tol);
  char *name = g_strdup_vprintf(what, args);
  va_end(args);
  test_mismatch("%s: actual %.17g, expected %.17g, relative error %.3g > %.3g",
                name, act, exp, err, tol);
  g_free(name);
  return FALSE;
}

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

/* q = R·diag(e)·Rᵀ (storage of pw85.h) for a random rotation R, from a
 * random unit quaternion: a symmetric form of eigenvalues e. */
/* A random unit quaternion (w, x, y, z): uniform entries in (−1, 1),
 * normalised in double. */
static inline void random_unit_quaternion(GRand *rng, double p[4]) {
  double norm = 0.;
  for (int k = 0; k < 4; k++) {
    p[k] = g_rand_double_range(rng, -1., 1.);
    norm += p[k] * p[k];
  }
  norm = sqrt(norm);
  for (int k = 0; k < 4; k++) p[k] /= norm;
}

/* The rotation of the unit quaternion p, row by row (v ↦ p v p*), in
 * double: orthonormal to a few u. */
static inline void quaternion_rotation(double const p[4], double r[9]) {
  double const w = p[0], x = p[1], y = p[2], z = p[3];
  double const m[9] = {1. - 2. * (y * y + z * z), 2. * (x * y - w * z),
                       2. * (x * z + w * y),      2. * (x * y + w * z),
                       1. - 2. * (x * x + z * z), 2. * (y * z - w * x),
                       2. * (x * z - w * y),      2. * (y * z + w * x),
                       1. - 2. * (x * x + y * y)};
  for (int k = 0; k < 9; k++) r[k] = m[k];
}

/* Q = R·diag(e)·Rᵀ for a random rotation R. */
static inline void random_form_with_eigenvalues(GRand *rng, double const e[3],
                                                double q[6]) {
  double p[4], rot[9];
  random_unit_quaternion(rng, p);
  quaternion_rotation(p, rot);
  int k = 0;
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++, k++)
      q[k] = rot[3 * i] * e[0] * rot[3 * j] +
             rot[3 * i + 1] * e[1] * rot[3 * j + 1] +
             rot[3 * i + 2] * e[2] * rot[3 * j + 2];
}

#endif /* PW85_TESTUTIL_H */
