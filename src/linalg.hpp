// SPDX-License-Identifier: BSD-3-Clause
// 3×3 symmetric linear algebra kernels, plain and compensated (private,
// header-only so that they are inlined, and compiled for the target of the
// function that calls them: see PW85_FMA_CLONES in dd.hpp). Storage
// conventions are those of include/pw85/pw85.h.
#ifndef PW85_SRC_LINALG_HPP
#define PW85_SRC_LINALG_HPP

#include <cmath>

#include "core.hpp"
#include "dd.hpp"

namespace pw85::detail {

#ifdef PW85_COUNT_EVALUATIONS
// Benchmark builds only: how many times Q(λ) was formed on this thread.
extern thread_local unsigned long long evaluations;
#define PW85_COUNT_EVALUATION() (++evaluations)
#else
#define PW85_COUNT_EVALUATION() ((void)0)
#endif

// Row and column of each stored entry of a symmetric matrix.
constexpr int row_of[sym] = {0, 0, 0, 1, 1, 2};
constexpr int col_of[sym] = {0, 1, 2, 1, 2, 2};
constexpr int diag_of[dim] = {0, 3, 5};

// The storage index of entry (i, j) of a symmetric matrix.
constexpr int sym_index(int i, int j) noexcept {
  int const a = i < j ? i : j;
  int const b = i < j ? j : i;
  return a == 0 ? b : (a == 1 ? 2 + b : 5);
}

// y = A·x for symmetric A.
PW85_INLINE void sym_mul(double const a[sym], double const x[dim],
                         double y[dim]) noexcept {
  y[0] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
  y[1] = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
  y[2] = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
}

PW85_INLINE double dot(double const x[dim], double const y[dim]) noexcept {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// Q(λ) = (1−λ)·Q1 + λ·Q2 (seed ch. 4, eq. (2)).
PW85_INLINE void combine(double lambda, double const q1[sym],
                         double const q2[sym], double q[sym]) noexcept {
  PW85_COUNT_EVALUATION();
  double const mu = 1.0 - lambda;
  PW85_UNROLL
  for (int i = 0; i < sym; ++i) q[i] = mu * q1[i] + lambda * q2[i];
}

// Q = L·D·Lᵀ with L unit lower triangular: no square root, unlike the
// Cholesky factor of ch. 4.1, and the same pivots dᵢ (squares of its
// diagonal), whose positivity decides definiteness.
struct Ldl {
  double l1, l2, l4;  // L10, L20, L21
  double inv_d[dim];  // 1/dᵢ
};

// Returns false when a pivot is not > 0 (NaN included).
PW85_INLINE bool ldl_decomp(double const a[sym], Ldl *f) noexcept {
  double const d0 = a[0];
  if (!(d0 > 0.0)) return false;
  f->inv_d[0] = 1.0 / d0;
  f->l1 = a[1] * f->inv_d[0];
  f->l2 = a[2] * f->inv_d[0];
  double const d1 = a[3] - f->l1 * a[1];
  if (!(d1 > 0.0)) return false;
  f->inv_d[1] = 1.0 / d1;
  double const e = a[4] - f->l1 * a[2];  // L21·d1
  f->l4 = e * f->inv_d[1];
  double const d2 = a[5] - f->l2 * a[2] - f->l4 * e;
  if (!(d2 > 0.0)) return false;
  f->inv_d[2] = 1.0 / d2;
  return true;
}

// The same factorisation with a shorter chain of dependent operations, for
// Q(λ) in the search, where latency counts: each pivot waits only for the
// reciprocal of the one before, dᵢ being formed from products of entries
// computed meanwhile (d1 = a11 − a01²/d0, not a11 − L10·a01). The roundings
// differ, not their number. Those products leave the range of doubles
// sooner than the terms of ldl_decomp(): the diagonal of a must lie in
// [2^−400, 2^400] (Scaled::moderate), where no product overflows, and one
// that underflows is below ε times the diagonal entry it is subtracted
// from, the rounding error of that subtraction anyway (while cond(a) is
// below 2^170). The input forms are factorised by ldl_decomp() alone,
// whose definiteness decisions the tests pin.
PW85_INLINE bool ldl_decomp_fast(double const a[sym], Ldl *f) noexcept {
  double const d0 = a[0];
  if (!(d0 > 0.0)) return false;
  double const inv0 = 1.0 / d0;
  f->inv_d[0] = inv0;
  f->l1 = a[1] * inv0;
  f->l2 = a[2] * inv0;
  double const d1 = a[3] - (a[1] * a[1]) * inv0;
  if (!(d1 > 0.0)) return false;
  double const inv1 = 1.0 / d1;
  f->inv_d[1] = inv1;
  double const e = a[4] - (a[1] * a[2]) * inv0;  // L21·d1
  f->l4 = e * inv1;
  double const d2 = a[5] - (a[2] * a[2]) * inv0 - (e * e) * inv1;
  if (!(d2 > 0.0)) return false;
  f->inv_d[2] = 1.0 / d2;
  return true;
}

// Which of the two factorisations Q(λ) gets: fast only where the caller
// knows the range condition of ldl_decomp_fast() to hold. Callers pass a
// constant where they can, so that the other is not compiled in.
PW85_INLINE bool ldl_decomp_q(double const a[sym], Ldl *f, bool fast) noexcept {
  return fast ? ldl_decomp_fast(a, f) : ldl_decomp(a, f);
}

// z = L⁻¹·b; then bᵀ·Q⁻¹·b = Σ zᵢ²/dᵢ.
PW85_INLINE void ldl_forward(Ldl const &f, double const b[dim],
                             double z[dim]) noexcept {
  z[0] = b[0];
  z[1] = b[1] - f.l1 * z[0];
  z[2] = b[2] - f.l2 * z[0] - f.l4 * z[1];
}

// bᵀ·Q⁻¹·b = Σ zᵢ²/dᵢ, a sum of non-negative terms, from z = L⁻¹·b.
PW85_INLINE double ldl_quad(Ldl const &f, double const z[dim]) noexcept {
  return z[0] * z[0] * f.inv_d[0] + z[1] * z[1] * f.inv_d[1] +
         z[2] * z[2] * f.inv_d[2];
}

// bᵀ·Q⁻¹·b.
PW85_INLINE double ldl_quad_inverse(Ldl const &f, double const b[dim]) noexcept {
  double z[dim];
  ldl_forward(f, b, z);
  return ldl_quad(f, z);
}

// x = Q⁻¹·b from z = L⁻¹·b (backward substitution with D⁻¹ and Lᵀ).
PW85_INLINE void ldl_backward(Ldl const &f, double const z[dim],
                              double x[dim]) noexcept {
  x[2] = z[2] * f.inv_d[2];
  x[1] = z[1] * f.inv_d[1] - f.l4 * x[2];
  x[0] = z[0] * f.inv_d[0] - f.l1 * x[1] - f.l2 * x[2];
}

// x = Q⁻¹·b. x may alias b.
PW85_INLINE void ldl_solve(Ldl const &f, double const b[dim],
                           double x[dim]) noexcept {
  double z[dim];
  ldl_forward(f, b, z);
  ldl_backward(f, z, x);
}

// x = Q⁻¹·b, returning bᵀ·Q⁻¹·b from the same forward pass, bitwise equal
// to ldl_quad_inverse(f, b).
PW85_INLINE double ldl_solve_quad(Ldl const &f, double const b[dim],
                                  double x[dim]) noexcept {
  double z[dim];
  ldl_forward(f, b, z);
  ldl_backward(f, z, x);
  return ldl_quad(f, z);
}

// An upper bound of the 2-norm condition number of Q = L·D·Lᵀ:
// tr(Q)·tr(Q⁻¹) ≥ λmax/λmin, with tr(Q⁻¹) = Σₖ (1/dₖ)·Σᵢ (L⁻¹)ₖᵢ² and
// L⁻¹ = [[1, 0, 0], [−l1, 1, 0], [l1·l4 − l2, −l4, 1]].
PW85_INLINE double ldl_cond_bound(double const q[sym], Ldl const &f) noexcept {
  double const m20 = f.l1 * f.l4 - f.l2;
  double const tr_inv = f.inv_d[0] + f.inv_d[1] * (1.0 + f.l1 * f.l1) +
                        f.inv_d[2] * (1.0 + f.l4 * f.l4 + m20 * m20);
  return (q[0] + q[3] + q[5]) * tr_inv;
}

// f(λ) = λ(1−λ)·rᵀ·Q(λ)⁻¹·r in plain double (core.hpp, f()):
// rᵀ·Q⁻¹·r = Σ zᵢ²/dᵢ with z = L⁻¹·r, one triangular solve instead of the
// two of ch. 4, eq. (4), no square root, and no cancellation.
// fast: see ldl_decomp_q().
PW85_INLINE bool f_plain(double lambda, double const r[dim],
                         double const q1[sym], double const q2[sym],
                         bool fast, double *value) noexcept {
  double q[sym];
  combine(lambda, q1, q2, q);
  Ldl fac;
  if (!ldl_decomp_q(q, &fac, fast)) return false;
  *value = lambda * (1.0 - lambda) * ldl_quad_inverse(fac, r);
  return true;
}

// Q(λ) in double-double: hi + lo equals (1−λ)·Q1 + λ·Q2 to ~2⁻¹⁰⁴ relative
// (1 − λ itself is carried as hi + lo; lo is not renormalised).
PW85_INLINE void combine_dd(double lambda, double const q1[sym],
                            double const q2[sym], double hi[sym],
                            double lo[sym]) noexcept {
  PW85_COUNT_EVALUATION();
  dd const mu = two_sum(1.0, -lambda);
  PW85_UNROLL
  for (int i = 0; i < sym; ++i) {
    dd const a = two_prod(mu.hi, q1[i]);
    dd const b = two_prod(lambda, q2[i]);
    dd const t = two_sum(a.hi, b.hi);
    hi[i] = t.hi;
    lo[i] = t.lo + (a.lo + b.lo + mu.lo * q1[i]);
  }
}

// Compensated accumulation (Ogita, Rump and Oishi, SIAM J. Sci. Comput. 26,
// 2005, algorithm Dot2): the result is as accurate as if computed in twice
// the working precision, then rounded.
struct Dot2 {
  double sum;
  double err;
  PW85_INLINE void add_product(double a, double b) noexcept {
    dd const p = two_prod(a, b);
    dd const t = two_sum(sum, p.hi);
    sum = t.hi;
    err += p.lo + t.lo;
  }
  PW85_INLINE void add(double a) noexcept {
    dd const t = two_sum(sum, a);
    sum = t.hi;
    err += t.lo;
  }
  PW85_INLINE double value() const noexcept { return sum + err; }
};

// ρ = r − (Qhi + Qlo)·s, to twice the working precision, then rounded.
PW85_INLINE void exact_residual(double const hi[sym], double const lo[sym],
                                double const r[dim], double const s[dim],
                                double rho[dim]) noexcept {
  PW85_UNROLL
  for (int i = 0; i < dim; ++i) {
    Dot2 acc{r[i], 0.0};
    double lo_part = 0.0;
    PW85_UNROLL
    for (int j = 0; j < dim; ++j) {
      int const k = sym_index(i, j);
      acc.add_product(-hi[k], s[j]);
      lo_part += lo[k] * s[j];
    }
    acc.err -= lo_part;
    rho[i] = acc.value();
  }
}

// sᵀ·A·s for symmetric A, to twice the working precision: no cancellation
// error however ill-conditioned A is.
PW85_INLINE double quad_form_dd(double const a[sym],
                                double const s[dim]) noexcept {
  Dot2 acc{0.0, 0.0};
  PW85_UNROLL
  for (int k = 0; k < sym; ++k) {
    double const factor = row_of[k] == col_of[k] ? 1.0 : 2.0;  // exact
    dd const p = two_prod(factor * a[k], s[row_of[k]]);
    acc.add_product(p.hi, s[col_of[k]]);
    acc.err += p.lo * s[col_of[k]];
  }
  return acc.value();
}

// x·y as an unevaluated sum hi + lo, to twice the working precision.
PW85_INLINE dd dot_dd(double const x[dim], double const y[dim]) noexcept {
  Dot2 acc{0.0, 0.0};
  PW85_UNROLL
  for (int i = 0; i < dim; ++i) acc.add_product(x[i], y[i]);
  return two_sum(acc.sum, acc.err);
}

// The compensated evaluation at λ (seed ch. 4, eq. (4), and ch. 5,
// eqs. (1a)–(1b)). With s = Q(λ)⁻¹·r in plain double, e = Q⁻¹r − s its
// error (relative size cond·ε) and the residual ρ = r − Q(λ)·s computed
// with error-free transformations (Q(λ) kept as hi + lo):
// r·s + s·ρ = rᵀQ⁻¹r − eᵀQe, so f = λ(1−λ)·(r·s + s·ρ) has an error of
// order (cond·ε)², below an ulp while cond(Q) ≤ refine_cond. Beyond it, s is
// refined once (s += Q⁻¹ρ) and ρ recomputed, squaring the error again.
// Pᵢ = sᵀ·Qᵢ·s, first order in e, use the refined s, with exact products.
// Returns false when Q(λ) does not factorise.
struct Accurate {
  double f;
  double f_lo;  // f + f_lo: f before its rounding to double
  double p1;
  double p2;
};

constexpr double refine_cond = 1e6;

// The plain factorisation and solution at λ, where the caller has them:
// Q(λ) rounded to double is exactly the hi part of combine_dd() (both round
// (1−λ)·Q1 and λ·Q2, then their sum, once), so they are those computed here.
struct Plain {
  Ldl fac;
  double s[dim];  // Q(λ)⁻¹·r
};

// fast: see ldl_decomp_q().
PW85_INLINE bool accurate_terms(double lambda, double const r[dim],
                                double const q1[sym], double const q2[sym],
                                bool fast, bool with_p, Accurate *out,
                                Plain const *plain = nullptr) noexcept {
  double hi[sym], lo[sym];
  combine_dd(lambda, q1, q2, hi, lo);
  Ldl fac;
  double s[dim], rho[dim], ds[dim];
  if (plain != nullptr) {
    fac = plain->fac;
    PW85_UNROLL
    for (int i = 0; i < dim; ++i) s[i] = plain->s[i];
  } else {
    if (!ldl_decomp_q(hi, &fac, fast)) return false;
    ldl_solve(fac, r, s);
  }
  exact_residual(hi, lo, r, s, rho);
  bool const refine = ldl_cond_bound(hi, fac) > refine_cond;
  if (refine || with_p) {
    ldl_solve(fac, rho, ds);
    PW85_UNROLL
    for (int i = 0; i < dim; ++i) ds[i] += s[i];  // the refined s
  }
  if (refine) {
    PW85_UNROLL
    for (int i = 0; i < dim; ++i) s[i] = ds[i];
    exact_residual(hi, lo, r, s, rho);
  }
  dd const rs = dd_add(dot_dd(r, s), dot(s, rho));     // rᵀQ⁻¹r − eᵀQe
  dd const w = dd_mul(two_sum(1.0, -lambda), lambda);  // λ(1−λ)
  dd const value = dd_mul(w, rs);  // normalised: value.hi = dd_round(value)
  out->f = value.hi;
  out->f_lo = value.lo;
  if (with_p) {
    out->p1 = quad_form_dd(q1, ds);
    out->p2 = quad_form_dd(q2, ds);
  }
  return true;
}

}  // namespace pw85::detail

#endif  // PW85_SRC_LINALG_HPP
