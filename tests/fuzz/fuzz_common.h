/* SPDX-License-Identifier: BSD-3-Clause */
/* Helpers shared by the fuzz targets of tests/fuzz: reading doubles from
 * the fuzzer's bytes, sentinels, a cheap upper bound of cond(Q), the floor
 * of μ², and CHECK, which reports a violated contract and aborts (libFuzzer
 * then saves the input as a crash). Header-only, C++ (the targets are C++
 * so that they need no extra runtime); it includes only public headers. */
#ifndef PW85_FUZZ_COMMON_H
#define PW85_FUZZ_COMMON_H

#include <pw85/pw85.h>

#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#define CHECK(cond, ...)                                               \
  do {                                                                 \
    if (!(cond)) {                                                     \
      std::fprintf(stderr, "%s:%d: contract violated: %s\n", __FILE__, \
                   __LINE__, #cond);                                   \
      std::fprintf(stderr, __VA_ARGS__);                               \
      std::fprintf(stderr, "\n");                                      \
      std::abort();                                                    \
    }                                                                  \
  } while (0)

namespace fuzz {

/* A byte stream that yields zeros once exhausted. */
struct Bytes {
  const uint8_t *p;
  size_t n;
  size_t pos = 0;
  Bytes(const uint8_t *data, size_t size) : p(data), n(size) {}
  uint8_t u8() { return pos < n ? p[pos++] : 0; }
  uint16_t u16() { return uint16_t(u8() | (unsigned(u8()) << 8)); }
  int16_t i16() { return int16_t(u16()); }
  double f64() {
    uint8_t b[8] = {0};
    for (int i = 0; i < 8; ++i) b[i] = u8();
    double x;
    std::memcpy(&x, b, 8);
    return x;
  }
};

/* The bit pattern that outputs hold before a call, to prove "untouched". */
inline void fill_sentinel(void *p, size_t n) { std::memset(p, 0xA5, n); }
inline bool is_sentinel(const void *p, size_t n) {
  const uint8_t *b = static_cast<const uint8_t *>(p);
  for (size_t i = 0; i < n; ++i)
    if (b[i] != 0xA5) return false;
  return true;
}

inline bool all_finite(const double *x, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}

inline bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/* An upper bound of cond(Q) (2-norm), tr(Q)·tr(Q⁻¹) ≥ λmax/λmin, by an
 * L·D·Lᵀ factorisation in long double (x87: no overflow for any finite
 * double input). Returns +inf when unsure (a pivot ≤ 0, non-finite
 * input). The bound exceeds cond by at most a factor 9. */
inline long double cond_bound(const double q[6]) {
  for (int i = 0; i < 6; ++i)
    if (!std::isfinite(q[i])) return INFINITY;
  long double a00 = q[0], a01 = q[1], a02 = q[2], a11 = q[3], a12 = q[4],
              a22 = q[5];
  if (!(a00 > 0 && a11 > 0 && a22 > 0)) return INFINITY;
  long double d0 = a00;
  long double l10 = a01 / d0, l20 = a02 / d0;
  long double d1 = a11 - l10 * a01;
  if (!(d1 > 0)) return INFINITY;
  long double l21 = (a12 - l20 * a01) / d1;
  long double d2 = a22 - l20 * a02 - l21 * l21 * d1;
  if (!(d2 > 0)) return INFINITY;
  /* M = L⁻¹ (unit lower): m10 = -l10, m20 = l10 l21 - l20, m21 = -l21.
   * tr(Q⁻¹) = Σ_k (1/d_k) Σ_i M_{k i}². */
  long double m10 = -l10, m21 = -l21, m20 = l10 * l21 - l20;
  long double tr_inv = 1 / d0 + (m10 * m10 + 1) / d1 +
                       (m20 * m20 + m21 * m21 + 1) / d2;
  long double tr = a00 + a11 + a22;
  long double c = tr * tr_inv;
  return std::isfinite(c) ? c : INFINITY;
}

/* The documented floor |r12|²/(√tr Q1 + √tr Q2)², in long double. */
inline long double mu2_floor(const double r[3], const double q1[6],
                             const double q2[6]) {
  long double rr = (long double)r[0] * r[0] + (long double)r[1] * r[1] +
                   (long double)r[2] * r[2];
  long double s = std::sqrt((long double)q1[0] + q1[3] + q1[5]) +
                  std::sqrt((long double)q2[0] + q2[3] + q2[5]);
  return rr / (s * s);
}

/* Inside the domain where the swapping symmetry is exact (pw85.h):
 * cond(Qᵢ) < 1e16, every non-zero entry between 2^-500 and 2^500 (the
 * internal rescaling by powers of two cannot push one out of the normal
 * range) and μ² normal. Beyond, μ² "may round to a subnormal" and the
 * orientations' roundings may differ. */
inline bool exact_swap_domain(const double r12[3], const double q1[6],
                              const double q2[6], double mu2) {
  if (!(cond_bound(q1) < 1e16L && cond_bound(q2) < 1e16L && mu2 >= DBL_MIN))
    return false;
  for (int i = 0; i < 15; ++i) {
    double const x = i < 3 ? r12[i] : i < 9 ? q1[i - 3] : q2[i - 9];
    if (!(x == 0 ||
          (std::fabs(x) >= 0x1p-500 && std::fabs(x) <= 0x1p500)))
      return false;
  }
  return true;
}

/* Contract and metamorphic oracles of pw85_contact_function and
 * pw85_overlap, shared by fuzz-contact-raw and fuzz-contact-structured.
 * k: the exponent of the joint scaling 2^k (lengths), from the input. */
void check_contact(const double r12[3], const double q1[6],
                   const double q2[6], int k);

}  // namespace fuzz

#endif /* PW85_FUZZ_COMMON_H */
