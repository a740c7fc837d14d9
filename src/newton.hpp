// SPDX-License-Identifier: BSD-3-Clause
// Safeguarded Newton on ω in plain double (private; docs/optimisation.rst,
// steps 4 and 6).
#ifndef PW85_SRC_NEWTON_HPP
#define PW85_SRC_NEWTON_HPP

#include <algorithm>
#include <cmath>

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
};

// The last point where ω was evaluated, with what the later stages reuse.
struct LastPoint {
  double lambda;
  double f;       // as neg_f_or_zero() computes it (negated)
  double domega;  // ω′
  LdlSolution sol;
};

struct NewtonResult {
  double lambda;  // the estimate of the root: the last iterate
  LastPoint last;
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

// At most max_steps safeguarded Newton steps on ω from λ (eqs. (5.6)–(5.8)).
template <bool Fast>
NewtonResult newton_on_omega(Problem const &p, double lambda,
                             int max_steps) noexcept;

extern template NewtonResult newton_on_omega<true>(Problem const &, double,
                                                   int) noexcept;
extern template NewtonResult newton_on_omega<false>(Problem const &, double,
                                                    int) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_NEWTON_HPP
