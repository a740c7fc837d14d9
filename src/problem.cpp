// SPDX-License-Identifier: BSD-3-Clause
// The problem as the search solves it (problem.hpp).
#include "problem.hpp"

#include "checks.hpp"

namespace pw85::detail {

template <int D>
Status prepare_uncertified(double const *q1, double const *q2,
                           bool factorised) noexcept {
  if (!is_positive_definite<D>(q1) || !is_positive_definite<D>(q2))
    return Status::not_positive_definite;
  return factorised ? Status::success : Status::out_of_range;
}

template Status prepare_uncertified<2>(double const *, double const *,
                                       bool) noexcept;
template Status prepare_uncertified<3>(double const *, double const *,
                                       bool) noexcept;

}  // namespace pw85::detail
