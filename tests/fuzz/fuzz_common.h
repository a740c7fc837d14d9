/* SPDX-License-Identifier: BSD-3-Clause */
/* Helpers shared by the fuzz targets of tests/fuzz: reading doubles from
 * the fuzzer's bytes, sentinels, L·D·Lᵀ and a cheap upper bound of cond(Q)
 * and the floor of μ² in 2 or 3 dimensions, the functions and layouts of
 * each dimension (Api<D>), the oracles written once for both, and CHECK,
 * which reports a violated contract and aborts (libFuzzer then saves the
 * input as a crash). C++ (the targets are C++ so that they need no extra
 * runtime); it includes only public headers. */
#ifndef PW85_FUZZ_COMMON_H
#define PW85_FUZZ_COMMON_H

#include <pw85/pw85.h>
#include <pw85/pw85_2d.h>

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

/* The dimension's storage: a symmetric D × D form holds its upper
 * triangle row by row (pw85.h, pw85_2d.h), sym_size(D) entries; entry
 * (i, j) is at sym_at(D, i, j), either order. */
constexpr int sym_size(int d) { return d * (d + 1) / 2; }
constexpr int sym_at(int d, int i, int j) {
  return i <= j ? i * d - i * (i - 1) / 2 + (j - i) : sym_at(d, j, i);
}

/* Q = L·diag(p)·Lᵀ, L unit lower triangular, in the arithmetic of T (the
 * fuzz references: long double, binary128). False when a pivot is not
 * > 0. tr_inv, if not null, receives tr(Q⁻¹) = Σₖ Σᵢ (L⁻¹)ₖᵢ²/pₖ. */
template <int D, typename T>
bool ldl(const T (&a)[sym_size(D)], T (&l)[D][D], T (&p)[D], T *tr_inv) {
  for (int j = 0; j < D; ++j) {
    T pj = a[sym_at(D, j, j)];
    for (int k = 0; k < j; ++k) pj -= l[j][k] * l[j][k] * p[k];
    if (!(pj > 0)) return false;
    p[j] = pj;
    l[j][j] = 1;
    for (int i = j + 1; i < D; ++i) {
      T t = a[sym_at(D, i, j)];
      for (int k = 0; k < j; ++k) t -= l[i][k] * l[j][k] * p[k];
      l[i][j] = t / pj;
      l[j][i] = 0;
    }
  }
  if (tr_inv != nullptr) {
    *tr_inv = 0;
    for (int c = 0; c < D; ++c) {  // y = L⁻¹·e_c
      T y[D];
      for (int k = 0; k < D; ++k) {
        y[k] = k == c ? 1 : 0;
        for (int m = 0; m < k; ++m) y[k] -= l[k][m] * y[m];
        *tr_inv += y[k] * y[k] / p[k];
      }
    }
  }
  return true;
}

/* s = Q⁻¹·r from ldl()'s factors. */
template <int D, typename T>
void ldl_solve(const T (&l)[D][D], const T (&p)[D], const T *r, T *s) {
  T z[D];
  for (int i = 0; i < D; ++i) {
    z[i] = r[i];
    for (int k = 0; k < i; ++k) z[i] -= l[i][k] * z[k];
  }
  for (int i = D - 1; i >= 0; --i) {
    s[i] = z[i] / p[i];
    for (int k = i + 1; k < D; ++k) s[i] -= l[k][i] * s[k];
  }
}

/* An upper bound of cond(Q) (2-norm), tr(Q)·tr(Q⁻¹) ≥ λmax/λmin, by
 * ldl() in long double (x87: no overflow for any finite double input).
 * Returns +inf when unsure (a pivot ≤ 0, non-finite input). The bound
 * exceeds cond by at most a factor D². */
template <int D = 3>
long double cond_bound(const double *q) {
  long double a[sym_size(D)], l[D][D], p[D], tr_inv, tr = 0;
  for (int k = 0; k < sym_size(D); ++k) {
    if (!std::isfinite(q[k])) return INFINITY;
    a[k] = q[k];
  }
  for (int i = 0; i < D; ++i) {
    if (!(q[sym_at(D, i, i)] > 0)) return INFINITY;
    tr += q[sym_at(D, i, i)];
  }
  if (!ldl<D>(a, l, p, &tr_inv)) return INFINITY;
  long double const c = tr * tr_inv;
  return std::isfinite(c) ? c : INFINITY;
}

/* The documented floor |r12|²/(√tr Q1 + √tr Q2)², in long double. */
template <int D = 3>
long double mu2_floor(const double *r, const double *q1, const double *q2) {
  long double rr = 0, t1 = 0, t2 = 0;
  for (int i = 0; i < D; ++i) {
    rr += (long double)r[i] * r[i];
    t1 += q1[sym_at(D, i, i)];
    t2 += q2[sym_at(D, i, i)];
  }
  long double const s = std::sqrt(t1) + std::sqrt(t2);
  return rr / (s * s);
}

/* Inside the domain where the swapping symmetry is exact (pw85.h):
 * cond(Qᵢ) < 1e16, every non-zero entry between 2^-500 and 2^500 (the
 * internal rescaling by powers of two cannot push one out of the normal
 * range) and μ² normal. Beyond, μ² "may round to a subnormal" and the
 * orientations' roundings may differ. */
template <int D = 3>
bool exact_swap_domain(const double *r12, const double *q1,
                       const double *q2, double mu2) {
  int const S = sym_size(D);
  if (!(cond_bound<D>(q1) < 1e16L && cond_bound<D>(q2) < 1e16L &&
        mu2 >= DBL_MIN))
    return false;
  for (int i = 0; i < D + 2 * S; ++i) {
    double const x = i < D ? r12[i] : i < D + S ? q1[i - D] : q2[i - D - S];
    if (!(x == 0 ||
          (std::fabs(x) >= 0x1p-500 && std::fabs(x) <= 0x1p500)))
      return false;
  }
  return true;
}

/* The functions of a pair of ellipsoids (D = 3, pw85.h) or of ellipses
 * (D = 2, pw85_2d.h) and the layouts of their outputs, for the oracles
 * written once for both. rot: the size of a torque block (a vector in
 * 3D, the scalar ∂μ²/∂θ in 2D). */
template <int D>
struct Api;

template <>
struct Api<3> {
  static constexpr int sym = PW85_SYM, rot = 3;
  static constexpr int geom_size = PW85_GEOM_SIZE, mu2 = PW85_GEOM_MU2,
                       lambda = PW85_GEOM_LAMBDA, point = PW85_GEOM_POINT,
                       normal = PW85_GEOM_NORMAL;
  static constexpr int deriv_size = PW85_DERIV_SIZE, d_r12 = PW85_DERIV_R12,
                       d_rot1 = PW85_DERIV_ROT1, d_rot2 = PW85_DERIV_ROT2,
                       d_q1 = PW85_DERIV_Q1, d_q2 = PW85_DERIV_Q2;
  static constexpr auto contact = pw85_contact_function;
  static constexpr auto overlap = pw85_overlap;
  static constexpr auto geometry = pw85_contact_geometry;
  static constexpr auto derivatives = pw85_contact_derivatives;
};

template <>
struct Api<2> {
  static constexpr int sym = PW85_2D_SYM, rot = 1;
  static constexpr int geom_size = PW85_2D_GEOM_SIZE,
                       mu2 = PW85_2D_GEOM_MU2, lambda = PW85_2D_GEOM_LAMBDA,
                       point = PW85_2D_GEOM_POINT,
                       normal = PW85_2D_GEOM_NORMAL;
  static constexpr int deriv_size = PW85_2D_DERIV_SIZE,
                       d_r12 = PW85_2D_DERIV_R12,
                       d_rot1 = PW85_2D_DERIV_THETA1,
                       d_rot2 = PW85_2D_DERIV_THETA2,
                       d_q1 = PW85_2D_DERIV_Q1, d_q2 = PW85_2D_DERIV_Q2;
  static constexpr auto contact = pw85_2d_contact_function;
  static constexpr auto overlap = pw85_2d_overlap;
  static constexpr auto geometry = pw85_2d_contact_geometry;
  static constexpr auto derivatives = pw85_2d_contact_derivatives;
};

/* Q positive definite exactly, as stored (the rule of pw85.h and
 * pw85_2d.h), decided on the exact rational values of its doubles (GMP,
 * contact_oracle.cpp). */
template <int D>
bool exactly_definite(const double *q);

/* Contract and metamorphic oracles of the contact function and the
 * overlap test (contact_oracle.cpp), shared by fuzz-contact-raw,
 * fuzz-contact-structured (D = 3) and fuzz-2d (D = 2). k: the exponent of
 * the joint scaling 2^k (lengths), from the input. */
template <int D>
void check_contact(const double *r12, const double *q1, const double *q2,
                   int k);

/* The oracle of the contact geometry and the derivatives
 * (geometry_oracle.cpp), shared by fuzz-geometry (D = 3) and fuzz-2d. */
template <int D>
void check_geometry(const double *r12, const double *q1, const double *q2);

}  // namespace fuzz

#endif /* PW85_FUZZ_COMMON_H */
