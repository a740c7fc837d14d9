// SPDX-License-Identifier: BSD-3-Clause
// The Cholesky factorisation and solve of docs/implementation.rst, "Implementation 1", as exposed by
// pw85__cholesky_decomp() and pw85__cholesky_solve() (private).
// L is stored l[0]=L00 l[1]=L10 l[2]=L20 l[3]=L11 l[4]=L21 l[5]=L22.
#ifndef PW85_SRC_CHOLESKY_HPP
#define PW85_SRC_CHOLESKY_HPP

#include "sym.hpp"

namespace pw85::detail {

// A = L·Lᵀ. Returns false, with l partly written, when a pivot is not > 0
// (A not positive definite to the resolution of the factorisation, or NaN).
bool cholesky_decomp(double const a[sym], double l[sym]) noexcept;

// Solves L·y = b (forward substitution). y may alias b.
void forward_solve(double const l[sym], double const b[dim],
                   double y[dim]) noexcept;

// Solves L·Lᵀ·x = b. x may alias b.
void cholesky_solve(double const l[sym], double const b[dim],
                    double x[dim]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_CHOLESKY_HPP
