// SPDX-License-Identifier: BSD-3-Clause
// Exact sign of a sum of products of doubles (exact.hpp).
//
// A finite double x ≠ 0 is s·M·2^E with M an integer < 2⁵³ and
// E ∈ [−1126, 971] (frexp, then M = |f|·2⁵³, E = e − 53; subnormals
// included). A monomial of nf ≤ 8 factors is then ±coef·(ΠM)·2^(ΣE): the
// integer ΠM has at most 8·53 + 3 = 427 bits, and ΣE ≥ 8·(−1126) = E_min.
// Each monomial is added, at bit ΣE − E_min, to one of two unsigned
// fixed-point accumulators (positive and negative terms); the sign is that
// of their difference. Width: ΣE − E_min ≤ 8·971 + 9008 = 16776, plus 427
// bits of the product and 8 bits of carries for 256 terms: 17211 bits,
// 269 limbs of 64 bits (limbs below).
#include "image/exact.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace pw85::detail {
namespace {

constexpr int e_min = -1126 * exact_max_factors;
constexpr int limbs = 272;
constexpr int product_limbs = 7;  // 427 bits

using u64 = std::uint64_t;
using u128 = unsigned __int128;

struct Accumulator {
  u64 w[limbs];
  int top;  // highest limb written + 1
};

// acc += p (n limbs) shifted left by `bit` bits.
void add_shifted(Accumulator &acc, u64 const *p, int n, int bit) noexcept {
  int const limb = bit / 64, shift = bit % 64;
  u64 carry = 0;
  int k = 0;
  for (; k <= n; ++k) {
    u64 const lo = k < n ? p[k] : 0;
    u64 const hi = k > 0 ? p[k - 1] : 0;
    u64 const part = shift == 0 ? lo : (lo << shift) | (hi >> (64 - shift));
    u128 const s = (u128)acc.w[limb + k] + part + carry;
    acc.w[limb + k] = (u64)s;
    carry = (u64)(s >> 64);
  }
  for (int j = limb + k; carry != 0; ++j) {
    u128 const s = (u128)acc.w[j] + carry;
    acc.w[j] = (u64)s;
    carry = (u64)(s >> 64);
    if (j + 1 > acc.top) acc.top = j + 1;
  }
  if (limb + k > acc.top) acc.top = limb + k;
}

}  // namespace

int exact_sign(Monomial const *m, int count) noexcept {
  static Accumulator const zero{};
  Accumulator pos = zero, neg = zero;  // 4.4 KiB each, on the stack
  pos.top = neg.top = 0;
  for (int t = 0; t < count; ++t) {
    if (m[t].coef == 0) continue;
    u64 p[product_limbs + 1] = {static_cast<u64>(m[t].coef < 0 ? -m[t].coef : m[t].coef)};
    int n = 1, exponent = 0;
    bool negative = m[t].coef < 0, zero_factor = false;
    for (int k = 0; k < m[t].nf; ++k) {
      double const x = m[t].f[k];
      if (x == 0.0) {
        zero_factor = true;
        break;
      }
      int e;
      double const f = std::frexp(x, &e);  // |f| ∈ [½, 1), exact
      negative ^= f < 0.0;
      u64 const mant = static_cast<u64>(std::ldexp(std::fabs(f), 53));
      exponent += e - 53;
      u64 carry = 0;
      for (int j = 0; j < n; ++j) {
        u128 const s = (u128)p[j] * mant + carry;
        p[j] = (u64)s;
        carry = (u64)(s >> 64);
      }
      if (carry != 0) p[n++] = carry;
    }
    if (zero_factor) continue;
    // exponent ≥ (−1126)·nf ≥ e_min: the bit position is ≥ 0.
    add_shifted(negative ? neg : pos, p, n, exponent - e_min);
  }
  int const top = pos.top > neg.top ? pos.top : neg.top;
  for (int j = top - 1; j >= 0; --j) {
    if (pos.w[j] != neg.w[j]) return pos.w[j] > neg.w[j] ? 1 : -1;
  }
  return 0;
}

}  // namespace pw85::detail
