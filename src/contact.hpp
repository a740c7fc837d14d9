// SPDX-License-Identifier: BSD-3-Clause
// The contact function μ² = max f over [0, 1] (private; docs/optimisation.rst;
// docs/optimisation.rst, "The algorithm").
#ifndef PW85_SRC_CONTACT_HPP
#define PW85_SRC_CONTACT_HPP

#include "newton.hpp"
#include "problem.hpp"
#include "status.hpp"

namespace pw85::detail {

// The search (steps 2–9) on input that passed check_pointers_and_finite(),
// stopped before λ is mapped back to the input's orientation: for the
// functions that go on from the maximiser (geometry.cpp).
template <int D = dim>
struct Contact {
  Problem<D> p;   // prepared; quads() and orient() done unless p.r_is_zero
  double mu2;     // μ² of the input: scaled back, floored; +∞ on overflow
  double lambda;  // the maximiser of the problem (1 − λ of the input's
                  // when p.swapped); ½ when p.r_is_zero
};

// Returns Status::success (c->mu2 may be +∞), or the status of prepare()
// (*c is then incomplete), or Status::no_memory.
template <int D>
Status contact_search(double const *r, double const *q1, double const *q2,
                      Contact<D> *c) noexcept;

// The contact function for input that passed check_pointers_and_finite():
// out = {μ², λ}. Returns Status::success, Status::not_positive_definite,
// Status::out_of_range (out[0] = +∞ when μ² overflows, out[1] = λ) or
// Status::no_memory.
template <int D = dim>
Status contact_function(double const *r, double const *q1, double const *q2,
                        double out[2]) noexcept;

// contact_function() of r + r_lo, a double-double (|r_lo_k| ≤
// ulp(r_k)/2; r_lo finite): μ² correctly rounded for r + r_lo, as
// contact_function() for r. The plain stages of the search (steps 3 to 6)
// run on r, which moves their λ by O(ε) relative; the compensated finish
// (step 7) evaluates f at r + r_lo (compensated_from()) and lands on the
// maximiser of that f. For the spatial index (src/index/broad.hpp).
template <int D = dim>
Status contact_function_dd(double const *r, double const *r_lo,
                           double const *q1, double const *q2,
                           double out[2]) noexcept;

// Steps 3 to 7 on a prepared problem with r ≠ 0: out = {μ² of the problem
// (unscaled, unfloored), λ}. Fast = p.moderate. r_lo: nullptr, or the low
// part of p.r, scaled as p.r (contact_function_dd()).
template <bool Fast, int D>
Status solve(Problem<D> const &p, double out[2],
             double const *r_lo = nullptr) noexcept;

// Steps 5 to 7, after step 4's Newton from the start of step 3 (newton:
// its result, as newton_on_omega<Fast>(p, start, warm_newton_iter) returns
// it, start being warm_start(p), then for ellipses rational_start(), or
// stopped earlier by a visitor): solve() is step 4, then
// this. The overlap test runs step 4 itself with its filters as the
// visitor, and continues here when they do not decide.
template <bool Fast, int D>
Status solve_after_newton(Problem<D> const &p, NewtonResult<D> newton,
                          double out[2], double const *r_lo) noexcept;

// The templates of this header are defined in contact.cpp and
// instantiated there for D = 2 and 3 (Fast true and false).

// Steps 8 and 9: μ² of the problem (solve()'s out[0]) floored at the
// rigorous sphere bound where it falls below it, or is NaN (beyond the
// documented domain, where the computed f can be meaningless), then
// scaled back to the input's: the μ² of pw85_contact_function(), also for
// the overlap test's exact stage (overlap.cpp), so that the two agree.
template <int D>
double floored_mu2(Problem<D> const &p, double mu2) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_CONTACT_HPP
