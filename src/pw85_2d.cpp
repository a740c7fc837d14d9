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
#include "overlap.hpp"
#include "status.hpp"

namespace {

namespace core = pw85::detail;
using core::Status;
using pw85::facade::to_code;

constexpr int D = 2;
static_assert(PW85_2D_DIM == D && PW85_2D_SYM == core::sym_size(D),
              "pw85_2d.h and the core disagree on sizes");

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
