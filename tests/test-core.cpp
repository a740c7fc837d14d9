// SPDX-License-Identifier: BSD-3-Clause
// Kernels of the core that the public API does not expose on their own,
// tested through the core's static library: the factorisations of Q(λ),
// the bracket given to GSL's Brent minimiser, the start of the search of
// ellipses, and the spatial index's inscribed radius and bulk insertion.
#include <glib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "brent_certify.hpp"
#include "index/deep.hpp"
#include "index/index.hpp"
#include "ldl.hpp"
#include "pw85.h"
#include "problem.hpp"
#include "pw85_2d.h"
#include "testutil.h"
#include "warm_start.hpp"

namespace {

using Ldl = pw85::detail::Ldl<3>;

// A random symmetric positive definite form R·diag(e)·Rᵀ (R from a random
// unit quaternion), eigenvalues 10^[-4, 4] times 2^[-300, 300]: condition
// numbers to 1e8, diagonal inside the range of ldl_decomp_fast().
void random_form(GRand *rng, double q[PW85_SYM]) {
  double const scale = std::ldexp(1., g_rand_int_range(rng, -300, 301));
  double e[3];
  for (double &ei : e) ei = scale * std::pow(10., g_rand_double_range(rng, -4., 4.));
  random_form_with_eigenvalues(rng, e, q);
}

// max over entries of |Q − L·D·Lᵀ| / (|L|·|D|·|Lᵀ|), in long double, with
// dᵢ = 1/(1/dᵢ) as stored.
double backward_error(double const q[PW85_SYM], Ldl const &f) {
  long double const l[3][3] = {{1.0L, 0.0L, 0.0L},
                               {f.l10, 1.0L, 0.0L},
                               {f.l20, f.l21, 1.0L}};
  long double d[3];
  for (int i = 0; i < 3; i++) d[i] = 1.0L / f.inv_d[i];
  double worst = 0.0;
  int k = 0;
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++, k++) {
      long double sum = 0.0L, size = 0.0L;
      for (int m = 0; m < 3; m++) {
        sum += l[i][m] * d[m] * l[j][m];
        size += std::fabs(l[i][m] * d[m] * l[j][m]);
      }
      worst = std::fmax(worst, double(std::fabs(sum - q[k]) / size));
    }
  return worst;
}

// Both factorisations are backward stable, |Q − LDLᵀ| ≤ c·ε·|L||D||Lᵀ|
// entrywise with c = 4 for a 3×3 form (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., Theorem 10.3, γ(n+1) with u = ε/2), and the
// reciprocal pivots they store add one rounding: 5ε is the bound checked.
void test_ldl_backward_error() {
  GRand *rng = g_rand_new_with_seed(1985);
  double worst[2] = {0.0, 0.0};
  for (int n = 0; n < 100000; n++) {
    double q[PW85_SYM];
    random_form(rng, q);
    Ldl f;
    g_assert_true(pw85::detail::ldl_decomp(q, &f));
    worst[0] = std::fmax(worst[0], backward_error(q, f));
    g_assert_true(pw85::detail::ldl_decomp_fast(q, &f));
    worst[1] = std::fmax(worst[1], backward_error(q, f));
  }
  g_test_message("worst backward error / eps: ldl_decomp %.2f, "
                 "ldl_decomp_fast %.2f",
                 worst[0] / DBL_EPSILON, worst[1] / DBL_EPSILON);
  g_assert_cmpfloat(worst[0], <=, 5.0 * DBL_EPSILON);
  g_assert_cmpfloat(worst[1], <=, 5.0 * DBL_EPSILON);
  g_rand_free(rng);
}

// The bracket of golden_bracket() makes GSL's Brent minimiser (the library
// installed, not a copy of its formula) evaluate first at the centre.
struct FirstCall {
  double centre;
  double first;
  int calls;
};

double parabola(double x, void *params) {
  auto *rec = static_cast<FirstCall *>(params);
  if (rec->calls++ == 0) rec->first = x;
  return (x - rec->centre) * (x - rec->centre);
}

void test_golden_bracket() {
  GRand *rng = g_rand_new_with_seed(2026);
  gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  g_assert_nonnull(s);
  int checked = 0, at_centre = 0;
  for (int n = 0; n < 100000; n++) {
    // Centres from 1e-5 to 1 − 1e-5, log-uniform towards both ends; the
    // widths certify_with_brent() tries.
    double const t = 0.5 * std::pow(10., g_rand_double_range(rng, -5., 0.));
    double const c = g_rand_boolean(rng) ? t : 1.0 - t;
    double const w = 0.98e-6 * std::ldexp(1., 4 * g_rand_int_range(rng, 0, 5));
    double a = 0.0, b = 0.0;
    pw85::detail::golden_bracket(c, w, &a, &b);
    if (!(a > 0.0 && b < 1.0)) continue;  // not used: certify_with_brent()
    g_assert_cmpfloat(a, <, c);
    g_assert_cmpfloat(c, <, b);
    g_assert_cmpfloat(std::fabs((b - a) - w), <=, 1e-6 * w);
    FirstCall rec{c, 0.0, 0};
    gsl_function fn{&parabola, &rec};
    double const fa = (a - c) * (a - c), fb = (b - c) * (b - c);
    g_assert_cmpint(gsl_min_fminimizer_set_with_values(s, &fn, c, 0.0, a, fa,
                                                       b, fb),
                    ==, GSL_SUCCESS);
    g_assert_cmpint(rec.calls, ==, 1);
    checked++;
    if (rec.first == c) at_centre++;
  }
  g_test_message("%d of %d brackets: GSL's first point is the centre",
                 at_centre, checked);
  g_assert_cmpint(checked, >, 60000);  // the widest brackets often leave (0, 1)
  g_assert_cmpint(at_centre, ==, checked);
  gsl_min_fminimizer_free(s);
  g_rand_free(rng);
}

// inscribed_radius(q): ρ² < λmin(Q) always (the certificate), and close
// to it for well-conditioned forms. Forms whose eigenvalues are exact:
// diagonal ones, the block [[a, b], [b, a]] (a ± b) beside c, and
// a·I + b·(J − I) (a + 2b, a − b twice), with small integers a, b, c
// times a power of two, in every arrangement of the axes, down to
// λmin/λmax = 2⁻⁴⁵; then random rotations of known spectra.
void check_radius(double const q[PW85_SYM], double lmin, double lmax,
                  int *tight) {
  double const rho = pw85::detail::inscribed_radius(q);
  g_assert_cmpfloat(rho, >=, 0.0);
  // ρ² − λmin with one rounding (fma): its sign is exact.
  if (rho > 0.0 && !(std::fma(rho, rho, -lmin) < 0.0))
    g_error("ρ = %.17g, λmin = %.17g: ρ² ≥ λmin", rho, lmin);
  if (lmax <= 1e4 * lmin) {
    // The Frobenius bound at worst: λmin(Q) ≥ 1/‖Q⁻¹‖_F ≥ λmin/√3.
    g_assert_cmpfloat(rho * rho, >=, lmin / std::sqrt(3.0) * (1.0 - 0x1p-9));
    if (rho * rho >= lmin * (1.0 - 0x1p-15)) ++*tight;
  }
}

// inscribed_radius<2>(q) of an ellipse: as check_radius(), on forms whose
// eigenvalues are exact (diagonal ones; [[a, b], [b, a]], eigenvalues
// a ± b, a and b small integers times a power of two, to
// λmin/λmax = 2⁻⁴⁵), then on rounded rotations R·diag(e)·Rᵀ.
void check_radius_2d(double const q[3], double lmin, double lmax, int *tight) {
  double const rho = pw85::detail::inscribed_radius<2>(q);
  g_assert_cmpfloat(rho, >=, 0.0);
  if (rho > 0.0 && !(std::fma(rho, rho, -lmin) < 0.0))
    g_error("2D: ρ = %.17g, λmin = %.17g: ρ² ≥ λmin", rho, lmin);
  if (lmax <= 1e4 * lmin) {
    // The Frobenius bound at worst: λmin(Q) ≥ 1/‖Q⁻¹‖_F ≥ λmin/√2.
    g_assert_cmpfloat(rho * rho, >=, lmin / std::sqrt(2.0) * (1.0 - 0x1p-9));
    if (rho * rho >= lmin * (1.0 - 0x1p-15)) ++*tight;
  }
}

void test_inscribed_radius_2d() {
  GRand *rng = g_rand_new_with_seed(2029);
  int tight = 0, moderate = 0;
  for (int n = 0; n < 20000; n++) {
    double const scale = std::ldexp(1., g_rand_int_range(rng, -250, 251));
    double q[3] = {0, 0, 0}, lmin = 0, lmax = 0;
    if (n % 3 == 0) {  // diagonal
      q[0] = scale * g_rand_int_range(rng, 1, 1 << 20);
      q[2] = scale * g_rand_int_range(rng, 1, 1 << 20);
      lmin = std::fmin(q[0], q[2]), lmax = std::fmax(q[0], q[2]);
    } else {  // a ± b; n % 3 == 2: a − |b| from 1 to 4 times the scale
      double const a = std::ldexp(1., 45) * scale;
      double const b = (n % 3 == 1
                            ? g_rand_int_range(rng, 0, 1 << 20) * std::ldexp(1., 25)
                            : std::ldexp(1., 45) - g_rand_int_range(rng, 1, 5)) *
                       scale * (n % 2 ? 1 : -1);
      q[0] = q[2] = a, q[1] = b;
      lmin = a - std::fabs(b), lmax = a + std::fabs(b);
    }
    if (lmax <= 1e4 * lmin) ++moderate;
    check_radius_2d(q, lmin, lmax, &tight);
  }
  // Rotations: the entries of the rounded R·diag(e)·Rᵀ carry a few
  // roundings each, so λmin is within 1e-12·e_max of e_min.
  for (int n = 0; n < 20000; n++) {
    double const scale = std::ldexp(1., g_rand_int_range(rng, -250, 251));
    double const e0 = scale * std::pow(10., g_rand_double_range(rng, -2., 2.));
    double const e1 = scale * std::pow(10., g_rand_double_range(rng, -2., 2.));
    double const t = g_rand_double_range(rng, -G_PI, G_PI);
    double const c = std::cos(t), s = std::sin(t);
    double const q[3] = {e0 * c * c + e1 * s * s, (e0 - e1) * c * s,
                         e0 * s * s + e1 * c * c};
    double const emin = std::fmin(e0, e1), emax = std::fmax(e0, e1);
    if (emax <= 1e4 * emin) ++moderate;
    check_radius_2d(q, emin - 1e-12 * emax, emax, &tight);
  }
  g_assert_cmpint(tight, >=, moderate * 9 / 10);
  double const tiny[3] = {0x1p-301, 0, 1}, huge[3] = {1, 0, 0x1p301};
  double const unit[3] = {1, 0, 1};
  g_assert_cmpfloat(pw85::detail::inscribed_radius<2>(tiny), ==, 0.0);
  g_assert_cmpfloat(pw85::detail::inscribed_radius<2>(huge), ==, 0.0);
  double const one = pw85::detail::inscribed_radius<2>(unit);
  g_assert_cmpfloat(one, <, 1.0);
  g_assert_cmpfloat(one, >, 1.0 - 0x1p-16);
  g_rand_free(rng);
}

// The deep-overlap shortcut for ellipses (line_factor<2>, deep_overlap<2>,
// with the index's filter d² < (reach + ρ)² and no slack): whenever it
// says "deep", pw85_2d_contact_function gives μ² ≤ (1 − 2⁻²⁰)²; and it
// decides most pairs whose centres are within half the inscribed radius.
void test_deep_overlap_2d() {
  GRand *rng = g_rand_new_with_seed(2030);
  int deep = 0, close = 0;
  for (int n = 0; n < 20000; n++) {
    double q[2][3];
    for (auto &f : q) {
      double const a[2] = {g_rand_double_range(rng, .1, 1.),
                           g_rand_double_range(rng, .1, 1.)};
      g_assert_cmpint(pw85_2d_ellipse(a, g_rand_double_range(rng, -3.2, 3.2), f), ==,
                      PW85_SUCCESS);
    }
    double const rho = pw85::detail::inscribed_radius<2>(q[1]);
    double l[3], s = 0.;
    if (!(rho > 0.) || !pw85::detail::line_factor<2>(q[0], l, &s)) continue;
    g_assert_cmpfloat(s, >, 0.);
    double const len = g_rand_double_range(rng, 0., 2.5);
    double const t = g_rand_double_range(rng, -3.2, 3.2);
    double const r[2] = {len * std::cos(t), len * std::sin(t)};
    double const d2 = r[0] * r[0] + r[1] * r[1];
    bool const near = len < .5 * rho;
    if (!pw85::detail::deep_overlap<2>(l, r, d2, rho)) {
      if (near) close++;  // a miss, counted below
      continue;
    }
    deep++;
    double out[2];
    g_assert_cmpint(pw85_2d_contact_function(r, q[0], q[1], out), ==, PW85_SUCCESS);
    if (!(out[0] <= (1. - 0x1p-20) * (1. - 0x1p-20)))
      g_error("deep_overlap<2>: mu2 = %.17g for r = (%.17g, %.17g)", out[0], r[0], r[1]);
  }
  g_test_message("2D: %d deep overlaps, %d near pairs missed", deep, close);
  g_assert_cmpint(deep, >, 2000);
  g_assert_cmpint(close, ==, 0);
  g_rand_free(rng);
}

// The maximiser of f for the problem p (scaled and oriented), computed
// independently of the quartic of rational_start(): bisection in long
// double on the sign of f′ = μ1² − μ2² (eq. (5.4)), s = Q(λ)⁻¹·r from the
// 2×2 inverse, 120 halvings (below the long double's resolution of λ*
// for the pairs drawn here, λ* ≥ 1e-6).
long double maximiser_2d(pw85::detail::Problem<2> const &p) {
  long double lo = 0.0L, hi = 1.0L;
  for (int k = 0; k < 120; ++k) {
    long double const l = 0.5L * (lo + hi), m = 1.0L - l;
    long double const a = m * p.q1[0] + l * p.q2[0],
                      b = m * p.q1[1] + l * p.q2[1],
                      c = m * p.q1[2] + l * p.q2[2];
    long double const det = a * c - b * b;
    long double const s0 = (c * p.r[0] - b * p.r[1]) / det,
                      s1 = (a * p.r[1] - b * p.r[0]) / det;
    long double const p1 = p.q1[0] * s0 * s0 + 2.0L * p.q1[1] * s0 * s1 +
                           p.q1[2] * s1 * s1;
    long double const p2 = p.q2[0] * s0 * s0 + 2.0L * p.q2[1] * s0 * s1 +
                           p.q2[2] * s1 * s1;
    (m * m * p1 - l * l * p2 > 0.0L ? lo : hi) = l;
  }
  return 0.5L * (lo + hi);
}

// A random ellipse: semi-axes 10^U(lo, 0), a random angle.
void random_ellipse(GRand *rng, double lo, double q[3]) {
  double const a[2] = {std::pow(10., g_rand_double_range(rng, lo, 0.)),
                       std::pow(10., g_rand_double_range(rng, lo, 0.))};
  g_assert_cmpint(pw85_2d_ellipse(a, g_rand_double_range(rng, -3.2, 3.2), q), ==,
                  PW85_SUCCESS);
}

// rational_start() (warm_start.hpp, eq. (5.9b)) lands within 1e-5 of λ*
// relative to min(λ*, 1 − λ*), inside the newton_accept of step 4, where
// the search then accepts its first point: Newton's step at its last point
// was below 1e-2, Halley's step leaves about the cube of that (1e-6), and
// the coefficients' rounding adds about ε·cond(Qᵢ) (below 1e-11 here).
// Three classes: ellipses of aspect ratios to 100 and similar sizes;
// aspect ratios to 10 with sizes (radii) up to 1000 apart (λ* down to
// 1e-6: P rises from λ = 0 before it falls); circles up to 1000 apart,
// where λ0 is already the root. Measured worst: printed. A wrong
// coefficient of the quartic moves its root by far more (checked: c2
// without its ν1β0 term fails), and so do a step test that Halley's small
// steps near P′ = 0 fool, or a start already at the root bisected away.
void test_rational_start() {
  using namespace pw85::detail;
  GRand *rng = g_rand_new_with_seed(2031);
  double worst = 0.0, worst_sphere = 0.0;
  for (int n = 0; n < 3000; n++) {
    int const kind = n % 3;
    double q1[3], q2[3];
    double const axes_lo = kind == 0 ? -2. : kind == 1 ? -1. : 0.;
    random_ellipse(rng, axes_lo, q1);
    random_ellipse(rng, axes_lo, q2);
    if (kind > 0) {  // radii up to 1000 times apart (forms 1e6)
      double const f = std::pow(10., g_rand_double_range(rng, -6., 6.));
      for (double &x : q2) x *= f;
    }
    double const t = g_rand_double_range(rng, -3.2, 3.2);
    double const len = std::pow(10., g_rand_double_range(rng, -1., 1.));
    double const r[2] = {len * std::cos(t), len * std::sin(t)};
    Problem<2> p;
    g_assert_true(prepare(r, q1, q2, &p) == Status::success);
    quads(&p);
    orient(&p);
    double const l0 = warm_start(p);
    double const l = rational_start(p, l0);
    long double const star = maximiser_2d(p);
    long double const near = std::fmin(star, 1.0L - star);
    double const err = double(std::fabs(l - star) / near);
    if (!(err <= 1e-5))
      g_error("rational_start: λ = %.17g, λ* = %.17Lg, λ0 = %.17g (pair %d)", l,
              star, l0, n);
    worst = std::fmax(worst, err);
    if (kind == 0)
      worst_sphere = std::fmax(worst_sphere, double(std::fabs(l0 - star) / near));
  }
  g_test_message("rational_start: worst relative error %.3g (the sphere "
                 "model's on the first class: %.3g)", worst, worst_sphere);
  // The sphere model alone is far off on these pairs: the test would see a
  // start that stayed at λ0.
  g_assert_cmpfloat(worst_sphere, >, 1e-2);
  g_rand_free(rng);
}

// Where the quartic's coefficients are not finite, or do not show
// P(0) > 0 > P(1) (here a form that is not positive definite), λ0 stays;
// for forms conditioned up to 1e15, and sizes up to 2^±900 apart, the
// start is some λ in (0, 1).
void test_rational_start_edges() {
  using namespace pw85::detail;
  Problem<2> p{};
  double const huge[3] = {1e200, 0.0, 1e200}, unit[3] = {1.0, 0.0, 1.0};
  double const indefinite[3] = {1.0, 2.0, 1.0};
  double const r[2] = {1.0, 0.5};
  std::memcpy(p.r, r, sizeof r);
  std::memcpy(p.q1, huge, sizeof huge);  // ν0β0 ~ 1e600
  std::memcpy(p.q2, unit, sizeof unit);
  g_assert_cmpfloat(rational_start(p, 0.3), ==, 0.3);
  std::memcpy(p.q1, indefinite, sizeof indefinite);  // β0 = −3, ν0 = 1
  p.r[1] = 0.0;
  g_assert_cmpfloat(rational_start(p, 0.3), ==, 0.3);
  GRand *rng = g_rand_new_with_seed(2032);
  for (int n = 0; n < 5000; n++) {
    double q1[3], q2[3];
    random_ellipse(rng, -7.5, q1);  // cond to 1e15
    random_ellipse(rng, -7.5, q2);
    if (n % 2) {  // sizes up to 2^±900 apart
      double const f = std::ldexp(1., g_rand_int_range(rng, -900, 901));
      for (double &x : q2) x *= f;
    }
    double const t = g_rand_double_range(rng, -3.2, 3.2);
    double const r2[2] = {std::cos(t), std::sin(t)};
    Problem<2> q;
    if (prepare(r2, q1, q2, &q) != Status::success) continue;
    quads(&q);
    orient(&q);
    double const l = rational_start(q, warm_start(q));
    if (!(l > 0.0 && l < 1.0)) g_error("rational_start: λ = %.17g (pair %d)", l, n);
  }
  g_rand_free(rng);
}

void test_inscribed_radius() {
  GRand *rng = g_rand_new_with_seed(2026);
  int tight = 0, moderate = 0;
  static int const perms[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  for (int n = 0; n < 20000; n++) {
    double const scale = std::ldexp(1., g_rand_int_range(rng, -250, 251));
    int const family = n % 4;
    double q[PW85_SYM] = {0, 0, 0, 0, 0, 0};
    double lmin = 0, lmax = 0;
    int const *p = perms[g_rand_int_range(rng, 0, 3)];
    auto at = [&](int i, int j) -> double & {
      return q[pw85::detail::sym_index(p[i], p[j])];
    };
    if (family == 0) {  // diagonal
      double d[3];
      for (double &x : d) x = scale * g_rand_int_range(rng, 1, 1 << 20);
      for (int k = 0; k < 3; k++) at(k, k) = d[k];
      lmin = std::fmin(d[0], std::fmin(d[1], d[2]));
      lmax = std::fmax(d[0], std::fmax(d[1], d[2]));
    } else if (family == 1 || family == 3) {  // a ± b beside c
      double const a = std::ldexp(1., 45) * scale;
      // family 3: a − |b| from 1 to 4 times the scale (λmin/λmax ≈ 2⁻⁴⁵).
      double const b = (family == 1
                            ? g_rand_int_range(rng, 0, 1 << 20) * std::ldexp(1., 25)
                            : std::ldexp(1., 45) - g_rand_int_range(rng, 1, 5)) *
                       scale * (n % 8 < 4 ? 1 : -1);
      double const c = scale * std::ldexp(g_rand_int_range(rng, 1, 1 << 20), 25);
      at(0, 0) = a, at(1, 1) = a, at(0, 1) = b, at(2, 2) = c;
      lmin = std::fmin(a - std::fabs(b), c);
      lmax = std::fmax(a + std::fabs(b), c);
    } else {  // a·I + b·(J − I), a > b, a + 2b > 0
      double const a = scale * std::ldexp(1., 44);
      double const b = scale * (g_rand_int_range(rng, -(1 << 20), 1 << 20)) *
                       std::ldexp(1., 22);
      for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) at(i, j) = i == j ? a : b;
      lmin = std::fmin(a + 2 * b, a - b);
      lmax = std::fmax(a + 2 * b, a - b);
    }
    if (lmax <= 1e4 * lmin) ++moderate;
    check_radius(q, lmin, lmax, &tight);
  }
  // Random rotations: Q̂ is the rounded R·diag(e)·Rᵀ, whose λmin is
  // within 1e-12·e_max of e_min (entries with a few roundings each); the
  // certificate is checked against e_min − 1e-12·e_max.
  for (int n = 0; n < 20000; n++) {
    double const scale = std::ldexp(1., g_rand_int_range(rng, -250, 251));
    double e[3];
    for (double &x : e) x = scale * std::pow(10., g_rand_double_range(rng, -2., 2.));
    double q[PW85_SYM];
    random_form_with_eigenvalues(rng, e, q);
    double const emin = std::fmin(e[0], std::fmin(e[1], e[2]));
    double const emax = std::fmax(e[0], std::fmax(e[1], e[2]));
    if (emax <= 1e4 * emin) ++moderate;
    check_radius(q, emin - 1e-12 * emax, emax, &tight);
  }
  // The cubic's estimate holds for almost all of the moderate forms.
  g_assert_cmpint(tight, >=, moderate * 9 / 10);
  // Outside [2⁻³⁰⁰, 2³⁰⁰] on the diagonal: 0.
  double const tiny[PW85_SYM] = {0x1p-301, 0, 0, 1, 0, 1};
  double const huge[PW85_SYM] = {1, 0, 0, 0x1p301, 0, 1};
  double const unit[PW85_SYM] = {1, 0, 0, 1, 0, 1};
  g_assert_cmpfloat(pw85::detail::inscribed_radius(tiny), ==, 0.0);
  g_assert_cmpfloat(pw85::detail::inscribed_radius(huge), ==, 0.0);
  double const one = pw85::detail::inscribed_radius(unit);
  g_assert_cmpfloat(one, <, 1.0);
  g_assert_cmpfloat(one, >, 1.0 - 0x1p-16);
  g_rand_free(rng);
}


// The whole state of two indexes, field by field: levels (in order), their
// cells (in order) and entries (in order, every field), the slots of the
// ids below cap, the counts and the coordinate bound. Capacities are not
// state.
bool same_state(pw85::detail::Index const &a, pw85::detail::Index const &b,
                std::size_t cap) {
  using namespace pw85::detail;
  if (a.count() != b.count() || a.coordinate_bound() != b.coordinate_bound() ||
      a.levels().size() != b.levels().size())
    return false;
  for (std::size_t l = 0; l < a.levels().size(); ++l) {
    Level const &x = a.levels()[l], &y = b.levels()[l];
    if (x.exponent != y.exponent || x.count != y.count ||
        x.cells.size() != y.cells.size() || x.dense.size() != y.dense.size())
      return false;
    for (int k = 0; k < dim; ++k)
      if (x.hmax[k] != y.hmax[k] || x.side[k] != y.side[k]) return false;
    for (std::size_t d = 0; d < x.dense.size(); ++d)
      if (x.dense[d] != y.dense[d]) return false;
    for (std::size_t ci = 0; ci < x.cells.size(); ++ci) {
      Cell const &u = x.cells[ci], &v = y.cells[ci];
      if (u.size() != v.size()) return false;
      for (std::size_t e = 0; e < u.size(); ++e) {
        Entry const &p = u[e], &q = v[e];
        if (p.id != q.id || std::memcmp(p.wrap, q.wrap, sizeof p.wrap) != 0 ||
            std::memcmp(p.c, q.c, sizeof p.c) != 0 ||
            std::memcmp(p.h, q.h, sizeof p.h) != 0 ||
            std::memcmp(p.q, q.q, sizeof p.q) != 0 ||
            std::memcmp(&p.rho, &q.rho, sizeof p.rho) != 0)
          return false;
      }
    }
  }
  for (std::size_t id = 0; id < cap; ++id) {
    Slot const s = a.slot(id), t = b.slot(id);
    if (s.level != t.level || s.cell != t.cell || s.index != t.index) return false;
  }
  return true;
}

// Index::insert_many() on 1, 2 and 8 threads (the bulk path, index.hpp:
// bulk_min) leaves the state that the loop of insert() leaves, field by
// field, into an empty index and into one that holds some already
// (periodic, several levels; open); a call that fails leaves the state as
// it was, the free slots of the id table included (the bulk path marks
// them for its test of repeated ids).
void test_bulk_insert() {
  using namespace pw85::detail;
  GRand *rng = g_rand_new_with_seed(26);
  std::size_t const n = 9000, first = 2000;
  std::vector<std::size_t> ids(n);
  std::vector<double> c(3 * n), q(6 * n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = i;
  for (std::size_t i = n - 1; i > 0; --i)
    std::swap(ids[i], ids[std::size_t(g_rand_int_range(rng, 0, gint32(i + 1)))]);
  double const side = 30.;
  for (std::size_t i = 0; i < n; ++i) {
    double const s = std::pow(10., g_rand_double(rng) * 0.8);  // 3 levels or more
    double const e[3] = {s * s * .04, s * s * .25, s * s};
    random_form_with_eigenvalues(rng, e, &q[6 * i]);
    for (int k = 0; k < 3; ++k) c[3 * i + k] = g_rand_double_range(rng, -side, 2 * side);
  }
  double const box[3] = {side, side * 1.25, side * .75};
  for (double const *b : {box, static_cast<double const *>(nullptr)}) {
    Index ref(b);
    for (std::size_t i = 0; i < n; ++i)
      g_assert_true(ref.insert(ids[i], &c[3 * i], &q[6 * i]) == Status::success);
    g_assert_cmpuint(ref.levels().size(), >=, 3);
    for (int threads : {1, 2, 8}) {
      for (std::size_t start : {std::size_t(0), first}) {
        Index ix(b);
        for (std::size_t i = 0; i < start; ++i)
          g_assert_true(ix.insert(ids[i], &c[3 * i], &q[6 * i]) == Status::success);
        // a failing call first: a repeated id near the end
        std::vector<std::size_t> bad(ids.begin() + long(start), ids.end());
        bad[bad.size() - 3] = bad[5];
        Index before(b);
        for (std::size_t i = 0; i < start; ++i)
          g_assert_true(before.insert(ids[i], &c[3 * i], &q[6 * i]) == Status::success);
        g_assert_true(ix.insert_many(n - start, bad.data(), &c[3 * start], &q[6 * start],
                                     threads) == Status::invalid_argument);
        if (!same_state(before, ix, n)) {
          g_test_message("threads %d, start %zu: a failed call changed the index",
                         threads, start);
          g_test_fail();
        }
        g_assert_true(ix.insert_many(n - start, &ids[start], &c[3 * start], &q[6 * start],
                                     threads) == Status::success);
        if (!same_state(ref, ix, n)) {
          g_test_message("threads %d, start %zu: not the state of insert()",
                         threads, start);
          g_test_fail();
        }
      }
    }
  }
  g_rand_free(rng);
}

// Buffers that borrow parts of a block of a BlockList (the cells that
// insert_many() creates): each reads its own part, one that grows moves
// to memory of its own with its content, a move takes the part along, and
// the list frees the block after them (checked by valgrind's and ASan's
// leak and use-after-free checks of this test).
void test_borrowed_parts() {
  using namespace pw85::detail;
  BlockList blocks;
  double *const part = static_cast<double *>(blocks.allocate(6 * sizeof(double)));
  g_assert_nonnull(part);
  Buffer<double> x, y;
  x.borrow(part, 2);
  y.borrow(part + 2, 4);
  g_assert_cmpuint(x.capacity(), ==, 2);
  g_assert_cmpuint(y.capacity(), ==, 4);
  for (int k = 0; k < 2; ++k) g_assert_true(x.push_back(k));
  for (int k = 0; k < 4; ++k) g_assert_true(y.push_back(10 + k));
  g_assert_true(x.data() == part && y.data() == part + 2);
  g_assert_true(x.push_back(2));  // beyond its part: x moves out
  g_assert_true(x.data() != part);
  g_assert_cmpuint(x.capacity(), >=, 3);
  for (int k = 0; k < 3; ++k) g_assert_cmpfloat(x[std::size_t(k)], ==, k);
  for (int k = 0; k < 4; ++k) g_assert_cmpfloat(y[std::size_t(k)], ==, 10 + k);
  Buffer<double> z(static_cast<Buffer<double> &&>(y));  // the part moves with it
  g_assert_true(z.data() == part + 2 && y.data() == nullptr);
  g_assert_cmpuint(z.capacity(), ==, 4);
  y = static_cast<Buffer<double> &&>(z);  // and back, by assignment
  g_assert_true(y.data() == part + 2 && z.data() == nullptr);
  y.reset();  // a borrowed part is not freed (the list frees the block)
  g_assert_true(y.data() == nullptr && y.capacity() == 0);
  g_assert_true(y.push_back(1.5) && y[0] == 1.5);
}

// After insert_many() into an empty index (its new cells share a block),
// the edits that make cells grow (insert, update), shrink (remove) and a
// second bulk call (into cells that exist, and into the new cells of a new
// level: every other ellipsoid twice as large) leave the state that the
// same edits leave after a loop of insert(), periodic and open.
void test_bulk_then_edits() {
  using namespace pw85::detail;
  GRand *rng = g_rand_new_with_seed(29);
  std::size_t const n = 8000, bulk = 4000, moved = 1500;
  std::vector<double> c(3 * n), q(6 * n), c2(3 * moved);
  std::vector<std::size_t> ids(n);
  double const side = 24.;
  for (std::size_t i = 0; i < n; ++i) {
    ids[i] = i;
    double const s = std::pow(10., g_rand_double(rng) * 0.6);
    double const e[3] = {s * s * .04, s * s * .25, s * s};
    random_form_with_eigenvalues(rng, e, &q[6 * i]);
    if (i >= n - moved && i % 2 == 1)
      for (int k = 0; k < 6; ++k) q[6 * i + k] *= 4.0;
    for (int k = 0; k < 3; ++k) c[3 * i + k] = g_rand_double_range(rng, 0, side);
  }
  for (std::size_t i = 0; i < 3 * moved; ++i) c2[i] = g_rand_double_range(rng, -side, 2 * side);
  double const box[3] = {side, side, side};
  for (double const *b : {box, static_cast<double const *>(nullptr)}) {
    Index ref(b), ix(b);
    for (std::size_t i = 0; i < bulk; ++i)
      g_assert_true(ref.insert(i, &c[3 * i], &q[6 * i]) == Status::success);
    g_assert_true(ix.insert_many(bulk, ids.data(), c.data(), q.data(), 2) == Status::success);
    for (Index *x : {&ref, &ix}) {
      for (std::size_t i = bulk; i < n - moved; ++i)
        g_assert_true(x->insert(i, &c[3 * i], &q[6 * i]) == Status::success);
      for (std::size_t i = 0; i < moved; ++i)
        g_assert_true(x->update(2 * i, &c2[3 * i], &q[6 * (2 * i)]) == Status::success);
      for (std::size_t i = 0; i < moved; ++i)
        g_assert_true(x->remove(2 * i + 1) == Status::success);
    }
    for (std::size_t i = n - moved; i < n; ++i)
      g_assert_true(ref.insert(i, &c[3 * i], &q[6 * i]) == Status::success);
    std::size_t const levels = ix.levels().size();
    g_assert_true(ix.insert_many(moved, &ids[n - moved], &c[3 * (n - moved)],
                                 &q[6 * (n - moved)], 2) == Status::success);
    g_assert_cmpuint(ix.levels().size(), >, levels);
    if (!same_state(ref, ix, n)) {
      g_test_message("%s: not the state of insert()", b ? "periodic" : "open");
      g_test_fail();
    }
  }
  g_rand_free(rng);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/core/ldl/backward-error", test_ldl_backward_error);
  g_test_add_func("/pw85/core/golden-bracket", test_golden_bracket);
  g_test_add_func("/pw85/core/rational-start", test_rational_start);
  g_test_add_func("/pw85/core/rational-start/edges", test_rational_start_edges);
  g_test_add_func("/pw85/core/index/inscribed-radius", test_inscribed_radius);
  g_test_add_func("/pw85/core/index/inscribed-radius-2d", test_inscribed_radius_2d);
  g_test_add_func("/pw85/core/index/deep-overlap-2d", test_deep_overlap_2d);
  g_test_add_func("/pw85/core/index/bulk-insert", test_bulk_insert);
  g_test_add_func("/pw85/core/index/borrowed-parts", test_borrowed_parts);
  g_test_add_func("/pw85/core/index/bulk-then-edits", test_bulk_then_edits);
  return g_test_run();
}
