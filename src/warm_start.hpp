// SPDX-License-Identifier: BSD-3-Clause
// Starting points of the search from the sphere model (private;
// docs/optimisation.rst, step 3 and the end steps of step 4).
#ifndef PW85_SRC_WARM_START_HPP
#define PW85_SRC_WARM_START_HPP

#include <algorithm>
#include <cmath>

#include "ldl.hpp"
#include "problem.hpp"
#include "sym.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

// The largest double below 1: where a step rounds onto λ = 1 (the root
// lies within an ulp of it), λ goes here instead, where f ≠ 0.
constexpr double below_one = 1.0 - 0x1p-53;

// 1/(1 + √(x/y)) for x, y ≥ 0, computed as √y/(√y + √x): the square roots
// side by side, then one division (rather than a division, a square root
// and a division in a row), and no ratio x/y to overflow or underflow.
inline double sphere_root(double x, double y) noexcept {
  double const root_y = std::sqrt(y);
  return root_y / (root_y + std::sqrt(x));
}

// The sphere model's maximiser (eq. (5.9)), exact for two spheres
// (Qᵢ = aᵢ²·I gives λ = a1/(a1 + a2)): λ0 = 1/(1 + √(a1/a2)) with
// aᵢ = rᵀQᵢ⁻¹r.
inline double warm_start(double a1, double a2) noexcept {
  double const lambda = sphere_root(a1, a2);
  if (lambda >= 1.0) return below_one;
  if (lambda > 0.0) return lambda;
  // 0 or NaN: a2 = 0, or a2 = ∞ (where λ0 → 1), or both 0 or both ∞.
  return a1 < a2 ? below_one : 0.5;
}

template <int D>
inline double warm_start(Problem<D> const &p) noexcept {
  return warm_start(p.a1, p.a2);
}

// The two-dimensional start (docs/optimisation.rst, step 3, "ellipses"):
// with s = 1 − λ, t = λ and Q(λ) = s·Q1 + t·Q2, rᵀ·adj(Q(λ))·r = ν0·s + ν1·t
// (adj is linear for 2×2 forms; νᵢ = rᵀ·adj(Qᵢ)·r) and
// det Q(λ) = β0·s² + β1·s·t + β2·t² (β0 = det Q1, β2 = det Q2,
// β1 = tr(adj(Q1)·Q2)), so f = s·t·(ν0·s + ν1·t)/det Q(λ) and f′ has the
// sign of the quartic
//   P = ν0β0·s⁴ + 2ν1β0·s³t + ((ν1 − ν0)β1 + ν1β0 − ν0β2)·s²t²
//       − 2ν0β2·st³ − ν1β2·t⁴
// (eq. (5.9b)), P(0) > 0 > P(1). Halley's steps on P from λ0, safeguarded
// by the bracket of its signs, cost a few dozen flops each, against a
// factorisation, a solve and four products per plain point. The
// coefficients are rounded (det Qᵢ cancels as cond(Qᵢ) grows): the root is
// a start only, which the certified stages do not rely on. Returns λ0
// where the coefficients are not finite or do not show P(0) > 0 > P(1), or
// where no step is accepted within rational_start_steps; always a λ in
// (0, 1) when λ0 is.
inline double rational_start(Problem<2> const &p, double lambda0) noexcept {
  double const *a = p.q1, *b = p.q2, *r = p.r;
  double const r00 = r[0] * r[0], r01 = 2.0 * (r[0] * r[1]), r11 = r[1] * r[1];
  double const nu0 = a[2] * r00 - a[1] * r01 + a[0] * r11;
  double const nu1 = b[2] * r00 - b[1] * r01 + b[0] * r11;
  double const beta0 = a[0] * a[2] - a[1] * a[1];
  double const beta2 = b[0] * b[2] - b[1] * b[1];
  double const beta1 = a[2] * b[0] + a[0] * b[2] - 2.0 * (a[1] * b[1]);
  double c0 = nu0 * beta0, c1 = 2.0 * (nu1 * beta0),
         c2 = (nu1 - nu0) * beta1 + (nu1 * beta0 - nu0 * beta2),
         c3 = -2.0 * (nu0 * beta2), c4 = -(nu1 * beta2);
  if (!(c0 > 0.0 && c4 < 0.0 && std::isfinite(c1 + c2 + c3))) return lambda0;
  // P divided by its largest coefficient (the root is the same), so that
  // Halley's products stay in range however far apart the forms' sizes.
  double cmax = c0 > -c4 ? c0 : -c4;
  for (double const ck : {c1, c2, c3})
    cmax = std::fabs(ck) > cmax ? std::fabs(ck) : cmax;
  double const scale = 1.0 / cmax;
  if (!(scale > 0.0 && scale < HUGE_VAL)) return lambda0;  // also NaN
  c0 *= scale, c1 *= scale, c2 *= scale, c3 *= scale, c4 *= scale;
  // P = Σ cⱼ·s^(4−j)·t^j, P′ = Σ dⱼ·s^(3−j)·t^j, P″ = Σ eⱼ·s^(2−j)·t^j.
  double const d0 = c1 - 4.0 * c0, d1 = 2.0 * c2 - 3.0 * c1,
               d2 = 3.0 * c3 - 2.0 * c2, d3 = 4.0 * c4 - c3;
  double const e0 = d1 - 3.0 * d0, e1 = 2.0 * (d2 - d1), e2 = 3.0 * d3 - d2;
  double lo = 0.0, hi = 1.0, lambda = lambda0;
  for (int k = 0; k < rational_start_steps; ++k) {
    double const t = lambda, s = 1.0 - lambda;
    double const ss = s * s, st = s * t, tt = t * t;
    double const pv =
        ss * (c0 * ss + c1 * st + c2 * tt) + tt * (c3 * st + c4 * tt);
    double const dp = ss * (d0 * s + d1 * t) + tt * (d2 * s + d3 * t);
    if (pv == 0.0) return lambda;
    (pv > 0.0 ? lo : hi) = lambda;
    double const near = std::min(lambda, 1.0 - lambda);
    if (dp < 0.0) {  // P decreases, as at its root
      // Accepted where Newton's step P/P′ is at most rational_start_accept
      // (relative): Halley's step from there, or λ itself where that step
      // leaves the bracket (it rounds onto λ, now one of its ends).
      bool const accept = std::fabs(pv) <= rational_start_accept * near * -dp;
      double const ddp = ss * e0 + st * e1 + tt * e2;
      double const next = lambda - 2.0 * pv * dp / (2.0 * dp * dp - pv * ddp);
      if (next > lo && next < hi) {
        if (accept) return next;
        lambda = next;
        continue;
      }
      if (accept) return lambda;
    }
    // P rises here (it may rise from λ = 0 before it falls, and Halley's
    // step is then small where P′ vanishes, far from the root), or the
    // step left the bracket: towards the root by a factor 16 relative to
    // the nearer end of [0, 1] while the bracket reaches one, else to its
    // middle.
    double const next = lo == 0.0 ? 0.0625 * hi
                        : hi == 1.0
                            ? std::min(16.0 * lo, 1.0 - 0.0625 * (1.0 - lo))
                            : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) return lambda;
    lambda = next;
  }
  return lambda0;
}

// Newton's step on ω from an end of [0, 1]. At λ = 0, ω = −1 and
// ω′ = 1 + ρ(0) (the λρ′ term vanishes), so the step lands on
// 1/(1 + ρ(0)); at λ = 1 the step on ω/ρ = λ − (1−λ)/ρ, whose value is 1
// and slope 1 + 1/ρ(1), lands on 1/(1 + ρ(1)). Both are exact when ρ is
// constant (two spheres), and close to the root when it is near that end:
// a thin disc against a wide body, where ω has a plateau that defeats
// Newton's steps from the middle (9.8% of the reference pairs took more
// than 8 steps without them). s = Q1⁻¹r at λ = 0, where
// ρ(0)² = sᵀQ2s / rᵀQ1⁻¹r, and s = Q2⁻¹r at λ = 1, where
// ρ(1)² = rᵀQ2⁻¹r / sᵀQ1s, from the factors of Q1 and Q2. A NaN (both
// forms 0, or both infinite) is rejected where it is used, as any point
// outside the bracket.
template <int D>
inline double step_from_end(Problem<D> const &p, bool from_zero) noexcept {
  double s[D], t[D];
  double const a = ldl_solve_quad(from_zero ? p.f1 : p.f2, p.r, s);
  sym_mul<D>(from_zero ? p.q2 : p.q1, s, t);
  double const b = dot<D>(s, t);
  return from_zero ? sphere_root(b, a) : sphere_root(a, b);
}

}  // namespace pw85::detail

#endif  // PW85_SRC_WARM_START_HPP
