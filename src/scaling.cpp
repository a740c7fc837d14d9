// SPDX-License-Identifier: BSD-3-Clause
// Exact rescaling by powers of two (scaling.hpp).
#include "scaling.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace pw85::detail {

namespace {

// The smallest and largest |x| of the diagonals of q1 and q2, written out
// as a tree of min and max: -O2 leaves loops rolled, and this runs on
// every call.
template <int D>
void diagonal_range(double const *q1, double const *q2, double *lo,
                    double *hi) noexcept {
  constexpr int k = Layout<D>::diag[1];
  double const a = std::fabs(q1[0]), b = std::fabs(q1[k]);
  double const c = std::fabs(q2[0]), d = std::fabs(q2[k]);
  if constexpr (D == 2) {
    *lo = std::min(std::min(a, b), std::min(c, d));
    *hi = std::max(std::max(a, b), std::max(c, d));
  } else {
    // Q1's last diagonal entry e, Q2's f; the same tree as in 2D with
    // their pair beside it.
    double const e = std::fabs(q1[5]), f = std::fabs(q2[5]);
    *lo = std::min(std::min(std::min(a, b), std::min(e, c)), std::min(d, f));
    *hi = std::max(std::max(std::max(a, b), std::max(e, c)), std::max(d, f));
  }
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

}  // namespace

int exponent(double x) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  int const biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased != 0) return biased - 1022;
  int e = 0;
  std::frexp(x, &e);
  return e;
}

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

template <int D>
bool rescale(double const *r, double const *q1, double const *q2,
             Scaled<D> *s) noexcept {
  double rmax = std::fabs(r[0]);
  PW85_UNROLL
  for (int i = 1; i < D; ++i) rmax = std::max(rmax, std::fabs(r[i]));
  s->r_is_zero = rmax == 0.0;
  int const er = exponent(rmax);
  // The exponent is monotone in |x|: those of the extreme diagonal entries
  // are the extreme exponents.
  double dmin = 0.0, dmax = 0.0;
  diagonal_range<D>(q1, q2, &dmin, &dmax);
  int const emin = exponent(dmin);
  int const emax = exponent(dmax);
  int const eq = emin + (emax - emin) / 2;
  scale_n<D>(r, -er, s->r);
  scale_n<sym_size(D)>(q1, -eq, s->q1);
  scale_n<sym_size(D)>(q2, -eq, s->q2);
  s->shift = 2 * er - eq;
  s->r_exp = er;
  s->q_exp = eq;
  // |x| < 2^e for the exponent e of x, and |x| ≥ 2^(e−1).
  s->moderate = emax - eq <= 400 && emin - eq >= -399;
  // No diagonal entry overflows within that span (emax − eq ≤ 996); an
  // off-diagonal entry cannot overflow without exceeding √(Qᵢᵢ·Qⱼⱼ),
  // which leaves the form indefinite: its factorisation then fails on a
  // non-finite pivot.
  return emax - emin <= max_diagonal_span;
}

template bool rescale<2>(double const *, double const *, double const *,
                         Scaled<2> *) noexcept;
template bool rescale<3>(double const *, double const *, double const *,
                         Scaled<3> *) noexcept;

}  // namespace pw85::detail
