// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85.hpp
 * @brief The C++ API of pw85 (that of pw85 2.0): inline wrappers over the C
 *        ABI of pw85.h, so that C++ code links the same -lpw85 and no C++
 *        type crosses the library boundary.
 *
 * Vectors are `double[3]` and symmetric matrices `double[6]` (upper
 * triangle, row by row), exactly as in pw85.h, whose documentation of each
 * function applies here. Functions whose name starts with an underscore are
 * internal, exposed for testing. Every function is thread-safe and none
 * throws.
 *
 * C++ standard: C++11 for everything but pw85::metadata, which needs C++17
 * (std::string_view, as in pw85 2.0) and is left out below C++17.
 *
 * Ellipses (pw85_2d.h): the same functions in namespace pw85::d2, over
 * `double[2]` vectors and `double[3]` forms (Q00, Q01, Q11).
 *
 * The spatial index of ellipsoids, pw85::Index, is defined in
 * pw85_index.hpp, which this header includes at its end.
 */
#ifndef PW85_HPP
#define PW85_HPP

#include <cstddef>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

#include "pw85.h"
#include "pw85_2d.h"

namespace pw85 {

/** The dimension of the physical space (PW85_DIM). */
constexpr std::size_t dim = PW85_DIM;
/** The number of entries of a symmetric matrix (PW85_SYM). */
constexpr std::size_t sym = PW85_SYM;
/** Brent's method stops when its bracket on λ is narrower than this, as
 *  built (PW85_LAMBDA_ATOL). */
constexpr double lambda_atol = PW85_LAMBDA_ATOL;
/** The maximum number of iterations of Brent's method, as built
 *  (PW85_MAX_ITER). */
constexpr std::size_t max_iter = PW85_MAX_ITER;
/** The maximum number of plain Newton steps restarted from Brent's
 *  estimate, as built (PW85_NR_ITER). */
constexpr std::size_t nr_iter = PW85_NR_ITER;

/** The version of the library actually loaded (pw85_version()).
 *  @since 2.1.0 */
inline char const *library_version() noexcept { return pw85_version(); }

/** The message of a status code (pw85_strerror()).
 *  @since 2.1.0 */
inline char const *strerror(int status) noexcept {
  return pw85_strerror(status);
}

/** A = L·Lᵀ (pw85__cholesky_decomp()). */
inline void _cholesky_decomp(double const a[sym], double l[sym]) noexcept {
  pw85__cholesky_decomp(a, l);
}

/** Solves L·Lᵀ·x = b (pw85__cholesky_solve()). */
inline void _cholesky_solve(double const l[sym], double const b[dim],
                            double x[dim]) noexcept {
  pw85__cholesky_solve(l, b, x);
}

/** The quadratic form of a spheroid, its preconditions checked
 *  (pw85_spheroid_checked(): a > 0, c > 0, n a unit vector to
 *  PW85_UNIT_TOL); returns a PW85_* status. The seed's signature returned
 *  nothing: on error, q (if not nullptr) is filled with NaN, a form that
 *  every function rejects (PW85_EDOM), never a plausible wrong one.
 *  @since 2.3.0 (the status and the checks) */
inline int spheroid(double a, double c, double const n[dim],
                    double q[sym]) noexcept {
  int const status = pw85_spheroid_checked(a, c, n, q);
  if (status != PW85_SUCCESS && q != nullptr)
    for (std::size_t k = 0; k < sym; ++k) q[k] = std::numeric_limits<double>::quiet_NaN();
  return status;
}

/** −f(λ) (pw85_f_neg()), with r12, q1, q2 passed separately. NaN if a
 *  pointer is NULL or an input is not finite. */
inline double f_neg(double lambda, double const r12[dim],
                    double const q1[sym], double const q2[sym]) noexcept {
  if (r12 == nullptr || q1 == nullptr || q2 == nullptr)
    return pw85_f_neg(lambda, nullptr);
  double params[PW85_DIM + 2 * PW85_SYM];
  for (std::size_t i = 0; i < dim; ++i) params[i] = r12[i];
  for (std::size_t i = 0; i < sym; ++i) {
    params[dim + i] = q1[i];
    params[dim + sym + i] = q2[i];
  }
  return pw85_f_neg(lambda, params);
}

/** out = {f(λ), g(λ), g′(λ)} (pw85__residual()). */
inline void _residual(double lambda, double const r12[dim],
                      double const q1[sym], double const q2[sym],
                      double out[3]) noexcept {
  pw85__residual(lambda, r12, q1, q2, out);
}

/** out = {μ², λ}; returns a PW85_* status (pw85_contact_function()). */
inline int contact_function(double const r12[dim], double const q1[sym],
                            double const q2[sym], double out[2]) noexcept {
  return pw85_contact_function(r12, q1, q2, out);
}

/** Certified overlap test (pw85_overlap()): *result = −1 overlap, +1
 *  disjoint, 0 tangent within 4 ulps; returns a PW85_* status.
 *  @since 2.1.0 */
inline int overlap(double const r12[dim], double const q1[sym],
                   double const q2[sym], int *result) noexcept {
  return pw85_overlap(r12, q1, q2, result);
}

/** Tolerance of the constructors on rotations and quaternions
 *  (PW85_UNIT_TOL).
 *  @since 2.2.0 */
constexpr double unit_tol = PW85_UNIT_TOL;

/** Offsets into the output of contact_geometry() (PW85_GEOM_*).
 *  @since 2.2.0 */
namespace geom {
/** μ² (PW85_GEOM_MU2). */
constexpr std::size_t mu2 = PW85_GEOM_MU2;
/** λ (PW85_GEOM_LAMBDA). */
constexpr std::size_t lambda = PW85_GEOM_LAMBDA;
/** 3 doubles: x − c1 (PW85_GEOM_POINT). */
constexpr std::size_t point = PW85_GEOM_POINT;
/** 3 doubles: the unit normal from ellipsoid 1 to 2 (PW85_GEOM_NORMAL). */
constexpr std::size_t normal = PW85_GEOM_NORMAL;
/** The number of doubles (PW85_GEOM_SIZE). */
constexpr std::size_t size = PW85_GEOM_SIZE;
}  // namespace geom

/** Offsets into the derivatives of contact_derivatives() (PW85_DERIV_*).
 *  @since 2.2.0 */
namespace deriv {
/** 3 doubles: ∂μ²/∂r12 (PW85_DERIV_R12). */
constexpr std::size_t r12 = PW85_DERIV_R12;
/** 3 doubles: ∂μ²/∂ω1, ω1 a rotation vector (PW85_DERIV_ROT1). */
constexpr std::size_t rot1 = PW85_DERIV_ROT1;
/** 3 doubles: ∂μ²/∂ω2 (PW85_DERIV_ROT2). */
constexpr std::size_t rot2 = PW85_DERIV_ROT2;
/** 6 doubles: ∂μ²/∂q1[k] (PW85_DERIV_Q1). */
constexpr std::size_t q1 = PW85_DERIV_Q1;
/** 6 doubles: ∂μ²/∂q2[k] (PW85_DERIV_Q2). */
constexpr std::size_t q2 = PW85_DERIV_Q2;
/** The number of doubles (PW85_DERIV_SIZE). */
constexpr std::size_t size = PW85_DERIV_SIZE;
}  // namespace deriv

/** Q = R·diag(a²)·Rᵀ, rot[3i + j] = R_ij (pw85_ellipsoid_rotation());
 *  returns a PW85_* status.
 *  @since 2.2.0 */
inline int ellipsoid_rotation(double const a[dim], double const rot[dim * dim],
                              double q[sym]) noexcept {
  return pw85_ellipsoid_rotation(a, rot, q);
}

/** Q from semi-axes and a unit quaternion (w, x, y, z), scalar first
 *  (OVITO and SciPy write (x, y, z, w)) (pw85_ellipsoid_quaternion()); returns a PW85_* status.
 *  @since 2.2.0 */
inline int ellipsoid_quaternion(double const a[dim], double const p[4],
                                double q[sym]) noexcept {
  return pw85_ellipsoid_quaternion(a, p, q);
}

/** Semi-axes (decreasing) and principal directions of Q
 *  (pw85_principal_axes()); returns a PW85_* status.
 *  @since 2.2.0 */
inline int principal_axes(double const q[sym], double a[dim],
                          double rot[dim * dim]) noexcept {
  return pw85_principal_axes(q, a, rot);
}

/** Semi-axes (decreasing) and the unit quaternion p = (w, x, y, z) of
 *  the principal directions, w ≥ 0 (pw85_principal_axes_quaternion());
 *  returns a PW85_* status.
 *  @since 2.3.0 */
inline int principal_axes_quaternion(double const q[sym], double a[dim],
                                     double p[4]) noexcept {
  return pw85_principal_axes_quaternion(q, a, p);
}

/** μ², λ, the contact point and the normal, laid out as geom::*
 *  (pw85_contact_geometry()); returns a PW85_* status.
 *  @since 2.2.0 */
inline int contact_geometry(double const r12[dim], double const q1[sym],
                            double const q2[sym],
                            double out[geom::size]) noexcept {
  return pw85_contact_geometry(r12, q1, q2, out);
}

/** contact_geometry() and the derivatives of μ², laid out as deriv::*
 *  (pw85_contact_derivatives()); returns a PW85_* status.
 *  @since 2.2.0 */
inline int contact_derivatives(double const r12[dim], double const q1[sym],
                               double const q2[sym],
                               double geometry[geom::size],
                               double d[deriv::size]) noexcept {
  return pw85_contact_derivatives(r12, q1, q2, geometry, d);
}

/** The number of threads a batch of n pairs runs on
 *  (pw85_batch_threads()).
 *  @since 2.2.0 */
inline int batch_threads(int threads, std::size_t n) noexcept {
  return pw85_batch_threads(threads, n);
}

/** contact_function() for n pairs, strides in doubles (0: one record for
 *  every pair), out = n×{μ², λ} (pw85_contact_function_batch()); returns
 *  PW85_SUCCESS or the first failing pair's status.
 *  @since 2.2.0 */
inline int contact_function_batch(std::size_t n, double const *r12,
                                  std::size_t r12_stride, double const *q1,
                                  std::size_t q1_stride, double const *q2,
                                  std::size_t q2_stride, double *out,
                                  int *status, int threads) noexcept {
  return pw85_contact_function_batch(n, r12, r12_stride, q1, q1_stride, q2,
                                     q2_stride, out, status, threads);
}

/** overlap() for n pairs (pw85_overlap_batch()).
 *  @since 2.2.0 */
inline int overlap_batch(std::size_t n, double const *r12,
                         std::size_t r12_stride, double const *q1,
                         std::size_t q1_stride, double const *q2,
                         std::size_t q2_stride, int *result, int *status,
                         int threads) noexcept {
  return pw85_overlap_batch(n, r12, r12_stride, q1, q1_stride, q2, q2_stride,
                            result, status, threads);
}

/** contact_geometry() for n pairs, out = n×geom::size
 *  (pw85_contact_geometry_batch()).
 *  @since 2.2.0 */
inline int contact_geometry_batch(std::size_t n, double const *r12,
                                  std::size_t r12_stride, double const *q1,
                                  std::size_t q1_stride, double const *q2,
                                  std::size_t q2_stride, double *out,
                                  int *status, int threads) noexcept {
  return pw85_contact_geometry_batch(n, r12, r12_stride, q1, q1_stride, q2,
                                     q2_stride, out, status, threads);
}

/** contact_derivatives() for n pairs, geometry = n×geom::size, d =
 *  n×deriv::size (pw85_contact_derivatives_batch()).
 *  @since 2.2.0 */
inline int contact_derivatives_batch(std::size_t n, double const *r12,
                                     std::size_t r12_stride,
                                     double const *q1, std::size_t q1_stride,
                                     double const *q2, std::size_t q2_stride,
                                     double *geometry, double *d, int *status,
                                     int threads) noexcept {
  return pw85_contact_derivatives_batch(n, r12, r12_stride, q1, q1_stride,
                                        q2, q2_stride, geometry, d, status,
                                        threads);
}

/** pw85_spheroid() for n spheroids, q = n×sym, with a status per item
 *  (pw85_spheroid_batch()).
 *  @since 2.2.0 */
inline int spheroid_batch(std::size_t n, double const *a,
                          std::size_t a_stride, double const *c,
                          std::size_t c_stride, double const *axis,
                          std::size_t axis_stride, double *q, int *status,
                          int threads) noexcept {
  return pw85_spheroid_batch(n, a, a_stride, c, c_stride, axis, axis_stride,
                             q, status, threads);
}

/** ellipsoid_rotation() for n ellipsoids, q = n×sym
 *  (pw85_ellipsoid_rotation_batch()).
 *  @since 2.2.0 */
inline int ellipsoid_rotation_batch(std::size_t n, double const *a,
                                    std::size_t a_stride, double const *rot,
                                    std::size_t rot_stride, double *q,
                                    int *status, int threads) noexcept {
  return pw85_ellipsoid_rotation_batch(n, a, a_stride, rot, rot_stride, q,
                                       status, threads);
}

/** ellipsoid_quaternion() for n ellipsoids, q = n×sym
 *  (pw85_ellipsoid_quaternion_batch()).
 *  @since 2.2.0 */
inline int ellipsoid_quaternion_batch(std::size_t n, double const *a,
                                      std::size_t a_stride, double const *p,
                                      std::size_t p_stride, double *q,
                                      int *status, int threads) noexcept {
  return pw85_ellipsoid_quaternion_batch(n, a, a_stride, p, p_stride, q,
                                         status, threads);
}

/** principal_axes() for n forms, a = n×dim, rot = n×9
 *  (pw85_principal_axes_batch()).
 *  @since 2.2.0 */
inline int principal_axes_batch(std::size_t n, double const *q,
                                std::size_t q_stride, double *a, double *rot,
                                int *status, int threads) noexcept {
  return pw85_principal_axes_batch(n, q, q_stride, a, rot, status, threads);
}

/** Ellipses: the functions of pw85_2d.h, with the conventions and the
 *  error model of the three-dimensional ones above (a PW85_* status
 *  returned, outputs written on success only unless pw85_2d.h says
 *  otherwise; −f(λ) NaN on bad input). A vector is `double[2]`
 *  (d2::dim); a form `double[3]` (d2::sym) = (Q00, Q01, Q11).
 *  @since 2.5.0 */
namespace d2 {

/** The number of coordinates of a vector (PW85_2D_DIM).
 *  @since 2.5.0 */
constexpr std::size_t dim = PW85_2D_DIM;
/** The number of stored entries of a symmetric 2 × 2 form (PW85_2D_SYM).
 *  @since 2.5.0 */
constexpr std::size_t sym = PW85_2D_SYM;

/** Offsets into the output of d2::contact_geometry() (PW85_2D_GEOM_*).
 *  @since 2.5.0 */
namespace geom {
/** μ² (PW85_2D_GEOM_MU2). */
constexpr std::size_t mu2 = PW85_2D_GEOM_MU2;
/** λ (PW85_2D_GEOM_LAMBDA). */
constexpr std::size_t lambda = PW85_2D_GEOM_LAMBDA;
/** 2 doubles: x − c1 (PW85_2D_GEOM_POINT). */
constexpr std::size_t point = PW85_2D_GEOM_POINT;
/** 2 doubles: the unit normal from ellipse 1 to 2 (PW85_2D_GEOM_NORMAL). */
constexpr std::size_t normal = PW85_2D_GEOM_NORMAL;
/** The number of doubles (PW85_2D_GEOM_SIZE). */
constexpr std::size_t size = PW85_2D_GEOM_SIZE;
}  // namespace geom

/** Offsets into the derivatives of d2::contact_derivatives()
 *  (PW85_2D_DERIV_*).
 *  @since 2.5.0 */
namespace deriv {
/** 2 doubles: ∂μ²/∂r12 (PW85_2D_DERIV_R12). */
constexpr std::size_t r12 = PW85_2D_DERIV_R12;
/** ∂μ²/∂θ1 (PW85_2D_DERIV_THETA1). */
constexpr std::size_t theta1 = PW85_2D_DERIV_THETA1;
/** ∂μ²/∂θ2 (PW85_2D_DERIV_THETA2). */
constexpr std::size_t theta2 = PW85_2D_DERIV_THETA2;
/** 3 doubles: ∂μ²/∂q1[k] (PW85_2D_DERIV_Q1). */
constexpr std::size_t q1 = PW85_2D_DERIV_Q1;
/** 3 doubles: ∂μ²/∂q2[k] (PW85_2D_DERIV_Q2). */
constexpr std::size_t q2 = PW85_2D_DERIV_Q2;
/** The number of doubles (PW85_2D_DERIV_SIZE). */
constexpr std::size_t size = PW85_2D_DERIV_SIZE;
}  // namespace deriv

/** −f(λ) for two ellipses (pw85_2d_f_neg()), with r12, q1, q2 passed
 *  separately. NaN if a pointer is NULL or an input is not finite, or a
 *  form is not positive definite.
 *  @since 2.5.0 */
inline double f_neg(double lambda, double const r12[dim],
                    double const q1[sym], double const q2[sym]) noexcept {
  if (r12 == nullptr || q1 == nullptr || q2 == nullptr)
    return pw85_2d_f_neg(lambda, nullptr);
  double params[PW85_2D_DIM + 2 * PW85_2D_SYM];
  for (std::size_t i = 0; i < dim; ++i) params[i] = r12[i];
  for (std::size_t i = 0; i < sym; ++i) {
    params[dim + i] = q1[i];
    params[dim + sym + i] = q2[i];
  }
  return pw85_2d_f_neg(lambda, params);
}

/** out = {μ², λ} of two ellipses; returns a PW85_* status
 *  (pw85_2d_contact_function()).
 *  @since 2.5.0 */
inline int contact_function(double const r12[dim], double const q1[sym],
                            double const q2[sym], double out[2]) noexcept {
  return pw85_2d_contact_function(r12, q1, q2, out);
}

/** Certified overlap test of two ellipses (pw85_2d_overlap()): *result =
 *  −1 overlap, +1 disjoint, 0 tangent within 4 ulps; returns a PW85_*
 *  status.
 *  @since 2.5.0 */
inline int overlap(double const r12[dim], double const q1[sym],
                   double const q2[sym], int *result) noexcept {
  return pw85_2d_overlap(r12, q1, q2, result);
}

/** μ², λ, the contact point and the normal, laid out as d2::geom::*
 *  (pw85_2d_contact_geometry()); returns a PW85_* status.
 *  @since 2.5.0 */
inline int contact_geometry(double const r12[dim], double const q1[sym],
                            double const q2[sym],
                            double out[geom::size]) noexcept {
  return pw85_2d_contact_geometry(r12, q1, q2, out);
}

/** d2::contact_geometry() and the derivatives of μ² (∂μ²/∂r12, ∂μ²/∂θ1,
 *  ∂μ²/∂θ2, ∂μ²/∂q1, ∂μ²/∂q2), laid out as d2::deriv::*
 *  (pw85_2d_contact_derivatives()); returns a PW85_* status.
 *  @since 2.5.0 */
inline int contact_derivatives(double const r12[dim], double const q1[sym],
                               double const q2[sym],
                               double geometry[geom::size],
                               double d[deriv::size]) noexcept {
  return pw85_2d_contact_derivatives(r12, q1, q2, geometry, d);
}

/** Q = R(θ)·diag(a0², a1²)·R(θ)ᵀ, a[0] along (cos θ, sin θ)
 *  (pw85_2d_ellipse()); returns a PW85_* status.
 *  @since 2.5.0 */
inline int ellipse(double const a[dim], double theta,
                   double q[sym]) noexcept {
  return pw85_2d_ellipse(a, theta, q);
}

/** The semi-axes (decreasing) and the angle θ in (−π/2, π/2] of the
 *  larger one (pw85_2d_principal_axes()); returns a PW85_* status.
 *  @since 2.5.0 */
inline int principal_axes(double const q[sym], double a[dim],
                          double *theta) noexcept {
  return pw85_2d_principal_axes(q, a, theta);
}

/** d2::contact_function() for n pairs, strides in doubles (0: one record
 *  for every pair), out = n×{μ², λ} (pw85_2d_contact_function_batch());
 *  returns PW85_SUCCESS or the first failing pair's status.
 *  @since 2.5.0 */
inline int contact_function_batch(std::size_t n, double const *r12,
                                  std::size_t r12_stride, double const *q1,
                                  std::size_t q1_stride, double const *q2,
                                  std::size_t q2_stride, double *out,
                                  int *status, int threads) noexcept {
  return pw85_2d_contact_function_batch(n, r12, r12_stride, q1, q1_stride,
                                        q2, q2_stride, out, status, threads);
}

/** d2::overlap() for n pairs (pw85_2d_overlap_batch()).
 *  @since 2.5.0 */
inline int overlap_batch(std::size_t n, double const *r12,
                         std::size_t r12_stride, double const *q1,
                         std::size_t q1_stride, double const *q2,
                         std::size_t q2_stride, int *result, int *status,
                         int threads) noexcept {
  return pw85_2d_overlap_batch(n, r12, r12_stride, q1, q1_stride, q2,
                               q2_stride, result, status, threads);
}

/** d2::contact_geometry() for n pairs, out = n×geom::size
 *  (pw85_2d_contact_geometry_batch()).
 *  @since 2.5.0 */
inline int contact_geometry_batch(std::size_t n, double const *r12,
                                  std::size_t r12_stride, double const *q1,
                                  std::size_t q1_stride, double const *q2,
                                  std::size_t q2_stride, double *out,
                                  int *status, int threads) noexcept {
  return pw85_2d_contact_geometry_batch(n, r12, r12_stride, q1, q1_stride,
                                        q2, q2_stride, out, status, threads);
}

/** d2::contact_derivatives() for n pairs, geometry = n×geom::size, d =
 *  n×deriv::size (pw85_2d_contact_derivatives_batch()).
 *  @since 2.5.0 */
inline int contact_derivatives_batch(std::size_t n, double const *r12,
                                     std::size_t r12_stride,
                                     double const *q1, std::size_t q1_stride,
                                     double const *q2, std::size_t q2_stride,
                                     double *geometry, double *d, int *status,
                                     int threads) noexcept {
  return pw85_2d_contact_derivatives_batch(n, r12, r12_stride, q1, q1_stride,
                                           q2, q2_stride, geometry, d,
                                           status, threads);
}

/** d2::ellipse() for n ellipses, theta_stride 1 or 0, q = n×sym
 *  (pw85_2d_ellipse_batch()).
 *  @since 2.5.0 */
inline int ellipse_batch(std::size_t n, double const *a,
                         std::size_t a_stride, double const *theta,
                         std::size_t theta_stride, double *q, int *status,
                         int threads) noexcept {
  return pw85_2d_ellipse_batch(n, a, a_stride, theta, theta_stride, q,
                               status, threads);
}

/** d2::principal_axes() for n forms, a = n×dim, theta = n
 *  (pw85_2d_principal_axes_batch()).
 *  @since 2.5.0 */
inline int principal_axes_batch(std::size_t n, double const *q,
                                std::size_t q_stride, double *a,
                                double *theta, int *status,
                                int threads) noexcept {
  return pw85_2d_principal_axes_batch(n, q, q_stride, a, theta, status,
                                      threads);
}

}  // namespace d2

}  // namespace pw85

// C++17 or later (MSVC reports its standard in _MSVC_LANG). Doxygen, which
// defines no __cplusplus, documents this part too.
#if !defined(__cplusplus) || __cplusplus >= 201703L || \
    (defined(_MSVC_LANG) && _MSVC_LANG >= 201703L)
#include <string_view>

namespace pw85 {

/** Facts about this project, fixed at compile time from the headers.
 *  Needs C++17 (std::string_view). */
namespace metadata {
constexpr std::string_view name{"pw85"};
/** The headers' version; pw85::library_version() gives the loaded one. */
constexpr std::string_view version{PW85_VERSION};
constexpr std::string_view description{
    "Implementation of the \"contact function\" defined by Perram and "
    "Wertheim (J. Comp. Phys. 58(3), 409-416, "
    "DOI:10.1016/0021-9991(85)90171-8) for two ellipsoids."};
constexpr std::string_view license{"BSD-3-Clause"};
constexpr std::string_view author{"The pw85 developers"};
/** Empty: the project has no public contact address yet. */
constexpr std::string_view author_email{""};
/** Empty: the project has no public home page yet. */
constexpr std::string_view url{""};
constexpr std::string_view year{"2026"};
}  // namespace metadata

}  // namespace pw85
#endif  // C++17

/// @cond INTERNAL
// Shared by the C++ headers of the index, the packer and the image (not
// part of the API).
namespace pw85 {
namespace detail_vector {
// Resizes v to n: PW85_SUCCESS, or PW85_ENOMEM (v then unchanged) where it
// cannot grow. Without exceptions, resize() itself ends the program then.
template <typename T>
int resize(std::vector<T> &v, std::size_t n) noexcept {
#if defined(__cpp_exceptions) || defined(__EXCEPTIONS) || defined(_CPPUNWIND)
  try {
    v.resize(n);
  } catch (std::bad_alloc const &) {
    return PW85_ENOMEM;
  } catch (std::length_error const &) {
    return PW85_ENOMEM;
  }
#else
  v.resize(n);
#endif
  return PW85_SUCCESS;
}
}  // namespace detail_vector
}  // namespace pw85
/// @endcond

// pw85::Index (the spatial index, pw85_index.h) belongs to this API; it
// has its own header, which includes this one.
#include "pw85_index.hpp"

#endif  // PW85_HPP
