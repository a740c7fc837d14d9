// SPDX-License-Identifier: BSD-3-Clause
// The L·D·Lᵀ factorisation of a symmetric D×D matrix (D = 2 or 3) and the
// solves built on it (private, header-only: inlined, and compiled for the
// target of the caller; see PW85_FMA_CLONES in compiler.hpp). Each kernel
// is written out for 3 and for 2 (the 2D one is the 3D one without its
// last row and column: the same operations, in the same order).
#ifndef PW85_SRC_LDL_HPP
#define PW85_SRC_LDL_HPP

#include "compiler.hpp"
#include "sym.hpp"

namespace pw85::detail {

// Q = L·D·Lᵀ with L unit lower triangular: no square root, unlike the
// Cholesky factor of docs/implementation.rst, "Implementation 1", and the same pivots dᵢ (squares of its
// diagonal), whose positivity decides definiteness.
template <int D = dim>
struct Ldl;

template <>
struct Ldl<3> {
  // The entries of L below its unit diagonal:
  //   L = [[1, 0, 0], [l10, 1, 0], [l20, l21, 1]].
  double l10, l20, l21;
  // The reciprocal pivots 1/dᵢ, D = diag(d0, d1, d2).
  double inv_d[3];
};

template <>
struct Ldl<2> {
  double l10;        // L = [[1, 0], [l10, 1]]
  double inv_d[2];   // 1/dᵢ, D = diag(d0, d1)
};

// Returns false when a pivot is not > 0 (NaN included).
template <int D>
PW85_INLINE bool ldl_decomp(double const *a, Ldl<D> *f) noexcept {
  double const d0 = a[0];
  if (!(d0 > 0.0)) return false;
  f->inv_d[0] = 1.0 / d0;
  f->l10 = a[1] * f->inv_d[0];
  if constexpr (D == 3) f->l20 = a[2] * f->inv_d[0];
  double const d1 = a[Layout<D>::diag[1]] - f->l10 * a[1];
  if (!(d1 > 0.0)) return false;
  f->inv_d[1] = 1.0 / d1;
  if constexpr (D == 3) {
    double const e = a[4] - f->l10 * a[2];  // L21·d1
    f->l21 = e * f->inv_d[1];
    double const d2 = a[5] - f->l20 * a[2] - f->l21 * e;
    if (!(d2 > 0.0)) return false;
    f->inv_d[2] = 1.0 / d2;
  }
  return true;
}

// The same factorisation with a shorter chain of dependent operations, for
// Q(λ) in the search, where latency counts: each pivot waits only for the
// reciprocal of the one before, dᵢ being formed from products of entries
// computed meanwhile (d1 = a11 − a01²/d0, not a11 − L10·a01; in 2D
// 1/d1 = d0/det(a), below, so that the two divisions run side by side).
// The roundings differ, not their number. Those products leave the range
// of doubles sooner than the terms of ldl_decomp(): the diagonal of a must
// lie in [2^−400, 2^400] (Scaled::moderate), where no product overflows,
// and one that underflows is below ε times the diagonal entry it is
// subtracted from, the rounding error of that subtraction anyway (while
// cond(a) is below 2^170). The input forms are factorised by ldl_decomp()
// alone, whose definiteness decisions the tests pin.
template <int D>
PW85_INLINE bool ldl_decomp_fast(double const *a, Ldl<D> *f) noexcept {
  double const d0 = a[0];
  if (!(d0 > 0.0)) return false;
  if constexpr (D == 2) {
    // d1 = det(a)/d0, so 1/d1 = d0/det(a): the two divisions are
    // independent, not one waiting for the other (the 2D overlap test
    // near contact 5% faster, bench-2d; 3D has no such shortcut without
    // a third division in the chain). det(a) = a00·a11 − a01² cancels as
    // d1 = a11 − a01²/d0 does; its sign decides definiteness as d1's.
    double const det = a[0] * a[2] - a[1] * a[1];
    if (!(det > 0.0)) return false;
    double const inv0 = 1.0 / d0;
    f->inv_d[0] = inv0;
    f->l10 = a[1] * inv0;
    f->inv_d[1] = d0 / det;
    return true;
  }
  double const inv0 = 1.0 / d0;
  f->inv_d[0] = inv0;
  f->l10 = a[1] * inv0;
  if constexpr (D == 3) f->l20 = a[2] * inv0;
  double const d1 = a[Layout<D>::diag[1]] - (a[1] * a[1]) * inv0;
  if (!(d1 > 0.0)) return false;
  double const inv1 = 1.0 / d1;
  f->inv_d[1] = inv1;
  if constexpr (D == 3) {
    double const e = a[4] - (a[1] * a[2]) * inv0;  // L21·d1
    f->l21 = e * inv1;
    double const d2 = a[5] - (a[2] * a[2]) * inv0 - (e * e) * inv1;
    if (!(d2 > 0.0)) return false;
    f->inv_d[2] = 1.0 / d2;
  }
  return true;
}

// Which of the two factorisations Q(λ) gets: fast only where the caller
// knows the range condition of ldl_decomp_fast() to hold. Callers pass a
// constant where they can, so that the other is not compiled in.
template <int D>
PW85_INLINE bool ldl_decomp_q(double const *a, Ldl<D> *f, bool fast) noexcept {
  return fast ? ldl_decomp_fast(a, f) : ldl_decomp(a, f);
}

// z = L⁻¹·b; then bᵀ·Q⁻¹·b = Σ zᵢ²/dᵢ.
template <int D>
PW85_INLINE void ldl_forward(Ldl<D> const &f, double const *b,
                             double *z) noexcept {
  z[0] = b[0];
  z[1] = b[1] - f.l10 * z[0];
  if constexpr (D == 3) z[2] = b[2] - f.l20 * z[0] - f.l21 * z[1];
}

// bᵀ·Q⁻¹·b = Σ zᵢ²/dᵢ, a sum of non-negative terms, from z = L⁻¹·b.
template <int D>
PW85_INLINE double ldl_quad(Ldl<D> const &f, double const *z) noexcept {
  if constexpr (D == 2)
    return z[0] * z[0] * f.inv_d[0] + z[1] * z[1] * f.inv_d[1];
  else
    return z[0] * z[0] * f.inv_d[0] + z[1] * z[1] * f.inv_d[1] +
         z[2] * z[2] * f.inv_d[2];
}

// bᵀ·Q⁻¹·b.
template <int D>
PW85_INLINE double ldl_quad_inverse(Ldl<D> const &f, double const *b) noexcept {
  double z[D];
  ldl_forward(f, b, z);
  return ldl_quad(f, z);
}

// x = Q⁻¹·b from z = L⁻¹·b (backward substitution with D⁻¹ and Lᵀ).
template <int D>
PW85_INLINE void ldl_backward(Ldl<D> const &f, double const *z,
                              double *x) noexcept {
  if constexpr (D == 2) {
    x[1] = z[1] * f.inv_d[1];
    x[0] = z[0] * f.inv_d[0] - f.l10 * x[1];
  } else {
    x[2] = z[2] * f.inv_d[2];
    x[1] = z[1] * f.inv_d[1] - f.l21 * x[2];
    x[0] = z[0] * f.inv_d[0] - f.l10 * x[1] - f.l20 * x[2];
  }
}

// x = Q⁻¹·b. x may alias b.
template <int D>
PW85_INLINE void ldl_solve(Ldl<D> const &f, double const *b,
                           double *x) noexcept {
  double z[D];
  ldl_forward(f, b, z);
  ldl_backward(f, z, x);
}

// x = Q⁻¹·b, returning bᵀ·Q⁻¹·b from the same forward pass, bitwise equal
// to ldl_quad_inverse(f, b).
template <int D>
PW85_INLINE double ldl_solve_quad(Ldl<D> const &f, double const *b,
                                  double *x) noexcept {
  double z[D];
  ldl_forward(f, b, z);
  ldl_backward(f, z, x);
  return ldl_quad(f, z);
}

// tr(Q⁻¹) = Σₖ (1/dₖ)·Σᵢ (L⁻¹)ₖᵢ², with
// L⁻¹ = [[1, 0, 0], [−l10, 1, 0], [l10·l21 − l20, −l21, 1]] (in 2D its
// upper left 2×2 block).
template <int D>
PW85_INLINE double ldl_trace_inverse(Ldl<D> const &f) noexcept {
  if constexpr (D == 2) {
    return f.inv_d[0] + f.inv_d[1] * (1.0 + f.l10 * f.l10);
  } else {
    double const m20 = f.l10 * f.l21 - f.l20;
    return f.inv_d[0] + f.inv_d[1] * (1.0 + f.l10 * f.l10) +
           f.inv_d[2] * (1.0 + f.l21 * f.l21 + m20 * m20);
  }
}

// κ̄(Q) = tr(Q)·tr(Q⁻¹) ≥ λmax/λmin, an upper bound of the 2-norm condition
// number of Q = L·D·Lᵀ.
template <int D>
PW85_INLINE double ldl_cond_bound(double const *q, Ldl<D> const &f) noexcept {
  return trace<D>(q) * ldl_trace_inverse(f);
}

// Q factorised and s = Q⁻¹·r, both in plain double: what the compensated
// evaluation (compensated.hpp) needs from a plain one at the same λ.
template <int D = dim>
struct LdlSolution {
  Ldl<D> fac;
  double s[D];
};

}  // namespace pw85::detail

#endif  // PW85_SRC_LDL_HPP
