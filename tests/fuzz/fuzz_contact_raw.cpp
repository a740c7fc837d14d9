// SPDX-License-Identifier: BSD-3-Clause
// fuzz-contact-raw: any 15 doubles (r12, q1, q2, raw bytes, zero-padded)
// and one byte for the scaling exponent, through pw85_contact_function and
// pw85_overlap; the oracle is fuzz::check_contact<3>.
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  double x[15];
  for (double &v : x) v = in.f64();
  int const k = int(in.u8() % 41) - 20;
  fuzz::check_contact<3>(x, x + 3, x + 9, k);
  return 0;
}

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
  // NULL pointers, once: PW85_EFAULT, outputs untouched.
  double const r[3] = {1, 0, 0}, q[6] = {1, 0, 0, 1, 0, 1};
  double out[2];
  int res;
  fuzz::fill_sentinel(out, sizeof out);
  fuzz::fill_sentinel(&res, sizeof res);
  CHECK(pw85_contact_function(nullptr, q, q, out) == PW85_EFAULT, "r12");
  CHECK(pw85_contact_function(r, nullptr, q, out) == PW85_EFAULT, "q1");
  CHECK(pw85_contact_function(r, q, nullptr, out) == PW85_EFAULT, "q2");
  CHECK(pw85_contact_function(r, q, q, nullptr) == PW85_EFAULT, "out");
  CHECK(pw85_overlap(nullptr, q, q, &res) == PW85_EFAULT, "r12");
  CHECK(pw85_overlap(r, q, q, nullptr) == PW85_EFAULT, "result");
  CHECK(fuzz::is_sentinel(out, sizeof out) &&
            fuzz::is_sentinel(&res, sizeof res),
        "outputs written on EFAULT");
  return 0;
}
