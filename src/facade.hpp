// SPDX-License-Identifier: BSD-3-Clause
// What the two facades (pw85.cpp, legacy/pw85_legacy.cpp) share: the map
// from the core's status to the PW85_* codes of pw85.h. Included by the
// facades only (private).
#ifndef PW85_SRC_FACADE_HPP
#define PW85_SRC_FACADE_HPP

#include "pw85.h"
#include "status.hpp"

namespace pw85::facade {

inline int to_code(pw85::detail::Status status) noexcept {
  using pw85::detail::Status;
  switch (status) {
    case Status::success:
      return PW85_SUCCESS;
    case Status::null_pointer:
      return PW85_EFAULT;
    case Status::not_finite:
      return PW85_EDOM;
    case Status::not_positive_definite:
      return PW85_ENOTPOSDEF;
    case Status::out_of_range:
      return PW85_ERANGE;
    case Status::no_memory:
      return PW85_ENOMEM;
    case Status::no_convergence:
      return PW85_ENOCONV;
    case Status::invalid_argument:
      return PW85_EINVAL;
  }
  return PW85_ENOMEM;  // not reached: every Status is mapped above
}

}  // namespace pw85::facade

#endif  // PW85_SRC_FACADE_HPP
