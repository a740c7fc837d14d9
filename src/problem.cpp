// SPDX-License-Identifier: BSD-3-Clause
// The problem as the search solves it (problem.hpp).
#include "problem.hpp"

#include "checks.hpp"

namespace pw85::detail {

Status prepare_uncertified(double const q1[sym], double const q2[sym],
                           bool factorised) noexcept {
  if (!is_positive_definite(q1) || !is_positive_definite(q2))
    return Status::not_positive_definite;
  return factorised ? Status::success : Status::out_of_range;
}

}  // namespace pw85::detail
