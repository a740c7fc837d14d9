// SPDX-License-Identifier: BSD-3-Clause
// Every validation of input (checks.hpp).
#include "checks.hpp"

#include <cmath>

#include "cholesky.hpp"
#include "ldl.hpp"
#include "scaling.hpp"

namespace pw85::detail {

namespace {

// D·Q·D, D = diag(2^−h[i]), and its ldl_decomp() factors (false when a
// pivot is ≤ 0). Q finite with a positive diagonal.
template <int D>
bool scaled_ldl(double const *q, double *scaled, Ldl<D> *f, int *h) noexcept {
  using L = Layout<D>;
  for (int i = 0; i < D; ++i) h[i] = exponent(q[L::diag[i]]) / 2;
  for (int k = 0; k < sym_size(D); ++k)
    scaled[k] = times_pow2(q[k], -(h[L::row[k]] + h[L::col[k]]));
  return ldl_decomp(scaled, f);
}

template <int D>
bool finite_with_positive_diagonal(double const *q) noexcept {
  if (!all_finite<sym_size(D)>(q)) return false;
  for (int i = 0; i < D; ++i)
    if (!(q[Layout<D>::diag[i]] > 0.0)) return false;
  return true;
}

}  // namespace

template <int D>
bool is_positive_definite(double const *q) noexcept {
  if (!finite_with_positive_diagonal<D>(q)) return false;
  Ldl<D> f;
  int h[D];
  double scaled[sym_size(D)];
  if (scaled_ldl<D>(q, scaled, &f, h) &&
      ldl_certifies<D>(scaled, ldl_trace_inverse(f)))
    return true;
  return exactly_positive_definite<D>(q);
}

template bool is_positive_definite<2>(double const *) noexcept;
template bool is_positive_definite<3>(double const *) noexcept;

bool cholesky_by_rule(double const q[sym], double l[sym]) noexcept {
  if (!is_positive_definite(q)) return false;
  if (cholesky_decomp(q, l)) return true;
  Ldl<3> f;
  int h[dim];
  double scaled[sym];
  if (!scaled_ldl<3>(q, scaled, &f, h)) return false;
  // Q = D⁻¹·L̃·diag(d)·L̃ᵀ·D⁻¹, so L = D⁻¹·L̃·diag(√d): column j of L̃
  // times √dⱼ, row i divided by Dᵢ = 2^−hᵢ.
  double root_d[dim];
  for (int j = 0; j < dim; ++j) root_d[j] = std::sqrt(1.0 / f.inv_d[j]);
  double const unit_lower[sym] = {1.0, f.l10, f.l20, 1.0, f.l21, 1.0};
  int const row[sym] = {0, 1, 2, 1, 2, 2};  // storage of cholesky.hpp:
  int const col[sym] = {0, 0, 0, 1, 1, 2};  // column by column
  for (int k = 0; k < sym; ++k)
    l[k] = times_pow2(unit_lower[k] * root_d[col[k]], h[row[k]]);
  return true;
}

Status check_input(double const *r, double const *q1, double const *q2,
                   void const *out) noexcept {
  Status const status = check_pointers_and_finite(r, q1, q2, out);
  if (status != Status::success) return status;
  if (!is_positive_definite(q1) || !is_positive_definite(q2))
    return Status::not_positive_definite;
  return Status::success;
}

}  // namespace pw85::detail
