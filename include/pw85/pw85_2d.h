/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_2d.h
 * @brief The contact function of Perram and Wertheim for two ellipses, with
 *        the contract of its three-dimensional counterpart (pw85.h).
 *
 * Storage conventions, used by every function below:
 * - a vector is a `double[2]` (PW85_2D_DIM) of Cartesian coordinates;
 * - a symmetric matrix A is a `double[3]` (PW85_2D_SYM) holding its upper
 *   triangle row by row: `a[0]=A00 a[1]=A01 a[2]=A11`.
 *
 * An ellipse of centre c is the set {m : (m − c)ᵀ Q⁻¹ (m − c) ≤ 1}, where
 * Q is symmetric positive definite; Q = a0²·v0·v0ᵀ + a1²·v1·v1ᵀ for
 * semi-axes aᵢ along unit vectors vᵢ. Q has the dimension of a squared
 * length. The contact function μ², its maximiser λ and f(λ) are those of
 * pw85.h with 2 × 2 forms: f(λ) = λ(1 − λ)·r12ᵀ·Q(λ)⁻¹·r12,
 * Q(λ) = (1 − λ)·Q1 + λ·Q2, μ² = max f over [0, 1].
 *
 * One implementation: the library computes these with the same code as
 * the functions of pw85.h, compiled for two dimensions (the same scaling,
 * definiteness rule, search, certification, compensated finish and
 * overlap filters), so every statement of pw85.h about them holds here
 * word for word where it is not about sizes.
 *
 * Positive definite, as stored: the rule of pw85.h. A form is accepted
 * when its entries are finite and it is positive definite exactly, as
 * stored: Q00 > 0 and Q00·Q11 − Q01² > 0 on the exact values of the three
 * doubles (decided in floating point where an error bound proves the
 * answer, else exactly, in integer arithmetic), whatever its scale. A form
 * so nearly singular that double cannot factorise it (cond(Q) ≳ 1/ε) is
 * accepted; the functions that must factorise it answer PW85_ERANGE.
 *
 * Statuses: those of pw85.h (PW85_SUCCESS, PW85_EFAULT, ...), with the
 * same meanings; outputs are written on success only, unless a function
 * says otherwise.
 *
 * Thread safety: every function is reentrant and thread-safe; none keeps
 * state between calls. None prints, aborts, exits, allocates from the heap
 * or changes process-wide state (GSL's error handler is never installed
 * nor reached).
 *
 * @since 2.5.0
 */
#ifndef PW85_2D_H
#define PW85_2D_H

#include "pw85.h"

#ifdef __cplusplus
extern "C" {
#endif

/** @name Sizes of the two-dimensional storage
 *  @{ */
/** The number of coordinates of a vector. @since 2.5.0 */
#define PW85_2D_DIM 2
/** The number of stored entries of a symmetric 2 × 2 matrix. @since 2.5.0 */
#define PW85_2D_SYM 3
/** @} */

/**
 * @brief −f(λ) for two ellipses, in the shape of pw85_f_neg() (and of
 *        GSL's gsl_function: a double, then a pointer to the parameters).
 *
 * f(λ) = λ(1 − λ)·r12ᵀ·Q(λ)⁻¹·r12, Q(λ) = (1 − λ)·Q1 + λ·Q2, evaluated as
 * pw85_f_neg() evaluates it: compensated (double-double) arithmetic, Q(λ)
 * factorised in double-double where the bound tr(Q)·tr(Q⁻¹) of cond(Q(λ))
 * exceeds 1e10. Measured: correctly rounded at the 4 λ of each of the
 * 2D reference pairs within the range below (10 472 values, cond to
 * 1e15). No rescaling: intermediate values must stay within the
 * range of a double (|r12|² and the entries of Q1, Q2 between about
 * 1e-150 and 1e150).
 * @param[in] lambda λ, normally in [0, 1].
 * @param[in] params PW85_2D_DIM + 2·PW85_2D_SYM = 8 doubles: r12[2] (the
 *                   centre-to-centre vector c2 − c1), then q1[3], then
 *                   q2[3].
 * @return −f(λ) (a squared length over a squared length: dimensionless),
 *         never positive for λ in [0, 1] (−0 where rounding, with
 *         cond(Q(λ)) beyond ~1e14, would make f negative); NaN if params
 *         is NULL, if lambda or an entry of params is not finite, if q1
 *         or q2 is not positive definite by the rule above, or if Q(λ) is
 *         not positive definite to the resolution of its factorisation.
 * @since 2.5.0
 */
PW85_API double pw85_2d_f_neg(double lambda,
                              double const params[PW85_2D_DIM +
                                                  2 * PW85_2D_SYM])
    PW85_NOEXCEPT;

/**
 * @brief The contact function μ² of two ellipses and its maximiser λ.
 *
 * μ² = max over λ in [0, 1] of f(λ): the square of the common factor by
 * which both ellipses must be scaled, centres fixed, to be externally
 * tangent (μ² < 1: they overlap; μ² > 1: they are disjoint). μ² is
 * dimensionless and invariant under r12 → t·r12, Q → t²·Q, and under a
 * rotation of the whole configuration; inputs are rescaled internally by
 * powers of two, so any finite input is accepted. Documented domain:
 * cond(Q1), cond(Q2) < 1e16 (aspect ratios to 1e8), where μ² is
 * correctly rounded (the method of pw85_contact_function(), whose
 * guarantees it shares): on every one of the 3000 reference pairs of
 * data/pw85_2d_pairs.h5 (needles to aspect 1e6, |μ² − 1| down to 1e-15,
 * λ* within 1e-22 of 0 or 1, cond to 1e15, extreme scales, tiny r12, flat
 * maxima), with λ inside the interval where f is within an ulp of μ².
 * Swapping the ellipses, (r12, q1, q2) → (−r12, q2, q1), gives the same μ²
 * bit for bit and λ → 1 − λ (rounded), for any input. Beyond the domain
 * the answer is still finite, ≥ (1 − 24ε)·|r12|²/(√tr Q1 + √tr Q2)² > 0,
 * with the statuses below, but may be inaccurate.
 * @param[in] r12 the centre-to-centre vector c2 − c1 (a length; any
 *                finite vector; r12 = 0 gives μ² = 0, λ = ½).
 * @param[in] q1 the quadratic form of the first ellipse (a squared
 *               length).
 * @param[in] q2 the quadratic form of the second ellipse.
 * @param[out] out out[0] = μ² (≥ 0; may round to a subnormal or to 0 when
 *                 μ² is below the range of a double), out[1] = λ in
 *                 [0, 1].
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL (out untouched);
 *         PW85_EDOM if an input is NaN or infinite (out untouched);
 *         PW85_ENOTPOSDEF if q1 or q2 is not positive definite as stored,
 *         by the rule above (out untouched);
 *         PW85_ERANGE if μ² exceeds DBL_MAX: out[0] = +infinity,
 *         out[1] = λ; or if the diagonal entries of q1 and q2 together
 *         span more than the search can carry (as pw85.h: binary
 *         exponents more than 2016 apart, about 1e607), or q1 or q2, positive
 *         definite, cannot be factorised in double once both are rescaled,
 *         or f cannot be evaluated in double along the search (forms
 *         singular far beyond the domain; out untouched);
 *         PW85_ENOMEM if GSL's minimiser would need more than the working
 *         memory reserved on the stack (out untouched; not expected).
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_function(double const r12[PW85_2D_DIM],
                                      double const q1[PW85_2D_SYM],
                                      double const q2[PW85_2D_SYM],
                                      double out[2]) PW85_NOEXCEPT;

/**
 * @brief Do two ellipses overlap? A certified decision, faster than
 *        computing μ² (the method of pw85_overlap()).
 *
 * Decides the sign of μ² − 1 from bounds that hold at every λ, with
 * certified rounding margins, and falls back to the exact μ² of
 * pw85_2d_contact_function() only near tangency (or beyond the bounds'
 * reach), so the answer never contradicts it.
 * @param[in] r12 the centre-to-centre vector c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipse.
 * @param[in] q2 the quadratic form of the second ellipse.
 * @param[out] result −1 if the ellipses overlap (μ² < 1), +1 if they are
 *             disjoint (μ² > 1), 0 if they are tangent to the resolution
 *             of double arithmetic: |μ² − 1| ≤ 4·DBL_EPSILON, μ² the
 *             exact value (as pw85_overlap()). Coincident
 *             centres overlap. Swapping the ellipses gives the same
 *             answer.
 * @return the statuses of pw85_2d_contact_function(), with the same
 *         meaning; *result is written on PW85_SUCCESS only (also when μ²
 *         would overflow: such ellipses are disjoint, *result = +1); with
 *         the exception of pw85_overlap(): PW85_SUCCESS, +1, where the
 *         sphere bound alone proves the ellipses disjoint though the
 *         contact function cannot evaluate f (far beyond the domain).
 * @since 2.5.0
 */
PW85_API int pw85_2d_overlap(double const r12[PW85_2D_DIM],
                             double const q1[PW85_2D_SYM],
                             double const q2[PW85_2D_SYM],
                             int *result) PW85_NOEXCEPT;

/** @name Layout of the output of pw85_2d_contact_geometry()
 *  Offsets into `double out[PW85_2D_GEOM_SIZE]`; fixed.
 *  @{ */
#define PW85_2D_GEOM_MU2 0     /**< μ², as pw85_2d_contact_function().
                                    @since 2.5.0 */
#define PW85_2D_GEOM_LAMBDA 1  /**< λ, the maximiser. @since 2.5.0 */
#define PW85_2D_GEOM_POINT 2   /**< 2 doubles: x − c1, the contact point
                                    of the scaled ellipses relative to c1.
                                    @since 2.5.0 */
#define PW85_2D_GEOM_NORMAL 4  /**< 2 doubles: the unit normal at x, from
                                    ellipse 1 towards ellipse 2.
                                    @since 2.5.0 */
#define PW85_2D_GEOM_SIZE 6    /**< the number of doubles. @since 2.5.0 */
/** @} */

/** @name Layout of the output of pw85_2d_contact_derivatives()
 *  Offsets into `double d[PW85_2D_DERIV_SIZE]`; fixed.
 *  @{ */
#define PW85_2D_DERIV_R12 0    /**< 2 doubles: ∂μ²/∂r12 (1/length).
                                    @since 2.5.0 */
#define PW85_2D_DERIV_THETA1 2 /**< 1 double: ∂μ²/∂θ1, θ1 the angle
                                    (radians, counter-clockwise) turning
                                    ellipse 1 about c1. @since 2.5.0 */
#define PW85_2D_DERIV_THETA2 3 /**< 1 double: ∂μ²/∂θ2, the same for
                                    ellipse 2 about c2. @since 2.5.0 */
#define PW85_2D_DERIV_Q1 4     /**< 3 doubles: ∂μ²/∂q1[k], k = 0..2, with
                                    respect to the three stored entries
                                    (1/squared length). @since 2.5.0 */
#define PW85_2D_DERIV_Q2 7     /**< 3 doubles: ∂μ²/∂q2[k]. @since 2.5.0 */
#define PW85_2D_DERIV_SIZE 10  /**< the number of doubles. @since 2.5.0 */
/** @} */

/**
 * @brief The contact function, the contact point and the common normal
 *        of two ellipses (the method of pw85_contact_geometry()).
 *
 * One search, that of pw85_2d_contact_function() (same μ², bit for bit),
 * then λ polished by Newton steps on ω in compensated arithmetic and
 * s = Q(λ)⁻¹·r12 solved with compensated residuals; x − c1 =
 * (1 − λ)·Q1·s, the point where the ellipses scaled by μ touch, and
 * n = s/‖s‖, the outward normal of scaled ellipse 1 at x, n·r12 > 0.
 * Accuracy, measured on the 400 pairs of data/pw85_2d_geometry.h5
 * (references at 60 digits and more, 40 of each class of the 2D reference
 * pairs), with u = 2⁻⁵³ and c = cond(Q(λ)) + 1/min(λ, 1 − λ): λ within
 * 0.98·u·cond(Q(λ)) relative to min(λ, 1 − λ) (less the half-ulp of its
 * rounding near 1); x − c1 and n within 0.46·u·c relative to their norms.
 * (The term 1/min(λ, 1 − λ): where λ is near 1 but the search kept λ, not
 * 1 − λ, as its variable, the weight 1 − λ is known to u/(1 − λ) only, as
 * pw85.h says of λ.) The tests hold them to 8 times that. Swapping the
 * ellipses gives the same μ², λ → 1 − λ and n → −n.
 * @param[in] r12 c2 − c1; r12 = 0 gives μ² = 0, λ = ½, x − c1 = 0 and
 *                n = 0.
 * @param[in] q1 the quadratic form of the first ellipse.
 * @param[in] q2 the quadratic form of the second ellipse.
 * @param[out] out PW85_2D_GEOM_SIZE doubles, laid out as PW85_2D_GEOM_*.
 * @return the statuses of pw85_2d_contact_function(), with the same
 *         meaning; out untouched on error, except PW85_ERANGE when a
 *         result overflows (μ² = +∞, or x − c1 beyond DBL_MAX): every
 *         output is then written, some infinite. Also PW85_ERANGE, out
 *         untouched, where Q(λ) cannot be factorised at the maximiser
 *         (far beyond the documented domain).
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_geometry(double const r12[PW85_2D_DIM],
                                      double const q1[PW85_2D_SYM],
                                      double const q2[PW85_2D_SYM],
                                      double out[PW85_2D_GEOM_SIZE])
    PW85_NOEXCEPT;

/**
 * @brief pw85_2d_contact_geometry() and the first derivatives of μ²: for
 *        forces, torques and changes of shape.
 *
 * By the envelope theorem, with s = Q(λ)⁻¹·r12 at the maximiser:
 * ∂μ²/∂r12 = 2λ(1 − λ)·s (with respect to c2; to c1, its opposite);
 * ∂μ²/∂q1 = −λ(1 − λ)²·(s0², 2·s0·s1, s1²) and
 * ∂μ²/∂q2 = −λ²(1 − λ)·(s0², 2·s0·s1, s1²), with respect to the stored
 * entries (the off-diagonal one counts twice), so that
 * δμ² = Σₖ (∂μ²/∂q1[k])·δq1[k]; turning ellipse i about its centre by an
 * angle θᵢ, Qᵢ → R(θᵢ)·Qᵢ·R(θᵢ)ᵀ (R as in pw85_2d_ellipse()):
 * ∂μ²/∂θ1 = 2λ(1 − λ)²·s × (Q1·s) and ∂μ²/∂θ2 = 2λ²(1 − λ)·s × (Q2·s),
 * with a × b = a0·b1 − a1·b0. For a pair energy U(μ²): the force on
 * ellipse 2 is −U′·∂μ²/∂r12, the torque on ellipse i is −U′·∂μ²/∂θᵢ.
 * Accuracy, measured as for pw85_2d_contact_geometry(), in the same units
 * u·c: ∂μ²/∂r12 within 0.48, ∂μ²/∂q1 and ∂μ²/∂q2 within 1.1, relative to
 * the norm of each block; ∂μ²/∂θᵢ within 0.46 of their scale
 * |∂μ²/∂r12|·|x − cᵢ| (a torque may vanish). Swapping the ellipses exchanges ∂μ²/∂θ1 and
 * ∂μ²/∂θ2, ∂μ²/∂q1 and ∂μ²/∂q2, and negates ∂μ²/∂r12.
 * @param[in] r12 c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipse.
 * @param[in] q2 the quadratic form of the second ellipse.
 * @param[out] geometry PW85_2D_GEOM_SIZE doubles, as
 *             pw85_2d_contact_geometry().
 * @param[out] d PW85_2D_DERIV_SIZE doubles, laid out as PW85_2D_DERIV_*.
 * @return as pw85_2d_contact_geometry(); with PW85_ERANGE, both arrays
 *         are written.
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_derivatives(double const r12[PW85_2D_DIM],
                                         double const q1[PW85_2D_SYM],
                                         double const q2[PW85_2D_SYM],
                                         double geometry[PW85_2D_GEOM_SIZE],
                                         double d[PW85_2D_DERIV_SIZE])
    PW85_NOEXCEPT;

/**
 * @brief The quadratic form of an ellipse from its semi-axes and an angle:
 *        Q = R(θ)·diag(a0², a1²)·R(θ)ᵀ, R(θ) = [[cos θ, −sin θ],
 *        [sin θ, cos θ]].
 *
 * a[0] lies along (cos θ, sin θ), a[1] along (−sin θ, cos θ). Accuracy:
 * cos θ and sin θ come from the C library, rounded to double; for those,
 * every entry of Q is computed in double-double arithmetic and rounded
 * once (as pw85_ellipsoid_rotation()). Against Q_k exact for the θ given,
 * with u = 2⁻⁵³: |q[k] − Q_k| ≤ 2u·(|Q_k| + Σₘ |R_im·R_jm|·aₘ²) (the
 * rounding of cos θ and sin θ included; measured at most 1.3 u·(…) on the
 * 264 constructor cases of data/pw85_2d_geometry.h5). Q is exactly
 * symmetric by construction.
 * @param[in] a the two semi-axes (lengths, each > 0).
 * @param[in] theta the angle θ from the x axis to the axis of a[0]
 *                  (radians, counter-clockwise; any finite value).
 * @param[out] q the quadratic form Q (a squared length).
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL;
 *         PW85_EDOM if a[0], a[1] or theta is NaN or infinite;
 *         PW85_EINVAL if a semi-axis is not > 0;
 *         PW85_ERANGE if an aₘ² overflows or underflows.
 *         q is written on success only.
 * @since 2.5.0
 */
PW85_API int pw85_2d_ellipse(double const a[PW85_2D_DIM], double theta,
                             double q[PW85_2D_SYM]) PW85_NOEXCEPT;

/**
 * @brief The semi-axes and orientation of an ellipse: the inverse of
 *        pw85_2d_ellipse().
 *
 * θ = ½·atan2(2·Q01, Q00 − Q11) on Q as stored (every entry halved
 * first, exactly, where 2·Q01 would overflow), the direction of the larger
 * semi-axis, off by the roundings of Q00 − Q11 and of atan2 only, whatever
 * the eccentricity and the range of the entries; a0² is then the
 * Rayleigh quotient of that direction and a1² = det(Q)/a0², both in
 * double-double arithmetic, which keeps the small semi-axis of a needle
 * accurate (relative error of aⱼ at most u·(1 + u·(a0/aⱼ)²), u = 2⁻⁵³). Measured on
 * the 264 constructor cases of data/pw85_2d_geometry.h5 (aspect ratios to
 * 1e8, near-circles): every aⱼ correctly rounded, θ within an ulp.
 * Semi-axes in decreasing order, a[0] ≥ a[1] > 0; θ in (−π/2, π/2],
 * θ = 0 for a circle.
 * @param[in] q the quadratic form Q.
 * @param[out] a the semi-axes, in decreasing order.
 * @param[out] theta the angle from the x axis to the axis of a[0]
 *             (radians).
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL; PW85_EDOM if an
 *         entry of q is NaN or infinite; PW85_ENOTPOSDEF if Q is not
 *         positive definite by the rule above; PW85_ERANGE if the
 *         Rayleigh quotient or det(Q) is not > 0 in double-double (Q
 *         singular to that precision). a and theta are written on success
 *         only.
 * @since 2.5.0
 */
PW85_API int pw85_2d_principal_axes(double const q[PW85_2D_SYM],
                                    double a[PW85_2D_DIM],
                                    double *theta) PW85_NOEXCEPT;

/** @name Batches
 *  The functions above for n pairs (or n ellipses), with the conventions
 *  of pw85.h, "Batches": strides in doubles (PW85_2D_DIM and PW85_2D_SYM
 *  when contiguous, 0 for one record for every pair, 1 to the record's
 *  size − 1 an error: PW85_EINVAL), contiguous outputs, `status` NULL or
 *  n ints, every pair computed as the single-pair function computes it
 *  (the same outputs bit for bit, for any number of threads), the status
 *  of the first failing pair returned; PW85_EFAULT or PW85_EINVAL for the
 *  call itself (nothing written, `status` filled with the code); n = 0:
 *  PW85_SUCCESS, whatever the other arguments. Threads as
 *  pw85_batch_threads() says.
 *  @{ */

/**
 * @brief pw85_2d_contact_function() for n pairs.
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_2D_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipses.
 * @param[in] q1_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipses.
 * @param[in] q2_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[out] out 2·n doubles: `out[2·i]` = μ², `out[2·i + 1]` = λ.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return PW85_SUCCESS, or the status of the first failing pair;
 *         PW85_EFAULT or PW85_EINVAL for the call itself.
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_function_batch(
    size_t n, double const *r12, size_t r12_stride, double const *q1,
    size_t q1_stride, double const *q2, size_t q2_stride, double *out,
    int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_2d_overlap() for n pairs.
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_2D_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipses.
 * @param[in] q1_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipses.
 * @param[in] q2_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[out] result n ints: −1, +1 or 0 for each pair, as
 *             pw85_2d_overlap().
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return as pw85_2d_contact_function_batch().
 * @since 2.5.0
 */
PW85_API int pw85_2d_overlap_batch(size_t n, double const *r12,
                                   size_t r12_stride, double const *q1,
                                   size_t q1_stride, double const *q2,
                                   size_t q2_stride, int *result,
                                   int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_2d_contact_geometry() for n pairs.
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_2D_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipses.
 * @param[in] q1_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipses.
 * @param[in] q2_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[out] out n·PW85_2D_GEOM_SIZE doubles: pair i at
 *             `out + i·PW85_2D_GEOM_SIZE`, laid out as PW85_2D_GEOM_*.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return as pw85_2d_contact_function_batch().
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_geometry_batch(
    size_t n, double const *r12, size_t r12_stride, double const *q1,
    size_t q1_stride, double const *q2, size_t q2_stride, double *out,
    int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_2d_contact_derivatives() for n pairs.
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_2D_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipses.
 * @param[in] q1_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipses.
 * @param[in] q2_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[out] geometry n·PW85_2D_GEOM_SIZE doubles, as
 *             pw85_2d_contact_geometry_batch().
 * @param[out] d n·PW85_2D_DERIV_SIZE doubles: pair i at
 *             `d + i·PW85_2D_DERIV_SIZE`, laid out as PW85_2D_DERIV_*.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return as pw85_2d_contact_function_batch().
 * @since 2.5.0
 */
PW85_API int pw85_2d_contact_derivatives_batch(
    size_t n, double const *r12, size_t r12_stride, double const *q1,
    size_t q1_stride, double const *q2, size_t q2_stride, double *geometry,
    double *d, int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_2d_ellipse() for n ellipses.
 * @param[in] n the number of ellipses (0 is valid).
 * @param[in] a the semi-axes (lengths), item i at `a + i·a_stride`.
 * @param[in] a_stride PW85_2D_DIM when contiguous, 0 for one pair of
 *            semi-axes.
 * @param[in] theta the angles (radians), item i at `theta[i·theta_stride]`.
 * @param[in] theta_stride 1 when contiguous, 0 for one angle.
 * @param[out] q n·PW85_2D_SYM doubles: item i at `q + i·PW85_2D_SYM`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return PW85_SUCCESS, or the status of the first failing item (those of
 *         pw85_2d_ellipse()); PW85_EFAULT or PW85_EINVAL for the call.
 * @since 2.5.0
 */
PW85_API int pw85_2d_ellipse_batch(size_t n, double const *a,
                                   size_t a_stride, double const *theta,
                                   size_t theta_stride, double *q,
                                   int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_2d_principal_axes() for n ellipses.
 * @param[in] n the number of ellipses (0 is valid).
 * @param[in] q the forms, item i at `q + i·q_stride`.
 * @param[in] q_stride PW85_2D_SYM when contiguous, 0 for one form.
 * @param[out] a n·PW85_2D_DIM doubles: item i at `a + i·PW85_2D_DIM`.
 * @param[out] theta n doubles: the angle of item i.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k.
 * @return PW85_SUCCESS, or the status of the first failing item (those of
 *         pw85_2d_principal_axes()); PW85_EFAULT or PW85_EINVAL for the
 *         call.
 * @since 2.5.0
 */
PW85_API int pw85_2d_principal_axes_batch(size_t n, double const *q,
                                          size_t q_stride, double *a,
                                          double *theta, int *status,
                                          int threads) PW85_NOEXCEPT;
/** @} */

#ifdef __cplusplus
}
#endif

#endif /* PW85_2D_H */
