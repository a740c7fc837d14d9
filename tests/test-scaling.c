/* SPDX-License-Identifier: BSD-3-Clause */
/* Invariance of pw85_contact_function, pw85_overlap and pw85_f_neg under a
 * change of unit of length: r → t·r, Q → t²·Q leaves μ² and λ unchanged,
 * exactly when t is a power of two (the library rescales by powers of two
 * itself), to a few ulps otherwise; and pairs whose sizes differ by up to
 * 2^1000. (The input contract: test-input-contract.c.) */
#include <float.h>
#include <pw85.h>
#include <pw85_2d.h>

#include "contract.h"
#include "ddref.h"
#include "testutil.h"

/* The valid input of tests/contract.h: the tutorial's pair. */
#define r_ok contract_r
#define q1_ok contract_q1
#define q2_ok contract_q2


/* μ²(t·r, t²·Q1, t²·Q2) = μ²(r, Q1, Q2). t is not a power of two, so the
 * scaled inputs are rounded: the results agree to a few ulps (measured:
 * 2.6e-16). */
static void test_scale_invariance(void) {
  double ref[2];
  g_assert_cmpint(contract_cf(r_ok, q1_ok, q2_ok, ref), ==, PW85_SUCCESS);
  double const scales[] = {1e-150, 1e-100, 1e-10, 1e10, 1e100, 1e150};
  for (size_t k = 0; k < G_N_ELEMENTS(scales); k++) {
    double const t = scales[k];
    double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
    contract_scaled(t, r_ok, q1_ok, q2_ok, r, q1, q2);
    int const status = contract_cf(r, q1, q2, out);
    contract_assert_valid(status, out);
    assert_close("mu2, scaled by %g", out[0], ref[0], 1e-14, t);
    assert_close("lambda, scaled by %g", out[1], ref[1], 1e-9, t);
  }
}

/* Scaling by exact powers of two changes nothing at all: the library
 * rescales by powers of two itself. */
static void test_scale_power_of_two(void) {
  double ref[2];
  int ref_overlap = 0;
  g_assert_cmpint(contract_cf(r_ok, q1_ok, q2_ok, ref), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_overlap(r_ok, q1_ok, q2_ok, &ref_overlap), ==,
                  PW85_SUCCESS);
  int const exps[] = {-500, -250, -1, 1, 250, 500};
  for (size_t k = 0; k < G_N_ELEMENTS(exps); k++) {
    double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
    for (int i = 0; i < PW85_DIM; i++) r[i] = ldexp(r_ok[i], exps[k]);
    for (int i = 0; i < PW85_SYM; i++) {
      q1[i] = ldexp(q1_ok[i], 2 * exps[k]);
      q2[i] = ldexp(q2_ok[i], 2 * exps[k]);
    }
    g_assert_cmpint(contract_cf(r, q1, q2, out), ==, PW85_SUCCESS);
    g_assert_cmpfloat(out[0], ==, ref[0]);
    g_assert_cmpfloat(out[1], ==, ref[1]);
    int result = 42;
    g_assert_cmpint(pw85_overlap(r, q1, q2, &result), ==, PW85_SUCCESS);
    g_assert_cmpint(result, ==, ref_overlap);
  }
}

/* Ellipsoids of one shape and orientation whose sizes differ by 2^m
 * (Q2 = 4^m·Q1), up to 2^1000: μ² = rᵀQ1⁻¹r/(1 + 2^m)² and λ = 1/(1 + 2^m)
 * exactly (an affine map makes them two spheres). Q1 = R·D·Rᵀ·2⁻ᵐ with
 * R = R'/25, R' an integer matrix, so that R'·D·R'ᵀ is exact in double and
 * Q1 is correctly rounded; rᵀQ1⁻¹r = Σₙ cₙ²/(dₙ·2⁻ᵐ), c = Rᵀr, is computed
 * in double-double (tests/ddref.h) from r = 2^m·(0.3, 0.2, 0.1): μ² =
 * 2^m·Σₙ c'ₙ²/(625·dₙ) with c' = R'ᵀ(0.3, 0.2, 0.1), since (1 + 2^m)² =
 * 2^2m to 2⁻⁹⁹ relative for m ≥ 100, and λ = 2⁻ᵐ once rounded. Rounding Q1
 * to double moves μ² by about 2e-17 relative, so μ² is checked to one ulp.
 * Beyond m ≈ 512, rᵀQ1⁻¹r / rᵀQ2⁻¹r overflows: a warm start formed from
 * that ratio fell back to λ = ½, and μ² came out 3e-6 off. (The reference
 * was in long double before: valgrind runs it at double precision, where
 * 2^2000 overflows.) */
static void test_size_ratio(void) {
  double const rot25[3][3] = {{9., 12., -20.}, {-20., 15., 0.},
                              {12., 16., 15.}};
  double const d[3] = {1., 2., 3.};
  double const r0[3] = {0.3, 0.2, 0.1};
  DD a = dd(0.);
  for (int n = 0; n < 3; n++) {
    DD c = dd(0.);
    for (int i = 0; i < 3; i++) c = dd_add(c, dd_mul(dd(rot25[i][n]), dd(r0[i])));
    a = dd_add(a, dd_div(dd_mul(c, c), dd(625. * d[n])));
  }
  for (int m = 100; m <= 1000; m += 100) {
    double const s = ldexp(1., -m);
    double q1[PW85_SYM], q2[PW85_SYM];
    int k = 0;
    for (int i = 0; i < 3; i++)
      for (int j = i; j < 3; j++, k++) {
        double t = 0.; /* an integer below 2^53: exact */
        for (int n = 0; n < 3; n++) t += rot25[i][n] * d[n] * rot25[j][n];
        q1[k] = t / 625. * s;
        q2[k] = ldexp(q1[k], 2 * m);
      }
    double const r[PW85_DIM] = {ldexp(r0[0], m), ldexp(r0[1], m),
                                ldexp(r0[2], m)};
    double out[2];
    contract_assert_valid(contract_cf(r, q1, q2, out), out);
    assert_close("mu2, size ratio 2^%d", out[0], ldexp(dd_to_double(a), m),
                 DBL_EPSILON, m);
    assert_close("lambda, size ratio 2^%d", out[1], ldexp(1., -m),
                 DBL_EPSILON, m);
  }
}

/* pw85_f_neg works on its input as given, unscaled: scaling r by 2^k and the
 * forms by 2^2k changes no rounding of f = λ(1−λ)·rᵀQ⁻¹r while no
 * intermediate leaves the normal range, so the value must not change at
 * all. 2^±800 in the forms is where a product of two entries of Q(λ), were
 * it formed, would overflow or underflow; a factorisation that forms one
 * must notice. */
static void test_f_neg_scale(void) {
  /* r, then two forms with off-diagonal entries (diagonally dominant). */
  double const params[15] = {0.7, -0.7, 1.1,
                             4., 1., 0.5, 3., 0.25, 2.,
                             1., -0.3, 0.2, 2., 0.1, 5.};
  double const lambdas[] = {0.1, 0.5, 0.9};
  int const exps[] = {-400, -200, 200, 400};
  for (size_t l = 0; l < G_N_ELEMENTS(lambdas); l++) {
    double const ref = pw85_f_neg(lambdas[l], params);
    g_assert_true(isfinite(ref) && ref < 0.);
    for (size_t k = 0; k < G_N_ELEMENTS(exps); k++) {
      double scaled[15];
      for (int i = 0; i < 15; i++)
        scaled[i] = ldexp(params[i], i < 3 ? exps[k] : 2 * exps[k]);
      g_assert_cmpfloat(pw85_f_neg(lambdas[l], scaled), ==, ref);
    }
  }
}

/* The span of the diagonals that the search carries (pw85.h: binary
 * exponents at most 2016 apart). Two spheres of radii 2^−504 and 2^504
 * (forms 2^−1008·I and 2^1008·I: frexp exponents −1007 and 1009, 2016
 * apart), centres 2^504 apart: μ² = 2^1008/(2^504 + 2^−504)² =
 * (1 + 2^−1008)^−2, within 2^−1006 of 1, so 1 once rounded; λ* =
 * ρ1/(ρ1 + ρ2) = 2^−1008/(1 + 2^−1008), which rounds to 2^−1008. The
 * larger sphere twice as large (exponents 2017 apart): PW85_ERANGE from
 * every entry point, outputs untouched. The same in 2D. */
static void test_span_limit(void) {
  double const r[3] = {0x1p504, 0., 0.};
  double const q1[PW85_SYM] = {0x1p-1008, 0., 0., 0x1p-1008, 0., 0x1p-1008};
  double q2[PW85_SYM] = {0x1p1008, 0., 0., 0x1p1008, 0., 0x1p1008};
  double out[2] = {-1., -1.};
  int res = 7;
  g_assert_cmpint(pw85_contact_function(r, q1, q2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 1.);
  g_assert_cmpfloat(out[1], ==, 0x1p-1008);
  double const r2[2] = {0x1p504, 0.};
  double const p1[3] = {0x1p-1008, 0., 0x1p-1008};
  double p2[3] = {0x1p1008, 0., 0x1p1008};
  g_assert_cmpint(pw85_2d_contact_function(r2, p1, p2, out), ==,
                  PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 1.);
  g_assert_cmpfloat(out[1], ==, 0x1p-1008);

  q2[0] = q2[3] = q2[5] = 0x1p1009;
  p2[0] = p2[2] = 0x1p1009;
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  for (int k = 0; k < PW85_GEOM_SIZE; k++) g[k] = -1.;
  for (int k = 0; k < PW85_DERIV_SIZE; k++) d[k] = -1.;
  out[0] = out[1] = -1.;
  g_assert_cmpint(pw85_contact_function(r, q1, q2, out), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_overlap(r, q1, q2, &res), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_contact_geometry(r, q1, q2, g), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_contact_derivatives(r, q1, q2, g, d), ==,
                  PW85_ERANGE);
  g_assert_cmpint(pw85_2d_contact_function(r2, p1, p2, out), ==,
                  PW85_ERANGE);
  g_assert_cmpint(pw85_2d_overlap(r2, p1, p2, &res), ==, PW85_ERANGE);
  g_assert_true(out[0] == -1. && out[1] == -1. && res == 7);
  for (int k = 0; k < PW85_GEOM_SIZE; k++) g_assert_cmpfloat(g[k], ==, -1.);
  for (int k = 0; k < PW85_DERIV_SIZE; k++) g_assert_cmpfloat(d[k], ==, -1.);
}

/* Both ways through the rescaling (src/scaling.cpp): the common one, read
 * from the exponent bits, up to its edges (the largest |rᵢ| or the middle
 * diagonal exponent at 2^1021, frexp exponent 1022), and the general one
 * beyond them (exponent 1023 or 1024, where 2^−e is subnormal) or for
 * subnormal entries (frexp, ldexp). Two equal spheres Q = 2^2k·I, centres
 * 2^m apart along an axis: μ² = 2^2m/(2·2^k)² = 2^(2m−2k−2) and λ = ½,
 * exactly (subnormal μ² too: a power of two). In 3D and in 2D. */
static void test_rescale_paths(void) {
  struct {
    int m, k;
  } const cases[] = {
      {0, 0},         {1000, 500},  {-1000, -500}, /* common */
      {1021, 510},    /* r and the diagonals at the common path's edge */
      {1022, 511},    {1023, 511},  /* r beyond it; the diagonals beyond */
      {1021, 511},    /* the diagonals alone beyond it */
      {-530, -530},   /* subnormal diagonals */
      {-1040, -525},  /* subnormal r and diagonals, subnormal μ² */
      {-1021, -511},  {-1022, -511}, /* μ² at 2^−1022 and 2^−1024 */
  };
  for (size_t c = 0; c < G_N_ELEMENTS(cases); c++) {
    int const m = cases[c].m, k = cases[c].k;
    double const mu2 = ldexp(1., 2 * m - 2 * k - 2), d = ldexp(1., 2 * k);
    int const expected = mu2 < 1. ? -1 : 1;
    double const r[PW85_DIM] = {0., ldexp(1., m), 0.};
    double const q[PW85_SYM] = {d, 0., 0., d, 0., d};
    double out[2] = {-1., -1.};
    int res = 7;
    g_assert_cmpint(pw85_contact_function(r, q, q, out), ==, PW85_SUCCESS);
    g_assert_cmpfloat(out[0], ==, mu2);
    g_assert_cmpfloat(out[1], ==, 0.5);
    g_assert_cmpint(pw85_overlap(r, q, q, &res), ==, PW85_SUCCESS);
    g_assert_cmpint(res, ==, expected);
    double const r2[2] = {ldexp(1., m), 0.};
    double const p[3] = {d, 0., d};
    out[0] = out[1] = -1.;
    res = 7;
    g_assert_cmpint(pw85_2d_contact_function(r2, p, p, out), ==,
                    PW85_SUCCESS);
    g_assert_cmpfloat(out[0], ==, mu2);
    g_assert_cmpfloat(out[1], ==, 0.5);
    g_assert_cmpint(pw85_2d_overlap(r2, p, p, &res), ==, PW85_SUCCESS);
    g_assert_cmpint(res, ==, expected);
  }
}

/* A point-like ellipse (entries 2^-1060, subnormal) against a form of
 * order one, r nearly along its long axis: μ² is rᵀQ2⁻¹r to about 1e-150
 * (f rises to it for λ far above the first form's size and μ² ≤ rᵀQ2⁻¹r,
 * the centre bound), and rᵀQ2⁻¹r − 1 = 11.2069·ε exactly in rationals
 * (python3 fractions: (c·r0² − 2b·r0·r1 + a·r1²)/(ac − b²) − 1 with
 * Q2 = [[a, b], [b, c]]), outside the 4-ulp band: disjoint. The search
 * visits λ ≈ 2^-528, where λ² is subnormal: μ2² = λ²·P2 computed with it
 * came out 2e-6 low, and the overlap test answered −1 (fuzz-2d,
 * regress-lambda-squared-underflow; the same in 3D with a third axis). */
static void test_lambda_squared_underflow(void) {
  double const r2[2] = {0x1.0000000000001p+0, 0x1.0000000003p+0};
  double const p1[3] = {0x0.0000000004626p-1022, 0., 0x0.000fp-1022};
  double const p2[3] = {1., 1., 0x1.0000000fa35p+0};
  double const mr2[2] = {-r2[0], -r2[1]};
  double out[2];
  int res = 7;
  g_assert_cmpint(pw85_2d_contact_function(r2, p1, p2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 1. + 11. * DBL_EPSILON); /* rounded 11.2069 */
  g_assert_cmpint(pw85_2d_overlap(r2, p1, p2, &res), ==, PW85_SUCCESS);
  g_assert_cmpint(res, ==, 1);
  res = 7;
  g_assert_cmpint(pw85_2d_overlap(mr2, p2, p1, &res), ==, PW85_SUCCESS);
  g_assert_cmpint(res, ==, 1);
  double const r3[3] = {r2[0], r2[1], 0.};
  double const mr3[3] = {-r2[0], -r2[1], 0.};
  double const q1[6] = {p1[0], 0., 0., p1[2], 0., p1[2]};
  double const q2[6] = {1., 1., 0., p2[2], 0., 1.};
  g_assert_cmpint(pw85_contact_function(r3, q1, q2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 1. + 11. * DBL_EPSILON);
  res = 7;
  g_assert_cmpint(pw85_overlap(r3, q1, q2, &res), ==, PW85_SUCCESS);
  g_assert_cmpint(res, ==, 1);
  res = 7;
  g_assert_cmpint(pw85_overlap(mr3, q2, q1, &res), ==, PW85_SUCCESS);
  g_assert_cmpint(res, ==, 1);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/scaling/contact_function/any-factor",
                  test_scale_invariance);
  g_test_add_func("/pw85/scaling/contact_function/power-of-two",
                  test_scale_power_of_two);
  g_test_add_func("/pw85/scaling/contact_function/size-ratio",
                  test_size_ratio);
  g_test_add_func("/pw85/scaling/f_neg/power-of-two", test_f_neg_scale);
  g_test_add_func("/pw85/scaling/span-limit", test_span_limit);
  g_test_add_func("/pw85/scaling/rescale-paths", test_rescale_paths);
  g_test_add_func("/pw85/scaling/overlap/lambda-squared-underflow",
                  test_lambda_squared_underflow);
  return g_test_run();
}
