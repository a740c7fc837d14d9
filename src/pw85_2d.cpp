// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the two-dimensional functions
// (include/pw85/pw85_2d.h): check arguments, call the core (the same
// templates as pw85.cpp, with D = 2), map statuses.
#include "pw85_2d.h"

#include <cmath>

#include "checks.hpp"
#include "contact.hpp"
#include "ellipsoid.hpp"
#include "f.hpp"
#include "facade.hpp"
#include "geometry.hpp"
#include "overlap.hpp"
#include "status.hpp"

namespace {

namespace core = pw85::detail;
using core::Status;
using pw85::facade::to_code;

constexpr int D = 2;
static_assert(PW85_2D_DIM == D && PW85_2D_SYM == core::sym_size(D),
              "pw85_2d.h and the core disagree on sizes");

using Out = core::Outputs<D>;
static_assert(PW85_2D_GEOM_MU2 == Out::mu2 &&
                  PW85_2D_GEOM_LAMBDA == Out::lambda &&
                  PW85_2D_GEOM_POINT == Out::point &&
                  PW85_2D_GEOM_NORMAL == Out::normal &&
                  PW85_2D_GEOM_SIZE == Out::size &&
                  PW85_2D_DERIV_R12 == Out::r12 &&
                  PW85_2D_DERIV_THETA1 == Out::rot1 &&
                  PW85_2D_DERIV_THETA2 == Out::rot2 &&
                  PW85_2D_DERIV_Q1 == Out::q1 && PW85_2D_DERIV_Q2 == Out::q2 &&
                  PW85_2D_DERIV_SIZE == Out::deriv_size,
              "pw85_2d.h and the core disagree on the layouts of the outputs");

// with_d: pw85_2d_contact_derivatives() (d must not be NULL; a NULL d is
// reported after the inputs' checks, as pw85_contact_derivatives() does).
int geometry_one(double const *r12, double const *q1, double const *q2,
                 double *geometry, double *d, bool with_d) noexcept {
  Status status = core::check_pointers_and_finite<D>(r12, q1, q2, geometry);
  if (status == Status::success && with_d && d == nullptr)
    status = Status::null_pointer;
  if (status != Status::success) return to_code(status);
  return to_code(core::contact_geometry<D>(r12, q1, q2, geometry, d));
}

}  // namespace

extern "C" {

double pw85_2d_f_neg(double lambda,
                     double const params[PW85_2D_DIM + 2 * PW85_2D_SYM]) noexcept {
  if (params == nullptr) return NAN;
  double const *r12 = params;
  double const *q1 = params + PW85_2D_DIM;
  double const *q2 = q1 + PW85_2D_SYM;
  double value = 0.0;
  if (!core::valid_f_input<D>(lambda, r12, q1, q2) ||
      !core::is_positive_definite<D>(q1) || !core::is_positive_definite<D>(q2) ||
      !core::f_compensated<D>(lambda, r12, q1, q2, &value))
    return NAN;
  return -value;
}

int pw85_2d_contact_function(double const r12[PW85_2D_DIM],
                             double const q1[PW85_2D_SYM],
                             double const q2[PW85_2D_SYM],
                             double out[2]) noexcept {
  Status const status = core::check_pointers_and_finite<D>(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(core::contact_function<D>(r12, q1, q2, out));
}

int pw85_2d_overlap(double const r12[PW85_2D_DIM], double const q1[PW85_2D_SYM],
                    double const q2[PW85_2D_SYM], int *result) noexcept {
  Status const status = core::check_pointers_and_finite<D>(r12, q1, q2, result);
  if (status != Status::success) return to_code(status);
  return to_code(core::overlap<D>(r12, q1, q2, result));
}

int pw85_2d_contact_geometry(double const r12[PW85_2D_DIM],
                             double const q1[PW85_2D_SYM],
                             double const q2[PW85_2D_SYM],
                             double out[PW85_2D_GEOM_SIZE]) noexcept {
  return geometry_one(r12, q1, q2, out, nullptr, false);
}

int pw85_2d_contact_derivatives(double const r12[PW85_2D_DIM],
                                double const q1[PW85_2D_SYM],
                                double const q2[PW85_2D_SYM],
                                double geometry[PW85_2D_GEOM_SIZE],
                                double d[PW85_2D_DERIV_SIZE]) noexcept {
  return geometry_one(r12, q1, q2, geometry, d, true);
}

int pw85_2d_ellipse(double const a[PW85_2D_DIM], double theta,
                    double q[PW85_2D_SYM]) noexcept {
  if (a == nullptr || q == nullptr) return PW85_EFAULT;
  return to_code(core::ellipse_angle(a, theta, q));
}

int pw85_2d_principal_axes(double const q[PW85_2D_SYM], double a[PW85_2D_DIM],
                           double *theta) noexcept {
  if (q == nullptr || a == nullptr || theta == nullptr) return PW85_EFAULT;
  return to_code(core::ellipse_principal_axes(q, a, theta));
}

}  // extern "C"
