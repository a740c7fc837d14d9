// SPDX-License-Identifier: BSD-3-Clause
// Error-free transformations, double-double arithmetic and compensated
// sums (private).
// two_sum: Knuth, TAOCP vol. 2, 4.2.2; two_prod: exact through a fused
// multiply-add (std::fma is exact also where it is emulated in software).
#ifndef PW85_SRC_DD_HPP
#define PW85_SRC_DD_HPP

#include <cmath>

#include "compiler.hpp"

namespace pw85::detail {

// An unevaluated sum hi + lo with |lo| ≤ ulp(hi)/2.
struct dd {
  double hi;
  double lo;
};

// a + b = s + e exactly.
PW85_INLINE dd two_sum(double a, double b) noexcept {
  double const s = a + b;
  double const bb = s - a;
  double const e = (a - (s - bb)) + (b - bb);
  return {s, e};
}

// a·b = p + e exactly (barring underflow).
PW85_INLINE dd two_prod(double a, double b) noexcept {
  double const p = a * b;
  return {p, std::fma(a, b, -p)};
}

PW85_INLINE dd dd_add(dd a, dd b) noexcept {
  dd s = two_sum(a.hi, b.hi);
  s.lo += a.lo + b.lo;
  return two_sum(s.hi, s.lo);
}

PW85_INLINE dd dd_neg(dd a) noexcept { return {-a.hi, -a.lo}; }

PW85_INLINE dd dd_mul(dd a, dd b) noexcept {
  dd p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return two_sum(p.hi, p.lo);
}

PW85_INLINE dd dd_mul(dd a, double b) noexcept {
  dd p = two_prod(a.hi, b);
  p.lo += a.lo * b;
  return two_sum(p.hi, p.lo);
}

PW85_INLINE dd dd_add(dd a, double b) noexcept {
  dd s = two_sum(a.hi, b);
  s.lo += a.lo;
  return two_sum(s.hi, s.lo);
}

PW85_INLINE double dd_round(dd a) noexcept { return a.hi + a.lo; }

PW85_INLINE dd dd_sub(dd a, dd b) noexcept { return dd_add(a, dd_neg(b)); }

// a/b for b ≠ 0, to about 2⁻¹⁰⁴ relative: the quotient of the leading parts
// and two corrections from the remainder a − q·b, computed in
// double-double.
PW85_INLINE dd dd_div(dd a, dd b) noexcept {
  double const q1 = a.hi / b.hi;
  dd r = dd_sub(a, dd_mul(b, q1));
  double const q2 = r.hi / b.hi;
  r = dd_sub(r, dd_mul(b, q2));
  double const q3 = r.hi / b.hi;
  return dd_add(two_sum(q1, q2), q3);
}

// √a for a > 0 as a double-double: one Newton correction of √a.hi.
PW85_INLINE dd dd_sqrt(dd a) noexcept {
  double const x = std::sqrt(a.hi);
  dd const rem = dd_sub(a, two_prod(x, x));
  return two_sum(x, (rem.hi + rem.lo) / (2.0 * x));
}

// Compensated accumulation (Ogita, Rump and Oishi, SIAM J. Sci. Comput. 26,
// 2005, algorithm Dot2): the result is as accurate as if computed in twice
// the working precision, then rounded.
struct Dot2 {
  double sum;
  double err;
  PW85_INLINE void add_product(double a, double b) noexcept {
    dd const p = two_prod(a, b);
    dd const t = two_sum(sum, p.hi);
    sum = t.hi;
    err += p.lo + t.lo;
  }
  PW85_INLINE void add(double a) noexcept {
    dd const t = two_sum(sum, a);
    sum = t.hi;
    err += t.lo;
  }
  PW85_INLINE double value() const noexcept { return sum + err; }
};

}  // namespace pw85::detail

#endif  // PW85_SRC_DD_HPP
