// SPDX-License-Identifier: BSD-3-Clause
// The compensated evaluation through a double-double factorisation of Q(λ)
// (compensated.hpp, compensated_dd()).
#include "compensated.hpp"

namespace pw85::detail {

namespace {

// Q = L·D·Lᵀ in double-double (the algorithm of ldl_decomp()), for Q(λ)
// too ill-conditioned for a double factorisation: its backward error is of
// order κ(Q)·2⁻¹⁰⁴ relative instead of κ(Q)·ε.
// L = [[1, 0, 0], [l10, 1, 0], [l20, l21, 1]] and the pivots
// d = (d0, d1, d2); in 2D their upper left block (l20, l21 unused).
template <int D>
struct LdlDd {
  dd l10, l20, l21;
  dd d[D];
};

// Returns false when a pivot is not > 0.
template <int D>
PW85_INLINE bool ldl_decomp_dd(dd const *a, LdlDd<D> *f) noexcept {
  f->d[0] = a[0];
  if (!(a[0].hi > 0.0)) return false;
  f->l10 = dd_div(a[1], a[0]);
  if constexpr (D == 3) f->l20 = dd_div(a[2], a[0]);
  f->d[1] = dd_sub(a[Layout<D>::diag[1]], dd_mul(f->l10, a[1]));
  if (!(f->d[1].hi > 0.0)) return false;
  if constexpr (D == 3) {
    dd const e = dd_sub(a[4], dd_mul(f->l10, a[2]));  // L21·d1
    f->l21 = dd_div(e, f->d[1]);
    f->d[2] = dd_sub(dd_sub(a[5], dd_mul(f->l20, a[2])), dd_mul(f->l21, e));
    return f->d[2].hi > 0.0;
  }
  return true;
}

// rᵀ·Q⁻¹·r = Σ zᵢ²/dᵢ (a sum of non-negative terms) and s = Q⁻¹·r as
// s_hi + s_lo, from z = L⁻¹·r, all in double-double; r + r_lo when r_lo
// is not nullptr.
template <int D>
PW85_INLINE dd ldl_solve_quad_dd(LdlDd<D> const &f, double const *r,
                                 double const *r_lo, double *s,
                                 double *s_lo) noexcept {
  dd z[D], y[D], x[D];
  PW85_UNROLL
  for (int i = 0; i < D; ++i) z[i] = dd{r[i], r_lo != nullptr ? r_lo[i] : 0.0};
  z[1] = dd_sub(z[1], dd_mul(f.l10, z[0]));
  if constexpr (D == 3)
    z[2] = dd_sub(dd_sub(z[2], dd_mul(f.l20, z[0])), dd_mul(f.l21, z[1]));
  PW85_UNROLL
  for (int i = 0; i < D; ++i) y[i] = dd_div(z[i], f.d[i]);
  x[D - 1] = y[D - 1];
  if constexpr (D == 2) {
    x[0] = dd_sub(y[0], dd_mul(f.l10, x[1]));
  } else {
    x[1] = dd_sub(y[1], dd_mul(f.l21, x[2]));
    x[0] = dd_sub(dd_sub(y[0], dd_mul(f.l10, x[1])), dd_mul(f.l20, x[2]));
  }
  dd quad = dd_mul(z[0], y[0]);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    dd const t = two_sum(x[i].hi, x[i].lo);
    s[i] = t.hi;
    s_lo[i] = t.lo;
    if (i > 0) quad = dd_add(quad, dd_mul(z[i], y[i]));
  }
  return quad;
}

// Q = hi + lo factorised in double-double; false when a pivot is not > 0.
template <int D>
PW85_INLINE bool factorise_dd(double const *hi, double const *lo,
                              LdlDd<D> *f) noexcept {
  dd a[sym_size(D)];
  for (int k = 0; k < sym_size(D); ++k) a[k] = two_sum(hi[k], lo[k]);
  return ldl_decomp_dd(a, f);
}

// Q(λ) = hi + lo (combine_dd()) factorised in double-double; false when a
// pivot is not > 0.
template <int D>
PW85_INLINE bool factorise_q_dd(double lambda, double const *q1,
                                double const *q2, LdlDd<D> *f) noexcept {
  double hi[sym_size(D)], lo[sym_size(D)];
  combine_dd<D>(lambda, q1, q2, hi, lo);
  return factorise_dd(hi, lo, f);
}

// The sum of t[0..n) (overwritten) as hi + lo, as accurate as if computed
// in three times the working precision (SumK with K = 3: two error-free
// passes of two_sum along the vector, then the plain sum; Ogita, Rump and
// Oishi, "Accurate sum and dot product", SIAM J. Sci. Comput. 26, 2005,
// Algorithm 4.8): error ε·|Σt| + O(n³ε³)·Σ|tᵢ|.
PW85_INLINE dd sum3(double t[], int n) noexcept {
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 1; i < n; ++i) {
      dd const u = two_sum(t[i], t[i - 1]);
      t[i] = u.hi;
      t[i - 1] = u.lo;
    }
  double lo = 0.0;
  for (int i = 0; i < n - 1; ++i) lo += t[i];
  return two_sum(t[n - 1], lo);
}

// Q(λ) = (1 − λ)·Q1 + λ·Q2 as three doubles per entry, hi + mid + lo,
// off from the exact value by O(ε³)·(|(1 − λ)·Q1| + |λ·Q2|): the six
// doubles of μ_hi·Q1, μ_lo·Q1 and λ·Q2 split by two_prod (1 − λ = μ_hi +
// μ_lo exactly) sum exactly to the entry; one pass of two_sum leaves hi
// and five errors, a second pass over those leaves mid and errors of order
// ε²·Σ|parts|, summed plainly into lo.
template <int D>
PW85_INLINE void combine_td(double lambda, double const *q1, double const *q2,
                            double *hi, double *mid, double *lo) noexcept {
  dd const mu = two_sum(1.0, -lambda);
  for (int k = 0; k < sym_size(D); ++k) {
    dd const a = two_prod(mu.hi, q1[k]);
    dd const b = two_prod(mu.lo, q1[k]);
    dd const c = two_prod(lambda, q2[k]);
    double t[6] = {a.lo, b.lo, c.lo, b.hi, c.hi, a.hi};
    for (int i = 1; i < 6; ++i) {
      dd const u = two_sum(t[i], t[i - 1]);
      t[i] = u.hi;
      t[i - 1] = u.lo;
    }
    for (int i = 1; i < 5; ++i) {
      dd const u = two_sum(t[i], t[i - 1]);
      t[i] = u.hi;
      t[i - 1] = u.lo;
    }
    hi[k] = t[5];
    mid[k] = t[4];
    lo[k] = (t[0] + t[1]) + (t[2] + t[3]);
  }
}

// rᵀQ⁻¹r refined from s = s_hi + s_lo (the double-double solution): with
// ρ = r − Q(λ)·s formed as in three times the working precision,
// rᵀs + sᵀρ = rᵀQ⁻¹r − eᵀQe (e = Q⁻¹r − s): the double-double solution's
// error κ(Q)·2⁻¹⁰⁴, an ulp of f at κ near 4e15, enters squared. (Found by
// fuzz-contact-raw: μ² 0.4996 ulp above a double, cond(Q1) = 3.9e15,
// rounded the wrong way.) Q(λ) enters ρ to O(ε³) (combine_td()), with
// r + r_lo and the products hi·s, hi·s_lo, mid·s split by two_prod; only
// mid·s_lo and lo·s, themselves O(ε²)·|Q||s|, are rounded, and lo·s_lo,
// O(ε³), is left out. An error δ in Q(λ)'s entries, relative to
// (1 − λ)·|Q1| + λ·|Q2|, moves f by up to about 2δ·κ(Q(λ)) relative:
// combine_dd()'s hi + lo, δ = 2⁻¹⁰⁶, was not enough (a held-out pair of
// the hard set's lambda_end_ill class, κ = 8.6e15: f 2.4e-18 relative
// low, μ² 0.017 ulp across a midpoint, rounded the wrong way).
template <int D>
PW85_INLINE dd refined_quad(double lambda, double const *q1, double const *q2,
                            double const *r, double const *r_lo,
                            double const *s, double const *s_lo) noexcept {
  double hi[sym_size(D)], mid[sym_size(D)], lo[sym_size(D)];
  combine_td<D>(lambda, q1, q2, hi, mid, lo);
  double rho[D];
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    double t[2 + 8 * D];
    int n = 0;
    t[n++] = r[i];
    if (r_lo != nullptr) t[n++] = r_lo[i];
    PW85_UNROLL
    for (int j = 0; j < D; ++j) {
      int const k = sym_index<D>(i, j);
      dd const a = two_prod(hi[k], s[j]);
      dd const b = two_prod(hi[k], s_lo[j]);
      dd const c = two_prod(mid[k], s[j]);
      t[n++] = -a.hi;
      t[n++] = -a.lo;
      t[n++] = -b.hi;
      t[n++] = -b.lo;
      t[n++] = -c.hi;
      t[n++] = -c.lo;
      t[n++] = -(mid[k] * s_lo[j]);
      t[n++] = -(lo[k] * s[j]);
    }
    rho[i] = sum3(t, n).hi;
  }
  Dot2 acc{0.0, 0.0};
  double low = 0.0;
  PW85_UNROLL
  for (int i = 0; i < D; ++i) {
    acc.add_product(r[i], s[i]);
    acc.add_product(r[i], s_lo[i]);
    if (r_lo != nullptr) low += r_lo[i] * (s[i] + s_lo[i]);
    low += (s[i] + s_lo[i]) * rho[i];
  }
  acc.err += low;
  return two_sum(acc.sum, acc.err);
}

template <int D>
PW85_INLINE bool compensated_dd_steps(double lambda, double const *r,
                                      double const *q1, double const *q2,
                                      bool with_p, Compensated *out,
                                      double const *r_lo) noexcept {
  // f = λ(1−λ)·rᵀQ⁻¹r from the double-double factors, and Pᵢ = sᵀQᵢs from
  // s = s_hi + s_lo: sᵀQs = s_hiᵀQs_hi + 2·(Q·s_hi)·s_lo to second order
  // in s_lo. (From s rounded to double, Pᵢ would be off by up to
  // ε·√cond(Qᵢ) relative, and λ by as much.)
  double hi[sym_size(D)], lo[sym_size(D)];
  combine_dd<D>(lambda, q1, q2, hi, lo);
  LdlDd<D> fdd;
  if (!factorise_dd(hi, lo, &fdd)) return false;
  double s[D], s_lo[D];
  ldl_solve_quad_dd(fdd, r, r_lo, s, s_lo);
  dd const quad = refined_quad<D>(lambda, q1, q2, r, r_lo, s, s_lo);
  dd const value = dd_mul(dd_mul(two_sum(1.0, -lambda), lambda), quad);
  out->f = value.hi;
  out->f_lo = value.lo;
  if (with_p) {
    out->p_exp = 0;
    p_from<D>(q1, q2, s, s_lo, out);
    if (!(out->p1 > p_floor && out->p2 > p_floor)) {
      out->p_exp = scale_for_p<D>(s, s_lo);
      p_from<D>(q1, q2, s, s_lo, out);
    }
  }
  return true;
}

template <int D>
PW85_INLINE bool solve_dd_steps(double lambda, double const *r,
                                double const *q1, double const *q2, double *s,
                                double *s_lo) noexcept {
  LdlDd<D> fdd;
  if (!factorise_q_dd<D>(lambda, q1, q2, &fdd)) return false;
  ldl_solve_quad_dd(fdd, r, nullptr, s, s_lo);
  return true;
}

}  // namespace

// The entry points, one per dimension, each compiled for CPUs with and
// without FMA (PW85_FMA_CLONES: clang's target_clones takes explicit
// specialisations, not templates).
#define PW85_COMPENSATED_DD_ENTRIES(D)                                        \
  template <>                                                                 \
  PW85_FMA_CLONES bool compensated_dd<D>(                                     \
      double lambda, double const *r, double const *q1, double const *q2,     \
      bool with_p, Compensated *out, double const *r_lo) noexcept {           \
    return compensated_dd_steps<D>(lambda, r, q1, q2, with_p, out, r_lo);     \
  }                                                                           \
  template <>                                                                 \
  PW85_FMA_CLONES bool solve_dd<D>(double lambda, double const *r,            \
                                   double const *q1, double const *q2,        \
                                   double *s, double *s_lo) noexcept {        \
    return solve_dd_steps<D>(lambda, r, q1, q2, s, s_lo);                     \
  }

PW85_COMPENSATED_DD_ENTRIES(2)
PW85_COMPENSATED_DD_ENTRIES(3)

}  // namespace pw85::detail
