// SPDX-License-Identifier: BSD-3-Clause
// Every validation of input, for both libraries (private).
#ifndef PW85_SRC_CHECKS_HPP
#define PW85_SRC_CHECKS_HPP

#include "compiler.hpp"
#include "status.hpp"
#include "sym3.hpp"

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

// The arguments of every function that evaluates f at λ (pw85_f_neg and
// the legacy f1, f2): no pointer NULL, λ and every entry of r (3), q1 and
// q2 (6 each) finite.
bool valid_f_input(double lambda, double const *r, double const *q1,
                   double const *q2) noexcept;

// Status::null_pointer if a pointer is NULL, Status::not_finite if an entry
// of r (3), q1 or q2 (6 each) is not finite, Status::success otherwise.
// out is only tested against NULL. Inline: it runs on every call.
inline Status check_pointers_and_finite(double const *r, double const *q1,
                                        double const *q2,
                                        void const *out) noexcept {
  if (r == nullptr || q1 == nullptr || q2 == nullptr || out == nullptr)
    return Status::null_pointer;
  if (!(all_finite<dim>(r) && all_finite<sym>(q1) && all_finite<sym>(q2)))
    return Status::not_finite;
  return Status::success;
}

// The definiteness rule of both libraries (pw85.h): q is positive definite
// when the L·D·Lᵀ factorisation (ldl_decomp()) of D·Q·D has positive
// pivots, D = diag(2^−hᵢ) the exact power-of-two scaling that brings the
// diagonal of Q to [1/4, 1). Such a scaling changes none of the roundings
// of the factorisation (barring underflow), so the rule decides as the
// factorisation of Q itself, or of Q scaled by any power of two, would
// (prepare() in problem.cpp), and no square overflows or underflows however
// widely the diagonal entries range. False for a non-finite entry.
bool is_positive_definite(double const q[sym]) noexcept;

// The Cholesky factor of q (storage of cholesky.hpp) when q is positive
// definite by the rule above, else false: cholesky_decomp(), or, where one
// of its pivots rounds to ≤ 0 although the rule accepts q, L̃·√D/D from the
// rule's factors (so that the two never disagree).
bool cholesky_by_rule(double const q[sym], double l[sym]) noexcept;

// check_pointers_and_finite(), then Status::not_positive_definite if q1 or
// q2 is not positive definite: the input contract of the legacy contact
// functions.
Status check_input(double const *r, double const *q1, double const *q2,
                   void const *out) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_CHECKS_HPP
