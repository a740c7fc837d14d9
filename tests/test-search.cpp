// SPDX-License-Identifier: BSD-3-Clause
// The search for μ² stage by stage, through the core's static library, as
// GSL's min/test.c tests its minimisers: the invariants of each stage at
// every iteration (the bracket holds the maximiser and narrows, the iterate
// stays inside it), not only the final value. Maximisers λ* and μ² come
// from data/pw85_general_pairs.h5 (exact references, data/README.md).
#include <glib.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "brent_certify.hpp"
#include "compensated.hpp"
#include "contact.hpp"
#include "evaluate.hpp"
#include "f.hpp"
#include "finish.hpp"
#include "newton.hpp"
#include "overlap.hpp"
#include "problem.hpp"
#include "tolerances.hpp"
#include "warm_start.hpp"

extern "C" {
#include "refdata.h"
#include "testutil.h"
}

namespace {

namespace core = pw85::detail;

GeneralPairs pairs;

// The prepared and oriented problem of general pair n (rescaled: λ* is
// unchanged, or 1 − λ* if oriented the other way; μ² is scaled by
// 2^−shift).
core::Problem<3> problem(size_t n) {
  core::Problem<3> p;
  g_assert_true(core::prepare(pairs.r12 + 3 * n, pairs.q1 + 6 * n,
                              pairs.q2 + 6 * n, &p) == core::Status::success);
  g_assert_false(p.r_is_zero);
  core::quads(&p);  // as the contact function does
  core::orient(&p);
  return p;
}

// λ* of the problem, in its orientation (orient() may have exchanged Q1
// and Q2; 1 − λ* is exact for λ* ≥ ½).
double star_of(core::Problem<3> const &p, size_t n) {
  return p.swapped ? 1.0 - pairs.LAMBDA[n] : pairs.LAMBDA[n];
}

template <bool Fast>
core::NewtonResult<3> newton(core::Problem<3> const &p, double lambda, int steps) {
  return core::newton_on_omega<Fast>(p, lambda, steps);
}

// How far outside a bracket [lo, hi] the maximiser may lie because the
// signs of the plain ω that set it are rounding noise within about
// κ̄(Q(λ))·ε of the root (eq. (5.6): ω′ ≥ 1, so an error δ in ω moves its
// root by at most δ). The general pairs have κ̄ up to about 1e9; measured
// worst excess: printed by the test.
constexpr double sign_noise = 1e-6;

// Newton on ω (step 4), step by step: a run of k steps is the prefix of a
// run of k + 1 (the iteration is deterministic), so the state after each
// step is that of newton_on_omega(p, λ0, k). At every step: the iterate
// lies strictly inside the bracket, the bracket only narrows, and it holds
// λ* up to the noise of the plain signs; once stopped for convergence, the
// estimate is within 1e-8 of λ*.
void test_newton_invariants() {
  double worst_excess = 0.0, worst_converged = 0.0;
  int checked = 0;
  for (size_t n = 0; n < pairs.count; n++) {
    core::Problem<3> const p = problem(n);
    double const star = star_of(p, n);
    double const start = core::warm_start(p);
    core::Bracket prev;
    for (int k = 1; k <= core::warm_newton_iter; k++) {
      core::NewtonResult<3> const r = p.moderate ? newton<true>(p, start, k)
                                              : newton<false>(p, start, k);
      core::Bracket const &b = r.bracket;
      if (!(b.lo >= prev.lo && b.hi <= prev.hi && b.lo < b.hi))
        g_test_fail_printf("pair %zu, step %d: bracket [%.17g, %.17g] after "
                           "[%.17g, %.17g]", n, k, b.lo, b.hi, prev.lo, prev.hi);
      if (r.stop == core::NewtonStop::step_limit && !b.contains(r.lambda))
        g_test_fail_printf("pair %zu, step %d: iterate %.17g outside "
                           "[%.17g, %.17g]", n, k, r.lambda, b.lo, b.hi);
      double const excess = std::max(b.lo - star, star - b.hi);
      worst_excess = std::max(worst_excess, excess);
      if (excess > sign_noise)
        g_test_fail_printf("pair %zu, step %d: lambda* = %.17g outside "
                           "[%.17g, %.17g]", n, k, star, b.lo, b.hi);
      checked++;
      prev = b;
      if (r.stop != core::NewtonStop::step_limit) {
        if (r.converged()) {
          double const e = std::fabs(r.lambda - star);
          worst_converged = std::max(worst_converged, e);
          if (!(e <= 1e-8))
            g_test_fail_printf("pair %zu: converged (stop %d) at %.17g, "
                               "lambda* = %.17g", n, int(r.stop), r.lambda,
                               star);
        }
        break;
      }
    }
  }
  g_test_message("%d Newton states: worst excess of lambda* over the bracket "
                 "%.3g, worst |lambda - lambda*| at convergence %.3g",
                 checked, worst_excess, worst_converged);
}

template <bool Fast>
void brent_at(core::Problem<3> const &p, double centre, int iter,
              core::BrentResult *out) {
  double const neg_f = core::neg_f_or_zero<Fast>(centre, p);
  g_assert_true(core::certify_with_brent<Fast>(p, centre, neg_f, iter, out) ==
                core::Status::success);
}

template <bool Fast>
double cond_at(core::Problem<3> const &p, double lambda) {
  core::PlainPoint<3> pt;
  core::PlainBounds b;
  if (!core::evaluate_plain<Fast>(lambda, p, &pt) || !core::plain_bounds(pt, &b))
    return HUGE_VAL;
  return b.cond;
}

// How far from λ* comparisons of the plain f can be fooled by its rounding
// noise η = plain_form_margin·κ̄(Q)·f (the bound tolerances.hpp derives):
// f is flat to within η over |λ − λ*| ≤ δ = √(2η/|f″|), f″ = −g′
// (docs/optimisation.rst, eq. (5.5)); and a bracket of width w about a point at distance d
// from λ* passes the check of step 5 when the difference of f across it,
// about |f″|·d·w, is below η, that is up to d = η/(|f″|·w), w the width of
// the first bracket.
template <bool Fast>
double noise_zone(core::Problem<3> const &p, double star) {
  double res[3];
  core::residual(star, p.r, p.q1, p.q2, res);
  double const eta = core::plain_form_margin * cond_at<Fast>(p, star) * res[0];
  double const f2 = std::fabs(res[2]);
  return std::sqrt(2.0 * eta / f2) + eta / (f2 * core::first_bracket_width);
}

// Brent's certification (step 5) after 0, 1, 2, ... iterations, from a
// centre 1e-3·min(λ*, 1 − λ*) off λ* (so that the first brackets fail
// their check and widen, and Brent must move): lower ≤ estimate ≤ upper,
// the bracket narrows and holds λ* to within the noise zone of the plain f,
// and −f at the estimate never exceeds −f at the centre it started from
// (Brent keeps the best point).
void test_brent_invariants() {
  int checked = 0;
  double worst = 0.0;  // excess of λ* over the bracket / noise zone
  for (size_t n = 0; n < pairs.count; n++) {
    core::Problem<3> const p = problem(n);
    double const star = star_of(p, n);
    double const zone = p.moderate ? noise_zone<true>(p, star)
                                   : noise_zone<false>(p, star);
    double const offset = 1e-3 * std::min(star, 1.0 - star);
    double const centre = n % 2 ? star - offset : star + offset;
    double const f_centre = p.moderate ? core::neg_f_or_zero<true>(centre, p)
                                       : core::neg_f_or_zero<false>(centre, p);
    double prev_width = 2.0;
    for (int iter = 0; iter <= core::brent_max_iter; iter++) {
      core::BrentResult b;
      if (p.moderate)
        brent_at<true>(p, centre, iter, &b);
      else
        brent_at<false>(p, centre, iter, &b);
      double const width = b.upper - b.lower;
      if (!(b.lower <= b.estimate && b.estimate <= b.upper))
        g_test_fail_printf("pair %zu, %d iterations: estimate %.17g outside "
                           "[%.17g, %.17g]", n, iter, b.estimate, b.lower,
                           b.upper);
      double const excess = std::max(b.lower - star, star - b.upper);
      worst = std::max(worst, excess / zone);
      if (!(excess <= zone))
        g_test_fail_printf("pair %zu, %d iterations: lambda* = %.17g outside "
                           "[%.17g, %.17g] by %.3g, noise zone %.3g", n, iter,
                           star, b.lower, b.upper, excess, zone);
      if (!(width <= prev_width))
        g_test_fail_printf("pair %zu, %d iterations: width %.3g after %.3g", n,
                           iter, width, prev_width);
      double const f_est = p.moderate
                               ? core::neg_f_or_zero<true>(b.estimate, p)
                               : core::neg_f_or_zero<false>(b.estimate, p);
      if (!(f_est <= f_centre))
        g_test_fail_printf("pair %zu, %d iterations: -f(estimate) %.17g > "
                           "-f(centre) %.17g", n, iter, f_est, f_centre);
      prev_width = width;
      checked++;
      if (width < core::lambda_atol) break;
    }
    if (!(prev_width < core::lambda_atol))
      g_test_fail_printf("pair %zu: Brent's bracket still %.3g wide", n,
                         prev_width);
  }
  g_test_message("%d Brent states checked: worst excess of lambda* over the "
                 "bracket %.3g of the noise zone", checked, worst);
}

// The compensated f at λ, f(λ) ≤ μ² in exact arithmetic.
double f_compensated(core::Problem<3> const &p, double lambda) {
  core::Compensated a;
  if (!core::evaluate_compensated<false, 3>(lambda, p.r, p.q1, p.q2, false,
                                            nullptr, &a))
    return -HUGE_VAL;
  return a.f;
}

// The μ² that the search returns is at least every f it evaluated: at
// every Newton iterate and at Brent's estimate. Rounding is monotone, so a
// correctly rounded μ² is at least the correctly rounded f(λ) for every λ;
// the compensated f is within about an ulp of the latter (pw85.h), hence
// the one-ulp allowance. Also, the returned μ² is the reference.
void test_result_bounds_every_f() {
  int checked = 0;
  for (size_t n = 0; n < pairs.count; n++) {
    core::Problem<3> const p = problem(n);
    double out[2];
    g_assert_true((p.moderate ? core::solve<true>(p, out)
                              : core::solve<false>(p, out)) ==
                  core::Status::success);
    double const mu2 = out[0];
    double const expected = std::ldexp(pairs.MU2[n], -p.shift);
    if (mu2 != expected)
      g_test_fail_printf("pair %zu: mu^2 %.17g, expected %.17g", n, mu2,
                         expected);
    double const allowance = std::nextafter(mu2, HUGE_VAL) - mu2;
    std::vector<double> points;
    double const start = core::warm_start(p);
    points.push_back(start);
    for (int k = 1; k <= core::warm_newton_iter; k++) {
      core::NewtonResult<3> const r = p.moderate ? newton<true>(p, start, k)
                                              : newton<false>(p, start, k);
      points.push_back(r.last.lambda);
      points.push_back(r.lambda);
      if (r.stop != core::NewtonStop::step_limit) break;
    }
    core::BrentResult b;
    if (p.moderate)
      brent_at<true>(p, points.back(), core::brent_max_iter, &b);
    else
      brent_at<false>(p, points.back(), core::brent_max_iter, &b);
    points.push_back(b.estimate);
    for (double lambda : points) {
      if (!(lambda > 0.0 && lambda < 1.0)) continue;
      double const f = f_compensated(p, lambda);
      if (!(mu2 + allowance >= f))
        g_test_fail_printf("pair %zu: mu^2 %.17g below f(%.17g) = %.17g", n,
                           mu2, lambda, f);
      checked++;
    }
  }
  g_test_message("%d evaluated points checked", checked);
}

// The safeguard of Newton's iteration (step 4), on its own.
void test_safeguard() {
  auto const no_end_step = [](bool) { return NAN; };
  // A Newton iterate inside the narrowed bracket is kept.
  {
    core::Bracket b;
    core::EndStepsTried tried;
    double const next = core::safeguard(0.5, -0.1, 0.6, 1.0, &b, &tried,
                                        no_end_step);
    g_assert_cmpfloat(next, ==, 0.6);
    g_assert_cmpfloat(b.lo, ==, 0.5);
    g_assert_cmpfloat(b.hi, ==, 1.0);
  }
  // Outside: Newton's step from the end on the root's side, once; then the
  // sphere model's 1/(1 + ρ); then bisection.
  {
    core::Bracket b;
    core::EndStepsTried tried;
    int calls = 0;
    auto const end_step = [&calls](bool from_zero) {
      calls++;
      g_assert_true(from_zero);  // ω > 0: the root lies below λ
      return 0.25;
    };
    double next = core::safeguard(0.5, 0.3, -2.0, 1.0, &b, &tried, end_step);
    g_assert_cmpfloat(next, ==, 0.25);
    g_assert_cmpfloat(b.hi, ==, 0.5);
    g_assert_true(tried.from_zero);
    next = core::safeguard(0.4, 0.1, 7.0, 3.0, &b, &tried, end_step);
    g_assert_cmpint(calls, ==, 1);
    g_assert_cmpfloat(next, ==, 1.0 / (1.0 + 3.0));  // 0.25 < 0.4 = hi
    next = core::safeguard(0.3, 0.1, 7.0, 1.0, &b, &tried, end_step);
    g_assert_cmpfloat(next, ==, 0.5 * (0.0 + 0.3));  // 1/(1+1) > hi
  }
  // A step onto 1 goes to the largest double below 1.
  {
    core::Bracket b;
    core::EndStepsTried tried{true, true};
    double const next =
        core::safeguard(0.9, -0.1, 1.5, 0.0, &b, &tried, no_end_step);
    g_assert_cmpfloat(next, ==, core::below_one);
  }
  // No double strictly inside the bracket: NaN.
  {
    double const lo = 0.5, hi = std::nextafter(0.5, 1.0);
    core::Bracket b{lo, 1.0};
    core::EndStepsTried tried{true, true};
    double const next =
        core::safeguard(hi, 0.2, 2.0, 0.0, &b, &tried, no_end_step);
    g_assert_true(std::isnan(next));
  }
}

template <bool Fast>
double plain_slope(core::Problem<3> const &p, double lambda) {
  core::PlainPoint<3> pt{};
  core::NewtonStep step{};
  if (!core::evaluate_plain<Fast>(lambda, p, &pt) ||
      !core::newton_step(pt, &step)) {
    g_test_fail_printf("no Newton step at %.17g", lambda);
    return 1.0;
  }
  return step.domega;
}

// The compensated finish (step 7) from λ*·(1 ± 1e-9), with the plain ω′
// there as its first slope (as the search starts it): it lands within
// 2e-11·min(λ*, 1 − λ*) of λ*, returns the reference μ², and never less
// than the compensated f at its start. (Its steps stop at a relative size
// of finish_accept = 1e-7; the error left is then far smaller, and
// largest where f is flat. Measured worst: 1.1e-11 relative, pair 680,
// f″(λ*) = −5.4e-3 at 60 digits, so that f is within an ulp of μ² over
// ±1.4e-7 of λ*; the earlier draw of the general pairs gave 2.3e-12.)
void test_finish() {
  double worst = 0.0;
  for (size_t n = 0; n < pairs.count; n++) {
    core::Problem<3> const p = problem(n);
    double const star = star_of(p, n);
    double const start = star + (n % 2 ? 1e-9 : -1e-9) * std::min(star, 1 - star);
    double const slope = p.moderate ? plain_slope<true>(p, start)
                                    : plain_slope<false>(p, start);
    core::FinishStart<3> const s{start, slope, nullptr, nullptr};
    core::Finished out;
    g_assert_true(core::finish(p, s, &out));
    double const expected = std::ldexp(pairs.MU2[n], -p.shift);
    if (out.mu2 != expected)
      g_test_fail_printf("pair %zu: finish gives %.17g, expected %.17g", n,
                         out.mu2, expected);
    if (!(out.mu2 >= f_compensated(p, start)))
      g_test_fail_printf("pair %zu: finish below its start", n);
    worst = std::max(worst, std::fabs(out.lambda - star) /
                                std::min(star, 1.0 - star));
  }
  g_test_message(
      "worst |lambda - lambda*|/min(lambda*, 1 - lambda*) after the finish: "
      "%.3g", worst);
  g_assert_cmpfloat(worst, <=, 2e-11);
}

// The second upper bound of μ² at a plain point (moved_upper_bound(),
// evaluate.hpp), with the margins the overlap test gives it, at
// λ = λ* ± h·min(λ*, 1 − λ*) for h = 1e-2 and 1e-3 on each general pair:
// - never below μ² (the mpmath reference, correctly rounded: an ulp of
//   slack);
// - of second order: its excess over μ² falls at least 25 times from
//   h = 1e-2 to 1e-3 (100 for the leading term; 10 for a bound of first
//   order, as max(μ1², μ2²) is), down to the floor its margins set (four
//   times what they add at h = 1e-3).
void test_moved_upper_bound() {
  int checked = 0, second_order = 0;
  double worst_ratio = HUGE_VAL;
  for (size_t n = 0; n < pairs.count; n++) {
    core::Problem<3> const p = problem(n);
    double const star = star_of(p, n);
    double const mu2 = core::times_pow2(pairs.MU2[n], -p.shift);
    double const k1 = core::trace<3>(p.q1) * p.tinv1,
                 k2 = core::trace<3>(p.q2) * p.tinv2;
    for (double const side : {-1.0, 1.0}) {
      double excess[2] = {NAN, NAN}, floor = 0.0;
      for (int k = 0; k < 2; k++) {
        double const h = k == 0 ? 1e-2 : 1e-3;
        double const lambda = star + side * h * std::min(star, 1.0 - star);
        core::PlainPoint<3> pt;
        core::PlainBounds b;
        bool const ok = p.moderate ? core::evaluate_terms<true>(lambda, p, &pt)
                                   : core::evaluate_terms<false>(lambda, p, &pt);
        if (!ok || !core::plain_bounds(pt, &b)) continue;
        core::PlainMargins const m = core::plain_margins(b.cond, k1, k2);
        double const upper = core::moved_upper_bound(
            pt, b, std::max(p.a1, p.a2), m, core::form_margin(k1, k2));
        if (!std::isfinite(upper)) continue;
        checked++;
        if (!(upper >= mu2 * (1.0 - DBL_EPSILON)))
          g_test_fail_printf("pair %zu, lambda %.17g: bound %.17g below "
                             "mu^2 %.17g", n, lambda, upper, mu2);
        excess[k] = (upper - mu2) / mu2;
        // What the margins alone add (g's margin in the correction, m.f),
        // four times.
        double const gm = m.mu * (b.mu1_sq + b.mu2_sq);
        double const w = lambda * (1.0 - lambda) / pt.f;
        floor = 4.0 * (m.f + 0.5 * gm * gm * std::max(p.a1, p.a2) * w * w / mu2);
      }
      if (std::isnan(excess[0]) || std::isnan(excess[1])) continue;
      if (excess[1] <= floor) continue;
      second_order++;
      worst_ratio = std::min(worst_ratio, excess[0] / excess[1]);
      if (!(excess[1] <= excess[0] / 25.0))
        g_test_fail_printf("pair %zu: excess %.3g at h = 1e-2, %.3g at "
                           "1e-3", n, excess[0], excess[1]);
    }
  }
  g_test_message("%d bounds checked; %d pairs of steps above the margins' "
                 "floor, worst ratio of excesses %.3g", checked,
                 second_order, worst_ratio);
  g_assert_cmpint(checked, >=, 2000);
  g_assert_cmpint(second_order, >=, 1000);
}

// The overlap test's point filters (overlap_filters_at()), each alone, on
// each general pair at λ* ± h·min(λ*, 1 − λ*) and elsewhere in (0, 1),
// against thresholds one = μ²·(1 ∓ τ) around the mpmath μ² (τ ≥ 1e-14, far
// above its half-ulp rounding): no filter may answer "overlap" (μ² < one)
// below μ², nor "disjoint" above it. The counts of the answers they may
// give show that the filters decide on both sides, the second upper bound
// among them.
void test_overlap_filters() {
  long bad = 0, decided[2][3] = {{0, 0, 0}, {0, 0, 0}};
  double const taus[] = {1e-14, 1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2};
  double const steps[] = {0.0, 1e-9, 1e-6, 1e-4, 1e-2, 1e-1};
  for (size_t n = 0; n < pairs.count; n++) {
    double const *r = pairs.r12 + 3 * n, *q1 = pairs.q1 + 6 * n,
                 *q2 = pairs.q2 + 6 * n;
    double const mu2 = pairs.MU2[n], star = pairs.LAMBDA[n];
    std::vector<double> lambdas = {0.1, 0.5, 0.9};
    for (double const h : steps)
      for (double const side : {-1.0, 1.0}) {
        double const lambda = star + side * h * std::min(star, 1.0 - star);
        if (lambda > 0.0 && lambda < 1.0) lambdas.push_back(lambda);
      }
    for (double const tau : taus)
      for (int above = 0; above < 2; above++) {
        double const one = mu2 * (above ? 1.0 + tau : 1.0 - tau);
        int const forbidden = above ? 1 : -1;  // the answer that is wrong
        for (double const lambda : lambdas) {
          int d[3];
          g_assert_true(core::overlap_filters_at<3>(r, q1, q2, lambda, one,
                                                    d) ==
                        core::Status::success);
          for (int k = 0; k < 3; k++) {
            if (d[k] == 0) continue;
            if (d[k] == forbidden) {
              if (bad++ < 10)
                g_test_fail_printf("pair %zu, lambda %.17g, one = mu^2 "
                                   "(1 %c %g): filter %d answers %d", n,
                                   lambda, above ? '+' : '-', tau, k, d[k]);
            } else {
              decided[above][k]++;
            }
          }
        }
      }
  }
  g_test_message("answers below mu^2 (disjoint): %ld %ld %ld; above "
                 "(overlap): %ld %ld %ld", decided[0][0], decided[0][1],
                 decided[0][2], decided[1][0], decided[1][1], decided[1][2]);
  for (int k = 0; k < 3; k++) {
    g_assert_cmpint(decided[0][k], >=, 10000);
    g_assert_cmpint(decided[1][k], >=, 10000);
  }
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  install_failing_gsl_handler();
  general_pairs_load_or_fail(&pairs);
  g_test_add_func("/pw85/search/safeguard", test_safeguard);
  g_test_add_func("/pw85/search/newton/invariants", test_newton_invariants);
  g_test_add_func("/pw85/search/brent/invariants", test_brent_invariants);
  g_test_add_func("/pw85/search/finish", test_finish);
  g_test_add_func("/pw85/search/result-bounds-every-f", test_result_bounds_every_f);
  g_test_add_func("/pw85/search/moved-upper-bound", test_moved_upper_bound);
  g_test_add_func("/pw85/search/overlap-filters", test_overlap_filters);
  int const status = g_test_run();
  general_pairs_clear(&pairs);
  return status;
}
