/* SPDX-License-Identifier: BSD-3-Clause */
/* An independent reference of the contact function for the fuzz oracles:
 * λ* and μ² = f(λ*) in binary128 (__float128, 113 bits, exponents to
 * ±16383: no scaling needed for any finite double input), by bisection
 * on the sign of μ2² − μ1² (docs/optimisation.rst, eq. (5.4)), Q(λ)⁻¹r
 * by an L·D·Lᵀ factorisation in quad. Nothing of pw85 is used.
 * Its error is of order cond(Q(λ*))·2⁻¹¹³ relative: the oracles allow
 * that much (cond bounded by fuzz::cond_bound()). Header-only, C++. */
#ifndef PW85_FUZZ_QUAD_REF_H
#define PW85_FUZZ_QUAD_REF_H

#include <cmath>

namespace fuzz {

typedef __float128 quad;

struct QuadRef {
  quad lambda;  // λ*
  quad other;   // 1 − λ*, kept apart: within 2⁻¹¹³ of 1, λ* rounds to 1
  quad mu2;     // f(λ*)
  bool ok;      // converged
};

/* s = Q⁻¹r for Q(λ) = m·Q1 + λ·Q2 by L·D·Lᵀ in quad (backward stable:
 * relative error of order cond(Q)·2⁻¹¹³; the adjugate would square the
 * condition number of a needle's minors), and κ̄ = tr(Q)·tr(Q⁻¹) ≥
 * cond(Q) if cond is not null. False when a pivot is not > 0. */
inline bool quad_solve(quad lam, quad m, const quad r[3], const quad q1[6],
                       const quad q2[6], quad s[3], quad *cond) {
  quad q[6];
  for (int k = 0; k < 6; ++k) q[k] = m * q1[k] + lam * q2[k];
  quad const d0 = q[0];
  if (!(d0 > 0)) return false;
  quad const l10 = q[1] / d0, l20 = q[2] / d0;
  quad const d1 = q[3] - l10 * q[1];
  if (!(d1 > 0)) return false;
  quad const l21 = (q[4] - l10 * q[2]) / d1;
  quad const d2 = q[5] - l20 * q[2] - l21 * l21 * d1;
  if (!(d2 > 0)) return false;
  quad const z0 = r[0], z1 = r[1] - l10 * z0, z2 = r[2] - l20 * z0 - l21 * z1;
  s[2] = z2 / d2;
  s[1] = z1 / d1 - l21 * s[2];
  s[0] = z0 / d0 - l10 * s[1] - l20 * s[2];
  if (cond != nullptr) {
    quad const m20 = l10 * l21 - l20;
    *cond = (q[0] + q[3] + q[5]) *
            (1 / d0 + (1 + l10 * l10) / d1 + (1 + l21 * l21 + m20 * m20) / d2);
  }
  return true;
}

/* f(λ) and, if w is not null, w = μ2² − μ1² = λ²·P2 − (1−λ)²·P1 with
 * Pᵢ = sᵀQᵢs, s = Q(λ)⁻¹r (docs/optimisation.rst, eqs. (5.1a)–(5.4)),
 * whose sign is that of −f′ and which, unlike f′ = (1−2λ)·rᵀs −
 * λ(1−λ)·sᵀ(Q2−Q1)s, suffers no cancellation when one form is far larger
 * than the other (there f′'s terms cancel to 2^−750 of their size). False
 * when Q(λ) is singular in quad. */
inline bool quad_f(quad lam, const quad r[3], const quad q1[6],
                   const quad q2[6], quad *f, quad *w, quad m = -1) {
  if (m < 0) m = 1 - lam;  // 1 − λ, unless given (near 1)
  quad s[3];
  if (!quad_solve(lam, m, r, q1, q2, s, nullptr)) return false;
  quad const rs = r[0] * s[0] + r[1] * s[1] + r[2] * s[2];
  *f = lam * m * rs;
  if (w == nullptr) return true;
  auto form = [&](const quad x[6]) {
    return x[0] * s[0] * s[0] + x[3] * s[1] * s[1] + x[5] * s[2] * s[2] +
           2 * (x[1] * s[0] * s[1] + x[2] * s[0] * s[2] + x[4] * s[1] * s[2]);
  };
  *w = lam * lam * form(q2) - m * m * form(q1);
  return true;
}

/* λ* = argmax f on [0, 1] (f concave, f′(0) > 0 > f′(1) for r ≠ 0), by
 * bisection on the sign of w = μ2² − μ1² (quad_f()): first on the exponent, about the nearer end of
 * [0, 1], until the bracket's ends are within a factor 2 of each other
 * (λ* may lie 2^−1000 from an end), then halving, to 2^−110 relative.
 * About 130 evaluations; μ² = the larger f at the bracket's ends. */
inline QuadRef quad_contact(const double r12[3], const double q1d[6],
                            const double q2d[6]) {
  quad r[3], q1[6], q2[6];
  for (int i = 0; i < 3; ++i) r[i] = r12[i];
  for (int k = 0; k < 6; ++k) {
    q1[k] = q1d[k];
    q2[k] = q2d[k];
  }
  QuadRef out{0, 0, 0, false};
  quad f, w;
  if (!quad_f(0.5Q, r, q1, q2, &f, &w)) return out;
  if (w == 0) return QuadRef{0.5Q, 0.5Q, f, true};
  // Work in t = distance to the nearer end: λ = t (left) or 1 − t, with
  // 1 − λ = t given exactly on the right.
  bool const left = w > 0;
  auto lambda_of = [&](quad t) { return left ? t : 1 - t; };
  auto eval = [&](quad t, quad *ff, quad *wt) {
    return quad_f(lambda_of(t), r, q1, q2, ff, wt, left ? 1 - t : t);
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
 * ∂μ²/∂ω1 = 2λ(1−λ)²·s × Q1s, ∂μ²/∂ω2 = 2λ²(1−λ)·s × Q2s; pw85.h), and
 * κ̄ = tr(Q(λ))·tr(Q(λ)⁻¹) ≥ cond(Q(λ)). False when Q(λ) is singular. */
struct QuadGeometry {
  quad point[3], point2[3], normal[3], d_r12[3], rot1[3], rot2[3];
  quad cond;
};

inline bool quad_geometry(quad lam, quad m, const double r12[3],
                          const double q1d[6], const double q2d[6],
                          QuadGeometry *g) {  // m = 1 − λ
  quad r[3], q1[6], q2[6], s[3];
  for (int i = 0; i < 3; ++i) r[i] = r12[i];
  for (int k = 0; k < 6; ++k) {
    q1[k] = q1d[k];
    q2[k] = q2d[k];
  }
  if (!quad_solve(lam, m, r, q1, q2, s, &g->cond)) return false;
  auto mul = [&](const quad a[6], quad out[3]) {
    out[0] = a[0] * s[0] + a[1] * s[1] + a[2] * s[2];
    out[1] = a[1] * s[0] + a[3] * s[1] + a[4] * s[2];
    out[2] = a[2] * s[0] + a[4] * s[1] + a[5] * s[2];
  };
  auto cross = [](const quad a[3], const quad b[3], quad out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
  };
  quad t1[3], t2[3], c1[3], c2[3];
  mul(q1, t1);
  mul(q2, t2);
  cross(s, t1, c1);
  cross(s, t2, c2);
  quad const ns = (quad)sqrtl((long double)(s[0] * s[0] + s[1] * s[1] +
                                            s[2] * s[2]));
  for (int i = 0; i < 3; ++i) {
    g->point[i] = m * t1[i];
    g->point2[i] = -lam * t2[i];  // x − c2 (theory, eq. (3.9b)), no cancellation
    g->normal[i] = s[i] / ns;
    g->d_r12[i] = 2 * lam * m * s[i];
    g->rot1[i] = 2 * lam * m * m * c1[i];
    g->rot2[i] = 2 * lam * lam * m * c2[i];
  }
  return true;
}

}  // namespace fuzz

#endif /* PW85_FUZZ_QUAD_REF_H */
