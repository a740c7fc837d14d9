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
PW85_INLINE void diagonal_range(double const *q1, double const *q2,
                                double *lo, double *hi) noexcept {
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

int frexp_exponent(double x) noexcept {
  int e = 0;
  std::frexp(x, &e);
  return e;
}

double ldexp_of(double x, int k) noexcept { return std::ldexp(x, k); }

namespace {

// The fields of *s set by the exponents e of rmax (er) and of the extreme
// diagonal entries (emin, emax), the scaled entries aside; returns
// rescale()'s answer.
template <int D>
PW85_INLINE bool set_exponents(int er, int emin, int emax, int eq,
                               Scaled<D> *s) noexcept {
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

// rescale() for any finite input, from rmax = max|rᵢ| and the extreme
// |diagonal entries|: zero r, subnormal entries, scale factors beyond the
// normal range (ldexp). Out of line, so that the common path calls nothing.
template <int D>
__attribute__((noinline)) bool rescale_general(double const *r,
                                               double const *q1,
                                               double const *q2, double rmax,
                                               double dmin, double dmax,
                                               Scaled<D> *s) noexcept {
  s->r_is_zero = rmax == 0.0;
  int const er = exponent(rmax);
  // The exponent is monotone in |x|: those of the extreme diagonal entries
  // are the extreme exponents.
  int const emin = exponent(dmin);
  int const emax = exponent(dmax);
  int const eq = emin + (emax - emin) / 2;
  scale_n<D>(r, -er, s->r);
  scale_n<sym_size(D)>(q1, -eq, s->q1);
  scale_n<sym_size(D)>(q2, -eq, s->q2);
  return set_exponents(er, emin, emax, eq, s);
}

}  // namespace

// The common case is rescale_general() with its first branches taken
// (the same operations, the same results bit for bit): r ≠ 0 and the
// extreme diagonal entries normal, so that exponent() reads the bits, and
// both scale factors normal doubles (scale_n()'s multiplication).
template <int D>
bool rescale(double const *r, double const *q1, double const *q2,
             Scaled<D> *s) noexcept {
  double rmax = std::fabs(r[0]);
  PW85_UNROLL
  for (int i = 1; i < D; ++i) rmax = std::max(rmax, std::fabs(r[i]));
  double dmin = 0.0, dmax = 0.0;
  diagonal_range<D>(q1, q2, &dmin, &dmax);
  int const br = biased_exponent(rmax);
  int const bmin = biased_exponent(dmin);
  int const er = br - 1022, emin = bmin - 1022;
  int const emax = biased_exponent(dmax) - 1022;  // ≥ emin
  int const eq = emin + (emax - emin) / 2;
  // Normal rmax and dmin (so dmax too) give er, eq ≥ −1021; 2^−er and
  // 2^−eq are then normal while er, eq ≤ 1022.
  if (PW85_UNLIKELY(br == 0 || bmin == 0 || er > 1022 || eq > 1022))
    return rescale_general<D>(r, q1, q2, rmax, dmin, dmax, s);
  double const fr = normal_pow2(-er), fq = normal_pow2(-eq);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) s->r[i] = r[i] * fr;
  constexpr int n = sym_size(D);
  PW85_UNROLL
  for (int i = 0; i < n; ++i) {
    s->q1[i] = q1[i] * fq;
    s->q2[i] = q2[i] * fq;
  }
  s->r_is_zero = false;
  return set_exponents(er, emin, emax, eq, s);
}

template bool rescale<2>(double const *, double const *, double const *,
                         Scaled<2> *) noexcept;
template bool rescale<3>(double const *, double const *, double const *,
                         Scaled<3> *) noexcept;

}  // namespace pw85::detail
