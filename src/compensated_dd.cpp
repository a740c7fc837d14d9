// SPDX-License-Identifier: BSD-3-Clause
// The compensated evaluation through a double-double factorisation of Q(λ)
// (compensated.hpp, compensated_dd()).
#include "compensated.hpp"

namespace pw85::detail {

namespace {

// Q = L·D·Lᵀ in double-double (the algorithm of ldl_decomp()), for Q(λ)
// too ill-conditioned for a double factorisation: its backward error is of
// order κ(Q)·2⁻¹⁰⁴ relative instead of κ(Q)·ε.
struct LdlDd {
  dd l10, l20, l21;  // L = [[1, 0, 0], [l10, 1, 0], [l20, l21, 1]]
  dd d[dim];         // D = diag(d0, d1, d2)
};

// Returns false when a pivot is not > 0.
PW85_INLINE bool ldl_decomp_dd(dd const a[sym], LdlDd *f) noexcept {
  f->d[0] = a[0];
  if (!(a[0].hi > 0.0)) return false;
  f->l10 = dd_div(a[1], a[0]);
  f->l20 = dd_div(a[2], a[0]);
  f->d[1] = dd_sub(a[3], dd_mul(f->l10, a[1]));
  if (!(f->d[1].hi > 0.0)) return false;
  dd const e = dd_sub(a[4], dd_mul(f->l10, a[2]));  // L21·d1
  f->l21 = dd_div(e, f->d[1]);
  f->d[2] = dd_sub(dd_sub(a[5], dd_mul(f->l20, a[2])), dd_mul(f->l21, e));
  return f->d[2].hi > 0.0;
}

// rᵀ·Q⁻¹·r = Σ zᵢ²/dᵢ (a sum of non-negative terms) and s = Q⁻¹·r as
// s_hi + s_lo, from z = L⁻¹·r, all in double-double; r + r_lo when r_lo
// is not nullptr.
PW85_INLINE dd ldl_solve_quad_dd(LdlDd const &f, double const r[dim],
                                 double const *r_lo, double s[dim],
                                 double s_lo[dim]) noexcept {
  dd const z0{r[0], r_lo != nullptr ? r_lo[0] : 0.0};
  dd const z1 =
      dd_sub(dd{r[1], r_lo != nullptr ? r_lo[1] : 0.0}, dd_mul(f.l10, z0));
  dd const z2 = dd_sub(
      dd_sub(dd{r[2], r_lo != nullptr ? r_lo[2] : 0.0}, dd_mul(f.l20, z0)),
      dd_mul(f.l21, z1));
  dd const y0 = dd_div(z0, f.d[0]);
  dd const y1 = dd_div(z1, f.d[1]);
  dd const y2 = dd_div(z2, f.d[2]);
  dd const x2 = y2;
  dd const x1 = dd_sub(y1, dd_mul(f.l21, x2));
  dd const x0 = dd_sub(dd_sub(y0, dd_mul(f.l10, x1)), dd_mul(f.l20, x2));
  dd const x[dim] = {two_sum(x0.hi, x0.lo), two_sum(x1.hi, x1.lo),
                     two_sum(x2.hi, x2.lo)};
  PW85_UNROLL
  for (int i = 0; i < dim; ++i) {
    s[i] = x[i].hi;
    s_lo[i] = x[i].lo;
  }
  return dd_add(dd_add(dd_mul(z0, y0), dd_mul(z1, y1)), dd_mul(z2, y2));
}

// Q = hi + lo factorised in double-double; false when a pivot is not > 0.
PW85_INLINE bool factorise_dd(double const hi[sym], double const lo[sym],
                              LdlDd *f) noexcept {
  dd a[sym];
  for (int k = 0; k < sym; ++k) a[k] = two_sum(hi[k], lo[k]);
  return ldl_decomp_dd(a, f);
}

// Q(λ) = hi + lo (combine_dd()) factorised in double-double; false when a
// pivot is not > 0.
PW85_INLINE bool factorise_q_dd(double lambda, double const q1[sym],
                                double const q2[sym], LdlDd *f) noexcept {
  double hi[sym], lo[sym];
  combine_dd(lambda, q1, q2, hi, lo);
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

// rᵀQ⁻¹r refined from s = s_hi + s_lo (the double-double solution): with
// ρ = r − Q·s formed as in three times the working precision (Q(λ) =
// hi + lo, r + r_lo, every product split exactly by two_prod),
// rᵀs + sᵀρ = rᵀQ⁻¹r − eᵀQe (e = Q⁻¹r − s): the double-double solution's
// error κ(Q)·2⁻¹⁰⁴, an ulp of f at κ near 4e15, enters squared. (Found by
// fuzz-contact-raw: μ² 0.4996 ulp above a double, cond(Q1) = 3.9e15,
// rounded the wrong way.)
PW85_INLINE dd refined_quad(double const hi[sym], double const lo[sym],
                            double const r[dim], double const *r_lo,
                            double const s[dim],
                            double const s_lo[dim]) noexcept {
  double rho[dim];
  PW85_UNROLL
  for (int i = 0; i < dim; ++i) {
    double t[2 + 7 * dim];
    int n = 0;
    t[n++] = r[i];
    if (r_lo != nullptr) t[n++] = r_lo[i];
    PW85_UNROLL
    for (int j = 0; j < dim; ++j) {
      int const k = sym_index(i, j);
      dd const a = two_prod(hi[k], s[j]);
      dd const b = two_prod(hi[k], s_lo[j]);
      dd const c = two_prod(lo[k], s[j]);
      t[n++] = -a.hi;
      t[n++] = -a.lo;
      t[n++] = -b.hi;
      t[n++] = -b.lo;
      t[n++] = -c.hi;
      t[n++] = -c.lo;
      t[n++] = -(lo[k] * s_lo[j]);
    }
    rho[i] = sum3(t, n).hi;
  }
  Dot2 acc{0.0, 0.0};
  double low = 0.0;
  PW85_UNROLL
  for (int i = 0; i < dim; ++i) {
    acc.add_product(r[i], s[i]);
    acc.add_product(r[i], s_lo[i]);
    if (r_lo != nullptr) low += r_lo[i] * (s[i] + s_lo[i]);
    low += (s[i] + s_lo[i]) * rho[i];
  }
  acc.err += low;
  return two_sum(acc.sum, acc.err);
}

}  // namespace

PW85_FMA_CLONES
bool compensated_dd(double lambda, double const r[dim], double const q1[sym],
                    double const q2[sym], bool with_p, Compensated *out,
                    double const *r_lo) noexcept {
  // f = λ(1−λ)·rᵀQ⁻¹r from the double-double factors, and Pᵢ = sᵀQᵢs from
  // s = s_hi + s_lo: sᵀQs = s_hiᵀQs_hi + 2·(Q·s_hi)·s_lo to second order
  // in s_lo. (From s rounded to double, Pᵢ would be off by up to
  // ε·√cond(Qᵢ) relative, and λ by as much.)
  double hi[sym], lo[sym];
  combine_dd(lambda, q1, q2, hi, lo);
  LdlDd fdd;
  if (!factorise_dd(hi, lo, &fdd)) return false;
  double s[dim], s_lo[dim];
  ldl_solve_quad_dd(fdd, r, r_lo, s, s_lo);
  dd const quad = refined_quad(hi, lo, r, r_lo, s, s_lo);
  dd const value = dd_mul(dd_mul(two_sum(1.0, -lambda), lambda), quad);
  out->f = value.hi;
  out->f_lo = value.lo;
  if (with_p) {
    out->p_exp = 0;
    p_from(q1, q2, s, s_lo, out);
    if (!(out->p1 > p_floor && out->p2 > p_floor)) {
      out->p_exp = scale_for_p(s, s_lo);
      p_from(q1, q2, s, s_lo, out);
    }
  }
  return true;
}

PW85_FMA_CLONES
bool solve_dd(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double s[dim], double s_lo[dim]) noexcept {
  LdlDd fdd;
  if (!factorise_q_dd(lambda, q1, q2, &fdd)) return false;
  ldl_solve_quad_dd(fdd, r, nullptr, s, s_lo);
  return true;
}

}  // namespace pw85::detail
