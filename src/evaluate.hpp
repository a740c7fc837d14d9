// SPDX-License-Identifier: BSD-3-Clause
// f and the terms of Newton's step on ω at one λ, in plain double
// (private; docs/optimisation.rst, eqs. (5.1a)–(5.8)).
//
// The functions of the search take Fast = Problem::moderate as a template
// argument, so that each compiled search factorises Q(λ) one way
// (ldl_decomp_q()).
#ifndef PW85_SRC_EVALUATE_HPP
#define PW85_SRC_EVALUATE_HPP

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "compiler.hpp"
#include "ldl.hpp"
#include "problem.hpp"
#include "scaling.hpp"
#include "sym.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

// f(λ) = λ(1−λ)·rᵀ·Q(λ)⁻¹·r (docs/implementation.rst, eqs. (4.1)–(4.4)) in plain double:
// rᵀ·Q⁻¹·r = Σ zᵢ²/dᵢ with z = L⁻¹·r, one triangular solve instead of the
// two of ch. 4, eq. (4), no square root, and no cancellation. Returns false
// when Q(λ) does not factorise. fast: see ldl_decomp_q().
template <int D>
PW85_INLINE bool f_plain(double lambda, double const *r, double const *q1,
                         double const *q2, bool fast, double *value) noexcept {
  double q[sym_size(D)];
  combine<D>(lambda, q1, q2, q);
  Ldl<D> fac;
  if (!ldl_decomp_q(q, &fac, fast)) return false;
  *value = lambda * (1.0 - lambda) * ldl_quad_inverse(fac, r);
  return true;
}

// −f(λ), or 0 where Q(λ) fails to factorise (only possible through
// rounding) or f is not finite: 0 is f at the ends of [0, 1], which a
// maximisation never prefers. The objective of Brent's method, which
// needs a finite value everywhere.
template <bool Fast, int D>
PW85_INLINE double neg_f_or_zero(double lambda, Problem<D> const &p) noexcept {
  double value = 0.0;
  if (!f_plain<D>(lambda, p.r, p.q1, p.q2, Fast, &value) ||
      !std::isfinite(value))
    return 0.0;
  return -value;
}

// The plain evaluation at λ (ch. 5, eqs. (1a)–(1b)): Q(λ) factorised,
// s = Q(λ)⁻¹·r, Qᵢ·s, Pᵢ = sᵀ·Qᵢ·s, then f and
// ω(λ) = λ·ρ − (1 − λ) with ρ = √(P2/P1) (eq. (5.6)): ω = (μ2 − μ1)/√P1
// has the sign of g = μ2² − μ1² (ch. 5, eq. (4)) but is linear for two
// spheres and nearly so otherwise, where g varies sharply near λ = 0 or 1.
template <int D = dim>
struct PlainPoint {
  double lambda;
  double trace_q;       // tr(Q(λ))
  LdlSolution<D> sol;   // the factors of Q(λ) and s
  double q1s[D];        // Q1·s
  double q2s[D];        // Q2·s
  double p1, p2;        // Pᵢ = sᵀ·Qᵢ·s
  double root_p1;       // √P1
  double root_p2;       // √P2
  double f;             // as neg_f_or_zero() computes it, bit for bit
  double rho;           // ρ: 1/(1 + ρ) would be the root if ρ were constant
  double omega;         // ω(λ)
};

// The terms of a plain point up to Pᵢ (Q(λ) and its factors, s, Qᵢ·s,
// Pᵢ = sᵀ·Qᵢ·s) and *quad = rᵀ·Q(λ)⁻¹·r: false when Q(λ) does not
// factorise, or P1 or P2 is not > 0. The first part of evaluate_plain()
// and of evaluate_terms().
template <bool Fast, int D>
PW85_INLINE bool plain_terms(double lambda, Problem<D> const &p,
                             PlainPoint<D> *pt, double *quad) noexcept {
  double q[sym_size(D)];
  combine<D>(lambda, p.q1, p.q2, q);
  pt->lambda = lambda;
  pt->trace_q = trace<D>(q);
  Ldl<D> &fac = pt->sol.fac;
  if (!ldl_decomp_q(q, &fac, Fast)) return false;
  *quad = ldl_solve_quad(fac, p.r, pt->sol.s);  // rᵀ·Q(λ)⁻¹·r
  sym_mul<D>(p.q1, pt->sol.s, pt->q1s);
  sym_mul<D>(p.q2, pt->sol.s, pt->q2s);
  pt->p1 = dot<D>(pt->sol.s, pt->q1s);
  pt->p2 = dot<D>(pt->sol.s, pt->q2s);
  return pt->p1 > 0.0 && pt->p2 > 0.0;
}

// Returns false when Q(λ) does not factorise, P1 or P2 is not > 0, or f or
// ω is not finite.
template <bool Fast, int D>
PW85_INLINE bool evaluate_plain(double lambda, Problem<D> const &p,
                                PlainPoint<D> *pt) noexcept {
  double quad;
  if (!plain_terms<Fast>(lambda, p, pt, &quad)) return false;
  double const mu = 1.0 - lambda;
  pt->root_p1 = std::sqrt(pt->p1);
  pt->root_p2 = std::sqrt(pt->p2);
  pt->rho = pt->root_p2 / pt->root_p1;
  pt->f = lambda * mu * quad;  // the expression of f_plain()
  pt->omega = lambda * pt->rho - mu;
  return std::isfinite(pt->omega) && std::isfinite(pt->f);
}

// evaluate_plain() in two parts, the same operations, for a caller that
// may stop before ω: the overlap test, whose filters read all but √Pᵢ, ρ
// and ω. evaluate_terms() returns false when Q(λ) does not factorise, P1
// or P2 is not > 0, or f is not finite; evaluate_omega() when ω is not
// finite. (evaluate_plain() is not written as these two: gcc 12 then
// compiled the contact function's Newton loop otherwise, to as many
// instructions but 3% slower, measured.)
template <bool Fast, int D>
PW85_INLINE bool evaluate_terms(double lambda, Problem<D> const &p,
                                PlainPoint<D> *pt) noexcept {
  double quad;
  if (!plain_terms<Fast>(lambda, p, pt, &quad)) return false;
  pt->f = lambda * (1.0 - lambda) * quad;  // the expression of f_plain()
  return std::isfinite(pt->f);
}

template <int D>
PW85_INLINE bool evaluate_omega(PlainPoint<D> *pt) noexcept {
  double const lambda = pt->lambda;
  pt->root_p1 = std::sqrt(pt->p1);
  pt->root_p2 = std::sqrt(pt->p2);
  pt->rho = pt->root_p2 / pt->root_p1;
  pt->omega = lambda * pt->rho - (1.0 - lambda);
  return std::isfinite(pt->omega);
}

// Newton's step on ω from a plain point.
struct NewtonStep {
  double next;    // λ − ω/ω′
  double domega;  // ω′ = 1 + ρ + λρ′ (eq. (5.7))
};

// newton_step() where its formulas overflow: aᵢ or ρ′ alone beyond the
// range of doubles while λρ′ is not (λ near 2⁻⁵¹³ with forms 2¹⁰⁰⁰ apart:
// aᵢ ~ 2¹⁰³⁹, ρ′ ~ 2¹⁰²⁵; fuzz-geometry, regressions/newton-overflow).
// ρ′/ρ = a1/P1 − a2/P2 with y scaled by a power of two, then
// λρ′ = (λρ)·(ρ′/ρ), λρ being finite where ω is. Only called where
// newton_step()'s formulas give no finite step: elsewhere, steps are bit
// for bit as before. (An entry of y below 2^−1074 of the largest is then
// lost: this ω′ is a slope only, in a safeguarded step; λ is set by the
// sign or the compensated value of ω.)
template <int D>
PW85_INLINE bool scaled_step(PlainPoint<D> const &pt, double const *z1,
                             double const *z2, double *y,
                             NewtonStep *step) noexcept {
  double const lambda = pt.lambda;
  double ymax = 0.0;
  for (int i = 0; i < D; ++i) ymax = std::fmax(ymax, std::fabs(y[i]));
  if (!std::isfinite(ymax)) return false;  // y itself overflowed: no step
  int const k = exponent(ymax);
  for (int i = 0; i < D; ++i) y[i] = times_pow2(y[i], -k);
  double const ratio =
      times_pow2(dot<D>(z1, y) / pt.p1 - dot<D>(z2, y) / pt.p2, k);  // ρ′/ρ
  double const lambda_drho = lambda * pt.rho * ratio;                 // λρ′
  step->domega = 1.0 + pt.rho + lambda_drho;
  step->next = (1.0 + lambda * lambda_drho) / step->domega;
  return std::isfinite(step->next);
}

// Returns false when the step is not finite. With v = Q⁻¹·(Q2 − Q1)·s,
// s′ = −v (ch. 4, eq. (5)), so Pᵢ′ = −2·sᵀ·Qᵢ·v and
// ρ′ = (ρ/2)·(P2′/P2 − P1′/P1) (eq. (5.7)).
template <int D>
PW85_INLINE bool newton_step(PlainPoint<D> const &pt, NewtonStep *step) noexcept {
  Ldl<D> const &fac = pt.sol.fac;
  double const lambda = pt.lambda;
  double const p1 = pt.p1, p2 = pt.p2;
  // aᵢ = sᵀQᵢv = zᵢᵀ·D⁻¹·(z2 − z1) with zᵢ = L⁻¹Qᵢs, since
  // v = L⁻ᵀD⁻¹L⁻¹(Q2 − Q1)s: two forward substitutions side by side
  // instead of a forward and a backward one in a row.
  double z1[D], z2[D], y[D];
  ldl_forward(fac, pt.q1s, z1);
  ldl_forward(fac, pt.q2s, z2);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) y[i] = (z2[i] - z1[i]) * fac.inv_d[i];
  double const a1 = dot<D>(z1, y);
  double const a2 = dot<D>(z2, y);
  // ρ′/ρ = sᵀQ1v/P1 − sᵀQ2v/P2. The step λ − ω/ω′ is computed as
  // (1 + λ²ρ′)/ω′ (eq. (5.8)), which does not cancel when the root is far
  // smaller than λ (ρ ≫ 1: a thin disc), and with both terms multiplied by
  // c = √P1·P1·P2: then ρ·c = √P2·P1·P2 and ρ′·c = √P2·(a1·P2 − a2·P1)
  // need neither ρ nor a division, and the step waits for the square
  // roots and one division only. Unless c leaves the normal range.
  double const p12 = p1 * p2;
  double const c = pt.root_p1 * p12;
  if (c >= DBL_MIN && c <= DBL_MAX) {
    double const w = pt.root_p2 * (a1 * p2 - a2 * p1);           // ρ′·c
    double const den = (pt.root_p1 + pt.root_p2) * p12 + lambda * w;  // ω′·c
    step->next = (c + lambda * lambda * w) / den;
    step->domega = den / c;
  } else {
    double const drho = pt.rho * (a1 / p1 - a2 / p2);
    step->domega = 1.0 + pt.rho + lambda * drho;
    step->next = (1.0 + lambda * lambda * drho) / step->domega;
  }
  if (PW85_UNLIKELY(!std::isfinite(step->next)))
    return scaled_step(pt, z1, z2, y, step);
  return true;
}

// The bounds of μ² at a plain point (ch. 5, eqs. (1a)–(1b), (3.16)):
// f(λ) ≤ μ² ≤ max(μ1², μ2²), and κ̄(Q(λ)) for their rounding margins.
struct PlainBounds {
  double mu1_sq;  // μ1² = (1−λ)²·P1
  double mu2_sq;  // μ2² = λ²·P2
  double cond;    // κ̄(Q(λ)) = tr(Q)·tr(Q⁻¹) ≥ cond(Q(λ))
};

// λ²·p for λ in (0, 1): below 2⁻⁵¹¹, λ² would be subnormal and keep fewer
// than 53 bits, which the bounds' margins (ε-relative roundings) do not
// cover (μ2² 2e-6 low there made pw85_2d_overlap answer "overlap" for
// μ² = 1 + 11 ulps: fuzz-2d, regress-lambda-squared-underflow); then
// λ·(λ·p), whose intermediate is of order μ2²/λ. Elsewhere (λ ≥ 2⁻⁵¹¹)
// the product as before, bit for bit.
PW85_INLINE double lambda_sq_times(double lambda, double p) noexcept {
  return lambda >= 0x1p-511 ? lambda * lambda * p : lambda * (lambda * p);
}

// μ1² and μ2² of *b.
template <int D>
PW85_INLINE void plain_mu_sq(PlainPoint<D> const &pt, PlainBounds *b) noexcept {
  double const lambda = pt.lambda, mu = 1.0 - lambda;
  b->mu1_sq = mu * mu * pt.p1;
  b->mu2_sq = lambda_sq_times(lambda, pt.p2);
}

// κ̄ of *b (its margins' only cost, a trace of Q⁻¹ from the factors);
// returns false when it is not finite.
template <int D>
PW85_INLINE bool plain_cond(PlainPoint<D> const &pt, PlainBounds *b) noexcept {
  b->cond = pt.trace_q * ldl_trace_inverse(pt.sol.fac);
  return std::isfinite(b->cond);
}

// The relative margins of the plain bounds (tolerances.hpp, eq. (5.11)):
// aᵢ = rᵀQᵢ⁻¹r off by form_margin() (filter 2 of overlap.cpp), and at a
// point f(λ) by f and μᵢ² by mu (filter 3), from κ̄(Q(λ)) and κ̄(Qᵢ).
PW85_INLINE double form_margin(double cond1, double cond2) noexcept {
  return plain_form_margin * std::max(cond1, cond2);
}

struct PlainMargins {
  double f, mu;
};

PW85_INLINE PlainMargins plain_margins(double cond, double cond1,
                                       double cond2) noexcept {
  double const m_f = plain_form_margin * cond;
  return {m_f, m_f * (1.0 + std::sqrt(std::max(cond1, cond2)))};
}

// A second upper bound of μ² at a plain point, second order in λ − λ*
// where max(μ1², μ2²) is first order. At the point x0 = c1 + (1 − λ)·Q1s
// of the curve (s = Q(λ)⁻¹r), dᵢ² = μᵢ², dᵢ² being the form of ellipsoid i
// at a point; both ellipsoids scaled by max(d1(x), d2(x)) contain x, so
// μ² ≤ max(d1², d2²) at any point x (ch. 5, the argument of eq. (1b)). At
// x = x0 + t·r, since r = (1 − λ)Q1s + λQ2s,
//   d1² = μ1² + 2t(1 − λ)·sᵀr + t²·a1,   d2² = μ2² − 2tλ·sᵀr + t²·a2,
// with aᵢ = rᵀQᵢ⁻¹r. For t = g/(2sᵀr), g = μ2² − μ1², the terms of first
// order meet at λμ1² + (1 − λ)μ2² = f(λ) (f = λ(1 − λ)·sᵀr, and
// sᵀr = sᵀQs = (1 − λ)P1 + λP2), so that
//   μ² ≤ f(λ) + g²·max(a1, a2)/(4(sᵀr)²),   sᵀr = f/(λ(1 − λ)),
// within O(g²) = O((λ − λ*)²) of μ², as f is from below.
// Certified here with the margins m of plain_margins() and m_a of
// form_margin(): f off by m.f relative, μᵢ² by m.mu, aᵢ by m_a, so g by
// m.mu·(μ1² + μ2²) plus its rounding; while each margin is at most 1/8,
// the correction's factors are off by (1 + 1/8)/(1 − 1/8)² < 1.5, which
// the factor 2 (for ¼) covers. +∞ where a margin exceeds 1/8 (or f ≤ 0).
// a_max = max(a1, a2) as computed.
template <int D>
PW85_INLINE double moved_upper_bound(PlainPoint<D> const &pt,
                                     PlainBounds const &b, double a_max,
                                     PlainMargins const &m,
                                     double m_a) noexcept {
  if (!(std::max(m.f, std::max(m.mu, m_a)) <= 0.125 && pt.f > 0.0))
    return HUGE_VAL;
  double const g = std::fabs(b.mu2_sq - b.mu1_sq) * (1.0 + DBL_EPSILON) +
                   m.mu * (b.mu1_sq + b.mu2_sq);
  double const w = pt.lambda * (1.0 - pt.lambda) / pt.f;  // 1/(sᵀr)
  return pt.f * (1.0 + m.f) + 0.5 * g * g * a_max * w * w;
}

// All of *b; returns false when κ̄ is not finite.
template <int D>
PW85_INLINE bool plain_bounds(PlainPoint<D> const &pt, PlainBounds *b) noexcept {
  plain_mu_sq(pt, b);
  return plain_cond(pt, b);
}

}  // namespace pw85::detail

#endif  // PW85_SRC_EVALUATE_HPP
