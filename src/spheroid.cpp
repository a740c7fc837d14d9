// SPDX-License-Identifier: BSD-3-Clause
// The quadratic form of a spheroid (spheroid.hpp).
#include "spheroid.hpp"

#include "dd.hpp"

namespace pw85::detail {

void spheroid(double a, double c, double const n[dim], double q[sym]) noexcept {
  // In double-double: the diagonal a² + (c² − a²)·nᵢ² cancels when c ≪ a
  // and nᵢ ≈ 1 (the polar entry of a flat oblate spheroid would otherwise
  // lose up to log10(a²/c²) digits).
  dd const a2 = two_prod(a, a);
  dd const d = dd_add(two_prod(c, c), dd_neg(a2));
  for (int k = 0; k < sym; ++k) {
    dd const t = dd_mul(dd_mul(d, n[row_of[k]]), n[col_of[k]]);
    q[k] = dd_round(row_of[k] == col_of[k] ? dd_add(a2, t) : t);
  }
}

}  // namespace pw85::detail
