/* SPDX-License-Identifier: BSD-3-Clause */
/* The two implementations of f of libpw85_legacy (docs/implementation.rst) against the
 * dataset F of data/pw85_ref_data.h5 (correctly rounded references), and
 * the derivatives of implementation #1 against closed forms and finite
 * differences. Each sweep prints its worst error and where it occurred;
 * tolerances are at most 10× the measured worst. */
#include <pw85_legacy.h>
#include <string.h>

#include "worst.h"
#include "refdata.h"

static RefData data;

static double const *direction(size_t k) { return data.directions + 3 * k; }
static double const *spheroid(size_t i) { return data.spheroids + 6 * i; }

typedef double (*FFunc)(double, double const *, double const *, double const *,
                        double *);

/* Relative error against F over the whole dataset (f(0) = f(1) = 0 must
 * be exact). NaN results are counted, not compared: *num_nan gets their
 * number, and each must be at λ = 0 or 1. */
static void replay_f(FFunc func, Worst *w, size_t *num_nan) {
  *num_nan = 0;
  for (size_t i = 0; i < data.num_spheroids; i++)
    for (size_t j = 0; j < data.num_spheroids; j++)
      for (size_t k = 0; k < data.num_directions; k++)
        for (size_t l = 0; l < data.num_lambdas; l++) {
          size_t const n = ref_data_f_index(&data, i, j, k, l);
          double const exp = data.F[n];
          double out[3] = {NAN, NAN, NAN};
          double const act = func(data.lambdas[l], direction(k), spheroid(i),
                                  spheroid(j), out);
          /* out[0] is the returned value. */
          if (memcmp(&out[0], &act, sizeof act) != 0) {
            g_test_message("record %zu: out[0] = %.17g != returned %.17g", n,
                           out[0], act);
            g_test_fail();
          }
          if (isnan(act)) {
            if ((*num_nan)++ < 3)
              g_test_message("%s: record %zu (λ = %g): NaN", w->what, n,
                             data.lambdas[l]);
            if (data.lambdas[l] != 0. && data.lambdas[l] != 1.) {
              g_test_message("%s: record %zu: NaN inside (0, 1)", w->what, n);
              g_test_fail();
            }
            continue;
          }
          worst_check(w, n, act, exp, rel_err(act, exp));
        }
  worst_report(w);
  g_test_message("%s: %zu NaN results", w->what, *num_nan);
}

/* Implementation #1 (Cholesky), plain double arithmetic: errors grow with
 * the condition number of Q(λ), up to 2.5e7 here (aspect ratio 5,000).
 * Measured worst relative error over the 1,539,648 values: 3.47e-9 (record
 * 1035939); no NaN. */
#define TOL_F1 1e-8

static void test_f1_ref_data(void) {
  Worst w = worst_init("pw85_legacy_f1 vs F", TOL_F1);
  size_t num_nan;
  replay_f(pw85_legacy_f1, &w, &num_nan);
  g_assert_cmpuint(num_nan, ==, 0);
}

/* Implementation #2 (rational fraction): the coefficients of a and b come
 * from values at λ = 0, 1, −1, ½ (docs/implementation.rst, eqs. (4.12a)–(4.12g)) and cancel
 * when the ellipsoids differ much. Measured worst relative error of the
 * finite values: 1.33e-8 (record 1060024). For 96 pairs (q1, q2) the
 * computed b(1) = b0 + b1 + b2 + b3 rounds to exactly 0, so that
 * f(1) = 0·a(1)/0 is NaN: MAX_NAN_F2 = 96 pairs × 12 directions, all at
 * λ = 1. */
#define TOL_F2 1e-7
#define MAX_NAN_F2 1152

static void test_f2_ref_data(void) {
  Worst w = worst_init("pw85_legacy_f2 vs F", TOL_F2);
  size_t num_nan;
  replay_f(pw85_legacy_f2, &w, &num_nan);
  g_assert_cmpuint(num_nan, <=, MAX_NAN_F2);
}

/* Coaxial pairs Q1 = diag(p), Q2 = diag(q): f is the sum over i of
 * t_i(λ) = r_i²·λ(1−λ)/d_i(λ), d_i = (1−λ)p_i + λq_i, δ_i = q_i − p_i;
 * with N = λ(1−λ): t′ = r²(N′d − Nδ)/d², t″ = r²[N″d² − 2δ(N′d − Nδ)]/d³.
 * Evaluated in long double (t″ cancels). */
static void coaxial_f(double lambda, double const r[3], double const p[3],
                      double const q[3], double out[3], double scale[3]) {
  long double const l = lambda;
  long double const n = l * (1.0L - l), n1 = 1.0L - 2.0L * l, n2 = -2.0L;
  long double f = 0.0L, f1 = 0.0L, f2 = 0.0L;
  long double rs = 0.0L, su = 0.0L, uv = 0.0L; /* docs/implementation.rst, eqs. (4.4)–(4.9) */
  for (int i = 0; i < 3; i++) {
    long double const d = (1.0L - l) * p[i] + l * q[i];
    long double const delta = (long double)q[i] - p[i];
    long double const r2 = (long double)r[i] * r[i];
    f += r2 * n / d;
    f1 += r2 * (n1 * d - n * delta) / (d * d);
    f2 += r2 * (n2 * d * d - 2.0L * delta * (n1 * d - n * delta)) / (d * d * d);
    rs += r2 / d;
    su += r2 * delta / (d * d);
    uv += r2 * delta * delta / (d * d * d);
  }
  /* The sizes of the terms of eqs. (4), (6) and (9). */
  scale[0] = (double)f;
  scale[1] = (double)(fabsl(n1) * rs + n * fabsl(su) + f);
  scale[2] = (double)(2.0L * rs + 2.0L * fabsl(n1 * su) + 2.0L * n * uv);
  out[0] = (double)f;
  out[1] = (double)f1;
  out[2] = (double)f2;
}

/* The sizes of the terms of docs/implementation.rst, eqs. (4.6) and (9), from f, f′, f″
 * (rᵀs = f/N, sᵀu = ((1−2λ)rᵀs − f′)/N, uᵀv = (f″ + 2rᵀs +
 * 2(1−2λ)sᵀu)/(2N), N = λ(1−λ)): the natural scale of their rounding
 * errors, since both sums cancel (f′ vanishes at the maximiser). f is added
 * to the scale of f′, whose terms vanish together at λ = ½ when Q1 = Q2. */
static void term_scales(double lambda, double const d[3], double scale[3]) {
  double const n = lambda * (1. - lambda), n1 = 1. - 2. * lambda;
  double const rs = d[0] / n;
  double const su = (n1 * rs - d[1]) / n;
  double const uv = (d[2] + 2. * rs + 2. * n1 * su) / (2. * n);
  scale[0] = fabs(d[0]);
  scale[1] = fabs(n1) * rs + n * fabs(su) + d[0];
  scale[2] = 2. * rs + 2. * fabs(n1 * su) + 2. * n * fabs(uv);
}

/* Against the closed forms, for coaxial pairs from spheres to aspect ratio
 * 1e4 (references in long double), λ = 0.05, 0.1, ..., 0.95. Errors
 * relative to f, and to the size of the terms of eqs. (6) and (9) for f′
 * and f″. Measured worst: 6.4e-16 (f), 4.8e-16 (f′), 4.1e-16 (f″). */
#define TOL_F_CLOSED 4.5e-15
#define TOL_DERIV_CLOSED 4e-15

static void test_f1_derivatives_closed_form(void) {
  double const semi[][3] = {{1., 1., 1.},   {3., 3., 3.},   {1., 2., 3.},
                            {0.01, 1., 1.}, {100., 1., 1.}, {1., 1e-2, 1e2},
                            {5., 0.2, 0.05}};
  double const rs[][3] = {{1., 0., 0.}, {0.3, -0.4, 1.2}, {1., 1., 1.}};
  size_t const ns = G_N_ELEMENTS(semi);
  Worst w0 = worst_init("f1 closed form, f", TOL_F_CLOSED);
  Worst w1 = worst_init("f1 closed form, f'", TOL_DERIV_CLOSED);
  Worst w2 = worst_init("f1 closed form, f''", TOL_DERIV_CLOSED);
  size_t n = 0;
  for (size_t a = 0; a < ns; a++)
    for (size_t b = 0; b < ns; b++)
      for (size_t c = 0; c < G_N_ELEMENTS(rs); c++)
        for (int l = 1; l < 20; l++, n++) {
          double p[3], q[3];
          for (int i = 0; i < 3; i++) {
            p[i] = semi[a][i] * semi[a][i];
            q[i] = semi[b][i] * semi[b][i];
          }
          double const q1[PW85_SYM] = {p[0], 0., 0., p[1], 0., p[2]};
          double const q2[PW85_SYM] = {q[0], 0., 0., q[1], 0., q[2]};
          double const lambda = l / 20.;
          double exp[3], act[3], scale[3];
          coaxial_f(lambda, rs[c], p, q, exp, scale);
          pw85_legacy_f1(lambda, rs[c], q1, q2, act);
          worst_check(&w0, n, act[0], exp[0], rel_err(act[0], exp[0]));
          worst_check(&w1, n, act[1], exp[1], fabs(act[1] - exp[1]) / scale[1]);
          worst_check(&w2, n, act[2], exp[2], fabs(act[2] - exp[2]) / scale[2]);
        }
  worst_report(&w0);
  worst_report(&w1);
  worst_report(&w2);
}

/* f′ and f″ against central differences, Richardson-extrapolated (error
 * O(h⁴)), of f (−pw85_f_neg of libpw85: correctly rounded, so that the
 * difference quotient is not swamped by the rounding errors of f) and of
 * f1's own f′, over a sample of the reference pairs (every 5th spheroid,
 * every direction, λ = 0.1, ..., 0.9), with h = STEPk·min(λ, 1−λ), the
 * steps that minimised the measured error. Errors relative to the size of
 * the terms of eqs. (6) and (9). Measured worst: 2.28e-9 (f′), 4.04e-7
 * (f″, whose difference quotient carries the rounding errors of f′). */
#define STEP1 1e-2
#define STEP2 3e-2
#define TOL_FD1 2e-8
#define TOL_FD2 4e-6

typedef struct {
  double params[PW85_DIM + 2 * PW85_SYM];
} Params;

static double f_of(double lambda, Params const *p) {
  return -pw85_f_neg(lambda, p->params);
}

static double df_of(double lambda, Params const *p) {
  double out[3];
  pw85_legacy_f1(lambda, p->params, p->params + PW85_DIM,
                 p->params + PW85_DIM + PW85_SYM, out);
  return out[1];
}

static double richardson(double (*g)(double, Params const *), Params const *p,
                         double lambda, double h) {
  double const d1 = (g(lambda + h, p) - g(lambda - h, p)) / (2. * h);
  double const d2 = (g(lambda + 0.5 * h, p) - g(lambda - 0.5 * h, p)) / h;
  return (4. * d2 - d1) / 3.;
}

static void test_f1_derivatives_finite_differences(void) {
  Worst w1 = worst_init("f1 finite differences, f'", TOL_FD1);
  Worst w2 = worst_init("f1 finite differences, f''", TOL_FD2);
  for (size_t i = 0; i < data.num_spheroids; i += 5)
    for (size_t j = 0; j < data.num_spheroids; j += 5)
      for (size_t k = 0; k < data.num_directions; k++)
        for (size_t l = 1; l + 1 < data.num_lambdas; l++) {
          size_t const n = ref_data_f_index(&data, i, j, k, l);
          Params p;
          memcpy(p.params, direction(k), PW85_DIM * sizeof(double));
          memcpy(p.params + PW85_DIM, spheroid(i), PW85_SYM * sizeof(double));
          memcpy(p.params + PW85_DIM + PW85_SYM, spheroid(j),
                 PW85_SYM * sizeof(double));
          double const lambda = data.lambdas[l];
          double const delta = fmin(lambda, 1. - lambda);
          double out[3], scale[3];
          pw85_legacy_f1(lambda, direction(k), spheroid(i), spheroid(j), out);
          term_scales(lambda, out, scale);
          double const fd1 = richardson(f_of, &p, lambda, STEP1 * delta);
          double const fd2 = richardson(df_of, &p, lambda, STEP2 * delta);
          worst_check(&w1, n, out[1], fd1, fabs(out[1] - fd1) / scale[1]);
          worst_check(&w2, n, out[2], fd2, fabs(out[2] - fd2) / scale[2]);
        }
  worst_report(&w1);
  worst_report(&w2);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  ref_data_load_or_fail(&data);
  g_test_add_func("/pw85/legacy/f1/ref_data", test_f1_ref_data);
  g_test_add_func("/pw85/legacy/f2/ref_data", test_f2_ref_data);
  g_test_add_func("/pw85/legacy/f1/derivatives/closed-form",
                  test_f1_derivatives_closed_form);
  g_test_add_func("/pw85/legacy/f1/derivatives/finite-differences",
                  test_f1_derivatives_finite_differences);
  int const status = g_test_run();
  ref_data_clear(&data);
  return status;
}
