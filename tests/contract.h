/* SPDX-License-Identifier: BSD-3-Clause */
/* The input contract shared by every contact function (pw85_contact_function
 * and the two legacy ones), checked the same way for each: a NULL pointer
 * gives PW85_EFAULT, a NaN or infinity anywhere PW85_EDOM, a form that is
 * not positive definite PW85_ENOTPOSDEF (even with coincident centres), all
 * with out untouched; coincident centres give μ² = 0, λ = ½. Header-only
 * test code. */
#ifndef PW85_TESTS_CONTRACT_H
#define PW85_TESTS_CONTRACT_H

#include <glib.h>
#include <math.h>
#include <pw85.h>
#include <string.h>

typedef int (*ContactFn)(double const *, double const *, double const *,
                         double *);

/* A valid input: the tutorial's pair. */
static double const contract_r[PW85_DIM] = {0.7, -0.7, 1.1};
static double const contract_q1[PW85_SYM] = {100., 0., 0., 100., 0., 0.01};
static double const contract_q2[PW85_SYM] = {25., 0., 0., 0.25, 0., 0.25};

/* Sentinels: a failing call must leave out exactly as it was. */
static double const contract_sentinel[2] = {42., -7.};

static inline int contract_call(ContactFn fn, double const *r,
                                double const *q1, double const *q2,
                                double out[2]) {
  memcpy(out, contract_sentinel, sizeof contract_sentinel);
  return fn(r, q1, q2, out);
}

static inline void contract_assert_untouched(double const out[2]) {
  g_assert_cmpmem(out, 2 * sizeof(double), contract_sentinel,
                  sizeof contract_sentinel);
}

/* A successful call: status PW85_SUCCESS, μ² finite and ≥ 0, λ in [0, 1]. */
/* contract_call() of pw85_contact_function. */
static inline int contract_cf(double const *r, double const *q1,
                              double const *q2, double out[2]) {
  return contract_call(pw85_contact_function, r, q1, q2, out);
}

static inline void contract_assert_valid(int status, double const out[2]) {
  g_assert_cmpint(status, ==, PW85_SUCCESS);
  g_assert_true(isfinite(out[0]));
  g_assert_cmpfloat(out[0], >=, 0.);
  g_assert_cmpfloat(out[1], >=, 0.);
  g_assert_cmpfloat(out[1], <=, 1.);
}

static inline void contract_check_null(ContactFn fn) {
  double const *r = contract_r, *q1 = contract_q1, *q2 = contract_q2;
  double out[2];
  g_assert_cmpint(contract_call(fn, NULL, q1, q2, out), ==, PW85_EFAULT);
  contract_assert_untouched(out);
  g_assert_cmpint(contract_call(fn, r, NULL, q2, out), ==, PW85_EFAULT);
  contract_assert_untouched(out);
  g_assert_cmpint(contract_call(fn, r, q1, NULL, out), ==, PW85_EFAULT);
  contract_assert_untouched(out);
  g_assert_cmpint(fn(r, q1, q2, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(contract_call(fn, NULL, NULL, NULL, out), ==, PW85_EFAULT);
  contract_assert_untouched(out);
}

/* NaN, +∞ and −∞ in each of the 15 positions. */
static inline void contract_check_not_finite(ContactFn fn) {
  double const bad[] = {NAN, INFINITY, -INFINITY};
  for (size_t b = 0; b < G_N_ELEMENTS(bad); b++)
    for (int i = 0; i < PW85_DIM + 2 * PW85_SYM; i++) {
      double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
      memcpy(r, contract_r, sizeof r);
      memcpy(q1, contract_q1, sizeof q1);
      memcpy(q2, contract_q2, sizeof q2);
      if (i < PW85_DIM)
        r[i] = bad[b];
      else if (i < PW85_DIM + PW85_SYM)
        q1[i - PW85_DIM] = bad[b];
      else
        q2[i - PW85_DIM - PW85_SYM] = bad[b];
      g_assert_cmpint(contract_call(fn, r, q1, q2, out), ==, PW85_EDOM);
      contract_assert_untouched(out);
    }
}

static inline void contract_check_not_posdef(ContactFn fn) {
  double const not_pd[][PW85_SYM] = {
      {1., 0., 0., -1., 0., 1.},           /* indefinite, diagonal */
      {1., 2., 0., 1., 0., 1.},            /* indefinite, positive diagonal */
      {-1., 0., 0., -1., 0., -1.},         /* negative definite */
      {0., 0., 0., 0., 0., 0.},            /* zero */
      {1., 0., 0., 1., 0., 0.},            /* semi-definite, singular */
      {1., 1., 1., 1., 1., 1.},            /* rank one */
      {1e300, 0., 0., 1e300, 0., -1e-300}, /* wide range, last pivot < 0 */
  };
  double const zero[PW85_DIM] = {0., 0., 0.};
  for (size_t k = 0; k < G_N_ELEMENTS(not_pd); k++) {
    double out[2];
    g_assert_cmpint(contract_call(fn, contract_r, not_pd[k], contract_q2, out),
                    ==, PW85_ENOTPOSDEF);
    contract_assert_untouched(out);
    g_assert_cmpint(contract_call(fn, contract_r, contract_q1, not_pd[k], out),
                    ==, PW85_ENOTPOSDEF);
    contract_assert_untouched(out);
    /* An invalid quadratic form is an error even with coincident centres. */
    g_assert_cmpint(contract_call(fn, zero, not_pd[k], contract_q2, out), ==,
                    PW85_ENOTPOSDEF);
    contract_assert_untouched(out);
  }
}

static inline void contract_check_coincident(ContactFn fn) {
  double const zeros[][PW85_DIM] = {{0., 0., 0.}, {-0., 0., -0.}};
  for (size_t k = 0; k < G_N_ELEMENTS(zeros); k++) {
    double out[2];
    g_assert_cmpint(contract_call(fn, zeros[k], contract_q1, contract_q2, out),
                    ==, PW85_SUCCESS);
    g_assert_cmpfloat(out[0], ==, 0.);
    g_assert_cmpfloat(out[1], ==, 0.5);
  }
}

/* The same pair with every length scaled by t: r → t·r, Q → t²·Q, under
 * which μ² and λ are invariant. */
static inline void contract_scaled(double t, double const r0[PW85_DIM],
                                   double const q1_0[PW85_SYM],
                                   double const q2_0[PW85_SYM],
                                   double r[PW85_DIM], double q1[PW85_SYM],
                                   double q2[PW85_SYM]) {
  for (int i = 0; i < PW85_DIM; i++) r[i] = t * r0[i];
  for (int i = 0; i < PW85_SYM; i++) {
    q1[i] = (t * t) * q1_0[i];
    q2[i] = (t * t) * q2_0[i];
  }
}

#endif /* PW85_TESTS_CONTRACT_H */
