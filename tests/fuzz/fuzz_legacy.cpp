// SPDX-License-Identifier: BSD-3-Clause
// fuzz-legacy: pw85_legacy_contact_function1/2, pw85_legacy_f1/f2 and the
// polynomial helpers against their documented contracts
// (include/pw85/pw85_legacy.h), and against pw85_contact_function where
// the header ties them to it.
//
// Layout: mode byte (bits 0-2: λ; bit 3: forms from pw85_spheroid), the
// raw λ, then 15 doubles (r12, q1, q2; or r12 and a, c, n per form).
#define PW85_LEGACY_DEPRECATED(msg)
#include <pw85/pw85_legacy.h>

#include "fuzz_common.h"

namespace {

bool is_legacy_status(int s) {
  return s == PW85_SUCCESS || s == PW85_EDOM || s == PW85_ENOTPOSDEF ||
         s == PW85_ERANGE || s == PW85_ENOCONV;
}

void check_f(double lambda, const double *r, const double *q1,
             const double *q2, bool finite_in) {
  double o1[3], o2[1];
  double const f1 = pw85_legacy_f1(lambda, r, q1, q2, o1);
  double const f1n = pw85_legacy_f1(lambda, r, q1, q2, nullptr);
  CHECK(fuzz::same_bits(f1, f1n) || (std::isnan(f1) && std::isnan(f1n)),
        "f1 %a, with out NULL %a", f1, f1n);
  if (std::isnan(f1))
    CHECK(std::isnan(o1[0]) && std::isnan(o1[1]) && std::isnan(o1[2]),
          "f1 NaN, out {%a, %a, %a}", o1[0], o1[1], o1[2]);
  else
    CHECK(fuzz::same_bits(o1[0], f1), "f1 %a, out[0] %a", f1, o1[0]);
  if (!finite_in) CHECK(std::isnan(f1), "non-finite input, f1 = %a", f1);
  if (lambda >= 0 && lambda <= 1)
    CHECK(!(f1 < 0), "f1(%a) = %a < 0", lambda, f1);

  double const f2 = pw85_legacy_f2(lambda, r, q1, q2, o2);
  if (std::isnan(f2))
    CHECK(std::isnan(o2[0]), "f2 NaN, out %a", o2[0]);
  else
    CHECK(fuzz::same_bits(o2[0], f2), "f2 %a, out[0] %a", f2, o2[0]);
  if (!finite_in) CHECK(std::isnan(f2), "non-finite input, f2 = %a", f2);
}

void check_poly(const double *r, const double *q1, const double *q2) {
  double q3[6], q4[6];
  for (int i = 0; i < 6; ++i) {
    q3[i] = 2 * q1[i] - q2[i];
    q4[i] = (q1[i] + q2[i]) / 2;
  }
  double const d1 = pw85_legacy__det_sym(q1);
  if (!fuzz::all_finite(q1, 6))
    CHECK(!std::isfinite(d1), "det of a non-finite matrix = %a", d1);
  double b[4];
  pw85_legacy__detQ_as_poly(q1, q2, q3, q4, b);
  CHECK(fuzz::same_bits(b[0], d1) || (std::isnan(b[0]) && std::isnan(d1)),
        "b[0] = %a, det(Q1) = %a", b[0], d1);
  double a[3], a_old[3];
  pw85_legacy__rT_adjQ_r_as_poly(r, q1, q2, q3, a);
  pw85__rT_adjQ_r_as_poly(r, q1, q2, q3, a_old);
  CHECK(std::memcmp(a, a_old, sizeof a) == 0, "deprecated spelling differs");
  double const x = pw85_legacy__xT_adjA_x(r, q1);
  CHECK(fuzz::same_bits(a[0], x) || (std::isnan(a[0]) && std::isnan(x)),
        "a[0] = %a, rT adj(Q1) r = %a", a[0], x);
}

void check_contact(const double *r, const double *q1, const double *q2) {
  double ref[2];
  int const st = pw85_contact_function(r, q1, q2, ref);
  bool const zero = r[0] == 0 && r[1] == 0 && r[2] == 0;
  bool const well =
      fuzz::cond_bound(q1) < 1e8L && fuzz::cond_bound(q2) < 1e8L;
  for (int which = 1; which <= 2; ++which) {
    double out[2];
    fuzz::fill_sentinel(out, sizeof out);
    int const s = which == 1 ? pw85_legacy_contact_function1(r, q1, q2, out)
                             : pw85_legacy_contact_function2(r, q1, q2, out);
    bool const untouched = fuzz::is_sentinel(out, sizeof out);
    CHECK(is_legacy_status(s), "legacy %d: status %d", which, s);
    // The input contract is pw85_contact_function's.
    if (st == PW85_EDOM || s == PW85_EDOM)
      CHECK(s == st, "legacy %d: status %d, pw85 %d", which, s, st);
    if (s == PW85_ENOTPOSDEF)
      CHECK(st == PW85_ENOTPOSDEF, "legacy %d: ENOTPOSDEF, pw85 %d", which,
            st);
    if (st == PW85_ENOTPOSDEF)
      CHECK(s == PW85_ENOTPOSDEF || (s == PW85_ERANGE && untouched),
            "legacy %d: status %d, pw85 ENOTPOSDEF", which, s);
    if (s == PW85_EDOM || s == PW85_ENOTPOSDEF)
      CHECK(untouched, "legacy %d: out written on %d", which, s);
    if (s == PW85_ERANGE && !untouched)
      CHECK(out[0] == INFINITY && out[1] >= 0 && out[1] <= 1,
            "legacy %d: ERANGE, out {%a, %a}", which, out[0], out[1]);
    if (s == PW85_SUCCESS || s == PW85_ENOCONV) {
      CHECK(std::isfinite(out[0]) && out[0] >= 0 && out[1] >= 0 &&
                out[1] <= 1,
            "legacy %d: status %d, out {%a, %a}", which, s, out[0], out[1]);
      if (zero)
        CHECK(s == PW85_SUCCESS && out[0] == 0 && out[1] == 0.5,
              "legacy %d: r12 = 0, status %d, out {%a, %a}", which, s,
              out[0], out[1]);
    }
    if (which == 2 && s == PW85_ENOCONV)
      CHECK(out[0] == 0, "legacy 2: ENOCONV, out[0] = %a", out[0]);
    // Method 1 returns f at an iterate: at most mu2 (f1 has relative error
    // about cond·ε; 1e-6 is far above it for cond < 1e8).
    if (which == 1 && (s == PW85_SUCCESS || s == PW85_ENOCONV) &&
        st == PW85_SUCCESS && well)
      CHECK(out[0] <= ref[0] * (1 + 1e-6) + 1e-300,
            "legacy 1: status %d, out[0] = %a > mu2 = %a", s, out[0], ref[0]);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  unsigned const mode = in.u8();
  double lambda = in.f64();
  switch (mode & 7) {
    case 0: break;
    case 1: lambda = in.u16() / 65535.0; break;
    case 2: lambda = 0; break;
    case 3: lambda = 1; break;
    default: lambda = 0.5; break;
  }
  double p[15];
  for (double &v : p) v = in.f64();
  if (mode & 8) {
    double q1[6], q2[6];
    pw85_spheroid(p[3], p[4], p + 5, q1);
    pw85_spheroid(p[9], p[10], p + 11, q2);
    std::memcpy(p + 3, q1, sizeof q1);
    std::memcpy(p + 9, q2, sizeof q2);
  }
  bool const finite_in = std::isfinite(lambda) && fuzz::all_finite(p, 15);
  check_f(lambda, p, p + 3, p + 9, finite_in);
  check_poly(p, p + 3, p + 9);
  check_contact(p, p + 3, p + 9);
  return 0;
}

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
  double const r[3] = {1, 0, 0}, q[6] = {1, 0, 0, 1, 0, 1};
  double out[3];
  CHECK(std::isnan(pw85_legacy_f1(0.5, nullptr, q, q, out)) &&
            std::isnan(out[0]),
        "f1(NULL)");
  CHECK(std::isnan(pw85_legacy_f2(0.5, r, nullptr, q, out)), "f2(NULL)");
  fuzz::fill_sentinel(out, sizeof out);
  CHECK(pw85_legacy_contact_function1(r, q, nullptr, out) == PW85_EFAULT &&
            pw85_legacy_contact_function2(nullptr, q, q, out) == PW85_EFAULT &&
            fuzz::is_sentinel(out, sizeof out),
        "legacy EFAULT");
  return 0;
}
