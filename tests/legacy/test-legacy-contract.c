/* SPDX-License-Identifier: BSD-3-Clause */
/* The input contract of the legacy functions: the contact functions take
 * that of pw85_contact_function (status codes, out untouched on error,
 * coincident centres), f1 and f2 that of pw85_f_neg (NaN). Bad or extreme
 * input always gets a documented answer, never a crash or an endless loop. */
#include <pw85_legacy.h>
#include <string.h>

#include "contract.h"
#include "testutil.h"
#include "worst.h"


/* A contact function and its measured accuracy on two tests below. */
typedef struct {
  const char *name;
  ContactFn func;
  double tol_spheres_mu2, tol_spheres_lambda, tol_scale;
} Impl;

/* Measured worst (see test_spheres, test_scale_invariance): function 1:
 * 3.9e-16 (μ², spheres), 2.2e-16 (λ, spheres), 1.9e-16 (scaling);
 * function 2: 7.3e-12, 8.8e-9, 5.7e-16. */
static Impl const impl1 = {"contact_function1", pw85_legacy_contact_function1,
                           3.5e-15, 2e-15, 1.5e-15};
static Impl const impl2 = {"contact_function2", pw85_legacy_contact_function2,
                           7e-11, 8e-8, 5e-15};

#define r_ok contract_r
#define q1_ok contract_q1
#define q2_ok contract_q2

static int call(Impl const *impl, double const *r, double const *q1,
                double const *q2, double out[2]) {
  return contract_call(impl->func, r, q1, q2, out);
}

static void assert_untouched(double const out[2]) {
  contract_assert_untouched(out);
}

/* The contract shared with pw85_contact_function (tests/contract.h). */
static void test_null(gconstpointer p) {
  contract_check_null(((Impl const *)p)->func);
}

static void test_not_finite(gconstpointer p) {
  contract_check_not_finite(((Impl const *)p)->func);
}

static void test_not_posdef(gconstpointer p) {
  contract_check_not_posdef(((Impl const *)p)->func);
}

static void test_coincident(gconstpointer p) {
  contract_check_coincident(((Impl const *)p)->func);
}

/* Two spheres of radii a1, a2: μ² = |r|²/(a1 + a2)², λ = a1/(a1 + a2).
 * Newton's method (contact_function1) fails as soon as the radii differ by
 * a factor 3.25 or more (a step from λ = ½ leaves [0, 1] and does not come
 * back): the documented lower bound is checked there. */

static void test_spheres(gconstpointer p) {
  Impl const *impl = p;
  struct {
    double a1, a2, r[PW85_DIM];
  } const cases[] = {{1., 1., {0.5, 0., 0.}},
                     {1., 3., {1., 2., 2.}},
                     {0.5, 2., {3., -4., 12.}},
                     {7., 0.25, {-0.3, 0.2, 0.1}},
                     {2.5, 2.5, {0., 0., 5.}}};
  Worst wm = worst_init("spheres, mu2", impl->tol_spheres_mu2);
  Worst wl = worst_init("spheres, lambda", impl->tol_spheres_lambda);
  size_t failures = 0;
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    double const a1 = cases[k].a1, a2 = cases[k].a2;
    double const q1[PW85_SYM] = {a1 * a1, 0., 0., a1 * a1, 0., a1 * a1};
    double const q2[PW85_SYM] = {a2 * a2, 0., 0., a2 * a2, 0., a2 * a2};
    double const *r = cases[k].r;
    double const norm2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    double const mu2 = norm2 / ((a1 + a2) * (a1 + a2));
    double out[2];
    int const status = call(impl, r, q1, q2, out);
    double const ratio = a1 > a2 ? a1 / a2 : a2 / a1;
    if (impl->func == pw85_legacy_contact_function1 && ratio >= 3.25) {
      g_assert_cmpint(status, ==, PW85_ENOCONV);
      failures++;
      g_assert_cmpfloat(out[0], <=, mu2 * (1. + 1e-15));
      g_assert_cmpfloat(out[1], >=, 0.);
      g_assert_cmpfloat(out[1], <=, 1.);
      continue;
    }
    g_assert_cmpint(status, ==, PW85_SUCCESS);
    worst_check(&wm, k, out[0], mu2, rel_err(out[0], mu2));
    worst_check(&wl, k, out[1], a1 / (a1 + a2),
                rel_err(out[1], a1 / (a1 + a2)));
  }
  worst_report(&wm);
  worst_report(&wl);
  g_test_message("%s: %zu of %zu sphere pairs failed (PW85_ENOCONV)",
                 impl->name, failures, G_N_ELEMENTS(cases));
}

/* μ²(t·r, t²·Q1, t²·Q2) = μ²(r, Q1, Q2) for t over 300 decades: the inputs
 * are rescaled by powers of two. A pair of mild ellipsoids, on which
 * Newton's method converges. t is not a power of two, so the scaled inputs
 * are rounded. */
static void test_scale_invariance(gconstpointer p) {
  Impl const *impl = p;
  double const r0[PW85_DIM] = {0.7, -0.7, 1.1};
  double const q1_0[PW85_SYM] = {4., 1., 0., 3., 0.5, 2.};
  double const q2_0[PW85_SYM] = {2., 0., 0.3, 5., 0., 1.};
  double ref[2];
  g_assert_cmpint(call(impl, r0, q1_0, q2_0, ref), ==, PW85_SUCCESS);
  double const scales[] = {1e-150, 1e-100, 1e-10, 1e10, 1e100, 1e150};
  Worst w = worst_init("scale invariance, mu2", impl->tol_scale);
  for (size_t k = 0; k < G_N_ELEMENTS(scales); k++) {
    double const t = scales[k];
    double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
    contract_scaled(t, r0, q1_0, q2_0, r, q1, q2);
    g_assert_cmpint(call(impl, r, q1, q2, out), ==, PW85_SUCCESS);
    worst_check(&w, k, out[0], ref[0], rel_err(out[0], ref[0]));
  }
  worst_report(&w);
}

static void test_overflow(gconstpointer p) {
  Impl const *impl = p;
  /* μ² = |r|²/(2a)² = 1e400/4e-200: beyond DBL_MAX. */
  double const r[PW85_DIM] = {1e200, 0., 0.};
  double const tiny[PW85_SYM] = {1e-200, 0., 0., 1e-200, 0., 1e-200};
  double out[2];
  g_assert_cmpint(call(impl, r, tiny, tiny, out), ==, PW85_ERANGE);
  g_assert_true(isinf(out[0]) && out[0] > 0.);
  g_assert_cmpfloat(fabs(out[1] - 0.5), <=, 1e-9);
  /* Diagonals spanning 1e308 to 5e-324 together: no power-of-two scaling
   * keeps both in range. */
  double const huge[PW85_SYM] = {1e308, 0., 0., 1e308, 0., 1e308};
  double const denormal[PW85_SYM] = {5e-324, 0., 0., 5e-324, 0., 5e-324};
  double const r1[PW85_DIM] = {1., 1., 1.};
  g_assert_cmpint(call(impl, r1, huge, denormal, out), ==, PW85_ERANGE);
  assert_untouched(out);
}

/* Needles and discs of aspect ratio up to 1e8, crossed, near and far: the
 * legacy methods may be inaccurate there, but every call returns a
 * documented status with a valid out. */
static void test_extreme_aspect(gconstpointer p) {
  Impl const *impl = p;
  double const ratios[] = {1e2, 1e4, 1e6, 1e8};
  double const dirs[][PW85_DIM] = {{1., 0., 0.},
                                   {0., 1., 0.},
                                   {0.6, 0.8, 0.},
                                   {1e-3, 2e-3, 1.},
                                   {1., 1., 1.}};
  size_t counts[8] = {0};
  for (size_t k = 0; k < G_N_ELEMENTS(ratios); k++) {
    double const rho = ratios[k];
    double const needle[PW85_SYM] = {rho * rho, 0., 0., 1., 0., 1.};
    double const disc[PW85_SYM] = {1., 0., 0., 1., 0., 1. / (rho * rho)};
    double const sphere[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
    double const *forms[] = {needle, disc, sphere};
    for (size_t i = 0; i < 3; i++)
      for (size_t j = 0; j < 3; j++)
        for (size_t d = 0; d < G_N_ELEMENTS(dirs); d++)
          for (int s = -3; s <= 3; s += 2) {
            double r[PW85_DIM], out[2];
            double const t = pow(10., s);
            for (int c = 0; c < PW85_DIM; c++) r[c] = t * dirs[d][c];
            int const status = call(impl, r, forms[i], forms[j], out);
            g_assert_true(status == PW85_SUCCESS || status == PW85_ENOCONV ||
                          status == PW85_ERANGE);
            counts[status]++;
            if (status == PW85_ERANGE) {
              assert_untouched(out);
              continue;
            }
            g_assert_true(isfinite(out[0]));
            g_assert_cmpfloat(out[0], >=, 0.);
            g_assert_cmpfloat(out[1], >=, 0.);
            g_assert_cmpfloat(out[1], <=, 1.);
          }
  }
  g_test_message(
      "%s, extreme aspect ratios: %zu success, %zu PW85_ENOCONV, "
      "%zu PW85_ERANGE",
      impl->name, counts[PW85_SUCCESS], counts[PW85_ENOCONV],
      counts[PW85_ERANGE]);
}

typedef double (*FFunc)(double, double const *, double const *, double const *,
                        double *);

static void check_f_contract(FFunc func, int num_out) {
  double out[3];
  g_assert_true(isfinite(func(0.5, r_ok, q1_ok, q2_ok, NULL)));
  g_assert_true(isfinite(func(0.5, r_ok, q1_ok, q2_ok, out)));
  for (int i = 0; i < num_out; i++) g_assert_true(isfinite(out[i]));
  g_assert_true(isnan(func(0.5, NULL, q1_ok, q2_ok, out)));
  for (int i = 0; i < num_out; i++) g_assert_true(isnan(out[i]));
  g_assert_true(isnan(func(0.5, r_ok, NULL, q2_ok, NULL)));
  g_assert_true(isnan(func(0.5, r_ok, q1_ok, NULL, NULL)));
  g_assert_true(isnan(func(NAN, r_ok, q1_ok, q2_ok, NULL)));
  g_assert_true(isnan(func(INFINITY, r_ok, q1_ok, q2_ok, NULL)));
  double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM];
  memcpy(r, r_ok, sizeof r);
  memcpy(q1, q1_ok, sizeof q1);
  memcpy(q2, q2_ok, sizeof q2);
  double *inputs[] = {r, q1, q2};
  int const sizes[] = {PW85_DIM, PW85_SYM, PW85_SYM};
  for (int a = 0; a < 3; a++)
    for (int i = 0; i < sizes[a]; i++) {
      double const saved = inputs[a][i];
      inputs[a][i] = NAN;
      g_assert_true(isnan(func(0.5, r, q1, q2, out)));
      for (int o = 0; o < num_out; o++) g_assert_true(isnan(out[o]));
      inputs[a][i] = -INFINITY;
      g_assert_true(isnan(func(0.5, r, q1, q2, NULL)));
      inputs[a][i] = saved;
    }
  /* Q(λ) not positive definite: q1 indefinite, λ = 0. */
  q1[3] = -1.;
  g_assert_true(isnan(func(0., r, q1, q2, out)));
  for (int o = 0; o < num_out; o++) g_assert_true(isnan(out[o]));
  /* f(0) = f(1) = 0 exactly. */
  g_assert_cmpfloat(func(0., r_ok, q1_ok, q2_ok, NULL), ==, 0.);
  g_assert_cmpfloat(func(1., r_ok, q1_ok, q2_ok, NULL), ==, 0.);
}

#define TOL_AGREE_F1 2e-15
#define TOL_AGREE_F2 2e-14

static void test_f1_contract(void) { check_f_contract(pw85_legacy_f1, 3); }
static void test_f2_contract(void) { check_f_contract(pw85_legacy_f2, 1); }

/* The two implementations agree with pw85_f_neg (implementation #1 of
 * libpw85, compensated) on the pair used above (aspect ratios 100 and 10),
 * λ = 0.1, ..., 0.9. Measured worst: f1 2.35e-16, f2 2.99e-15. */
static void test_f_agree(void) {
  double params[PW85_DIM + 2 * PW85_SYM];
  memcpy(params, r_ok, sizeof r_ok);
  memcpy(params + PW85_DIM, q1_ok, sizeof q1_ok);
  memcpy(params + PW85_DIM + PW85_SYM, q2_ok, sizeof q2_ok);
  Worst w1 = worst_init("f1 vs pw85_f_neg", TOL_AGREE_F1);
  Worst w2 = worst_init("f2 vs pw85_f_neg", TOL_AGREE_F2);
  for (int l = 1; l < 10; l++) {
    double const lambda = l / 10.;
    double const f = -pw85_f_neg(lambda, params);
    double const f1 = pw85_legacy_f1(lambda, r_ok, q1_ok, q2_ok, NULL);
    double const f2 = pw85_legacy_f2(lambda, r_ok, q1_ok, q2_ok, NULL);
    worst_check(&w1, (size_t)l, f1, f, rel_err(f1, f));
    worst_check(&w2, (size_t)l, f2, f, rel_err(f2, f));
  }
  worst_report(&w1);
  worst_report(&w2);
}

/* pw85_legacy_f1 returns NaN with NaN in every entry of out, also where
 * the computation overflows: at λ = 0 with r12 of 1e160, rᵀQ⁻¹r = ∞ and
 * f = 0·∞, while f′ and f″ would be ±∞ (Q1 = Q2, so that sᵀ(Q2 − Q1)s = 0
 * stays finite). */
static void test_f1_nan_everywhere(void) {
  double const r[PW85_DIM] = {1e160, -1e160, 1e160};
  double out[3] = {1., 2., 3.};
  double const f = pw85_legacy_f1(0., r, q1_ok, q1_ok, out);
  g_assert_true(isnan(f));
  for (int i = 0; i < 3; i++)
    if (!isnan(out[i])) test_mismatch("out[%d] = %g, not NaN", i, out[i]);
}

/* One definiteness rule (pw85.h): pw85_contact_function and both legacy
 * contact functions accept or reject the same forms, here forms
 * R·diag(1, e1, e2)·Rᵀ whose smallest eigenvalue e2 lies about the
 * resolution of a factorisation in double (±10^−19..−14), where rounding
 * decides; pw85__cholesky_decomp answers NaN for every rejected form, and
 * also for accepted ones singular to the precision of double. (The exact
 * verdicts: test-definite.) */
static void test_one_definiteness_rule(void) {
  GRand *rng = g_rand_new_with_seed(85);
  int rejected = 0, disagree = 0;
  int const count = 20000;
  for (int n = 0; n < count; n++) {
    double const e2 = (g_rand_boolean(rng) ? 1. : -1.) *
                      pow(10., g_rand_double_range(rng, -19., -14.));
    double const e[3] = {1., g_rand_double_range(rng, 0.5, 2.), e2};
    double q[PW85_SYM], l[PW85_SYM], out[2];
    random_form_with_eigenvalues(rng, e, q);
    gboolean const main1 =
        pw85_contact_function(r_ok, q, q2_ok, out) == PW85_ENOTPOSDEF;
    gboolean const main2 =
        pw85_contact_function(r_ok, q2_ok, q, out) == PW85_ENOTPOSDEF;
    gboolean const leg1 =
        pw85_legacy_contact_function1(r_ok, q, q2_ok, out) == PW85_ENOTPOSDEF;
    gboolean const leg2 =
        pw85_legacy_contact_function2(r_ok, q2_ok, q, out) == PW85_ENOTPOSDEF;
    pw85__cholesky_decomp(q, l);
    gboolean const chol = isnan(l[0]);
    if (!chol) {
      /* The factor of an accepted form reproduces it: Cholesky is backward
       * stable, |A − L·Lᵀ| ≤ 4ε|L||Lᵀ| ≈ 4ε max|A| (Higham, Thm 10.3); the
       * fallback from the rule's factors adds a few roundings. 16ε. */
      double const L[3][3] = {{l[0], 0., 0.}, {l[1], l[3], 0.},
                              {l[2], l[4], l[5]}};
      double worst = 0., size = 0.;
      for (int k = 0; k < PW85_SYM; k++) size = fmax(size, fabs(q[k]));
      for (int i = 0, k = 0; i < 3; i++)
        for (int j = i; j < 3; j++, k++) {
          double const a = L[i][0] * L[j][0] + L[i][1] * L[j][1] +
                           L[i][2] * L[j][2];
          worst = fmax(worst, fabs(a - q[k]));
        }
      if (!(worst <= 16. * DBL_EPSILON * size))
        test_mismatch("form %d: |A - L L^T| = %.3g of max|A| %.3g", n, worst,
                      size);
    }
    if (main1) rejected++;
    if (main1 != main2 || main1 != leg1 || main1 != leg2 || (main1 && !chol)) {
      if (disagree++ < 5)
        test_mismatch("form %d (e2 = %.3g): rejected by contact_function "
                      "%d/%d, legacy 1 %d, legacy 2 %d, cholesky %d",
                      n, e2, main1, main2, leg1, leg2, chol);
    }
  }
  g_test_message("%d forms, %d rejected, %d disagreements", count, rejected,
                 disagree);
  /* Both answers occur, so that the rule is exercised where it decides. */
  g_assert_cmpint(rejected, >, count / 10);
  g_assert_cmpint(rejected, <, count - count / 10);
  g_assert_cmpint(disagree, ==, 0);
  g_rand_free(rng);
}

static void add_contact_tests(Impl const *impl) {
  struct {
    const char *path;
    GTestDataFunc func;
  } const tests[] = {
      {"contract/null", test_null},
      {"contract/not-finite", test_not_finite},
      {"contract/not-posdef", test_not_posdef},
      {"contract/coincident", test_coincident},
      {"contract/scale-invariance", test_scale_invariance},
      {"contract/overflow", test_overflow},
      {"contract/extreme-aspect", test_extreme_aspect},
      {"spheres", test_spheres},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(tests); k++) {
    char *path =
        g_strdup_printf("/pw85/legacy/%s/%s", impl->name, tests[k].path);
    g_test_add_data_func(path, impl, tests[k].func);
    g_free(path);
  }
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  add_contact_tests(&impl1);
  add_contact_tests(&impl2);
  g_test_add_func("/pw85/legacy/f1/contract", test_f1_contract);
  g_test_add_func("/pw85/legacy/f2/contract", test_f2_contract);
  g_test_add_func("/pw85/legacy/f/agree", test_f_agree);
  g_test_add_func("/pw85/legacy/f1/nan-everywhere", test_f1_nan_everywhere);
  g_test_add_func("/pw85/legacy/definiteness/one-rule",
                  test_one_definiteness_rule);
  return g_test_run();
}
