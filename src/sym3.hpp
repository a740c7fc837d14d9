// SPDX-License-Identifier: BSD-3-Clause
// Vectors of 3 and symmetric 3×3 matrices in the storage of
// include/pw85/pw85.h: a[0]=A00 a[1]=A01 a[2]=A02 a[3]=A11 a[4]=A12
// a[5]=A22 (private).
#ifndef PW85_SRC_SYM3_HPP
#define PW85_SRC_SYM3_HPP

#include "compiler.hpp"

namespace pw85::detail {

constexpr int dim = 3;
constexpr int sym = 6;

// Row and column of each stored entry; the stored index of each diagonal
// entry.
constexpr int row_of[sym] = {0, 0, 0, 1, 1, 2};
constexpr int col_of[sym] = {0, 1, 2, 1, 2, 2};
constexpr int diag_of[dim] = {0, 3, 5};

// The stored index of entry (i, j).
constexpr int sym_index(int i, int j) noexcept {
  int const a = i < j ? i : j;
  int const b = i < j ? j : i;
  return a == 0 ? b : (a == 1 ? 2 + b : 5);
}

// y = A·x for symmetric A.
PW85_INLINE void sym_mul(double const a[sym], double const x[dim],
                         double y[dim]) noexcept {
  y[0] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
  y[1] = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
  y[2] = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
}

PW85_INLINE double dot(double const x[dim], double const y[dim]) noexcept {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

PW85_INLINE double trace(double const a[sym]) noexcept {
  return a[0] + a[3] + a[5];
}

// Q(λ) = (1−λ)·Q1 + λ·Q2 (docs/implementation.rst, eq. (4.2)).
PW85_INLINE void combine(double lambda, double const q1[sym],
                         double const q2[sym], double q[sym]) noexcept {
  PW85_COUNT_EVALUATION();
  double const mu = 1.0 - lambda;
  PW85_UNROLL
  for (int i = 0; i < sym; ++i) q[i] = mu * q1[i] + lambda * q2[i];
}

// The adjugate of a symmetric A (symmetric too: its entries are the
// cofactors), in the same storage; det A = a·(row 0 of adj A).
PW85_INLINE void sym_adjugate(double const a[sym], double c[sym]) noexcept {
  c[0] = a[3] * a[5] - a[4] * a[4];
  c[1] = a[2] * a[4] - a[1] * a[5];
  c[2] = a[1] * a[4] - a[2] * a[3];
  c[3] = a[0] * a[5] - a[2] * a[2];
  c[4] = a[1] * a[2] - a[0] * a[4];
  c[5] = a[0] * a[3] - a[1] * a[1];
}

}  // namespace pw85::detail

#endif  // PW85_SRC_SYM3_HPP
