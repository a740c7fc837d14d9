/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_ellipsoid_rotation(), pw85_ellipsoid_quaternion(),
 * pw85_principal_axes(), pw85_principal_axes_quaternion() and
 * pw85_spheroid_checked(): the input contract, hand-derived cases, the error
 * bound of pw85.h against a double-double reference computed here
 * (aspect ratios to 1e8), and the properties of the principal axes. The
 * comparison with references at 60 digits is test-geometry-refs.c. */
#include <float.h>
#include <glib.h>
#include <math.h>
#include <string.h>

#include "ddref.h"
#include "pw85.h"
#include "testutil.h"
#include "worst.h"

#define U (DBL_EPSILON / 2.0)

static gboolean untouched(double const *x, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (x[i] != -7.0) return FALSE;
  return TRUE;
}

static void fill(double *x, size_t n) {
  for (size_t i = 0; i < n; i++) x[i] = -7.0;
}

static double const identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};

static void test_contract(void) {
  double const a[3] = {3.0, 2.0, 1.0};
  double const p[4] = {1.0, 0.0, 0.0, 0.0};
  double q[6];
  g_assert_cmpint(pw85_ellipsoid_rotation(NULL, identity, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_ellipsoid_rotation(a, NULL, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_ellipsoid_rotation(a, identity, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_ellipsoid_quaternion(NULL, p, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_ellipsoid_quaternion(a, NULL, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, NULL), ==, PW85_EFAULT);
  /* Each argument's entries in turn non-finite, then a semi-axis not > 0:
   * the status, and q untouched. */
  for (int k = 0; k < 3 + 9 + 4; k++) {
    double aa[3], rr[9], pp[4];
    memcpy(aa, a, sizeof aa), memcpy(rr, identity, sizeof rr);
    memcpy(pp, p, sizeof pp);
    double *x = k < 3 ? aa + k : (k < 12 ? rr + (k - 3) : pp + (k - 12));
    *x = k % 2 ? NAN : INFINITY;
    fill(q, 6);
    if (k < 12) {
      g_assert_cmpint(pw85_ellipsoid_rotation(aa, rr, q), ==, PW85_EDOM);
      g_assert_true(untouched(q, 6));
    }
    if (k < 3 || k >= 12) {
      g_assert_cmpint(pw85_ellipsoid_quaternion(aa, pp, q), ==, PW85_EDOM);
      g_assert_true(untouched(q, 6));
    }
  }
  double const bad_axes[3] = {0.0, -0.0, -1.0};
  for (int k = 0; k < 3; k++) {
    double aa[3];
    memcpy(aa, a, sizeof aa);
    aa[k] = bad_axes[k];
    fill(q, 6);
    g_assert_cmpint(pw85_ellipsoid_rotation(aa, identity, q), ==, PW85_EINVAL);
    g_assert_cmpint(pw85_ellipsoid_quaternion(aa, p, q), ==, PW85_EINVAL);
    g_assert_true(untouched(q, 6));
  }
  /* a² out of the normal range of doubles. */
  double const big[3] = {1e155, 1.0, 1.0}, small[3] = {1.0, 1e-160, 1.0};
  fill(q, 6);
  g_assert_cmpint(pw85_ellipsoid_rotation(big, identity, q), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_ellipsoid_quaternion(small, p, q), ==, PW85_ERANGE);
  g_assert_true(untouched(q, 6));
}

/* Orthonormality to PW85_UNIT_TOL: a rotation perturbed by 0.4 of the
 * tolerance passes, by 2.5 times fails, in every entry; so for the norm of
 * a quaternion. A reflection passes. */
static void test_unit_tolerance(void) {
  double const a[3] = {3.0, 2.0, 1.0};
  double q[6];
  for (int k = 0; k < 9; k++) {
    double r[9];
    memcpy(r, identity, sizeof r);
    r[k] += 0.4 * PW85_UNIT_TOL;
    g_assert_cmpint(pw85_ellipsoid_rotation(a, r, q), ==, PW85_SUCCESS);
    r[k] = identity[k] + 2.5 * PW85_UNIT_TOL;
    fill(q, 6);
    g_assert_cmpint(pw85_ellipsoid_rotation(a, r, q), ==, PW85_EINVAL);
    g_assert_true(untouched(q, 6));
  }
  /* ‖p‖² = 1 ± 0.8·tol passes, 1 ± 1.5·tol fails. */
  double const p[4] = {0.5, -0.5, 0.5, 0.5};
  double const factors[4] = {0.8, -0.8, 1.5, -1.5};
  for (int k = 0; k < 4; k++) {
    double pk[4];
    double const f = sqrt(1.0 + factors[k] * PW85_UNIT_TOL);
    for (int i = 0; i < 4; i++) pk[i] = p[i] * f;
    fill(q, 6);
    g_assert_cmpint(pw85_ellipsoid_quaternion(a, pk, q), ==,
                    k < 2 ? PW85_SUCCESS : PW85_EINVAL);
    if (k >= 2) g_assert_true(untouched(q, 6));
  }
  double const reflection[9] = {0, 1, 0, 1, 0, 0, 0, 0, 1};
  g_assert_cmpint(pw85_ellipsoid_rotation(a, reflection, q), ==, PW85_SUCCESS);
  double const expected[6] = {4.0, 0.0, 0.0, 9.0, 0.0, 1.0};
  g_assert_cmpmem(q, sizeof q, expected, sizeof expected);
}

/* Hand-derived: the identity and the half-turns about each axis (p = ±1,
 * ±i, ±j, ±k) leave diag(a²) exactly; a quarter turn about z,
 * p = (cos 45°, 0, 0, sin 45°), takes a[0] to the y axis and a[1] to −x:
 * Q = diag(a1², a0², a2²) up to the rounding of cos 45° and sin 45° in p
 * (p is still a rotation, by 90° to within 2u: Q01 is at most about
 * 2u·|a0² − a1²|). */
static void test_hand_derived(void) {
  double const a[3] = {3.0, 2.0, 0.5};
  double const diag[6] = {9.0, 0.0, 0.0, 4.0, 0.0, 0.25};
  double q[6];
  for (int k = 0; k < 8; k++) {
    double p[4] = {0.0, 0.0, 0.0, 0.0};
    p[k % 4] = k < 4 ? 1.0 : -1.0;
    g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, q), ==, PW85_SUCCESS);
    g_assert_cmpmem(q, sizeof q, diag, sizeof diag);
  }
  g_assert_cmpint(pw85_ellipsoid_rotation(a, identity, q), ==, PW85_SUCCESS);
  g_assert_cmpmem(q, sizeof q, diag, sizeof diag);
  double const p[4] = {cos(G_PI / 4), 0.0, 0.0, sin(G_PI / 4)};
  g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, q), ==, PW85_SUCCESS);
  double const turned[6] = {4.0, 0.0, 0.0, 9.0, 0.0, 0.25};
  for (int k = 0; k < 6; k++)
    g_assert_cmpfloat(fabs(q[k] - turned[k]), <=, 4 * U * 5.0 + 2 * U * turned[k]);
  /* The same turn as a rotation matrix: columns R·e_j = e_y, −e_x, e_z. */
  double const r[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  g_assert_cmpint(pw85_ellipsoid_rotation(a, r, q), ==, PW85_SUCCESS);
  g_assert_cmpmem(q, sizeof q, turned, sizeof turned);
}

/* A random rotation from a random unit quaternion (in double: orthonormal
 * to a few u), and semi-axes with aspect ratios up to max_aspect. */
static void random_case(GRand *rng, double max_aspect, double a[3],
                        double p[4], double rot[9]) {
  random_unit_quaternion(rng, p);
  quaternion_rotation(p, rot);
  double const size = pow(10.0, g_rand_double_range(rng, -3.0, 3.0));
  for (int i = 0; i < 3; i++)
    a[i] = size * pow(max_aspect, -g_rand_double(rng));
}

/* The bound of pw85.h for pw85_ellipsoid_rotation(): |q[k] − Q_k| ≤ u·|Q_k|
 * + 2⁻¹⁰⁰·Σₘ|R_im·R_jm|·aₘ², against Q_k in double-double computed here
 * (each product and sum within 4·2⁻¹⁰⁶ of its operands: the reference
 * itself is within 2⁻¹⁰¹·Σ). Measured in units of the bound. */
static void test_rotation_bound(void) {
  GRand *rng = g_rand_new_with_seed(8);
  Worst w = worst_init("|q - Q| / (u|Q| + 2^-100 sum + 2^-101 sum)", 1.0);
  size_t exact = 0, count = 0;
  for (int k = 0; k < 20000; k++) {
    double a[3], p[4], rot[9], q[6];
    random_case(rng, k % 2 ? 1e8 : 1e3, a, p, rot);
    g_assert_cmpint(pw85_ellipsoid_rotation(a, rot, q), ==, PW85_SUCCESS);
    int m = 0;
    for (int i = 0; i < 3; i++)
      for (int j = i; j < 3; j++, m++) {
        DD acc = dd(0.0);
        double sum = 0.0;
        for (int l = 0; l < 3; l++) {
          DD const t = dd_mul(dd_mul(dd(rot[3 * i + l]), dd(rot[3 * j + l])),
                              dd_mul(dd(a[l]), dd(a[l])));
          acc = dd_add(acc, t);
          sum += fabs(rot[3 * i + l] * rot[3 * j + l]) * a[l] * a[l];
        }
        double const ref = dd_to_double(acc);
        double const err = fabs(dd_to_double(dd_sub(dd(q[m]), acc)));
        double const bound = U * fabs(ref) + (0x1p-100 + 0x1p-101) * sum;
        worst_check(&w, (size_t)(6 * k + m), q[m], ref, err / bound);
        exact += q[m] == ref;
        count++;
      }
  }
  g_test_message("%zu of %zu entries equal to the rounded reference", exact,
                 count);
  worst_report(&w);
  g_rand_free(rng);
}

/* pw85_ellipsoid_quaternion() against pw85_ellipsoid_rotation() of the
 * same rotation formed in double (orthonormal to a few u): both within a
 * few u·max aₘ² of each other. Measured in units of u·max aₘ². */
static void test_quaternion_matches_rotation(void) {
  GRand *rng = g_rand_new_with_seed(9);
  Worst w = worst_init("|q(p) - q(R(p))| / (u max a^2)", 16.0);
  for (int k = 0; k < 20000; k++) {
    double a[3], p[4], rot[9], qp[6], qr[6];
    random_case(rng, 1e8, a, p, rot);
    g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, qp), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_ellipsoid_rotation(a, rot, qr), ==, PW85_SUCCESS);
    double const amax = fmax(a[0], fmax(a[1], a[2]));
    for (int m = 0; m < 6; m++) {
      double const err = fabs(qp[m] - qr[m]) / (U * amax * amax);
      worst_check(&w, (size_t)(6 * k + m), qp[m], qr[m], err);
    }
  }
  worst_report(&w);
  g_rand_free(rng);
}

/* Diagonal forms, by hand: a = √ of the diagonal, sorted, R a signed
 * permutation with det +1 and the largest entry of columns 0 and 1
 * positive. */
static void test_axes_diagonal(void) {
  double const q[6] = {9.0, 0.0, 0.0, 1e-16, 0.0, 4.0};
  double a[3], rot[9];
  g_assert_cmpint(pw85_principal_axes(q, a, rot), ==, PW85_SUCCESS);
  double const expected_a[3] = {3.0, 2.0, 1e-8};
  for (int i = 0; i < 3; i++)
    g_assert_cmpfloat(fabs(a[i] - expected_a[i]), <=, 2 * U * expected_a[i]);
  /* Columns e_x, e_z, then −e_y for det = +1. */
  double const expected_r[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  for (int k = 0; k < 9; k++)
    g_assert_cmpfloat(fabs(rot[k] - expected_r[k]), <=, 4 * U);
}

static void test_axes_contract(void) {
  double const q[6] = {1.0, 0.1, 0.0, 2.0, 0.0, 0.5};
  double const indefinite[6] = {1.0, 2.0, 0.0, 1.0, 0.0, 1.0};
  double a[3], rot[9];
  g_assert_cmpint(pw85_principal_axes(NULL, a, rot), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_principal_axes(q, NULL, rot), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_principal_axes(q, a, NULL), ==, PW85_EFAULT);
  for (int k = 0; k < 6; k++) {
    double bad[6];
    memcpy(bad, q, sizeof bad);
    bad[k] = k % 2 ? NAN : -INFINITY;
    fill(a, 3), fill(rot, 9);
    g_assert_cmpint(pw85_principal_axes(bad, a, rot), ==, PW85_EDOM);
    g_assert_true(untouched(a, 3) && untouched(rot, 9));
  }
  fill(a, 3), fill(rot, 9);
  g_assert_cmpint(pw85_principal_axes(indefinite, a, rot), ==,
                  PW85_ENOTPOSDEF);
  g_assert_true(untouched(a, 3) && untouched(rot, 9));
  /* cond(Q) = 2^950 (> about 1e270): refused; 2^850: accepted, and the
   * semi-axes of a diagonal form are the square roots of its diagonal. */
  double const flat[6] = {1.0, 0.0, 0.0, 0x1p-950, 0.0, 0x1p-950};
  g_assert_cmpint(pw85_principal_axes(flat, a, rot), ==, PW85_ERANGE);
  g_assert_true(untouched(a, 3) && untouched(rot, 9));
  double const thin[6] = {1.0, 0.0, 0.0, 0x1p-850, 0.0, 0x1p-850};
  g_assert_cmpint(pw85_principal_axes(thin, a, rot), ==, PW85_SUCCESS);
  g_assert_cmpfloat(a[0], ==, 1.0);
  g_assert_cmpfloat(a[1], ==, 0x1p-425);
  g_assert_cmpfloat(a[2], ==, 0x1p-425);
}

/* On random ellipsoids (aspect ratios to 1e8, any size): R orthonormal with
 * det +1 and the sign convention; a sorted; the residuals ‖Q·vⱼ − aⱼ²·vⱼ‖
 * within a few u·‖Q‖ (GSL's backward stability); and a round trip through
 * pw85_ellipsoid_rotation() within a few u·‖Q‖ of q. GSL accumulates its
 * eigenvectors from Givens rotations of the tridiagonal QR iterations and
 * a Householder reflection, each off by a few u: orthonormality and the
 * round trip measured 18u and 16u at worst on these 20000 cases, so both
 * are held to 32u; the residual (measured 6u) to 16u. */
static void test_axes_properties(void) {
  GRand *rng = g_rand_new_with_seed(10);
  Worst orth = worst_init("|R^T R - I| / u", 32.0);
  Worst res = worst_init("|Q v - a^2 v| / (u |Q|)", 16.0);
  Worst trip = worst_init("|rebuilt q - q| / (u |Q|)", 32.0);
  for (int k = 0; k < 20000; k++) {
    double a0[3], p[4], rot0[9], q[6], a[3], rot[9], back[6];
    random_case(rng, k % 2 ? 1e8 : 10.0, a0, p, rot0);
    if (k % 5 == 0) a0[1] = a0[0];  /* spheroids */
    g_assert_cmpint(pw85_ellipsoid_quaternion(a0, p, q), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_principal_axes(q, a, rot), ==, PW85_SUCCESS);
    g_assert_cmpfloat(a[0], >=, a[1]);
    g_assert_cmpfloat(a[1], >=, a[2]);
    g_assert_cmpfloat(a[2], >, 0.0);
    double const norm = a[0] * a[0];
    double e = 0.0;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        double g = 0.0;
        for (int m = 0; m < 3; m++) g += rot[3 * m + i] * rot[3 * m + j];
        e = fmax(e, fabs(g - (i == j)));
      }
    worst_check(&orth, (size_t)k, e, 0.0, e / U);
    double const det =
        rot[0] * (rot[4] * rot[8] - rot[5] * rot[7]) -
        rot[1] * (rot[3] * rot[8] - rot[5] * rot[6]) +
        rot[2] * (rot[3] * rot[7] - rot[4] * rot[6]);
    g_assert_cmpfloat(det, >, 0.0);
    for (int j = 0; j < 2; j++) {
      int big = 0;
      for (int i = 1; i < 3; i++)
        if (fabs(rot[3 * i + j]) > fabs(rot[3 * big + j])) big = i;
      g_assert_cmpfloat(rot[3 * big + j], >, 0.0);
    }
    double const full[3][3] = {{q[0], q[1], q[2]}, {q[1], q[3], q[4]},
                               {q[2], q[4], q[5]}};
    double worst_res = 0.0;
    for (int j = 0; j < 3; j++)
      for (int i = 0; i < 3; i++) {
        DD acc = dd_mul(dd(-a[j] * a[j]), dd(rot[3 * i + j]));
        for (int m = 0; m < 3; m++)
          acc = dd_add(acc, dd_mul(dd(full[i][m]), dd(rot[3 * m + j])));
        worst_res = fmax(worst_res, fabs(dd_to_double(acc)));
      }
    worst_check(&res, (size_t)k, worst_res, 0.0, worst_res / (U * norm));
    g_assert_cmpint(pw85_ellipsoid_rotation(a, rot, back), ==, PW85_SUCCESS);
    double t = 0.0;
    for (int m = 0; m < 6; m++) t = fmax(t, fabs(back[m] - q[m]));
    worst_check(&trip, (size_t)k, t, 0.0, t / (U * norm));
  }
  worst_report(&orth);
  worst_report(&res);
  worst_report(&trip);
  g_rand_free(rng);
}

/* pw85_principal_axes_quaternion(): the contract of pw85_principal_axes(),
 * and hand-derived cases. diag(9, 4, 1) is the identity, p = (1, 0, 0, 0)
 * exactly; diag(4, 9, 1) puts a[0] = 3 along y, a[1] = 2 along x, so R has
 * columns e_y, e_x and −e_z (det +1): the half-turn about (1, 1, 0)/√2,
 * p = (0, √½, √½, 0) (x > 0: the sign rule for w = 0). */
static void test_axes_quaternion_contract(void) {
  double const q[6] = {1.0, 0.1, 0.0, 2.0, 0.0, 0.5};
  double const indefinite[6] = {1.0, 2.0, 0.0, 1.0, 0.0, 1.0};
  double a[3], p[4];
  g_assert_cmpint(pw85_principal_axes_quaternion(NULL, a, p), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_principal_axes_quaternion(q, NULL, p), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_principal_axes_quaternion(q, a, NULL), ==, PW85_EFAULT);
  for (int k = 0; k < 6; k++) {
    double bad[6];
    memcpy(bad, q, sizeof bad);
    bad[k] = k % 2 ? NAN : INFINITY;
    fill(a, 3), fill(p, 4);
    g_assert_cmpint(pw85_principal_axes_quaternion(bad, a, p), ==, PW85_EDOM);
    g_assert_true(untouched(a, 3) && untouched(p, 4));
  }
  fill(a, 3), fill(p, 4);
  g_assert_cmpint(pw85_principal_axes_quaternion(indefinite, a, p), ==,
                  PW85_ENOTPOSDEF);
  g_assert_true(untouched(a, 3) && untouched(p, 4));

  double const d1[6] = {9.0, 0.0, 0.0, 4.0, 0.0, 1.0};
  g_assert_cmpint(pw85_principal_axes_quaternion(d1, a, p), ==, PW85_SUCCESS);
  double const a1[3] = {3.0, 2.0, 1.0}, p1[4] = {1.0, 0.0, 0.0, 0.0};
  g_assert_cmpmem(a, sizeof a, a1, sizeof a1);
  g_assert_cmpmem(p, sizeof p, p1, sizeof p1);
  double const d2[6] = {4.0, 0.0, 0.0, 9.0, 0.0, 1.0};
  g_assert_cmpint(pw85_principal_axes_quaternion(d2, a, p), ==, PW85_SUCCESS);
  g_assert_cmpmem(a, sizeof a, a1, sizeof a1);
  g_assert_cmpfloat(p[0], ==, 0.0);
  g_assert_cmpfloat(fabs(p[1] - (G_SQRT2 / 2.0)), <=, 2.0 * U);
  g_assert_cmpfloat(fabs(p[2] - (G_SQRT2 / 2.0)), <=, 2.0 * U);
  g_assert_cmpfloat(p[3], ==, 0.0);
}

/* On random ellipsoids (aspect ratios to 1e8): the semi-axes are those of
 * pw85_principal_axes(), bit for bit; w ≥ 0; ‖p‖² within 4u of 1
 * (measured; held to 8u); R(p), computed here in double-double, within
 * 11u of the rotation of pw85_principal_axes() (measured on these 20000
 * cases, GSL's R being itself orthonormal only to 18u; held to 16u); and
 * pw85_ellipsoid_quaternion(a, p) rebuilds Q within 6.6u·‖Q‖ (measured;
 * held to 16u, as the residual of test_axes_properties). The
 * batch gives every item's result bit for bit, also with stride 0. */
static void test_axes_quaternion_properties(void) {
  GRand *rng = g_rand_new_with_seed(11);
  Worst unit = worst_init("|p.p - 1| / u", 8.0);
  Worst match = worst_init("|R(p) - R| / u", 16.0);
  Worst trip = worst_init("|rebuilt q - q| / (u |Q|)", 16.0);
  enum { N = 20000 };
  static double qs[N][6], as[N][3], ps[N][4];
  for (int k = 0; k < N; k++) {
    double a0[3], p0[4], rot0[9], q[6], a[3], p[4], ar[3], rot[9], back[6];
    random_case(rng, k % 2 ? 1e8 : 10.0, a0, p0, rot0);
    g_assert_cmpint(pw85_ellipsoid_quaternion(a0, p0, q), ==, PW85_SUCCESS);
    memcpy(qs[k], q, sizeof q);
    g_assert_cmpint(pw85_principal_axes_quaternion(q, a, p), ==, PW85_SUCCESS);
    memcpy(as[k], a, sizeof a), memcpy(ps[k], p, sizeof p);
    g_assert_cmpint(pw85_principal_axes(q, ar, rot), ==, PW85_SUCCESS);
    g_assert_cmpmem(a, sizeof a, ar, sizeof ar);
    g_assert_cmpfloat(p[0], >=, 0.0);
    double const nn = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3];
    worst_check(&unit, (size_t)k, nn, 1.0, fabs(nn - 1.0) / U);
    /* R(p) = I + 2(w[u]x + [u]x^2) for unit p, in double-double. */
    DD const w = dd(p[0]), x = dd(p[1]), y = dd(p[2]), z = dd(p[3]);
    DD const two = dd(2.0), one = dd(1.0);
    DD r[9];
    r[0] = dd_sub(one, dd_mul(two, dd_add(dd_mul(y, y), dd_mul(z, z))));
    r[4] = dd_sub(one, dd_mul(two, dd_add(dd_mul(x, x), dd_mul(z, z))));
    r[8] = dd_sub(one, dd_mul(two, dd_add(dd_mul(x, x), dd_mul(y, y))));
    r[1] = dd_mul(two, dd_sub(dd_mul(x, y), dd_mul(w, z)));
    r[3] = dd_mul(two, dd_add(dd_mul(x, y), dd_mul(w, z)));
    r[2] = dd_mul(two, dd_add(dd_mul(x, z), dd_mul(w, y)));
    r[6] = dd_mul(two, dd_sub(dd_mul(x, z), dd_mul(w, y)));
    r[5] = dd_mul(two, dd_sub(dd_mul(y, z), dd_mul(w, x)));
    r[7] = dd_mul(two, dd_add(dd_mul(y, z), dd_mul(w, x)));
    double e = 0.0;
    for (int m = 0; m < 9; m++)
      e = fmax(e, fabs(dd_to_double(dd_sub(r[m], dd(rot[m])))));
    worst_check(&match, (size_t)k, e, 0.0, e / U);
    g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, back), ==, PW85_SUCCESS);
    double t = 0.0;
    for (int m = 0; m < 6; m++) t = fmax(t, fabs(back[m] - q[m]));
    worst_check(&trip, (size_t)k, t, 0.0, t / (U * a[0] * a[0]));
  }
  worst_report(&unit);
  worst_report(&match);
  worst_report(&trip);
  g_rand_free(rng);

  static double ab[N][3], pb[N][4];
  static int st[N];
  g_assert_cmpint(pw85_principal_axes_quaternion_batch(
                      N, &qs[0][0], 6, &ab[0][0], &pb[0][0], st, 2),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(ab, sizeof ab, as, sizeof as);
  g_assert_cmpmem(pb, sizeof pb, ps, sizeof ps);
  g_assert_cmpint(pw85_principal_axes_quaternion_batch(
                      3, qs[5], 0, &ab[0][0], &pb[0][0], st, 1),
                  ==, PW85_SUCCESS);
  for (int i = 0; i < 3; i++) {
    g_assert_cmpmem(ab[i], sizeof ab[i], as[5], sizeof as[5]);
    g_assert_cmpmem(pb[i], sizeof pb[i], ps[5], sizeof ps[5]);
  }
  g_assert_cmpint(pw85_principal_axes_quaternion_batch(
                      3, qs[5], 2, &ab[0][0], &pb[0][0], st, 1),
                  ==, PW85_EINVAL);
}

/* pw85_spheroid_checked(): each precondition of pw85_spheroid() refused
 * with its status and q untouched; the tolerance on ‖n‖² as for a
 * quaternion (0.8·tol passes, 1.5·tol fails); otherwise the Q of
 * pw85_spheroid(), bit for bit. */
static void test_spheroid_checked(void) {
  double const n[3] = {0.0, 0.6, 0.8};
  double q[6], ref[6];
  g_assert_cmpint(pw85_spheroid_checked(1.0, 2.0, NULL, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_spheroid_checked(1.0, 2.0, n, NULL), ==, PW85_EFAULT);
  double const bad[][2] = {{NAN, 1.0}, {1.0, INFINITY}, {0.0, 1.0},
                           {1.0, 0.0}, {-1.0, 2.0}, {1.0, -0.0},
                           {1e155, 1.0}, {1.0, 1e-160}};
  int const expected[] = {PW85_EDOM, PW85_EDOM, PW85_EINVAL, PW85_EINVAL,
                          PW85_EINVAL, PW85_EINVAL, PW85_ERANGE, PW85_ERANGE};
  for (size_t k = 0; k < G_N_ELEMENTS(expected); k++) {
    fill(q, 6);
    g_assert_cmpint(pw85_spheroid_checked(bad[k][0], bad[k][1], n, q), ==,
                    expected[k]);
    g_assert_true(untouched(q, 6));
  }
  double const nan_axis[3] = {0.0, NAN, 1.0}, zero_axis[3] = {0.0, 0.0, 0.0};
  fill(q, 6);
  g_assert_cmpint(pw85_spheroid_checked(1.0, 2.0, nan_axis, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_spheroid_checked(1.0, 2.0, zero_axis, q), ==,
                  PW85_EINVAL);
  g_assert_true(untouched(q, 6));
  double const factors[4] = {0.8, -0.8, 1.5, -1.5};
  for (int k = 0; k < 4; k++) {
    double const f = sqrt(1.0 + factors[k] * PW85_UNIT_TOL);
    double const nk[3] = {n[0] * f, n[1] * f, n[2] * f};
    fill(q, 6);
    g_assert_cmpint(pw85_spheroid_checked(1.0, 2.0, nk, q), ==,
                    k < 2 ? PW85_SUCCESS : PW85_EINVAL);
    if (k < 2) {
      pw85_spheroid(1.0, 2.0, nk, ref);
      g_assert_cmpmem(q, sizeof q, ref, sizeof ref);
    } else {
      g_assert_true(untouched(q, 6));
    }
  }
  g_assert_cmpint(pw85_spheroid_checked(10.0, 0.1, n, q), ==, PW85_SUCCESS);
  pw85_spheroid(10.0, 0.1, n, ref);
  g_assert_cmpmem(q, sizeof q, ref, sizeof ref);
}

/* A rotation with a tiny entry (fuzz-2d's constructor underflow, in 3D):
 * R = [[1, −t, 0], [t, 1, 0], [0, 0, 1]], t = −1.8·2^-656 (orthonormal to
 * t² = 2^-1311), a = (2^-495, 2^433, 1). Q00 = a0² + t²·a1² = 1.808e-134;
 * R01·R01 underflowed before it met a1², and Q00 came out as a0² =
 * 2^-990. References: mpmath at 60 digits of the same exact R, rounded
 * once. */
static void test_rotation_underflow(void) {
  double const t = -0x1.d00000020f008p-656;
  double const a[3] = {0x1.0820003f53f01p-495, 0x1.0000003ff0025p+433, 1.};
  double const rot[9] = {1., -t, 0., t, 1., 0., 0., 0., 1.};
  double const ref[6] = {0x1.a48000d5c6a8ap-445, 0x1.d00000e9d5090p+210, 0.,
                         0x1.0000007fe004bp+866, 0., 1.};
  double q[6];
  g_assert_cmpint(pw85_ellipsoid_rotation(a, rot, q), ==, PW85_SUCCESS);
  for (int k = 0; k < 6; k++) g_assert_cmpfloat(q[k], ==, ref[k]);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/ellipsoid/contract", test_contract);
  g_test_add_func("/pw85/ellipsoid/rotation-underflow",
                  test_rotation_underflow);
  g_test_add_func("/pw85/ellipsoid/unit-tolerance", test_unit_tolerance);
  g_test_add_func("/pw85/ellipsoid/hand-derived", test_hand_derived);
  g_test_add_func("/pw85/ellipsoid/rotation-bound", test_rotation_bound);
  g_test_add_func("/pw85/ellipsoid/quaternion-matches-rotation",
                  test_quaternion_matches_rotation);
  g_test_add_func("/pw85/principal-axes/contract", test_axes_contract);
  g_test_add_func("/pw85/principal-axes/diagonal", test_axes_diagonal);
  g_test_add_func("/pw85/principal-axes/properties", test_axes_properties);
  g_test_add_func("/pw85/principal-axes-quaternion/contract",
                  test_axes_quaternion_contract);
  g_test_add_func("/pw85/principal-axes-quaternion/properties",
                  test_axes_quaternion_properties);
  g_test_add_func("/pw85/spheroid-checked/contract", test_spheroid_checked);
  return g_test_run();
}
