// SPDX-License-Identifier: BSD-3-Clause
// Certification of the maximum of f by GSL's Brent minimiser on −f
// (private; docs/optimisation.rst, step 5). brent_certify.cpp is the only
// file of the search that includes GSL (principal_axes.cpp, outside it,
// uses GSL's eigensolver).
#ifndef PW85_SRC_BRENT_CERTIFY_HPP
#define PW85_SRC_BRENT_CERTIFY_HPP

#include "problem.hpp"
#include "status.hpp"

namespace pw85::detail {

// GSL's Brent minimiser, given a bracket [a, b], evaluates its objective
// first at a + golden·(b − a) (gsl/min/brent.c, brent_init).
// golden_bracket() returns in *a, *b a bracket of width about w about c
// (c − 0.38·w to c + 0.62·w) for which that point, computed in double, is
// c itself, nearly always. 0 < w, and c ± w finite.
extern double const gsl_brent_golden;
void golden_bracket(double c, double w, double *a, double *b) noexcept;

struct BrentResult {
  double estimate;  // Brent's λ
  double lower;     // its final bracket
  double upper;
};

// Brent's method on −f about λ, where −f = neg_f (as neg_f_or_zero()
// computes it): on a bracket verified to enclose the maximum,
// golden_bracket() of width first_bracket_width, widened by bracket_growth
// while rounding noise in f (up to cond(Q)·ε) defeats the check, up to
// [0, 1] where f(0) = f(1) = 0. Iterates until the bracket is narrower than
// PW85_LAMBDA_ATOL, at most max_iter times. Returns Status::success, or
// Status::no_memory should GSL's Brent state outgrow the space reserved
// for it.
template <bool Fast, int D>
Status certify_with_brent(Problem<D> const &p, double lambda, double neg_f,
                          int max_iter, BrentResult *out) noexcept;

#define PW85_CERTIFY_WITH_BRENT(Fast, D)                                    \
  Status certify_with_brent<Fast, D>(Problem<D> const &, double, double, \
                                     int, BrentResult *) noexcept
extern template PW85_CERTIFY_WITH_BRENT(true, 2);
extern template PW85_CERTIFY_WITH_BRENT(false, 2);
extern template PW85_CERTIFY_WITH_BRENT(true, 3);
extern template PW85_CERTIFY_WITH_BRENT(false, 3);

}  // namespace pw85::detail

#endif  // PW85_SRC_BRENT_CERTIFY_HPP
