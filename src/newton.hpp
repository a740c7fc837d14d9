// SPDX-License-Identifier: BSD-3-Clause
// Safeguarded Newton on ω in plain double (private; docs/optimisation.rst,
// steps 4 and 6).
#ifndef PW85_SRC_NEWTON_HPP
#define PW85_SRC_NEWTON_HPP

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "evaluate.hpp"
#include "ldl.hpp"
#include "problem.hpp"
#include "tolerances.hpp"
#include "warm_start.hpp"

namespace pw85::detail {

// An interval known to hold the root of ω: ω(0) = −1 < 0 < ω(1) = ρ(1),
// narrowed by the sign of every ω computed.
struct Bracket {
  double lo = 0.0;
  double hi = 1.0;
  bool contains(double x) const noexcept { return x > lo && x < hi; }
};

// Whether Newton's step from each end of [0, 1] was tried.
struct EndStepsTried {
  bool from_zero = false;
  bool from_one = false;
};

// The next iterate of the safeguarded Newton, from λ where ω(λ) ≠ 0 was
// computed with Newton iterate `newton` and ratio ρ: narrows *b with the
// sign of ω; a step leaving it takes Newton's step from the end of [0, 1]
// on the root's side (end_step(from_zero), at most once per end), else the
// sphere model's 1/(1 + ρ), else bisects. Returns NaN when no double lies
// strictly inside the bracket (the root is within an ulp of λ, one of its
// ends). A step that rounds onto λ = 1, where λ(1−λ) = 0, goes to the
// largest double below 1 instead. end_step: double(bool from_zero).
template <class EndStep>
double safeguard(double lambda, double omega, double newton, double rho,
                 Bracket *b, EndStepsTried *tried, EndStep end_step) noexcept {
  (omega < 0.0 ? b->lo : b->hi) = lambda;
  double next = newton;
  if (!b->contains(next)) {
    bool const from_zero = omega > 0.0;  // the root lies below λ
    bool &was_tried = from_zero ? tried->from_zero : tried->from_one;
    if (!was_tried) next = end_step(from_zero);
    was_tried = true;
  }
  if (!b->contains(next)) next = 1.0 / (1.0 + rho);
  if (next >= 1.0 && b->hi == 1.0) next = below_one;
  if (!b->contains(next)) next = 0.5 * (b->lo + b->hi);
  // (The midpoint rounds onto an end when no double lies between them.)
  return b->contains(next) ? next : NAN;
}

// Why newton_on_omega() stopped.
enum class NewtonStop {
  root,            // ω = 0 exactly at the last point
  small_step,      // the last step was at most newton_accept, relative
  no_double_left,  // no double strictly inside the bracket
  step_limit,      // the allowed number of steps was taken
  not_evaluable,   // Q(λ) failed to factorise, or a term was not finite
  visitor,         // the visitor stopped it
};

// The last point where ω was evaluated, with what the later stages reuse.
template <int D = dim>
struct LastPoint {
  double lambda;
  double f;       // as neg_f_or_zero() computes it (negated)
  double domega;  // ω′
  LdlSolution<D> sol;  // set only where the iteration converged
};

template <int D = dim>
struct NewtonResult {
  double lambda;  // the estimate of the root: the last iterate
  LastPoint<D> last;
  NewtonStop stop;
  Bracket bracket;

  // Converged to the resolution of the plain ω.
  bool converged() const noexcept {
    return stop == NewtonStop::root || stop == NewtonStop::small_step ||
           stop == NewtonStop::no_double_left;
  }
  // The estimate lies within tol of the last point evaluated, after
  // convergence: what was computed there may stand for the estimate.
  bool last_within(double tol) const noexcept {
    return converged() && std::fabs(lambda - last.lambda) <= tol;
  }
};

// Visits nothing (newton_on_omega()'s default).
struct NoVisit {
  template <int D>
  bool operator()(PlainPoint<D> const &, double) const noexcept {
    return false;
  }
};

// At most max_steps safeguarded Newton steps on ω from λ (eqs. (5.6)–(5.8)).
// visit(pt, h) is called at every point evaluated, with h the relative
// size of the step that led there (+∞ at the first), once its terms are
// (evaluate_terms()), before ω: true stops the iteration there
// (NewtonStop::visitor; the overlap test's filters, which decide on the
// way, and need no ω at the point where they decide). Without a visitor,
// the search's Newton.
template <bool Fast, int D, class Visit = NoVisit>
NewtonResult<D> newton_on_omega(Problem<D> const &p, double lambda,
                                int max_steps,
                                Visit &&visit = Visit{}) noexcept {
  // last.sol is read only after convergence (last_within()): it is set
  // at the three exits that converge, which leave from the point just
  // evaluated, and left unset otherwise (not evaluable, step limit, or a
  // visitor: the overlap test's common path). Copied at every point, it
  // cost the overlap test 1.5% of its instructions near contact, spent
  // mostly on reloading and recomputing the factors (gcc 12, callgrind).
  NewtonResult<D> out;
  out.lambda = lambda;
  out.last.lambda = lambda;
  out.last.f = 0.0;
  out.last.domega = 0.0;
  out.stop = NewtonStop::step_limit;
  EndStepsTried tried;
  auto const end_step = [&p](bool from_zero) {
    return step_from_end(p, from_zero);
  };
  double h = HUGE_VAL;  // the relative size of the step to λ
  // A visitor sees each point before its ω is computed; without one, the
  // point is evaluated at once (evaluate_plain(): the same operations, and
  // 1.1% fewer instructions in the contact function than in two parts;
  // gcc 12, callgrind).
  constexpr bool visits = !std::is_same_v<std::decay_t<Visit>, NoVisit>;
  for (int k = 0; k < max_steps; ++k) {
    PlainPoint<D> pt;
    NewtonStep step;
    if constexpr (visits) {
      if (!evaluate_terms<Fast>(lambda, p, &pt)) {
        out.stop = NewtonStop::not_evaluable;
        return out;
      }
      if (visit(pt, h)) {
        out.stop = NewtonStop::visitor;
        return out;
      }
      if (!evaluate_omega(&pt)) {
        out.stop = NewtonStop::not_evaluable;
        return out;
      }
    } else if (!evaluate_plain<Fast>(lambda, p, &pt)) {
      out.stop = NewtonStop::not_evaluable;
      return out;
    }
    if (!newton_step(pt, &step)) {
      out.stop = NewtonStop::not_evaluable;
      return out;
    }
    out.last.lambda = lambda;
    out.last.f = pt.f;
    out.last.domega = step.domega;
    NewtonStop stop = NewtonStop::root;  // ω = 0 exactly
    if (pt.omega != 0.0) {
      if (std::fabs(step.next - lambda) <=
          newton_accept * std::min(lambda, 1.0 - lambda)) {
        // Newton's convergence is quadratic: after a step this small, λ is
        // within ~1e-10 relative, about the rounding noise of the plain ω,
        // whose further steps (and the signs that set the bracket) would
        // only jitter. The compensated finish takes over.
        if (step.next > 0.0 && step.next < 1.0) out.lambda = step.next;
        stop = NewtonStop::small_step;
      } else {
        double const next = safeguard(lambda, pt.omega, step.next, pt.rho,
                                      &out.bracket, &tried, end_step);
        if (!std::isnan(next)) {
          h = std::fabs(next - lambda) / std::min(lambda, 1.0 - lambda);
          lambda = next;
          out.lambda = lambda;
          continue;
        }
        // λ, an end of the bracket inside (0, 1), is as close to the root
        // as doubles allow.
        stop = NewtonStop::no_double_left;
      }
    }
    // Converged, at this point.
    out.last.sol = pt.sol;
    out.stop = stop;
    return out;
  }
  return out;
}

}  // namespace pw85::detail

#endif  // PW85_SRC_NEWTON_HPP
