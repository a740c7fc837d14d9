// SPDX-License-Identifier: BSD-3-Clause
// pw85_legacy.h compiles as C++ with every warning an error, and its
// functions are declared noexcept.
#include <pw85_legacy.h>

static_assert(noexcept(pw85_legacy_f1(0.5, nullptr, nullptr, nullptr, nullptr)),
              "the legacy ABI does not throw");

int main() {
  double const r[PW85_DIM] = {1., 0., 0.};
  double const q[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double out[2];
  int const status = pw85_legacy_contact_function1(r, q, q, out);
  return status == PW85_SUCCESS && pw85_legacy__det_sym(q) == 1. ? 0 : 1;
}
