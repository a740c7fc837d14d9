// SPDX-License-Identifier: BSD-3-Clause
// The compensated finish of the search (finish.hpp).
#include "finish.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "compensated.hpp"
#include "compiler.hpp"
#include "scaling.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

namespace {

// ω = λρ − (1 − λ), ρ = √(P2/P1) (eq. (5.6)), from compensated P1 and P2.
PW85_INLINE double omega_of(double lambda, Compensated const &a) noexcept {
  return lambda_rho(lambda, a.p1, a.p2) - (1.0 - lambda);
}

// The quadratic model's gain over f(λ) for the Newton step Δλ = −step
// (eq. (5.10)): ½·f′·Δλ = ½·√P1·ω·(μ1 + μ2)·step, with μ1 = (1−λ)√P1 and
// μ2 = λ√P2 (Pᵢ = a.pᵢ·2^p_exp).
PW85_INLINE double model_gain(double lambda, Compensated const &a,
                              double omega, double step) noexcept {
  double const root_p1 = std::sqrt(a.p1);
  double const sum_mu = (1.0 - lambda) * root_p1 + lambda * std::sqrt(a.p2);
  // √P1·(μ1 + μ2) back to scale first: it is of order μ², however small
  // the scaled P1 and P2 are.
  double const scale = a.p_exp == 0 ? root_p1 * sum_mu
                                     : times_pow2(root_p1 * sum_mu, a.p_exp);
  return 0.5 * scale * omega * step;
}

// What the finish returns when no step ends it: the largest compensated f
// seen (each a lower bound of μ², to rounding), and the λ where the
// compensated |ω| was smallest, the estimate of its root (not the λ of
// that f: on a flat maximum the f differ by their rounding only, and the
// largest may lie far from the root).
struct Best {
  double f = 0.0;
  double lambda = 0.0;
  double abs_omega = HUGE_VAL;
  bool any = false;
  void see(double f_at, double lambda_at, double omega_at) noexcept {
    if (!any || f_at > f) f = f_at;
    if (!any || std::fabs(omega_at) < abs_omega)
      lambda = lambda_at, abs_omega = std::fabs(omega_at);
    any = true;
  }
};

template <int D>
PW85_INLINE bool finish_steps(Problem<D> const &p, FinishStart<D> const &start,
                              Finished *out) noexcept {
  double lambda = start.lambda;
  // The slope of the next step, and whether it is local: the start's plain
  // ω′ (at or next to the start) is; a secant is where its two points lie
  // within finish_local of each other (relative to the nearer end of
  // [0, 1]) or within 4 steps. Only a local slope ends the iteration: a
  // secant through a far point can be many times the slope at λ where ω
  // bends (a flat maximum: ω′ 7.5e-4 at λ = 1.2e-4 and a secant of 350
  // through λ/1024, on a fuzzing input), and its step then looks converged
  // long before λ is.
  double domega = start.domega;
  bool local = true;
  // The least slope seen (the start's ω′ and every secant), for the
  // flatness test (contact.cpp, 7b): where Q(λ) is ill-conditioned the
  // plain ω′ and a secant through ω's rounding noise may both exceed the
  // slope by orders of magnitude (3.7e8 and 8e5 against about 1e3 on a
  // fuzzing input, regress-flat-least-slope), while a secant over a wider
  // base still shows it.
  double least = start.domega;
  // The plain factors and solution at the current λ, where known: those
  // of the start, if given, until λ moves.
  LdlSolution<D> const *plain = start.plain;
  Best best;
  double prev_lambda = 0.0, prev_omega = 0.0;
  // The root of the compensated ω lies in (lo, hi): narrowed by the sign of
  // every ω computed here, which is reliable (unlike that of the plain ω
  // when Q(λ) is ill-conditioned) where |ω| exceeds its rounding; w_lo < 0
  // and w_hi > 0 are ω at lo and hi once evaluated there (NaN before).
  double lo = 0.0, hi = 1.0, w_lo = NAN, w_hi = NAN;
  // The bracket's size (relative to the nearer end of [0, 1]; log-scale
  // while its ends differ by more than a factor 4) and the step's length,
  // one and two evaluations ago: where neither has halved in two
  // evaluations (a secant of rounding noise crawling), a bisection.
  double size_before[2] = {HUGE_VAL, HUGE_VAL};
  double move_before[2] = {HUGE_VAL, HUGE_VAL};
  int fall = 10;  // the exponent of the next fallback step towards an end
  for (int evaluations = 1; evaluations <= finish_iter; ++evaluations) {
    Compensated a;
    if (!evaluate_compensated<true, D>(lambda, p.r, p.q1, p.q2, p.moderate,
                                       plain, &a, start.r_lo))
      break;
    double const omega = omega_of(lambda, a);
    best.see(a.f, lambda, omega);
    if (omega == 0.0) {  // the root, to the resolution of doubles
      out->lambda = lambda;
      out->slope = least;
      out->mu2 = std::max(a.f + a.f_lo, best.f);
      return true;
    }
    if (omega < 0.0) lo = std::max(lo, lambda), w_lo = omega;
    if (omega > 0.0) hi = std::min(hi, lambda), w_hi = omega;
    double const near = std::min(lambda, 1.0 - lambda);
    // The slope: after the first evaluation, the secant through the
    // previous point (positive and finite, as ω′ is), or none: a stale
    // slope is not carried over.
    if (evaluations > 1) {
      domega = NAN;
      if (lambda != prev_lambda && std::isfinite(omega)) {
        double const secant = (omega - prev_omega) / (lambda - prev_lambda);
        if (secant > 0.0 && secant < HUGE_VAL) {
          domega = secant;
          least = std::fmin(least, secant);
          double const width = std::fabs(lambda - prev_lambda);
          local = width <= finish_local * near ||
                  width <= 4.0 * std::fabs(omega / secant);
        }
      }
    }
    // Newton's step (NaN without a usable slope).
    double const step =
        domega > 0.0 && domega < HUGE_VAL ? omega / domega : NAN;
    double next = lambda - step;
    if (local && next > 0.0 && next < 1.0 &&
        std::fabs(step) <= finish_accept * near) {
      double const gain = model_gain(lambda, a, omega, step);
      if (gain >= 0.0 && gain <= max_model_gain * a.f) {
        out->lambda = next;
        // For the flatness test (contact.cpp, 7b): the least slope seen.
        // A secant through ω's rounding noise can exceed ω′ by orders of
        // magnitude (14.6 against 5e-6 on a fuzzing input), and hide a
        // flat maximum.
        out->slope = least;
        // The gain is added to f before f is rounded: it can reach an ulp.
        out->mu2 = std::max(a.f + (a.f_lo + gain), best.f);
        return true;
      }
    }
    if (std::isnan(step) && evaluations == 1) {
      // No slope at the start (Newton did not converge there): a probe
      // 2^−20 away, relative to the nearer end, towards the root, so that
      // the next slope is a local secant.
      double const d = (omega > 0.0 ? -1.0 : 1.0) * 0x1p-20;
      next = lambda <= 0.5 ? lambda * (1.0 + d) : 1.0 - (1.0 - lambda) * (1.0 - d);
    } else if (!(next > lo && next < hi) && w_lo < 0.0 && w_hi > 0.0) {
      // Both ends evaluated: the secant through them (regula falsi), inside
      // the bracket.
      next = lo - w_lo * ((hi - lo) / (w_hi - w_lo));
    }
    // The bracket's size, log-scale where its ends differ by more than a
    // factor 4 relative to the nearer end of [0, 1].
    // (+∞ while it touches an end of [0, 1].)
    double const size = !(lo > 0.0 && hi < 1.0) ? HUGE_VAL
                        : hi <= 0.5 && hi > 4.0 * lo ? std::log2(hi / lo)
                        : lo >= 0.5 && 1.0 - lo > 4.0 * (1.0 - hi)
                            ? std::log2((1.0 - lo) / (1.0 - hi))
                            : (hi - lo) / std::min(lo, 1.0 - hi);
    double const move = std::fabs(next - lambda);
    bool const stalled = evaluations > 2 && size < HUGE_VAL &&
                         !(size <= 0.5 * size_before[0]) &&
                         !(move <= 0.5 * move_before[0]);
    size_before[0] = size_before[1];
    size_before[1] = size;
    move_before[0] = move_before[1];
    move_before[1] = move;
    if (!(next > lo && next < hi) || stalled) {
      // Newton's step leaves the bracket (a start far from the root, with
      // a slope that rounding made meaningless), or the bracket does not
      // shrink: a step into the bracket instead, towards the end of [0, 1]
      // it reaches by 2^−10, 2^−20, 2^−40, … (a root near an end may be
      // 2^−1000 from it), or to its geometric middle relative to the
      // nearer end while its ends differ by more than a factor 4, else to
      // its middle.
      // (Not below DBL_MIN: a λ* below it is not found to the accuracy
      // pw85.h states.)
      if (lo == 0.0) {
        next = std::max(times_pow2(hi, -fall), DBL_MIN);
      } else if (hi == 1.0) {
        next = 1.0 - times_pow2(1.0 - lo, -fall);
      } else if (hi <= 0.5 && hi > 4.0 * lo) {
        next = std::sqrt(lo) * std::sqrt(hi);
      } else if (lo >= 0.5 && 1.0 - lo > 4.0 * (1.0 - hi)) {
        next = 1.0 - std::sqrt(1.0 - lo) * std::sqrt(1.0 - hi);
      } else {
        next = 0.5 * (lo + hi);
      }
      if (lo == 0.0 || hi == 1.0) fall = std::min(2 * fall, 1100);
      if (!(next > lo && next < hi)) break;
    }
    prev_lambda = lambda;
    prev_omega = omega;
    lambda = next;
    plain = nullptr;
  }
  if (!best.any) return false;
  out->lambda = best.lambda;
  out->mu2 = best.f;
  out->slope = NAN;
  return true;
}

}  // namespace

PW85_FMA_CLONES
bool finish(Problem<2> const &p, FinishStart<2> const &start,
            Finished *out) noexcept {
  return finish_steps(p, start, out);
}

PW85_FMA_CLONES
bool finish(Problem<3> const &p, FinishStart<3> const &start,
            Finished *out) noexcept {
  return finish_steps(p, start, out);
}

}  // namespace pw85::detail
