// SPDX-License-Identifier: BSD-3-Clause
// The compensated evaluation of f and Pᵢ at λ (private; docs/implementation.rst, eq. (4.4),
// and ch. 5, eqs. (1a)–(1b); docs/implementation.rst). Header-only: the
// callers are compiled for CPUs with and without FMA (PW85_FMA_CLONES),
// and these kernels with them.
#ifndef PW85_SRC_COMPENSATED_HPP
#define PW85_SRC_COMPENSATED_HPP

#include "compiler.hpp"
#include "dd.hpp"
#include "ldl.hpp"
#include "scaling.hpp"
#include "sym.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

// Q(λ) in double-double: hi + lo equals (1−λ)·Q1 + λ·Q2 to ~2⁻¹⁰⁴ relative
// (1 − λ itself is carried as hi + lo; lo is not renormalised). hi is Q(λ)
// as combine() rounds it, bit for bit (both round (1−λ)·Q1 and λ·Q2, then
// their sum, once).
template <int D = dim>
PW85_INLINE void combine_dd(double lambda, double const *q1, double const *q2,
                            double *hi, double *lo) noexcept {
  PW85_COUNT_EVALUATION();
  dd const mu = two_sum(1.0, -lambda);
  constexpr int n = sym_size(D);
  PW85_UNROLL
  for (int i = 0; i < n; ++i) {
    dd const a = two_prod(mu.hi, q1[i]);
    dd const b = two_prod(lambda, q2[i]);
    dd const t = two_sum(a.hi, b.hi);
    hi[i] = t.hi;
    lo[i] = t.lo + (a.lo + b.lo + mu.lo * q1[i]);
  }
}

// ρ = r − (Qhi + Qlo)·s, computed as in twice the working precision, then
// rounded (compensated: its error is of order ε·|ρ|, not ε·|Q|·|s|).
template <int D = dim>
PW85_INLINE void compensated_residual(double const *hi, double const *lo,
                                      double const *r, double const *s,
                                      double *rho) noexcept {
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    Dot2 acc{r[i], 0.0};
    double lo_part = 0.0;
    PW85_UNROLL
    for (int j = 0; j < D; ++j) {
      int const k = sym_index<D>(i, j);
      acc.add_product(-hi[k], s[j]);
      lo_part += lo[k] * s[j];
    }
    acc.err -= lo_part;
    rho[i] = acc.value();
  }
}

// sᵀ·A·s for symmetric A, accumulated as in twice the working precision
// (the sum and its error): no cancellation error however ill-conditioned
// A is.
template <int D = dim>
PW85_INLINE Dot2 quad_form_acc(double const *a, double const *s) noexcept {
  using L = Layout<D>;
  Dot2 acc{0.0, 0.0};
  constexpr int n = sym_size(D);
  PW85_UNROLL
  for (int k = 0; k < n; ++k) {
    double const factor = L::row[k] == L::col[k] ? 1.0 : 2.0;  // exact
    dd const p = two_prod(factor * a[k], s[L::row[k]]);
    acc.add_product(p.hi, s[L::col[k]]);
    acc.err += p.lo * s[L::col[k]];
  }
  return acc;
}

// λ·ρ = λ·√(P2/P1) (eq. (5.6)) with P2 first scaled by an even power of
// two 2^−e towards P1 (exact), so that neither the ratio nor the root
// leaves the range of doubles where λ·ρ does not: one form may be 2^1000
// times the other, and ρ beyond DBL_MAX while λ·ρ is near 1.
PW85_INLINE double lambda_rho(double lambda, double p1, double p2) noexcept {
  int e = exponent(p2) - exponent(p1);
  e -= e % 2;
  return times_pow2(lambda * std::sqrt(times_pow2(p2, -e) / p1), e / 2);
}

// hi + lo = a + b entry by entry, exactly (two_sum); hi and lo may be a
// or b.
template <int D = dim>
PW85_INLINE void split_sum(double const *a, double const *b, double *hi,
                           double *lo) noexcept {
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    dd const t = two_sum(a[i], b[i]);
    hi[i] = t.hi;
    lo[i] = t.lo;
  }
}

// quad_form_acc() rounded to double.
template <int D = dim>
PW85_INLINE double quad_form_dd(double const *a, double const *s) noexcept {
  return quad_form_acc<D>(a, s).value();
}

// x·y as an unevaluated sum hi + lo, as in twice the working precision.
template <int D = dim>
PW85_INLINE dd dot_dd(double const *x, double const *y) noexcept {
  Dot2 acc{0.0, 0.0};
  PW85_UNROLL
  for (int i = 0; i < D; ++i) acc.add_product(x[i], y[i]);
  return two_sum(acc.sum, acc.err);
}

// The compensated evaluation at λ. With s = Q(λ)⁻¹·r in plain double,
// e = Q⁻¹r − s its error (relative size cond·ε) and the residual
// ρ = r − Q(λ)·s (compensated_residual(), Q(λ) kept as hi + lo):
// r·s + s·ρ = rᵀQ⁻¹r − eᵀQe, so f = λ(1−λ)·(r·s + s·ρ) has an error of
// order (cond·ε)², below an ulp while κ̄(Q) ≤ refine_cond. Beyond it, s is
// refined once (s += Q⁻¹ρ) and ρ recomputed, squaring the error again;
// beyond factor_dd_cond, Q(λ) is factorised in double-double instead
// (compensated_dd()).
// Pᵢ = sᵀ·Qᵢ·s, first order in e, use the refined s, with exact products.
struct Compensated {
  double f;
  double f_lo;  // f + f_lo: f before its rounding to double
  double p1;    // P1·2^−p_exp, when asked for
  double p2;    // P2·2^−p_exp, when asked for
  int p_exp;    // 0, or where P1 or P2 would fall below p_floor, 2e for s
                // scaled by 2^−e to |s|∞ in [1/2, 1) (exact): neither then
                // underflows when Qᵢ and s are both small (one form far
                // below the other), and ρ = √(P2/P1) is the same
};

// Pᵢ = sᵀQᵢs into out (s_lo: nullptr, or the tail of s = s + s_lo, taken
// to first order: s rounded alone would leave Pᵢ off by up to
// ε·√cond(Qᵢ) relative, and λ by as much).
template <int D>
PW85_INLINE void p_from(double const *q1, double const *q2, double const *s,
                        double const *s_lo, Compensated *out) noexcept {
  out->p1 = quad_form_dd<D>(q1, s);
  out->p2 = quad_form_dd<D>(q2, s);
  if (s_lo != nullptr) {
    double t1[D], t2[D];
    sym_mul<D>(q1, s, t1);
    sym_mul<D>(q2, s, t2);
    out->p1 += 2.0 * dot<D>(t1, s_lo);
    out->p2 += 2.0 * dot<D>(t2, s_lo);
  }
}

// Below this, P1 or P2 may have lost digits to underflow (its terms then
// lie below 2^−1022): they are formed again from s scaled to order one.
constexpr double p_floor = 0x1p-900;

// s and s_lo scaled by the power of two 2^−e that brings |s|∞ to [1/2, 1)
// (exact, barring the underflow of a tail far below s); returns 2e, the
// exponent by which Pᵢ = sᵀQᵢs from the scaled s must be multiplied.
template <int D>
PW85_INLINE int scale_for_p(double *s, double *s_lo) noexcept {
  double m = std::fabs(s[0]);
  PW85_UNROLL
  for (int i = 1; i < D; ++i) m = std::fmax(m, std::fabs(s[i]));
  int const e = exponent(m);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    s[i] = times_pow2(s[i], -e);
    if (s_lo != nullptr) s_lo[i] = times_pow2(s_lo[i], -e);
  }
  return 2 * e;
}

// The evaluation from Q(λ) = hi + lo factorised in double-double
// (compensated_dd.cpp): for Q(λ) too ill-conditioned for the double
// factors (κ̄ > factor_dd_cond), and where Q(λ) rounded to double does not
// factorise (a form near the resolution of a double, made indefinite by
// the rounding of Q(λ)) while hi + lo may still be definite. Out of line,
// as it is rare and large; it forms hi + lo again itself, so that its
// callers' hi and lo never leave registers on the common path (passing
// them made pw85_f_neg 20% slower). Returns false when that factorisation
// fails (a pivot not > 0); *out is then unchanged.
// r_lo: as for compensated_from().
// Specialised for D = 2 and 3 (each compiled with PW85_FMA_CLONES).
template <int D>
bool compensated_dd(double lambda, double const *r, double const *q1,
                    double const *q2, bool with_p, Compensated *out,
                    double const *r_lo = nullptr) noexcept;

// s = Q(λ)⁻¹·r as s + s_lo, from Q(λ) = hi + lo factorised in
// double-double: relative error of order κ(Q(λ))·2⁻¹⁰⁴ (the contact
// geometry, geometry.cpp). Returns false when a pivot is not > 0.
template <int D>
bool solve_dd(double lambda, double const *r, double const *q1,
              double const *q2, double *s, double *s_lo) noexcept;

template <>
bool compensated_dd<2>(double, double const *, double const *,
                       double const *, bool, Compensated *,
                       double const *) noexcept;
template <>
bool compensated_dd<3>(double, double const *, double const *,
                       double const *, bool, Compensated *,
                       double const *) noexcept;
template <>
bool solve_dd<2>(double, double const *, double const *, double const *,
                 double *, double *) noexcept;
template <>
bool solve_dd<3>(double, double const *, double const *, double const *,
                 double *, double *) noexcept;

// The evaluation from Q(λ) as hi + lo and its plain factors and solution.
// WithP: also P1 and P2. r_lo: nullptr, or the low part of r = r + r_lo
// (a double-double, |r_lo_k| ≤ ulp(r_k)/2: the index's image vectors,
// src/index/broad.hpp): f and Pᵢ are then those of r + r_lo. It enters the
// residual, ρ = (r + r_lo) − Q(λ)·s, rounded once more (an error of
// ε·|ρ + r_lo|, of the order of ρ's own rounding), and r·s, as r_lo·s in
// the low part: r·s + r_lo·s + s·ρ = (r + r_lo)ᵀQ⁻¹(r + r_lo) − eᵀQe.
template <bool WithP, int D>
PW85_INLINE void compensated_from(double lambda, double const *r,
                                  double const *q1, double const *q2,
                                  double const *hi, double const *lo,
                                  LdlSolution<D> const &plain,
                                  Compensated *out,
                                  double const *r_lo = nullptr) noexcept {
  Ldl<D> const &fac = plain.fac;
  double s[D], rho[D], ds[D] = {};
  double const cond = ldl_cond_bound(hi, fac);
  if (PW85_UNLIKELY(cond > factor_dd_cond) &&
      compensated_dd<D>(lambda, r, q1, q2, WithP, out, r_lo))
    return;
  auto residual = [&]() {
    compensated_residual<D>(hi, lo, r, s, rho);
    if (r_lo != nullptr) {
      PW85_UNROLL
      for (int i = 0; i < D; ++i) rho[i] += r_lo[i];
    }
  };
  PW85_UNROLL
  for (int i = 0; i < D; ++i) s[i] = plain.s[i];
  residual();
  bool const refine = cond > refine_cond;
  // The refined s is ds + ds_lo; ds_lo is kept where it may matter, when
  // Q(λ) is ill-conditioned (below p_carry_cond, Pᵢ from ds alone moves λ
  // by less than the tolerances of the tests measure).
  bool const carry = cond > p_carry_cond;
  double ds_lo[D];
  if (carry) {
    ldl_solve(fac, rho, ds);
    split_sum<D>(s, ds, ds, ds_lo);
  } else if (refine || WithP) {
    ldl_solve(fac, rho, ds);
    PW85_UNROLL
    for (int i = 0; i < D; ++i) ds[i] += s[i];
  }
  if (refine) {
    PW85_UNROLL
    for (int i = 0; i < D; ++i) s[i] = ds[i];
    residual();
  }
  double low = dot<D>(s, rho);
  if (r_lo != nullptr) low += dot<D>(r_lo, s);
  dd const rs = dd_add(dot_dd<D>(r, s), low);  // rᵀQ⁻¹r − eᵀQe
  dd const w = dd_mul(two_sum(1.0, -lambda), lambda);  // λ(1−λ)
  dd const value = dd_mul(w, rs);  // normalised: value.hi = dd_round(value)
  out->f = value.hi;
  out->f_lo = value.lo;
  if (WithP) {
    out->p_exp = 0;
    p_from<D>(q1, q2, ds, carry ? ds_lo : nullptr, out);
    if (PW85_UNLIKELY(!(out->p1 > p_floor && out->p2 > p_floor))) {
      out->p_exp = scale_for_p<D>(ds, carry ? ds_lo : nullptr);
      p_from<D>(q1, q2, ds, carry ? ds_lo : nullptr, out);
    }
  }
}

// The compensated evaluation at λ. plain: the plain factors and solution
// of Q(λ) at this λ where the caller has them (evaluate_plain() computes
// those this function would: hi is Q(λ) as combine() rounds it), else
// nullptr, and they are computed here. Returns false when Q(λ) does not
// factorise, in double nor in double-double. fast: see ldl_decomp_q().
// (One function for both cases, so that a caller inlines the kernels
// once: code size counts in the finish's loop.)
// r_lo: as for compensated_from().
template <bool WithP, int D = dim>
PW85_INLINE bool evaluate_compensated(double lambda, double const *r,
                                      double const *q1, double const *q2,
                                      bool fast, LdlSolution<D> const *plain,
                                      Compensated *out,
                                      double const *r_lo = nullptr) noexcept {
  double hi[sym_size(D)], lo[sym_size(D)];
  combine_dd<D>(lambda, q1, q2, hi, lo);
  LdlSolution<D> fresh;
  if (plain == nullptr) {
    if (PW85_UNLIKELY(!ldl_decomp_q(hi, &fresh.fac, fast)))
      return compensated_dd<D>(lambda, r, q1, q2, WithP, out, r_lo);
    ldl_solve(fresh.fac, r, fresh.s);
    plain = &fresh;
  }
  compensated_from<WithP, D>(lambda, r, q1, q2, hi, lo, *plain, out, r_lo);
  return true;
}

}  // namespace pw85::detail

#endif  // PW85_SRC_COMPENSATED_HPP
