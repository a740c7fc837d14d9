// SPDX-License-Identifier: BSD-3-Clause
// f and the residual at a given λ (f.hpp).
#include "f.hpp"

#include <cmath>

#include "cholesky.hpp"
#include "compensated.hpp"
#include "compiler.hpp"

namespace pw85::detail {

namespace {

template <int D>
PW85_INLINE bool f_value(double lambda, double const *r, double const *q1,
                         double const *q2, double *value) noexcept {
  Compensated a;
  if (!evaluate_compensated<false, D>(lambda, r, q1, q2, false, nullptr, &a))
    return false;
  // f ≥ 0 on [0, 1], where Q(λ) is positive definite; a negative value is
  // rounding error (cond(Q(λ)) beyond ~1e14), and 0 is nearer the truth.
  *value = lambda >= 0.0 && lambda <= 1.0 && a.f < 0.0 ? 0.0 : a.f;
  return true;
}

}  // namespace

template <>
PW85_FMA_CLONES bool f_compensated<2>(double lambda, double const *r,
                                      double const *q1, double const *q2,
                                      double *value) noexcept {
  return f_value<2>(lambda, r, q1, q2, value);
}

template <>
PW85_FMA_CLONES bool f_compensated<3>(double lambda, double const *r,
                                      double const *q1, double const *q2,
                                      double *value) noexcept {
  return f_value<3>(lambda, r, q1, q2, value);
}

void residual(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double out[3]) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  if (!cholesky_decomp(q, l)) {
    out[0] = out[1] = out[2] = NAN;
    return;
  }
  double q12[sym];
  for (int i = 0; i < sym; ++i) q12[i] = q2[i] - q1[i];
  double s[dim], u[dim], v[dim];
  cholesky_solve(l, r, s);  // s = Q⁻¹·r
  sym_mul(q12, s, u);       // u = Q12·s
  cholesky_solve(l, u, v);  // v = Q⁻¹·u
  double const rs = dot(r, s);
  double const su = dot(s, u);
  double const uv = dot(u, v);
  double const w = lambda * (1.0 - lambda);
  if (!f_compensated(lambda, r, q1, q2, &out[0])) out[0] = w * rs;  // ch. 4 (4)
  out[1] = (2.0 * lambda - 1.0) * rs + w * su;                      // ch. 5 (4)
  out[2] = 2.0 * rs + 2.0 * (1.0 - 2.0 * lambda) * su - 2.0 * w * uv;  // (5)
}

}  // namespace pw85::detail
