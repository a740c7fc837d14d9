// SPDX-License-Identifier: BSD-3-Clause
// Every validation of input (checks.hpp).
#include "checks.hpp"

#include <cmath>

#include "cholesky.hpp"
#include "scaling.hpp"

namespace pw85::detail {

bool valid_f_input(double lambda, double const *r, double const *q1,
                   double const *q2) noexcept {
  return r != nullptr && q1 != nullptr && q2 != nullptr &&
         std::isfinite(lambda) && all_finite<dim>(r) && all_finite<sym>(q1) &&
         all_finite<sym>(q2);
}

Status check_pointers_and_finite(double const *r, double const *q1,
                                 double const *q2, void const *out) noexcept {
  if (r == nullptr || q1 == nullptr || q2 == nullptr || out == nullptr)
    return Status::null_pointer;
  if (!(all_finite<dim>(r) && all_finite<sym>(q1) && all_finite<sym>(q2)))
    return Status::not_finite;
  return Status::success;
}

bool is_positive_definite(double const q[sym]) noexcept {
  // Symmetric diagonal scaling by powers of two, D·Q·D with D = diag(2^-hᵢ)
  // and Qᵢᵢ ≈ 4^hᵢ: exact, preserves definiteness, and brings the diagonal
  // to [1/4, 1) so that no square overflows or underflows however widely
  // the diagonal entries range.
  if (!all_finite<sym>(q)) return false;
  int h[dim];
  for (int i = 0; i < dim; ++i) {
    if (!(q[diag_of[i]] > 0.0)) return false;
    h[i] = exponent(q[diag_of[i]]) / 2;
  }
  double scaled[sym];
  for (int k = 0; k < sym; ++k)
    scaled[k] = std::ldexp(q[k], -(h[row_of[k]] + h[col_of[k]]));
  double l[sym];
  return cholesky_decomp(scaled, l);
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
