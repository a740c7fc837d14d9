// SPDX-License-Identifier: BSD-3-Clause
// Vectors of D and symmetric D×D matrices, D = 2 or 3, stored as the upper
// triangle row by row (private): in 3D as in include/pw85/pw85.h,
// a[0]=A00 a[1]=A01 a[2]=A02 a[3]=A11 a[4]=A12 a[5]=A22; in 2D as in
// include/pw85/pw85_2d.h, a[0]=A00 a[1]=A01 a[2]=A11.
//
// The dimension is a template parameter of the core, from these kernels up
// to the contact function and the overlap test: one implementation for
// both (docs/implementation.rst, "One core for two dimensions"). Where a
// kernel is written out entry by entry, it is specialised for 2 and 3 (a
// loop would change neither the operations nor their order, but -O2 would
// leave it rolled). D defaults to 3 so that the rooms that are 3D only
// (index, packer, legacy library, ellipsoid constructors) read as before;
// the 2D facade names D = 2 at every call.
#ifndef PW85_SRC_SYM_HPP
#define PW85_SRC_SYM_HPP

#include "compiler.hpp"

namespace pw85::detail {

// The sizes of the 3D library (PW85_DIM, PW85_SYM).
constexpr int dim = 3;
constexpr int sym = 6;

// The number of stored entries of a symmetric D×D matrix.
constexpr int sym_size(int d) noexcept { return d * (d + 1) / 2; }

// Row and column of each stored entry; the stored index of each diagonal
// entry.
template <int D>
struct Layout;

template <>
struct Layout<2> {
  static constexpr int row[3] = {0, 0, 1};
  static constexpr int col[3] = {0, 1, 1};
  static constexpr int diag[2] = {0, 2};
};

template <>
struct Layout<3> {
  static constexpr int row[sym] = {0, 0, 0, 1, 1, 2};
  static constexpr int col[sym] = {0, 1, 2, 1, 2, 2};
  static constexpr int diag[dim] = {0, 3, 5};
};

inline constexpr auto &row_of = Layout<dim>::row;
inline constexpr auto &col_of = Layout<dim>::col;
inline constexpr auto &diag_of = Layout<dim>::diag;

// The stored index of entry (i, j): row a = min(i, j) starts at
// a·D − a(a−1)/2.
template <int D = dim>
constexpr int sym_index(int i, int j) noexcept {
  int const a = i < j ? i : j;
  int const b = i < j ? j : i;
  return a * D - a * (a - 1) / 2 + (b - a);
}

// y = A·x for symmetric A.
template <int D = dim>
PW85_INLINE void sym_mul(double const *a, double const *x, double *y) noexcept {
  if constexpr (D == 2) {
    y[0] = a[0] * x[0] + a[1] * x[1];
    y[1] = a[1] * x[0] + a[2] * x[1];
  } else {
    y[0] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
    y[1] = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
    y[2] = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
  }
}

// x·y, summed from the first entry.
template <int D = dim>
PW85_INLINE double dot(double const *x, double const *y) noexcept {
  if constexpr (D == 2)
    return x[0] * y[0] + x[1] * y[1];
  else
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// The trace, summed from the first diagonal entry.
template <int D = dim>
PW85_INLINE double trace(double const *a) noexcept {
  if constexpr (D == 2)
    return a[0] + a[2];
  else
    return a[0] + a[3] + a[5];
}

// Q(λ) = (1−λ)·Q1 + λ·Q2 (docs/implementation.rst, eq. (4.2)).
template <int D = dim>
PW85_INLINE void combine(double lambda, double const *q1, double const *q2,
                         double *q) noexcept {
  PW85_COUNT_EVALUATION();
  double const mu = 1.0 - lambda;
  constexpr int n = sym_size(D);
  PW85_UNROLL
  for (int i = 0; i < n; ++i) q[i] = mu * q1[i] + lambda * q2[i];
}

// The adjugate of a symmetric 3×3 A (symmetric too: its entries are the
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

#endif  // PW85_SRC_SYM_HPP
