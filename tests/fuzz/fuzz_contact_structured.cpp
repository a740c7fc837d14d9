// SPDX-License-Identifier: BSD-3-Clause
// fuzz-contact-structured: bytes decoded into two triaxial ellipsoids
// (semi-axes m·2^e, e up to ±60, rotations from quaternions) and a
// centre-to-centre vector near tangency, r12 = (1 + s·2^-j)·u/μ(u), so that
// valid inputs dominate and the overlap test is exercised where it is
// hardest; the oracle is fuzz::check_contact.
//
// Layout (missing bytes read as 0): flags, scale, then per ellipsoid 3 ×
// (exponent byte, mantissa byte) and a quaternion (4 × int16), then the
// direction u (3 × int16), j, s, and the exponent k of the scaling relation.
#include "fuzz_common.h"

namespace {

void form(fuzz::Bytes &in, bool wide, int scale, double q[6]) {
  double a[3];
  for (double &ai : a) {
    int const e8 = int8_t(in.u8());
    int e = wide ? e8 / 2 : e8 / 16;  // ±60 (wide) or ±8: aspect ratios
    if (e > 60) e = 60;
    if (e < -60) e = -60;
    ai = std::ldexp(1 + in.u8() / 256.0, scale + e);
  }
  double w = in.i16(), x = in.i16(), y = in.i16(), z = in.i16();
  double const n = std::sqrt(w * w + x * x + y * y + z * z);
  if (n == 0) {
    w = 1;
  } else {
    w /= n, x /= n, y /= n, z /= n;
  }
  double const R[3][3] = {
      {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  // Q = R·diag(a²)·Rᵀ, upper triangle row by row.
  int idx = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j) {
      double s = 0;
      for (int m = 0; m < 3; ++m) s += R[i][m] * R[j][m] * a[m] * a[m];
      q[idx++] = s;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  unsigned const flags = in.u8();
  int const scale = int(in.u8() % 121) - 60;
  double q1[6], q2[6];
  form(in, flags & 1, scale, q1);
  form(in, flags & 2, scale, q2);
  double u[3] = {double(in.i16()), double(in.i16()), double(in.i16())};
  double const nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  if (nu == 0) {
    u[0] = 1;
  } else {
    for (double &c : u) c /= nu;
  }
  int const j = in.u8() % 64;
  int const s = int(in.u8() % 3) - 1;
  int const k = int(in.u8() % 41) - 20;
  double r12[3];
  double out[2];
  double const t = std::ldexp(1.0, scale);
  if (pw85_contact_function(u, q1, q2, out) == PW85_SUCCESS && out[0] > 0 &&
      std::isfinite(out[0])) {
    double const d = (1 + s * std::ldexp(1.0, -j)) / std::sqrt(out[0]);
    for (int i = 0; i < 3; ++i) r12[i] = u[i] * d;
  } else {
    for (int i = 0; i < 3; ++i) r12[i] = u[i] * t;
  }
  fuzz::check_contact<3>(r12, q1, q2, k);
  return 0;
}
