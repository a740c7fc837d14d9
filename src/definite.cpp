// SPDX-License-Identifier: BSD-3-Clause
// The exact decision of positive definiteness (checks.hpp): Sylvester's
// criterion on the exact values of the stored doubles, in integer
// arithmetic. Slow (a few hundred nanoseconds) and used only where the
// floating-point certificate of ldl_certifies() cannot decide.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "checks.hpp"

namespace pw85::detail {

namespace {

// x = sign·m·2^e exactly, m < 2^53 an integer (m = 0 for ±0). x finite.
struct Split {
  std::uint64_t m;
  int e;
  bool negative;
};

Split split(double x) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  int const biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t const frac = bits & ((std::uint64_t{1} << 52) - 1);
  Split s;
  s.negative = (bits >> 63) != 0;
  if (biased == 0) {  // zero or subnormal: frac·2^−1074
    s.m = frac;
    s.e = -1074;
  } else {
    s.m = frac | (std::uint64_t{1} << 52);
    s.e = biased - 1075;
  }
  return s;
}

// A product of up to three doubles, exactly: ±(w[0] + w[1]·2^64 +
// w[2]·2^128)·2^e (magnitude below 2^159).
struct Term {
  std::uint64_t w[3];
  int e;
  bool negative;
};

// hi·2^64 + lo = a·b, from 32-bit halves (no 128-bit type needed).
void mul64(std::uint64_t a, std::uint64_t b, std::uint64_t *hi,
           std::uint64_t *lo) noexcept {
  std::uint64_t const mask = 0xffffffffu;
  std::uint64_t const a0 = a & mask, a1 = a >> 32, b0 = b & mask, b1 = b >> 32;
  std::uint64_t const p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0,
                      p11 = a1 * b1;
  std::uint64_t const mid = (p00 >> 32) + (p01 & mask) + (p10 & mask);
  *lo = (mid << 32) | (p00 & mask);
  *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

// sign·2^k·x·y·z (k ≥ 0 a small power of two factor); z may be 1.0.
Term product(int k, bool negative, double x, double y, double z) noexcept {
  Split const a = split(x), b = split(y), c = split(z);
  Term t;
  std::uint64_t hi, lo;
  mul64(a.m, b.m, &hi, &lo);  // < 2^106
  // (hi·2^64 + lo)·c.m < 2^159
  std::uint64_t h1, l1, h2, l2;
  mul64(lo, c.m, &h1, &l1);
  mul64(hi, c.m, &h2, &l2);
  t.w[0] = l1;
  t.w[1] = h1 + l2;
  t.w[2] = h2 + (t.w[1] < l2 ? 1 : 0);
  t.e = a.e + b.e + c.e + k;
  t.negative = (negative != (a.negative != b.negative)) != c.negative;
  return t;
}

bool is_zero(Term const &t) noexcept {
  return (t.w[0] | t.w[1] | t.w[2]) == 0;
}

// The sign (−1, 0, +1) of the exact sum of n terms: a fixed-point
// accumulator in two's complement whose bit 0 weighs 2^(least exponent).
// Exponents of products of three doubles lie in [−3·1074, 3·971], so the
// terms span at most 6135 + 159 bits; with the carries of five terms,
// 6400 bits (100 words) hold the sum.
int sign_of_sum(Term const *terms, int n) noexcept {
  constexpr int words = 100;
  int emin = 0;
  bool any = false;
  for (int i = 0; i < n; ++i)
    if (!is_zero(terms[i]) && (!any || terms[i].e < emin)) {
      emin = terms[i].e;
      any = true;
    }
  if (!any) return 0;
  std::uint64_t acc[words] = {};
  for (int i = 0; i < n; ++i) {
    Term const &t = terms[i];
    if (is_zero(t)) continue;
    int const shift = t.e - emin;  // in [0, 6135]
    int const word = shift / 64, bit = shift % 64;
    // The term's magnitude shifted by `bit`, in four words.
    std::uint64_t m[4];
    m[0] = t.w[0] << bit;
    m[1] = bit ? (t.w[1] << bit) | (t.w[0] >> (64 - bit)) : t.w[1];
    m[2] = bit ? (t.w[2] << bit) | (t.w[1] >> (64 - bit)) : t.w[2];
    m[3] = bit ? t.w[2] >> (64 - bit) : 0;
    // acc ± m·2^(64·word), carries (or borrows) to the top.
    std::uint64_t carry = 0;
    for (int j = word; j < words; ++j) {
      std::uint64_t const x = j - word < 4 ? m[j - word] : 0;
      if (x == 0 && carry == 0 && j - word >= 4) break;
      std::uint64_t const old = acc[j];
      if (!t.negative) {
        std::uint64_t const s = old + x;
        std::uint64_t const s2 = s + carry;
        carry = (s < old ? 1 : 0) + (s2 < s ? 1 : 0);
        acc[j] = s2;
      } else {
        std::uint64_t const s = old - x;
        std::uint64_t const s2 = s - carry;
        carry = (old < x ? 1 : 0) + (s < carry ? 1 : 0);
        acc[j] = s2;
      }
    }
  }
  if ((acc[words - 1] >> 63) != 0) return -1;
  for (std::uint64_t w : acc)
    if (w != 0) return 1;
  return 0;
}

}  // namespace

template <int D>
bool exactly_positive_definite(double const *q) noexcept {
  if (!all_finite<sym_size(D)>(q)) return false;
  // Sylvester's criterion: Q is positive definite if and only if its
  // leading principal minors are positive.
  if (!(q[0] > 0.0)) return false;
  Term const minor2[2] = {product(0, false, q[0], q[Layout<D>::diag[1]], 1.0),
                          product(0, true, q[1], q[1], 1.0)};
  if (sign_of_sum(minor2, 2) <= 0) return false;
  if constexpr (D == 3) {
    // det Q = Q00·Q11·Q22 + 2·Q01·Q12·Q02 − Q00·Q12² − Q11·Q02² − Q22·Q01².
    Term const det[5] = {
        product(0, false, q[0], q[3], q[5]),
        product(1, false, q[1], q[4], q[2]),
        product(0, true, q[0], q[4], q[4]), product(0, true, q[3], q[2], q[2]),
        product(0, true, q[5], q[1], q[1])};
    return sign_of_sum(det, 5) > 0;
  }
  return true;  // in 2D, the two leading minors are all
}

template bool exactly_positive_definite<2>(double const *) noexcept;
template bool exactly_positive_definite<3>(double const *) noexcept;

}  // namespace pw85::detail
