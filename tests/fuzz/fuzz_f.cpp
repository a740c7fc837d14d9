// SPDX-License-Identifier: BSD-3-Clause
// fuzz-f: pw85_f_neg, pw85__residual, pw85__cholesky_decomp,
// pw85__cholesky_solve and pw85_spheroid against their documented
// contracts (include/pw85/pw85.h).
//
// Layout: mode byte (bits 0-2: λ; bit 3: forms from pw85_spheroid), the
// raw λ, then 15 doubles (r12, q1, q2; or, in spheroid mode, r12 and
// a, c, n for each form).
#include "fuzz_common.h"

namespace {

const double eps = DBL_EPSILON;

bool in_range(double x, double lo, double hi) {
  return x == 0 || (std::fabs(x) >= lo && std::fabs(x) <= hi);
}

// The documented range of pw85_f_neg, with a margin: |r12|² and the
// entries of Q1, Q2 between 1e-140 and 1e140.
bool f_range(const double p[15]) {
  long double const rr = (long double)p[0] * p[0] +
                         (long double)p[1] * p[1] + (long double)p[2] * p[2];
  if (rr != 0 && (rr < 1e-140L || rr > 1e140L)) return false;
  for (int i = 3; i < 15; ++i)
    if (!in_range(p[i], 1e-140, 1e140)) return false;
  return true;
}

void check_cholesky(const double a[6], const double b[3]) {
  double l[6];
  pw85__cholesky_decomp(a, l);
  int nan = 0;
  for (double v : l) nan += std::isnan(v);
  CHECK(nan == 0 || nan == 6, "%d NaN entries in L", nan);
  if (!fuzz::all_finite(a, 6) || !(a[0] > 0 && a[3] > 0 && a[5] > 0))
    CHECK(nan == 6, "L of a form with a bad diagonal or entry");
  if (nan) return;
  CHECK(fuzz::all_finite(l, 6) && l[0] > 0 && l[3] > 0 && l[5] > 0,
        "L = {%a, %a, %a, %a, %a, %a}", l[0], l[1], l[2], l[3], l[4], l[5]);
  // Backward stability, where no product overflows or underflows.
  bool range = true;
  for (int i = 0; i < 6; ++i) range = range && in_range(a[i], 1e-100, 1e100);
  if (range) {
    // L (lower, column by column) as a dense matrix.
    double const L[3][3] = {
        {l[0], 0, 0}, {l[1], l[3], 0}, {l[2], l[4], l[5]}};
    int idx = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j, ++idx) {
        long double s = 0, abs = 0;
        for (int m = 0; m < 3; ++m) {
          s += (long double)L[i][m] * L[j][m];
          abs += std::fabs((long double)L[i][m] * L[j][m]);
        }
        CHECK(std::fabs(s - a[idx]) <= 32 * eps * abs,
              "L·Lᵀ[%d][%d] = %La, A = %a", i, j, s, a[idx]);
      }
  }
  // Solving in place (x aliasing b) gives the same bits.
  double x[3], y[3] = {b[0], b[1], b[2]};
  pw85__cholesky_solve(l, b, x);
  pw85__cholesky_solve(l, y, y);
  CHECK(std::memcmp(x, y, sizeof x) == 0, "in-place solve differs");
}

void check_spheroid(double a, double c, const double n0[3]) {
  double q[6];
  pw85_spheroid(a, c, n0, nullptr);  // must not crash
  pw85_spheroid(a, c, nullptr, q);
  for (double v : q) CHECK(std::isnan(v), "n = NULL: entry %a", v);
  pw85_spheroid(a, c, n0, q);
  bool const finite_in = std::isfinite(a) && std::isfinite(c) &&
                         fuzz::all_finite(n0, 3);
  if (!finite_in) {
    CHECK(!fuzz::all_finite(q, 6), "non-finite input, finite Q");
    return;
  }
  // n as an eigenvector of eigenvalue c² (n normalised first).
  if (!in_range(a, 1e-100, 1e100) || !in_range(c, 1e-100, 1e100)) return;
  long double nn = 0;
  for (int i = 0; i < 3; ++i) nn += (long double)n0[i] * n0[i];
  if (!(nn >= 1e-200L && nn <= 1e200L)) return;
  double n[3];
  for (int i = 0; i < 3; ++i) n[i] = double(n0[i] / std::sqrt(nn));
  pw85_spheroid(a, c, n, q);
  double const Q[3][3] = {
      {q[0], q[1], q[2]}, {q[1], q[3], q[4]}, {q[2], q[4], q[5]}};
  double const big = std::fmax(a * a, c * c);
  for (int i = 0; i < 3; ++i) {
    long double s = 0;
    for (int j = 0; j < 3; ++j) s += (long double)Q[i][j] * n[j];
    CHECK(std::fabs(s - (long double)c * c * n[i]) <= 16 * eps * big,
          "(Q·n)[%d] = %La, c²·n = %a", i, s, c * c * n[i]);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  unsigned const mode = in.u8();
  double lambda = in.f64();
  switch (mode & 7) {
    case 0: break;  // raw
    case 1: lambda = in.u16() / 65535.0; break;
    case 2: lambda = 0; break;
    case 3: lambda = 1; break;
    case 4: lambda = 0.5; break;
    default: lambda = 0.5 + in.u16() / 131070.0; break;  // [1/2, 1]
  }
  double p[15];
  for (double &v : p) v = in.f64();
  if (mode & 8) {
    // p[3..8] and p[9..14] hold a, c, n of each form: build spheroids.
    double q1[6], q2[6];
    check_spheroid(p[3], p[4], p + 5);
    check_spheroid(p[9], p[10], p + 11);
    pw85_spheroid(p[3], p[4], p + 5, q1);
    pw85_spheroid(p[9], p[10], p + 11, q2);
    std::memcpy(p + 3, q1, sizeof q1);
    std::memcpy(p + 9, q2, sizeof q2);
  } else {
    check_spheroid(p[0], p[1], p + 2);
  }
  check_cholesky(p + 3, p);
  check_cholesky(p + 9, p);

  double const fneg = pw85_f_neg(lambda, p);
  bool const finite_in = std::isfinite(lambda) && fuzz::all_finite(p, 15);
  if (!finite_in) CHECK(std::isnan(fneg), "non-finite input: %a", fneg);
  bool const unit = lambda >= 0 && lambda <= 1;
  if (unit) CHECK(!(fneg > 0), "-f(%a) = %a > 0", lambda, fneg);
  if (lambda == 0 || lambda == 1)
    CHECK(fneg == 0 || std::isnan(fneg), "-f(%a) = %a", lambda, fneg);
  if (std::isnan(fneg) || !unit || !f_range(p)) return 0;

  // Q(λ) and a bound of its condition number.
  double ql[6];
  for (int i = 0; i < 6; ++i) ql[i] = (1 - lambda) * p[3 + i] + lambda * p[9 + i];
  long double const cq = fuzz::cond_bound(ql);
  if (!(cq < 1e8L)) return 0;

  // The residual: finite, and its f agrees with pw85_f_neg, where no
  // intermediate (g and g′ are quartic in 1/Q) overflows: every entry
  // between 1e-30 and 1e30.
  bool small = true;
  for (int i = 0; i < 15; ++i) small = small && in_range(p[i], 1e-30, 1e30);
  if (small) {
    double out[3];
    pw85__residual(lambda, p, p + 3, p + 9, out);
    // g and g′ may overflow (no range is promised): f only.
    CHECK(std::isfinite(out[0]), "residual {%a, %a, %a}", out[0], out[1],
          out[2]);
    CHECK(std::fabs(out[0] + fneg) <=
              64 * eps * (double)cq * std::fabs(fneg) + 1e-300,
          "residual f = %a, f_neg = %a", out[0], fneg);
  }

  // Swapping: f(λ; r, Q1, Q2) = f(1 - λ; -r, Q2, Q1), 1 - λ exact on [½, 1].
  if (lambda >= 0.5) {
    double s[15] = {-p[0], -p[1], -p[2]};
    std::memcpy(s + 3, p + 9, 6 * sizeof(double));
    std::memcpy(s + 9, p + 3, 6 * sizeof(double));
    double const g = pw85_f_neg(1 - lambda, s);
    CHECK(std::fabs(g - fneg) <= 4 * eps * std::fabs(fneg) + 4 * DBL_TRUE_MIN,
          "-f(%a) = %a, swapped %a", lambda, fneg, g);
  }
  return 0;
}

extern "C" int LLVMFuzzerInitialize(int *, char ***) {
  double const l = 0.5;
  CHECK(std::isnan(pw85_f_neg(l, nullptr)), "f_neg(NULL)");
  return 0;
}
