// SPDX-License-Identifier: BSD-3-Clause
// Kernels of the core that the public API does not expose on their own,
// tested through the core's static library: the factorisations of Q(λ),
// the bracket given to GSL's Brent minimiser, and the spatial index's
// inscribed radius.
#include <glib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <cfloat>
#include <cmath>

#include "brent_certify.hpp"
#include "index/deep.hpp"
#include "index/index.hpp"
#include "ldl.hpp"
#include "pw85.h"
#include "testutil.h"

namespace {

using pw85::detail::Ldl;

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

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/core/ldl/backward-error", test_ldl_backward_error);
  g_test_add_func("/pw85/core/golden-bracket", test_golden_bracket);
  g_test_add_func("/pw85/core/index/inscribed-radius", test_inscribed_radius);
  return g_test_run();
}
