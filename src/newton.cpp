// SPDX-License-Identifier: BSD-3-Clause
// Safeguarded Newton on ω in plain double (newton.hpp).
#include "newton.hpp"

#include "evaluate.hpp"

namespace pw85::detail {

template <bool Fast>
NewtonResult newton_on_omega(Problem const &p, double lambda,
                             int max_steps) noexcept {
  NewtonResult out{lambda, LastPoint{lambda, 0.0, 0.0, {}},
                   NewtonStop::step_limit, Bracket{}};
  EndStepsTried tried;
  auto const end_step = [&p](bool from_zero) {
    return step_from_end(p, from_zero);
  };
  for (int k = 0; k < max_steps; ++k) {
    PlainPoint pt;
    NewtonStep step;
    if (!evaluate_plain<Fast>(lambda, p, &pt) || !newton_step(pt, &step)) {
      out.stop = NewtonStop::not_evaluable;
      return out;
    }
    out.last = LastPoint{lambda, pt.f, step.domega, pt.sol};
    if (pt.omega == 0.0) {
      out.stop = NewtonStop::root;
      return out;
    }
    if (std::fabs(step.next - lambda) <=
        newton_accept * std::min(lambda, 1.0 - lambda)) {
      // Newton's convergence is quadratic: after a step this small, λ is
      // within ~1e-10 relative, about the rounding noise of the plain ω,
      // whose further steps (and the signs that set the bracket) would
      // only jitter. The compensated finish takes over.
      if (step.next > 0.0 && step.next < 1.0) out.lambda = step.next;
      out.stop = NewtonStop::small_step;
      return out;
    }
    double const next = safeguard(lambda, pt.omega, step.next, pt.rho,
                                  &out.bracket, &tried, end_step);
    if (std::isnan(next)) {
      // λ, an end of the bracket inside (0, 1), is as close to the root as
      // doubles allow.
      out.stop = NewtonStop::no_double_left;
      return out;
    }
    lambda = next;
    out.lambda = lambda;
  }
  return out;
}

template NewtonResult newton_on_omega<true>(Problem const &, double,
                                            int) noexcept;
template NewtonResult newton_on_omega<false>(Problem const &, double,
                                             int) noexcept;

}  // namespace pw85::detail
