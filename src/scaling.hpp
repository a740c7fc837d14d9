// SPDX-License-Identifier: BSD-3-Clause
// Exact rescaling by powers of two (private).
#ifndef PW85_SRC_SCALING_HPP
#define PW85_SRC_SCALING_HPP

#include "sym.hpp"

namespace pw85::detail {

// The exponent e with |x| = m·2^e, m in [0.5, 1), read from the bits (a
// libm call per entry would cost more than the rest of the rescaling);
// frexp for zero and subnormals. x finite.
int exponent(double x) noexcept;

// 2^k, built from its bits when it is a normal double; ldexp otherwise.
double pow2(int k) noexcept;

// x·2^k, as std::ldexp(x, k) computes it, without a libm call when 2^k is a
// normal double.
double times_pow2(double x, int k) noexcept;

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

// Fills *s from finite input. Returns false when the diagonals of Q1 and
// Q2 span more than the range of a double, so that a rescaled diagonal
// entry overflows (decided from the exponents; an off-diagonal entry that
// overflows leaves the form indefinite, which its factorisation rejects).
template <int D>
bool rescale(double const *r, double const *q1, double const *q2,
             Scaled<D> *s) noexcept;

extern template bool rescale<2>(double const *, double const *,
                                double const *, Scaled<2> *) noexcept;
extern template bool rescale<3>(double const *, double const *,
                                double const *, Scaled<3> *) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_SCALING_HPP
