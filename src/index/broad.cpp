// SPDX-License-Identifier: BSD-3-Clause
// The rare paths of the broad phase (broad.hpp), out of line.
#include "broad.hpp"

#include <algorithm>

namespace pw85::detail::spatial {

template <int D>
bool line::separated_scaled(double const *r, double const *q1,
                            double const *h1, double const *q2,
                            double const *h2, double sqrt_t,
                            double slack_sum) noexcept {
  // The test is homogeneous: r, h, the slack scaled by 2^k and the forms
  // by 2^2k leave both sides scaled by 2^2k. k brings max |r_k| to [½, 1)
  // (|r|² ≥ ¼); ldexp is exact but where a result leaves the range of
  // doubles (margins.hpp, form_floor).
  double m = std::fabs(r[0]);
  for (int i = 1; i < D; ++i) m = std::max(m, std::fabs(r[i]));
  if (!(m > 0.0)) return false;  // coincident centres: not separated
  int const k = -exponent(m);
  constexpr int S = sym_size(D);
  double rs[D], g1[D], g2[D], p1[S], p2[S];
  for (int i = 0; i < D; ++i) {
    rs[i] = std::ldexp(r[i], k);
    g1[i] = std::ldexp(h1[i], k);
    g2[i] = std::ldexp(h2[i], k);
  }
  for (int i = 0; i < S; ++i) {
    p1[i] = std::ldexp(q1[i], 2 * k);
    p2[i] = std::ldexp(q2[i], 2 * k);
  }
  return separated<D>(rs, dot<D>(rs, rs), p1, g1, p2, g2, sqrt_t,
                      std::ldexp(slack_sum, k));
}

template bool line::separated_scaled<2>(double const *, double const *,
                                        double const *, double const *,
                                        double const *, double,
                                        double) noexcept;
template bool line::separated_scaled<3>(double const *, double const *,
                                        double const *, double const *,
                                        double const *, double,
                                        double) noexcept;

void image_vector_tail(double b, double b_lo, double a_lo, double p_lo,
                       double *r, double *lo) noexcept {
  // Every step is exact (two_sum()) but the last sum of the two least
  // terms, below 2⁻¹⁰⁵ of the result and 2⁻²⁰⁰ of the centres' magnitudes
  // (each tail term is below u² times the one before it).
  dd const t = two_sum(a_lo, p_lo);
  dd const u = two_sum(b_lo, t.hi);
  dd const h = two_sum(b, u.hi);    // r = h.hi + h.lo + u.lo + t.lo
  dd const w = two_sum(u.lo, t.lo);
  dd const x = two_sum(h.lo, w.hi);  // r = h.hi + x.hi + x.lo + w.lo
  dd const f = two_sum(h.hi, x.hi);
  dd const out = two_sum(f.hi, f.lo + (x.lo + w.lo));
  *r = out.hi;
  *lo = out.lo;
}

}  // namespace pw85::detail::spatial
