// SPDX-License-Identifier: BSD-3-Clause
// The certified overlap test (overlap.hpp): a chain of filters, cheapest
// first, each deciding only where its rounding margin (tolerances.hpp)
// makes the answer certain, ending with the exact μ² (as Shewchuk's
// adaptive predicates end with the exact sign).
#include "overlap.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

#include "compensated.hpp"
#include "compiler.hpp"
#include "contact.hpp"
#include "evaluate.hpp"
#include "ldl.hpp"
#include "newton.hpp"
#include "problem.hpp"
#include "tolerances.hpp"
#include "warm_start.hpp"

namespace pw85::detail {

namespace {

// A filter's answer: the result of pw85_overlap(), or undecided.
enum class Decision { overlap = -1, tangent = 0, disjoint = 1, undecided };

// The problem with what the filters share. μ² < 1 ⟺ μ²(problem) < one,
// one = 2^−shift (exact; 0 or +∞ out of range, which decides the
// comparison correctly since μ²(problem) is finite and > 0).
template <int D>
struct Filtering {
  Problem<D> const &p;
  double one;
  double cond1, cond2;  // κ̄(Q1), κ̄(Q2)
  double const *r_lo;   // nullptr, or the low part of p.r (overlap_dd())
};

// The Filtering of a prepared p with r ≠ 0 against one: p's forms
// aᵢ = rᵀQᵢ⁻¹r (quads()) and κ̄(Qᵢ) = tr(Qᵢ)·tr(Qᵢ⁻¹) (ldl_cond_bound()).
template <int D>
PW85_INLINE Filtering<D> filtering(Problem<D> *p, double one) noexcept {
  quads(p);
  return {*p, one, trace<D>(p->q1) * p->tinv1, trace<D>(p->q2) * p->tinv2,
          nullptr};
}

// p in its canonical orientation (orient()), κ̄ᵢ following the forms that
// it may have exchanged.
template <int D>
PW85_INLINE void orient_filtering(Problem<D> *p, Filtering<D> *s) noexcept {
  orient(p);
  if (p->swapped) std::swap(s->cond1, s->cond2);
}

// Filter 1, no factorisation needed: the sphere bound μ² ≥
// |r|²/(√tr Q1 + √tr Q2)², already a certified lower bound, compared
// times 2^8 (256·one is exact, or +∞ where it does not decide).
template <int D>
Decision sphere_filter(Problem<D> const &p, double one) noexcept {
  return sphere_lower_bound_x256(p) > 256.0 * one ? Decision::disjoint
                                                  : Decision::undecided;
}

// Filter 2, from the factors of Q1 and Q2: at λ = 0 and 1 the point x0 is
// a centre, so μ² ≤ min(rᵀQ1⁻¹r, rᵀQ2⁻¹r), each off by a few κ̄(Qᵢ)·ε
// relative (plain_form_margin).
template <int D>
PW85_INLINE Decision centre_filter(Filtering<D> const &s) noexcept {
  double const m_a = form_margin(s.cond1, s.cond2);
  if (m_a < margin_limit && std::min(s.p.a1, s.p.a2) * (1.0 + m_a) < s.one)
    return Decision::overlap;
  return Decision::undecided;
}

// Whether the second upper bound of μ² (moved_upper_bound(), evaluate.hpp)
// lies below 1 in plain double, with no margin: whether filter 3 runs.
// As (g²/4)·max(aᵢ)·(λ(1 − λ))² < (1 − f)·f², without a division.
template <int D>
PW85_INLINE bool moved_bound_below(PlainPoint<D> const &pt,
                                   PlainBounds const &b,
                                   Filtering<D> const &s) noexcept {
  double const g = b.mu2_sq - b.mu1_sq;
  double const lm = pt.lambda * (1.0 - pt.lambda);
  return 0.25 * g * g * std::max(s.p.a1, s.p.a2) * lm * lm <
         (s.one - pt.f) * pt.f * pt.f;
}

// Filter 3, the bounds valid at every λ (ch. 5, eqs. (1a)–(1b)):
// f(λ) ≤ μ² because μ² is the maximum of f; μ² ≤ max(μ1², μ2²) because
// the point x0(λ) lies in both ellipsoids scaled by max(μ1, μ2), which
// therefore meet. Margins of eq. (5.11): f is off by a few κ̄(Q(λ))·ε
// relative, μᵢ² (a quadratic form in s) by that times √κ̄(Qᵢ)
// (plain_margins(), evaluate.hpp).
// Inline: out of line, its call made the compiler keep more of Newton's
// point in registers across it (3.7% more instructions in pw85_overlap
// once the dimension became a template; 1.5% inlined; callgrind).
template <int D>
PW85_INLINE Decision bounds_filter(PlainPoint<D> const &pt, PlainBounds const &b,
                       Filtering<D> const &s) noexcept {
  PlainMargins const m = plain_margins(b.cond, s.cond1, s.cond2);
  if (m.f < margin_limit && pt.f * (1.0 - m.f) > s.one)
    return Decision::disjoint;
  if (m.mu < margin_limit && std::max(b.mu1_sq, b.mu2_sq) * (1.0 + m.mu) < s.one)
    return Decision::overlap;
  // The second upper bound, for a double r only: its f(λ)·(1 + m.f) stands
  // for λμ1² + (1 − λ)μ2², and μ2² moves with r_lo by up to
  // ε·√(κ̄(Q2)·a2)/μ relative, which m.f (of κ̄(Q(λ)), not of Q2) need not
  // cover (overlap.hpp, overlap_dd()). Filter 4 carries r_lo in ρ.
  if (s.r_lo == nullptr &&
      moved_upper_bound(pt, b, std::max(s.p.a1, s.p.a2), m,
                        form_margin(s.cond1, s.cond2)) <
          s.one * (1.0 - 5.0 * DBL_EPSILON))
    return Decision::overlap;
  return Decision::undecided;
}

// Filter 4, near λ* (after a small Newton step), with bounds that hold for
// any vector ŝ (here the plain s = Q(λ)⁻¹r) and need no condition number,
// only the residual ρ = r − Q(λ)·ŝ computed as in twice the working
// precision (compensated.hpp):
//   lower: rᵀQ⁻¹r = max_y (2yᵀr − yᵀQy) ≥ 2ŝᵀr − ŝᵀQŝ = ŝᵀr + ŝᵀρ, so
//          μ² ≥ f(λ) ≥ λ(1 − λ)·(ŝᵀr + ŝᵀρ);
//   upper: x = c1 + (1 − λ)·Q1ŝ lies in ellipsoid 1 scaled by μ1 and in
//          ellipsoid 2 scaled by μ2 with μ1² = (1 − λ)²·ŝᵀQ1ŝ and, as
//          x − c2 = −(λQ2ŝ + ρ), μ2² = λ²·ŝᵀQ2ŝ + 2λ·ŝᵀρ + ρᵀQ2⁻¹ρ, so
//          μ² ≤ max(μ1², μ2²) (the bound of filter 3 at the exact point
//          of the computed ŝ), with ρᵀQ2⁻¹ρ ≤ ‖ρ‖²·tr(Q2⁻¹).
// Their rounding is a few ε relative plus terms of order 2⁻¹⁰⁰ of
// ‖ŝ‖₁·(|r| + tr Q·‖ŝ‖₁) (Q(λ) as hi + lo, the residual's and Dot2's
// second-order errors; |Qᵢⱼ| ≤ tr Q for a definite Q), bounded with
// margin below. The lower bound is f, second order in λ − λ*; the upper
// one first order: after a Newton step of relative size h ≤
// overlap_accurate_step, both lie within O(h²) of μ², and decide
// |μ² − 1| down to a few ulps. Outside [1 − 5ε, 1 + 5ε] only: the
// tangency band (tolerances.hpp) is the exact stage's.
template <int D>
PW85_INLINE Decision accurate_bounds(PlainPoint<D> const &pt,
                                     Filtering<D> const &s) noexcept {
  constexpr double eps = DBL_EPSILON;  // 2u
  constexpr double tiny = 0x1p-98;
  Problem<D> const &p = s.p;
  // tr(Q2⁻¹) from the factors of Q2 is within a few κ̄(Q2)·ε of its value:
  // within a factor 2 (taken below) while κ̄(Q2)·ε ≤ 1/8.
  if (!(s.cond2 * eps <= 0.125)) return Decision::undecided;
  double const lambda = pt.lambda;
  double const *const sv = pt.sol.s;
  double hi[sym_size(D)], lo[sym_size(D)], res[D];
  combine_dd<D>(lambda, p.q1, p.q2, hi, lo);
  compensated_residual<D>(hi, lo, p.r, sv, res);
  double s1 = 0.0, r_max = 0.0, abs_sr = 0.0, res2 = 0.0;
  for (int i = 0; i < D; ++i) {
    if (s.r_lo != nullptr) res[i] += s.r_lo[i];
    s1 += std::fabs(sv[i]);
    r_max = std::max(r_max, std::fabs(p.r[i]));
    abs_sr += std::fabs(sv[i] * res[i]);
    res2 += res[i] * res[i];
  }
  // ŝᵀr (+ ŝᵀr_lo) + ŝᵀρ, and the bound of its error beyond a few ε
  // relative: the rounding of ŝᵀρ and of ρ (ε·|ρ|), ρ's second-order part
  // and Q(λ)'s representation error (e_sq).
  double const sr = dot<D>(sv, res);
  double low = sr, abs_low = abs_sr;
  if (s.r_lo != nullptr) {
    low += dot<D>(s.r_lo, sv);
    for (int i = 0; i < D; ++i) abs_low += std::fabs(s.r_lo[i] * sv[i]);
  }
  double const e_sq = tiny * s1 * (r_max + pt.trace_q * s1);
  dd const sigma = dot_dd<D>(p.r, sv);  // ŝᵀr, r the double part
  double const rs = dd_add(sigma, low).hi;
  double const rs_err = 4.0 * eps * abs_low + e_sq;
  dd const mu = two_sum(1.0, -lambda);  // 1 − λ = mu.hi + mu.lo, exactly
  double const margin = 8.0 * eps;
  double const lower = lambda * mu.hi * (rs - rs_err) * (1.0 - margin);
  if (lower > s.one * (1.0 + 5.0 * eps)) return Decision::disjoint;
  // Pᵢ = ŝᵀQᵢŝ as Dot2 sums: error ε·Pᵢ + tiny·tr Qᵢ·‖ŝ‖₁².
  double const p1 =
      quad_form_acc<D>(p.q1, sv).value() + tiny * trace<D>(p.q1) * s1 * s1;
  double const p2 =
      quad_form_acc<D>(p.q2, sv).value() + tiny * trace<D>(p.q2) * s1 * s1;
  double const mu1_sq = mu.hi * mu.hi * p1 * (1.0 + margin);
  double const cross = 2.0 * lambda * (sr + 4.0 * eps * abs_sr + e_sq);
  // The margin on the sum of the terms' magnitudes: the cross term may be
  // negative, and of the order of the others where κ(Q(λ)) nears 1/ε.
  double const lam2_p2 = lambda_sq_times(lambda, p2),
               rho_q2 = 2.0 * p.tinv2 * res2;
  double const mu2_sq = lam2_p2 + cross + rho_q2 +
                        margin * (lam2_p2 + std::fabs(cross) + rho_q2);
  if (std::max(mu1_sq, mu2_sq) < s.one * (1.0 - 5.0 * eps))
    return Decision::overlap;
  // The moved point of moved_upper_bound() (evaluate.hpp) for this ŝ:
  // x = x0 + t·r with
  // x0 = c1 + (1 − λ)Q1ŝ and r the double part (any direction serves), so
  // that, as x − c2 = −(λQ2ŝ + ρ) + t·r,
  //   d1² = μ1² + 2t(1 − λ)·σ + t²·a1,
  //   d2² = μ2² − 2tλ·σ − 2t·ρᵀQ2⁻¹r + t²·a2,
  // σ = ŝᵀr, μᵢ² the two forms bounded above (mu1_sq, mu2_sq). With
  // t = g/(2σ), g = mu2_sq − mu1_sq (2tσ = g(1 + θ), |θ| ≤ ε with g and
  // t rounded), both lie
  // below λ·mu1_sq + (1 − λ)·mu2_sq + 2ε|g| + 2|t|·(e_σ + √(ρᵀQ2⁻¹ρ·a2))
  // + t²·max(aᵢ), |ρᵀQ2⁻¹r| ≤ √(ρᵀQ2⁻¹ρ)·√a2 (Cauchy–Schwarz), e_σ the
  // error of σ (Dot2: ε/2·|σ| plus the second-order e_sq), aᵢ off by m_a
  // as in filter 2; 8ε on the sum of non-negative terms for its rounding.
  double const m_a = form_margin(s.cond1, s.cond2);
  double const sig = sigma.hi + sigma.lo;
  if (m_a <= 0.125 && sig > 0.0) {
    double const m1 = std::max(mu1_sq, 0.0), m2 = std::max(mu2_sq, 0.0);
    double const g = m2 - m1;
    double const t = std::fabs(g / (2.0 * sig));
    double const a1 = p.a1 * (1.0 + m_a), a2 = p.a2 * (1.0 + m_a);
    double const e_sigma = eps * std::fabs(sig) + e_sq;
    double const moved =
        (lambda * m1 + mu.hi * m2 + 2.0 * eps * std::fabs(g) +
         2.0 * t * (e_sigma + std::sqrt(rho_q2 * a2)) +
         t * t * std::max(a1, a2)) *
        (1.0 + margin);
    if (moved < s.one * (1.0 - 5.0 * eps)) return Decision::overlap;
  }
  return Decision::undecided;
}

// accurate_bounds() for each dimension, compiled for CPUs with and without
// FMA.
PW85_FMA_CLONES
Decision accurate_filter(PlainPoint<2> const &pt,
                         Filtering<2> const &s) noexcept {
  return accurate_bounds(pt, s);
}

PW85_FMA_CLONES
Decision accurate_filter(PlainPoint<3> const &pt,
                         Filtering<3> const &s) noexcept {
  return accurate_bounds(pt, s);
}

// Where μ² rounds onto an edge of the tangency band, 1 ± 4ε (both
// doubles), the exact μ² may lie beyond it: up to ε/2 above 1 + 4ε, ε/4
// below 1 − 4ε (a held-out near-tangent pair: μ² − 1 = 4.49ε, rounded to
// 4ε). Decided by f at the search's λ in double-double: f(λ) ≤ μ², within
// about 2⁻¹⁰⁰ relative of it there (the finish's accuracy). Returns
// whether the exact μ² lies beyond the edge by more than 2⁻⁹⁶ relative,
// upper or lower (false where Q(λ) does not factorise, or the edge in the
// problem's scale is not exact: then the band, as before). The slack
// covers the rounding of f in double-double (up to 2⁻¹⁰⁵ relative
// measured, on circles whose exact μ² is 1 + 4ε itself: 844 of 8328 such
// calls answered 1 without it) and μ² − f(λ), second order in λ − λ*; the
// pairs of data/pw85_tangency_edges.txt lie 2⁻⁶⁰ or more from the edge.
template <int D>
PW85_INLINE bool beyond_band(Problem<D> const &p, double lambda, bool upper,
                             double const *r_lo) noexcept {
  double const edge_1 = upper ? 1.0 + tangency : 1.0 - tangency;
  double const edge = times_pow2(edge_1, -p.shift);  // μ² of the problem
  if (!(times_pow2(edge, p.shift) == edge_1)) return false;
  Compensated a;
  if (!evaluate_compensated<false, D>(lambda, p.r, p.q1, p.q2, p.moderate,
                                      nullptr, &a, r_lo))
    return false;
  double const above = (a.f - edge) + a.f_lo;  // f − edge, a.f − edge exact
  double const slack = 0x1p-96 * edge;
  return upper ? above > slack : above < -slack;
}

PW85_FMA_CLONES
bool beyond_band_at(Problem<2> const &p, double lambda, bool upper,
                    double const *r_lo) noexcept {
  return beyond_band(p, lambda, upper, r_lo);
}

PW85_FMA_CLONES
bool beyond_band_at(Problem<3> const &p, double lambda, bool upper,
                    double const *r_lo) noexcept {
  return beyond_band(p, lambda, upper, r_lo);
}

// The last stage: the exact contact function (steps 5 to 9 after Newton's
// result: μ² floored and scaled back as pw85_contact_function() returns
// it), for nearly tangent pairs or pairs too ill-conditioned for the
// bounds. 0 (tangent) exactly where the exact μ² lies within 4 ulps of 1,
// as pw85.h states.
template <bool Fast, int D>
Status exact_decision(Problem<D> const &p, NewtonResult<D> const &newton,
                      double const *r_lo, Decision *d) noexcept {
  double res[2];
  Status const status = solve_after_newton<Fast, D>(p, newton, res, r_lo);
  if (status != Status::success) return status;
  if (std::isnan(res[0])) return Status::out_of_range;  // as contact.cpp
  double const mu2 = floored_mu2(p, res[0]);
  double const off = std::fabs(mu2 - 1.0);  // exact near 1
  Decision const side = mu2 < 1.0 ? Decision::overlap : Decision::disjoint;
  *d = off < tangency ? Decision::tangent : side;
  // On an edge of the band: beyond it only where f at the search's λ says
  // so; a floored μ² (not the search's) stays in the band, as before.
  if (PW85_UNLIKELY(off == tangency) &&
      (mu2 != times_pow2(res[0], p.shift) ||
       !beyond_band_at(p, res[1], mu2 > 1.0, r_lo)))
    *d = Decision::tangent;
  return Status::success;
}

// Filters 3 and 4 at one plain point, reached by a step of relative size
// h. Where the plain bounds would decide without their margins, filter 3
// (its margins need κ̄(Q(λ)), a trace of Q⁻¹ from the factors), then, if
// the margins are too wide (an ill-conditioned Q(λ) or Qᵢ), filter 4,
// whose bounds are those of filter 3 to a few ulps. Elsewhere filter 4
// only near λ* (h ≤ overlap_accurate_step), where the plain bounds are
// within their rounding of 1.
template <int D>
PW85_INLINE Decision point_filters(PlainPoint<D> const &pt, double h,
                                   Filtering<D> const &s) noexcept {
  PlainBounds b;
  plain_mu_sq(pt, &b);
  if (pt.f > s.one || std::max(b.mu1_sq, b.mu2_sq) < s.one ||
      moved_bound_below(pt, b, s)) {
    Decision const d = plain_cond(pt, &b) ? bounds_filter(pt, b, s)
                                          : Decision::undecided;
    return d != Decision::undecided ? d : accurate_filter(pt, s);
  }
  return h <= overlap_accurate_step ? accurate_filter(pt, s)
                                    : Decision::undecided;
}

// The search's own Newton on ω from its start (step 4, newton_on_omega();
// for ellipses once filters 3 and 4 fail at λ0), with filters 3 and 4 at
// each of its points: the bounds hold at every λ, so each point is
// certified as the first; the
// intervals shrink onto μ² as λ → λ*, and the test decides as soon as one
// excludes 1, near contact after a few steps, without the search's
// certification and finish. Where Newton stops on a small step, up to
// overlap_extra_steps more Newton points, where the accurate bounds are
// tightest. Else the exact stage, continuing from Newton's result: its μ²
// is the contact function's, bit for bit.
template <bool Fast, int D>
Status decide(Filtering<D> const &s, Decision *d) noexcept {
  Problem<D> const &p = s.p;
  *d = Decision::undecided;
  auto const visit = [&s, d](PlainPoint<D> const &pt, double h) {
    *d = point_filters(pt, h, s);
    return *d != Decision::undecided;
  };
  double start = warm_start(p);
  if constexpr (D == 2) {
    // The filters at the warm start first (far from contact they decide
    // there, without the quartic's cost); else Newton from the root of the
    // quartic (warm_start.hpp, rational_start()).
    PlainPoint<D> pt;
    if (evaluate_terms<Fast>(start, p, &pt)) {
      *d = point_filters(pt, HUGE_VAL, s);
      if (*d != Decision::undecided) return Status::success;
    }
    start = rational_start(p, start);
  }
  NewtonResult<D> const newton =
      newton_on_omega<Fast>(p, start, warm_newton_iter, visit);
  if (*d != Decision::undecided) return Status::success;
  if (newton.stop == NewtonStop::small_step) {
    double lambda = newton.lambda;
    double h = std::fabs(lambda - newton.last.lambda) /
               std::min(newton.last.lambda, 1.0 - newton.last.lambda);
    for (int k = 0; k < overlap_extra_steps; ++k) {
      PlainPoint<D> pt;
      NewtonStep step;
      if (!evaluate_terms<Fast>(lambda, p, &pt)) break;
      *d = point_filters(pt, h, s);
      if (*d != Decision::undecided) return Status::success;
      if (!evaluate_omega(&pt) || !newton_step(pt, &step) ||
          !(step.next > 0.0 && step.next < 1.0) ||
          step.next == lambda)
        break;
      h = std::fabs(step.next - lambda) / std::min(lambda, 1.0 - lambda);
      lambda = step.next;
    }
  }
  return exact_decision<Fast, D>(p, newton, s.r_lo, d);
}

// overlap() of r + r_lo (r_lo: nullptr for 0).
template <int D>
PW85_INLINE Status decide_overlap(double const *r, double const *r_lo,
                                  double const *q1, double const *q2,
                                  int *result) noexcept {
  Problem<D> p;
  Status status = prepare(r, q1, q2, &p);
  if (status != Status::success) return status;
  if (p.r_is_zero) {  // μ² = 0
    *result = -1;
    return Status::success;
  }
  double const one = pow2(-p.shift);
  Decision d = sphere_filter(p, one);
  if (d == Decision::undecided) {
    Filtering<D> s = filtering(&p, one);
    d = centre_filter(s);
    if (d == Decision::undecided) {
      // The remaining stages in the problem's canonical orientation, so
      // that both argument orders take the same steps. (The filters above
      // are symmetric in Q1 and Q2 as they stand.)
      orient_filtering(&p, &s);
      // r_lo scaled as r (contact.cpp, search()).
      double lo[D];
      if (r_lo != nullptr) {
        for (int k = 0; k < D; ++k) lo[k] = times_pow2(r_lo[k], -p.r_exp);
        s.r_lo = lo;
      }
      status = p.moderate ? decide<true, D>(s, &d) : decide<false, D>(s, &d);
      if (status != Status::success) return status;
    }
  }
  *result = static_cast<int>(d);
  return Status::success;
}

}  // namespace

template <int D>
Status overlap_filters_at(double const *r, double const *q1, double const *q2,
                          double lambda, double one, int decisions[3]) noexcept {
  Problem<D> p;
  Status const status = prepare(r, q1, q2, &p);
  if (status != Status::success) return status;
  decisions[0] = decisions[1] = decisions[2] = 0;
  if (p.r_is_zero) return Status::success;
  Filtering<D> s = filtering(&p, times_pow2(one, -p.shift));
  orient_filtering(&p, &s);
  if (p.swapped) lambda = 1.0 - lambda;
  PlainPoint<D> pt;
  bool const ok = p.moderate ? evaluate_terms<true>(lambda, p, &pt)
                             : evaluate_terms<false>(lambda, p, &pt);
  if (!ok) return Status::success;
  PlainBounds b;
  plain_mu_sq(pt, &b);
  Decision const d[3] = {
      plain_cond(pt, &b) ? bounds_filter(pt, b, s) : Decision::undecided,
      accurate_filter(pt, s), point_filters(pt, 0.0, s)};
  for (int k = 0; k < 3; ++k)
    decisions[k] = d[k] == Decision::undecided ? 0 : static_cast<int>(d[k]);
  return Status::success;
}

template <int D>
Status overlap(double const *r, double const *q1, double const *q2,
               int *result) noexcept {
  return decide_overlap<D>(r, nullptr, q1, q2, result);
}

template <int D>
Status overlap_dd(double const *r, double const *r_lo, double const *q1,
                  double const *q2, int *result) noexcept {
  return decide_overlap<D>(r, r_lo, q1, q2, result);
}

template Status overlap<2>(double const *, double const *, double const *,
                           int *) noexcept;
template Status overlap<3>(double const *, double const *, double const *,
                           int *) noexcept;
template Status overlap_dd<2>(double const *, double const *, double const *,
                              double const *, int *) noexcept;
template Status overlap_dd<3>(double const *, double const *, double const *,
                              double const *, int *) noexcept;
template Status overlap_filters_at<2>(double const *, double const *,
                                      double const *, double, double,
                                      int[3]) noexcept;
template Status overlap_filters_at<3>(double const *, double const *,
                                      double const *, double, double,
                                      int[3]) noexcept;

}  // namespace pw85::detail
