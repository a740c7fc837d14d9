// SPDX-License-Identifier: BSD-3-Clause
// The contact geometry and the derivatives of μ² (geometry.hpp). Everything
// is computed in the problem of the search (rescaled, oriented), then mapped
// to the input: swapping the ellipsoids then mirrors every output bit for
// bit (but the contact point, which is measured from the other centre).
#include "geometry.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "checks.hpp"
#include "compensated.hpp"
#include "compiler.hpp"
#include "contact.hpp"
#include "dd.hpp"
#include "evaluate.hpp"
#include "polish.hpp"
#include "scaling.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

namespace {

// Q·s for s = s + s_lo, as t + t_lo (t = the rounded value).
template <int D>
PW85_INLINE void sym_mul_dd(double const *q, double const *s,
                            double const *s_lo, double *t,
                            double *t_lo) noexcept {
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    Dot2 acc{0.0, 0.0};
    double tail = 0.0;
    PW85_UNROLL
    for (int j = 0; j < D; ++j) {
      double const qij = q[sym_index<D>(i, j)];
      acc.add_product(qij, s[j]);
      tail += qij * s_lo[j];
    }
    dd const v = two_sum(acc.sum, acc.err + tail);
    t[i] = v.hi;
    t_lo[i] = v.lo;
  }
}

// a × b for a = a + a_lo, b = b + b_lo, each component as in twice the
// working precision then rounded: no cancellation error when a is nearly
// parallel to b (s nearly an eigenvector of Qᵢ, for instance). In 2D the
// one component a0·b1 − a1·b0 (that along z of vectors of the plane).
template <int D>
PW85_INLINE void cross_dd(double const *a, double const *a_lo,
                          double const *b, double const *b_lo,
                          double *c) noexcept {
  PW85_UNROLL
  for (int n = 0; n < Outputs<D>::rot_size; ++n) {
    int const i = D == 3 ? n : 2;  // the component
    int const j = (i + 1) % 3, k = (i + 2) % 3;
    Dot2 acc{0.0, 0.0};
    acc.add_product(a[j], b[k]);
    acc.add_product(-a[k], b[j]);
    acc.err += (a[j] * b_lo[k] + a_lo[j] * b[k]) -
               (a[k] * b_lo[j] + a_lo[k] * b[j]);
    c[n] = acc.value();
  }
}

// x = m·2^e exactly, m in [1/2, 1) (m = 0 for x = 0); products keep
// the mantissa in [1/4, 1) and add the exponents, so that no product of
// weights underflows.
struct Pow2Split {
  double m;
  int e;
  Pow2Split operator*(Pow2Split o) const noexcept { return {m * o.m, e + o.e}; }
};

PW85_INLINE Pow2Split split_pow2(double x) noexcept {
  int const e = exponent(x);
  return {times_pow2(x, -e), e};
}

// x · 2^k for the n entries of x.
PW85_INLINE void scale_back(double *x, int n, int k) noexcept {
  PW85_UNROLL
  for (int i = 0; i < n; ++i) x[i] = times_pow2(x[i], k);
}

PW85_INLINE bool any_infinite(double const *x, int n) noexcept {
  PW85_UNROLL
  for (int i = 0; i < n; ++i)
    if (std::isinf(x[i])) return true;
  return false;
}

// The largest |xᵢ| of the D entries of x.
template <int D>
PW85_INLINE double max_abs(double const *x) noexcept {
  double m = std::fabs(x[0]);
  PW85_UNROLL
  for (int i = 1; i < D; ++i) m = std::max(m, std::fabs(x[i]));
  return m;
}

// The largest diagonal entry of a symmetric D × D form.
template <int D>
PW85_INLINE double max_diagonal(double const *q) noexcept {
  double m = q[0];
  PW85_UNROLL
  for (int i = 1; i < D; ++i) m = std::max(m, q[Layout<D>::diag[i]]);
  return m;
}

// Steps after the search: the polish of λ, s, and every output, into out
// and der (scaled back to the input's units). Returns false when no s can
// be solved for (far beyond the domain).
template <int D>
PW85_INLINE bool output_steps(Contact<D> const &c, double *out,
                              double *der) noexcept {
  using O = Outputs<D>;
  constexpr int sym = sym_size(D);
  using L = Layout<D>;
  out[O::mu2] = c.mu2;
  out[O::lambda] = 0.5;
  if (!c.p.r_is_zero) {
    // λ' and s of the problem; (1 − λ', Q1') and (λ', Q2') are the weights
    // and forms of (9a) and (9b) in the problem's orientation. Where the
    // search's orientation (the sphere model's side of ½) was wrong, λ' > ½,
    // the polish continues with the forms exchanged, from 1 − λ' (exact):
    // near 1, λ' carries only ulp(1)/(1 − λ') of 1 − λ' relative, and s,
    // hence x, moves with λ by up to ‖Q2 − Q1‖/‖Q(λ)‖ times that (λ 5e-14
    // relative off at λ* = 1 − 1.0e-3, and x − c1 14·u·cond(Q(λ)) off:
    // tests/fuzz/open/geometry/point-e9ebfbf5).
    Problem<D> p = c.p;
    double lambda =
        p.moderate ? polish<true>(p, c.lambda) : polish<false>(p, c.lambda);
    if (lambda > 0.5) {
      exchange_forms(&p);
      lambda = p.moderate ? polish<true>(p, 1.0 - lambda)
                          : polish<false>(p, 1.0 - lambda);
    }
    double s[D], s_lo[D];
    if (!solve_accurately(p, lambda, s, s_lo)) return false;
    // Everything below is computed from s·2^−es, Q1'·2^−e1 and Q2'·2^−e2,
    // each of magnitude below 1 (exact scalings by powers of two, each form
    // by its own exponent, so that a form far smaller than the other keeps
    // its digits), and from the weights λ^i·(1 − λ)^j split into a
    // mantissa and a power of two: no product overflows or underflows
    // whatever the input's range (a torque of order 2^−369 stays a normal
    // double); the exponents are put back at the end, once.
    int const es = exponent(max_abs<D>(s));
    int const e1 = exponent(max_diagonal<D>(p.q1));
    int const e2 = exponent(max_diagonal<D>(p.q2));
    double q1[sym], q2[sym];
    PW85_UNROLL
    for (int k = 0; k < sym; ++k) {
      q1[k] = times_pow2(p.q1[k], -e1);
      q2[k] = times_pow2(p.q2[k], -e2);
    }
    PW85_UNROLL
    for (int i = 0; i < D; ++i) {
      s[i] = times_pow2(s[i], -es);
      s_lo[i] = times_pow2(s_lo[i], -es);
    }
    double const u = lambda, v = 1.0 - lambda;
    double t1[D], t1_lo[D], t2[D], t2_lo[D];
    sym_mul_dd<D>(q1, s, s_lo, t1, t1_lo);  // Q1'·s, scaled
    sym_mul_dd<D>(q2, s, s_lo, t2, t2_lo);  // Q2'·s, scaled
    // Weights as m·2^e, m in [1/2, 1): λ, 1 − λ, λ(1 − λ), λ(1 − λ)² (of
    // Q1') and λ²(1 − λ) (of Q2'); the products of mantissas are exact
    // to rounding and far from underflow.
    Pow2Split const wu = split_pow2(u), wv = split_pow2(v);
    Pow2Split const w = wu * wv, w1 = w * wv, w2 = w * wu;
    // s is that of the input (Q'(λ') = Q(λ), r unchanged), and x − c1 is
    // (1 − λ)·Q1·s (9a) in the input's terms: (1 − λ')·Q1'·s, or λ'·Q2'·s
    // when the problem is swapped.
    double *point = out + O::point;
    PW85_UNROLL
    for (int i = 0; i < D; ++i)
      point[i] = p.swapped ? wu.m * t2[i] : wv.m * t1[i];
    int const point_exp = p.swapped ? wu.e + e2 : wv.e + e1;
    // n = s/‖s‖ (s scaled: no square overflows).
    double const norm = std::sqrt(dot<D>(s, s));
    PW85_UNROLL
    for (int i = 0; i < D; ++i) out[O::normal + i] = s[i] / norm;
    out[O::lambda] = p.swapped ? v : u;
    // The envelope theorem: ∂μ²/∂y = ∂f/∂y at λ* for every input y.
    PW85_UNROLL
    for (int i = 0; i < D; ++i) der[O::r12 + i] = 2.0 * w.m * s[i];
    double rot1[O::rot_size], rot2[O::rot_size];
    cross_dd<D>(s, s_lo, t1, t1_lo, rot1);
    cross_dd<D>(s, s_lo, t2, t2_lo, rot2);
    int const first = p.swapped ? O::rot2 : O::rot1;
    int const second = p.swapped ? O::rot1 : O::rot2;
    PW85_UNROLL
    for (int i = 0; i < O::rot_size; ++i) {
      der[first + i] = 2.0 * w1.m * rot1[i];
      der[second + i] = 2.0 * w2.m * rot2[i];
    }
    int const first_q = p.swapped ? O::q2 : O::q1;
    int const second_q = p.swapped ? O::q1 : O::q2;
    PW85_UNROLL
    for (int k = 0; k < sym; ++k) {
      // ∂(sᵀQs)/∂q[k]: s_i², or 2·s_i·s_j for an off-diagonal entry.
      double const factor = L::row[k] == L::col[k] ? 1.0 : 2.0;
      double const ss = factor * s[L::row[k]] * s[L::col[k]];
      der[first_q + k] = -w1.m * ss;
      der[second_q + k] = -w2.m * ss;
    }
    // Back to the input's scale: r = r'·2^a, Q = Q'·2^b, so s = s'·2^(a−b),
    // x − c1 scales as r, ∂μ²/∂r as s, ∂μ²/∂ω as μ², ∂μ²/∂q as s²; and the
    // scalings by 2^es, 2^e1, 2^e2 and of the weights above.
    int const a = p.r_exp, b = p.q_exp;
    scale_back(point, D, a + point_exp + es);
    scale_back(der + O::r12, D, a - b + es + w.e);
    scale_back(der + first, O::rot_size, 2 * a - b + 2 * es + e1 + w1.e);
    scale_back(der + second, O::rot_size, 2 * a - b + 2 * es + e2 + w2.e);
    scale_back(der + first_q, sym, 2 * (a - b + es) + w1.e);
    scale_back(der + second_q, sym, 2 * (a - b + es) + w2.e);
  }
  return true;
}

// output_steps() for each dimension, compiled for CPUs with and without
// FMA (the double-double kernels use std::fma).
PW85_FMA_CLONES
bool outputs(Contact<2> const &c, double *out, double *der) noexcept {
  return output_steps(c, out, der);
}

PW85_FMA_CLONES
bool outputs(Contact<3> const &c, double *out, double *der) noexcept {
  return output_steps(c, out, der);
}

}  // namespace

template <int D>
Status contact_geometry(double const *r, double const *q1, double const *q2,
                        double *geometry, double *d) noexcept {
  using O = Outputs<D>;
  Contact<D> c;
  Status const status = contact_search(r, q1, q2, &c);
  if (status != Status::success) return status;
  double out[O::size] = {0.0};
  double der[O::deriv_size] = {0.0};
  if (!outputs(c, out, der)) return Status::out_of_range;
  bool const overflow = std::isinf(out[O::mu2]) ||
                        any_infinite(out + O::point, D) ||
                        (d != nullptr && any_infinite(der, O::deriv_size));
  PW85_UNROLL
  for (int i = 0; i < O::size; ++i) geometry[i] = out[i];
  if (d != nullptr)
    PW85_UNROLL
    for (int i = 0; i < O::deriv_size; ++i) d[i] = der[i];
  return overflow ? Status::out_of_range : Status::success;
}

template Status contact_geometry<2>(double const *, double const *,
                                    double const *, double *,
                                    double *) noexcept;
template Status contact_geometry<3>(double const *, double const *,
                                    double const *, double *,
                                    double *) noexcept;

}  // namespace pw85::detail
