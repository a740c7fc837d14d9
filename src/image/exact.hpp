// SPDX-License-Identifier: BSD-3-Clause
// The exact sign of a sum of products of doubles: the last stage of the
// point-in-ellipsoid predicates of the voxel image (raster.cpp), reached
// only when their floating-point filter cannot certify a sign.
#ifndef PW85_SRC_IMAGE_EXACT_HPP
#define PW85_SRC_IMAGE_EXACT_HPP

namespace pw85::detail {

// At most this many factors in a monomial.
inline constexpr int exact_max_factors = 8;

// coef·f[0]·…·f[nf − 1]: coef a small integer (|coef| ≤ 4), nf ≤
// exact_max_factors, every f finite (subnormals included).
struct Monomial {
  int coef;
  int nf;
  double f[exact_max_factors];
};

// The sign (−1, 0, +1) of Σ m[t] over count monomials (count ≤ 256),
// computed without rounding: each product is formed as an integer times a
// power of two and summed into a fixed-point integer wide enough for every
// finite double (no overflow, no underflow, no dependence on the
// floating-point environment).
int exact_sign(Monomial const *m, int count) noexcept;

}  // namespace pw85::detail

#endif
