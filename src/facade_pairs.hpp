// SPDX-License-Identifier: BSD-3-Clause
// The single-pair entry points shared by the facades of both dimensions
// (pw85.cpp with D = 3, pw85_2d.cpp with D = 2; private): check the
// arguments, call the core, map to PW85_*. Also used by their batches
// (an exported function called inside the library would go through the
// PLT).
#ifndef PW85_SRC_FACADE_PAIRS_HPP
#define PW85_SRC_FACADE_PAIRS_HPP

#include <cmath>

#include "checks.hpp"
#include "contact.hpp"
#include "f.hpp"
#include "facade.hpp"
#include "geometry.hpp"
#include "overlap.hpp"
#include "status.hpp"
#include "sym.hpp"

namespace pw85::facade {

template <int D>
inline int contact_function_one(double const *r12, double const *q1,
                                double const *q2, double *out) noexcept {
  using pw85::detail::Status;
  Status const status =
      pw85::detail::check_pointers_and_finite<D>(r12, q1, q2, out);
  if (status != Status::success) return to_code(status);
  return to_code(pw85::detail::contact_function<D>(r12, q1, q2, out));
}

template <int D>
inline int overlap_one(double const *r12, double const *q1, double const *q2,
                       int *result) noexcept {
  using pw85::detail::Status;
  Status const status =
      pw85::detail::check_pointers_and_finite<D>(r12, q1, q2, result);
  if (status != Status::success) return to_code(status);
  return to_code(pw85::detail::overlap<D>(r12, q1, q2, result));
}

// The contact geometry, and with_d the derivatives into d (a NULL d is
// then reported after the inputs' checks).
template <int D>
inline int geometry_one(double const *r12, double const *q1, double const *q2,
                        double *geometry, double *d, bool with_d) noexcept {
  using pw85::detail::Status;
  Status status =
      pw85::detail::check_pointers_and_finite<D>(r12, q1, q2, geometry);
  if (status == Status::success && with_d && d == nullptr)
    status = Status::null_pointer;
  if (status != Status::success) return to_code(status);
  return to_code(pw85::detail::contact_geometry<D>(r12, q1, q2, geometry, d));
}

template <int D>
inline int geometry_only(double const *r12, double const *q1,
                         double const *q2, double *geometry) noexcept {
  return geometry_one<D>(r12, q1, q2, geometry, nullptr, false);
}

template <int D>
inline int with_derivatives(double const *r12, double const *q1,
                            double const *q2, double *geometry,
                            double *d) noexcept {
  return geometry_one<D>(r12, q1, q2, geometry, d, true);
}

// −f(λ) from params = r12 (D doubles), q1, q2 (sym_size(D) each), or NaN
// (pw85_f_neg(), pw85_2d_f_neg()).
template <int D>
inline double f_neg_one(double lambda, double const *params) noexcept {
  namespace core = pw85::detail;
  if (params == nullptr) return NAN;
  double const *r12 = params;
  double const *q1 = params + D;
  double const *q2 = q1 + core::sym_size(D);
  double value = 0.0;
  if (!core::valid_f_input<D>(lambda, r12, q1, q2) ||
      !core::is_positive_definite<D>(q1) ||
      !core::is_positive_definite<D>(q2) ||
      !core::f_compensated<D>(lambda, r12, q1, q2, &value))
    return NAN;
  return -value;
}

}  // namespace pw85::facade

#endif  // PW85_SRC_FACADE_PAIRS_HPP
