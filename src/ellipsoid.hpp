// SPDX-License-Identifier: BSD-3-Clause
// Ellipsoids from semi-axes and an orientation, and back (private;
// docs/theory.rst, eq. (3.2): Q = Σ aᵢ²·vᵢ·vᵢᵀ).
#ifndef PW85_SRC_ELLIPSOID_HPP
#define PW85_SRC_ELLIPSOID_HPP

#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// The tolerance of pw85.h's PW85_UNIT_TOL.
constexpr double unit_tol = 1e-6;

// pw85_ellipsoid_rotation(): Q = R·diag(a²)·Rᵀ, rot[3i + j] = R_ij, in
// double-double, rounded once. Pointers valid. Returns Status::success,
// not_finite, invalid_argument or out_of_range; q is written on success
// only.
Status ellipsoid_rotation(double const a[dim], double const rot[dim * dim],
                          double q[sym]) noexcept;

// pw85_ellipsoid_quaternion(): the same with R = R(p/‖p‖), p = (w, x, y, z).
Status ellipsoid_quaternion(double const a[dim], double const p[4],
                            double q[sym]) noexcept;

// pw85_principal_axes() (principal_axes.cpp: GSL's gsl_eigen_symmv).
// Returns Status::success, not_finite, not_positive_definite or
// out_of_range (cond(Q) above about 1e270); a and rot are written on
// success only.
Status principal_axes(double const q[sym], double a[dim],
                      double rot[dim * dim]) noexcept;

// pw85_principal_axes_quaternion(): principal_axes(), then the unit
// quaternion p = (w, x, y, z) of R (w ≥ 0). Statuses as principal_axes();
// a and p are written on success only.
Status principal_axes_quaternion(double const q[sym], double a[dim],
                                 double p[4]) noexcept;

// pw85_2d_ellipse(): Q = R(θ)·diag(a²)·R(θ)ᵀ in double-double, rounded
// once, R(θ) from cos θ and sin θ in double. Pointers valid. Statuses as
// ellipsoid_rotation(); q is written on success only.
Status ellipse_angle(double const a[2], double theta, double q[3]) noexcept;

// pw85_2d_principal_axes(): θ in closed form, the semi-axes from
// Rayleigh quotients in double-double. Pointers valid. Returns
// Status::success, not_finite, not_positive_definite or out_of_range; a
// and theta are written on success only.
Status ellipse_principal_axes(double const q[3], double a[2],
                              double *theta) noexcept;

// pw85_spheroid_checked(): the preconditions of pw85_spheroid() checked
// (finite, a > 0, c > 0, |‖n‖² − 1| ≤ unit_tol, a² and c² normal), then
// spheroid(). Returns Status::success, not_finite, invalid_argument or
// out_of_range; q is written on success only.
Status spheroid_checked(double a, double c, double const n[dim],
                        double q[sym]) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_ELLIPSOID_HPP
