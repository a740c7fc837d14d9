// SPDX-License-Identifier: BSD-3-Clause
// Exact rescaling by powers of two (private).
#ifndef PW85_SRC_SCALING_HPP
#define PW85_SRC_SCALING_HPP

#include <cstdint>
#include <cstring>

#include "compiler.hpp"
#include "sym.hpp"

namespace pw85::detail {

// The biased exponent field of x (0 for zero and subnormals).
inline int biased_exponent(double x) noexcept {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return static_cast<int>((bits >> 52) & 0x7ff);
}

// 2^k for k in [−1022, 1023], from its bits (pow2() without the check).
inline double normal_pow2(int k) noexcept {
  std::uint64_t const bits = static_cast<std::uint64_t>(k + 1023) << 52;
  double x;
  std::memcpy(&x, &bits, sizeof x);
  return x;
}

// The rare paths of the functions below (libm's frexp and ldexp), out of
// line.
int frexp_exponent(double x) noexcept;
double ldexp_of(double x, int k) noexcept;

// The exponent e with |x| = m·2^e, m in [0.5, 1), read from the bits (a
// libm call per entry would cost more than the rest of the rescaling);
// frexp for zero and subnormals. x finite. Inline, as the two below: the
// search calls them at every compensated point (lambda_rho()), where a call
// cost more than the bit operations.
inline int exponent(double x) noexcept {
  int const biased = biased_exponent(x);
  return PW85_UNLIKELY(biased == 0) ? frexp_exponent(x) : biased - 1022;
}

// 2^k, built from its bits when it is a normal double; ldexp otherwise.
inline double pow2(int k) noexcept {
  return PW85_UNLIKELY(k < -1022 || k > 1023) ? ldexp_of(1.0, k)
                                               : normal_pow2(k);
}

// x·2^k, as std::ldexp(x, k) computes it, without a libm call when 2^k is a
// normal double (x·2^k is then rounded once, as ldexp rounds it).
inline double times_pow2(double x, int k) noexcept {
  return PW85_UNLIKELY(k < -1022 || k > 1023) ? ldexp_of(x, k)
                                               : x * normal_pow2(k);
}

// r, Q1, Q2 rescaled exactly by powers of two (docs/theory.rst, eq. (3.6):
// μ²(t·r, s·Q1, s·Q2) = (t²/s)·μ²(r, Q1, Q2), λ unchanged): r to order
// one, Q1 and Q2 so that their diagonals (which bound every entry of a
// positive definite matrix) straddle one. μ²(input) = μ²(scaled)·2^shift.
template <int D = dim>
struct Scaled {
  double r[D];
  double q1[sym_size(D)];
  double q2[sym_size(D)];
  int shift;       // 2·r_exp − q_exp
  int r_exp;       // r = r(scaled)·2^r_exp
  int q_exp;       // Qᵢ = Qᵢ(scaled)·2^q_exp
  bool r_is_zero;
  // Every rescaled diagonal entry of Q1 and Q2, hence of Q(λ), a convex
  // combination of them, lies in [2^−400, 2^400]: the range in which
  // ldl_decomp_fast() (ldl.hpp) may be used.
  bool moderate;
};

// The widest span of the diagonal entries of Q1 and Q2 together that the
// search takes on, as a difference of binary exponents (exponent()).
// Beyond it, rescaled to the middle of the span, the smaller form's
// entries come within 2^−1008 of the bottom of the normal range, where the
// low parts of the compensated finish's error-free products are subnormal,
// hence inexact. Measured against 700-digit references (gen_geometry.py):
// μ² 1 to 3 ulps off from spans of 2^2024 up (fuzz-contact-raw's three
// inputs at 2^2028 to 2^2045, and 9 of 217 random pairs at 2^2024 and
// 2^2036, cond(Qᵢ) to 1e15, λ* near 2^−1010); none wrong among 500 at
// 2^2012 to 2^2020, nor on the 8 finish-* regression pairs at exactly
// 2^2016.
inline constexpr int max_diagonal_span = 2016;

// Fills *s from finite input. Returns false when the diagonals of Q1 and
// Q2 span more than max_diagonal_span (decided from the exponents; also
// where a rescaled diagonal entry would overflow; an off-diagonal entry
// that overflows leaves the form indefinite, which its factorisation
// rejects).
template <int D>
bool rescale(double const *r, double const *q1, double const *q2,
             Scaled<D> *s) noexcept;

extern template bool rescale<2>(double const *, double const *,
                                double const *, Scaled<2> *) noexcept;
extern template bool rescale<3>(double const *, double const *,
                                double const *, Scaled<3> *) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_SCALING_HPP
