// SPDX-License-Identifier: BSD-3-Clause
// The deep-overlap shortcut (deep.hpp), for D = 2 and 3: the kernels that
// are written out entry by entry (the Cholesky factor and its forward
// substitution, the estimate of λmin, the bound of σmin(L)) are
// specialised; the rest is one code.
#include "deep.hpp"

#include <algorithm>
#include <cmath>

#include "cholesky.hpp"

namespace pw85::detail {

namespace {

// Is every Q_kk in [moderate_low, moderate_high]? The range in which the
// shortcut of overlap_any() works (margins.hpp).
template <int D>
bool moderate_diagonal(double const *q) noexcept {
  double lo = q[Layout<D>::diag[0]], hi = lo;
  for (int k = 1; k < D; ++k) {
    lo = std::min(lo, q[Layout<D>::diag[k]]);
    hi = std::max(hi, q[Layout<D>::diag[k]]);
  }
  return lo >= moderate_low && hi <= moderate_high;
}

// A = L·Lᵀ (3D: cholesky_decomp(); 2D: the same steps on a 2 × 2 form).
// False when a pivot is not > 0 (NaN included).
template <int D>
bool factor(double const *a, double *l) noexcept {
  if constexpr (D == 3) {
    return cholesky_decomp(a, l);
  } else {
    if (!(a[0] > 0.0)) return false;
    l[0] = std::sqrt(a[0]);
    l[1] = a[1] / l[0];
    double const d1 = a[2] - l[1] * l[1];
    if (!(d1 > 0.0)) return false;
    l[2] = std::sqrt(d1);
    return true;
  }
}

// Solves L·y = b (3D: forward_solve()).
template <int D>
void solve_lower(double const *l, double const *b, double *y) noexcept {
  if constexpr (D == 3) {
    forward_solve(l, b, y);
  } else {
    y[0] = b[0] / l[0];
    y[1] = (b[1] - l[1] * y[0]) / l[2];
  }
}

// Does the Cholesky factorisation of Q − s·I complete with every pivot
// > 0? (Then Q − s·I + E is positive definite for some ‖E‖₂ < 2⁻⁴⁸·M,
// M = max Q_kk ≥ s: margins.hpp, shift_margin.)
template <int D>
bool definite_after_shift(double const *q, double s) noexcept {
  constexpr int S = sym_size(D);
  double a[S], l[S];
  for (int k = 0; k < S; ++k) a[k] = q[k];
  for (int k = 0; k < D; ++k) a[Layout<D>::diag[k]] -= s;
  return factor<D>(a, l);
}

// An estimate of λmin(Q), not certified. 3D: the trigonometric solution
// of the characteristic cubic (O. K. Smith, Commun. ACM 4(4), 168, 1961);
// 2D: the root m − √(((Q00 − Q11)/2)² + Q01²), m = tr(Q)/2, of the
// quadratic.
template <int D>
double least_eigenvalue_estimate(double const *q) noexcept {
  if constexpr (D == 2) {
    return 0.5 * (q[0] + q[2]) - std::hypot(0.5 * (q[0] - q[2]), q[1]);
  } else {
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
}

// The bound λmin(Q) ≥ 1/‖Q⁻¹‖_F = det(Q)/‖adj(Q)‖_F, not certified.
template <int D>
double frobenius_estimate(double const *q) noexcept {
  if constexpr (D == 2) {  // adj(Q) = [[Q11, −Q01], [−Q01, Q00]]
    double const det = q[0] * q[2] - q[1] * q[1];
    return det / std::sqrt(q[0] * q[0] + q[2] * q[2] + 2.0 * q[1] * q[1]);
  } else {
    double a[sym];
    sym_adjugate(q, a);
    double const det = q[0] * a[0] + q[1] * a[1] + q[2] * a[2];
    double const frob = std::sqrt(a[0] * a[0] + a[3] * a[3] + a[5] * a[5] +
                                  2.0 * (a[1] * a[1] + a[2] * a[2] + a[4] * a[4]));
    return det / frob;
  }
}

// A lower bound g of σmin(L) from the diagonal of L and f = ‖L‖_F²: 3D,
// σ1·σ2·σ3 = |det L| with σ2·σ3 ≤ f/2, so σ1 ≥ 2·|det L|/f; 2D,
// σ1·σ2 = |det L| with σ2 ≤ √f, so σ1 ≥ |det L|/√f (margins.hpp,
// line_factor()).
template <int D>
double least_singular_bound(double const *l, double f) noexcept {
  if constexpr (D == 2)
    return (l[0] * l[2]) / std::sqrt(f);
  else
    return 2.0 * (l[0] * l[3] * l[5]) / f;
}

}  // namespace

template <int D>
double inscribed_radius(double const *q) noexcept {
  if (!moderate_diagonal<D>(q)) return 0.0;
  double m = q[Layout<D>::diag[0]];
  for (int k = 1; k < D; ++k) m = std::max(m, q[Layout<D>::diag[k]]);
  double const margin = shift_margin * m;
  auto certified = [&](double est) {  // also false for NaN
    return est >= estimate_floor && est <= m &&
           definite_after_shift<D>(q, est + margin);
  };
  // First the closed form's estimate, lowered; if the check fails (an
  // ill-conditioned Q, whose λmin the estimate gets wrong), the bound
  // λmin(Q) ≥ 1/‖Q⁻¹‖_F, lowered more.
  double est = least_eigenvalue_estimate<D>(q) * (1.0 - estimate_lowering);
  if (!certified(est)) {
    est = frobenius_estimate<D>(q) * (1.0 - fallback_lowering);
    if (!certified(est)) return 0.0;
  }
  return std::sqrt(est) * (1.0 - root_lowering);  // λmin(Q) > est
}

template <int D>
bool line_factor(double const *q, double *l, double *s) noexcept {
  if (!moderate_diagonal<D>(q) || !factor<D>(q, l)) return false;
  double const tr = trace<D>(q);
  double f = 0.0;
  for (int k = 0; k < sym_size(D); ++k) f += l[k] * l[k];
  double const g = least_singular_bound<D>(l, f);
  *s = g * g * (1.0 - factor_lowering) - factor_shift * tr;
  return *s > 0.0 && tr <= max_trace_ratio * *s;
}

template <int D>
bool deep_overlap(double const *lq, double const *r, double d2,
                  double rho_e) noexcept {
  double y[D];
  solve_lower<D>(lq, r, y);
  double const a = dot<D>(y, y) * (1.0 + deep_form);
  double const d = std::sqrt(d2);
  double const t =
      d - rho_e * (1.0 - deep_shrink) + deep_rounding * (d + rho_e);
  return t <= 0.0 || t * std::sqrt(a) < d * (1.0 - deep_bound);
}

#define PW85_DEEP(D)                                                           \
  template double inscribed_radius<D>(double const *) noexcept;                \
  template bool line_factor<D>(double const *, double *, double *) noexcept;   \
  template bool deep_overlap<D>(double const *, double const *, double,        \
                                double) noexcept;
PW85_DEEP(2)
PW85_DEEP(3)
#undef PW85_DEEP

}  // namespace pw85::detail
