/* SPDX-License-Identifier: BSD-3-Clause */
/**
 * @file pw85.h
 * @brief The C ABI of pw85: the contact function of Perram and Wertheim
 *        (J. Comp. Phys. 58(3), 409-416, 1985) for two ellipsoids.
 *
 * Storage conventions, used by every function below:
 * - a vector is a `double[3]` (PW85_DIM) of Cartesian coordinates;
 * - a symmetric matrix A is a `double[6]` (PW85_SYM) holding its upper
 *   triangle row by row:
 *   `a[0]=A00 a[1]=A01 a[2]=A02 a[3]=A11 a[4]=A12 a[5]=A22`;
 * - a lower-triangular matrix L (Cholesky factor) is a `double[6]` holding
 *   its lower triangle column by column:
 *   `l[0]=L00 l[1]=L10 l[2]=L20 l[3]=L11 l[4]=L21 l[5]=L22`.
 *
 * An ellipsoid of centre c is the set {m : (m-c)ᵀ Q⁻¹ (m-c) ≤ 1}, where Q
 * is symmetric positive definite; Q = Σ aᵢ² vᵢ vᵢᵀ for semi-axes aᵢ along
 * unit vectors vᵢ. Q has the dimension of a squared length.
 *
 * Positive definite, as stored: every function of pw85 and pw85_legacy
 * applies one rule. A form is accepted when its entries are finite and it
 * is positive definite exactly, as stored: Sylvester's criterion,
 * Q00 > 0, Q00·Q11 − Q01² > 0, det Q > 0, on the exact values of the six
 * doubles. The floating-point factorisation decides where its error bound
 * proves the answer (forms with cond(Q) up to about 1e14); beyond, the
 * minors are evaluated exactly, in integer arithmetic (a few hundred
 * nanoseconds more). So no form that is not positive definite is ever
 * accepted, and none that is is refused, however nearly singular, and
 * whatever its scale (since 2.3.0; earlier releases decided by the
 * factorisation alone, and accepted some indefinite forms). A form so
 * nearly singular that double cannot factorise it (cond(Q) ≳ 1/ε, far
 * beyond the documented domain) is accepted; the functions that must
 * factorise it answer PW85_ERANGE.
 *
 * Thread safety: every function is reentrant and thread-safe; none keeps
 * state between calls. None prints, aborts, exits, allocates from the heap
 * (the index of pw85_index.h does, and says so), or changes process-wide
 * state (in particular GSL's error handler is never
 * installed nor reached).
 *
 * Versions: what carries no `@since` is the C API of pw85 1.0, same names
 * and argument order; `@since` marks what a later release added. The
 * shared library versions its symbols: a function without `@since` is in
 * the version node PW85_2.0, one `@since X.Y.Z` in PW85_X.Y; each node
 * inherits the one before, a released node never changes, and a release
 * that adds functions adds a node (src/libpw85.map). A program records the
 * nodes it uses; run against an older libpw85.so.2 that lacks one, it does
 * not start, and the loader names the missing node.
 */
#ifndef PW85_H
#define PW85_H

#include <stddef.h>

#include "pw85_version.h"

/** Marks the exported functions; define it before including this header to
 *  override (for example as empty, to link a static copy).
 *  @since 2.1.0 */
#ifndef PW85_API
#if defined(_WIN32) && defined(PW85_BUILDING_DLL)
#define PW85_API __declspec(dllexport)
#elif defined(__GNUC__) && __GNUC__ >= 4
#define PW85_API __attribute__((visibility("default")))
#else
#define PW85_API
#endif
#endif

/** Exception specification of the functions below for C++ callers: none
 *  of them throws.
 *  @since 2.1.0 */
#if defined(__cplusplus) && __cplusplus >= 201103L
#define PW85_NOEXCEPT noexcept
#else
#define PW85_NOEXCEPT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** The dimension of the physical space. */
#define PW85_DIM 3
/** The number of independent entries of a symmetric PW85_DIM×PW85_DIM
 *  matrix. */
#define PW85_SYM 6
/** @name Parameters of the search, as built
 *  The values pw85_contact_function() was compiled with, for information:
 *  defining them otherwise in a program changes nothing. The steps named
 *  are those of "The algorithm" in the optimisation chapter of the docs.
 *  @{ */
/** Brent's method stops when its bracket on λ is narrower than this
 *  (step 5); the first verified bracket handed to it is
 *  0.98 × PW85_LAMBDA_ATOL wide, so that it already meets that test. */
#define PW85_LAMBDA_ATOL 1e-6
/** The maximum number of iterations of Brent's method (step 5). */
#define PW85_MAX_ITER 25
/** The maximum number of plain Newton steps on ω restarted from Brent's
 *  estimate when the first Newton run did not converge or converged
 *  outside Brent's bracket (step 6). */
#define PW85_NR_ITER 3
/** @} */

/** @name Status codes
 *  Returned by the functions that return an int (pw85 1.0 returned 0
 *  always). Values never change once released; new codes are appended.
 *  @{ */
#define PW85_SUCCESS 0     /**< success. @since 2.1.0 */
#define PW85_EFAULT 1      /**< a pointer argument is NULL. @since 2.1.0 */
#define PW85_EDOM 2        /**< an input is NaN or infinite.
                                @since 2.1.0 */
#define PW85_ENOTPOSDEF 3  /**< q1 or q2 is not positive definite.
                                @since 2.1.0 */
#define PW85_ERANGE 4      /**< μ², or the dynamic range of the input,
                                exceeds the range of a double.
                                @since 2.1.0 */
#define PW85_ENOMEM 5      /**< out of memory: the index could not
                                allocate, or the minimiser needs more
                                working memory than pw85 reserves (not
                                expected with any GSL). @since 2.1.0 */
#define PW85_ENOCONV 6     /**< the method did not converge (legacy contact
                                functions; out holds a lower bound of μ²).
                                @since 2.1.0 */
#define PW85_EINVAL 7      /**< a finite argument is outside its documented
                                domain (a semi-axis not > 0, a rotation not
                                orthonormal, ...). @since 2.2.0 */
#define PW85_ECANCELLED 8  /**< a function of the caller (a pair energy,
                                a progress callback) returned non-zero:
                                the call stopped. @since 2.4.0 */
/** @} */

/**
 * @brief Name a status code.
 * @param[in] status a value returned by a pw85 function.
 * @return a static, NUL-terminated English message (never NULL); an unknown
 *         code gets "unknown pw85 status".
 * @since 2.1.0
 */
PW85_API const char *pw85_strerror(int status) PW85_NOEXCEPT;

/**
 * @brief The version of the library actually loaded, "MAJOR.MINOR.PATCH".
 *
 * Compare with PW85_VERSION (the headers' version) when the library is loaded
 * with dlopen.
 * @return a static string (never NULL).
 * @since 2.1.0
 */
PW85_API const char *pw85_version(void) PW85_NOEXCEPT;

/**
 * @brief Cholesky factorisation A = L·Lᵀ of a symmetric positive definite
 *        3×3 matrix (internal, exposed for testing).
 *
 * Precondition, not checked: a and l are valid pointers. If A is not
 * positive definite by the rule above (a NaN or infinite entry included),
 * every entry of l is set to NaN; otherwise l holds the factor (should the
 * usual algorithm meet a pivot ≤ 0 on a form that the rule accepts, L is
 * formed from the L·D·Lᵀ factors of A scaled by powers of two per axis;
 * should those meet one too, A being singular to the precision of double,
 * NaN as well).
 * @param[in] a the matrix A (upper triangle, see the file description).
 * @param[out] l the lower-triangular factor L (see the file description).
 */
PW85_API void pw85__cholesky_decomp(double const a[PW85_SYM],
                                    double l[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief Solve L·Lᵀ·x = b by forward and back substitution (internal,
 *        exposed for testing).
 *
 * Preconditions, not checked: pointers are valid, L has a non-zero
 * diagonal. x may alias b.
 * @param[in] l the factor from pw85__cholesky_decomp().
 * @param[in] b the right-hand side.
 * @param[out] x the solution.
 */
PW85_API void pw85__cholesky_solve(double const l[PW85_SYM],
                                   double const b[PW85_DIM],
                                   double x[PW85_DIM]) PW85_NOEXCEPT;

/**
 * @brief The quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ.
 *
 * The signature of pw85 1.0, with no status: the preconditions are not
 * checked. Preconditions: a > 0 and c > 0 (a = 0 or c = 0 gives a
 * singular Q, and −a gives the Q of a), a² and c² within the normal range
 * of a double, and ‖n‖ = 1 (a non-unit n gives the formula's Q, which is
 * not that spheroid). pw85_spheroid_checked() checks them and returns a
 * status; every binding calls it.
 * @param[in] a the equatorial radius (a length).
 * @param[in] c the polar radius (a length).
 * @param[in] n the unit vector of the axis of revolution (not normalised
 *              here).
 * @param[out] q the matrix Q (a squared length). Not written if q is NULL;
 *               filled with NaN if n is NULL. Non-finite input gives
 *               non-finite entries.
 */
PW85_API void pw85_spheroid(double a, double c, double const n[PW85_DIM],
                            double q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief pw85_spheroid() with its preconditions checked.
 *
 * The same Q, bit for bit, when they hold.
 * @param[in] a the equatorial radius (a length, > 0).
 * @param[in] c the polar radius (a length, > 0).
 * @param[in] n the unit vector of the axis of revolution:
 *              |‖n‖² − 1| ≤ PW85_UNIT_TOL (not normalised here).
 * @param[out] q the matrix Q (a squared length).
 * @return PW85_SUCCESS; PW85_EFAULT if n or q is NULL; PW85_EDOM if a, c
 *         or an entry of n is NaN or infinite; PW85_EINVAL if a ≤ 0,
 *         c ≤ 0 or |‖n‖² − 1| > PW85_UNIT_TOL; PW85_ERANGE if a² or c²
 *         overflows or is below DBL_MIN. q is written on success only.
 * @since 2.3.0
 */
PW85_API int pw85_spheroid_checked(double a, double c,
                                   double const n[PW85_DIM],
                                   double q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief Minus the function f of the contact problem:
 *        −f(λ) = −λ(1−λ) r12ᵀ·Q(λ)⁻¹·r12, Q(λ) = (1−λ)·Q1 + λ·Q2.
 *
 * Shaped like GSL's gsl_function, as in pw85 1.0 (a double, then a
 * pointer to the parameters); GSL takes `void *params`, so pass it to GSL
 * through a wrapper function. Evaluated with compensated (double-double)
 * arithmetic, Q(λ) factorised in double-double where the bound
 * tr(Q)·tr(Q⁻¹) of cond(Q(λ)) exceeds 1e10. Measured: every value of the
 * reference dataset is correctly rounded; on the 4800 cases of
 * data/pw85_f_cases.h5 (300 per decade of cond(Q(λ)) from 1 to 1e16),
 * every value with cond(Q(λ)) < 1e14 is correctly rounded, and every value
 * up to 1e16 within one ulp (1 of 300 one ulp off in [1e14, 1e15), 3 of
 * 300 in [1e15, 1e16)). Beyond 1e16 the error grows with cond(Q(λ)) (not
 * measured). No rescaling: intermediate values must stay within the range
 * of a double (|r12|² and the entries of Q1, Q2 between about 1e-150 and
 * 1e150).
 * @param[in] lambda λ, normally in [0, 1].
 * @param[in] params PW85_DIM + 2·PW85_SYM = 15 doubles: r12[3], then
 *                   q1[6], then q2[6].
 * @return −f(λ), never positive for λ in [0, 1] (−0 where rounding, with
 *         cond(Q(λ)) beyond ~1e14, would make f negative); NaN if params
 *         is NULL, if lambda or an entry of params is not finite, or if
 *         q1 or q2 is not positive definite by the rule above, or if Q(λ)
 *         is not positive definite to the resolution of its
 *         factorisation.
 */
PW85_API double pw85_f_neg(double lambda,
                           double const params[PW85_DIM + 2 * PW85_SYM])
    PW85_NOEXCEPT;

/**
 * @brief f(λ), the residual g(λ) = μ2²(λ) − μ1²(λ) and g′(λ) (internal,
 *        exposed for testing; see the optimisation chapter of the docs).
 *
 * Preconditions, not checked: pointers valid, inputs finite, Q(λ) positive
 * definite.
 * @param[in] lambda λ in [0, 1].
 * @param[in] r12 the centre-to-centre vector c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out out[0] = f(λ), out[1] = g(λ), out[2] = g′(λ).
 */
PW85_API void pw85__residual(double lambda, double const r12[PW85_DIM],
                             double const q1[PW85_SYM],
                             double const q2[PW85_SYM], double out[3]) PW85_NOEXCEPT;

/**
 * @brief The contact function μ² of two ellipsoids and its maximiser λ.
 *
 * μ² = max over λ in [0, 1] of f(λ); μ is the common factor by which both
 * ellipsoids must be scaled, centres fixed, to be externally tangent:
 * μ² < 1 means they overlap, μ² > 1 that they are disjoint. μ² is
 * dimensionless and invariant under r12 → t·r12, Q → t²·Q; inputs are
 * rescaled internally by powers of two, so any finite input is accepted.
 * Documented domain: cond(Q1), cond(Q2) < 1e16 (aspect ratios to 1e8).
 * There μ² is evaluated with compensated arithmetic and is correctly
 * rounded on every pair of the tests: the reference dataset, the general
 * pairs (aspect ratios to 1e4), the finish pairs and the hard set
 * (data/pw85_hard_pairs.h5: 3103 pairs with cond to just below 1e16,
 * needles and discs side by side and end to end, λ* down to 2e-20 from 0
 * or 1, |r12| down to 1e-100 of the sizes, |μ² − 1| down to 1e-15). λ is
 * within 3e-13 of λ* on the first two, 1.2e-11 on the finish pairs, and
 * within 6e-10·min(λ*, 1 − λ*) on the hard set, well inside the window
 * where f(λ) is within an ulp of μ² (measured worst errors).
 * Swapping the ellipsoids, (r12, q1, q2) → (−r12, q2, q1), gives the same
 * μ² bit for bit and λ → 1 − λ (rounded), for any input. Beyond the
 * domain, the answer is still finite, ≥ (1 − 24ε)·|r12|²/(√tr Q1 +
 * √tr Q2)² > 0 (ε = DBL_EPSILON: the bound, computed in double with a
 * margin of 16ε, carries its own rounding),
 * with the statuses below, but may be inaccurate.
 *
 * The method, step by step in the optimisation chapter of the docs: check
 * the input; rescale it by powers of two; start from the maximiser for two
 * spheres; take safeguarded Newton steps on ω(λ) = λ·ρ − (1−λ),
 * ρ = √(P2/P1), Pi = sᵀ·Qi·s, s = Q(λ)⁻¹·r12, which has the sign of
 * g = μ2² − μ1²; certify the maximum with GSL's Brent minimiser on a narrow
 * bracket verified to enclose it; finish with Newton steps on ω in
 * compensated (double-double) arithmetic, safeguarded by a bracket, so
 * that μ² is correctly rounded; never return μ² below the bound above;
 * scale back. The search runs in a canonical orientation (Q1 and Q2
 * exchanged, and λ → 1 − λ, when the two-sphere maximiser is above ½;
 * ties broken by the stored entries), hence the swapping symmetry, and a
 * λ* near 1 keeps its digits in 1 − λ*.
 *
 * @param[in] r12 the centre-to-centre vector c2 − c1 (any finite vector;
 *                r12 = 0 gives μ² = 0, λ = ½).
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out out[0] = μ² (≥ 0; may round to a subnormal or to 0 when
 *                 μ² is below the range of a double), out[1] = λ in [0, 1].
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL (out untouched);
 *         PW85_EDOM if an input is NaN or infinite (out untouched);
 *         PW85_ENOTPOSDEF if q1 or q2 is not positive definite as stored,
 *         by the rule above (out untouched);
 *         PW85_ERANGE if μ² exceeds DBL_MAX: out[0] = +infinity, out[1] = λ;
 *         or if the diagonal entries of q1 and q2 together span more
 *         than the search can carry (their binary exponents, as frexp
 *         gives them, more than 2016 apart: a ratio of largest to
 *         smallest above about 1e607; out untouched; since 2.5.0, before
 *         which the limit was the range of a double, about 1e616, and μ²
 *         could be 1 to 3 ulps off above about 1e609);
 *         or if q1 or q2, positive definite, cannot be factorised in
 *         double once both are rescaled (singular to that precision,
 *         cond ≳ 1/ε: out untouched), or f cannot be evaluated in double
 *         along the search (forms singular far beyond that, cond up to
 *         1e600 with subnormal entries, found by fuzzing: out untouched);
 *         PW85_ENOMEM if GSL's minimiser would need more than the working
 *         memory reserved on the stack (out untouched; not expected).
 *         (pw85 1.0 returned 0 always; these statuses since 2.1.0.)
 */
PW85_API int pw85_contact_function(double const r12[PW85_DIM],
                                   double const q1[PW85_SYM],
                                   double const q2[PW85_SYM], double out[2]) PW85_NOEXCEPT;

/**
 * @brief Do two ellipsoids overlap? A certified decision, faster than
 *        computing μ².
 *
 * Decides the sign of μ² − 1 from bounds that hold at every λ,
 * f(λ) ≤ μ² ≤ max(μ1²(λ), μ2²(λ)), evaluated with certified rounding
 * margins at each of Newton's iterates towards λ* (the interval shrinks
 * onto μ²; near λ* with a compensated residual, deciding |μ² − 1| down to
 * a few ulps); only pairs within a few ulps of tangency (or beyond the
 * bounds' reach) fall back to the exact μ² of pw85_contact_function(),
 * so the answer never contradicts it.
 * @param[in] r12 the centre-to-centre vector c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] result −1 if the ellipsoids overlap (μ² < 1), +1 if they are
 *             disjoint (μ² > 1), 0 if they are tangent to the resolution of
 *             double arithmetic: |μ² − 1| ≤ 4·DBL_EPSILON (4 ulps of 1),
 *             μ² the exact value (where the correctly rounded μ² is
 *             1 ± 4·DBL_EPSILON itself, the exact one may lie beyond:
 *             decided in double-double, 0 within 2⁻⁹⁶ relative beyond
 *             the edge; since 2.5.0).
 *             Coincident centres overlap. Inside the domain of
 *             pw85_contact_function() (cond(Q1), cond(Q2) < 1e16), the
 *             answer agrees with the correctly rounded μ² on every pair
 *             of the tests outside that 4-ulp band (reference data,
 *             general, finish and hard pairs, near tangency with cond up
 *             to 1e16 included). Swapping the ellipsoids gives the same
 *             answer. Beyond the domain: the statuses below; the answer
 *             is not certified.
 * @return the statuses of pw85_contact_function(), with the same meaning;
 *         *result is written on PW85_SUCCESS only (also when μ² would
 *         overflow: such ellipsoids are disjoint, *result = +1). One
 *         exception, far beyond the domain: where pw85_contact_function()
 *         answers PW85_ERANGE because f cannot be evaluated along its
 *         search (forms singular to far below double precision), this
 *         function answers PW85_SUCCESS, *result = +1, when the bound
 *         μ² ≥ |r12|²/(√tr Q1 + √tr Q2)², which holds at any conditioning,
 *         alone proves the ellipsoids disjoint (it is tried first).
 * @since 2.1.0
 */
PW85_API int pw85_overlap(double const r12[PW85_DIM],
                          double const q1[PW85_SYM],
                          double const q2[PW85_SYM], int *result) PW85_NOEXCEPT;

/** @name Ellipsoids from semi-axes and orientation
 *  @{ */
/** The tolerance on the orthonormality of a rotation matrix,
 *  max over (i, j) of |(RᵀR − I)ᵢⱼ|, and on the norm of a quaternion,
 *  |‖q‖² − 1|, below which the constructors accept them (float data
 *  converted to double passes).
 *  @since 2.2.0 */
#define PW85_UNIT_TOL 1e-6
/** @} */

/**
 * @brief The quadratic form of an ellipsoid from its semi-axes and a
 *        rotation matrix: Q = R·diag(a0², a1², a2²)·Rᵀ (theory, eq. (2)).
 *
 * Column j of R is the unit direction of the semi-axis a[j]. R is stored
 * row by row, `rot[3·i + j] = R_ij`: in NumPy, `R = rot.reshape(3, 3)` and
 * `R[:, j]` is the direction of `a[j]`; a Fortran array `R(3, 3)` holds Rᵀ
 * in that memory order (its rows are then the directions). A reflection
 * (det R = −1) describes the same ellipsoid and is accepted.
 *
 * Accuracy: R is used as given (not re-orthonormalised). Every entry is
 * computed in double-double arithmetic and rounded once: with u = 2⁻⁵³,
 * |q[k] − Q_k| ≤ u·|Q_k| + 2⁻¹⁰⁰·Σₘ |R_im·R_jm|·aₘ², where Q_k is the
 * exact value of R·diag(a²)·Rᵀ for the doubles given (entry (i, j)):
 * correctly rounded but for a cancellation below 2⁻⁴⁷ of the largest
 * term, at any aspect ratio. Q is exactly symmetric by construction.
 * @param[in] a the three semi-axes (lengths, each > 0).
 * @param[in] rot the rotation matrix R (9 doubles, row by row).
 * @param[out] q the quadratic form Q (a squared length).
 * @return PW85_SUCCESS;
 *         PW85_EFAULT if a pointer is NULL;
 *         PW85_EDOM if an entry of a or rot is NaN or infinite;
 *         PW85_EINVAL if a semi-axis is not > 0, or if
 *         max |(RᵀR − I)ᵢⱼ| > PW85_UNIT_TOL;
 *         PW85_ERANGE if an aₘ² overflows or underflows (q untouched).
 *         q is written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_ellipsoid_rotation(double const a[PW85_DIM],
                                     double const rot[PW85_DIM * PW85_DIM],
                                     double q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief The quadratic form of an ellipsoid from its semi-axes and a unit
 *        quaternion: Q = R(p)·diag(a0², a1², a2²)·R(p)ᵀ.
 *
 * p = (w, x, y, z), scalar first (OVITO and SciPy's Rotation.as_quat()
 * write (x, y, z, w): reorder them), = cos(θ/2) + sin(θ/2)·(u_x·i +
 * u_y·j + u_z·k) is the
 * rotation by θ about the unit axis u that maps the coordinate axes to the
 * principal directions (a[j] lies along R(p)·e_j): the convention of
 * HOOMD-blue's and LAMMPS's ellipsoids. p and −p give the same Q. p is
 * normalised here, so R(p) is a rotation to rounding.
 *
 * Accuracy: R(p/‖p‖) and Q are computed in double-double arithmetic and
 * rounded once: |q[k] − Q_k| ≤ u·|Q_k| + 2⁻¹⁰⁰·maxₘ aₘ² with Q_k exact for
 * p/‖p‖ and the given a (u = 2⁻⁵³).
 * @param[in] a the three semi-axes (lengths, each > 0).
 * @param[in] p the quaternion (w, x, y, z).
 * @param[out] q the quadratic form Q (a squared length).
 * @return PW85_SUCCESS; PW85_EFAULT, PW85_EDOM, PW85_ERANGE as
 *         pw85_ellipsoid_rotation(); PW85_EINVAL if a semi-axis is not > 0
 *         or if |‖p‖² − 1| > PW85_UNIT_TOL. q is written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_ellipsoid_quaternion(double const a[PW85_DIM],
                                       double const p[4],
                                       double q[PW85_SYM]) PW85_NOEXCEPT;

/**
 * @brief The semi-axes and principal directions of an ellipsoid:
 *        Q = R·diag(a0², a1², a2²)·Rᵀ, the inverse of
 *        pw85_ellipsoid_rotation().
 *
 * Eigenvectors from GSL's symmetric eigensolver (gsl_eigen_symmv, on Q
 * scaled by a power of two); each aⱼ² is then the Rayleigh quotient of its
 * direction, computed in double-double arithmetic, which keeps the small
 * semi-axes of needles and discs accurate: relative error of aⱼ of order
 * u·(1 + u·(a0/aⱼ)²·‖Q‖/gapⱼ), gapⱼ the distance from aⱼ² to the other
 * eigenvalues (measured within 1.94 times that on 310 forms with aspect
 * ratios to 1e8: a few u for distinct semi-axes; test-geometry-refs).
 * Semi-axes sorted in decreasing order, a[0] ≥ a[1] ≥ a[2] > 0; R is a
 * rotation (det R = +1) stored as in pw85_ellipsoid_rotation(), each of its
 * first two columns with its entry of largest magnitude positive.
 * Directions of equal semi-axes (spheroids, spheres) are any orthonormal
 * basis of their eigenspace.
 * @param[in] q the quadratic form Q.
 * @param[out] a the semi-axes, in decreasing order.
 * @param[out] rot the rotation R (9 doubles, row by row; column j is the
 *             direction of a[j]).
 * @return PW85_SUCCESS; PW85_EFAULT if a pointer is NULL; PW85_EDOM if an
 *         entry of q is NaN or infinite; PW85_ENOTPOSDEF if Q is not
 *         positive definite by the rule above; PW85_ERANGE if Q, positive
 *         definite, is singular to double precision (its L·D·Lᵀ
 *         factorisation in double meets a pivot ≤ 0: cond(Q) about 1/ε or
 *         more), if cond(Q) exceeds about 1e270 (tr(Q)·tr(Q⁻¹) > 2^900:
 *         GSL's iterations could meet subnormal numbers, where they may
 *         not converge), or if a Rayleigh quotient is not > 0 in
 *         double-double. a and rot are written on success only.
 * @since 2.2.0
 */
PW85_API int pw85_principal_axes(double const q[PW85_SYM],
                                 double a[PW85_DIM],
                                 double rot[PW85_DIM * PW85_DIM]) PW85_NOEXCEPT;

/**
 * @brief The semi-axes and orientation of an ellipsoid as a unit
 *        quaternion: the inverse of pw85_ellipsoid_quaternion().
 *
 * pw85_principal_axes(), then the quaternion p of its rotation R
 * (Shepperd's method: the largest of 4w², 4x², 4y², 4z² from the diagonal
 * of R, the others from its off-diagonal entries), normalised:
 * pw85_ellipsoid_quaternion(a, p, q') gives Q again, to the accuracy of
 * the semi-axes and directions (pw85_principal_axes()). p = (w, x, y, z),
 * scalar first, the convention of pw85_ellipsoid_quaternion(); OVITO and
 * SciPy (Rotation.as_quat()) write (x, y, z, w). Of the pair ±p, the one
 * with w > 0 (w = 0: the first non-zero component positive). Equal
 * semi-axes: any orientation of their eigenspace, as pw85_principal_axes().
 * @param[in] q the quadratic form Q.
 * @param[out] a the semi-axes, in decreasing order.
 * @param[out] p the unit quaternion (w, x, y, z): a[j] lies along
 *             R(p)·e_j.
 * @return the statuses of pw85_principal_axes(); a and p are written on
 *         success only.
 * @since 2.3.0
 */
PW85_API int pw85_principal_axes_quaternion(double const q[PW85_SYM],
                                            double a[PW85_DIM],
                                            double p[4]) PW85_NOEXCEPT;

/** @name Layout of the output of pw85_contact_geometry()
 *  Offsets into `double out[PW85_GEOM_SIZE]`. Fixed: a later release adds
 *  outputs through new functions, never by changing these.
 *  @{ */
#define PW85_GEOM_MU2 0     /**< μ², as pw85_contact_function(). @since 2.2.0 */
#define PW85_GEOM_LAMBDA 1  /**< λ, the maximiser. @since 2.2.0 */
#define PW85_GEOM_POINT 2   /**< 3 doubles: x − c1, the contact point of
                                 the scaled ellipsoids relative to c1.
                                 @since 2.2.0 */
#define PW85_GEOM_NORMAL 5  /**< 3 doubles: the unit normal at x, from
                                 ellipsoid 1 towards ellipsoid 2.
                                 @since 2.2.0 */
#define PW85_GEOM_SIZE 8    /**< the number of doubles. @since 2.2.0 */
/** @} */

/** @name Layout of the output of pw85_contact_derivatives()
 *  Offsets into `double d[PW85_DERIV_SIZE]`; fixed, as above.
 *  @{ */
#define PW85_DERIV_R12 0    /**< 3 doubles: ∂μ²/∂r12 (1/length).
                                 @since 2.2.0 */
#define PW85_DERIV_ROT1 3   /**< 3 doubles: ∂μ²/∂ω1, ω1 a rotation vector
                                 (radians) turning ellipsoid 1 about c1.
                                 @since 2.2.0 */
#define PW85_DERIV_ROT2 6   /**< 3 doubles: ∂μ²/∂ω2, the same for
                                 ellipsoid 2 about c2. @since 2.2.0 */
#define PW85_DERIV_Q1 9     /**< 6 doubles: ∂μ²/∂q1[k], k = 0..5, the
                                 partial derivatives with respect to the
                                 six stored entries (1/squared length).
                                 @since 2.2.0 */
#define PW85_DERIV_Q2 15    /**< 6 doubles: ∂μ²/∂q2[k]. @since 2.2.0 */
#define PW85_DERIV_SIZE 21  /**< the number of doubles. @since 2.2.0 */
/** @} */

/**
 * @brief The contact function, the contact point and the common normal
 *        of two ellipsoids.
 *
 * One search, that of pw85_contact_function() (same μ², bit for bit),
 * then λ polished by Newton steps on ω in compensated arithmetic until a
 * step is below the rounding of λ, and s = Q(λ)⁻¹·r12 solved with
 * compensated residuals. Then (theory, eqs. (9a), (8)):
 * x − c1 = (1 − λ)·Q1·s, the point where the ellipsoids scaled by μ touch;
 * n = s/‖s‖, the outward normal of scaled ellipsoid 1 at x (and the inward
 * normal of scaled ellipsoid 2), so that n·r12 > 0.
 *
 * Accuracy, measured against references at 100 digits on the 400 pairs of
 * data/pw85_geometry_pairs.h5 (aspect ratios to 1e6, near tangency, λ
 * within 1e-8 of 0 and 1): relative to the norm of each vector, x − c1 and
 * n within 1.5·u·cond(Q(λ)) (u = 2⁻⁵³, cond the 2-norm condition number
 * of Q(λ) at the maximiser); λ within 1.5·u·cond(Q(λ))·min(λ, 1 − λ) + u
 * (the absolute u: λ may be computed as 1 − λ, near 1, where the sphere
 * model (optimisation.rst, eq. (5.9)) misjudges its side of ½; 1e-13
 * relative for a λ of 1e-3 on a fuzzing input). These are measurements,
 * not proven bounds: on 620 pairs drawn otherwise (an adversarial review,
 * 2.5.0), x − c1 reached 1.9·u·cond (near-spheres with off-diagonal
 * entries of 1e-15). (tests: test-geometry-refs; the tests hold them to
 * 8·u·cond.) λ may differ from pw85_contact_function()'s in the last
 * digits, being more accurate.
 * Swapping the ellipsoids, (r12, q1, q2) → (−r12, q2, q1), gives the same
 * μ² (bit for bit), λ → 1 − λ (rounded), n → −n (exactly; a zero may
 * change sign) and x − c2 = (x − c1) − r12 (to rounding).
 *
 * @param[in] r12 c2 − c1; r12 = 0 gives μ² = 0, λ = ½, x − c1 = 0 and
 *                n = 0 (no direction).
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] out PW85_GEOM_SIZE doubles, laid out as PW85_GEOM_*.
 * @return the statuses of pw85_contact_function(), with the same
 *         meaning; out untouched on error, except PW85_ERANGE when a
 *         result overflows (μ² = +∞, or x − c1 beyond DBL_MAX): every
 *         output is then written, some infinite. Also PW85_ERANGE, out
 *         untouched, where pw85_contact_function() succeeds but Q(λ)
 *         cannot be factorised at the maximiser, in double-double nor in
 *         double: only far beyond the documented domain, for entries
 *         spanning most of the range of a double.
 * @since 2.2.0
 */
PW85_API int pw85_contact_geometry(double const r12[PW85_DIM],
                                   double const q1[PW85_SYM],
                                   double const q2[PW85_SYM],
                                   double out[PW85_GEOM_SIZE]) PW85_NOEXCEPT;

/**
 * @brief pw85_contact_geometry() and the first derivatives of μ²: for
 *        forces, torques and changes of shape.
 *
 * By the envelope theorem (f is stationary in λ at the maximiser), with
 * s = Q(λ)⁻¹·r12 and Q(λ) = (1 − λ)·Q1 + λ·Q2:
 * - ∂μ²/∂r12 = 2λ(1 − λ)·s (the derivative with respect to c2; that with
 *   respect to c1 is its opposite);
 * - ∂μ²/∂Q1 = −λ(1 − λ)²·s·sᵀ and ∂μ²/∂Q2 = −λ²(1 − λ)·s·sᵀ as matrices;
 *   stored as the derivatives with respect to the stored entries, whose
 *   off-diagonal entries count twice: ∂μ²/∂q1 = −λ(1 − λ)²·(s0², 2·s0·s1,
 *   2·s0·s2, s1², 2·s1·s2, s2²), so that δμ² = Σₖ (∂μ²/∂q1[k])·δq1[k];
 * - turning ellipsoid i about its centre by a small rotation vector ω,
 *   Qᵢ → R(ω)·Qᵢ·R(ω)ᵀ: ∂μ²/∂ω1 = 2λ(1 − λ)²·s × (Q1·s) and
 *   ∂μ²/∂ω2 = 2λ²(1 − λ)·s × (Q2·s). With g = ∂μ²/∂r12, these are
 *   g × (x − c1) and (x − c2) × g: the lever arms of the contact point.
 * For a pair energy U(μ²): the force on ellipsoid 2 is −U′·g, that on
 * ellipsoid 1 is +U′·g, the torque on ellipsoid i is −U′·∂μ²/∂ωᵢ.
 * Accuracy, measured as for pw85_contact_geometry(): ∂μ²/∂r12 within
 * 1.2·u·cond(Q(λ)), the derivatives with respect to q1 and q2 within
 * 3.8·u·cond(Q(λ)), relative in the norm of each block; the torques within
 * 1.1·u·cond(Q(λ)) of their scale |∂μ²/∂r12|·|x − cᵢ| (a torque may
 * vanish, its own norm is then no scale). Measurements, not proven
 * bounds: on the pairs of the review above, ∂μ²/∂r12 reached
 * 1.4·u·cond; the tests hold every block to 8·u·cond.
 * Swapping the ellipsoids exchanges ∂μ²/∂ω1 and ∂μ²/∂ω2, ∂μ²/∂q1 and
 * ∂μ²/∂q2, and negates ∂μ²/∂r12, exactly (a zero may change sign). r12 = 0: μ² is minimal
 * there, every derivative is 0.
 *
 * @param[in] r12 c2 − c1.
 * @param[in] q1 the quadratic form of the first ellipsoid.
 * @param[in] q2 the quadratic form of the second ellipsoid.
 * @param[out] geometry PW85_GEOM_SIZE doubles, as pw85_contact_geometry().
 * @param[out] d PW85_DERIV_SIZE doubles, laid out as PW85_DERIV_*.
 * @return as pw85_contact_geometry(); with PW85_ERANGE, both arrays are
 *         written (a derivative may be infinite, when the input's scale
 *         is extreme).
 * @since 2.2.0
 */
PW85_API int pw85_contact_derivatives(double const r12[PW85_DIM],
                                      double const q1[PW85_SYM],
                                      double const q2[PW85_SYM],
                                      double geometry[PW85_GEOM_SIZE],
                                      double d[PW85_DERIV_SIZE]) PW85_NOEXCEPT;

/** @name Batches
 *  One call for n pairs, or n ellipsoids for the constructors and
 *  pw85_principal_axes() (@since 2.2.0): the one path for callers that pay
 *  per call (Python, other interpreters), and the way to use threads. What
 *  follows says "pair" for an item of any batch; the constructors' batches
 *  give their own layouts.
 *
 *  Layouts. Pair i reads `r12 + i·r12_stride`, `q1 + i·q1_stride` and
 *  `q2 + i·q2_stride` (strides counted in doubles): PW85_DIM and PW85_SYM
 *  for contiguous n×3 and n×6 arrays, larger for records that hold more;
 *  0 uses the same vector or form for every pair (one ellipsoid against
 *  many, without copies). A stride from 1 to the record's size − 1 is an
 *  error (PW85_EINVAL). Outputs are contiguous: pair i writes `out[2·i]`
 *  and `out[2·i + 1]`, `result[i]`, `out + i·PW85_GEOM_SIZE`,
 *  `d + i·PW85_DERIV_SIZE`. Outputs overlap neither the inputs nor each
 *  other.
 *
 *  Results. Pair i is computed alone, exactly as the single-pair function
 *  computes it: the same outputs bit for bit and the same status, and a
 *  failing pair's outputs are left as that function leaves them
 *  (untouched, or written for PW85_ERANGE as it documents). Every pair is
 *  computed, whether others fail or not. `status` is NULL, or n ints:
 *  `status[i]` receives pair i's status; every entry is written, also
 *  when the call itself fails (each then holds the call's status).
 *
 *  Return value: PW85_SUCCESS when every pair succeeds, else the status
 *  of the first failing pair (lowest index). Errors of the call itself,
 *  before any pair is computed (no output written, `status` filled with
 *  the code): PW85_EFAULT if n > 0 and an input or output pointer is
 *  NULL; PW85_EINVAL if a stride is between 1 and its record's size − 1,
 *  or threads < 0. n = 0: PW85_SUCCESS, nothing read nor written,
 *  whatever the other arguments (any pointer may be NULL, threads or a
 *  stride out of range).
 *
 *  Threads. `threads` = 1: the calling thread only; 0: OpenMP's default
 *  count (omp_get_max_threads(): OMP_NUM_THREADS if set, else one per
 *  processor); k > 1: up to k. A batch of n pairs uses at most n/256
 *  threads (rounded down), and never more than 1024 (as every threaded
 *  call of libpw85): no thread is started for n < 512, nor for
 *  threads = 1. pw85_batch_threads() gives the count a call would use.
 *  Pairs are handed to threads, as they become free, in chunks of
 *  consecutive indices: about 32 per thread, of at least 256 pairs. The results do not depend on the count, bit for
 *  bit. Built without OpenMP (meson option `openmp`), every call runs in
 *  the calling thread, whatever the count. pw85 allocates nothing; the
 *  OpenMP runtime keeps its pool of threads from the first threaded call
 *  on. Reentrant: concurrent calls from several threads each use their
 *  own threads.
 *  @{ */

/**
 * @brief The number of threads a batch of n pairs runs on (see Batches).
 *
 * @param[in] threads the count requested: 0 for OpenMP's default, k ≥ 1.
 * @param[in] n the number of pairs.
 * @return the count, ≥ 1: min(k, n/256, 1024) and at least 1 (k =
 *         OpenMP's default for threads = 0); 1 for n ≥ 2⁵⁶ (a batch that large
 *         runs in the calling thread) and when libpw85 was built without
 *         OpenMP; 0 if threads < 0 (the batch calls reject it).
 * @since 2.2.0
 */
PW85_API int pw85_batch_threads(int threads, size_t n) PW85_NOEXCEPT;

/**
 * @brief pw85_contact_function() for n pairs.
 *
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the centre-to-centre vectors c2 − c1.
 * @param[in] r12_stride doubles from one vector to the next: PW85_DIM
 *            when contiguous, 0 for the same vector for every pair.
 * @param[in] q1 the quadratic forms of the first ellipsoids.
 * @param[in] q1_stride PW85_SYM when contiguous, 0 for one form.
 * @param[in] q2 the quadratic forms of the second ellipsoids.
 * @param[in] q2_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] out 2·n doubles: `out[2·i]` = μ², `out[2·i + 1]` = λ of
 *             pair i.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing pair (those of
 *         pw85_contact_function()); PW85_EFAULT or PW85_EINVAL for the
 *         call itself (see Batches).
 * @since 2.2.0
 */
PW85_API int pw85_contact_function_batch(size_t n, double const *r12,
                                         size_t r12_stride, double const *q1,
                                         size_t q1_stride, double const *q2,
                                         size_t q2_stride, double *out,
                                         int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_overlap() for n pairs.
 *
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipsoids.
 * @param[in] q1_stride PW85_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipsoids.
 * @param[in] q2_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] result n ints: −1 (overlap), +1 (disjoint) or 0 (tangent)
 *             for each pair, as pw85_overlap().
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing pair (those of
 *         pw85_overlap()); PW85_EFAULT or PW85_EINVAL for the call itself.
 * @since 2.2.0
 */
PW85_API int pw85_overlap_batch(size_t n, double const *r12,
                                size_t r12_stride, double const *q1,
                                size_t q1_stride, double const *q2,
                                size_t q2_stride, int *result, int *status,
                                int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_contact_geometry() for n pairs.
 *
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipsoids.
 * @param[in] q1_stride PW85_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipsoids.
 * @param[in] q2_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] out n·PW85_GEOM_SIZE doubles: pair i at
 *             `out + i·PW85_GEOM_SIZE`, laid out as PW85_GEOM_*.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing pair (those of
 *         pw85_contact_geometry()); PW85_EFAULT or PW85_EINVAL for the
 *         call itself.
 * @since 2.2.0
 */
PW85_API int pw85_contact_geometry_batch(size_t n, double const *r12,
                                         size_t r12_stride, double const *q1,
                                         size_t q1_stride, double const *q2,
                                         size_t q2_stride, double *out,
                                         int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_contact_derivatives() for n pairs.
 *
 * @param[in] n the number of pairs (0 is valid).
 * @param[in] r12 the vectors c2 − c1.
 * @param[in] r12_stride PW85_DIM when contiguous, 0 for one vector.
 * @param[in] q1 the forms of the first ellipsoids.
 * @param[in] q1_stride PW85_SYM when contiguous, 0 for one form.
 * @param[in] q2 the forms of the second ellipsoids.
 * @param[in] q2_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] geometry n·PW85_GEOM_SIZE doubles, as
 *             pw85_contact_geometry_batch().
 * @param[out] d n·PW85_DERIV_SIZE doubles: pair i at
 *             `d + i·PW85_DERIV_SIZE`, laid out as PW85_DERIV_*.
 * @param[out] status NULL, or n ints: the status of each pair.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing pair (those of
 *         pw85_contact_derivatives()); PW85_EFAULT or PW85_EINVAL for the
 *         call itself.
 * @since 2.2.0
 */
PW85_API int pw85_contact_derivatives_batch(
    size_t n, double const *r12, size_t r12_stride, double const *q1,
    size_t q1_stride, double const *q2, size_t q2_stride, double *geometry,
    double *d, int *status, int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_spheroid() for n spheroids.
 *
 * Item i reads `a[i·a_stride]`, `c[i·c_stride]` and the unit vector
 * `axis + i·axis_stride`, and writes `q + i·PW85_SYM` (strides 0 for one
 * value or vector for every item; 1 and PW85_DIM when contiguous). Unlike
 * pw85_spheroid(), which has no status, each item is checked: PW85_EDOM
 * if a, c or an entry of the axis is NaN or infinite (q untouched),
 * PW85_ERANGE if an entry of Q overflows (q written, as pw85_spheroid()
 * writes it). The other items' forms are those of pw85_spheroid(), bit
 * for bit. Everything else as in Batches.
 *
 * @param[in] n the number of spheroids (0 is valid).
 * @param[in] a the equatorial radii (lengths).
 * @param[in] a_stride 1 when contiguous, 0 for one radius.
 * @param[in] c the polar radii (lengths).
 * @param[in] c_stride 1 when contiguous, 0 for one radius.
 * @param[in] axis the directions of the axes of revolution (unit vectors).
 * @param[in] axis_stride PW85_DIM when contiguous, 0 for one direction.
 * @param[out] q n·PW85_SYM doubles: item i at `q + i·PW85_SYM`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing item;
 *         PW85_EFAULT or PW85_EINVAL for the call itself.
 * @since 2.2.0
 */
PW85_API int pw85_spheroid_batch(size_t n, double const *a, size_t a_stride,
                                 double const *c, size_t c_stride,
                                 double const *axis, size_t axis_stride,
                                 double *q, int *status,
                                 int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_ellipsoid_rotation() for n ellipsoids.
 *
 * Item i reads the semi-axes `a + i·a_stride` and the rotation
 * `rot + i·rot_stride` (9 doubles, row by row), and writes
 * `q + i·PW85_SYM`; strides 0 for one record for every item.
 *
 * @param[in] n the number of ellipsoids (0 is valid).
 * @param[in] a the semi-axes (lengths).
 * @param[in] a_stride PW85_DIM when contiguous, 0 for one triple.
 * @param[in] rot the rotations.
 * @param[in] rot_stride 9 when contiguous, 0 for one rotation.
 * @param[out] q n·PW85_SYM doubles: item i at `q + i·PW85_SYM`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing item (those of
 *         pw85_ellipsoid_rotation()); PW85_EFAULT or PW85_EINVAL for the
 *         call itself.
 * @since 2.2.0
 */
PW85_API int pw85_ellipsoid_rotation_batch(size_t n, double const *a,
                                           size_t a_stride, double const *rot,
                                           size_t rot_stride, double *q,
                                           int *status,
                                           int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_ellipsoid_quaternion() for n ellipsoids.
 *
 * Item i reads the semi-axes `a + i·a_stride` and the quaternion
 * `p + i·p_stride` (w, x, y, z), scalar first, and writes `q + i·PW85_SYM`; strides 0
 * for one record for every item.
 *
 * @param[in] n the number of ellipsoids (0 is valid).
 * @param[in] a the semi-axes (lengths).
 * @param[in] a_stride PW85_DIM when contiguous, 0 for one triple.
 * @param[in] p the quaternions.
 * @param[in] p_stride 4 when contiguous, 0 for one quaternion.
 * @param[out] q n·PW85_SYM doubles: item i at `q + i·PW85_SYM`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing item (those of
 *         pw85_ellipsoid_quaternion()); PW85_EFAULT or PW85_EINVAL for
 *         the call itself.
 * @since 2.2.0
 */
PW85_API int pw85_ellipsoid_quaternion_batch(size_t n, double const *a,
                                             size_t a_stride, double const *p,
                                             size_t p_stride, double *q,
                                             int *status,
                                             int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_principal_axes() for n forms.
 *
 * Item i reads `q + i·q_stride` and writes `a + i·PW85_DIM` and
 * `rot + 9·i`.
 *
 * @param[in] n the number of forms (0 is valid).
 * @param[in] q the quadratic forms.
 * @param[in] q_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] a n·PW85_DIM doubles: the semi-axes, decreasing, of item i
 *             at `a + i·PW85_DIM`.
 * @param[out] rot 9·n doubles: the rotation of item i at `rot + 9·i`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing item (those of
 *         pw85_principal_axes()); PW85_EFAULT or PW85_EINVAL for the call
 *         itself.
 * @since 2.2.0
 */
PW85_API int pw85_principal_axes_batch(size_t n, double const *q,
                                       size_t q_stride, double *a,
                                       double *rot, int *status,
                                       int threads) PW85_NOEXCEPT;

/**
 * @brief pw85_principal_axes_quaternion() for n forms.
 *
 * Item i reads `q + i·q_stride` and writes `a + i·PW85_DIM` and
 * `p + 4·i`.
 *
 * @param[in] n the number of forms (0 is valid).
 * @param[in] q the quadratic forms.
 * @param[in] q_stride PW85_SYM when contiguous, 0 for one form.
 * @param[out] a n·PW85_DIM doubles: the semi-axes, decreasing.
 * @param[out] p 4·n doubles: the quaternion (w, x, y, z) of item i at
 *             `p + 4·i`.
 * @param[out] status NULL, or n ints: the status of each item.
 * @param[in] threads 1, 0 (OpenMP's default) or up to k (see Batches).
 * @return PW85_SUCCESS, or the status of the first failing item;
 *         PW85_EFAULT or PW85_EINVAL for the call itself.
 * @since 2.3.0
 */
PW85_API int pw85_principal_axes_quaternion_batch(size_t n, double const *q,
                                                  size_t q_stride, double *a,
                                                  double *p, int *status,
                                                  int threads) PW85_NOEXCEPT;
/** @} */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* PW85_H */
