// SPDX-License-Identifier: BSD-3-Clause
// Primitives of the core: factorisations, the spheroid, f and its
// derivatives, input validation. The search for μ² is in contact.cpp.
#include "core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

#include "dd.hpp"
#include "linalg.hpp"
#include "pw85.h"

namespace pw85::detail {

#ifdef PW85_COUNT_EVALUATIONS
thread_local unsigned long long evaluations = 0;
unsigned long long evaluation_count() noexcept { return evaluations; }
#endif

namespace {

// The exponent e with |x| = m·2^e, m in [0.5, 1), read from the bits (a
// libm call per entry would cost more than the rest of the rescaling);
// frexp for zero and subnormals. x finite.
int exponent(double x) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  int const biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased != 0) return biased - 1022;
  int e = 0;
  std::frexp(x, &e);
  return e;
}



// The smallest and largest |x| of the diagonals of q1 and q2, written out:
// -O2 leaves loops rolled, and this runs on every call.
void diagonal_range(double const q1[sym], double const q2[sym], double *lo,
                    double *hi) noexcept {
  double const a = std::fabs(q1[0]), b = std::fabs(q1[3]), c = std::fabs(q1[5]);
  double const d = std::fabs(q2[0]), e = std::fabs(q2[3]), f = std::fabs(q2[5]);
  *lo = std::min(std::min(std::min(a, b), std::min(c, d)), std::min(e, f));
  *hi = std::max(std::max(std::max(a, b), std::max(c, d)), std::max(e, f));
}

// y = x·2^k for N entries: exact unless a result leaves the normal range.
template <int N>
inline void scale_n(double const *x, int k, double *y) noexcept {
  if (k >= -1022 && k <= 1023) {
    double const factor = pow2(k);
    PW85_UNROLL
    for (int i = 0; i < N; ++i) y[i] = x[i] * factor;
  } else {
    for (int i = 0; i < N; ++i) y[i] = std::ldexp(x[i], k);
  }
}

// True when the N entries of x are finite: x − x is 0 for finite x and NaN
// for NaN and ±∞. (The additions form a chain, but nothing waits for it:
// the branch on the result is predicted.)
template <int N>
inline bool finite_n(double const *x) noexcept {
  double acc = 0.0;
  PW85_UNROLL
  for (int i = 0; i < N; ++i) acc += x[i] - x[i];
  return acc == 0.0;
}

}  // namespace

double pow2(int k) noexcept {
  if (k < -1022 || k > 1023) return std::ldexp(1.0, k);
  std::uint64_t const bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

double times_pow2(double x, int k) noexcept {
  // x·2^k is rounded once, as ldexp rounds it, when 2^k is a double.
  return k >= -1022 && k <= 1023 ? x * pow2(k) : std::ldexp(x, k);
}

bool rescale(double const r[dim], double const q1[sym], double const q2[sym],
             Scaled *s) noexcept {
  double const rmax =
      std::max(std::max(std::fabs(r[0]), std::fabs(r[1])), std::fabs(r[2]));
  s->r_is_zero = rmax == 0.0;
  int const er = exponent(rmax);
  // The exponent is monotone in |x|: those of the extreme diagonal entries
  // are the extreme exponents.
  double dmin = 0.0, dmax = 0.0;
  diagonal_range(q1, q2, &dmin, &dmax);
  int const emin = exponent(dmin);
  int const emax = exponent(dmax);
  int const eq = emin + (emax - emin) / 2;
  scale_n<dim>(r, -er, s->r);
  scale_n<sym>(q1, -eq, s->q1);
  scale_n<sym>(q2, -eq, s->q2);
  s->shift = 2 * er - eq;
  // |x| < 2^e for the exponent e of x, and |x| ≥ 2^(e−1).
  s->moderate = emax - eq <= 400 && emin - eq >= -399;
  // A diagonal entry overflows only if the diagonals span more than the
  // range of doubles (emax − eq > 1024); an off-diagonal entry cannot
  // overflow without exceeding √(Qᵢᵢ·Qⱼⱼ), which leaves the form
  // indefinite: its factorisation then fails on a non-finite pivot.
  return emax - eq <= 1024;
}

bool all_finite(double const *x, int n) noexcept {
  double acc = 0.0;  // as finite_n()
  for (int i = 0; i < n; ++i) acc += x[i] - x[i];
  return acc == 0.0;
}

bool cholesky_decomp(double const a[sym], double l[sym]) noexcept {
  // Written so that a NaN pivot fails the test as a negative one does.
  if (!(a[0] > 0.0)) return false;
  l[0] = std::sqrt(a[0]);
  l[1] = a[1] / l[0];
  l[2] = a[2] / l[0];
  double const d1 = a[3] - l[1] * l[1];
  if (!(d1 > 0.0)) return false;
  l[3] = std::sqrt(d1);
  l[4] = (a[4] - l[1] * l[2]) / l[3];
  double const d2 = a[5] - l[2] * l[2] - l[4] * l[4];
  if (!(d2 > 0.0)) return false;
  l[5] = std::sqrt(d2);
  return true;
}

void forward_solve(double const l[sym], double const b[dim],
                   double y[dim]) noexcept {
  y[0] = b[0] / l[0];
  y[1] = (b[1] - l[1] * y[0]) / l[3];
  y[2] = (b[2] - l[2] * y[0] - l[4] * y[1]) / l[5];
}

void cholesky_solve(double const l[sym], double const b[dim],
                    double x[dim]) noexcept {
  double y[dim];
  forward_solve(l, b, y);
  x[2] = y[2] / l[5];
  x[1] = (y[1] - l[4] * x[2]) / l[3];
  x[0] = (y[0] - l[1] * x[1] - l[2] * x[2]) / l[0];
}

void spheroid(double a, double c, double const n[dim], double q[sym]) noexcept {
  // In double-double: the diagonal a² + (c² − a²)·nᵢ² cancels when c ≪ a
  // and nᵢ ≈ 1 (the polar entry of a flat oblate spheroid would otherwise
  // lose up to log10(a²/c²) digits).
  dd const a2 = two_prod(a, a);
  dd const d = dd_add(two_prod(c, c), dd_neg(a2));
  for (int k = 0; k < sym; ++k) {
    dd const t = dd_mul(dd_mul(d, n[row_of[k]]), n[col_of[k]]);
    q[k] = dd_round(row_of[k] == col_of[k] ? dd_add(a2, t) : t);
  }
}

bool f(double lambda, double const r[dim], double const q1[sym],
       double const q2[sym], double *value) noexcept {
  return f_plain(lambda, r, q1, q2, false, value);
}

PW85_FMA_CLONES
bool f_accurate(double lambda, double const r[dim], double const q1[sym],
                double const q2[sym], double *value) noexcept {
  Accurate a;
  if (!accurate_terms(lambda, r, q1, q2, false, false, &a)) return false;
  *value = a.f;
  return true;
}

void residual(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double out[3]) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  if (!cholesky_decomp(q, l)) {
    out[0] = out[1] = out[2] = NAN;
    return;
  }
  double q12[sym];
  for (int i = 0; i < sym; ++i) q12[i] = q2[i] - q1[i];
  double s[dim], u[dim], v[dim];
  cholesky_solve(l, r, s);  // s = Q⁻¹·r
  sym_mul(q12, s, u);       // u = Q12·s
  cholesky_solve(l, u, v);  // v = Q⁻¹·u
  double const rs = dot(r, s);
  double const su = dot(s, u);
  double const uv = dot(u, v);
  double const w = lambda * (1.0 - lambda);
  if (!f_accurate(lambda, r, q1, q2, &out[0])) out[0] = w * rs;  // ch. 4 (4)
  out[1] = (2.0 * lambda - 1.0) * rs + w * su;                   // ch. 5 (4)
  out[2] = 2.0 * rs + 2.0 * (1.0 - 2.0 * lambda) * su - 2.0 * w * uv;  // (5)
}

bool is_positive_definite(double const q[sym]) noexcept {
  // Symmetric diagonal scaling by powers of two, D·Q·D with D = diag(2^-hᵢ)
  // and Qᵢᵢ ≈ 4^hᵢ: exact, preserves definiteness, and brings the diagonal
  // to [1/4, 1) so that no square overflows or underflows however widely
  // the diagonal entries range.
  for (int k = 0; k < sym; ++k)
    if (!std::isfinite(q[k])) return false;
  int h[dim];
  for (int i = 0; i < dim; ++i) {
    if (!(q[diag_of[i]] > 0.0)) return false;
    h[i] = exponent(q[diag_of[i]]) / 2;
  }
  double scaled[sym];
  for (int k = 0; k < sym; ++k)
    scaled[k] = std::ldexp(q[k], -(h[row_of[k]] + h[col_of[k]]));
  double l[sym];
  return cholesky_decomp(scaled, l);
}

int check_pointers_and_finite(double const *r, double const *q1,
                              double const *q2, void const *out) noexcept {
  if (r == nullptr || q1 == nullptr || q2 == nullptr || out == nullptr)
    return PW85_EFAULT;
  if (!(finite_n<dim>(r) && finite_n<sym>(q1) && finite_n<sym>(q2)))
    return PW85_EDOM;
  return PW85_SUCCESS;
}

int check_input(double const *r, double const *q1, double const *q2,
                double const *out) noexcept {
  int const status = check_pointers_and_finite(r, q1, q2, out);
  if (status != PW85_SUCCESS) return status;
  if (!is_positive_definite(q1) || !is_positive_definite(q2))
    return PW85_ENOTPOSDEF;
  return PW85_SUCCESS;
}

}  // namespace pw85::detail
