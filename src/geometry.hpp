// SPDX-License-Identifier: BSD-3-Clause
// The contact point, the common normal and the first derivatives of μ²,
// from the maximiser of the search (private; docs/theory.rst, eqs. (3.8)–(3.14);
// docs/geometry.rst).
#ifndef PW85_SRC_GEOMETRY_HPP
#define PW85_SRC_GEOMETRY_HPP

#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// Offsets of the outputs (pw85.h, PW85_GEOM_* and PW85_DERIV_*).
namespace geom {
constexpr int mu2 = 0, lambda = 1, point = 2, normal = 5, size = 8;
}  // namespace geom
namespace deriv {
constexpr int r12 = 0, rot1 = 3, rot2 = 6, q1 = 9, q2 = 15, size = 21;
}  // namespace deriv

// pw85_contact_geometry() (d == nullptr) and pw85_contact_derivatives(),
// for input that passed check_pointers_and_finite(). Returns
// Status::success; Status::out_of_range with every output written when one
// overflows; the statuses of contact_search() with nothing written; or
// Status::out_of_range, nothing written, when Q(λ) does not factorise at
// the maximiser, in double-double nor in double (far beyond the domain:
// entries spanning most of the range of a double).
Status contact_geometry(double const r[dim], double const q1[sym],
                        double const q2[sym], double geometry[geom::size],
                        double d[deriv::size]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_GEOMETRY_HPP
