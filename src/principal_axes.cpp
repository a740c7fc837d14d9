// SPDX-License-Identifier: BSD-3-Clause
// The semi-axes and principal directions of an ellipsoid (ellipsoid.hpp):
// the eigenvectors from GSL's symmetric eigensolver, the eigenvalues from
// their Rayleigh quotients in double-double.
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include <algorithm>
#include <cmath>

#include "checks.hpp"
#include "compensated.hpp"
#include "ellipsoid.hpp"
#include "ldl.hpp"
#include "scaling.hpp"

namespace pw85::detail {

namespace {

// GSL's eigenvectors of the 3×3 symmetric matrix q, as the columns of v
// (row by row). gsl_eigen_symmv's workspace is a public struct of four
// arrays of n doubles (gsl_eigen_symmv_alloc() allocates exactly that):
// built here on the stack, so that nothing is allocated. With square
// matrices of matching sizes, gsl_eigen_symmv() cannot fail nor reach the
// error handler; it converges for finite input.
void eigenvectors(double const q[sym], double v[dim * dim]) noexcept {
  double a[dim * dim], eval[dim];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) a[dim * i + j] = q[sym_index(i, j)];
  double d[dim], sd[dim], gc[dim], gs[dim];
  gsl_eigen_symmv_workspace work{dim, d, sd, gc, gs};
  gsl_matrix_view am = gsl_matrix_view_array(a, dim, dim);
  gsl_matrix_view vm = gsl_matrix_view_array(v, dim, dim);
  gsl_vector_view ev = gsl_vector_view_array(eval, dim);
  gsl_eigen_symmv(&am.matrix, &ev.vector, &vm.matrix, &work);
}

}  // namespace

Status principal_axes(double const q[sym], double a[dim],
                      double rot[dim * dim]) noexcept {
  if (!all_finite<sym>(q)) return Status::not_finite;
  if (!is_positive_definite(q)) return Status::not_positive_definite;
  // Q = Q'·2^e with e even, so that a = a'·2^(e/2) exactly, and the
  // largest diagonal entry of Q' in [1/4, 1) (which bounds every entry).
  double dmax = std::max(std::max(q[0], q[3]), q[5]);
  int e = exponent(dmax);
  if (e % 2 != 0) ++e;
  double qs[sym];
  for (int k = 0; k < sym; ++k) qs[k] = times_pow2(q[k], -e);
  // GSL's QR iterations can fail to converge (they never return) once
  // their numbers are subnormal, which the diagonal of the tridiagonal
  // form, bounded below by λmin, keeps them from while λmin ≥ 2^−900
  // (the deflation test then stays above 2^−952). λmin ≥ 1/tr(Q⁻¹) ≥
  // λmin/3: forms with a larger condition number (above about 1e270) are
  // refused.
  Ldl fac;
  if (!ldl_decomp(qs, &fac) || !(ldl_trace_inverse(fac) <= 0x1p900))
    return Status::out_of_range;
  double v[dim * dim];
  eigenvectors(qs, v);
  // aⱼ² = vⱼᵀQvⱼ/vⱼᵀvⱼ, vⱼ the column j of v: off by (λmax − λⱼ)·sin²θⱼ
  // for vⱼ at an angle θⱼ of order ε·‖Q‖/gapⱼ from its eigenspace, plus
  // the rounding of the quotient, however small aⱼ² is beside ‖Q‖.
  double a2[dim], col[dim][dim];
  for (int j = 0; j < dim; ++j) {
    for (int i = 0; i < dim; ++i) col[j][i] = v[dim * i + j];
    dd const vv = dot_dd(col[j], col[j]);
    a2[j] = quad_form_dd(qs, col[j]) / (vv.hi + vv.lo);
    // Q is positive definite (the rule, exact): a quotient ≤ 0 is below
    // the precision of double-double, not a sign of indefiniteness.
    if (!(a2[j] > 0.0)) return Status::out_of_range;
  }
  // Decreasing order: an insertion sort of three, stable (std::stable_sort
  // may allocate a buffer).
  int order[dim] = {0, 1, 2};
  for (int i = 1; i < dim; ++i)
    for (int j = i; j > 0 && a2[order[j]] > a2[order[j - 1]]; --j) {
      int const t = order[j];
      order[j] = order[j - 1];
      order[j - 1] = t;
    }
  double r[dim][dim];  // r[j]: the direction of a[j]
  for (int j = 0; j < dim; ++j) {
    a[j] = times_pow2(std::sqrt(a2[order[j]]), e / 2);
    for (int i = 0; i < dim; ++i) r[j][i] = col[order[j]][i];
  }
  // Signs: the entry of largest magnitude of r[0] and r[1] positive, r[2]
  // then such that det R = +1.
  for (int j = 0; j < 2; ++j) {
    int big = 0;
    for (int i = 1; i < dim; ++i)
      if (std::fabs(r[j][i]) > std::fabs(r[j][big])) big = i;
    if (r[j][big] < 0.0)
      for (int i = 0; i < dim; ++i) r[j][i] = -r[j][i];
  }
  double const det =
      r[2][0] * (r[0][1] * r[1][2] - r[0][2] * r[1][1]) +
      r[2][1] * (r[0][2] * r[1][0] - r[0][0] * r[1][2]) +
      r[2][2] * (r[0][0] * r[1][1] - r[0][1] * r[1][0]);
  if (det < 0.0)
    for (int i = 0; i < dim; ++i) r[2][i] = -r[2][i];
  for (int i = 0; i < dim; ++i)
    for (int j = 0; j < dim; ++j) rot[dim * i + j] = r[j][i];
  return Status::success;
}

}  // namespace pw85::detail
