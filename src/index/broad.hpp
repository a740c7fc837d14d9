// SPDX-License-Identifier: BSD-3-Clause
// The broad phase of the spatial index, written once for the queries on a
// candidate (index.cpp) and the all-pairs queries (pairs.cpp), which are
// its visitors (private; docs/assemblies.rst, "Why the answers are
// certified"; every margin: margins.hpp):
// - the reach of a query and the cells it covers (reach_of(),
//   cell_range());
// - the image shifts within reach of a stored centre (for_each_shift());
// - the box test, on the image vector r̂ formed in double (boxes_meet());
// - the line-of-centres test (separated_along_r());
// - the narrow phase, on the image vector formed exactly
//   (image_vector_exact(), image_overlap(), image_contact()).
//
// Box test: the axis-aligned bounding box (AABB) of {x : xᵀQ⁻¹x ≤ 1} has
// half-widths h_k = √Q_kk exactly, and that of the ellipsoid scaled by √t
// half-widths √t·h_k; two scaled ellipsoids that meet have meeting AABBs,
// so |r_k| > √t·(h_k + h'_k) for some k proves μ² > t.
#ifndef PW85_SRC_INDEX_BROAD_HPP
#define PW85_SRC_INDEX_BROAD_HPP

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "compiler.hpp"
#include "contact.hpp"
#include "dd.hpp"
#include "margins.hpp"
#include "overlap.hpp"
#include "scaling.hpp"
#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// The index is written once for D = 2 and 3 (namespace spatial, every
// template on D); the 3D names of the rest of the core (Index, Entry, ...)
// are aliases of its D = 3 (index.hpp).
namespace spatial {

// The AABB half-widths √Q_kk of a positive definite q.
template <int D>
PW85_INLINE void half_widths(double const *q, double *h) noexcept {
  for (int k = 0; k < D; ++k) h[k] = std::sqrt(q[Layout<D>::diag[k]]);
}

// The absolute rounding allowance σ_k of a query along an axis
// (margins.hpp, slack_factor).
inline double rounding_slack(double cmax, double c, double reach,
                             double box) noexcept {
  return slack_factor * (cmax + std::fabs(c) + reach + box);
}

// The bound of the box test along an axis, √t·(h + h')·(1 + broad_margin).
inline double box_bound(double sqrt_t, double h1, double h2) noexcept {
  return sqrt_t * (h1 + h2) * (1.0 + broad_margin);
}

// A query's extent in a level of the grid (or a grid of the snapshot),
// per axis: the largest bound of its box tests there (its h and the
// level's largest), and the slack σ_k; slack_sum = Σσ_k.
template <int D>
struct Reach {
  double reach[D];
  double slack[D];
  double slack_sum;
};

// box: the sides, or zeros in an open domain.
template <int D>
inline Reach<D> reach_of(double const *c, double const *h,
                         double const *hmax, double sqrt_t, double cmax,
                         double const *box) noexcept {
  Reach<D> rc;
  rc.slack_sum = 0.0;
  for (int k = 0; k < D; ++k) {
    rc.reach[k] = box_bound(sqrt_t, h[k], hmax[k]);
    rc.slack[k] = rounding_slack(cmax, c[k], rc.reach[k], box[k]);
    rc.slack_sum += rc.slack[k];
  }
  return rc;
}

// The cells along each axis that hold the centres within reach of c:
// [lo_k, hi_k], ⌊(c_k − origin_k ∓ (reach_k + σ_k))·inv_k⌋, clamped to
// [first_k, last_k] (an open domain's clamp; ±∞ for none). The cell of a
// centre x is ⌊(x − origin)·inv⌋ clamped alike (monotone in x). Returns
// the number of cells of the block.
template <int D>
inline double cell_range(Reach<D> const &rc, double const *c,
                         double const *origin, double const *inv,
                         double const *first, double const *last,
                         double *lo, double *hi) noexcept {
  double cells = 1.0;
  for (int k = 0; k < D; ++k) {
    double const x = c[k] - origin[k], w = rc.reach[k] + rc.slack[k];
    lo[k] = std::min(std::max(std::floor((x - w) * inv[k]), first[k]), last[k]);
    hi[k] = std::min(std::max(std::floor((x + w) * inv[k]), first[k]), last[k]);
    cells *= hi[k] - lo[k] + 1.0;
  }
  return cells;
}

// The image shifts n of a stored centre cj whose images cj + n∘L may be
// within reach + slack of c along each axis: [lo_k, hi_k] (a superset: the
// box test decides). Open domain: n = 0. Returns false when an axis spans
// more than max_span shifts.
template <int D>
inline bool shift_range(bool periodic, double const *c, double const *reach,
                        double const *slack, double const *cj,
                        double const *box, std::int64_t *lo,
                        std::int64_t *hi) noexcept {
  for (int k = 0; k < D; ++k) {
    lo[k] = hi[k] = 0;
    if (!periodic) continue;
    double const w = reach[k] + slack[k];
    double const a = std::floor((c[k] - w - cj[k]) / box[k]);
    double const b = std::floor((c[k] + w - cj[k]) / box[k]) + 1.0;
    if (b - a + 1.0 > max_span) return false;
    lo[k] = static_cast<std::int64_t>(a);
    hi[k] = static_cast<std::int64_t>(b);
  }
  return true;
}

// The loop over the shifts along axis K, nesting those along the axes
// after it (D nested loops once inlined): for_each_shift().
template <int D, int K, typename F>
PW85_INLINE bool shifts_along(std::int64_t const *lo, std::int64_t const *hi,
                              std::int32_t *shift, F &f) noexcept {
  for (std::int64_t a = lo[K]; a <= hi[K]; ++a) {
    shift[K] = std::int32_t(a);
    if constexpr (K + 1 < D) {
      if (!shifts_along<D, K + 1>(lo, hi, shift, f)) return false;
    } else if (!f(static_cast<std::int32_t const *>(shift))) {
      return false;
    }
  }
  return true;
}

// Calls f(shift) for every shift of [lo, hi] (lexicographic order) until
// f returns false; returns false then.
template <int D, typename F>
PW85_INLINE bool for_each_shift(std::int64_t const *lo, std::int64_t const *hi,
                                F &&f) noexcept {
  std::int32_t shift[D];
  return shifts_along<D, 0>(lo, hi, shift, f);
}

// The box test on r̂ = (c_j + n∘L) − c formed in double (written to r):
// false proves μ² > t·(1 + broad_margin) (margins.hpp: the slack covers
// the rounding of r̂). box: the sides, or zeros in an open domain.
// Without a branch per axis (a mispredicted exit per scanned entry cost
// more than the test): the excess |r̂_k| − bound_k of every axis, and
// their maximum. fl(a − b) has the sign of a − b (rounding is monotone,
// and a difference of doubles is 0 only when they are equal), so this
// rejects exactly the pairs the axis-by-axis test rejects; a NaN from
// inf − inf only keeps a pair (std::max passes over it or returns it).
template <int D>
PW85_INLINE bool boxes_meet(double const *c, double const *h, double const *cj,
                            double const *hj, std::int32_t const *shift,
                            double const *box, double sqrt_t,
                            double const *slack, double *r) noexcept {
  double excess[D];
  PW85_UNROLL
  for (int k = 0; k < D; ++k) {
    r[k] = (cj[k] + shift[k] * box[k]) - c[k];
    excess[k] = std::fabs(r[k]) - (box_bound(sqrt_t, h[k], hj[k]) + slack[k]);
  }
  PW85_UNROLL
  for (int k = 1; k < D; ++k) excess[0] = std::max(excess[0], excess[k]);
  return !(excess[0] > 0.0);
}

namespace line {

// The bound √(rᵀQr) + √(rᵀQ'r) of the line test, each term raised by its
// rounding (form_rounding) and by form_floor (underflow).
template <int D>
PW85_INLINE double projections(double const *r, double const *q1,
                               double const *h1, double const *q2,
                               double const *h2) noexcept {
  double y[D];
  sym_mul<D>(q1, r, y);
  double const a1 = dot<D>(r, y);
  sym_mul<D>(q2, r, y);
  double const a2 = dot<D>(r, y);
  double b1 = 0.0, b2 = 0.0;
  for (int k = 0; k < D; ++k) {
    double const x = std::fabs(r[k]);
    b1 += h1[k] * x;
    b2 += h2[k] * x;
  }
  return std::sqrt(a1 + form_rounding * b1 * b1 + form_floor) +
         std::sqrt(a2 + form_rounding * b2 * b2 + form_floor);
}

// The test proper on r (with |r|² = d2) and the slack Σσ_k.
template <int D>
PW85_INLINE bool separated(double const *r, double d2, double const *q1,
                           double const *h1, double const *q2,
                           double const *h2, double sqrt_t,
                           double slack_sum) noexcept {
  if (!(slack_sum * slack_sum <= slack_fold * slack_fold * d2)) return false;
  return d2 > sqrt_t * projections<D>(r, q1, h1, q2, h2) * (1.0 + broad_margin);
}

// The test on r and the forms scaled by powers of two, r to order one
// (a length scale far from one: margins.hpp, line_low).
template <int D>
bool separated_scaled(double const *r, double const *q1, double const *h1,
                      double const *q2, double const *h2, double sqrt_t,
                      double slack_sum) noexcept;
extern template bool separated_scaled<2>(double const *, double const *,
                                         double const *, double const *,
                                         double const *, double,
                                         double) noexcept;
extern template bool separated_scaled<3>(double const *, double const *,
                                         double const *, double const *,
                                         double const *, double,
                                         double) noexcept;

}  // namespace line

// The line-of-centres test, for images whose AABBs meet: are the
// projections of the two ellipsoids scaled by √t on the line of centres
// disjoint? The projection of {x : xᵀQ⁻¹x ≤ 1} on a unit vector u has
// half-width √(uᵀQu); with u = r/|r|, a plane normal to r separates the
// scaled ellipsoids when |r|² > √t·(√(rᵀQ1r) + √(rᵀQ2r)), and then μ² > t.
// Any u is valid: u = r̂/|r̂| from the r̂ of the box test, whose rounding
// the slack Σσ_k bounds (margins.hpp, slack_fold). True means
// μ² > t·(1 + broad_margin) at every length scale: outside
// [line_low, line_high], r̂ and the forms are scaled first.
template <int D>
PW85_INLINE bool separated_along_r(double const *r, double const *q1,
                                   double const *h1, double const *q2,
                                   double const *h2, double sqrt_t,
                                   double slack_sum) noexcept {
  double const d2 = dot<D>(r, r);
  if (PW85_UNLIKELY(!(d2 >= line_low && d2 <= line_high)))
    return line::separated_scaled<D>(r, q1, h1, q2, h2, sqrt_t, slack_sum);
  return line::separated<D>(r, d2, q1, h1, q2, h2, sqrt_t, slack_sum);
}

// The image vector r = (c_j + n∘L) − c, formed exactly (an error-free
// transformation: n_k·L_k by a fused multiply-add, the sums by two_sum()):
// r + lo, a double-double, |lo_k| ≤ ulp(r_k)/2, equal to the exact vector
// within 2⁻¹⁰⁵·|r_k| + 2⁻²⁰⁰·(|c_j,k| + |n_k·L_k| + |c_k|) along each axis
// (exactly, in the common case where c_j + n_k·L_k is a double). exact:
// lo = 0, r̂ of the box test was exact. box: zeros in an open domain.
template <int D>
struct ImageVector {
  double r[D];
  double lo[D];
  bool exact;
};

// The rare case of image_vector_exact(): r = b + b_lo + a_lo + p_lo
// exactly, the last two not zero.
void image_vector_tail(double b, double b_lo, double a_lo, double p_lo,
                       double *r, double *lo) noexcept;

template <int D>
PW85_INLINE void image_vector_exact(double const *c, double const *cj,
                                    std::int32_t const *shift,
                                    double const *box,
                                    ImageVector<D> *v) noexcept {
  bool exact = true;
  for (int k = 0; k < D; ++k) {
    if (shift[k] == 0) {  // the most common case: c_j − c
      dd const b = two_sum(cj[k], -c[k]);
      v->r[k] = b.hi;
      v->lo[k] = b.lo;
    } else {
      double const n = shift[k];
      double const p = n * box[k];
      double const p_lo = std::fma(n, box[k], -p);  // n·L = p + p_lo
      dd const a = two_sum(cj[k], p);               // c_j + p
      dd const b = two_sum(a.hi, -c[k]);            // a.hi − c
      if (PW85_UNLIKELY(a.lo != 0.0 || p_lo != 0.0)) {
        image_vector_tail(b.hi, b.lo, a.lo, p_lo, &v->r[k], &v->lo[k]);
      } else {
        v->r[k] = b.hi;
        v->lo[k] = b.lo;
      }
    }
    exact = exact && v->lo[k] == 0.0;
  }
  v->exact = exact;
}

// The narrow phase on an exact image vector: pw85_overlap()'s decision and
// pw85_contact_function()'s μ² and λ for the exact r (overlap_dd(),
// contact_function_dd()), through the double paths when r is a double.
template <int D>
inline Status image_overlap(ImageVector<D> const &v, double const *q1,
                            double const *q2, int *result) noexcept {
  return v.exact ? overlap<D>(v.r, q1, q2, result)
                 : overlap_dd<D>(v.r, v.lo, q1, q2, result);
}

template <int D>
inline Status image_contact(ImageVector<D> const &v, double const *q1,
                            double const *q2, double out[2]) noexcept {
  return v.exact ? contact_function<D>(v.r, q1, q2, out)
                 : contact_function_dd<D>(v.r, v.lo, q1, q2, out);
}

}  // namespace spatial

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_BROAD_HPP
