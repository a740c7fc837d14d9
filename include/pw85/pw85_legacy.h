/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85_legacy.h
 * @brief The legacy C ABI of pw85 (library libpw85_legacy, pkg-config
 *        module pw85_legacy): the earlier implementations of the function f
 *        and of the contact function, kept for reference and for the
 *        accuracy comparison of the documentation (docs/implementation.rst and docs/legacy-api.rst).
 *        New code should call pw85_f_neg() and pw85_contact_function().
 *
 * Storage conventions, status codes and the contact problem are those of
 * pw85.h: vectors are `double[PW85_DIM]`, symmetric matrices are
 * `double[PW85_SYM]` holding the upper triangle row by row.
 *
 * Thread safety: every function is reentrant and thread-safe; none keeps
 * state between calls. None prints, aborts, exits, allocates from the heap,
 * or changes process-wide state.
 *
 * Versions: what carries no `@since` is the legacy C API of pw85 1.0;
 * `@since` marks what a later release added. Symbol versions as in pw85.h,
 * with nodes of their own: PW85_LEGACY_2.0, PW85_LEGACY_X.Y.
 */
#ifndef PW85_LEGACY_H
#define PW85_LEGACY_H

#include "pw85.h"

/** Marks a deprecated spelling; define it (for example as empty) before
 *  including this header to override.
 *  @since 2.1.0 */
#ifndef PW85_LEGACY_DEPRECATED
#if defined(__GNUC__) && \
    (__GNUC__ > 4 || (__GNUC__ == 4 && __GNUC_MINOR__ >= 5))
#define PW85_LEGACY_DEPRECATED(msg) __attribute__((deprecated(msg)))
#else
#define PW85_LEGACY_DEPRECATED(msg)
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/**
 * @brief The determinant of a symmetric 3×3 matrix A.
 *
 * Preconditions, not checked: a is a valid pointer.
 * @param[in] a the matrix A (upper triangle, see pw85.h).
 * @return det(A), by cofactor expansion (not finite if an entry is not).
 */
PW85_API double pw85_legacy__det_sym(double const a[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief The quadratic form xᵀ·adj(A)·x of the adjugate of A (the transpose
 *        of its cofactor matrix).
 *
 * Preconditions, not checked: x and a are valid pointers.
 * @param[in] x the vector x.
 * @param[in] a the symmetric matrix A (upper triangle, see pw85.h).
 * @return xᵀ·adj(A)·x.
 */
PW85_API double pw85_legacy__xT_adjA_x(double const x[PW85_DIM],
                                       double const a[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief The coefficients of the cubic λ ↦ det[(1−λ)·Q1 + λ·Q2] =
 *        b[0] + b[1]·λ + b[2]·λ² + b[3]·λ³ (increasing order).
 *
 * Computed from the determinants at λ = 0, 1, −1 and ½, which are those of
 * q1, q2, q3 and q4. Preconditions, not checked: valid pointers;
 * q3[i] = 2·q1[i] − q2[i] and q4[i] = (q1[i] + q2[i])/2 for every i.
 * @param[in] q1 the matrix Q1 (upper triangle).
 * @param[in] q2 the matrix Q2.
 * @param[in] q3 the matrix 2·Q1 − Q2.
 * @param[in] q4 the matrix (Q1 + Q2)/2.
 * @param[out] b the coefficients b0, b1, b2, b3.
 */
PW85_API void pw85_legacy__detQ_as_poly(double const q1[PW85_SYM],
                                        double const q2[PW85_SYM],
                                        double const q3[PW85_SYM],
                                        double const q4[PW85_SYM],
                                        double b[PW85_DIM + 1]) PW85_NOEXCEPT;

/**
 * @brief The coefficients of the quadratic λ ↦ rᵀ·adj[(1−λ)·Q1 + λ·Q2]·r =
 *        a[0] + a[1]·λ + a[2]·λ² (increasing order).
 *
 * Computed from the values at λ = 0, 1 and −1, which use q1, q2 and q3.
 * Preconditions, not checked: valid pointers; q3[i] = 2·q1[i] − q2[i] for
 * every i.
 * @param[in] r the vector r.
 * @param[in] q1 the matrix Q1 (upper triangle).
 * @param[in] q2 the matrix Q2.
 * @param[in] q3 the matrix 2·Q1 − Q2.
 * @param[out] a the coefficients a0, a1, a2.
 * @since 2.1.0 (pw85 1.0 spelt it pw85__rT_adjQ_r_as_poly())
 */
PW85_API void pw85_legacy__rT_adjQ_r_as_poly(double const r[PW85_DIM],
                                             double const q1[PW85_SYM],
                                             double const q2[PW85_SYM],
                                             double const q3[PW85_SYM],
                                             double a[PW85_DIM]) PW85_NOEXCEPT;

/**
 * @brief Deprecated spelling of pw85_legacy__rT_adjQ_r_as_poly(), under
 *        which the seed documentation lists it; same contract.
 * @deprecated Call pw85_legacy__rT_adjQ_r_as_poly().
 * @param[in] r the vector r.
 * @param[in] q1 the matrix Q1 (upper triangle).
 * @param[in] q2 the matrix Q2.
 * @param[in] q3 the matrix 2·Q1 − Q2.
 * @param[out] a the coefficients a0, a1, a2.
 */
PW85_API PW85_LEGACY_DEPRECATED("use pw85_legacy__rT_adjQ_r_as_poly")
void pw85__rT_adjQ_r_as_poly(double const r[PW85_DIM],
                             double const q1[PW85_SYM],
                             double const q2[PW85_SYM],
                             double const q3[PW85_SYM],
                             double a[PW85_DIM]) PW85_NOEXCEPT;

/**
 * @brief Implementation #1 of f(λ) = λ(1−λ)·r12ᵀ·Q(λ)⁻¹·r12,
 *        Q(λ) = (1−λ)·Q1 + λ·Q2, and its derivatives, by a Cholesky
 *        factorisation of Q(λ).
 *
 * Plain double arithmetic, no rescaling (the range limits of pw85_f_neg()
 * apply).
 * @param[in] lambda λ, normally in [0, 1].
 * @param[in] r12 the centre-to-centre vector c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out NULL, or 3 doubles that receive out[0] = f(λ),
 *                 out[1] = f′(λ), out[2] = f″(λ); NaN in each entry when
 *                 the function returns NaN.
 * @return f(λ); NaN if r12, q1 or q2 is NULL, if an input is not finite,
 *         if q1 or q2 is not positive definite by the rule of pw85.h, or
 *         if Q(λ) is not positive definite.
 */
PW85_API double pw85_legacy_f1(double lambda, double const r12[PW85_DIM],
                               double const q1[PW85_SYM],
                               double const q2[PW85_SYM],
                               double out[3]) PW85_NOEXCEPT;

/**
 * @brief Implementation #2 of f(λ): the rational fraction
 *        λ(1−λ)·a(λ)/b(λ), a(λ) = r12ᵀ·adj[Q(λ)]·r12, b(λ) = det[Q(λ)].
 *
 * Less accurate than pw85_legacy_f1() (documentation, accuracy chapter):
 * the coefficients of a and b, computed from values at λ = 0, 1, −1 and ½,
 * cancel when the ellipsoids differ much in size or shape.
 * Arguments as pw85_legacy_f1().
 * @param[in] lambda λ, normally in [0, 1].
 * @param[in] r12 the centre-to-centre vector c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out NULL, or 1 double that receives f(λ) (NaN when the
 *                 function returns NaN).
 * @return f(λ); NaN if r12, q1 or q2 is NULL, if an input is not finite,
 *         if q1 or q2 is not positive definite by the rule of pw85.h,
 *         if Q(λ) is not positive definite, or if the computed b(λ) is 0
 *         (then 0/0 at λ = 1, where the rounded b(1) can vanish).
 */
PW85_API double pw85_legacy_f2(double lambda, double const r12[PW85_DIM],
                               double const q1[PW85_SYM],
                               double const q2[PW85_SYM],
                               double out[1]) PW85_NOEXCEPT;

/**
 * @brief The contact function by Newton–Raphson iterations on f′(λ) = 0
 *        (f′, f″ of pw85_legacy_f1()), from λ = ½. Not robust.
 *
 * Arguments and input contract as pw85_contact_function(). The iterates
 * are not safeguarded, and the steps overshoot where f varies sharply near
 * λ = 0 or 1: the method fails already for two spheres whose radii differ
 * by a factor 3.25 or more. It fails when Q(λ) is not positive definite at
 * an iterate, when f″(λ) = 0, when 50 steps do not converge, or when it
 * converges to a root of f′ outside [0, 1]; it then returns PW85_ENOCONV and
 * the best estimate met, a lower bound of μ².
 * @param[in] r12 the centre-to-centre vector c2 − c1 (r12 = 0 gives μ² = 0,
 *                λ = ½).
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out out[0] = μ², out[1] = λ in [0, 1].
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL (out untouched);
 *         PW85_EDOM if an input is NaN or infinite (out untouched);
 *         PW85_ENOTPOSDEF if q1 or q2 is not positive definite by the
 *         rule of pw85.h, the same as pw85_contact_function's (out
 *         untouched);
 *         PW85_ERANGE if μ² exceeds DBL_MAX (out[0] = +infinity, out[1] =
 *         λ), or if the diagonals of q1 and q2 together span more than
 *         pw85_contact_function() carries (about 1e607, as pw85.h
 *         states; out untouched);
 *         PW85_ENOCONV if Newton's method failed: out[0] = the largest f(λ)
 *         met at an iterate λ in [0, 1] (≤ μ²; the first iterate is ½),
 *         out[1] = that λ.
 *         (pw85 1.0 returned 0 always; these statuses since 2.1.0.)
 */
PW85_API int pw85_legacy_contact_function1(double const r12[PW85_DIM],
                                           double const q1[PW85_SYM],
                                           double const q2[PW85_SYM],
                                           double out[2]) PW85_NOEXCEPT;

/**
 * @brief The contact function by bisection on the numerator c(λ) of
 *        f′(λ) = c(λ)/b(λ)², a polynomial of degree 6, then μ² = f(λ) as a
 *        rational fraction (implementation #2).
 *
 * Arguments and input contract as pw85_contact_function(). Bisection always
 * terminates, but the coefficients of a, b and c, computed from values at
 * λ = 0, 1, −1, ½ (docs/implementation.rst, eq. (4.12)), lose accuracy to cancellation when
 * the ellipsoids differ much in size or shape: μ² may then have few correct
 * digits, or the rounded c may have no sign change inside (0, 1), in which
 * case bisection ends on λ = 0 or 1 and the function fails.
 * Prefer pw85_contact_function().
 * @param[in] r12 the centre-to-centre vector c2 − c1 (r12 = 0 gives μ² = 0,
 *                λ = ½).
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out out[0] = μ², out[1] = λ in [0, 1].
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL (out untouched);
 *         PW85_EDOM if an input is NaN or infinite (out untouched);
 *         PW85_ENOTPOSDEF if q1 or q2 is not positive definite by the
 *         rule of pw85.h, the same as pw85_contact_function's (out
 *         untouched);
 *         PW85_ERANGE if μ² exceeds DBL_MAX (out[0] = +infinity, out[1] =
 *         λ), or if the input's dynamic range is too wide for the
 *         polynomial coefficients, products of up to five entries of Q1,
 *         Q2 and two of r12 (out untouched);
 *         PW85_ENOCONV if bisection ended on λ = 0 or 1, or if a(λ), b(λ)
 *         or f(λ) came out non-positive or not finite: out[0] = 0 (the only
 *         lower bound of μ² known), out[1] = λ.
 *         (pw85 1.0 returned 0 always; these statuses since 2.1.0.)
 */
PW85_API int pw85_legacy_contact_function2(double const r12[PW85_DIM],
                                           double const q1[PW85_SYM],
                                           double const q2[PW85_SYM],
                                           double out[2]) PW85_NOEXCEPT;

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* PW85_LEGACY_H */
