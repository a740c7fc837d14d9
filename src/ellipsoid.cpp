// SPDX-License-Identifier: BSD-3-Clause
// Ellipsoids from semi-axes and a rotation or a quaternion (ellipsoid.hpp).
#include "ellipsoid.hpp"

#include <cfloat>
#include <cmath>

#include "checks.hpp"
#include "dd.hpp"
#include "scaling.hpp"
#include "spheroid.hpp"

namespace pw85::detail {

namespace {

// aₘ² exactly, as double-doubles (D of them); false when one is not > 0
// (invalid) or leaves the normal range (*range).
template <int D>
bool squares(double const *a, dd *a2, bool *range) noexcept {
  *range = true;
  for (int m = 0; m < D; ++m) {
    if (!(a[m] > 0.0)) return false;
    a2[m] = two_prod(a[m], a[m]);
    if (!(a2[m].hi >= DBL_MIN && a2[m].hi <= DBL_MAX)) *range = false;
  }
  return true;
}

// q[k] = Σₘ R_im·aₘ²·R_jm for entry k = (i, j), in double-double, rounded
// once. Each product and sum errs by at most a few 2⁻¹⁰⁶ of the magnitudes
// involved: less than 2⁻¹⁰⁰·Σₘ |R_im·R_jm|·aₘ² in all (pw85.h). R_im·aₘ²
// first: R_im·R_jm first underflowed where both are tiny (sin²θ = 2^−1311)
// before meeting a large aₘ² (2^866), and a term of 1.8e-134 was lost
// (fuzz-2d, regress-ellipse-underflow); |R_jm| ≤ 1, so what the second
// product loses is below the subnormal range itself. R is D × D, row by
// row.
template <int D>
void form(dd const *r, dd const *a2, double *q) noexcept {
  for (int k = 0; k < sym_size(D); ++k) {
    int const i = Layout<D>::row[k], j = Layout<D>::col[k];
    dd acc{0.0, 0.0};
    for (int m = 0; m < D; ++m)
      acc = dd_add(acc, dd_mul(dd_mul(r[D * i + m], a2[m]), r[D * j + m]));
    q[k] = acc.hi;  // dd_add normalises: hi is hi + lo rounded
  }
}

}  // namespace

Status ellipsoid_rotation(double const a[dim], double const rot[dim * dim],
                          double q[sym]) noexcept {
  if (!(all_finite<dim>(a) && all_finite<dim * dim>(rot)))
    return Status::not_finite;
  dd a2[dim];
  bool in_range = true;
  if (!squares<dim>(a, a2, &in_range)) return Status::invalid_argument;
  // RᵀR = I to PW85_UNIT_TOL, entry by entry (plain double suffices: the
  // tolerance is far above its rounding).
  for (int i = 0; i < dim; ++i)
    for (int j = i; j < dim; ++j) {
      double g = 0.0;
      for (int m = 0; m < dim; ++m) g += rot[dim * m + i] * rot[dim * m + j];
      if (!(std::fabs(g - (i == j ? 1.0 : 0.0)) <= unit_tol))
        return Status::invalid_argument;
    }
  if (!in_range) return Status::out_of_range;
  dd r[dim * dim];
  for (int k = 0; k < dim * dim; ++k) r[k] = dd{rot[k], 0.0};
  form<dim>(r, a2, q);
  return Status::success;
}

Status ellipsoid_quaternion(double const a[dim], double const p[4],
                            double q[sym]) noexcept {
  if (!(all_finite<dim>(a) && all_finite<4>(p))) return Status::not_finite;
  dd a2[dim];
  bool in_range = true;
  if (!squares<dim>(a, a2, &in_range)) return Status::invalid_argument;
  // n = ‖p‖² and the products pₖ·pₗ, exactly (two_prod), barring underflow.
  dd pp[4][4];
  for (int k = 0; k < 4; ++k)
    for (int l = k; l < 4; ++l) pp[k][l] = pp[l][k] = two_prod(p[k], p[l]);
  dd const n = dd_add(dd_add(pp[0][0], pp[1][1]), dd_add(pp[2][2], pp[3][3]));
  if (!(std::fabs(n.hi - 1.0) <= unit_tol)) return Status::invalid_argument;
  if (!in_range) return Status::out_of_range;
  // R(p/‖p‖) = I + (2/n)·(w·[u]× + [u]×²), u = (x, y, z): the rotation
  // v ↦ p·v·p* written with the products of the components of p.
  dd const c = dd_div(dd{2.0, 0.0}, n);
  int constexpr w = 0, x = 1, y = 2, z = 3;
  dd const diag[dim] = {dd_add(pp[y][y], pp[z][z]), dd_add(pp[x][x], pp[z][z]),
                        dd_add(pp[x][x], pp[y][y])};
  dd r[dim * dim];
  for (int i = 0; i < dim; ++i)
    r[dim * i + i] = dd_sub(dd{1.0, 0.0}, dd_mul(c, diag[i]));
  r[1] = dd_mul(c, dd_sub(pp[x][y], pp[w][z]));  // R01
  r[3] = dd_mul(c, dd_add(pp[x][y], pp[w][z]));  // R10
  r[2] = dd_mul(c, dd_add(pp[x][z], pp[w][y]));  // R02
  r[6] = dd_mul(c, dd_sub(pp[x][z], pp[w][y]));  // R20
  r[5] = dd_mul(c, dd_sub(pp[y][z], pp[w][x]));  // R12
  r[7] = dd_mul(c, dd_add(pp[y][z], pp[w][x]));  // R21
  form<dim>(r, a2, q);
  return Status::success;
}

Status ellipse_angle(double const a[2], double theta, double q[3]) noexcept {
  if (!(all_finite<2>(a) && std::isfinite(theta))) return Status::not_finite;
  dd a2[2];
  bool in_range = true;
  if (!squares<2>(a, a2, &in_range)) return Status::invalid_argument;
  if (!in_range) return Status::out_of_range;
  double const c = std::cos(theta), s = std::sin(theta);
  dd const r[4] = {{c, 0.0}, {-s, 0.0}, {s, 0.0}, {c, 0.0}};
  form<2>(r, a2, q);
  return Status::success;
}

Status ellipse_principal_axes(double const q[3], double a[2],
                              double *theta) noexcept {
  if (!all_finite<3>(q)) return Status::not_finite;
  if (!is_positive_definite<2>(q)) return Status::not_positive_definite;
  // Q·2^−2e, so that aⱼ = √(aⱼ² of the scaled Q)·2^e exactly; exact but
  // for an entry below 2^−1022 of the largest diagonal entry, whose
  // rounding (2^−1074 of it at most) moves each Rayleigh quotient below by
  // at most 2^−1073·cond(Q) relative: nothing for any Q not singular to
  // double.
  int const e = exponent(std::fmax(q[0], q[2])) / 2;
  double const s[3] = {times_pow2(q[0], -2 * e), times_pow2(q[1], -2 * e),
                       times_pow2(q[2], -2 * e)};
  // The eigenvector of the larger eigenvalue of [[q0, q1], [q1, q2]] is at
  // angle ½·atan2(2·q1, q0 − q2) (the double-angle form of tan 2θ =
  // 2·q1/(q0 − q2)), in [−π/2, π/2]; −π/2 is the same axis as π/2. From Q
  // as stored, not scaled: there Q01 may underflow, and with Q00 = Q11 the
  // axis at ±45° would become 0. q0 − q2 cannot overflow (both > 0);
  // 2·q1 could: then every entry is halved first, exactly (q1² < q0·q2
  // puts q0 and q2 above DBL_MAX/4).
  bool const halve = std::fabs(q[1]) > 0.5 * DBL_MAX;
  double const y = halve ? q[1] : 2.0 * q[1];
  double const x = halve ? 0.5 * q[0] - 0.5 * q[2] : q[0] - q[2];
  double t = 0.5 * std::atan2(y, x);
  if (t <= -0.5 * M_PI) t = 0.5 * M_PI;
  double const c = std::cos(t), n = std::sin(t);
  // a0² = the Rayleigh quotient vᵀSv/vᵀv of v = (c, n), in double-double
  // (S stored: vᵀSv = s0·v0² + 2·s1·v0·v1 + s2·v1²): an error δ in the
  // direction moves it by δ²·(a0² − a1²) only. a1² = det(S)/a0², the
  // product of the eigenvalues over the larger, with det(S) = s0·s2 − s1²
  // from exact products: relative error 2⁻¹⁰⁶·(s0·s2 + s1²)/det ≤
  // u²·(a0/a1)²/2 (u = 2⁻⁵³), where the Rayleigh quotient of w = (−n, c)
  // erred by δ²·(a0/a1)², a few u²·(a0/a1)² (fuzz-2d: 7.2·u for a stated
  // 6.4·u).
  dd const vx = two_prod(c, c), vxy = two_prod(c, n), vy = two_prod(n, n);
  dd const num = dd_add(dd_add(dd_mul(vx, s[0]), dd_mul(vxy, 2.0 * s[1])),
                        dd_mul(vy, s[2]));
  dd const big = dd_div(num, dd_add(vx, vy));
  dd const det = dd_sub(two_prod(s[0], s[2]), two_prod(s[1], s[1]));
  if (!(big.hi > 0.0) || !(det.hi > 0.0)) return Status::out_of_range;
  double axes[2] = {times_pow2(dd_round(dd_sqrt(big)), e),
                    times_pow2(dd_round(dd_sqrt(dd_div(det, big))), e)};
  // (atan2's choice makes axes[0] the larger, but for rounding where the
  // two are equal to the last bits.)
  if (axes[1] > axes[0]) {
    double const tmp = axes[0];
    axes[0] = axes[1];
    axes[1] = tmp;
    t = t > 0.0 ? t - 0.5 * M_PI : t + 0.5 * M_PI;
  }
  a[0] = axes[0];
  a[1] = axes[1];
  *theta = t;
  return Status::success;
}

Status spheroid_checked(double a, double c, double const n[dim],
                        double q[sym]) noexcept {
  if (!(std::isfinite(a) && std::isfinite(c) && all_finite<dim>(n)))
    return Status::not_finite;
  if (!(a > 0.0 && c > 0.0)) return Status::invalid_argument;
  // ‖n‖² in double-double (exact products), as for a quaternion.
  dd const nn = dd_add(dd_add(two_prod(n[0], n[0]), two_prod(n[1], n[1])),
                       two_prod(n[2], n[2]));
  if (!(std::fabs(nn.hi - 1.0) <= unit_tol)) return Status::invalid_argument;
  double const a2 = a * a, c2 = c * c;
  if (!(a2 >= DBL_MIN && a2 <= DBL_MAX && c2 >= DBL_MIN && c2 <= DBL_MAX))
    return Status::out_of_range;
  spheroid(a, c, n, q);
  return Status::success;
}

Status principal_axes_quaternion(double const q[sym], double a[dim],
                                 double p[4]) noexcept {
  double r[dim * dim], axes[dim];
  Status const status = principal_axes(q, axes, r);
  if (status != Status::success) return status;
  // The quaternion of a rotation matrix (Shepperd, J. Guidance and Control
  // 1(3), 223-224, 1978): of 4w² = 1 + tr R, 4x² = 1 + R00 − R11 − R22,
  // 4y² = 1 − R00 + R11 − R22, 4z² = 1 − R00 − R11 + R22, the largest
  // gives its component by a square root, far from cancellation (≥ 1/4);
  // the others come from the off-diagonal sums and differences, with
  // R(p) as in ellipsoid_quaternion(): R21 − R12 = 4wx, R02 − R20 = 4wy,
  // R10 − R01 = 4wz, R01 + R10 = 4xy, R02 + R20 = 4xz, R12 + R21 = 4yz.
  auto R = [&r](int i, int j) { return r[dim * i + j]; };
  double const four[4] = {1.0 + R(0, 0) + R(1, 1) + R(2, 2),
                          1.0 + R(0, 0) - R(1, 1) - R(2, 2),
                          1.0 - R(0, 0) + R(1, 1) - R(2, 2),
                          1.0 - R(0, 0) - R(1, 1) + R(2, 2)};
  int big = 0;
  for (int k = 1; k < 4; ++k)
    if (four[k] > four[big]) big = k;
  double const s = std::sqrt(four[big]);  // 2·|p_big|
  double const h = 0.5 / s;               // 1/(4·|p_big|)
  double const wx = R(2, 1) - R(1, 2), wy = R(0, 2) - R(2, 0),
               wz = R(1, 0) - R(0, 1), xy = R(0, 1) + R(1, 0),
               xz = R(0, 2) + R(2, 0), yz = R(1, 2) + R(2, 1);
  double t[4];
  switch (big) {
    case 0: t[0] = 0.5 * s; t[1] = wx * h; t[2] = wy * h; t[3] = wz * h; break;
    case 1: t[1] = 0.5 * s; t[0] = wx * h; t[2] = xy * h; t[3] = xz * h; break;
    case 2: t[2] = 0.5 * s; t[0] = wy * h; t[1] = xy * h; t[3] = yz * h; break;
    default: t[3] = 0.5 * s; t[0] = wz * h; t[1] = xz * h; t[2] = yz * h; break;
  }
  // Unit norm to rounding, and the sign of the pair ±p fixed: w > 0, or
  // w = 0 and the first non-zero component positive.
  double const norm = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] +
                                t[3] * t[3]);
  int first = 0;
  while (first < 3 && t[first] == 0.0) ++first;
  double const sign = t[first] < 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < dim; ++k) a[k] = axes[k];
  for (int k = 0; k < 4; ++k) p[k] = sign * t[k] / norm + 0.0;
  return Status::success;
}

}  // namespace pw85::detail
