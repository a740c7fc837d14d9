// SPDX-License-Identifier: BSD-3-Clause
// The quadratic form of a spheroid (private).
#ifndef PW85_SRC_SPHEROID_HPP
#define PW85_SRC_SPHEROID_HPP

#include "sym.hpp"

namespace pw85::detail {

// Q = a²·I + (c² − a²)·n·nᵀ (docs/theory.rst, eq. (3.2) for a spheroid), each entry
// from a double-double evaluation rounded once.
void spheroid(double a, double c, double const n[dim], double q[sym]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_SPHEROID_HPP
