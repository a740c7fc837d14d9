// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of libpw85: check arguments, call the core, map the
// core's status to PW85_*.
#include "pw85.h"

#include <cmath>

#include "checks.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "ellipsoid.hpp"
#include "f.hpp"
#include "facade.hpp"
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

using pw85::facade::to_code;

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
      return "the minimiser needs more working memory than reserved";
    case PW85_ENOCONV:
      return "the method did not converge";
    case PW85_EINVAL:
      return "an argument is outside its documented domain";
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
  if (params == nullptr) return NAN;
  double const *r12 = params;
  double const *q1 = params + PW85_DIM;
  double const *q2 = q1 + PW85_SYM;
  double value = 0.0;
  if (!core::valid_f_input(lambda, r12, q1, q2) ||
      !core::f_compensated(lambda, r12, q1, q2, &value))
    return NAN;
  return -value;
}

void pw85__residual(double lambda, double const r12[PW85_DIM],
                    double const q1[PW85_SYM], double const q2[PW85_SYM],
                    double out[3]) noexcept {
  core::residual(lambda, r12, q1, q2, out);
}

int pw85_contact_function(double const r12[PW85_DIM], double const q1[PW85_SYM],
                          double const q2[PW85_SYM], double out[2]) noexcept {
  Status const status = core::check_pointers_and_finite(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(core::contact_function(r12, q1, q2, out));
}

int pw85_overlap(double const r12[PW85_DIM], double const q1[PW85_SYM],
                 double const q2[PW85_SYM], int *result) noexcept {
  Status const status = core::check_pointers_and_finite(r12, q1, q2, result);
  if (status != Status::success) return to_code(status);
  return to_code(core::overlap(r12, q1, q2, result));
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

int pw85_contact_geometry(double const r12[PW85_DIM],
                          double const q1[PW85_SYM], double const q2[PW85_SYM],
                          double out[PW85_GEOM_SIZE]) noexcept {
  Status const status = core::check_pointers_and_finite(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(core::contact_geometry(r12, q1, q2, out, nullptr));
}

int pw85_contact_derivatives(double const r12[PW85_DIM],
                             double const q1[PW85_SYM],
                             double const q2[PW85_SYM],
                             double geometry[PW85_GEOM_SIZE],
                             double d[PW85_DERIV_SIZE]) noexcept {
  Status status = core::check_pointers_and_finite(r12, q1, q2, geometry);
  if (status == Status::success && d == nullptr) status = Status::null_pointer;
  if (status != Status::success) return to_code(status);
  return to_code(core::contact_geometry(r12, q1, q2, geometry, d));
}

}  // extern "C"
