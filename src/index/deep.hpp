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

// A radius ρ ≥ 0 of a ball about the centre inside the ellipsoid
// {x : xᵀQ⁻¹x ≤ 1}: ρ² < λmin(Q), certified (0 when not found; always 0
// unless every Q_kk is in [moderate_low, moderate_high]). An estimate s₀
// of λmin(Q) is checked by the Cholesky factorisation of
// Q − (s₀ + shift_margin·max Q_kk)·I. Within 2⁻¹⁷ of √λmin(Q) for forms
// of moderate condition.
double inscribed_radius(double const q[sym]) noexcept;

// The candidate's side of deep_overlap(): its Cholesky factor l and a
// certified lower bound *s of λmin(Q), when every Q_kk is in
// [moderate_low, moderate_high] and tr(Q) ≤ max_trace_ratio·s
// (margins.hpp, line_factor()); else false. No eigenvalue is computed: a
// query factors its candidate once.
bool line_factor(double const q[sym], double l[sym], double *s) noexcept;

// Does the point of the segment from c to c + r̂ at distance
// ρ_e·(1 − deep_shrink) from c + r̂ lie in the candidate (Cholesky factor
// lq) scaled by 1 − deep_shrink, with the margins of margins.hpp
// (deep_overlap())? d2 = |r̂|² as computed. The caller checks
// (Σσ_k)² ≤ deep_slack·s: then μ² ≤ (1 − 2⁻²⁰)² for the exact r.
bool deep_overlap(double const lq[sym], double const r[dim], double d2,
                  double rho_e) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_DEEP_HPP
