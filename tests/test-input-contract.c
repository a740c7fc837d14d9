/* SPDX-License-Identifier: BSD-3-Clause */
/* The input contract of pw85_contact_function, pw85_overlap and pw85_f_neg:
 * every class of bad or extreme input gets its documented status and
 * output, and GSL's error handler is never reached; pw85_strerror and
 * pw85_version. (Invariance under scaling: test-scaling.c.) */
#include <float.h>
#include <pw85.h>
#include <string.h>

#include "contract.h"
#include "testutil.h"

/* The valid input and the helpers of tests/contract.h, for
 * pw85_contact_function. */
#define r_ok contract_r
#define q1_ok contract_q1
#define q2_ok contract_q2


static void assert_untouched(double const out[2]) {
  contract_assert_untouched(out);
}

static void test_null(void) { contract_check_null(pw85_contact_function); }

static void test_not_finite(void) {
  contract_check_not_finite(pw85_contact_function);
}

static void test_not_posdef(void) {
  contract_check_not_posdef(pw85_contact_function);
}

static void test_coincident(void) {
  contract_check_coincident(pw85_contact_function);
}

/* pw85_overlap takes the contract of pw85_contact_function. */
static void test_overlap_contract(void) {
  int result = 42;
  g_assert_cmpint(pw85_overlap(NULL, q1_ok, q2_ok, &result), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_overlap(r_ok, NULL, q2_ok, &result), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_overlap(r_ok, q1_ok, NULL, &result), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_overlap(r_ok, q1_ok, q2_ok, NULL), ==, PW85_EFAULT);
  double bad[PW85_SYM] = {100., 0., 0., 100., 0., NAN};
  g_assert_cmpint(pw85_overlap(r_ok, bad, q2_ok, &result), ==, PW85_EDOM);
  double const indefinite[PW85_SYM] = {1., 2., 0., 1., 0., 1.};
  g_assert_cmpint(pw85_overlap(r_ok, q1_ok, indefinite, &result), ==,
                  PW85_ENOTPOSDEF);
  g_assert_cmpint(result, ==, 42); /* untouched on error */
  double const zero[PW85_DIM] = {0., 0., 0.};
  g_assert_cmpint(pw85_overlap(zero, q1_ok, q2_ok, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  /* The tutorial's pair is disjoint (μ² = 3.36). */
  g_assert_cmpint(pw85_overlap(r_ok, q1_ok, q2_ok, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
  /* Two unit spheres: μ² = |r|²/4. Exactly tangent at |r| = 2; overlapping
   * and disjoint by one ulp of |r| either side. */
  double const unit[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double const tangent[PW85_DIM] = {2., 0., 0.};
  double const inside[PW85_DIM] = {nextafter(2., 0.), 0., 0.};
  double const outside[PW85_DIM] = {0., 0., nextafter(2., 3.)};
  g_assert_cmpint(pw85_overlap(tangent, unit, unit, &result), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(result, ==, 0);
  /* |μ² − 1| ≈ 2.2e-16 and 4.4e-16: within 4 ulps, still "tangent". */
  g_assert_cmpint(pw85_overlap(inside, unit, unit, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 0);
  g_assert_cmpint(pw85_overlap(outside, unit, unit, &result), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(result, ==, 0);
  /* Beyond 4 ulps: 1 ± 1e-14 in μ² (45 ulps). */
  double const near_in[PW85_DIM] = {2. * sqrt(1. - 1e-14), 0., 0.};
  double const near_out[PW85_DIM] = {2. * sqrt(1. + 1e-14), 0., 0.};
  g_assert_cmpint(pw85_overlap(near_in, unit, unit, &result), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  g_assert_cmpint(pw85_overlap(near_out, unit, unit, &result), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
  /* μ² beyond DBL_MAX: disjoint. */
  double const far[PW85_DIM] = {1e200, 0., 0.};
  double const tiny[PW85_SYM] = {1e-200, 0., 0., 1e-200, 0., 1e-200};
  g_assert_cmpint(pw85_overlap(far, tiny, tiny, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
}

/* A random double: sign, mantissa in [1, 2), exponent in [−emax, emax];
 * sometimes zero, a subnormal, or (with `special`) NaN or ±∞. */
static double random_double(GRand *rng, int emax, gboolean special) {
  switch (g_rand_int_range(rng, 0, 40)) {
    case 0:
      return 0.;
    case 1:
      return g_rand_boolean(rng) ? 4.9e-324 : -1e-310;
    case 2:
      if (special) return g_rand_boolean(rng) ? NAN : -INFINITY;
      break;
    default:
      break;
  }
  double const m = 1. + g_rand_double(rng);
  double const x = ldexp(m, g_rand_int_range(rng, -emax, emax + 1));
  return g_rand_boolean(rng) ? x : -x;
}

/* A random quadratic form: mostly L·Lᵀ with random entries (positive
 * definite unless rounding says otherwise), sometimes any symmetric matrix,
 * sometimes an axis-aligned one with wildly different semi-axes. */
static void random_form(GRand *rng, int emax, gboolean special,
                        double q[PW85_SYM]) {
  int const kind = g_rand_int_range(rng, 0, 10);
  if (kind < 6) {
    double l[PW85_SYM];
    for (int i = 0; i < PW85_SYM; i++) l[i] = random_double(rng, emax, FALSE);
    q[0] = l[0] * l[0];
    q[1] = l[0] * l[1];
    q[2] = l[0] * l[2];
    q[3] = l[1] * l[1] + l[3] * l[3];
    q[4] = l[1] * l[2] + l[3] * l[4];
    q[5] = l[2] * l[2] + l[4] * l[4] + l[5] * l[5];
  } else if (kind < 8) {
    for (int i = 0; i < PW85_SYM; i++) q[i] = random_double(rng, emax, special);
  } else {
    for (int i = 0; i < PW85_SYM; i++) q[i] = 0.;
    q[0] = fabs(random_double(rng, emax, FALSE));
    q[3] = fabs(random_double(rng, emax, FALSE));
    q[5] = fabs(random_double(rng, emax, FALSE));
  }
}

/* Any input gets a documented answer: 200,000 seeded random inputs over the
 * whole range of doubles, most far outside the domain where μ² is accurate
 * (condition numbers to 1e300). On PW85_SUCCESS μ² is finite, ≥ +0 (0 only
 * by underflow: never −0, never negative) and λ in [0, 1]; on PW85_ERANGE either out is
 * untouched or μ² = +∞ with a valid λ; on any other status out is
 * untouched; pw85_overlap returns the same status (or PW85_SUCCESS, +1,
 * where μ² overflows). GSL's error handler must not be reached (the one
 * installed fails the test). */
static void test_random_input(void) {
  GRand *rng = g_rand_new_with_seed(20261121);
  int counts[8] = {0};
  for (int n = 0; n < 200000; n++) {
    int const emax = g_rand_boolean(rng) ? 8 : (g_rand_boolean(rng) ? 150 : 600);
    gboolean const special = g_rand_int_range(rng, 0, 20) == 0;
    double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
    for (int i = 0; i < PW85_DIM; i++) r[i] = random_double(rng, emax, special);
    if (r[0] == 0. && r[1] == 0. && r[2] == 0.) r[0] = 1.;
    random_form(rng, emax, special, q1);
    random_form(rng, emax, special, q2);
    int const status = contract_cf(r, q1, q2, out);
    g_assert_cmpint(status, >=, 0);
    g_assert_cmpint(status, <=, PW85_ERANGE);
    counts[status]++;
    int result = 42;
    int const ostatus = pw85_overlap(r, q1, q2, &result);
    if (status == PW85_SUCCESS) {
      contract_assert_valid(status, out);
      g_assert_false(signbit(out[0]));
      g_assert_cmpint(ostatus, ==, PW85_SUCCESS);
      g_assert_true(result == -1 || result == 0 || result == 1);
    } else if (status == PW85_ERANGE && isinf(out[0])) {
      g_assert_cmpfloat(out[1], >=, 0.);
      g_assert_cmpfloat(out[1], <=, 1.);
      g_assert_cmpint(ostatus, ==, PW85_SUCCESS);
      g_assert_cmpint(result, ==, 1);
    } else {
      assert_untouched(out);
      g_assert_cmpint(ostatus, ==, status);
      g_assert_cmpint(result, ==, 42);
    }
  }
  g_test_message("statuses: %d success, %d EDOM, %d ENOTPOSDEF, %d ERANGE",
                 counts[PW85_SUCCESS], counts[PW85_EDOM],
                 counts[PW85_ENOTPOSDEF], counts[PW85_ERANGE]);
  /* Every class was exercised. */
  g_assert_cmpint(counts[PW85_SUCCESS], >, 1000);
  g_assert_cmpint(counts[PW85_EDOM], >, 1000);
  g_assert_cmpint(counts[PW85_ENOTPOSDEF], >, 1000);
  g_assert_cmpint(counts[PW85_ERANGE], >, 0);
  g_rand_free(rng);
}

/* Q = R·diag(a²)·Rᵀ for a random rotation R (unit quaternion) and
 * semi-axes of aspect ratio up to 1e8 about a random scale 2^±150. */
static void random_ellipsoid(GRand *rng, double q[PW85_SYM]) {
  double const scale = ldexp(1., g_rand_int_range(rng, -150, 151));
  double a2[3];
  for (int i = 0; i < 3; i++) {
    double const a = scale * pow(10., g_rand_double_range(rng, -4., 4.));
    a2[i] = a * a;
  }
  random_form_with_eigenvalues(rng, a2, q);
}

/* Inside the documented domain pw85_overlap never contradicts μ²: 100,000
 * seeded random pairs of aspect ratios up to 1e8, at distances that put μ²
 * around 1 (from 1e-2 to 1e2). */
static void test_random_overlap(void) {
  GRand *rng = g_rand_new_with_seed(1985);
  int checked = 0;
  for (int n = 0; n < 100000; n++) {
    double q1[PW85_SYM], q2[PW85_SYM], r[PW85_DIM], out[2];
    random_ellipsoid(rng, q1);
    random_ellipsoid(rng, q2);
    double const size = sqrt(q1[0] + q1[3] + q1[5]) + sqrt(q2[0] + q2[3] + q2[5]);
    double const t = size * pow(10., g_rand_double_range(rng, -1., 0.3));
    for (int i = 0; i < PW85_DIM; i++) r[i] = t * g_rand_double_range(rng, -1., 1.);
    int const status = contract_cf(r, q1, q2, out);
    if (status == PW85_ENOTPOSDEF) continue; /* rounding made Q indefinite */
    contract_assert_valid(status, out);
    int result = 42;
    g_assert_cmpint(pw85_overlap(r, q1, q2, &result), ==, PW85_SUCCESS);
    if (out[0] < 1. - 4. * DBL_EPSILON && result != -1)
      test_mismatch("case %d: mu^2 = %.17g but pw85_overlap gives %d, "
                    "expected -1",
                    n, out[0], result);
    if (out[0] > 1. + 4. * DBL_EPSILON && result != 1)
      test_mismatch("case %d: mu^2 = %.17g but pw85_overlap gives %d, "
                    "expected 1",
                    n, out[0], result);
    checked++;
  }
  g_test_message("%d random pairs checked", checked);
  g_assert_cmpint(checked, >, 90000);
  g_rand_free(rng);
}

static void axis_spheroid(double a, double c, int axis, double q[PW85_SYM]) {
  double n[PW85_DIM] = {0., 0., 0.};
  n[axis] = 1.;
  pw85_spheroid(a, c, n, q);
}

/* Aspect ratios up to 1e8, prolate and oblate, crossed. */
static void test_extreme_aspect(void) {
  double const ratios[] = {1e2, 1e4, 1e6, 1e8};
  double const dirs[][PW85_DIM] = {
      {1., 0., 0.}, {0., 1., 0.}, {0.6, 0.8, 0.}, {1e-3, 2e-3, 1.}, {1., 1., 1.}};
  for (size_t k = 0; k < G_N_ELEMENTS(ratios); k++) {
    double const rho = ratios[k];
    double needle[PW85_SYM], disc[PW85_SYM], sphere[PW85_SYM];
    axis_spheroid(1., rho, 0, needle);      /* prolate along x */
    axis_spheroid(1., 1. / rho, 2, disc);   /* oblate, normal z */
    axis_spheroid(1., 1., 1, sphere);
    double const *forms[] = {needle, disc, sphere};
    for (size_t i = 0; i < 3; i++)
      for (size_t j = 0; j < 3; j++)
        for (size_t d = 0; d < G_N_ELEMENTS(dirs); d++)
          for (int s = -3; s <= 3; s += 2) {
            double r[PW85_DIM], out[2];
            double const t = pow(10., s); /* near, tangent-ish, far */
            for (int c = 0; c < PW85_DIM; c++) r[c] = t * dirs[d][c];
            contract_assert_valid(contract_cf(r, forms[i], forms[j], out), out);
          }
  }
}

/* Centres far closer than the size of the ellipsoids: f(½) = |r|²/4 would
 * underflow to 0 in plain double arithmetic, and GSL's bracket check would
 * fail. μ² = |r|²/(a1 + a2)² for spheres. */
static void test_tiny_distance(void) {
  double const unit[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  /* 1e-170: μ² = 2.5e-341 is below the smallest subnormal: it rounds to 0. */
  double const r0[PW85_DIM] = {1e-170, 0., 0.};
  double out[2];
  contract_assert_valid(contract_cf(r0, unit, unit, out), out);
  g_assert_cmpfloat(out[0], ==, 0.);
  assert_close("lambda, tiny r", out[1], 0.5, 1e-12);
  /* 1e-155: μ² = 2.5e-311, a subnormal with 36 significant bits left. */
  double const r1[PW85_DIM] = {0., 1e-155, 0.};
  contract_assert_valid(contract_cf(r1, unit, unit, out), out);
  assert_close("mu2, subnormal", out[0], 2.5e-311, 1e-10);
  /* 1e-140, normal range: full accuracy. */
  double const r2[PW85_DIM] = {0., 0., 1e-140};
  contract_assert_valid(contract_cf(r2, unit, unit, out), out);
  assert_close("mu2, 1e-140", out[0], 0.25e-280, 4.5e-16);
}

/* Spheres of radii 1e9 and 1e-9 at distance 1e9: the maximiser
 * λ = a1/(a1 + a2) = 1 − 1e-18 lies within an ulp of 1, where f(1) = 0;
 * μ² = 1e18/(1e9 + 1e-9)² = 1 − 2e-18 rounds to 1. */
static void test_maximiser_at_an_end(void) {
  double const big[PW85_SYM] = {1e18, 0., 0., 1e18, 0., 1e18};
  double const small[PW85_SYM] = {1e-18, 0., 0., 1e-18, 0., 1e-18};
  double const r[PW85_DIM] = {0., 1e9, 0.};
  double out[2];
  contract_assert_valid(contract_cf(r, big, small, out), out);
  assert_close("mu2, maximiser near 1", out[0], 1., DBL_EPSILON);
  g_assert_cmpfloat(out[1], >=, 1. - DBL_EPSILON);
  contract_assert_valid(contract_cf(r, small, big, out), out); /* and near 0 */
  assert_close("mu2, maximiser near 0", out[0], 1., DBL_EPSILON);
  g_assert_cmpfloat(out[1], <=, 1e-17);
}

static void test_overflow(void) {
  /* μ² = |r|²/(2a)² = 1e400/4e-200: beyond DBL_MAX. */
  double const r[PW85_DIM] = {1e200, 0., 0.};
  double const tiny[PW85_SYM] = {1e-200, 0., 0., 1e-200, 0., 1e-200};
  double out[2];
  g_assert_cmpint(contract_cf(r, tiny, tiny, out), ==, PW85_ERANGE);
  g_assert_true(isinf(out[0]) && out[0] > 0.);
  assert_close("lambda, overflow", out[1], 0.5, 1e-12);
  /* Just inside the range: |r|² = 1e300, Q = 0.25e-8·I → μ² = 1e308. */
  double const r2[PW85_DIM] = {1e150, 0., 0.};
  double const q2[PW85_SYM] = {0.25e-8, 0., 0., 0.25e-8, 0., 0.25e-8};
  contract_assert_valid(contract_cf(r2, q2, q2, out), out);
  assert_close("mu2 near DBL_MAX", out[0], 1e308, 1e-15);
}

/* A disc of radius 1e150 and thickness 1e-150 in the plane z = 0 (aspect
 * ratio 1e300) and a unit sphere centred at (1, 1, 1): the sphere's scaled
 * copy touches the plane when μ(1 + 1e-150) = 1, so μ² = 1 to double
 * precision (measured error 2.2e-16). */
static void test_wide_range(void) {
  double const disc[PW85_SYM] = {1e300, 0., 0., 1e300, 0., 1e-300};
  double const unit[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double const r[PW85_DIM] = {1., 1., 1.};
  double out[2];
  contract_assert_valid(contract_cf(r, disc, unit, out), out);
  assert_close("mu2, disc and sphere", out[0], 1., 1e-15);
  /* Diagonals spanning 1e308 to 5e-324 together: no power-of-two scaling
   * keeps both in range. */
  double const huge[PW85_SYM] = {1e308, 0., 0., 1e308, 0., 1e308};
  double const tiny[PW85_SYM] = {5e-324, 0., 0., 5e-324, 0., 5e-324};
  g_assert_cmpint(contract_cf(r, huge, tiny, out), ==, PW85_ERANGE);
  assert_untouched(out);
}

static void test_f_neg_contract(void) {
  double params[15];
  memcpy(params, r_ok, sizeof r_ok);
  memcpy(params + 3, q1_ok, sizeof q1_ok);
  memcpy(params + 9, q2_ok, sizeof q2_ok);
  g_assert_true(isfinite(pw85_f_neg(0.5, params)));
  g_assert_true(isnan(pw85_f_neg(0.5, NULL)));
  g_assert_true(isnan(pw85_f_neg(NAN, params)));
  g_assert_true(isnan(pw85_f_neg(INFINITY, params)));
  for (int i = 0; i < 15; i++) {
    double const saved = params[i];
    params[i] = NAN;
    g_assert_true(isnan(pw85_f_neg(0.5, params)));
    params[i] = -INFINITY;
    g_assert_true(isnan(pw85_f_neg(0.5, params)));
    params[i] = saved;
  }
  /* Q(λ) not positive definite: q1 indefinite, λ = 0. */
  params[3] = -1.;
  g_assert_true(isnan(pw85_f_neg(0., params)));
}

/* −f(λ) ≤ 0 on [0, 1] (or NaN), also where Q(λ) is so ill-conditioned
 * that the computed f may round below 0: Q1 and Q2 share their principal
 * directions, with a thin one (eigenvalues 1, u, 10^−19..−14 and u′, 1,
 * 10^−19..−14: cond 1e14 to 1e19), and r12 is random. */
static void test_f_neg_sign(void) {
  GRand *rng = g_rand_new_with_seed(1613);
  int positive = 0, finite = 0;
  int const count = 100000;
  for (int n = 0; n < count; n++) {
    double const e1[3] = {1., g_rand_double_range(rng, 1e-3, 1.),
                          pow(10., g_rand_double_range(rng, -19., -14.))};
    double const e2[3] = {g_rand_double_range(rng, 1e-3, 1.), 1.,
                          pow(10., g_rand_double_range(rng, -19., -14.))};
    double params[15];
    GRand *same = g_rand_copy(rng);
    random_form_with_eigenvalues(rng, e1, params + 3);
    random_form_with_eigenvalues(same, e2, params + 9); /* same rotation */
    g_rand_free(same);
    for (int c = 0; c < 3; c++) params[c] = g_rand_double_range(rng, -1., 1.);
    double const lambda = g_rand_double(rng);
    double const v = pw85_f_neg(lambda, params);
    if (isfinite(v)) finite++;
    if (v > 0.) {
      if (positive++ < 5)
        test_mismatch("pw85_f_neg(%a) = %.3g > 0", lambda, v);
    }
  }
  g_test_message("%d of %d values finite, %d positive", finite, count,
                 positive);
  g_assert_cmpint(finite, >, count / 2);
  g_assert_cmpint(positive, ==, 0);
  g_rand_free(rng);
}

/* Found by the fuzz target fuzz-contact-structured (issue 14): Q2's entries
 * are about 2^−55 of Q1's (cond(Q1) 8.7e15, inside the documented domain),
 * so Q(λ) rounded to double is not definite near λ* and μ² fell to the
 * floor, 0.998 instead of 2.5e10. The reference is the correctly rounded μ²
 * and λ* of the exact rational route of data/gen_ref_data.py (contact()),
 * agreeing with its mpmath route at 100 digits. Both argument orders. */
static void test_fuzz_regressions(void) {
  double const r[PW85_DIM] = {0x1.909bca2077721p+66, -0x1.1df82d0ff2c15p+52,
                              -0x1.1df82d0ff2c15p+52};
  double const q1[PW85_SYM] = {0x1.fb356c26ea2abp+120, 0x1.b82a8402b8b5p+126,
                               -0x1.5f7e9cea1d2c6p+126, 0x1.7f78e00e06b43p+132,
                               -0x1.3238c35894b05p+132, 0x1.e91118248dba9p+131};
  double const q2[PW85_SYM] = {0x1.72eb5ecf2f6c3p+76, 0x1.15aa70aca0f6dp+77,
                               -0x1.a3793ecea37a4p+75, 0x1.a53584d8bf977p+77,
                               -0x1.41fa3f2d319e5p+76, 0x1.f3166e3d458ffp+74};
  double const mu2 = 0x1.7a69905f0f4e4p+34, lambda = 0x1.c49a9978be5dap-1;
  double const minus_r[PW85_DIM] = {-r[0], -r[1], -r[2]};
  double out[2];
  g_assert_cmpint(pw85_contact_function(r, q1, q2, out), ==, PW85_SUCCESS);
  if (out[0] != mu2 || !(fabs(out[1] - lambda) <= 1e-12))
    test_mismatch("mu^2 %a, lambda %a; expected %a, %a", out[0], out[1], mu2,
                  lambda);
  g_assert_cmpint(pw85_contact_function(minus_r, q2, q1, out), ==,
                  PW85_SUCCESS);
  if (out[0] != mu2 || !(fabs(out[1] - (1. - lambda)) <= 1e-12))
    test_mismatch("swapped: mu^2 %a, lambda %a; expected %a, %a", out[0],
                  out[1], mu2, 1. - lambda);
  int result = 0;
  g_assert_cmpint(pw85_overlap(r, q1, q2, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
}

/* The handler installed by these tests does fail a test that reaches it:
 * provoke GSL's error in a subprocess, on purpose. */
static void test_gsl_handler_detects(void) {
  if (g_test_subprocess()) {
    install_failing_gsl_handler();
    gsl_error("provoked by the test", __FILE__, __LINE__, GSL_EINVAL);
    return;
  }
  g_test_trap_subprocess(NULL, 0, G_TEST_SUBPROCESS_DEFAULT);
  g_test_trap_assert_failed();
}

static void test_strerror(void) {
  int const codes[] = {PW85_SUCCESS, PW85_EFAULT, PW85_EDOM, PW85_ENOTPOSDEF,
                       PW85_ERANGE, PW85_ENOMEM, PW85_ENOCONV,
                       PW85_EINVAL};
  char const *unknown = pw85_strerror(-1);
  g_assert_nonnull(unknown);
  g_assert_cmpstr(unknown, ==, pw85_strerror(1000));
  for (size_t i = 0; i < G_N_ELEMENTS(codes); i++) {
    g_assert_cmpint(codes[i], ==, (int)i); /* values are pinned */
    char const *msg = pw85_strerror(codes[i]);
    g_assert_nonnull(msg);
    g_assert_cmpstr(msg, !=, unknown);
    for (size_t j = 0; j < i; j++)
      g_assert_cmpstr(msg, !=, pw85_strerror(codes[j]));
  }
}

static void test_version(void) {
  g_assert_cmpstr(pw85_version(), ==, PW85_VERSION);
  char *expected = g_strdup_printf("%d.%d.%d", PW85_VERSION_MAJOR,
                                   PW85_VERSION_MINOR, PW85_VERSION_PATCH);
  g_assert_cmpstr(pw85_version(), ==, expected);
  g_free(expected);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/contract/contact_function/null", test_null);
  g_test_add_func("/pw85/contract/contact_function/not-finite",
                  test_not_finite);
  g_test_add_func("/pw85/contract/contact_function/not-posdef",
                  test_not_posdef);
  g_test_add_func("/pw85/contract/contact_function/coincident",
                  test_coincident);
  g_test_add_func("/pw85/contract/contact_function/extreme-aspect",
                  test_extreme_aspect);
  g_test_add_func("/pw85/contract/contact_function/tiny-distance",
                  test_tiny_distance);
  g_test_add_func("/pw85/contract/contact_function/overflow", test_overflow);
  g_test_add_func("/pw85/contract/contact_function/maximiser-at-an-end",
                  test_maximiser_at_an_end);
  g_test_add_func("/pw85/contract/contact_function/wide-range",
                  test_wide_range);
  g_test_add_func("/pw85/contract/contact_function/random-input",
                  test_random_input);
  g_test_add_func("/pw85/contract/overlap/statuses", test_overlap_contract);
  g_test_add_func("/pw85/contract/overlap/random-pairs", test_random_overlap);
  g_test_add_func("/pw85/contract/f_neg", test_f_neg_contract);
  g_test_add_func("/pw85/contract/f_neg/sign", test_f_neg_sign);
  g_test_add_func("/pw85/contract/contact_function/fuzz-regressions",
                  test_fuzz_regressions);
  g_test_add_func("/pw85/contract/strerror", test_strerror);
  g_test_add_func("/pw85/contract/version", test_version);
  g_test_add_func("/pw85/contract/gsl-handler-detects",
                  test_gsl_handler_detects);
  return g_test_run();
}
