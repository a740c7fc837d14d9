// SPDX-License-Identifier: BSD-3-Clause
// The polish of λ (private, header-only): Newton steps on ω(λ) evaluated
// in double-double, for the contact geometry (geometry.cpp) and for a
// contact function whose maximum is flat (contact.cpp). Inlined, and
// compiled for the target of the caller (PW85_FMA_CLONES).
#ifndef PW85_SRC_POLISH_HPP
#define PW85_SRC_POLISH_HPP

#include <algorithm>
#include <cmath>

#include "compensated.hpp"
#include "compiler.hpp"
#include "dd.hpp"
#include "evaluate.hpp"
#include "problem.hpp"
#include "scaling.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

// A usable solution: finite, with a finite low part, and not zero.
template <int D = dim>
PW85_INLINE bool usable(double const *s, double const *s_lo) noexcept {
  bool nonzero = false;
  for (int i = 0; i < D; ++i) nonzero = nonzero || s[i] != 0.0;
  return all_finite<D>(s) && all_finite<D>(s_lo) && nonzero;
}

// s = Q(λ)⁻¹·r as s + s_lo (tolerances.hpp, geometry_refine_cond); false
// when no factorisation succeeds, or s is not finite or is zero (both only
// far beyond the domain).
template <int D>
PW85_INLINE bool solve_accurately(Problem<D> const &p, double lambda,
                                  double *s, double *s_lo) noexcept {
  double hi[sym_size(D)], lo[sym_size(D)];
  combine_dd<D>(lambda, p.q1, p.q2, hi, lo);
  Ldl<D> fac;
  bool const plain = ldl_decomp(hi, &fac);
  if (plain && ldl_cond_bound(hi, fac) <= geometry_refine_cond) {
    double rho[D], ds[D];
    ldl_solve(fac, p.r, s);
    compensated_residual<D>(hi, lo, p.r, s, rho);
    ldl_solve(fac, rho, ds);
    split_sum<D>(s, ds, s, s_lo);
    if (usable<D>(s, s_lo)) return true;
  }
  if (solve_dd<D>(lambda, p.r, p.q1, p.q2, s, s_lo) && usable<D>(s, s_lo))
    return true;
  // Beyond the domain (entries spanning most of the range of a double),
  // where even the double-double factors fail: the plain solve, if any.
  if (!plain) return false;
  ldl_solve(fac, p.r, s);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) s_lo[i] = 0.0;
  return usable<D>(s, s_lo);
}

// sᵀ·A·s for s = s + s_lo, as a double-double: the products of s exact
// (Dot2), the tail to first order, 2·(A·s)·s_lo.
template <int D>
PW85_INLINE dd quad_form_dd2(double const *a, double const *s,
                             double const *s_lo) noexcept {
  Dot2 acc = quad_form_acc<D>(a, s);
  double t[D];
  sym_mul<D>(a, s, t);
  acc.err += 2.0 * dot<D>(t, s_lo);
  return two_sum(acc.sum, acc.err);
}

// ω(λ) = λ·√(P2/P1) − (1 − λ) (eq. (5.6) of docs/optimisation.rst) in
// double-double from s = Q(λ)⁻¹·r as s + s_lo, rounded once: at a flat
// maximum (small ω′), the error of ω in double alone, a few ε, would move
// its root by a few ε/ω′ (2e-12 relative where f″·λ²/μ² = −1.5e-5).
// s is scaled to order one first (Pᵢ do not underflow; ρ is unchanged).
template <int D>
PW85_INLINE double omega_dd(double lambda, Problem<D> const &p, double *s,
                            double *s_lo) noexcept {
  scale_for_p<D>(s, s_lo);
  dd const p1 = quad_form_dd2<D>(p.q1, s, s_lo);
  dd const p2 = quad_form_dd2<D>(p.q2, s, s_lo);
  // P2 scaled by an even power of two towards P1 (exact), so that ρ does
  // not overflow where λ·ρ is near 1 (lambda_rho()).
  int e = exponent(p2.hi) - exponent(p1.hi);
  e -= e % 2;
  dd const p2s{times_pow2(p2.hi, -e), times_pow2(p2.lo, -e)};
  dd const rho_s = dd_mul(dd_sqrt(dd_div(p2s, p1)), lambda);
  dd const lambda_rho{times_pow2(rho_s.hi, e / 2), times_pow2(rho_s.lo, e / 2)};
  return dd_round(dd_sub(lambda_rho, two_sum(1.0, -lambda)));
}

// Newton steps on ω in double-double (omega_dd(); its root is λ*, the
// maximiser of f: docs/theory.rst): the slope only sets the rate, the
// compensated ω sets the root. The slope is the plain ω′ (eq. (5.7)) at
// the first point (the plain point is evaluated only then, and where no
// secant serves), then the secant through the last two compensated ω
// where it is positive and finite: where Q(λ) is so ill-conditioned that
// the plain ω′ is off by a few percent, Newton with it converges only
// linearly, and a step of polish_accept left λ 2e-11 off (fuzz-geometry,
// ω′ = 2.5e-12 at λ* = 0.087, cond(Qᵢ) near 1e15).
// Returns the polished λ (the last one reached where an evaluation fails);
// a step larger than the trust radius (relative, polish_max_step at
// first) is clamped to it, and the radius doubles while the clamped steps
// leave the sign of ω unchanged (the root is still ahead: ω increases
// with λ), up to polish_max_radius; it falls back to polish_max_step once
// ω changes sign. Found by fuzz-geometry: λ 0.6 % off from the search at
// a maximum so flat that eight steps of 1e-3 fell short (tests/fuzz/
// corpus/contact-raw/regress-geo-flat-*).
template <bool Fast, int D>
PW85_INLINE double polish(Problem<D> const &p, double lambda0) noexcept {
  double lambda = lambda0;
  double prev_lambda = NAN, prev_omega = NAN;
  double radius = polish_max_step;
  for (int k = 0; k < polish_iter; ++k) {
    double s[D], s_lo[D];
    if (!solve_accurately(p, lambda, s, s_lo)) break;
    double const omega = omega_dd(lambda, p, s, s_lo);
    double slope = (omega - prev_omega) / (lambda - prev_lambda);
    bool const by_secant = slope > 0.0 && slope < HUGE_VAL;
    if (!by_secant) {
      // The plain ω′ (eq. (5.7)), evaluated only where no secant serves.
      PlainPoint<D> pt;
      NewtonStep plain_step;
      if (!evaluate_plain<Fast>(lambda, p, &pt) ||
          !newton_step(pt, &plain_step))
        break;
      slope = plain_step.domega;
    }
    // The signs through copysign, not std::signbit: unoptimised, libstdc++'s
    // std::signbit(double) is emitted as a weak symbol of default
    // visibility, which the static archive must not export (check-archive).
    if ((std::copysign(1.0, omega) < 0.0) !=
        (std::copysign(1.0, prev_omega) < 0.0))
      radius = polish_max_step;
    prev_lambda = lambda;
    prev_omega = omega;
    double const step = omega / slope;
    double const size = std::min(lambda, 1.0 - lambda);
    if (std::isnan(step)) break;
    if (!(std::fabs(step) <= radius * size)) {
      // A trust region: the step clamped, towards the root that the sign
      // of the compensated ω gives.
      lambda -= std::copysign(radius * size, omega);
      radius = std::min(2.0 * radius, polish_max_radius);
      continue;
    }
    double const next = lambda - step;
    // A small step ends the polish when its slope is a secant of the
    // compensated ω, accurate to about the previous step's size; with the
    // plain ω′, only below polish_plain_accept. The plain ω′ may be off by
    // far more than its rounding suggests (0.2 % at λ* = 9.7e-165 with Q1
    // nearly singular, where the plain ω had the wrong sign: a step of
    // 1.6e-10 relative then left λ 3e-13 off; fuzz-geometry,
    // corpus/contact-raw/regress-geo-plain-slope-*).
    double const accept = by_secant ? polish_accept : polish_plain_accept;
    bool const done = std::fabs(step) <= accept * size;
    lambda = next;
    if (done) break;
  }
  return lambda;
}

}  // namespace pw85::detail

#endif  // PW85_SRC_POLISH_HPP
