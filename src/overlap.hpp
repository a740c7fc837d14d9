// SPDX-License-Identifier: BSD-3-Clause
// The certified overlap test (private; docs/optimisation.rst, "The overlap
// test").
#ifndef PW85_SRC_OVERLAP_HPP
#define PW85_SRC_OVERLAP_HPP

#include "status.hpp"
#include "sym3.hpp"

namespace pw85::detail {

// For input that passed check_pointers_and_finite(): *result = −1 when
// μ² < 1 (overlap), +1 when μ² > 1 (disjoint), 0 when |μ² − 1| ≤ 4ε
// (tangent). Returns Status::success, Status::not_positive_definite,
// Status::out_of_range or Status::no_memory, as contact_function().
Status overlap(double const r[dim], double const q1[sym], double const q2[sym],
               int *result) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_OVERLAP_HPP
