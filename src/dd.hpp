// SPDX-License-Identifier: BSD-3-Clause
// Error-free transformations and double-double arithmetic (private).
// two_sum: Knuth, TAOCP vol. 2, 4.2.2; two_prod: exact through a fused
// multiply-add (std::fma is exact also where it is emulated in software).
#ifndef PW85_SRC_DD_HPP
#define PW85_SRC_DD_HPP

#include <cmath>

// Force inlining, so that the helpers below are compiled for the target of
// the function that uses them (see PW85_FMA_CLONES).
// PW85_UNROLL before a loop of 3 to 9 iterations unrolls it completely, so
// that index arithmetic (sym_index, row_of, col_of) folds into constants:
// -O2 does not unroll by itself.
#if defined(__GNUC__)
#define PW85_UNROLL _Pragma("GCC unroll 9")
#else
#define PW85_UNROLL
#endif

#if defined(__GNUC__)
#define PW85_INLINE inline __attribute__((always_inline))
#else
#define PW85_INLINE inline
#endif

// Compile a function twice, for CPUs with and without FMA, and pick one at
// load time (an ifunc): where the CPU has FMA, std::fma becomes one
// instruction; elsewhere it stays the exact libm routine. The build itself
// stays portable.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__linux__) && \
    (defined(__clang__) ? __clang_major__ >= 14 : __GNUC__ >= 8)
#define PW85_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define PW85_FMA_CLONES
#endif

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

}  // namespace pw85::detail

#endif  // PW85_SRC_DD_HPP
