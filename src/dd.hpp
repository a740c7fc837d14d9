// SPDX-License-Identifier: BSD-3-Clause
// Error-free transformations and double-double arithmetic (private).
// two_sum: Knuth, TAOCP vol. 2, 4.2.2; two_prod: exact through a fused
// multiply-add (std::fma is exact also where it is emulated in software).
#ifndef PW85_SRC_DD_HPP
#define PW85_SRC_DD_HPP

#include <cmath>

namespace pw85::detail {

// An unevaluated sum hi + lo with |lo| ≤ ulp(hi)/2.
struct dd {
  double hi;
  double lo;
};

// a + b = s + e exactly.
inline dd two_sum(double a, double b) noexcept {
  double const s = a + b;
  double const bb = s - a;
  double const e = (a - (s - bb)) + (b - bb);
  return {s, e};
}

// a·b = p + e exactly (barring underflow).
inline dd two_prod(double a, double b) noexcept {
  double const p = a * b;
  return {p, std::fma(a, b, -p)};
}

inline dd dd_add(dd a, dd b) noexcept {
  dd s = two_sum(a.hi, b.hi);
  s.lo += a.lo + b.lo;
  return two_sum(s.hi, s.lo);
}

inline dd dd_neg(dd a) noexcept { return {-a.hi, -a.lo}; }

inline dd dd_mul(dd a, dd b) noexcept {
  dd p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  return two_sum(p.hi, p.lo);
}

inline dd dd_mul(dd a, double b) noexcept {
  dd p = two_prod(a.hi, b);
  p.lo += a.lo * b;
  return two_sum(p.hi, p.lo);
}

inline dd dd_add(dd a, double b) noexcept {
  dd s = two_sum(a.hi, b);
  s.lo += a.lo;
  return two_sum(s.hi, s.lo);
}

inline double dd_round(dd a) noexcept { return a.hi + a.lo; }

}  // namespace pw85::detail

#endif  // PW85_SRC_DD_HPP
