// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of libpw85_legacy: check arguments, call the core,
// map to a status.
#include "pw85_legacy.h"

#include <cmath>

#include "checks.hpp"
#include "facade.hpp"
#include "legacy.hpp"
#include "status.hpp"

namespace {

namespace core = pw85::detail;
namespace legacy = pw85::legacy::detail;
using core::Status;

using pw85::facade::to_code;

}  // namespace

extern "C" {

double pw85_legacy__det_sym(double const a[PW85_SYM]) noexcept {
  return legacy::det_sym(a);
}

double pw85_legacy__xT_adjA_x(double const x[PW85_DIM],
                              double const a[PW85_SYM]) noexcept {
  return legacy::xT_adjA_x(x, a);
}

void pw85_legacy__detQ_as_poly(double const q1[PW85_SYM],
                               double const q2[PW85_SYM],
                               double const q3[PW85_SYM],
                               double const q4[PW85_SYM],
                               double b[PW85_DIM + 1]) noexcept {
  legacy::detQ_as_poly(q1, q2, q3, q4, b);
}

void pw85_legacy__rT_adjQ_r_as_poly(double const r[PW85_DIM],
                                    double const q1[PW85_SYM],
                                    double const q2[PW85_SYM],
                                    double const q3[PW85_SYM],
                                    double a[PW85_DIM]) noexcept {
  legacy::rT_adjQ_r_as_poly(r, q1, q2, q3, a);
}

// The original spelling (docs/legacy-api.rst), kept so that code written from it links.
void pw85__rT_adjQ_r_as_poly(double const r[PW85_DIM],
                             double const q1[PW85_SYM],
                             double const q2[PW85_SYM],
                             double const q3[PW85_SYM],
                             double a[PW85_DIM]) noexcept {
  legacy::rT_adjQ_r_as_poly(r, q1, q2, q3, a);
}

double pw85_legacy_f1(double lambda, double const r12[PW85_DIM],
                      double const q1[PW85_SYM], double const q2[PW85_SYM],
                      double *out) noexcept {
  double f = NAN;
  if (!core::valid_f_input(lambda, r12, q1, q2) ||
      !core::is_positive_definite(q1) || !core::is_positive_definite(q2) ||
      !legacy::f1(lambda, r12, q1, q2, &f, out) || std::isnan(f)) {
    if (out != nullptr) out[0] = out[1] = out[2] = NAN;
    return NAN;
  }
  return f;
}

double pw85_legacy_f2(double lambda, double const r12[PW85_DIM],
                      double const q1[PW85_SYM], double const q2[PW85_SYM],
                      double *out) noexcept {
  double f = NAN;
  if (core::valid_f_input(lambda, r12, q1, q2) &&
      core::is_positive_definite(q1) && core::is_positive_definite(q2) &&
      legacy::q_positive_definite(lambda, q1, q2))
    f = legacy::f2(lambda, r12, q1, q2);
  if (out != nullptr) out[0] = f;
  return f;
}

int pw85_legacy_contact_function1(double const r12[PW85_DIM],
                                  double const q1[PW85_SYM],
                                  double const q2[PW85_SYM],
                                  double out[2]) noexcept {
  Status const status = core::check_input(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(legacy::contact_function1(r12, q1, q2, out));
}

int pw85_legacy_contact_function2(double const r12[PW85_DIM],
                                  double const q1[PW85_SYM],
                                  double const q2[PW85_SYM],
                                  double out[2]) noexcept {
  Status const status = core::check_input(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(legacy::contact_function2(r12, q1, q2, out));
}

}  // extern "C"
