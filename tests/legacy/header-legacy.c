/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_legacy.h compiles on its own (as C here, and as C++ through
 * header-legacy.cpp), with every warning an error. */
#include <pw85_legacy.h>

int main(void) {
  double const r[PW85_DIM] = {1., 0., 0.};
  double const q[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double out[2];
  int const status = pw85_legacy_contact_function2(r, q, q, out);
  return status == PW85_SUCCESS && pw85_legacy__det_sym(q) == 1. ? 0 : 1;
}
