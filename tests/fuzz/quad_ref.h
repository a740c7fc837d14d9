/* SPDX-License-Identifier: BSD-3-Clause */
/* An independent reference of the contact function for the fuzz oracles,
 * in D = 3 (ellipsoids) or D = 2 (ellipses) dimensions: λ* and
 * μ² = f(λ*) in binary128 (__float128, 113 bits, exponents to ±16383: no
 * scaling needed for any finite double input), by bisection on the sign
 * of μ2² − μ1² (docs/optimisation.rst, eq. (5.4)), Q(λ)⁻¹r by an L·D·Lᵀ
 * factorisation in quad (fuzz::ldl()). Nothing of pw85 is used.
 * Its error is of order cond(Q(λ*))·2⁻¹¹³ relative: the oracles allow
 * that much (cond bounded by fuzz::cond_bound()). Header-only, C++. */
#ifndef PW85_FUZZ_QUAD_REF_H
#define PW85_FUZZ_QUAD_REF_H

#include <cmath>

#include "fuzz_common.h"

namespace fuzz {

typedef __float128 quad;

struct QuadRef {
  quad lambda;  // λ*
  quad other;   // 1 − λ*, kept apart: within 2⁻¹¹³ of 1, λ* rounds to 1
  quad mu2;     // f(λ*)
  bool ok;      // converged
};

/* The doubles of a vector or a form, in quad. */
template <int N>
struct QuadArray {
  quad v[N];
  explicit QuadArray(const double *x) {
    for (int i = 0; i < N; ++i) v[i] = x[i];
  }
};

/* s = Q⁻¹r for Q(λ) = m·Q1 + λ·Q2 by L·D·Lᵀ in quad (backward stable:
 * relative error of order cond(Q)·2⁻¹¹³; the adjugate would square the
 * condition number of a needle's minors), and κ̄ = tr(Q)·tr(Q⁻¹) ≥
 * cond(Q) if cond is not null. False when a pivot is not > 0. */
template <int D>
bool quad_solve(quad lam, quad m, const quad *r, const quad *q1,
                const quad *q2, quad *s, quad *cond) {
  quad q[sym_size(D)], l[D][D], p[D], tr_inv, tr = 0;
  for (int k = 0; k < sym_size(D); ++k) q[k] = m * q1[k] + lam * q2[k];
  if (!ldl<D>(q, l, p, cond != nullptr ? &tr_inv : nullptr)) return false;
  ldl_solve<D>(l, p, r, s);
  if (cond != nullptr) {
    for (int i = 0; i < D; ++i) tr += q[sym_at(D, i, i)];
    *cond = tr * tr_inv;
  }
  return true;
}

/* xᵀ·A·y for a stored symmetric form A. */
template <int D>
quad quad_bilinear(const quad *a, const quad *x, const quad *y) {
  quad sum = 0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) sum += a[sym_at(D, i, j)] * x[i] * y[j];
  return sum;
}

/* f(λ) and, if w is not null, w = μ2² − μ1² = λ²·P2 − (1−λ)²·P1 with
 * Pᵢ = sᵀQᵢs, s = Q(λ)⁻¹r (docs/optimisation.rst, eqs. (5.1a)–(5.4)),
 * whose sign is that of −f′ and which, unlike f′ = (1−2λ)·rᵀs −
 * λ(1−λ)·sᵀ(Q2−Q1)s, suffers no cancellation when one form is far larger
 * than the other (there f′'s terms cancel to 2^−750 of their size). False
 * when Q(λ) is singular in quad. */
template <int D>
bool quad_f(quad lam, const quad *r, const quad *q1, const quad *q2,
            quad *f, quad *w, quad m = -1) {
  if (m < 0) m = 1 - lam;  // 1 − λ, unless given (near 1)
  quad s[D], rs = 0;
  if (!quad_solve<D>(lam, m, r, q1, q2, s, nullptr)) return false;
  for (int i = 0; i < D; ++i) rs += r[i] * s[i];
  *f = lam * m * rs;
  if (w == nullptr) return true;
  *w = lam * lam * quad_bilinear<D>(q2, s, s) -
       m * m * quad_bilinear<D>(q1, s, s);
  return true;
}

/* λ* = argmax f on [0, 1] (f concave, f′(0) > 0 > f′(1) for r ≠ 0), by
 * bisection on the sign of w = μ2² − μ1² (quad_f()): first on the exponent, about the nearer end of
 * [0, 1], until the bracket's ends are within a factor 2 of each other
 * (λ* may lie 2^−1000 from an end), then halving, to 2^−110 relative.
 * About 130 evaluations; μ² = the larger f at the bracket's ends. */
template <int D = 3>
QuadRef quad_contact(const double *r12, const double *q1d,
                     const double *q2d) {
  QuadArray<D> const rr(r12);
  QuadArray<sym_size(D)> const qq1(q1d), qq2(q2d);
  const quad *r = rr.v, *q1 = qq1.v, *q2 = qq2.v;
  QuadRef out{0, 0, 0, false};
  quad f, w;
  if (!quad_f<D>(0.5Q, r, q1, q2, &f, &w)) return out;
  if (w == 0) return QuadRef{0.5Q, 0.5Q, f, true};
  // Work in t = distance to the nearer end: λ = t (left) or 1 − t, with
  // 1 − λ = t given exactly on the right.
  bool const left = w > 0;
  auto lambda_of = [&](quad t) { return left ? t : 1 - t; };
  auto eval = [&](quad t, quad *ff, quad *wt) {
    return quad_f<D>(lambda_of(t), r, q1, q2, ff, wt, left ? 1 - t : t);
  };
  // w > 0 (f′ < 0) at λ = t (left) means the root is below: t too large.
  auto too_far = [&](quad t, bool *fail) {
    quad ff, wt;
    if (!eval(t, &ff, &wt)) *fail = true;
    return left ? wt > 0 : wt < 0;
  };
  bool fail = false;
  quad lo = 0, hi = 0.5Q;  // the root's t lies in (lo, hi)
  // Exponent phase: t = hi/2^k for k = 1, 2, 4, …, then bisect k.
  int k = 1, klo = 0, khi = -1;  // hi·2^−klo too far, hi·2^−khi not
  quad p = 0.5Q;
  while (khi < 0) {
    quad const t = hi * p;
    if (!(t > 0)) return out;  // below quad's range: not this input
    if (too_far(t, &fail)) {
      klo = k;
      k *= 2;
      p = 1;
      for (int j = 0; j < k; ++j) p /= 2;
    } else {
      khi = k;
    }
    if (fail || k > 32768) return out;
  }
  while (khi - klo > 1) {
    int const km = (klo + khi) / 2;
    quad t = hi;
    for (int j = 0; j < km; ++j) t /= 2;
    if (too_far(t, &fail)) klo = km; else khi = km;
    if (fail) return out;
  }
  quad tlo = hi, thi = hi;
  for (int j = 0; j < khi; ++j) tlo /= 2;
  for (int j = 0; j < klo; ++j) thi /= 2;
  lo = tlo;
  hi = thi;  // not too far at lo, too far at hi, hi = 2·lo (or hi = ½)
  for (int it = 0; it < 120 && hi - lo > lo * 0x1p-110Q; ++it) {
    quad const t = (lo + hi) / 2;
    if (too_far(t, &fail)) hi = t; else lo = t;
    if (fail) return out;
  }
  quad flo, fhi;
  if (!eval(lo, &flo, nullptr) || !eval(hi, &fhi, nullptr)) return out;
  out.lambda = lambda_of((lo + hi) / 2);
  out.other = left ? 1 - (lo + hi) / 2 : (lo + hi) / 2;
  out.mu2 = flo > fhi ? flo : fhi;
  out.ok = true;
  return out;
}

/* The contact geometry and the derivatives of μ² at λ (the reference λ*),
 * in quad (theory: x − c1 = (1−λ)·Q1·s, n = s/‖s‖, ∂μ²/∂r12 = 2λ(1−λ)·s,
 * ∂μ²/∂ω1 = 2λ(1−λ)²·s × Q1s, ∂μ²/∂ω2 = 2λ²(1−λ)·s × Q2s, the cross
 * product a scalar in 2D (∂μ²/∂θᵢ); ∂μ²/∂q1[k] = −λ(1−λ)²·sᵢsⱼ,
 * ∂μ²/∂q2[k] = −λ²(1−λ)·sᵢsⱼ, twice that off the diagonal, k the entry
 * (i, j); pw85.h, pw85_2d.h), and κ̄ = tr(Q(λ))·tr(Q(λ)⁻¹) ≥ cond(Q(λ)).
 * False when Q(λ) is singular. */
template <int D>
struct QuadGeometry {
  static constexpr int rot = D == 3 ? 3 : 1;
  quad point[D], point2[D], normal[D], d_r12[D], rot1[rot], rot2[rot];
  quad d_q1[sym_size(D)], d_q2[sym_size(D)];
  quad cond;
};

template <int D>
bool quad_geometry(quad lam, quad m, const double *r12, const double *q1d,
                   const double *q2d, QuadGeometry<D> *g) {  // m = 1 − λ
  QuadArray<D> const rr(r12);
  QuadArray<sym_size(D)> const qq1(q1d), qq2(q2d);
  quad s[D], t1[D], t2[D];
  if (!quad_solve<D>(lam, m, rr.v, qq1.v, qq2.v, s, &g->cond)) return false;
  for (int i = 0; i < D; ++i) {  // tᵢ = Qᵢ·s
    quad e[D] = {};
    e[i] = 1;
    t1[i] = quad_bilinear<D>(qq1.v, e, s);
    t2[i] = quad_bilinear<D>(qq2.v, e, s);
  }
  // a × b: (a × b)ₖ for k < rot (the scalar a0·b1 − a1·b0 in 2D).
  auto cross = [](const quad *a, const quad *b, int k) {
    int const i = D == 3 ? (k + 1) % 3 : 0, j = D == 3 ? (k + 2) % 3 : 1;
    return a[i] * b[j] - a[j] * b[i];
  };
  quad ss = 0;
  for (int i = 0; i < D; ++i) ss += s[i] * s[i];
  quad const ns = (quad)sqrtl((long double)ss);
  for (int i = 0; i < D; ++i) {
    g->point[i] = m * t1[i];
    g->point2[i] = -lam * t2[i];  // x − c2 (theory, eq. (3.9b)), no cancellation
    g->normal[i] = s[i] / ns;
    g->d_r12[i] = 2 * lam * m * s[i];
  }
  for (int k = 0; k < g->rot; ++k) {
    g->rot1[k] = 2 * lam * m * m * cross(s, t1, k);
    g->rot2[k] = 2 * lam * lam * m * cross(s, t2, k);
  }
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j) {
      quad const ssij = (i == j ? 1 : 2) * s[i] * s[j];
      g->d_q1[sym_at(D, i, j)] = -lam * m * m * ssij;
      g->d_q2[sym_at(D, i, j)] = -lam * lam * m * ssij;
    }
  return true;
}

}  // namespace fuzz

#endif /* PW85_FUZZ_QUAD_REF_H */
