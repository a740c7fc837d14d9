// SPDX-License-Identifier: BSD-3-Clause
// The certified overlap test (private; docs/optimisation.rst, "The overlap
// test").
#ifndef PW85_SRC_OVERLAP_HPP
#define PW85_SRC_OVERLAP_HPP

#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// For input that passed check_pointers_and_finite(): *result = −1 when
// μ² < 1 (overlap), +1 when μ² > 1 (disjoint), 0 when |μ² − 1| ≤ 4ε
// (tangent). Returns Status::success, Status::not_positive_definite,
// Status::out_of_range or Status::no_memory, as contact_function().
template <int D = dim>
Status overlap(double const *r, double const *q1, double const *q2,
               int *result) noexcept;

// overlap() of r + r_lo, a double-double (|r_lo_k| ≤ ulp(r_k)/2; r_lo
// finite): the decision on the sign of μ²(r + r_lo) − 1 (the exact μ² of
// contact_function_dd() near tangency). The filters run on r: |r_lo| ≤
// ε/2·|r| moves rᵀA⁻¹r by a factor within 1 ± ε·√κ̄(A)·(1 + ε·√κ̄(A)) for
// every A = Q(λ) or Qᵢ (|r_lo|_A⁻¹ ≤ √cond(A)·ε/2·|r|_A⁻¹), μ² and every
// μᵢ² likewise (cond Q(λ) ≤ max cond Qᵢ), and |r|² by 1 ± 1.01ε: inside
// each filter's margin (tolerances.hpp: 16ε for the sphere bound's 7.5ε;
// 32ε·κ̄ for estimates off by 8ε·κ̄, which leaves 24ε·κ̄ ≥ 48ε·√κ̄ as
// κ̄ ≥ D² ≥ 4, ellipses included), so that a filter's decision holds for
// r + r_lo.
template <int D = dim>
Status overlap_dd(double const *r, double const *r_lo, double const *q1,
                  double const *q2, int *result) noexcept;

// For the tests: the filters of the search's points, each alone, at λ (of
// the input's order) against the threshold `one` in place of 1 (μ² < one
// or > one): decisions[0] from filter 3 (the plain bounds with margins),
// [1] filter 4 (the accurate bounds), [2] the two as the search chains
// them near λ* (point_filters() with a step of size 0): −1 (μ² < one), +1
// (μ² > one), 0 undecided or Q(λ) not factorised. Statuses as overlap();
// decisions all 0 for r = 0.
template <int D = dim>
Status overlap_filters_at(double const *r, double const *q1, double const *q2,
                          double lambda, double one, int decisions[3]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_OVERLAP_HPP
