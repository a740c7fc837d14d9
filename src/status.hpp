// SPDX-License-Identifier: BSD-3-Clause
// The core's own status (private). The facades (pw85.cpp,
// pw85_index.cpp, legacy/pw85_legacy.cpp, through facade.hpp's to_code())
// map it to the PW85_* codes of the public headers, so that no core file
// includes a public header.
#ifndef PW85_SRC_STATUS_HPP
#define PW85_SRC_STATUS_HPP

namespace pw85::detail {

enum class Status {
  success,
  null_pointer,           // PW85_EFAULT
  not_finite,             // PW85_EDOM
  not_positive_definite,  // PW85_ENOTPOSDEF
  out_of_range,           // PW85_ERANGE
  no_memory,              // PW85_ENOMEM
  no_convergence,         // PW85_ENOCONV (legacy contact functions)
  invalid_argument,       // PW85_EINVAL
  cancelled,              // PW85_ECANCELLED (a caller's function said stop)
};

}  // namespace pw85::detail

#endif  // PW85_SRC_STATUS_HPP
