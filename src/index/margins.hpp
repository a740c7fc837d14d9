// SPDX-License-Identifier: BSD-3-Clause
// Every margin and limit of the spatial index, derived once (private; as
// src/tolerances.hpp does for the pair; docs/assemblies.rst, "Why the
// answers are certified"). u = 2⁻⁵³ is the unit roundoff, ε = 2u; a
// quantity formed with k roundings is off by at most k·u relative
// (1 + O(u)). The broad phase (broad.hpp) discards only pairs with
// μ² > t·(1 + broad_margin); the shortcut of overlap_any() (deep overlap,
// index.cpp) decides only pairs with μ² ≤ (1 − 2⁻²⁰)²: both far outside
// the 4-ulp band of pw85_overlap(), so that neither can change a decision
// of the narrow phase.
#ifndef PW85_SRC_INDEX_MARGINS_HPP
#define PW85_SRC_INDEX_MARGINS_HPP

#include <cstdint>

namespace pw85::detail {

// ---- The broad phase (broad.hpp) -----------------------------------------
//
// broad_margin: the box and line-of-centres tests compare with bounds
// inflated by 1 + 2⁻²⁰; the roundings of those bounds (a handful, below
// 2⁻⁵⁰ relative) and the folding of the slack below (2⁻²² relative) take
// less than half of it, so that a discarded pair has
// μ² > t·(1 + 2⁻²⁰/2)² > t·(1 + 2⁻²⁰).
constexpr double broad_margin = 0x1p-20;
//
// slack_factor: the absolute rounding allowance along an axis of a query
// of centre c and reach R (R ≥ every bound its box test uses), in an index
// whose stored centres have |c_k| ≤ cmax:
//   σ_k = 2⁻⁴⁰·(cmax + |c_k| + R_k + L_k)   (L_k = 0 in an open domain).
// (1) The image vector r̂ = (c_j + n∘L) − c formed in double (three
// roundings, n_k·L_k, + c_j, − c) is off by at most
// 3u·(1 + 2u)·(|c_j| + |n_k·L_k| + |c_k|) along k; an image within R of c
// has |n_k·L_k| ≤ cmax + |c_k| + R_k, so the error is below
// 2⁻⁵⁰·(cmax + |c_k| + R_k) ≤ σ_k: the box test compares |r̂_k| with its
// bound plus σ_k, and an image whose exact r meets the bound is kept.
// (2) The cell arithmetic (the wrap, the products by 1/side, c ± R) rounds
// magnitudes below cmax + |c| + R + L a few times each (2⁻⁵⁰ of them):
// the range of cells is widened by σ_k.
constexpr double slack_factor = 0x1p-40;
//
// The line-of-centres test on r̂ (exact r = r̂ + δ, |δ| ≤ Σσ_k): it is
// decided only when Σσ_k ≤ slack_fold·|r̂| (checked squared), so that
// u·r ≥ |r̂|·(1 − 2⁻²²) for u = r̂/|r̂| (folded into broad_margin above).
constexpr double slack_fold = broad_margin / 4;  // 2⁻²²
//
// form_rounding: rᵀQr in double (six products, five sums) is off by at
// most 11u·Σ|Q_ij||r_i||r_j| ≤ 11u·(Σ_k h_k|r_k|)², h_k = √Q_kk bounding
// |Q_ij| ≤ h_i·h_j: 2⁻⁴⁰·(Σ_k h_k|r_k|)², added to it, covers that.
constexpr double form_rounding = 0x1p-40;
//
// The line test is formed as it stands while |r̂|² lies in
// [line_low, line_high]; otherwise r̂ and the forms are first scaled by
// powers of two (r̂ to order one), exactly but for underflow or overflow.
// An overflow makes a bound +∞ or NaN, which keeps the pair (the narrow
// phase decides); an underflow is an absolute error below 2⁻¹⁰⁷⁰ in each
// rᵀQr, and form_floor = 2⁻¹⁰⁰⁰ added to each covers it. Against
// |r̂|² ≥ 2⁻⁴⁰⁰ (or ≥ ¼ once scaled) the floor weighs below 2⁻¹⁰⁰
// relative: no decision depends on an underflowed value.
constexpr double line_low = 0x1p-400;
constexpr double line_high = 1.0 / line_low;
constexpr double form_floor = 0x1p-1000;

// ---- The deep-overlap shortcut of overlap_any() (index.cpp) --------------
//
// moderate_low, moderate_high: inscribed radii and the candidate's factor
// are computed only for forms whose Q_kk all lie in [2⁻³⁰⁰, 2³⁰⁰]: nothing
// below over- or underflows, and two such forms are within the range that
// pw85_overlap() accepts.
constexpr double moderate_low = 0x1p-300;
constexpr double moderate_high = 1.0 / moderate_low;
//
// inscribed_radius(): λmin(Q) > s₀ is certified by the Cholesky
// factorisation of Q − s·I, s = s₀ + shift_margin·M (M = max Q_kk): it
// completes only if Q − s·I + E is positive definite for some
// ‖E‖₂ ≤ 3γ₄·M + u·M < 2⁻⁴⁸·M (Higham, Accuracy and Stability of Numerical
// Algorithms, 2nd ed., th. 10.3, and the rounding of the diagonal), and
// 2⁻⁴⁶ > 2⁻⁴⁸. The estimate s₀ is lowered first by estimate_lowering
// (the cubic's) or fallback_lowering (the bound 1/‖Q⁻¹‖_F), so that a
// good estimate passes the check; estimates below estimate_floor are not
// used (ρ would be negligible). √s₀ rounds up by half an ulp at most:
// ρ = √s₀·(1 − root_lowering).
constexpr double shift_margin = 0x1p-46;
constexpr double estimate_lowering = 0x1p-16;
constexpr double fallback_lowering = 0x1p-10;
constexpr double estimate_floor = 0x1p-900;
constexpr double root_lowering = 0x1p-50;
//
// line_factor(): the candidate's Cholesky factor L, computed, is that of
// some Q + ΔA, ‖ΔA‖₂ ≤ γ₄·‖L‖_F² < 2⁻⁵⁰·tr(Q) (th. 10.3); for a 3×3
// matrix σmin(L) ≥ 2·|det L|/‖L‖_F², so λmin(Q) ≥ g² − 2⁻⁵⁰·tr(Q),
// g = 2·L₀₀L₁₁L₂₂/‖L‖_F². The certified s lowers g² by factor_lowering
// (its dozen roundings) and takes the second term as factor_shift·tr(Q).
// The factor is used only when tr(Q) ≤ max_trace_ratio·s.
constexpr double factor_lowering = 0x1p-40;
constexpr double factor_shift = 0x1p-48;
constexpr double max_trace_ratio = 0x1p20;
//
// deep_overlap(): the point p of the segment from the candidate's centre
// c to the stored one's, c + r, at distance ρ_e·(1 − deep_shrink) from
// c + r, lies in the stored ellipsoid scaled by 1 − deep_shrink (its
// inscribed ball); it is in the candidate so scaled when
// t·√(rᵀQ⁻¹r) ≤ |r|·(1 − deep_shrink), t = |r| − ρ_e·(1 − deep_shrink).
// rᵀQ⁻¹r = |L⁻¹r|²: the computed factor and forward substitution give the
// exact |y|² of some Q + E, ‖E‖₂ ≤ (γ₄ + 2γ₃ + γ₃²)·tr(Q) < 2⁻⁴⁸·tr(Q)
// (th. 10.3 and 8.5), so that rᵀQ⁻¹r ≤ |y|²/(1 − η),
// η = ‖E‖₂/(λmin(Q) − ‖E‖₂) < 2⁻²⁷ when tr(Q) ≤ 2²⁰·λmin(Q)
// (max_trace_ratio). The test inflates |y|² by deep_form (2⁻²² ≫ η),
// t by deep_rounding·(|r| + ρ_e) (its rounding and that of |r|), and
// lowers the bound to |r|·(1 − deep_bound): p is then within 1 − 2⁻¹⁹ of
// c in the candidate's norm. Formed on r̂, not on the exact r = r̂ + δ:
// the point p + δ, at the same place relative to c + r, is within
// 1 − 2⁻¹⁹ + 2⁻²¹ < 1 − deep_shrink when |δ|_Q⁻¹ ≤ Σσ_k/√s ≤ 2⁻²¹, that is
// when (Σσ_k)² ≤ deep_slack·s (s: the certified λmin of line_factor()).
// Then μ² ≤ (1 − 2⁻²⁰)² < 1 − 2⁻²⁰.
constexpr double deep_shrink = 0x1p-20;
constexpr double deep_form = deep_shrink / 4;  // 2⁻²²
constexpr double deep_rounding = 0x1p-48;
constexpr double deep_bound = 2 * deep_shrink;  // 2⁻¹⁹
constexpr double deep_slack = (deep_shrink / 2) * (deep_shrink / 2);  // 2⁻⁴²
//
// Ellipses (D = 2, deep.cpp): the bounds above hold a fortiori. The 2 × 2
// Cholesky factorisation and forward substitution have backward errors
// with γ₃ and γ₂ where the 3 × 3 ones have γ₄ and γ₃ (th. 10.3 and 8.5);
// σmin(L) ≥ g = |det L|/‖L‖_F (σ₁·σ₂ = |det L|, σ₂ ≤ ‖L‖_F), formed with
// fewer roundings than the 3D g; the estimates of λmin (the root of the
// quadratic, then 1/‖Q⁻¹‖_F) are only estimates, certified as in 3D.

// ---- Limits --------------------------------------------------------------
//
// Centres: |c_k| ≤ max_wraps·L_k (periodic), so that wraps and shifts fit
// an int32.
constexpr double max_wraps = 0x1p29;
// Sides L_k ≤ max_side (periodic) and centres |c_k| ≤ max_centre (open;
// periodic: max_wraps·max_side, the same), so that no sum that the
// queries form overflows: |c_k − c'_k| ≤ 2¹⁰²², an image vector
// c'_k + n_k·L_k − c_k (|n_k| ≤ max_span) below 2¹⁰²³, and the slack of
// margins (cmax + |c| + L, before the reach) below 2¹⁰²³. A reach beyond
// that covers more than max_span sides, or, in an open domain, the
// whole grid: +∞ there is handled as such.
constexpr double max_side = 0x1p992;
constexpr double max_centre = max_wraps * max_side;  // 2¹⁰²¹
// The most cells (or image shifts) a query visits along an axis.
constexpr double max_span = 0x1p20;
// The most cells of a dense level (16 MiB of positions).
constexpr double dense_cells = 0x1p22;
// An open domain's cell coordinates are clamped to [−open_half,
// open_half) (the clamp is monotone: a range of positions maps onto the
// range of their cells).
constexpr double open_half = max_span;  // 2²⁰
// Ids fit 32 bits; 0xFFFFFFFF is no id.
constexpr std::uint32_t no_id = 0xFFFFFFFFu;
constexpr std::size_t max_id = 0xFFFFFFFEu;

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_MARGINS_HPP
