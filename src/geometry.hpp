// SPDX-License-Identifier: BSD-3-Clause
// The contact point, the common normal and the first derivatives of μ²,
// from the maximiser of the search (private; docs/theory.rst, eqs. (3.8)–(3.14);
// docs/geometry.rst).
#ifndef PW85_SRC_GEOMETRY_HPP
#define PW85_SRC_GEOMETRY_HPP

#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// Offsets of the outputs in D dimensions (pw85.h, PW85_GEOM_* and
// PW85_DERIV_*; pw85_2d.h, PW85_2D_GEOM_* and PW85_2D_DERIV_*). The
// geometry: μ², λ, the contact point (D), the normal (D). The derivatives
// of μ²: by r12 (D), by a rotation of each form about its centre (a
// rotation vector in 3D, an angle in 2D: rot_size entries each), by the
// stored entries of each form (sym_size(D) each).
template <int D>
struct Outputs {
  static constexpr int mu2 = 0, lambda = 1, point = 2, normal = 2 + D,
                       size = 2 + 2 * D;
  static constexpr int rot_size = D == 3 ? 3 : 1;
  static constexpr int r12 = 0, rot1 = D, rot2 = D + rot_size,
                       q1 = D + 2 * rot_size, q2 = q1 + sym_size(D),
                       deriv_size = q2 + sym_size(D);
};

namespace geom {
using O = Outputs<dim>;
constexpr int mu2 = O::mu2, lambda = O::lambda, point = O::point,
              normal = O::normal, size = O::size;
}  // namespace geom
namespace deriv {
using O = Outputs<dim>;
constexpr int r12 = O::r12, rot1 = O::rot1, rot2 = O::rot2, q1 = O::q1,
              q2 = O::q2, size = O::deriv_size;
}  // namespace deriv

// pw85_contact_geometry() (d == nullptr) and pw85_contact_derivatives(),
// and their 2D counterparts (D = 2; geometry of Outputs<D>::size doubles,
// d of Outputs<D>::deriv_size), for input that passed
// check_pointers_and_finite(). Returns
// Status::success; Status::out_of_range with every output written when one
// overflows; the statuses of contact_search() with nothing written; or
// Status::out_of_range, nothing written, when Q(λ) does not factorise at
// the maximiser, in double-double nor in double (far beyond the domain:
// entries spanning most of the range of a double).
template <int D = dim>
Status contact_geometry(double const *r, double const *q1, double const *q2,
                        double *geometry, double *d) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_GEOMETRY_HPP
