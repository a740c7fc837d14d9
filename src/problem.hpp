// SPDX-License-Identifier: BSD-3-Clause
// The problem as the search solves it: the rescaled input and the
// factorisations of Q1 and Q2 (docs/optimisation.rst, step 2).
#ifndef PW85_SRC_PROBLEM_HPP
#define PW85_SRC_PROBLEM_HPP

#include <cmath>

#include "checks.hpp"
#include "compiler.hpp"
#include "ldl.hpp"
#include "scaling.hpp"
#include "status.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

template <int D = dim>
struct Problem : Scaled<D> {
  Ldl<D> f1;   // Q1 = L·D·Lᵀ
  Ldl<D> f2;   // Q2 = L·D·Lᵀ
  double a1;   // rᵀ·Q1⁻¹·r
  double a2;   // rᵀ·Q2⁻¹·r
  double tinv1;  // tr(Q1⁻¹) (ldl_trace_inverse() of f1)
  double tinv2;  // tr(Q2⁻¹)
  // Q1 and Q2 (with their factors and aᵢ) were exchanged by orient(): the
  // problem's λ is then 1 − λ of the input (f(λ; Q1, Q2) = f(1−λ; Q2, Q1)).
  bool swapped;
};

// aᵢ = rᵀ·Qᵢ⁻¹·r from the factors.
template <int D>
inline void quads(Problem<D> *p) noexcept {
  p->a1 = ldl_quad_inverse(p->f1, p->r);
  p->a2 = ldl_quad_inverse(p->f2, p->r);
}

// After quads(): puts the problem in its canonical orientation, the one whose sphere-model
// maximiser (eq. (5.9)) is at most ½: a1 ≥ a2, ties broken by the stored
// entries. Both argument orders of the input, (r, Q1, Q2) and (−r, Q2, Q1),
// then give the same problem bit for bit (aᵢ and the rescaling are even in
// r and symmetric in Q1, Q2), hence the same μ², and λ ↔ 1 − λ; and a
// maximiser near 1 is computed as one near 0, in the variable that keeps
// its digits (1 − λ* may not be representable as 1 − a double, but it is
// as a double).
// Q1 and Q2 exchanged, with their factors and what is derived from them;
// λ becomes 1 − λ and p->swapped flips.
template <int D>
inline void exchange_forms(Problem<D> *p) noexcept {
  constexpr int n = sym_size(D);
  p->swapped = !p->swapped;
  for (int k = 0; k < n; ++k) {
    double const t = p->q1[k];
    p->q1[k] = p->q2[k];
    p->q2[k] = t;
  }
  Ldl<D> const f = p->f1;
  p->f1 = p->f2;
  p->f2 = f;
  double const a = p->a1;
  p->a1 = p->a2;
  p->a2 = a;
  double const t = p->tinv1;
  p->tinv1 = p->tinv2;
  p->tinv2 = t;
}

template <int D>
inline void orient(Problem<D> *p) noexcept {
  constexpr int n = sym_size(D);
  bool swap = p->a1 < p->a2;
  if (p->a1 == p->a2) {  // the first entry that differs decides
    int k = 0;
    while (k < n && p->q1[k] == p->q2[k]) ++k;
    swap = k < n && p->q2[k] < p->q1[k];
  }
  p->swapped = false;
  if (swap) exchange_forms(p);
}

// prepare() where the factors of the rescaled forms did not prove them
// positive definite (problem.cpp): the rule of checks.hpp on the forms as
// stored decides Status::not_positive_definite; a form that passes but
// that could not be factorised once rescaled with the other
// (factorised false: its diagonal spans, with the other's, more than
// max_diagonal_span, or it is singular to the precision of double) gives
// Status::out_of_range; else Status::success (the factors stand).
template <int D>
Status prepare_uncertified(double const *q1, double const *q2,
                           bool factorised) noexcept;

extern template Status prepare_uncertified<2>(double const *, double const *,
                                              bool) noexcept;
extern template Status prepare_uncertified<3>(double const *, double const *,
                                              bool) noexcept;

// rescale(), then the factorisations of Q1 and Q2, which prove them
// positive definite (ldl_certifies()) on the fast path; else the rule of
// checks.hpp decides, on the forms as stored (prepare_uncertified()). aᵢ
// are not yet computed (quads()), nor the problem oriented (orient()).
// Input: finite. Returns Status::success, Status::not_positive_definite or
// Status::out_of_range. Inline: it runs on every call.
template <int D>
inline Status prepare(double const *r, double const *q1, double const *q2,
                      Problem<D> *p) noexcept {
  p->swapped = false;
  bool const factorised = rescale<D>(r, q1, q2, p) &&
                          ldl_decomp(p->q1, &p->f1) &&
                          ldl_decomp(p->q2, &p->f2);
  if (PW85_UNLIKELY(!factorised))
    return prepare_uncertified<D>(q1, q2, false);
  p->tinv1 = ldl_trace_inverse(p->f1);
  p->tinv2 = ldl_trace_inverse(p->f2);
  if (PW85_UNLIKELY(!(ldl_certifies<D>(p->q1, p->tinv1) &&
                      ldl_certifies<D>(p->q2, p->tinv2))))
    return prepare_uncertified<D>(q1, q2, true);
  return Status::success;
}

// tr(Q)·2^−8, the terms scaled before they are summed (exact, barring
// underflow), so that the sum does not overflow.
template <int D>
PW85_INLINE double scaled_trace(double const *q) noexcept {
  constexpr double s = 0x1p-8;
  double t = s * q[0];
  PW85_UNROLL
  for (int i = 1; i < D; ++i) t += s * q[Layout<D>::diag[i]];
  return t;
}

// A lower bound of μ² valid for every input, times 2^8: each ellipsoid
// lies in the sphere of radius √λmax(Qᵢ) ≤ √tr(Qᵢ) about its centre, and
// those spheres meet only once scaled by |r|/(√tr Q1 + √tr Q2). Computed
// with a few roundings, whatever the conditioning of Q1 and Q2: the factor
// 1 − sphere_margin keeps it a lower bound. The diagonal entries are
// scaled by 2^−8 (exactly, barring underflow of entries far below the
// largest, which changes the traces by less than the margin), which
// changes no rounding: no trace or square overflows, however close the
// rescaled diagonals come to 2^1024 (which rescale() allows), and the
// result is a normal double.
template <int D>
inline double sphere_lower_bound_x256(Problem<D> const &p) noexcept {
  double const radii = std::sqrt(scaled_trace<D>(p.q1)) +
                       std::sqrt(scaled_trace<D>(p.q2));  // true radii / 16
  return dot<D>(p.r, p.r) / (radii * radii) * (1.0 - sphere_margin);
}

}  // namespace pw85::detail

#endif  // PW85_SRC_PROBLEM_HPP
