// SPDX-License-Identifier: BSD-3-Clause
// Every validation of input (checks.hpp).
#include "checks.hpp"

#include <cmath>

#include "cholesky.hpp"
#include "ldl.hpp"
#include "scaling.hpp"

namespace pw85::detail {

bool valid_f_input(double lambda, double const *r, double const *q1,
                   double const *q2) noexcept {
  return r != nullptr && q1 != nullptr && q2 != nullptr &&
         std::isfinite(lambda) && all_finite<dim>(r) && all_finite<sym>(q1) &&
         all_finite<sym>(q2);
}

namespace {

// D·Q·D, D = diag(2^−h[i]), and its ldl_decomp() factors (false when a
// pivot is ≤ 0). Q finite with a positive diagonal.
bool scaled_ldl(double const q[sym], double scaled[sym], Ldl *f,
                int h[dim]) noexcept {
  for (int i = 0; i < dim; ++i) h[i] = exponent(q[diag_of[i]]) / 2;
  for (int k = 0; k < sym; ++k)
    scaled[k] = times_pow2(q[k], -(h[row_of[k]] + h[col_of[k]]));
  return ldl_decomp(scaled, f);
}

bool finite_with_positive_diagonal(double const q[sym]) noexcept {
  return all_finite<sym>(q) && q[0] > 0.0 && q[3] > 0.0 && q[5] > 0.0;
}

}  // namespace

bool is_positive_definite(double const q[sym]) noexcept {
  if (!finite_with_positive_diagonal(q)) return false;
  Ldl f;
  int h[dim];
  double scaled[sym];
  if (scaled_ldl(q, scaled, &f, h) &&
      ldl_certifies(scaled, ldl_trace_inverse(f)))
    return true;
  return exactly_positive_definite(q);
}

bool cholesky_by_rule(double const q[sym], double l[sym]) noexcept {
  if (!is_positive_definite(q)) return false;
  if (cholesky_decomp(q, l)) return true;
  Ldl f;
  int h[dim];
  double scaled[sym];
  if (!scaled_ldl(q, scaled, &f, h)) return false;
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
