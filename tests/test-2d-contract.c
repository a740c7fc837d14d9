/* SPDX-License-Identifier: BSD-3-Clause */
/* The contract of the two-dimensional functions (pw85_2d.h), the checks
 * that need no reference data: every bad input gets its status with the
 * outputs untouched; the definiteness rule as stored (including forms
 * whose products underflow); and the invariances that correct rounding
 * implies, bit for bit: swapping the ellipses, scaling by powers of two,
 * the exact symmetries of the plane (quarter turns, reflections), and
 * the overlap verdict against the sign of μ² − 1. A general rotation moves
 * the rounded inputs, so μ² moves too: that one is checked with a
 * tolerance measured below. Accuracy against the mpmath references:
 * test-2d-ref-data. Randomness: GRand with fixed seeds. */
#include <float.h>
#include <math.h>
#include <pw85/pw85_2d.h>
#include <string.h>

#include "testutil.h"

/* A valid pair: a needle-ish ellipse and a wider one. */
static double const r0[2] = {0.7, -1.1};
static double const qa[3] = {4., 0.5, 0.25};
static double const qb[3] = {1., -0.3, 2.};

static double const sentinel[2] = {42., -7.};

static int cf(double const *r, double const *q1, double const *q2,
              double out[2]) {
  memcpy(out, sentinel, sizeof sentinel);
  return pw85_2d_contact_function(r, q1, q2, out);
}

static int ov(double const *r, double const *q1, double const *q2,
              int *result) {
  *result = 42;
  return pw85_2d_overlap(r, q1, q2, result);
}

static void assert_untouched(double const out[2], int result) {
  g_assert_cmpmem(out, sizeof sentinel, sentinel, sizeof sentinel);
  g_assert_cmpint(result, ==, 42);
}

/* Every function with (r, q1, q2) answers `status` and leaves its outputs
 * as they were; pw85_2d_f_neg gives NaN. */
static void assert_refused(double const *r, double const *q1,
                           double const *q2, int status) {
  double out[2];
  int result;
  g_assert_cmpint(cf(r, q1, q2, out), ==, status);
  g_assert_cmpint(ov(r, q1, q2, &result), ==, status);
  assert_untouched(out, result);
  if (r != NULL && q1 != NULL && q2 != NULL) {
    double params[8];
    memcpy(params, r, 2 * sizeof(double));
    memcpy(params + 2, q1, 3 * sizeof(double));
    memcpy(params + 5, q2, 3 * sizeof(double));
    g_assert_true(isnan(pw85_2d_f_neg(0.5, params)));
  }
}

static void test_null(void) {
  double out[2];
  int result;
  assert_refused(NULL, qa, qb, PW85_EFAULT);
  assert_refused(r0, NULL, qb, PW85_EFAULT);
  assert_refused(r0, qa, NULL, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_function(r0, qa, qb, NULL), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_overlap(r0, qa, qb, NULL), ==, PW85_EFAULT);
  g_assert_true(isnan(pw85_2d_f_neg(0.5, NULL)));
  /* NULL and bad values together: the pointer is reported. */
  double const nan_r[2] = {NAN, 0.};
  g_assert_cmpint(cf(nan_r, NULL, qb, out), ==, PW85_EFAULT);
  g_assert_cmpint(ov(nan_r, qa, NULL, &result), ==, PW85_EFAULT);
  assert_untouched(out, result);
}

static void test_not_finite(void) {
  double const bad[] = {NAN, INFINITY, -INFINITY};
  for (size_t b = 0; b < G_N_ELEMENTS(bad); b++) {
    for (int k = 0; k < 2; k++) {
      double r[2] = {r0[0], r0[1]};
      r[k] = bad[b];
      assert_refused(r, qa, qb, PW85_EDOM);
    }
    for (int k = 0; k < 3; k++) {
      double q[3] = {qa[0], qa[1], qa[2]};
      q[k] = bad[b];
      assert_refused(r0, q, qb, PW85_EDOM);
      assert_refused(r0, qb, q, PW85_EDOM);
    }
    double params[8] = {r0[0], r0[1], qa[0], qa[1], qa[2], qb[0], qb[1],
                        qb[2]};
    g_assert_true(isnan(pw85_2d_f_neg(bad[b], params)));
  }
  /* Not finite beats not positive definite, as in pw85.h. */
  double const q[3] = {-1., NAN, 1.};
  assert_refused(r0, q, qb, PW85_EDOM);
}

/* The rule as stored: Q00 > 0 and Q00·Q11 − Q01² > 0, exactly. */
static void test_definiteness(void) {
  double const eps = DBL_EPSILON;
  double const tiny = 1e-200; /* tiny², the minor's products, underflow */
  double const refused[][3] = {
      {0., 0., 1.},                          /* Q00 = 0 */
      {-1., 0., 1.},                         /* Q00 < 0 */
      {1., 0., 0.},                          /* Q11 = 0 */
      {1., 0., -1.},                         /* indefinite */
      {1., 1., 1.},                          /* singular */
      {1., 1. + eps, 1.},                    /* det = −2ε − ε² */
      {1., -1. - eps, 1.},
      {tiny, tiny, tiny},                    /* singular, underflowing */
      {tiny, tiny * (1. + eps), tiny},       /* indefinite, underflowing */
      {0x1p-1074, 0x1p-1074, 0x1p-1074},     /* subnormal, singular */
      {DBL_MAX, DBL_MAX, DBL_MAX},           /* singular, overflowing */
  };
  for (size_t i = 0; i < G_N_ELEMENTS(refused); i++) {
    g_test_message("refused form %zu: {%a, %a, %a}", i, refused[i][0],
                   refused[i][1], refused[i][2]);
    assert_refused(r0, refused[i], qb, PW85_ENOTPOSDEF);
    assert_refused(r0, qb, refused[i], PW85_ENOTPOSDEF);
    /* also with coincident centres, whose answer needs no search */
    double const zero[2] = {0., 0.};
    assert_refused(zero, refused[i], qb, PW85_ENOTPOSDEF);
    double a[2] = {42., 42.}, theta = 42.;
    g_assert_cmpint(pw85_2d_principal_axes(refused[i], a, &theta), ==,
                    PW85_ENOTPOSDEF);
    g_assert_true(a[0] == 42. && a[1] == 42. && theta == 42.);
  }
  /* Positive definite as stored, however nearly singular or small: never
   * PW85_ENOTPOSDEF (PW85_ERANGE is allowed for the forms singular to
   * double precision, which cannot be factorised). */
  double const accepted[][3] = {
      {1., 1., 1. + 2. * eps},               /* det = 2ε */
      {1., 1. - eps, 1.},
      {tiny, tiny * (1. - eps), tiny},       /* products underflow */
      {tiny, 0., tiny},
      {0x1p-1074, 0., 0x1p-1074},            /* subnormal */
      {DBL_MAX, 0., DBL_MAX},
      {1e300, 1e-300, 1e-300},               /* cond 1e600 */
  };
  for (size_t i = 0; i < G_N_ELEMENTS(accepted); i++) {
    double out[2];
    int result;
    int const s = cf(r0, accepted[i], qb, out);
    int const t = ov(r0, qb, accepted[i], &result);
    g_test_message("accepted form %zu: {%a, %a, %a}: statuses %d, %d", i,
                   accepted[i][0], accepted[i][1], accepted[i][2], s, t);
    g_assert_true(s == PW85_SUCCESS || s == PW85_ERANGE);
    g_assert_true(t == PW85_SUCCESS || t == PW85_ERANGE);
    if (s == PW85_ERANGE && !isinf(out[0])) assert_untouched(out, 42);
    if (t != PW85_SUCCESS) g_assert_cmpint(result, ==, 42);
  }
  /* Well-conditioned however small: success (r12 of the forms' size, so
   * that μ² stays in range). */
  double out[2];
  double const r_tiny[2] = {0x1p-540, -0x1p-541};
  g_assert_cmpint(cf(r0, accepted[3], accepted[3], out), ==, PW85_SUCCESS);
  g_assert_cmpint(cf(r_tiny, accepted[4], accepted[4], out), ==,
                  PW85_SUCCESS);
  /* two circles of radius 2^−537: μ² = |r|²/(2·2^−537)² */
  g_assert_cmpfloat(out[0], ==, (0x1p-6 + 0x1p-8) / 4.);
}

/* Coincident centres: μ² = 0, λ = ½, overlap. */
static void test_coincident(void) {
  double const zero[2] = {0., -0.};
  double out[2];
  int result;
  g_assert_cmpint(cf(zero, qa, qb, out), ==, PW85_SUCCESS);
  g_assert_true(out[0] == 0. && out[1] == 0.5);
  g_assert_cmpint(ov(zero, qa, qb, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
}

/* Two circles: μ² = |r|²/(ρ1 + ρ2)², λ* = ρ1/(ρ1 + ρ2), exact here. */
static void test_circles(void) {
  double const r[2] = {3., 4.}; /* |r| = 5 */
  double const q1[3] = {4., 0., 4.}, q2[3] = {9., 0., 9.}; /* ρ = 2, 3 */
  double out[2];
  int result;
  g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 1.);
  g_assert_cmpfloat(fabs(out[1] - 0.4), <=, 1e-15);
  g_assert_cmpint(ov(r, q1, q2, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 0);
  double const r2[2] = {6., 8.}; /* μ² = 4 */
  g_assert_cmpint(cf(r2, q1, q2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 4.);
  g_assert_cmpint(ov(r2, q1, q2, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
}

/* A random ellipse: semi-axes 10^U(−e, e)·size, any angle. */
static void random_form(GRand *rng, double log_aspect, double size,
                        double q[3]) {
  double const l = g_rand_double_range(rng, 0., log_aspect);
  double const a[2] = {size * pow(10., l / 2.), size * pow(10., -l / 2.)};
  double const theta = g_rand_double_range(rng, -4., 4.);
  g_assert_cmpint(pw85_2d_ellipse(a, theta, q), ==, PW85_SUCCESS);
}

/* A random pair near contact: |r| of the order of the sizes. */
static void random_pair(GRand *rng, double log_aspect, double r[2],
                        double q1[3], double q2[3]) {
  random_form(rng, log_aspect, 1., q1);
  random_form(rng, log_aspect, pow(10., g_rand_double_range(rng, -1., 1.)),
              q2);
  double const phi = g_rand_double_range(rng, 0., 2. * G_PI);
  double const d = g_rand_double_range(rng, 0.2, 4.);
  r[0] = d * cos(phi);
  r[1] = d * sin(phi);
}

enum { pairs_per_test = 2000 };

/* (−r, q2, q1) gives the same μ², bit for bit, and 1 − λ. */
static void test_swap(void) {
  GRand *rng = g_rand_new_with_seed(2901);
  for (int n = 0; n < pairs_per_test; n++) {
    double r[2], q1[3], q2[3], out[2], sw[2];
    int result, result_sw;
    random_pair(rng, n % 2 ? 6. : 1., r, q1, q2);
    double const mr[2] = {-r[0], -r[1]};
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    g_assert_cmpint(cf(mr, q2, q1, sw), ==, PW85_SUCCESS);
    if (!(sw[0] == out[0]))
      g_test_fail_printf("pair %d: mu^2 %a, swapped %a", n, out[0], sw[0]);
    /* 1 − λ rounded: within an ulp of ½ (the larger of λ and 1 − λ). */
    if (!(fabs(sw[1] - (1. - out[1])) <= DBL_EPSILON))
      g_test_fail_printf("pair %d: lambda %a, swapped %a", n, out[1],
                         sw[1]);
    g_assert_cmpint(ov(r, q1, q2, &result), ==, PW85_SUCCESS);
    g_assert_cmpint(ov(mr, q2, q1, &result_sw), ==, PW85_SUCCESS);
    g_assert_cmpint(result, ==, result_sw);
  }
  g_rand_free(rng);
}

/* μ²(2^k·r, 2^2k·Q1, 2^2k·Q2) = μ²(r, Q1, Q2) and λ unchanged, bit for bit
 * (the inputs scale exactly, and are rescaled by powers of two inside);
 * μ²(r, 2^k·Q1, 2^k·Q2) = 2^−k·μ², exactly. */
static void test_scaling(void) {
  GRand *rng = g_rand_new_with_seed(2902);
  int const ks[] = {-300, -7, 1, 13, 250};
  for (int n = 0; n < pairs_per_test / 4; n++) {
    double r[2], q1[3], q2[3], out[2];
    random_pair(rng, n % 2 ? 5. : 1., r, q1, q2);
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    for (size_t i = 0; i < G_N_ELEMENTS(ks); i++) {
      int const k = ks[i];
      double rs[2], s1[3], s2[3], t1[3], t2[3], o[2], p[2];
      for (int c = 0; c < 2; c++) rs[c] = ldexp(r[c], k);
      for (int c = 0; c < 3; c++) {
        s1[c] = ldexp(q1[c], 2 * k), s2[c] = ldexp(q2[c], 2 * k);
        t1[c] = ldexp(q1[c], k), t2[c] = ldexp(q2[c], k);
      }
      g_assert_cmpint(cf(rs, s1, s2, o), ==, PW85_SUCCESS);
      if (!(o[0] == out[0] && o[1] == out[1]))
        g_test_fail_printf("pair %d, k = %d: (mu^2, lambda) = (%a, %a), "
                           "unscaled (%a, %a)", n, k, o[0], o[1], out[0],
                           out[1]);
      g_assert_cmpint(cf(r, t1, t2, p), ==, PW85_SUCCESS);
      if (!(p[0] == ldexp(out[0], -k) && p[1] == out[1]))
        g_test_fail_printf("pair %d, Q times 2^%d: mu^2 %a, expected %a", n,
                           k, p[0], ldexp(out[0], -k));
    }
  }
  g_rand_free(rng);
}

/* The exact symmetries of the plane move no bit of the input: a quarter
 * turn (x, y) → (−y, x), Q → (Q11, −Q01, Q00); a reflection
 * (x, y) → (x, −y), Q → (Q00, −Q01, Q11); and the exchange of the axes
 * (x, y) → (y, x), Q → (Q11, Q01, Q00). μ² being correctly rounded, it is
 * the same double for each, and so is the overlap verdict. */
static void test_symmetries(void) {
  GRand *rng = g_rand_new_with_seed(2903);
  for (int n = 0; n < pairs_per_test / 2; n++) {
    double r[2], q1[3], q2[3], out[2];
    int result;
    random_pair(rng, n % 2 ? 6. : 1., r, q1, q2);
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    g_assert_cmpint(ov(r, q1, q2, &result), ==, PW85_SUCCESS);
    double const images[3][8] = {
        {-r[1], r[0], q1[2], -q1[1], q1[0], q2[2], -q2[1], q2[0]},
        {r[0], -r[1], q1[0], -q1[1], q1[2], q2[0], -q2[1], q2[2]},
        {r[1], r[0], q1[2], q1[1], q1[0], q2[2], q2[1], q2[0]},
    };
    for (int s = 0; s < 3; s++) {
      double o[2];
      int res;
      g_assert_cmpint(cf(images[s], images[s] + 2, images[s] + 5, o), ==,
                      PW85_SUCCESS);
      g_assert_cmpint(ov(images[s], images[s] + 2, images[s] + 5, &res), ==,
                      PW85_SUCCESS);
      if (!(o[0] == out[0]) || res != result)
        g_test_fail_printf("pair %d, symmetry %d: mu^2 %a (overlap %d), "
                           "direct %a (%d)", n, s, o[0], res, out[0],
                           result);
    }
  }
  g_rand_free(rng);
}

/* A rotation by a general angle φ of the whole configuration: the
 * ellipses built again by pw85_2d_ellipse() at θ + φ, r12 rotated in
 * double. Each input then differs from the exact rotation of the first
 * configuration by a few ulps (about 2u relative per entry, u = 2⁻⁵³),
 * and μ² with it, to first order by at most about 4u·κ relative for forms
 * of condition κ ≤ 100 here (semi-axes within a factor 10): 4.4e-14. The
 * tolerance, 2e-14, is 12 times the largest change measured over these
 * 2000 pairs (1.71e-15). */
static void test_rotation(void) {
  GRand *rng = g_rand_new_with_seed(2904);
  double worst = 0.;
  for (int n = 0; n < pairs_per_test; n++) {
    double a1[2], a2[2], t1, t2, q1[3], q2[3], r[2], out[2], o[2];
    for (int c = 0; c < 2; c++) {
      a1[c] = pow(10., g_rand_double_range(rng, -0.5, 0.5));
      a2[c] = pow(10., g_rand_double_range(rng, -0.5, 0.5));
    }
    t1 = g_rand_double_range(rng, -3., 3.);
    t2 = g_rand_double_range(rng, -3., 3.);
    double const d = g_rand_double_range(rng, 0.5, 5.),
                 psi = g_rand_double_range(rng, -3., 3.),
                 phi = g_rand_double_range(rng, -3., 3.);
    r[0] = d * cos(psi);
    r[1] = d * sin(psi);
    g_assert_cmpint(pw85_2d_ellipse(a1, t1, q1), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_ellipse(a2, t2, q2), ==, PW85_SUCCESS);
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    double const rr[2] = {d * cos(psi + phi), d * sin(psi + phi)};
    g_assert_cmpint(pw85_2d_ellipse(a1, t1 + phi, q1), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_ellipse(a2, t2 + phi, q2), ==, PW85_SUCCESS);
    g_assert_cmpint(cf(rr, q1, q2, o), ==, PW85_SUCCESS);
    double const rel = fabs(o[0] - out[0]) / out[0];
    if (rel > worst) worst = rel;
    if (!(rel <= 2e-14))
      g_test_fail_printf("pair %d, rotation %.17g: mu^2 %.17g, unrotated "
                         "%.17g (relative %.3g)", n, phi, o[0], out[0], rel);
  }
  g_test_message("rotation: worst relative change of mu^2 %.3g", worst);
  g_rand_free(rng);
}

/* The overlap verdict is the sign of μ² − 1 outside the tangency band,
 * with μ² from pw85_2d_contact_function (correctly rounded: its sign is
 * exact there). Distances drawn about contact, so that both answers and
 * near-tangent pairs occur. */
static void test_overlap_sign(void) {
  GRand *rng = g_rand_new_with_seed(2905);
  int counts[3] = {0, 0, 0};
  for (int n = 0; n < 4 * pairs_per_test; n++) {
    double r[2], q1[3], q2[3], out[2];
    int result;
    random_pair(rng, n % 3 ? 4. : 1., r, q1, q2);
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    /* r scaled onto contact, then off it by a relative 10^U(−15, −1) */
    double const t = 1. / sqrt(out[0]) *
                     (1. + (n % 2 ? 1. : -1.) *
                               pow(10., g_rand_double_range(rng, -15., -1.)));
    r[0] *= t;
    r[1] *= t;
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    g_assert_cmpint(ov(r, q1, q2, &result), ==, PW85_SUCCESS);
    double const m1 = out[0] - 1.;
    counts[result + 1]++;
    if (fabs(m1) <= 4. * DBL_EPSILON) {
      if (!(result == 0 || result == (m1 < 0. ? -1 : 1)))
        g_test_fail_printf("pair %d: overlap %d in the band, mu^2 - 1 = %a",
                           n, result, m1);
    } else if (result != (m1 < 0. ? -1 : 1)) {
      g_test_fail_printf("pair %d: overlap %d, mu^2 - 1 = %a", n, result,
                         m1);
    }
  }
  g_test_message("overlap: %d overlapping, %d tangent, %d disjoint",
                 counts[0], counts[1], counts[2]);
  g_assert_cmpint(counts[0], >, 0);
  g_assert_cmpint(counts[2], >, 0);
  g_rand_free(rng);
}

/* μ² overflowing: PW85_ERANGE, out = {+∞, λ}; the overlap test answers
 * +1 (disjoint) with success. */
static void test_overflow(void) {
  double const r[2] = {1e300, 0.};
  double const q[3] = {1e-300, 0., 1e-300};
  double out[2];
  int result;
  g_assert_cmpint(cf(r, q, q, out), ==, PW85_ERANGE);
  g_assert_true(isinf(out[0]) && out[0] > 0.);
  g_assert_cmpfloat(fabs(out[1] - 0.5), <=, DBL_EPSILON);
  g_assert_cmpint(ov(r, q, q, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
}

static void test_ellipse_statuses(void) {
  double const a[2] = {2., 1.};
  double q[3] = {42., 42., 42.};
  double const q_sentinel[3] = {42., 42., 42.};
  g_assert_cmpint(pw85_2d_ellipse(NULL, 0., q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_ellipse(a, 0., NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_ellipse(a, NAN, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_ellipse(a, INFINITY, q), ==, PW85_EDOM);
  double const nan_a[2] = {NAN, 1.}, zero_a[2] = {2., 0.},
               neg_a[2] = {-1., 1.}, big_a[2] = {1e200, 1.},
               small_a[2] = {1., 1e-170};
  g_assert_cmpint(pw85_2d_ellipse(nan_a, 0., q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_ellipse(zero_a, 0., q), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_ellipse(neg_a, 0., q), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_ellipse(big_a, 0., q), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_2d_ellipse(small_a, 0., q), ==, PW85_ERANGE);
  g_assert_cmpmem(q, sizeof q, q_sentinel, sizeof q_sentinel);
  /* θ = 0: diag(a0², a1²) exactly. */
  g_assert_cmpint(pw85_2d_ellipse(a, 0., q), ==, PW85_SUCCESS);
  g_assert_true(q[0] == 4. && q[1] == 0. && q[2] == 1.);
}

/* Regression (fuzz-2d, corpus/2d/regress-theta-underflow): equal diagonal
 * entries and an off-diagonal entry 2^-1152 of them. The axis of the
 * larger semi-axis is at −45° for Q01 < 0, +45° for Q01 > 0 (eigenvectors
 * (1, ∓1)/√2 of eigenvalues Q00 ± |Q01|); θ was ±0, Q01 having underflowed
 * in the scaled copy of Q. And Q00 − Q11 = 2^548, Q01 = 2^-500:
 * θ = ½·atan2(2^-499, 2^548) = 2^-1048 exactly (a subnormal), was 0. */
/* Regression (fuzz-2d, corpus/2d/regress-ellipse-underflow): a0 = 2^-495,
 * a1 = 2^433, θ = −1.8·2^-656. Q00 = a0²cos²θ + a1²sin²θ = 1.808e-134,
 * dominated by a1²sin²θ; the product sin²θ (2^-1311) underflowed before it
 * met a1², and Q00 came out as a0² = 2^-990. References: mpmath at 60
 * digits, rounded once (each entry correctly rounded here). */
static void test_ellipse_underflow(void) {
  double const a[2] = {0x1.0820003f53f01p-495, 0x1.0000003ff0025p+433};
  double const ref[3] = {0x1.a48000d5c6a8ap-445, 0x1.d00000e9d5090p+210,
                         0x1.0000007fe004bp+866};
  double q[3];
  g_assert_cmpint(pw85_2d_ellipse(a, -0x1.d00000020f008p-656, q), ==,
                  PW85_SUCCESS);
  for (int k = 0; k < 3; k++) g_assert_cmpfloat(q[k], ==, ref[k]);
}

static void test_principal_axes_underflow(void) {
  double a[2], theta;
  double const q_neg[3] = {0x1.3636363636363p+567, -0x1.3636363636363p-585,
                           0x1.3636363636363p+567};
  g_assert_cmpint(pw85_2d_principal_axes(q_neg, a, &theta), ==, PW85_SUCCESS);
  g_assert_cmpfloat(theta, ==, -G_PI / 4.);
  g_assert_true(a[0] == a[1] && a[0] == sqrt(q_neg[0]));
  double const q_pos[3] = {0x1p+600, 0x1p-580, 0x1p+600};
  g_assert_cmpint(pw85_2d_principal_axes(q_pos, a, &theta), ==, PW85_SUCCESS);
  g_assert_cmpfloat(theta, ==, G_PI / 4.);
  g_assert_true(a[0] == 0x1p+300 && a[1] == 0x1p+300);
  double const q_tilt[3] = {0x1p+600 + 0x1p+548, 0x1p-500, 0x1p+600};
  g_assert_cmpint(pw85_2d_principal_axes(q_tilt, a, &theta), ==,
                  PW85_SUCCESS);
  g_assert_cmpfloat(theta, ==, 0x1p-1048);
}

/* Regression (fuzz-2d, corpus/2d/regress-needle-axis-*): needles of
 * aspect 2.2e8 and 2.6e8 whose small semi-axis, the Rayleigh quotient of
 * the atan2 direction turned by 90°, was off by 7.2·u and 9.2·u where
 * pw85_2d.h states u·(1 + u·(a0/a1)²) = 6.4·u and 8.4·u. References:
 * √ of the eigenvalues, mpmath at 60 digits (tr ± √((Q00 − Q11)² +
 * 4·Q01²))/2, the smaller as det/λmax). */
static void test_principal_axes_needle(void) {
  static const struct {
    double q[3];
    long double a[2]; /* the references, to 64 bits */
  } cases[] = {
      {{0x1.0d61c162c6ca7p-6, -0x1.b188476020d5fp-6, 0x1.5cdad1e5c6821p-5},
       {0.2429538514886877924721487L, 1.102803891726490409762721e-9L}},
      {{0x1.51162f8b3b40cp-2, -0x1.1c450c803703dp-1, 0x1.df74fbea6285fp-1},
       {1.125000260770320908573856L, 4.355620812657070879764462e-9L}},
  };
  double const u = DBL_EPSILON / 2.;
  for (size_t n = 0; n < G_N_ELEMENTS(cases); n++) {
    double a[2], theta;
    g_assert_cmpint(pw85_2d_principal_axes(cases[n].q, a, &theta), ==,
                    PW85_SUCCESS);
    for (int j = 0; j < 2; j++) {
      long double const ref = cases[n].a[j], ratio = cases[n].a[0] / ref;
      long double const err = fabsl(a[j] - ref) / ref;
      long double const bound = u * (1. + u * ratio * ratio);
      if (!(err <= bound))
        g_test_fail_printf("case %zu: a[%d] = %a, reference %La (%.3Lg u > "
                           "%.3Lg u)", n, j, a[j], ref, err / u, bound / u);
    }
  }
}

static void test_principal_axes(void) {
  double a[2] = {42., 42.}, theta = 42.;
  double const q[3] = {4., 0., 1.};
  g_assert_cmpint(pw85_2d_principal_axes(NULL, a, &theta), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_principal_axes(q, NULL, &theta), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_principal_axes(q, a, NULL), ==, PW85_EFAULT);
  double const nan_q[3] = {4., NAN, 1.};
  g_assert_cmpint(pw85_2d_principal_axes(nan_q, a, &theta), ==, PW85_EDOM);
  g_assert_true(a[0] == 42. && a[1] == 42. && theta == 42.);
  /* Exact cases: axis-aligned (either order), a circle (θ = 0). */
  g_assert_cmpint(pw85_2d_principal_axes(q, a, &theta), ==, PW85_SUCCESS);
  g_assert_true(a[0] == 2. && a[1] == 1. && theta == 0.);
  double const q_tall[3] = {1., 0., 4.};
  g_assert_cmpint(pw85_2d_principal_axes(q_tall, a, &theta), ==,
                  PW85_SUCCESS);
  g_assert_true(a[0] == 2. && a[1] == 1.);
  g_assert_cmpfloat(theta, ==, G_PI / 2.);
  double const circle[3] = {9., 0., 9.};
  g_assert_cmpint(pw85_2d_principal_axes(circle, a, &theta), ==,
                  PW85_SUCCESS);
  g_assert_true(a[0] == 3. && a[1] == 3. && theta == 0.);
  /* Round trips through pw85_2d_ellipse(), aspect ratios to 1e4. Its
   * rounding of Q (‖ΔQ‖ ≤ about 4u·a0², u = 2⁻⁵³) moves the semi-axes of
   * the stored Q away from those given: a1 by up to about
   * 2u·(a0/a1)² relative (ε·(a0/a1)², ε = 2u) and the axis by up to about
   * 4u/gap (gap = 1 − (a1/a0)², the relative distance of the eigenvalues);
   * pw85_2d_principal_axes() adds u·(1 + u·(a0/aⱼ)²) (pw85_2d.h; exact to
   * the last bit on the constructor references of test-2d-ref-data). The
   * tolerances are twice those bounds plus 4ε for a: measured ratios are
   * printed. */
  GRand *rng = g_rand_new_with_seed(2906);
  double worst_a = 0., worst_t = 0.;
  double const tol_t = 8. * DBL_EPSILON / 2.; /* 2·4u */
  for (int n = 0; n < pairs_per_test; n++) {
    double const l = g_rand_double_range(rng, 0.01, 4.),
                 size = pow(10., g_rand_double_range(rng, -100., 100.));
    double const given[2] = {size * pow(10., l / 2.), size * pow(10., -l / 2.)};
    double const t = g_rand_double_range(rng, -1.5, 1.5);
    double qq[3];
    g_assert_cmpint(pw85_2d_ellipse(given, t, qq), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_principal_axes(qq, a, &theta), ==,
                    PW85_SUCCESS);
    for (int j = 0; j < 2; j++) {
      double const ratio = given[0] / given[j];
      double const bound = 4. + 2. * ratio * ratio; /* in ε */
      double const e = fabs(a[j] - given[j]) / given[j] / DBL_EPSILON;
      if (e / bound > worst_a) worst_a = e / bound;
      if (!(e <= bound))
        g_test_fail_printf("form %d: a[%d] %.17g, given %.17g (%.3g eps > "
                           "%.3g)", n, j, a[j], given[j], e, bound);
    }
    double const gap = 1. - (given[1] / given[0]) * (given[1] / given[0]);
    double dt = fabs(theta - t);
    dt = fmin(dt, fabs(dt - G_PI));
    if (dt * gap / tol_t > worst_t) worst_t = dt * gap / tol_t;
    if (!(dt * gap <= tol_t))
      g_test_fail_printf("form %d: theta %.17g, given %.17g (gap %.3g)", n,
                         theta, t, gap);
  }
  g_test_message("principal axes: worst error of a / tolerance %.3g, of "
                 "theta %.3g", worst_a, worst_t);
  g_rand_free(rng);
}

/* The contact geometry and the derivatives: the contract (statuses,
 * outputs untouched), the same μ² as the contact function bit for bit,
 * and swapping: λ → 1 − λ, n → −n exactly, x − c2 = (x − c1) − r12 to
 * rounding, ∂μ²/∂r12 negated and the other derivatives exchanged
 * exactly (a zero may change sign). */
static void test_geometry(void) {
  double g[PW85_2D_GEOM_SIZE], d[PW85_2D_DERIV_SIZE];
  double const zero2[2] = {0., 0.};
  for (int k = 0; k < PW85_2D_GEOM_SIZE; k++) g[k] = 42.;
  for (int k = 0; k < PW85_2D_DERIV_SIZE; k++) d[k] = 42.;
  double const nan_r[2] = {NAN, 1.}, bad_q[3] = {1., 2., 1.};
  g_assert_cmpint(pw85_2d_contact_geometry(NULL, qa, qb, g), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_geometry(r0, qa, qb, NULL), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_derivatives(r0, qa, qb, g, NULL), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_derivatives(r0, qa, qb, NULL, d), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_derivatives(nan_r, qa, qb, g, d), ==,
                  PW85_EDOM);
  g_assert_cmpint(pw85_2d_contact_derivatives(r0, bad_q, qb, g, d), ==,
                  PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_2d_contact_geometry(r0, qa, bad_q, g), ==,
                  PW85_ENOTPOSDEF);
  for (int k = 0; k < PW85_2D_GEOM_SIZE; k++) g_assert_true(g[k] == 42.);
  for (int k = 0; k < PW85_2D_DERIV_SIZE; k++) g_assert_true(d[k] == 42.);
  /* Coincident centres: μ² = 0, λ = ½, everything else 0. */
  g_assert_cmpint(pw85_2d_contact_derivatives(zero2, qa, qb, g, d), ==,
                  PW85_SUCCESS);
  g_assert_true(g[PW85_2D_GEOM_MU2] == 0. && g[PW85_2D_GEOM_LAMBDA] == 0.5);
  for (int k = PW85_2D_GEOM_POINT; k < PW85_2D_GEOM_SIZE; k++)
    g_assert_true(g[k] == 0.);
  for (int k = 0; k < PW85_2D_DERIV_SIZE; k++) g_assert_true(d[k] == 0.);
  GRand *rng = g_rand_new_with_seed(2907);
  for (int n = 0; n < pairs_per_test / 4; n++) {
    double r[2], q1[3], q2[3], out[2], h[PW85_2D_GEOM_SIZE],
        e[PW85_2D_DERIV_SIZE], hg[PW85_2D_GEOM_SIZE];
    random_pair(rng, n % 2 ? 5. : 1., r, q1, q2);
    double const mr[2] = {-r[0], -r[1]};
    g_assert_cmpint(cf(r, q1, q2, out), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_contact_derivatives(r, q1, q2, g, d), ==,
                    PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_contact_geometry(r, q1, q2, hg), ==,
                    PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_contact_derivatives(mr, q2, q1, h, e), ==,
                    PW85_SUCCESS);
    g_assert_cmpmem(g, sizeof g, hg, sizeof hg);
    g_assert_true(g[PW85_2D_GEOM_MU2] == out[0] && h[PW85_2D_GEOM_MU2] ==
                  out[0]);
    g_assert_cmpfloat(fabs(h[PW85_2D_GEOM_LAMBDA] -
                           (1. - g[PW85_2D_GEOM_LAMBDA])), <=, DBL_EPSILON);
    /* the unit normal, n·r12 > 0 */
    double const *nn = g + PW85_2D_GEOM_NORMAL;
    g_assert_cmpfloat(fabs(nn[0] * nn[0] + nn[1] * nn[1] - 1.), <=,
                      4. * DBL_EPSILON);
    g_assert_cmpfloat(nn[0] * r[0] + nn[1] * r[1], >, 0.);
    for (int i = 0; i < 2; i++) {
      g_assert_true(h[PW85_2D_GEOM_NORMAL + i] == -nn[i]);
      g_assert_true(e[PW85_2D_DERIV_R12 + i] == -d[PW85_2D_DERIV_R12 + i]);
      /* x − c2 = (x − c1) − r12 */
      double const x2 = g[PW85_2D_GEOM_POINT + i] - r[i];
      g_assert_cmpfloat(fabs(h[PW85_2D_GEOM_POINT + i] - x2), <=,
                        1e-12 * (fabs(x2) + fabs(r[i])));
    }
    g_assert_true(e[PW85_2D_DERIV_THETA1] == d[PW85_2D_DERIV_THETA2] &&
                  e[PW85_2D_DERIV_THETA2] == d[PW85_2D_DERIV_THETA1]);
    for (int k = 0; k < 3; k++)
      g_assert_true(e[PW85_2D_DERIV_Q1 + k] == d[PW85_2D_DERIV_Q2 + k] &&
                    e[PW85_2D_DERIV_Q2 + k] == d[PW85_2D_DERIV_Q1 + k]);
  }
  g_rand_free(rng);
}

/* The batches: every pair as the single-pair function computes it, bit
 * for bit, on 1, 2 and 8 threads (2000 pairs: threads are used), with
 * strides 0 (one form for every pair) and wider than the record; a
 * failing pair's status in its entry, its outputs untouched, the first
 * failure returned; the call's own errors (NULL, a stride inside a
 * record, threads < 0) with every status entry set; n = 0. */
static void test_batches(void) {
  enum { n = 2000, stride = 5 }; /* stride > 3: records with padding */
  GRand *rng = g_rand_new_with_seed(2908);
  double *r = g_new(double, 2 * n), *q1 = g_new(double, stride * n),
         *q2 = g_new(double, 3 * n);
  for (int i = 0; i < n; i++) {
    random_pair(rng, i % 2 ? 4. : 1., r + 2 * i, q1 + stride * i,
                q2 + 3 * i);
    q1[stride * i + 3] = NAN; /* padding, never read */
    q1[stride * i + 4] = NAN;
  }
  r[2 * 777] = NAN;    /* pair 777 fails: PW85_EDOM */
  q2[3 * 1234] = -1.; /* pair 1234 fails: PW85_ENOTPOSDEF */
  double *out = g_new(double, 2 * n), *ref = g_new(double, 2 * n);
  int *res = g_new(int, n), *ref_res = g_new(int, n);
  double *geo = g_new(double, PW85_2D_GEOM_SIZE * n),
         *der = g_new(double, PW85_2D_DERIV_SIZE * n),
         *ref_geo = g_new(double, PW85_2D_GEOM_SIZE * n),
         *ref_der = g_new(double, PW85_2D_DERIV_SIZE * n);
  int *status = g_new(int, n), *ref_status = g_new(int, n);
  for (int i = 0; i < n; i++) {
    ref[2 * i] = ref[2 * i + 1] = -1.;
    ref_res[i] = 42;
    for (int k = 0; k < PW85_2D_GEOM_SIZE; k++)
      ref_geo[PW85_2D_GEOM_SIZE * i + k] = -1.;
    for (int k = 0; k < PW85_2D_DERIV_SIZE; k++)
      ref_der[PW85_2D_DERIV_SIZE * i + k] = -1.;
    ref_status[i] = pw85_2d_contact_function(r + 2 * i, q1 + stride * i,
                                             q2 + 3 * i, ref + 2 * i);
    g_assert_cmpint(pw85_2d_overlap(r + 2 * i, q1 + stride * i, q2 + 3 * i,
                                    ref_res + i), ==, ref_status[i]);
    g_assert_cmpint(pw85_2d_contact_derivatives(
                        r + 2 * i, q1 + stride * i, q2 + 3 * i,
                        ref_geo + PW85_2D_GEOM_SIZE * i,
                        ref_der + PW85_2D_DERIV_SIZE * i), ==,
                    ref_status[i]);
  }
  g_assert_cmpint(ref_status[777], ==, PW85_EDOM);
  g_assert_cmpint(ref_status[1234], ==, PW85_ENOTPOSDEF);
  int const threads[] = {1, 2, 8};
  for (size_t t = 0; t < G_N_ELEMENTS(threads); t++) {
    for (int i = 0; i < n; i++) {
      out[2 * i] = out[2 * i + 1] = -1.;
      res[i] = 42;
      status[i] = 99;
    }
    for (int k = 0; k < PW85_2D_GEOM_SIZE * n; k++) geo[k] = -1.;
    for (int k = 0; k < PW85_2D_DERIV_SIZE * n; k++) der[k] = -1.;
    g_assert_cmpint(pw85_2d_contact_function_batch(n, r, 2, q1, stride, q2, 3,
                                                   out, status, threads[t]),
                    ==, PW85_EDOM);
    g_assert_cmpmem(out, 2 * n * sizeof(double), ref, 2 * n * sizeof(double));
    g_assert_cmpmem(status, n * sizeof(int), ref_status, n * sizeof(int));
    g_assert_cmpint(pw85_2d_overlap_batch(n, r, 2, q1, stride, q2, 3, res,
                                          NULL, threads[t]), ==, PW85_EDOM);
    g_assert_cmpmem(res, n * sizeof(int), ref_res, n * sizeof(int));
    g_assert_cmpint(pw85_2d_contact_derivatives_batch(
                        n, r, 2, q1, stride, q2, 3, geo, der, status,
                        threads[t]), ==, PW85_EDOM);
    g_assert_cmpmem(geo, PW85_2D_GEOM_SIZE * n * sizeof(double), ref_geo,
                    PW85_2D_GEOM_SIZE * n * sizeof(double));
    g_assert_cmpmem(der, PW85_2D_DERIV_SIZE * n * sizeof(double), ref_der,
                    PW85_2D_DERIV_SIZE * n * sizeof(double));
    for (int k = 0; k < PW85_2D_GEOM_SIZE * n; k++) geo[k] = -1.;
    g_assert_cmpint(pw85_2d_contact_geometry_batch(n, r, 2, q1, stride, q2, 3,
                                                   geo, NULL, threads[t]),
                    ==, PW85_EDOM);
    g_assert_cmpmem(geo, PW85_2D_GEOM_SIZE * n * sizeof(double), ref_geo,
                    PW85_2D_GEOM_SIZE * n * sizeof(double));
  }
  /* Stride 0: one form for every pair. */
  g_assert_cmpint(pw85_2d_contact_function_batch(10, r, 2, q2, 0, q2, 3, out,
                                                 status, 1), ==, PW85_SUCCESS);
  for (int i = 0; i < 10; i++) {
    double one[2];
    g_assert_cmpint(pw85_2d_contact_function(r + 2 * i, q2, q2 + 3 * i, one),
                    ==, PW85_SUCCESS);
    g_assert_true(one[0] == out[2 * i] && one[1] == out[2 * i + 1]);
  }
  /* The call's own errors: nothing computed, every status entry set. */
  for (int i = 0; i < n; i++) status[i] = 99;
  g_assert_cmpint(pw85_2d_contact_function_batch(n, r, 1, q1, stride, q2, 3,
                                                 out, status, 1), ==,
                  PW85_EINVAL);
  for (int i = 0; i < n; i++) g_assert_cmpint(status[i], ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_overlap_batch(n, r, 2, q1, 2, q2, 3, res, status,
                                        1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_overlap_batch(n, r, 2, q1, 3, q2, 3, res, status,
                                        -1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_contact_derivatives_batch(n, r, 2, q1, 3, q2, 3,
                                                    geo, NULL, status, 1),
                  ==, PW85_EFAULT);
  g_assert_cmpint(status[n - 1], ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_function_batch(n, NULL, 2, q1, 3, q2, 3,
                                                 out, NULL, 1), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_contact_function_batch(0, NULL, 1, NULL, 1, NULL,
                                                 1, NULL, NULL, -1), ==,
                  PW85_SUCCESS);
  /* The constructors' batches. */
  double a[2 * 100], theta[100], q[3 * 100], axes[2 * 100], angles[100];
  for (int i = 0; i < 100; i++) {
    a[2 * i] = g_rand_double_range(rng, 1., 10.);
    a[2 * i + 1] = g_rand_double_range(rng, 0.1, 1.);
    theta[i] = g_rand_double_range(rng, -1.5, 1.5);
  }
  a[2 * 50 + 1] = -1.; /* item 50: PW85_EINVAL */
  g_assert_cmpint(pw85_2d_ellipse_batch(100, a, 2, theta, 1, q, status, 2),
                  ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_principal_axes_batch(50, q, 3, axes, angles,
                                               status, 2), ==, PW85_SUCCESS);
  for (int i = 0; i < 50; i++) {
    double one[3], one_a[2], one_t;
    g_assert_cmpint(pw85_2d_ellipse(a + 2 * i, theta[i], one), ==,
                    PW85_SUCCESS);
    g_assert_cmpmem(one, sizeof one, q + 3 * i, sizeof one);
    g_assert_cmpint(pw85_2d_principal_axes(one, one_a, &one_t), ==,
                    PW85_SUCCESS);
    g_assert_true(one_a[0] == axes[2 * i] && one_a[1] == axes[2 * i + 1] &&
                  one_t == angles[i]);
  }
  g_assert_cmpint(pw85_2d_ellipse_batch(3, a, 1, theta, 1, q, NULL, 1), ==,
                  PW85_EINVAL);
  g_assert_cmpint(pw85_2d_principal_axes_batch(3, q, 3, axes, NULL, NULL, 1),
                  ==, PW85_EFAULT);
  g_free(r), g_free(q1), g_free(q2), g_free(out), g_free(ref), g_free(res),
      g_free(ref_res), g_free(geo), g_free(der), g_free(ref_geo),
      g_free(ref_der), g_free(status), g_free(ref_status);
  g_rand_free(rng);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/2d/contract/null", test_null);
  g_test_add_func("/pw85/2d/contract/not-finite", test_not_finite);
  g_test_add_func("/pw85/2d/contract/definiteness", test_definiteness);
  g_test_add_func("/pw85/2d/contract/coincident", test_coincident);
  g_test_add_func("/pw85/2d/contract/circles", test_circles);
  g_test_add_func("/pw85/2d/contract/overflow", test_overflow);
  g_test_add_func("/pw85/2d/invariance/swap", test_swap);
  g_test_add_func("/pw85/2d/invariance/scaling", test_scaling);
  g_test_add_func("/pw85/2d/invariance/symmetries", test_symmetries);
  g_test_add_func("/pw85/2d/invariance/rotation", test_rotation);
  g_test_add_func("/pw85/2d/overlap/sign", test_overlap_sign);
  g_test_add_func("/pw85/2d/geometry/contract", test_geometry);
  g_test_add_func("/pw85/2d/batch/pairs", test_batches);
  g_test_add_func("/pw85/2d/ellipse/statuses", test_ellipse_statuses);
  g_test_add_func("/pw85/2d/ellipse/principal-axes", test_principal_axes);
  g_test_add_func("/pw85/2d/ellipse/underflow", test_ellipse_underflow);
  g_test_add_func("/pw85/2d/ellipse/principal-axes-underflow",
                  test_principal_axes_underflow);
  g_test_add_func("/pw85/2d/ellipse/principal-axes-needle",
                  test_principal_axes_needle);
  return g_test_run();
}
