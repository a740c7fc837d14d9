// SPDX-License-Identifier: BSD-3-Clause
// Determinant, adjugate quadratic form and the polynomial coefficients of
// implementation #2 of f (docs/implementation.rst, "Implementation 2").
#include "legacy.hpp"

namespace pw85::legacy::detail {

double det_sym(double const a[sym]) noexcept {
  // Cofactors of the first row of A = [[a0 a1 a2] [a1 a3 a4] [a2 a4 a5]].
  double const c00 = a[3] * a[5] - a[4] * a[4];
  double const c01 = a[2] * a[4] - a[1] * a[5];
  double const c02 = a[1] * a[4] - a[2] * a[3];
  return a[0] * c00 + a[1] * c01 + a[2] * c02;
}

double xT_adjA_x(double const x[dim], double const a[sym]) noexcept {
  // adj(A) of a symmetric A is symmetric; its entries are the cofactors.
  double const c00 = a[3] * a[5] - a[4] * a[4];
  double const c01 = a[2] * a[4] - a[1] * a[5];
  double const c02 = a[1] * a[4] - a[2] * a[3];
  double const c11 = a[0] * a[5] - a[2] * a[2];
  double const c12 = a[1] * a[2] - a[0] * a[4];
  double const c22 = a[0] * a[3] - a[1] * a[1];
  return c00 * x[0] * x[0] + c11 * x[1] * x[1] + c22 * x[2] * x[2] +
         2.0 * (c01 * x[0] * x[1] + c02 * x[0] * x[2] + c12 * x[1] * x[2]);
}

void detQ_as_poly(double const q1[sym], double const q2[sym],
                  double const q3[sym], double const q4[sym],
                  double b[dim + 1]) noexcept {
  // Q(0) = Q1, Q(1) = Q2, Q(−1) = 2Q1 − Q2 = q3, Q(½) = (Q1 + Q2)/2 = q4.
  double const b_0 = det_sym(q1);
  double const b_1 = det_sym(q2);
  double const b_m1 = det_sym(q3);
  double const b_half = det_sym(q4);
  b[0] = b_0;                                                      // eq. (12d)
  b[1] = 8.0 * b_half / 3.0 - 2.0 * b_0 - 0.5 * b_1 - b_m1 / 6.0;  // (12e)
  b[2] = 0.5 * (b_1 + b_m1) - b_0;                                 // eq. (12f)
  b[3] = -8.0 * b_half / 3.0 + 2.0 * b_0 + b_1 - b_m1 / 3.0;       // eq. (12g)
}

void rT_adjQ_r_as_poly(double const r[dim], double const q1[sym],
                       double const q2[sym], double const q3[sym],
                       double a[dim]) noexcept {
  double const a_0 = xT_adjA_x(r, q1);
  double const a_1 = xT_adjA_x(r, q2);
  double const a_m1 = xT_adjA_x(r, q3);
  a[0] = a_0;                       // docs/implementation.rst, eq. (4.12a)
  a[1] = 0.5 * (a_1 - a_m1);        // docs/implementation.rst, eq. (4.12b)
  a[2] = 0.5 * (a_1 + a_m1) - a_0;  // docs/implementation.rst, eq. (4.12c)
}

}  // namespace pw85::legacy::detail
