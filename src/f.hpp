// SPDX-License-Identifier: BSD-3-Clause
// f and the residual at a given λ, for pw85_f_neg() and pw85__residual()
// (private).
#ifndef PW85_SRC_F_HPP
#define PW85_SRC_F_HPP

#include "sym.hpp"

namespace pw85::detail {

// f(λ) = λ(1−λ)·rᵀ·Q(λ)⁻¹·r (docs/implementation.rst, eqs. (4.1)–(4.4)), compensated
// (compensated.hpp): accurate to about one ulp while cond(Q(λ)) is below
// ~1e10; never below 0 for λ in [0, 1]. Returns false when Q(λ) is not
// positive definite to the resolution of its factorisation.
// Specialised for D = 2 and 3 (f.cpp).
template <int D = dim>
bool f_compensated(double lambda, double const *r, double const *q1,
                   double const *q2, double *f) noexcept;

template <>
bool f_compensated<2>(double, double const *, double const *, double const *,
                      double *) noexcept;
template <>
bool f_compensated<3>(double, double const *, double const *, double const *,
                      double *) noexcept;

// out = {f(λ), g(λ), g′(λ)} with g = μ2² − μ1² (docs/optimisation.rst, eqs. (5.4)–(5.5)),
// f compensated, g and g′ in plain double from the Cholesky factors.
// Where Q(λ) is not positive definite, out holds NaN.
void residual(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double out[3]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_F_HPP
