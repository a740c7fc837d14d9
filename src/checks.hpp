// SPDX-License-Identifier: BSD-3-Clause
// Every validation of input, for both libraries (private).
#ifndef PW85_SRC_CHECKS_HPP
#define PW85_SRC_CHECKS_HPP

#include <cmath>

#include "compiler.hpp"
#include "ldl.hpp"
#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// True when the N entries of x are finite: x − x is 0 for finite x and NaN
// for NaN and ±∞. (The additions form a chain, but nothing waits for it:
// the branch on the result is predicted.)
template <int N>
PW85_INLINE bool all_finite(double const *x) noexcept {
  double acc = 0.0;
  PW85_UNROLL
  for (int i = 0; i < N; ++i) acc += x[i] - x[i];
  return acc == 0.0;
}

// The arguments of every function that evaluates f at λ (pw85_f_neg,
// pw85_2d_f_neg and the legacy f1, f2): no pointer NULL, λ and every entry
// of r (D), q1 and q2 (sym_size(D) each) finite.
template <int D = dim>
inline bool valid_f_input(double lambda, double const *r, double const *q1,
                          double const *q2) noexcept {
  return r != nullptr && q1 != nullptr && q2 != nullptr &&
         std::isfinite(lambda) && all_finite<D>(r) &&
         all_finite<sym_size(D)>(q1) && all_finite<sym_size(D)>(q2);
}

// Status::null_pointer if a pointer is NULL, Status::not_finite if an entry
// of r (D), q1 or q2 (sym_size(D) each) is not finite, Status::success
// otherwise. out is only tested against NULL. Inline: it runs on every
// call.
template <int D = dim>
inline Status check_pointers_and_finite(double const *r, double const *q1,
                                        double const *q2,
                                        void const *out) noexcept {
  if (r == nullptr || q1 == nullptr || q2 == nullptr || out == nullptr)
    return Status::null_pointer;
  if (!(all_finite<D>(r) && all_finite<sym_size(D)>(q1) &&
        all_finite<sym_size(D)>(q2)))
    return Status::not_finite;
  return Status::success;
}

// The definiteness rule of both libraries and both dimensions (pw85.h,
// pw85_2d.h): q is accepted when its entries are finite and it is positive
// definite exactly, as stored (Sylvester's criterion on the exact values of
// its doubles). Decided
// by ldl_certifies() on the factors of D·Q·D, D = diag(2^−hᵢ) the exact
// power-of-two scaling that brings the diagonal to [1/4, 2), where their
// rounding errors allow, else by exactly_positive_definite(): never wrong,
// however nearly singular q is, and whatever its scaling underflows.
template <int D = dim>
bool is_positive_definite(double const *q) noexcept;

// Sylvester's criterion evaluated exactly, in integer arithmetic
// (definite.cpp): Q00 > 0, Q00·Q11 − Q01² > 0, and in 3D det Q > 0. False
// for a non-finite entry.
template <int D = dim>
bool exactly_positive_definite(double const *q) noexcept;

extern template bool is_positive_definite<2>(double const *) noexcept;
extern template bool is_positive_definite<3>(double const *) noexcept;
extern template bool exactly_positive_definite<2>(double const *) noexcept;
extern template bool exactly_positive_definite<3>(double const *) noexcept;

// True when the factors f that ldl_decomp() computed from a (all pivots
// > 0), through trace_inverse = ldl_trace_inverse(f), prove a positive
// definite. A = L·D·Lᵀ, the exact product of the
// computed factors, is a − Δ with ‖Δ‖₂ ≤ γ·tr(|L|·D·|Lᵀ|) = γ·tr(A) for
// γ = γ₄ = 4u/(1 − 4u) (Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., Thm 10.3, for L·D·Lᵀ with n = 3; the reciprocal
// pivots add a rounding; n = 2 has fewer, and the same γ bounds them), plus at most 2^−1060 for results that underflowed, in the
// factorisation or in the scaling of a. Weyl: λmin(a) ≥ λmin(A) − ‖Δ‖₂,
// and λmin(A) ≥ 1/tr(A⁻¹) (ldl_trace_inverse()). So a is positive definite
// when tr(A⁻¹)·(γ·tr(A) + 2^−1060) < 1; 2^−48 (8γ₄) in place of γ covers
// the roundings of this test and of tr(A) from the diagonal of a. Decides
// forms with tr(a)·tr(a⁻¹) below about 2.8e14; beyond, or with an
// overflow (tr(A⁻¹) or tr(a) = +∞), false: not proven.
template <int D = dim>
PW85_INLINE bool ldl_certifies(double const *a, double trace_inverse) noexcept {
  constexpr double g = 0x1p-48;
  return trace_inverse * (g * trace<D>(a) + 0x1p-1060) < 1.0;
}

// The Cholesky factor of q (storage of cholesky.hpp) when q is positive
// definite by the rule above, else false: cholesky_decomp(), or, where one
// of its pivots rounds to ≤ 0 although the rule accepts q, L̃·√D/D from the
// factors of D·Q·D. False also when those meet a pivot ≤ 0: q positive
// definite but singular to the precision of double.
bool cholesky_by_rule(double const q[sym], double l[sym]) noexcept;

// check_pointers_and_finite(), then Status::not_positive_definite if q1 or
// q2 is not positive definite: the input contract of the legacy contact
// functions.
Status check_input(double const *r, double const *q1, double const *q2,
                   void const *out) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_CHECKS_HPP
