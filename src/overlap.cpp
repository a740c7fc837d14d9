// SPDX-License-Identifier: BSD-3-Clause
// The certified overlap test (overlap.hpp): a chain of filters, cheapest
// first, each deciding only where its rounding margin (tolerances.hpp)
// makes the answer certain, ending with the exact μ² (as Shewchuk's
// adaptive predicates end with the exact sign).
#include "overlap.hpp"

#include <algorithm>
#include <cmath>

#include "compiler.hpp"
#include "contact.hpp"
#include "evaluate.hpp"
#include "ldl.hpp"
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
struct Filtering {
  Problem const &p;
  double one;
  double cond1, cond2;  // κ̄(Q1), κ̄(Q2)
  double a1, a2;        // rᵀQ1⁻¹r, rᵀQ2⁻¹r
  double const *r_lo;   // nullptr, or the low part of p.r (overlap_dd())
};

// Filter 1, no factorisation needed: the sphere bound μ² ≥
// |r|²/(√tr Q1 + √tr Q2)², already a certified lower bound, compared
// times 2^8 (256·one is exact, or +∞ where it does not decide).
Decision sphere_filter(Problem const &p, double one) noexcept {
  return sphere_lower_bound_x256(p) > 256.0 * one ? Decision::disjoint
                                                  : Decision::undecided;
}

// Filter 2, from the factors of Q1 and Q2: at λ = 0 and 1 the point x0 is
// a centre, so μ² ≤ min(rᵀQ1⁻¹r, rᵀQ2⁻¹r), each off by a few κ̄(Qᵢ)·ε
// relative (plain_form_margin).
Decision centre_filter(Filtering const &s) noexcept {
  double const m_a = plain_form_margin * std::max(s.cond1, s.cond2);
  if (m_a < margin_limit && std::min(s.a1, s.a2) * (1.0 + m_a) < s.one)
    return Decision::overlap;
  return Decision::undecided;
}

// Filter 3, the bounds valid at every λ (ch. 5, eqs. (1a)–(1b)):
// f(λ) ≤ μ² because μ² is the maximum of f; μ² ≤ max(μ1², μ2²) because
// the point x0(λ) lies in both ellipsoids scaled by max(μ1, μ2), which
// therefore meet. Margins of eq. (5.11): f is off by a few κ̄(Q(λ))·ε
// relative, μᵢ² (a quadratic form in s) by that times √κ̄(Qᵢ).
Decision bounds_filter(PlainPoint const &pt, PlainBounds const &b,
                       Filtering const &s) noexcept {
  double const cond_q = std::sqrt(std::max(s.cond1, s.cond2));
  double const m_f = plain_form_margin * b.cond;
  double const m_mu = plain_form_margin * b.cond * (1.0 + cond_q);
  if (m_f < margin_limit && pt.f * (1.0 - m_f) > s.one)
    return Decision::disjoint;
  if (m_mu < margin_limit && std::max(b.mu1_sq, b.mu2_sq) * (1.0 + m_mu) < s.one)
    return Decision::overlap;
  return Decision::undecided;
}

// Filter 3 at the warm start (eq. (5.9)), then (rarely needed) one Newton
// step on ω further.
template <bool Fast>
Decision bounds_filters(Filtering const &s) noexcept {
  double lambda = warm_start(s.a1, s.a2);
  for (int k = 0; k < 2; ++k) {
    PlainPoint pt;
    PlainBounds b;
    if (!evaluate_plain<Fast>(lambda, s.p, &pt) || !plain_bounds(pt, &b))
      break;
    Decision const d = bounds_filter(pt, b, s);
    if (d != Decision::undecided) return d;
    NewtonStep step;
    if (k == 1 || !newton_step(pt, &step)) break;
    double next = step.next;
    if (!(next > 0.0 && next < 1.0)) next = 1.0 / (1.0 + pt.rho);
    if (!(next > 0.0 && next < 1.0)) break;
    lambda = next;
  }
  return Decision::undecided;
}

// The last stage: the exact contact function, for nearly tangent pairs or
// pairs too ill-conditioned for the plain bounds.
template <bool Fast>
Status exact_decision(Problem const &p, double const *r_lo,
                      Decision *d) noexcept {
  double res[2];
  Status const status = solve<Fast>(p, res, r_lo);
  if (status != Status::success) return status;
  double const mu2 = std::ldexp(res[0], p.shift);
  *d = std::fabs(mu2 - 1.0) <= tangency
           ? Decision::tangent
           : (mu2 < 1.0 ? Decision::overlap : Decision::disjoint);
  return Status::success;
}

template <bool Fast>
Status decide(Filtering const &s, Decision *d) noexcept {
  *d = bounds_filters<Fast>(s);
  if (*d != Decision::undecided) return Status::success;
  return exact_decision<Fast>(s.p, s.r_lo, d);
}

// overlap() of r + r_lo (r_lo: nullptr for 0).
PW85_INLINE Status decide_overlap(double const r[dim], double const *r_lo,
                                  double const q1[sym], double const q2[sym],
                                  int *result) noexcept {
  Problem p;
  Status status = prepare(r, q1, q2, &p);
  if (status != Status::success) return status;
  if (p.r_is_zero) {  // μ² = 0
    *result = -1;
    return Status::success;
  }
  double const one = pow2(-p.shift);
  Decision d = sphere_filter(p, one);
  if (d == Decision::undecided) {
    quads(&p);
    Filtering const s{p,
                      one,
                      trace(p.q1) * p.tinv1,  // κ̄(Q1) (ldl_cond_bound())
                      trace(p.q2) * p.tinv2,
                      p.a1,
                      p.a2,
                      nullptr};
    d = centre_filter(s);
    if (d == Decision::undecided) {
      // The remaining stages in the problem's canonical orientation, so
      // that both argument orders take the same steps. (The filters above
      // are symmetric in Q1 and Q2 as they stand.)
      orient(&p);
      // r_lo scaled as r (contact.cpp, search()).
      double lo[dim];
      if (r_lo != nullptr)
        for (int k = 0; k < dim; ++k) lo[k] = times_pow2(r_lo[k], -p.r_exp);
      Filtering const t{p,       one,  s.cond1,
                        s.cond2, p.a1, p.a2,
                        r_lo != nullptr ? lo : nullptr};
      status = p.moderate ? decide<true>(t, &d) : decide<false>(t, &d);
      if (status != Status::success) return status;
    }
  }
  *result = static_cast<int>(d);
  return Status::success;
}

}  // namespace

Status overlap(double const r[dim], double const q1[sym], double const q2[sym],
               int *result) noexcept {
  return decide_overlap(r, nullptr, q1, q2, result);
}

Status overlap_dd(double const r[dim], double const r_lo[dim],
                  double const q1[sym], double const q2[sym],
                  int *result) noexcept {
  return decide_overlap(r, r_lo, q1, q2, result);
}

}  // namespace pw85::detail
