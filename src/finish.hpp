// SPDX-License-Identifier: BSD-3-Clause
// The compensated finish of the search (private; docs/optimisation.rst,
// step 7).
#ifndef PW85_SRC_FINISH_HPP
#define PW85_SRC_FINISH_HPP

#include "ldl.hpp"
#include "problem.hpp"

namespace pw85::detail {

template <int D = dim>
struct FinishStart {
  double lambda;  // where the compensated steps start
  double domega;  // the plain ω′ there (or nearby): the first slope; NaN
                  // if none is known
  // The plain factors and solution at lambda, when the caller has them
  // (Newton's last point), else nullptr.
  LdlSolution<D> const *plain;
  // nullptr, or the low part of the problem's r (scaled as p.r): the
  // compensated evaluations are then those of p.r + r_lo
  // (compensated_from()).
  double const *r_lo;
};

struct Finished {
  double lambda;
  double mu2;    // μ² of the problem
  double slope;  // the least of the start's plain ω′ and the secants
                 // (NaN if no step was accepted)
};

// Compensated Newton steps on ω (slope: start.domega first, then secants),
// at most finish_iter evaluations, until a step is at most finish_accept
// (relative). μ² is then the quadratic model's maximum (eq. (5.10)),
// f(λ) + ½·f′(λ)·Δλ with f′ = −g = −√P1·ω·(μ1 + μ2), the gain added to the
// double-double f before it is rounded, and never below the largest
// compensated f evaluated (each is a lower bound of μ², to rounding). When
// the steps do not settle, the largest f evaluated and its λ. Returns false
// when Q(λ) failed to factorise at the start (rounding only).
// One function per dimension, each compiled for CPUs with and without FMA
// (PW85_FMA_CLONES); the dimension-generic body is finish_steps()
// (finish.cpp).
bool finish(Problem<2> const &p, FinishStart<2> const &start,
            Finished *out) noexcept;
bool finish(Problem<3> const &p, FinishStart<3> const &start,
            Finished *out) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_FINISH_HPP
