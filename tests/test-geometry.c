/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_contact_geometry() and pw85_contact_derivatives(): the input
 * contract, r12 = 0, agreement with pw85_contact_function(), the identities
 * of docs/theory.rst (eqs. (3.8), (3.9a)–(3.9b), (3.14a)–(3.14b)) checked in
 * double-double, the swapping symmetry, and finite differences of μ².
 * The comparison with independent references at high precision is
 * test-geometry-refs.c. */
#include <float.h>
#include <glib.h>
#include <math.h>
#include <string.h>

#include "ddref.h"
#include "pw85.h"
#include "testutil.h"
#include "worst.h"

#define U (DBL_EPSILON / 2.0)

/* ---- Random pairs: triaxial ellipsoids, aspect ratios to max_aspect,
 * sizes within a factor 10, μ² spread over [1e-2, 1e2]. */
typedef struct {
  double r[3], q1[6], q2[6];
  double cond1, cond2;
} Pair;

static void random_axes(GRand *rng, double max_aspect, double e[3],
                        double *cond) {
  double const size = pow(10.0, g_rand_double_range(rng, -0.5, 0.5));
  double lo = 1.0, hi = 1.0;
  for (int i = 0; i < 3; i++) {
    double const a = size * pow(max_aspect, -g_rand_double(rng));
    e[i] = a * a;
    lo = fmin(lo, e[i] / (size * size));
    hi = fmax(hi, e[i] / (size * size));
  }
  *cond = hi / lo;
}

static void random_pair(GRand *rng, double max_aspect, Pair *p) {
  double e1[3], e2[3];
  random_axes(rng, max_aspect, e1, &p->cond1);
  random_axes(rng, max_aspect, e2, &p->cond2);
  random_form_with_eigenvalues(rng, e1, p->q1);
  random_form_with_eigenvalues(rng, e2, p->q2);
  double n = 0.0;
  for (int i = 0; i < 3; i++) {
    p->r[i] = g_rand_double_range(rng, -1.0, 1.0);
    n += p->r[i] * p->r[i];
  }
  /* Scale r so that μ² lands near a random target (μ² ∝ |r|²). */
  double out[2];
  g_assert_cmpint(pw85_contact_function(p->r, p->q1, p->q2, out), ==,
                  PW85_SUCCESS);
  double const target = pow(10.0, g_rand_double_range(rng, -2.0, 2.0));
  double const t = sqrt(target / out[0]);
  for (int i = 0; i < 3; i++) p->r[i] *= t;
}

/* ---- Double-double helpers for the identities. */

/* x = A⁻¹·b for symmetric positive definite A (storage of pw85.h), by
 * L·D·Lᵀ in double-double: exact enough (relative error about
 * cond(A)·2⁻¹⁰⁴) for the identities below. */
static void dd_solve(double const a[6], DD const b[3], DD x[3]) {
  DD const a00 = dd(a[0]), a01 = dd(a[1]), a02 = dd(a[2]);
  DD const l10 = dd_div(a01, a00), l20 = dd_div(a02, a00);
  DD const d1 = dd_sub(dd(a[3]), dd_mul(l10, a01));
  DD const e = dd_sub(dd(a[4]), dd_mul(l10, a02));
  DD const l21 = dd_div(e, d1);
  DD const d2 = dd_sub(dd_sub(dd(a[5]), dd_mul(l20, a02)), dd_mul(l21, e));
  DD const z0 = b[0];
  DD const z1 = dd_sub(b[1], dd_mul(l10, z0));
  DD const z2 = dd_sub(dd_sub(b[2], dd_mul(l20, z0)), dd_mul(l21, z1));
  x[2] = dd_div(z2, d2);
  x[1] = dd_sub(dd_div(z1, d1), dd_mul(l21, x[2]));
  x[0] = dd_sub(dd_sub(dd_div(z0, a00), dd_mul(l10, x[1])),
                dd_mul(l20, x[2]));
}

static DD dd_dot(DD const x[3], DD const y[3]) {
  return dd_add(dd_add(dd_mul(x[0], y[0]), dd_mul(x[1], y[1])),
                dd_mul(x[2], y[2]));
}

/* |x × y|/(|x|·|y|): the sine of the angle between x and y. */
static double sine(DD const x[3], double const y[3]) {
  double xs[3], c[3];
  for (int i = 0; i < 3; i++) xs[i] = dd_to_double(x[i]);
  c[0] = xs[1] * y[2] - xs[2] * y[1];
  c[1] = xs[2] * y[0] - xs[0] * y[2];
  c[2] = xs[0] * y[1] - xs[1] * y[0];
  double const nx = sqrt(xs[0] * xs[0] + xs[1] * xs[1] + xs[2] * xs[2]);
  double const ny = sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
  return sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / (nx * ny);
}

/* ---- The input contract: the statuses of pw85_contact_function(), and
 * outputs untouched on error. */

static gboolean untouched(double const *x, size_t n) {
  for (size_t i = 0; i < n; i++)
    if (x[i] != -7.0) return FALSE;
  return TRUE;
}

static int both(double const *r, double const *q1, double const *q2,
                gboolean *kept) {
  double g[PW85_GEOM_SIZE], g2[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  for (int i = 0; i < PW85_GEOM_SIZE; i++) g[i] = g2[i] = -7.0;
  for (int i = 0; i < PW85_DERIV_SIZE; i++) d[i] = -7.0;
  int const s1 = pw85_contact_geometry(r, q1, q2, g);
  int const s2 = pw85_contact_derivatives(r, q1, q2, g2, d);
  g_assert_cmpint(s1, ==, s2);
  *kept = untouched(g, PW85_GEOM_SIZE) && untouched(g2, PW85_GEOM_SIZE) &&
          untouched(d, PW85_DERIV_SIZE);
  return s1;
}

static void test_contract(void) {
  double const r[3] = {1.0, 0.5, -0.25};
  double const q[6] = {1.0, 0.1, 0.0, 2.0, 0.0, 0.5};
  double const indefinite[6] = {1.0, 2.0, 0.0, 1.0, 0.0, 1.0};
  double const tiny[6] = {1e-320, 0.0, 0.0, 1e-320, 0.0, 1e-320};
  double const huge[6] = {1e308, 0.0, 0.0, 1e308, 0.0, 1e308};
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  gboolean kept = FALSE;
  g_assert_cmpint(pw85_contact_geometry(NULL, q, q, g), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_contact_geometry(r, NULL, q, g), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_contact_geometry(r, q, NULL, g), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_contact_geometry(r, q, q, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_contact_derivatives(r, q, q, NULL, d), ==,
                  PW85_EFAULT);
  for (int i = 0; i < PW85_GEOM_SIZE; i++) g[i] = -7.0;
  g_assert_cmpint(pw85_contact_derivatives(r, q, q, g, NULL), ==,
                  PW85_EFAULT);
  g_assert_true(untouched(g, PW85_GEOM_SIZE));
  for (int k = 0; k < 15; k++) {
    double v[15];
    memcpy(v, r, sizeof r);
    memcpy(v + 3, q, sizeof q);
    memcpy(v + 9, q, sizeof q);
    v[k] = k % 2 ? NAN : -INFINITY;
    g_assert_cmpint(both(v, v + 3, v + 9, &kept), ==, PW85_EDOM);
    g_assert_true(kept);
  }
  g_assert_cmpint(both(r, indefinite, q, &kept), ==, PW85_ENOTPOSDEF);
  g_assert_true(kept);
  g_assert_cmpint(both(r, q, indefinite, &kept), ==, PW85_ENOTPOSDEF);
  g_assert_true(kept);
  /* Diagonals spanning 1e628: beyond the range of a double (2^2048). */
  g_assert_cmpint(both(r, tiny, huge, &kept), ==, PW85_ERANGE);
  g_assert_true(kept);
}

/* r12 = 0: μ² = 0, λ = ½, x = c1, n = 0, every derivative 0. */
static void test_zero_r12(void) {
  double const r[3] = {0.0, -0.0, 0.0};
  double const q1[6] = {1.0, 0.1, 0.0, 2.0, 0.0, 0.5};
  double const q2[6] = {3.0, 0.0, 0.2, 1.0, 0.0, 0.5};
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  g_assert_cmpint(pw85_contact_derivatives(r, q1, q2, g, d), ==,
                  PW85_SUCCESS);
  g_assert_cmpfloat(g[PW85_GEOM_MU2], ==, 0.0);
  g_assert_cmpfloat(g[PW85_GEOM_LAMBDA], ==, 0.5);
  for (int i = 0; i < 6; i++) g_assert_cmpfloat(g[PW85_GEOM_POINT + i], ==, 0.0);
  for (int i = 0; i < PW85_DERIV_SIZE; i++) g_assert_cmpfloat(d[i], ==, 0.0);
}

/* Two spheres of radii ρ1 = 1, ρ2 = 3, r = (0, 0, 8), by hand: μ = |r|/(ρ1
 * + ρ2) = 2, λ = ρ1/(ρ1 + ρ2) = ¼, Q(λ) = 3·I, s = r/3; x − c1 = (0, 0, 2)
 * divides the segment in the ratio of the radii; n = (0, 0, 1);
 * ∂μ²/∂r = 2r/(ρ1 + ρ2)² = (0, 0, 1); no torque. Stretching sphere i
 * along r, q[5] → ρᵢ² + δ, moves ρᵢ by δ/(2ρᵢ) along the line of centres,
 * and μ² = |r|²/(ρ1 + ρ2)² by −2·δ/(2ρᵢ): ∂μ²/∂q1[5] = −1,
 * ∂μ²/∂q2[5] = −1/3, the other entries 0 (first order). */
static void test_spheres(void) {
  double const r[3] = {0.0, 0.0, 8.0};
  double const q1[6] = {1.0, 0.0, 0.0, 1.0, 0.0, 1.0};
  double const q2[6] = {9.0, 0.0, 0.0, 9.0, 0.0, 9.0};
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  g_assert_cmpint(pw85_contact_derivatives(r, q1, q2, g, d), ==,
                  PW85_SUCCESS);
  double const expected_g[8] = {4.0, 0.25, 0.0, 0.0, 2.0, 0.0, 0.0, 1.0};
  double expected_d[21] = {0.0};
  expected_d[PW85_DERIV_R12 + 2] = 1.0;
  expected_d[PW85_DERIV_Q1 + 5] = -1.0;
  expected_d[PW85_DERIV_Q2 + 5] = -1.0 / 3.0;
  for (int i = 0; i < 8; i++)
    g_assert_true(fabs(g[i] - expected_g[i]) <= 4 * U * fabs(expected_g[i]));
  for (int i = 0; i < 21; i++)
    g_assert_true(fabs(d[i] - expected_d[i]) <= 4 * U * fabs(expected_d[i]));
}

/* μ² is that of pw85_contact_function(), bit for bit; λ within its
 * documented accuracy of it; pw85_contact_geometry() and the geometry of
 * pw85_contact_derivatives() agree bit for bit. */
static void test_same_search(void) {
  GRand *rng = g_rand_new_with_seed(15);
  for (int k = 0; k < 2000; k++) {
    Pair p;
    random_pair(rng, k % 2 ? 1e6 : 10.0, &p);
    double out[2], g[PW85_GEOM_SIZE], g2[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
    g_assert_cmpint(pw85_contact_function(p.r, p.q1, p.q2, out), ==, 0);
    g_assert_cmpint(pw85_contact_geometry(p.r, p.q1, p.q2, g), ==, 0);
    g_assert_cmpint(pw85_contact_derivatives(p.r, p.q1, p.q2, g2, d), ==, 0);
    g_assert_cmpmem(g, sizeof g, g2, sizeof g2);
    g_assert_cmpfloat(g[PW85_GEOM_MU2], ==, out[0]);
    double const lambda = out[1];
    g_assert_cmpfloat(fabs(g[PW85_GEOM_LAMBDA] - lambda), <=,
                      1e-10 * fmin(lambda, 1.0 - lambda));
  }
  g_rand_free(rng);
}

/* The identities, in double-double, on random pairs with aspect ratios
 * to 1e4 (cond(Qᵢ) to 1e8):
 * - x on both scaled ellipsoids (eqs. (14a)–(14b)):
 *   (x − c1)ᵀ·Q1⁻¹·(x − c1) = μ² = (x − c2)ᵀ·Q2⁻¹·(x − c2);
 * - the normal along Q1⁻¹·(x − c1) and along −Q2⁻¹·(x − c2) (eq. (8)).
 * The point and the normal are off by a few u relative (measured on the
 * references, test-geometry-refs.c). An error δ of x moves
 * (x − c)ᵀQ⁻¹(x − c) by at most 2·|δ|·√cond(Qᵢ)/|x − c| relative (the error
 * is measured in the norm of Qᵢ⁻¹), and turns Qᵢ⁻¹(x − c) by up to
 * cond(Qᵢ)·|δ|/|x − c|: tolerances 8·u·(1 + √cond(Qᵢ)) and
 * 8·u·(1 + cond(Qᵢ)), against measured worsts of 1 and 0.41. */
static void test_identities(void) {
  GRand *rng = g_rand_new_with_seed(1985);
  Worst on1 = worst_init("on scaled ellipsoid 1 / (u(1 + sqrt cond1))", 8.0);
  Worst on2 = worst_init("on scaled ellipsoid 2 / (u(1 + sqrt cond2))", 8.0);
  Worst par1 = worst_init("sin(n, Q1^-1 (x - c1)) / (u(1 + cond1))", 8.0);
  Worst par2 = worst_init("sin(n, -Q2^-1 (x - c2)) / (u(1 + cond2))", 8.0);
  for (int k = 0; k < 3000; k++) {
    Pair p;
    random_pair(rng, 1e4, &p);
    double g[PW85_GEOM_SIZE];
    g_assert_cmpint(pw85_contact_geometry(p.r, p.q1, p.q2, g), ==, 0);
    double const mu2 = g[PW85_GEOM_MU2];
    double const *x = g + PW85_GEOM_POINT, *n = g + PW85_GEOM_NORMAL;
    DD x1[3], x2[3], y1[3], y2[3];
    for (int i = 0; i < 3; i++) {
      x1[i] = dd(x[i]);
      x2[i] = dd_sub(dd(x[i]), dd(p.r[i]));
    }
    dd_solve(p.q1, x1, y1);
    dd_solve(p.q2, x2, y2);
    double const c1 = 1.0 + sqrt(p.cond1), c2 = 1.0 + sqrt(p.cond2);
    double const e1 = fabs(dd_to_double(dd_dot(x1, y1)) / mu2 - 1.0);
    double const e2 = fabs(dd_to_double(dd_dot(x2, y2)) / mu2 - 1.0);
    worst_check(&on1, (size_t)k, e1, 0.0, e1 / (U * c1));
    worst_check(&on2, (size_t)k, e2, 0.0, e2 / (U * c2));
    double const s1 = sine(y1, n), s2 = sine(y2, n);
    worst_check(&par1, (size_t)k, s1, 0.0, s1 / (U * (1.0 + p.cond1)));
    worst_check(&par2, (size_t)k, s2, 0.0, s2 / (U * (1.0 + p.cond2)));
    /* Directions: n·Q1⁻¹(x − c1) > 0 > n·Q2⁻¹(x − c2). */
    double d1 = 0.0, d2 = 0.0;
    for (int i = 0; i < 3; i++) {
      d1 += n[i] * dd_to_double(y1[i]);
      d2 += n[i] * dd_to_double(y2[i]);
    }
    g_assert_cmpfloat(d1, >, 0.0);
    g_assert_cmpfloat(d2, <, 0.0);
  }
  worst_report(&on1);
  worst_report(&on2);
  worst_report(&par1);
  worst_report(&par2);
  g_rand_free(rng);
}

/* Swapping the ellipsoids, (r12, q1, q2) → (−r12, q2, q1): μ² and the
 * derivatives exchanged or negated bit for bit, λ → 1 − λ, n → −n, and
 * x − c2 = (x − c1) − r12 to a few ulps of the larger. */
static void test_swap(void) {
  GRand *rng = g_rand_new_with_seed(2);
  Worst point = worst_init("swapped point / (u max(|x - c1|, |r12|))", 8.0);
  for (int k = 0; k < 2000; k++) {
    Pair p;
    random_pair(rng, k % 2 ? 1e6 : 30.0, &p);
    double const mr[3] = {-p.r[0], -p.r[1], -p.r[2]};
    double ga[PW85_GEOM_SIZE], gb[PW85_GEOM_SIZE];
    double da[PW85_DERIV_SIZE], db[PW85_DERIV_SIZE];
    g_assert_cmpint(pw85_contact_derivatives(p.r, p.q1, p.q2, ga, da), ==, 0);
    g_assert_cmpint(pw85_contact_derivatives(mr, p.q2, p.q1, gb, db), ==, 0);
    g_assert_cmpfloat(ga[PW85_GEOM_MU2], ==, gb[PW85_GEOM_MU2]);
    double const la = ga[PW85_GEOM_LAMBDA], lb = gb[PW85_GEOM_LAMBDA];
    g_assert_true(la == 1.0 - lb || lb == 1.0 - la);
    for (int i = 0; i < 3; i++) {
      g_assert_cmpfloat(ga[PW85_GEOM_NORMAL + i], ==,
                        -gb[PW85_GEOM_NORMAL + i]);
      g_assert_cmpfloat(da[PW85_DERIV_R12 + i], ==, -db[PW85_DERIV_R12 + i]);
      g_assert_cmpfloat(da[PW85_DERIV_ROT1 + i], ==, db[PW85_DERIV_ROT2 + i]);
      g_assert_cmpfloat(da[PW85_DERIV_ROT2 + i], ==, db[PW85_DERIV_ROT1 + i]);
    }
    for (int i = 0; i < 6; i++) {
      g_assert_cmpfloat(da[PW85_DERIV_Q1 + i], ==, db[PW85_DERIV_Q2 + i]);
      g_assert_cmpfloat(da[PW85_DERIV_Q2 + i], ==, db[PW85_DERIV_Q1 + i]);
    }
    double scale = 0.0, err = 0.0;
    for (int i = 0; i < 3; i++) {
      scale = fmax(scale, fmax(fabs(ga[PW85_GEOM_POINT + i]), fabs(p.r[i])));
      err = fmax(err, fabs(gb[PW85_GEOM_POINT + i] -
                           (ga[PW85_GEOM_POINT + i] - p.r[i])));
    }
    worst_check(&point, (size_t)k, err, 0.0, err / (U * scale));
  }
  worst_report(&point);
  g_rand_free(rng);
}

/* Rotation of q by the rotation vector w (Rodrigues' formula): R·Q·Rᵀ. */
static void rotate(double const q[6], double const w[3], double out[6]) {
  double const t = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  double const k[3] = {w[0] / t, w[1] / t, w[2] / t};
  double const c = cos(t), s = sin(t);
  double r[3][3];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) r[i][j] = (1.0 - c) * k[i] * k[j];
  for (int i = 0; i < 3; i++) r[i][i] += c;
  r[0][1] -= s * k[2], r[1][0] += s * k[2];
  r[0][2] += s * k[1], r[2][0] -= s * k[1];
  r[1][2] -= s * k[0], r[2][1] += s * k[0];
  double const full[3][3] = {{q[0], q[1], q[2]}, {q[1], q[3], q[4]},
                             {q[2], q[4], q[5]}};
  int m = 0;
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++, m++) {
      double v = 0.0;
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) v += r[i][a] * full[a][b] * r[j][b];
      out[m] = v;
    }
}

static double mu2_of(double const r[3], double const q1[6],
                     double const q2[6]) {
  double out[2];
  g_assert_cmpint(pw85_contact_function(r, q1, q2, out), ==, 0);
  return out[0];
}

/* Central differences of the (correctly rounded) μ² of
 * pw85_contact_function(), step h relative: error about u/h + h² ≈ 1e-10
 * relative for h = 1e-5 on these moderate pairs (aspect ratios to 10);
 * compared in the norm of each derivative with tolerance 1e-7. An
 * independent check of every formula and of the layout; the
 * extended-precision check is tests/python/test_geometry.py. */
static void test_finite_differences(void) {
  GRand *rng = g_rand_new_with_seed(7);
  Worst w = worst_init("finite differences (relative, in norm)", 1e-7);
  for (int k = 0; k < 200; k++) {
    Pair p;
    random_pair(rng, 10.0, &p);
    double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE], fd[PW85_DERIV_SIZE];
    g_assert_cmpint(pw85_contact_derivatives(p.r, p.q1, p.q2, g, d), ==, 0);
    double const h = 1e-5;
    double const rn = sqrt(p.r[0] * p.r[0] + p.r[1] * p.r[1] + p.r[2] * p.r[2]);
    for (int i = 0; i < 3; i++) {
      double rp[3], rm[3];
      memcpy(rp, p.r, sizeof rp), memcpy(rm, p.r, sizeof rm);
      rp[i] += h * rn, rm[i] -= h * rn;
      fd[PW85_DERIV_R12 + i] =
          (mu2_of(rp, p.q1, p.q2) - mu2_of(rm, p.q1, p.q2)) / (2 * h * rn);
      double wv[3] = {0.0, 0.0, 0.0}, qp[6], qm[6];
      wv[i] = h;
      rotate(p.q1, wv, qp);
      wv[i] = -h;
      rotate(p.q1, wv, qm);
      fd[PW85_DERIV_ROT1 + i] =
          (mu2_of(p.r, qp, p.q2) - mu2_of(p.r, qm, p.q2)) / (2 * h);
      rotate(p.q2, wv, qm);
      wv[i] = h;
      rotate(p.q2, wv, qp);
      fd[PW85_DERIV_ROT2 + i] =
          (mu2_of(p.r, p.q1, qp) - mu2_of(p.r, p.q1, qm)) / (2 * h);
    }
    /* Entry (i, j) moved by h·√(Q_ii·Q_jj), its natural scale. */
    int const row[6] = {0, 0, 0, 1, 1, 2}, col[6] = {0, 1, 2, 1, 2, 2};
    int const diag[3] = {0, 3, 5};
    for (int m = 0; m < 6; m++) {
      double qp[6], qm[6];
      double const hq = h * sqrt(p.q1[diag[row[m]]] * p.q1[diag[col[m]]]);
      memcpy(qp, p.q1, sizeof qp), memcpy(qm, p.q1, sizeof qm);
      qp[m] += hq, qm[m] -= hq;
      fd[PW85_DERIV_Q1 + m] =
          (mu2_of(p.r, qp, p.q2) - mu2_of(p.r, qm, p.q2)) / (2 * hq);
      double const hq2 = h * sqrt(p.q2[diag[row[m]]] * p.q2[diag[col[m]]]);
      memcpy(qp, p.q2, sizeof qp), memcpy(qm, p.q2, sizeof qm);
      qp[m] += hq2, qm[m] -= hq2;
      fd[PW85_DERIV_Q2 + m] =
          (mu2_of(p.r, p.q1, qp) - mu2_of(p.r, p.q1, qm)) / (2 * hq2);
    }
    int const start[5] = {0, 3, 6, 9, 15}, len[5] = {3, 3, 3, 6, 6};
    for (int b = 0; b < 5; b++) {
      double diff = 0.0, norm = 0.0;
      for (int i = start[b]; i < start[b] + len[b]; i++) {
        diff += (d[i] - fd[i]) * (d[i] - fd[i]);
        norm += d[i] * d[i];
      }
      /* The torques vanish for some pairs: measured against the scale
       * of ∂μ²/∂r12 times |r12| (the lever arms are at most |r12|-ish). */
      double scale = sqrt(norm);
      if (b == 1 || b == 2)
        scale = fmax(scale, rn * sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      double const e = sqrt(diff) / scale;
      worst_check(&w, (size_t)(5 * k + b), d[start[b]], fd[start[b]], e);
    }
  }
  worst_report(&w);
  g_rand_free(rng);
}

/* μ² beyond DBL_MAX: PW85_ERANGE, every output written, μ² = +∞. */
static void test_overflow(void) {
  double const r[3] = {1e200, 0.0, 0.0};
  double const q[6] = {1e-200, 0.0, 0.0, 1e-200, 0.0, 1e-200};
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  g_assert_cmpint(pw85_contact_derivatives(r, q, q, g, d), ==, PW85_ERANGE);
  g_assert_true(isinf(g[PW85_GEOM_MU2]));
  g_assert_cmpfloat(g[PW85_GEOM_LAMBDA], ==, 0.5);
  g_assert_cmpfloat(g[PW85_GEOM_POINT], ==, 5e199);
  g_assert_cmpfloat(g[PW85_GEOM_NORMAL], ==, 1.0);
  g_assert_true(isinf(d[PW85_DERIV_R12]));
  g_assert_cmpint(pw85_contact_geometry(r, q, q, g), ==, PW85_ERANGE);
  /* Far from overflow at another scale: the same pair scaled. */
  double const r2[3] = {1e100, 0.0, 0.0};
  double const q2[6] = {1e198, 0.0, 0.0, 1e198, 0.0, 1e198};
  g_assert_cmpint(pw85_contact_derivatives(r2, q2, q2, g, d), ==, 0);
  g_assert_cmpfloat(fabs(g[PW85_GEOM_MU2] - 25.0), <=, 25.0 * 4 * U);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/geometry/contract", test_contract);
  g_test_add_func("/pw85/geometry/zero-r12", test_zero_r12);
  g_test_add_func("/pw85/geometry/spheres", test_spheres);
  g_test_add_func("/pw85/geometry/same-search", test_same_search);
  g_test_add_func("/pw85/geometry/identities", test_identities);
  g_test_add_func("/pw85/geometry/swap", test_swap);
  g_test_add_func("/pw85/geometry/finite-differences", test_finite_differences);
  g_test_add_func("/pw85/geometry/overflow", test_overflow);
  return g_test_run();
}
