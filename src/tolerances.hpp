// SPDX-License-Identifier: BSD-3-Clause
// Every tolerance and rounding margin of the search and of the overlap test,
// derived in one place (private). ε = DBL_EPSILON = 2⁻⁵²; cond(A) is bounded
// above by κ̄(A) = tr(A)·tr(A⁻¹) (ldl_cond_bound()). Equation numbers refer
// to docs/optimisation.rst.
#ifndef PW85_SRC_TOLERANCES_HPP
#define PW85_SRC_TOLERANCES_HPP

#include <cfloat>

namespace pw85::detail {

// ---- Rounding margins (certified bounds; the overlap test and the floor)
//
// A quantity computed with a handful of roundings of relative size ε/2 each
// is off by at most about k·ε/2 relative. sphere_margin: the sphere bound
// |r|²/(√tr Q1 + √tr Q2)² takes 15 roundings (two traces, two square roots,
// a sum, a square, a dot product, a division, the final product), at most
// 7.5·ε: 16·ε covers them twice, so (1 − sphere_margin) keeps it a lower
// bound.
constexpr double sphere_margin = 16.0 * DBL_EPSILON;
// f(λ) = λ(1−λ)·rᵀQ(λ)⁻¹r in plain double: the LDLᵀ solve is backward
// stable with |ΔQ| ≤ 4ε|L||D||Lᵀ| (Higham, Theorem 10.3, n = 3), so the
// quadratic form is off by at most a few κ̄(Q)·ε relative, and forming Q(λ)
// and λ(1−λ) adds a few ε. The same holds for rᵀQᵢ⁻¹r (λ = 0 or 1). The
// margin m_f (eq. (5.11)) takes 32·ε·κ̄, at least 4 times that estimate.
constexpr double plain_form_margin = 32.0 * DBL_EPSILON;
// μᵢ² = sᵀQᵢs with s = Q(λ)⁻¹r off by κ̄(Q)·ε relative: a quadratic form in
// an inexact vector, off by that times √κ̄(Qᵢ) (the error of s is amplified
// by at most the ratio of the norms in which Qᵢ measures it). m_μ of
// eq. (5.11) is plain_form_margin·κ̄(Q)·(1 + √max κ̄(Qᵢ)).
// A margin is used only while it is below margin_limit: beyond, the plain
// bounds are not trusted at all and the exact μ² decides.
constexpr double margin_limit = 0.5;
// pw85_overlap applies the accurate bounds (overlap.cpp, filter 4) at a
// point reached by a Newton step of at most this relative size h: λ is
// then within O(h²) of λ*, and so are the bounds of μ².
constexpr double overlap_accurate_step = 1e-5;
// Where the search's Newton stops on a small step, pw85_overlap takes at
// most this many more Newton points before its exact stage.
constexpr int overlap_extra_steps = 2;
// pw85_overlap reports tangency (0) within 4 ulps of 1.
constexpr double tangency = 4.0 * DBL_EPSILON;

// ---- Stopping rules of the search (accuracy, not certification)
//
// The three that pw85.h publishes (PW85_LAMBDA_ATOL, PW85_MAX_ITER,
// PW85_NR_ITER; pw85.cpp checks that they agree): Brent's method stops when
// its bracket is narrower than lambda_atol, after at most brent_max_iter
// iterations; when the first Newton run did not converge, or converged
// outside Brent's bracket, at most restart_newton_iter Newton steps restart
// from Brent's estimate (step 6).
constexpr double lambda_atol = 1e-6;
constexpr int brent_max_iter = 25;
constexpr int restart_newton_iter = 3;
//
// Newton on the plain ω (step 4) stops after a step of relative size h ≤
// newton_accept: its error is then O(h²) ≈ 1e-10, the rounding noise of
// the plain ω for cond(Q) near 1e6. (At 1e-4, λ ended 6e-14 off on the
// reference data, for 1% fewer evaluations.)
constexpr double newton_accept = 1e-5;
// The two-dimensional start (warm_start.hpp, rational_start()) takes at
// most this many Halley steps on its quartic P, and stops where Newton's
// step P/P′ is at most rational_start_accept relative to min(λ, 1 − λ):
// Halley's step from there leaves λ about the cube of that off (to the
// rounding of the coefficients), within the newton_accept of step 4's
// first point.
constexpr int rational_start_steps = 12;
constexpr double rational_start_accept = 1e-2;
// Newton steps on ω from the warm start, before Brent's method certifies.
constexpr int warm_newton_iter = 8;
// The width of Brent's first bracket, which already meets Brent's stopping
// test once it is verified to hold the maximum.
constexpr double first_bracket_width = 0.98 * lambda_atol;
// Each failed check of the bracket widens it by this factor.
constexpr double bracket_growth = 16.0;
// Brent's method (step 5) reuses f at Newton's last point when Newton's
// estimate lies within this fraction of the first bracket's width of it,
// that is well inside the bracket [λ − 0.38·w, λ + 0.62·w].
constexpr double brent_reuse_fraction = 0.125;
// The compensated finish (step 7) starts from Newton's last point, reusing
// its factors, when Newton's last step from it was at most this (relative):
// the first compensated step is then as small, and leaves λ off by its
// square.
constexpr double finish_reuse = 1e-8;
// At most this many compensated evaluations. Well-conditioned problems
// need one or two; ill-conditioned ones, on which the plain search of
// steps 4 to 6 may end far from λ* (its ω is then rounding noise), take
// the steps they need, up to the resolution of the compensated ω.
constexpr int finish_iter = 40;
// A compensated Newton step of relative size h leaves λ off by O(h²) and
// the quadratic model's μ² (eq. (5.10)) off by O(h³) relative: at
// h ≤ finish_accept both are below the rounding of a double, so the step is
// taken and the iteration stops.
constexpr double finish_accept = 1e-7;
// A secant of the finish is a local slope (one that may end it) where its
// two points lie within finish_local of each other, relative to the nearer
// end of [0, 1]: the probe of a start without a slope is 2⁻²⁰ away.
constexpr double finish_local = 0x1p-19;
// The quadratic model's gain ½·f′·Δλ is O(h²)·f ≤ 1e-14·f after such a
// step for a smooth maximum; a gain above max_model_gain·f (or negative)
// means the model does not hold there (a sharp maximum: end-on needles,
// nearly parallel needles or discs), and the iteration goes on. The rule
// is thus one on μ²: the step is the last only when the error left in
// μ² = f + gain, of order gain·h ≤ max_model_gain·finish_accept·f =
// 1e-17·f, is below a tenth of an ulp of μ².
constexpr double max_model_gain = 1e-10;
// The compensated f is refined once (s += Q⁻¹ρ) when κ̄(Q(λ)) exceeds this:
// below, its error O((κ̄·ε)²) is under an ulp already.
constexpr double refine_cond = 1e6;
// Beyond κ̄(Q(λ)) = factor_dd_cond, Q(λ) is factorised in double-double
// (κ̄·2⁻¹⁰⁴ relative error): one refinement from the double factors leaves
// errors of order κ̄²(κ̄·ε)⁴, above an ulp from about κ̄ = 1e12 (measured:
// 45 of 158 random f not correctly rounded at cond 1e12–1e13).
constexpr double factor_dd_cond = 1e10;
// Beyond κ̄(Q(λ)) = p_carry_cond, Pᵢ (for the compensated ω) are formed
// from the refined s as a double-double, not rounded to double: rounded,
// they are off by up to ε·√cond(Qᵢ) relative, which moved λ by up to
// 4e-9·min(λ, 1 − λ) on the hard set (cond(Qᵢ) to 1e16).
constexpr double p_carry_cond = 1e7;

// ---- The contact geometry (geometry.cpp)
//
// λ is polished by Newton steps on the compensated ω, with the plain ω′ as
// slope, from the search's λ (within about 1e-11·min(λ, 1 − λ) of λ*):
// after a step of relative size h ≤ polish_accept, λ is off by O(h²) plus
// the rounding of the compensated ω, below an ulp; the polish then stops.
// A step larger than polish_max_step (relative) is clamped to it (a trust
// region: at maxima so flat that the plain ω is 0 over 2e-3 of λ, ω′ =
// 6e-14 at λ* = 0.357 on a fuzzing input, the search's λ may be that far
// off). At most polish_iter evaluations.
constexpr double polish_accept = 1e-9;
// A step taken with the plain ω′ (the polish's first) ends it only below
// this (relative): the plain ω′ may be off by a few tenths of a percent
// where the plain ω is off by far more than its rounding (polish.hpp), and
// the λ it leaves is then off by that times the step, here below u/8 for a
// slope 1 % off. Larger steps are checked by one more evaluation, whose
// secant slope is accurate. The search's λ is usually within this of λ*:
// then the polish costs one evaluation, as before.
constexpr double polish_plain_accept = 0x1p-50;
// The finish's λ is off by about δω/ω′, relative to the nearer end δω/h
// with h = min(λ, 1 − λ)·ω′ (small at a flat maximum: f″·λ²/μ² small),
// δω the error of ω in double from the compensated Pᵢ, which may be off
// by ε·√κ̄(Qᵢ) relative (compensated.hpp), κ̄ = max κ̄(Qᵢ); measured:
// δω ≈ 5e-11 at κ̄ = 9e15, 0.005·ε·√κ̄. Where h < flat_slope, or
// h < 0.01·ε·√κ̄·10¹⁰ (δω/h above 1e-10 by that measure, twice over),
// the contact function polishes λ as the geometry does (omega_dd(): Pᵢ
// in double-double from s + s_lo). Found by fuzz-contact-structured's
// binary128 oracle: λ 1.8e-8 off at h = 2.6e-3, κ̄ = 9e15, and 1.1e-8 off
// at h ≈ 1e-2, κ̄ = 9.4e15. Measured: 1.4% of random triaxial pairs
// (aspect ratios to 1e3) have h < flat_slope.
constexpr double flat_slope = 1e-2;
constexpr double flat_cond_slope2 =
    (0.01 * 0x1p-52 * 1e10) * (0.01 * 0x1p-52 * 1e10);  // against h²/κ̄
constexpr double polish_max_step = 1e-3;
// The trust radius doubles up to this (relative): λ stays in (0, 1).
constexpr double polish_max_radius = 0.25;
constexpr int polish_iter = 16;
// s = Q(λ)⁻¹·r for the outputs: from the plain factors with one
// refinement by a compensated residual while κ̄(Q(λ)) ≤ geometry_refine_cond
// (relative error (κ̄·ε)² ≤ 5e-20), from a double-double factorisation
// beyond (κ̄·2⁻¹⁰⁴).
constexpr double geometry_refine_cond = 1e6;

}  // namespace pw85::detail

#endif  // PW85_SRC_TOLERANCES_HPP
