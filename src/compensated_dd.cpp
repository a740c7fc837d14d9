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

// Q(λ) = hi + lo (combine_dd()) factorised in double-double; false when a
// pivot is not > 0.
PW85_INLINE bool factorise_q_dd(double lambda, double const q1[sym],
                                double const q2[sym], LdlDd *f) noexcept {
  double hi[sym], lo[sym];
  combine_dd(lambda, q1, q2, hi, lo);
  dd a[sym];
  for (int k = 0; k < sym; ++k) a[k] = two_sum(hi[k], lo[k]);
  return ldl_decomp_dd(a, f);
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
  LdlDd fdd;
  if (!factorise_q_dd(lambda, q1, q2, &fdd)) return false;
  double s[dim], s_lo[dim];
  dd const quad = ldl_solve_quad_dd(fdd, r, r_lo, s, s_lo);
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
