/* SPDX-License-Identifier: BSD-3-Clause */
/* Double-double arithmetic for test references (about 104 bits, relative
 * error of each operation below 4·2⁻¹⁰⁶), built on fma, so that a reference
 * is exact enough on every platform and under valgrind, which runs x87
 * long double at double precision. Algorithms: Dekker's two-sum and
 * two-product (Knuth TAOCP vol. 2, 4.2.2; the product with fma), and the
 * accurate addition and division of the QD library (Hida, Li, Bailey 2001).
 * Tests only: the library has its own (src/dd.hpp). */
#ifndef PW85_TESTS_DDREF_H
#define PW85_TESTS_DDREF_H

#include <math.h>

typedef struct {
  double hi, lo;
} DD;

static inline DD dd_two_sum(double a, double b) {
  double const s = a + b, bb = s - a;
  return (DD){s, (a - (s - bb)) + (b - bb)};
}

static inline DD dd_quick_two_sum(double a, double b) {
  double const s = a + b;
  return (DD){s, b - (s - a)};
}

static inline DD dd(double a) { return (DD){a, 0.}; }

static inline DD dd_add(DD a, DD b) {
  DD s = dd_two_sum(a.hi, b.hi);
  DD const t = dd_two_sum(a.lo, b.lo);
  s.lo += t.hi;
  s = dd_quick_two_sum(s.hi, s.lo);
  s.lo += t.lo;
  return dd_quick_two_sum(s.hi, s.lo);
}

static inline DD dd_neg(DD a) { return (DD){-a.hi, -a.lo}; }

static inline DD dd_sub(DD a, DD b) { return dd_add(a, dd_neg(b)); }

static inline DD dd_mul(DD a, DD b) {
  double const p = a.hi * b.hi;
  double e = fma(a.hi, b.hi, -p);
  e += a.hi * b.lo + a.lo * b.hi;
  return dd_quick_two_sum(p, e);
}

static inline DD dd_div(DD a, DD b) {
  double const q1 = a.hi / b.hi;
  DD r = dd_sub(a, dd_mul(dd(q1), b));
  double const q2 = r.hi / b.hi;
  r = dd_sub(r, dd_mul(dd(q2), b));
  double const q3 = r.hi / b.hi;
  return dd_add(dd_quick_two_sum(q1, q2), dd(q3));
}

/* Rounded to the nearest double (hi + lo, |lo| ≤ ulp(hi)/2). */
static inline double dd_to_double(DD a) { return a.hi + a.lo; }

#endif /* PW85_TESTS_DDREF_H */
