// SPDX-License-Identifier: BSD-3-Clause
// Starting points of the search from the sphere model (private;
// docs/optimisation.rst, step 3 and the end steps of step 4).
#ifndef PW85_SRC_WARM_START_HPP
#define PW85_SRC_WARM_START_HPP

#include "ldl.hpp"
#include "problem.hpp"
#include "sym.hpp"

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
