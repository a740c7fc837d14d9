// SPDX-License-Identifier: BSD-3-Clause
// The two implementations of f(λ) = λ(1−λ)·rᵀ·Q(λ)⁻¹·r (docs/implementation.rst).
#include "legacy.hpp"

#include "cholesky.hpp"

namespace pw85::legacy::detail {

namespace core = pw85::detail;
using core::combine;
using core::dot;
using core::sym_mul;

bool q_positive_definite(double lambda, double const q1[sym],
                         double const q2[sym]) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  return core::cholesky_decomp(q, l);
}

bool f1(double lambda, double const r[dim], double const q1[sym],
        double const q2[sym], double *f, double out[3]) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  if (!core::cholesky_decomp(q, l)) return false;  // docs/implementation.rst, eq. (4.3)
  // rᵀ·s = rᵀ·Q⁻¹·r = |L⁻¹·r|², a sum of squares (no cancellation).
  double y[dim];
  core::forward_solve(l, r, y);
  double const rs = dot(y, y);
  double const w = lambda * (1.0 - lambda);
  *f = w * rs;  // docs/implementation.rst, eq. (4.4)
  if (out == nullptr) return true;

  double q12[sym];
  for (int i = 0; i < sym; ++i) q12[i] = q2[i] - q1[i];
  double s[dim], u[dim], z[dim];
  core::cholesky_solve(l, r, s);  // s = Q⁻¹·r
  sym_mul(q12, s, u);             // u = Q12·s, docs/implementation.rst, eq. (4.5)
  core::forward_solve(l, u, z);   // uᵀ·v = uᵀ·Q⁻¹·u = |L⁻¹·u|²
  double const su = dot(s, u);
  double const uv = dot(z, z);
  out[0] = *f;
  out[1] = (1.0 - 2.0 * lambda) * rs - w * su;  // docs/implementation.rst, eq. (4.6)
  out[2] = -2.0 * rs - 2.0 * (1.0 - 2.0 * lambda) * su +
           2.0 * w * uv;  // docs/implementation.rst, eq. (4.9)
  return true;
}

double f2(double lambda, double const r[dim], double const q1[sym],
          double const q2[sym]) noexcept {
  double q3[sym];
  double q4[sym];
  for (int i = 0; i < sym; ++i) {
    q3[i] = 2.0 * q1[i] - q2[i];    // Q(−1)
    q4[i] = 0.5 * (q1[i] + q2[i]);  // Q(½)
  }
  double a[dim];
  double b[dim + 1];
  rT_adjQ_r_as_poly(r, q1, q2, q3, a);  // docs/implementation.rst, eqs. (4.12a)–(4.12c)
  detQ_as_poly(q1, q2, q3, q4, b);      // docs/implementation.rst, eqs. (4.12d)–(4.12g)
  double const a_lambda = (a[2] * lambda + a[1]) * lambda + a[0];  // (11a)
  double const b_lambda =
      ((b[3] * lambda + b[2]) * lambda + b[1]) * lambda + b[0];  // (11b)
  return lambda * (1.0 - lambda) * a_lambda / b_lambda;  // docs/implementation.rst, eq. (4.10)
}

}  // namespace pw85::legacy::detail
