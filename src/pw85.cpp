// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of libpw85: check arguments, call the core, map the
// core's status to PW85_*.
#include "pw85.h"

#include <cmath>
#include <cstddef>

#include "batch.hpp"
#include "checks.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "ellipsoid.hpp"
#include "f.hpp"
#include "facade.hpp"
#include "facade_pairs.hpp"
#include "geometry.hpp"
#include "overlap.hpp"
#include "spheroid.hpp"
#include "status.hpp"
#include "tolerances.hpp"

namespace {

namespace core = pw85::detail;
using core::Status;

static_assert(PW85_DIM == core::dim && PW85_SYM == core::sym,
              "pw85.h and the core disagree on sizes");
static_assert(PW85_GEOM_MU2 == core::geom::mu2 &&
                  PW85_GEOM_LAMBDA == core::geom::lambda &&
                  PW85_GEOM_POINT == core::geom::point &&
                  PW85_GEOM_NORMAL == core::geom::normal &&
                  PW85_GEOM_SIZE == core::geom::size &&
                  PW85_DERIV_R12 == core::deriv::r12 &&
                  PW85_DERIV_ROT1 == core::deriv::rot1 &&
                  PW85_DERIV_ROT2 == core::deriv::rot2 &&
                  PW85_DERIV_Q1 == core::deriv::q1 &&
                  PW85_DERIV_Q2 == core::deriv::q2 &&
                  PW85_DERIV_SIZE == core::deriv::size,
              "pw85.h and the core disagree on the layouts of the outputs");
static_assert(PW85_UNIT_TOL == core::unit_tol,
              "pw85.h and the core disagree on PW85_UNIT_TOL");
static_assert(PW85_LAMBDA_ATOL == core::lambda_atol &&
                  PW85_MAX_ITER == core::brent_max_iter &&
                  PW85_NR_ITER == core::restart_newton_iter,
              "pw85.h does not describe the core as built");

using pw85::facade::run_items;
using pw85::facade::to_code;
using pw85::facade::valid_stride;

// The single-pair functions, shared with pw85_2d.cpp (facade_pairs.hpp).
constexpr int D = PW85_DIM;
using pw85::facade::contact_function_one;
using pw85::facade::f_neg_one;
using pw85::facade::geometry_only;
using pw85::facade::overlap_one;
using pw85::facade::with_derivatives;
// ---------------------------------------------------------------------------
// Batches (pw85.h, "Batches").

using pw85::facade::pairs_batch;
using pw85::facade::pairs_batch2;

// pw85_spheroid() with the statuses of its batch: PW85_EDOM for a
// non-finite input (q untouched), PW85_ERANGE for a non-finite entry of q
// (q written).
inline int spheroid_one(double a, double c, double const *axis,
                        double *q) noexcept {
  if (!std::isfinite(a) || !std::isfinite(c) || !std::isfinite(axis[0]) ||
      !std::isfinite(axis[1]) || !std::isfinite(axis[2]))
    return PW85_EDOM;
  core::spheroid(a, c, axis, q);
  for (int k = 0; k < PW85_SYM; ++k)
    if (!std::isfinite(q[k])) return PW85_ERANGE;
  return PW85_SUCCESS;
}

}  // namespace

extern "C" {

const char *pw85_strerror(int status) noexcept {
  switch (status) {
    case PW85_SUCCESS:
      return "success";
    case PW85_EFAULT:
      return "a pointer argument is NULL";
    case PW85_EDOM:
      return "an input is NaN or infinite";
    case PW85_ENOTPOSDEF:
      return "a quadratic form is not positive definite";
    case PW85_ERANGE:
      return "the result, or the dynamic range of the input, exceeds the "
             "range of a double";
    case PW85_ENOMEM:
      return "out of memory (the index could not allocate, or the "
             "minimiser needs more working memory than reserved)";
    case PW85_ENOCONV:
      return "the method did not converge";
    case PW85_EINVAL:
      return "an argument is outside its documented domain";
    case PW85_ECANCELLED:
      return "cancelled by a function of the caller";
    default:
      return "unknown pw85 status";
  }
}

const char *pw85_version(void) noexcept { return PW85_VERSION; }

void pw85__cholesky_decomp(double const a[PW85_SYM],
                           double l[PW85_SYM]) noexcept {
  // No status in the original signature: a form that is not positive
  // definite (the rule of pw85.h) is reported as NaN in every entry.
  if (!core::cholesky_by_rule(a, l))
    for (int i = 0; i < PW85_SYM; ++i) l[i] = NAN;
}

void pw85__cholesky_solve(double const l[PW85_SYM], double const b[PW85_DIM],
                          double x[PW85_DIM]) noexcept {
  core::cholesky_solve(l, b, x);
}

void pw85_spheroid(double a, double c, double const n[PW85_DIM],
                   double q[PW85_SYM]) noexcept {
  if (q == nullptr) return;
  if (n == nullptr) {
    for (int i = 0; i < PW85_SYM; ++i) q[i] = NAN;
    return;
  }
  core::spheroid(a, c, n, q);
}

double pw85_f_neg(double lambda,
                  double const params[PW85_DIM + 2 * PW85_SYM]) noexcept {
  return f_neg_one<D>(lambda, params);
}

void pw85__residual(double lambda, double const r12[PW85_DIM],
                    double const q1[PW85_SYM], double const q2[PW85_SYM],
                    double out[3]) noexcept {
  core::residual(lambda, r12, q1, q2, out);
}

int pw85_contact_function(double const r12[PW85_DIM], double const q1[PW85_SYM],
                          double const q2[PW85_SYM], double out[2]) noexcept {
  return contact_function_one<D>(r12, q1, q2, out);
}

int pw85_overlap(double const r12[PW85_DIM], double const q1[PW85_SYM],
                 double const q2[PW85_SYM], int *result) noexcept {
  return overlap_one<D>(r12, q1, q2, result);
}

int pw85_ellipsoid_rotation(double const a[PW85_DIM],
                            double const rot[PW85_DIM * PW85_DIM],
                            double q[PW85_SYM]) noexcept {
  if (a == nullptr || rot == nullptr || q == nullptr) return PW85_EFAULT;
  return to_code(core::ellipsoid_rotation(a, rot, q));
}

int pw85_ellipsoid_quaternion(double const a[PW85_DIM], double const p[4],
                              double q[PW85_SYM]) noexcept {
  if (a == nullptr || p == nullptr || q == nullptr) return PW85_EFAULT;
  return to_code(core::ellipsoid_quaternion(a, p, q));
}

int pw85_principal_axes(double const q[PW85_SYM], double a[PW85_DIM],
                        double rot[PW85_DIM * PW85_DIM]) noexcept {
  if (q == nullptr || a == nullptr || rot == nullptr) return PW85_EFAULT;
  return to_code(core::principal_axes(q, a, rot));
}

int pw85_principal_axes_quaternion(double const q[PW85_SYM],
                                   double a[PW85_DIM], double p[4]) noexcept {
  if (q == nullptr || a == nullptr || p == nullptr) return PW85_EFAULT;
  return to_code(core::principal_axes_quaternion(q, a, p));
}

int pw85_spheroid_checked(double a, double c, double const n[PW85_DIM],
                          double q[PW85_SYM]) noexcept {
  if (n == nullptr || q == nullptr) return PW85_EFAULT;
  return to_code(core::spheroid_checked(a, c, n, q));
}

int pw85_contact_geometry(double const r12[PW85_DIM],
                          double const q1[PW85_SYM], double const q2[PW85_SYM],
                          double out[PW85_GEOM_SIZE]) noexcept {
  return geometry_only<D>(r12, q1, q2, out);
}

int pw85_contact_derivatives(double const r12[PW85_DIM],
                             double const q1[PW85_SYM],
                             double const q2[PW85_SYM],
                             double geometry[PW85_GEOM_SIZE],
                             double d[PW85_DERIV_SIZE]) noexcept {
  return with_derivatives<D>(r12, q1, q2, geometry, d);
}

int pw85_batch_threads(int threads, size_t n) noexcept {
  return threads < 0 ? 0 : core::batch_threads(threads, n);
}

int pw85_contact_function_batch(size_t n, double const *r12,
                                size_t r12_stride, double const *q1,
                                size_t q1_stride, double const *q2,
                                size_t q2_stride, double *out, int *status,
                                int threads) noexcept {
  return pairs_batch<PW85_DIM>(
      n, {r12, q1, q2, r12_stride, q1_stride, q2_stride}, out, 2, status,
      threads, contact_function_one<D>);
}

int pw85_overlap_batch(size_t n, double const *r12, size_t r12_stride,
                       double const *q1, size_t q1_stride, double const *q2,
                       size_t q2_stride, int *result, int *status,
                       int threads) noexcept {
  return pairs_batch<PW85_DIM>(
      n, {r12, q1, q2, r12_stride, q1_stride, q2_stride}, result, 1, status,
      threads, overlap_one<D>);
}

int pw85_contact_geometry_batch(size_t n, double const *r12,
                                size_t r12_stride, double const *q1,
                                size_t q1_stride, double const *q2,
                                size_t q2_stride, double *out, int *status,
                                int threads) noexcept {
  return pairs_batch<PW85_DIM>(
      n, {r12, q1, q2, r12_stride, q1_stride, q2_stride}, out,
      PW85_GEOM_SIZE, status, threads, geometry_only<D>);
}

int pw85_contact_derivatives_batch(size_t n, double const *r12,
                                   size_t r12_stride, double const *q1,
                                   size_t q1_stride, double const *q2,
                                   size_t q2_stride, double *geometry,
                                   double *d, int *status,
                                   int threads) noexcept {
  return pairs_batch2<PW85_DIM>(
      n, {r12, q1, q2, r12_stride, q1_stride, q2_stride}, geometry,
      PW85_GEOM_SIZE, d, PW85_DERIV_SIZE, status, threads,
      with_derivatives<D>);
}

int pw85_spheroid_batch(size_t n, double const *a, size_t a_stride,
                        double const *c, size_t c_stride, double const *axis,
                        size_t axis_stride, double *q, int *status,
                        int threads) noexcept {
  return run_items(
      n, a != nullptr && c != nullptr && axis != nullptr && q != nullptr,
      valid_stride(a_stride, 1) && valid_stride(c_stride, 1) &&
          valid_stride(axis_stride, PW85_DIM),
      status, threads, [=](std::size_t i) noexcept {
        return spheroid_one(a[i * a_stride], c[i * c_stride],
                            axis + i * axis_stride, q + PW85_SYM * i);
      });
}

int pw85_ellipsoid_rotation_batch(size_t n, double const *a, size_t a_stride,
                                  double const *rot, size_t rot_stride,
                                  double *q, int *status,
                                  int threads) noexcept {
  return run_items(
      n, a != nullptr && rot != nullptr && q != nullptr,
      valid_stride(a_stride, PW85_DIM) &&
          valid_stride(rot_stride, PW85_DIM * PW85_DIM),
      status, threads, [=](std::size_t i) noexcept {
        return to_code(core::ellipsoid_rotation(
            a + i * a_stride, rot + i * rot_stride, q + PW85_SYM * i));
      });
}

int pw85_ellipsoid_quaternion_batch(size_t n, double const *a,
                                    size_t a_stride, double const *p,
                                    size_t p_stride, double *q, int *status,
                                    int threads) noexcept {
  return run_items(
      n, a != nullptr && p != nullptr && q != nullptr,
      valid_stride(a_stride, PW85_DIM) && valid_stride(p_stride, 4), status,
      threads, [=](std::size_t i) noexcept {
        return to_code(core::ellipsoid_quaternion(
            a + i * a_stride, p + i * p_stride, q + PW85_SYM * i));
      });
}

int pw85_principal_axes_batch(size_t n, double const *q, size_t q_stride,
                              double *a, double *rot, int *status,
                              int threads) noexcept {
  return run_items(
      n, q != nullptr && a != nullptr && rot != nullptr,
      valid_stride(q_stride, PW85_SYM), status, threads,
      [=](std::size_t i) noexcept {
        return to_code(core::principal_axes(q + i * q_stride,
                                            a + PW85_DIM * i,
                                            rot + PW85_DIM * PW85_DIM * i));
      });
}

int pw85_principal_axes_quaternion_batch(size_t n, double const *q,
                                         size_t q_stride, double *a,
                                         double *p, int *status,
                                         int threads) noexcept {
  return run_items(
      n, q != nullptr && a != nullptr && p != nullptr,
      valid_stride(q_stride, PW85_SYM), status, threads,
      [=](std::size_t i) noexcept {
        return to_code(core::principal_axes_quaternion(
            q + i * q_stride, a + PW85_DIM * i, p + 4 * i));
      });
}

}  // extern "C"
