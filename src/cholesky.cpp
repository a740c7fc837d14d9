// SPDX-License-Identifier: BSD-3-Clause
// The Cholesky factorisation and solve (cholesky.hpp; docs/implementation.rst, "Implementation 1").
#include "cholesky.hpp"

#include <cmath>

namespace pw85::detail {

bool cholesky_decomp(double const a[sym], double l[sym]) noexcept {
  // Written so that a NaN pivot fails the test as a negative one does.
  if (!(a[0] > 0.0)) return false;
  l[0] = std::sqrt(a[0]);
  l[1] = a[1] / l[0];
  l[2] = a[2] / l[0];
  double const d1 = a[3] - l[1] * l[1];
  if (!(d1 > 0.0)) return false;
  l[3] = std::sqrt(d1);
  l[4] = (a[4] - l[1] * l[2]) / l[3];
  double const d2 = a[5] - l[2] * l[2] - l[4] * l[4];
  if (!(d2 > 0.0)) return false;
  l[5] = std::sqrt(d2);
  return true;
}

void forward_solve(double const l[sym], double const b[dim],
                   double y[dim]) noexcept {
  y[0] = b[0] / l[0];
  y[1] = (b[1] - l[1] * y[0]) / l[3];
  y[2] = (b[2] - l[2] * y[0] - l[4] * y[1]) / l[5];
}

void cholesky_solve(double const l[sym], double const b[dim],
                    double x[dim]) noexcept {
  double y[dim];
  forward_solve(l, b, y);
  x[2] = y[2] / l[5];
  x[1] = (y[1] - l[4] * x[2]) / l[3];
  x[0] = (y[0] - l[1] * x[1] - l[2] * x[2]) / l[0];
}

}  // namespace pw85::detail
