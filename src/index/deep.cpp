// SPDX-License-Identifier: BSD-3-Clause
// The deep-overlap shortcut (deep.hpp).
#include "deep.hpp"

#include <algorithm>
#include <cmath>

#include "cholesky.hpp"

namespace pw85::detail {

namespace {

// Is every Q_kk in [moderate_low, moderate_high]? The range in which the
// shortcut of overlap_any() works (margins.hpp).
bool moderate_diagonal(double const q[sym]) noexcept {
  double const lo = std::min(std::min(q[0], q[3]), q[5]);
  double const hi = std::max(std::max(q[0], q[3]), q[5]);
  return lo >= moderate_low && hi <= moderate_high;
}

// Does the Cholesky factorisation of Q − s·I (cholesky_decomp()) complete
// with every pivot > 0? (Then Q − s·I + E is positive definite for some
// ‖E‖₂ < 2⁻⁴⁸·M, M = max Q_kk ≥ s: margins.hpp, shift_margin.)
bool definite_after_shift(double const q[sym], double s) noexcept {
  double a[sym], l[sym];
  for (int k = 0; k < sym; ++k) a[k] = q[k];
  for (int k = 0; k < dim; ++k) a[diag_of[k]] -= s;
  return cholesky_decomp(a, l);
}

// An estimate of λmin(Q), not certified: the trigonometric solution of
// the characteristic cubic (O. K. Smith, Commun. ACM 4(4), 168, 1961).
double least_eigenvalue_estimate(double const q[sym]) noexcept {
  double const off = q[1] * q[1] + q[2] * q[2] + q[4] * q[4];
  double const m = (q[0] + q[3] + q[5]) / 3.0;
  double const b0 = q[0] - m, b1 = q[3] - m, b2 = q[5] - m;
  double const p = std::sqrt((b0 * b0 + b1 * b1 + b2 * b2 + 2.0 * off) / 6.0);
  if (!(p > 0.0)) return m;  // Q = m·I
  // det(B)/2 for B = (Q − m·I)/p.
  double const c0 = b0 / p, c1 = b1 / p, c2 = b2 / p;
  double const e01 = q[1] / p, e02 = q[2] / p, e12 = q[4] / p;
  double const half_det = 0.5 * (c0 * (c1 * c2 - e12 * e12) -
                                 e01 * (e01 * c2 - e12 * e02) +
                                 e02 * (e01 * e12 - c1 * e02));
  double const phi =
      std::acos(std::min(1.0, std::max(-1.0, half_det))) / 3.0;
  return m + 2.0 * p * std::cos(phi + 2.0943951023931957);  // + 2π/3
}

}  // namespace

double inscribed_radius(double const q[sym]) noexcept {
  if (!moderate_diagonal(q)) return 0.0;
  double const m = std::max(std::max(q[0], q[3]), q[5]);
  double const margin = shift_margin * m;
  auto certified = [&](double est) {  // also false for NaN
    return est >= estimate_floor && est <= m &&
           definite_after_shift(q, est + margin);
  };
  // First the cubic's estimate, lowered; if the check fails (an
  // ill-conditioned Q, whose λmin the estimate gets wrong), the bound
  // λmin(Q) ≥ 1/‖Q⁻¹‖_F (Q⁻¹ = adj(Q)/det(Q)), lowered more.
  double est = least_eigenvalue_estimate(q) * (1.0 - estimate_lowering);
  if (!certified(est)) {
    double a[sym];
    sym_adjugate(q, a);
    double const det = q[0] * a[0] + q[1] * a[1] + q[2] * a[2];
    double const frob = std::sqrt(a[0] * a[0] + a[3] * a[3] + a[5] * a[5] +
                                  2.0 * (a[1] * a[1] + a[2] * a[2] + a[4] * a[4]));
    est = det / frob * (1.0 - fallback_lowering);
    if (!certified(est)) return 0.0;
  }
  return std::sqrt(est) * (1.0 - root_lowering);  // λmin(Q) > est
}

bool line_factor(double const q[sym], double l[sym], double *s) noexcept {
  if (!moderate_diagonal(q) || !cholesky_decomp(q, l)) return false;
  double const tr = q[0] + q[3] + q[5];
  double f = 0.0;
  for (int k = 0; k < sym; ++k) f += l[k] * l[k];
  double const g = 2.0 * (l[0] * l[3] * l[5]) / f;
  *s = g * g * (1.0 - factor_lowering) - factor_shift * tr;
  return *s > 0.0 && tr <= max_trace_ratio * *s;
}

bool deep_overlap(double const lq[sym], double const r[dim], double d2,
                  double rho_e) noexcept {
  double y[dim];
  forward_solve(lq, r, y);
  double const a = dot(y, y) * (1.0 + deep_form);
  double const d = std::sqrt(d2);
  double const t =
      d - rho_e * (1.0 - deep_shrink) + deep_rounding * (d + rho_e);
  return t <= 0.0 || t * std::sqrt(a) < d * (1.0 - deep_bound);
}

}  // namespace pw85::detail
