// SPDX-License-Identifier: BSD-3-Clause
// fuzz-geometry: any 15 doubles (r12, q1, q2, raw bytes, zero-padded: the
// layout of fuzz-contact-raw, whose corpus it starts from) through
// pw85_contact_geometry and pw85_contact_derivatives, and the first 7
// (semi-axes, quaternion) and the first 12 (semi-axes, rotation) through
// the constructors and pw85_principal_axes. Oracles: those of
// fuzz::check_geometry (geometry_oracle.cpp) for the pair; the
// constructors' statuses, and a positive, sorted set of semi-axes from
// every Q they build that is positive definite.
#include "fuzz_common.h"

namespace {

bool is_constructor_status(int st) {
  return st == PW85_SUCCESS || st == PW85_EDOM || st == PW85_EINVAL ||
         st == PW85_ERANGE;
}

void check_axes_of(const double q[6]) {
  double a[3], rot[9];
  fuzz::fill_sentinel(a, sizeof a);
  int const st = pw85_principal_axes(q, a, rot);
  // ERANGE (pw85.h): a form positive definite but singular to double
  // precision (its factorisation in double fails: cond near 1/ε or
  // beyond; cond_bound() overestimates cond by up to 9), or cond above
  // about 1e270.
  CHECK(st == PW85_SUCCESS || st == PW85_ENOTPOSDEF || st == PW85_EDOM ||
            (st == PW85_ERANGE && fuzz::cond_bound(q) > 1e15),
        "principal axes %d, cond bound %Lg", st, fuzz::cond_bound(q));
  if (st != PW85_SUCCESS) {
    CHECK(fuzz::is_sentinel(a, sizeof a), "status %d wrote a", st);
    return;
  }
  CHECK(a[0] >= a[1] && a[1] >= a[2] && a[2] > 0.0 &&
            fuzz::all_finite(a, 3) && fuzz::all_finite(rot, 9),
        "a = %a %a %a", a[0], a[1], a[2]);
}

void check_constructors(const double x[15]) {
  double q[6];
  fuzz::fill_sentinel(q, sizeof q);
  int st = pw85_ellipsoid_quaternion(x, x + 3, q);
  CHECK(is_constructor_status(st), "quaternion %d", st);
  if (st != PW85_SUCCESS)
    CHECK(fuzz::is_sentinel(q, sizeof q), "status %d wrote q", st);
  else
    CHECK(fuzz::all_finite(q, 6), "quaternion: q not finite");
  check_axes_of(st == PW85_SUCCESS ? q : x + 3);
  fuzz::fill_sentinel(q, sizeof q);
  st = pw85_ellipsoid_rotation(x, x + 3, q);
  CHECK(is_constructor_status(st), "rotation %d", st);
  if (st != PW85_SUCCESS)
    CHECK(fuzz::is_sentinel(q, sizeof q), "status %d wrote q", st);
  else
    CHECK(fuzz::all_finite(q, 6), "rotation: q not finite");
  if (st == PW85_SUCCESS) check_axes_of(q);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  double x[15];
  for (double &v : x) v = in.f64();
  fuzz::check_geometry<3>(x, x + 3, x + 9);
  check_constructors(x);
  return 0;
}
