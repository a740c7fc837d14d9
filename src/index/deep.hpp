// SPDX-License-Identifier: BSD-3-Clause
// The deep-overlap shortcut of overlap_any() (private): a point inside
// both ellipsoids scaled by 1 − 2⁻²⁰ decides an overlap without the narrow
// phase, far outside pw85_overlap()'s 4-ulp band. Its margins and their
// proofs: margins.hpp ("The deep-overlap shortcut").
#ifndef PW85_SRC_INDEX_DEEP_HPP
#define PW85_SRC_INDEX_DEEP_HPP

#include "margins.hpp"
#include "sym.hpp"

namespace pw85::detail {

// The shortcut is written for D = 2 and 3 (an ellipse, an ellipsoid; the
// margins of margins.hpp hold for both).
//
// A radius ρ ≥ 0 of a ball about the centre inside the ellipsoid
// {x : xᵀQ⁻¹x ≤ 1}: ρ² < λmin(Q), certified (0 when not found; always 0
// unless every Q_kk is in [moderate_low, moderate_high]). An estimate s₀
// of λmin(Q) is checked by the Cholesky factorisation of
// Q − (s₀ + shift_margin·max Q_kk)·I. Within 2⁻¹⁷ of √λmin(Q) for forms
// of moderate condition.
template <int D = dim>
double inscribed_radius(double const *q) noexcept;

// The candidate's side of deep_overlap(): its Cholesky factor l and a
// certified lower bound *s of λmin(Q), when every Q_kk is in
// [moderate_low, moderate_high] and tr(Q) ≤ max_trace_ratio·s
// (margins.hpp, line_factor()); else false. No eigenvalue is computed: a
// query factors its candidate once.
template <int D>
bool line_factor(double const *q, double *l, double *s) noexcept;

// Does the point of the segment from c to c + r̂ at distance
// ρ_e·(1 − deep_shrink) from c + r̂ lie in the candidate (Cholesky factor
// lq) scaled by 1 − deep_shrink, with the margins of margins.hpp
// (deep_overlap())? d2 = |r̂|² as computed. The caller checks
// (Σσ_k)² ≤ deep_slack·s: then μ² ≤ (1 − 2⁻²⁰)² for the exact r.
template <int D>
bool deep_overlap(double const *lq, double const *r, double d2,
                  double rho_e) noexcept;

// D = 2 and 3 are instantiated in deep.cpp. In 2D, L is stored
// l[0]=L00 l[1]=L10 l[2]=L11 (3D: cholesky.hpp).

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_DEEP_HPP
