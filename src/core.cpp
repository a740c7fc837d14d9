// SPDX-License-Identifier: BSD-3-Clause
#include "core.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <cmath>
#include <algorithm>
#include <cfloat>
#include <cstddef>

#include "dd.hpp"
#include "pw85.h"

namespace pw85::detail {

namespace {

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
void sym_mul(double const a[sym], double const x[dim], double y[dim]) noexcept {
  y[0] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2];
  y[1] = a[1] * x[0] + a[3] * x[1] + a[4] * x[2];
  y[2] = a[2] * x[0] + a[4] * x[1] + a[5] * x[2];
}

double dot(double const x[dim], double const y[dim]) noexcept {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// Q(λ) = (1−λ)·Q1 + λ·Q2 (ch. 4, eq. (2)).
void combine(double lambda, double const q1[sym], double const q2[sym],
             double q[sym]) noexcept {
  double const mu = 1.0 - lambda;
  for (int i = 0; i < sym; ++i) q[i] = mu * q1[i] + lambda * q2[i];
}

double max_abs(double const *x, int n) noexcept {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::fmax(m, std::fabs(x[i]));
  return m;
}

// The exponent e with x = m·2^e, m in [0.5, 1); 0 for x = 0.
int exponent(double x) noexcept {
  int e = 0;
  std::frexp(x, &e);
  return e;
}

// Q(λ) = (1−λ)·Q1 + λ·Q2 in double-double: hi + lo is exact to ~2⁻¹⁰⁶
// relative (1 − λ itself is carried as a double-double).
void combine_dd(double lambda, double const q1[sym], double const q2[sym],
                double hi[sym], double lo[sym]) noexcept {
  dd const mu = two_sum(1.0, -lambda);
  for (int i = 0; i < sym; ++i) {
    dd const t = dd_add(dd_mul(mu, q1[i]), two_prod(lambda, q2[i]));
    hi[i] = t.hi;
    lo[i] = t.lo;
  }
}

// ρ = r − (Qhi + Qlo)·s, accumulated in double-double and rounded.
void exact_residual(double const hi[sym], double const lo[sym],
                    double const r[dim], double const s[dim],
                    double rho[dim]) noexcept {
  for (int i = 0; i < dim; ++i) {
    dd acc{r[i], 0.0};
    for (int j = 0; j < dim; ++j) {
      int const k = sym_index(i, j);
      acc = dd_add(acc, dd_neg(two_prod(hi[k], s[j])));
      acc = dd_add(acc, -lo[k] * s[j]);
    }
    rho[i] = dd_round(acc);
  }
}

// sᵀ·A·s for symmetric A, every product exact, summed in double-double: no
// cancellation error however ill-conditioned A is.
double quad_form_dd(double const a[sym], double const s[dim]) noexcept {
  dd acc{0.0, 0.0};
  for (int k = 0; k < sym; ++k) {
    double const factor = row_of[k] == col_of[k] ? 1.0 : 2.0;  // exact
    acc = dd_add(acc, dd_mul(two_prod(factor * a[k], s[row_of[k]]),
                             s[col_of[k]]));
  }
  return dd_round(acc);
}

// x·y in double-double.
dd dot_dd(double const x[dim], double const y[dim]) noexcept {
  dd acc = two_prod(x[0], y[0]);
  acc = dd_add(acc, two_prod(x[1], y[1]));
  return dd_add(acc, two_prod(x[2], y[2]));
}

// The problem that Brent's method sees: r, Q1, Q2 rescaled to order one.
struct Problem {
  double r[dim];
  double q1[sym];
  double q2[sym];
};

// −f(λ) for gsl_min; finite for every λ, as Brent's method requires (it
// calls GSL's error handler on a non-finite value): where Q(λ) fails to
// factorise (only possible through rounding), −f is taken as 0, the value
// at the ends of [0, 1], which Brent's method never prefers.
double brent_objective(double lambda, void *params) noexcept {
  auto const *p = static_cast<Problem const *>(params);
  double value = 0.0;
  if (!f(lambda, p->r, p->q1, p->q2, &value) || !std::isfinite(value))
    return 0.0;
  return -value;
}

// f(λ), ω(λ) = λ·ρ − (1 − λ) and two candidate steps towards its root,
// ρ = √(P2/P1), Pᵢ = sᵀ·Qᵢ·s,
// s = Q(λ)⁻¹·r. With v = Q⁻¹·(Q2 − Q1)·s, s′ = −v (ch. 4, eq. (5)), so
// Pᵢ′ = −2·sᵀ·Qᵢ·v and ρ′ = (ρ/2)·(P2′/P2 − P1′/P1).
struct NewtonTerms {
  double f;
  double omega;
  double domega;  // ω′ = 1 + ρ + λρ′
  double newton;  // λ − ω/ω′
  double fixed;   // 1/(1 + ρ), the root of ω if ρ were constant
};

bool newton_terms(double lambda, Problem const &p, NewtonTerms *t) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, p.q1, p.q2, q);
  if (!cholesky_decomp(q, l)) return false;
  double q12[sym];
  for (int i = 0; i < sym; ++i) q12[i] = p.q2[i] - p.q1[i];
  double s[dim], u[dim], v[dim], q1s[dim], q2s[dim];
  cholesky_solve(l, p.r, s);
  sym_mul(q12, s, u);
  cholesky_solve(l, u, v);
  sym_mul(p.q1, s, q1s);
  sym_mul(p.q2, s, q2s);
  double const p1 = dot(s, q1s);
  double const p2 = dot(s, q2s);
  if (!(p1 > 0.0 && p2 > 0.0)) return false;
  double const rho = std::sqrt(p2 / p1);
  double const drho = 0.5 * rho * (-2.0 * dot(q2s, v) / p2 + 2.0 * dot(q1s, v) / p1);
  t->f = lambda * (1.0 - lambda) * dot(p.r, s);
  t->omega = lambda * rho - (1.0 - lambda);
  // λ − ω/ω′ with ω′ = 1 + ρ + λρ′, rearranged so that it does not cancel
  // when the root is far smaller than λ (ρ ≫ 1: a thin disc).
  t->domega = 1.0 + rho + lambda * drho;
  t->newton = (1.0 + lambda * lambda * drho) / t->domega;
  t->fixed = 1.0 / (1.0 + rho);
  return std::isfinite(t->f) && std::isfinite(t->omega);
}

// Working memory of the GSL minimiser, on the stack: no allocation (GSL's
// gsl_min_fminimizer_alloc calls the error handler when malloc fails).
// Brent's state is 8 doubles in every GSL release.
constexpr std::size_t minimizer_state_size = 512;

// Relative size of a Newton step on the plain ω below which it is taken as
// converged: above its rounding noise, cond(Q)·ε, for cond(Q) up to 1e7,
// and small enough that one step on the compensated ω, whose error is
// quadratic, then reaches full accuracy.
constexpr double newton_noise = 1e-9;

}  // namespace

bool all_finite(double const *x, int n) noexcept {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(x[i])) return false;
  return true;
}

bool cholesky_decomp(double const a[sym], double l[sym]) noexcept {
  // Written so that a NaN pivot fails the test as a negative one does.
  if (!(a[0] > 0.0)) return false;
  l[0] = std::sqrt(a[0]);
  l[1] = a[1] / l[0];
  l[2] = a[2] / l[0];
  double const d1 = a[3] - l[1] * l[1];
  if (!(d1 > 0.0)) return false;
  l[3] = std::sqrt(d1);
  l[4] = (a[4] - l[1] * l[2]) / l[3];
  double const d2 = a[5] - l[2] * l[2] - l[4] * l[4];
  if (!(d2 > 0.0)) return false;
  l[5] = std::sqrt(d2);
  return true;
}

void forward_solve(double const l[sym], double const b[dim],
                   double y[dim]) noexcept {
  y[0] = b[0] / l[0];
  y[1] = (b[1] - l[1] * y[0]) / l[3];
  y[2] = (b[2] - l[2] * y[0] - l[4] * y[1]) / l[5];
}

void cholesky_solve(double const l[sym], double const b[dim],
                    double x[dim]) noexcept {
  double y[dim];
  forward_solve(l, b, y);
  x[2] = y[2] / l[5];
  x[1] = (y[1] - l[4] * x[2]) / l[3];
  x[0] = (y[0] - l[1] * x[1] - l[2] * x[2]) / l[0];
}

void spheroid(double a, double c, double const n[dim], double q[sym]) noexcept {
  // In double-double: the diagonal a² + (c² − a²)·nᵢ² cancels when c ≪ a
  // and nᵢ ≈ 1 (the polar entry of a flat oblate spheroid would otherwise
  // lose up to log10(a²/c²) digits).
  dd const a2 = two_prod(a, a);
  dd const d = dd_add(two_prod(c, c), dd_neg(a2));
  for (int k = 0; k < sym; ++k) {
    dd const t = dd_mul(dd_mul(d, n[row_of[k]]), n[col_of[k]]);
    q[k] = dd_round(row_of[k] == col_of[k] ? dd_add(a2, t) : t);
  }
}

bool f(double lambda, double const r[dim], double const q1[sym],
       double const q2[sym], double *value) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  if (!cholesky_decomp(q, l)) return false;
  // rᵀ·Q⁻¹·r = |L⁻¹·r|², a sum of squares: one triangular solve instead of
  // the two of ch. 4, eq. (4), and no cancellation.
  double y[dim];
  forward_solve(l, r, y);
  *value = lambda * (1.0 - lambda) * dot(y, y);
  return true;
}

namespace {

// s = Q(λ)⁻¹·r refined once against the exact residual, and that residual
// ρ = r − Q(λ)·s for the refined s. The refinement gains log10(1/(cond·ε))
// digits, so that s has a relative error of order (cond·ε)².
bool refined_solve(double lambda, double const r[dim], double const q1[sym],
                   double const q2[sym], double s[dim],
                   double rho[dim]) noexcept {
  double hi[sym], lo[sym], l[sym];
  combine_dd(lambda, q1, q2, hi, lo);
  if (!cholesky_decomp(hi, l)) return false;
  double ds[dim];
  cholesky_solve(l, r, s);
  exact_residual(hi, lo, r, s, rho);
  cholesky_solve(l, rho, ds);
  for (int i = 0; i < dim; ++i) s[i] += ds[i];
  exact_residual(hi, lo, r, s, rho);
  return true;
}

}  // namespace

bool f_accurate(double lambda, double const r[dim], double const q1[sym],
                double const q2[sym], double *value) noexcept {
  double s[dim], rho[dim];
  if (!refined_solve(lambda, r, q1, q2, s, rho)) return false;
  dd const rs = dd_add(dot_dd(r, s), dot(s, rho));  // rᵀQ⁻¹r − eᵀQe
  dd const w = dd_mul(two_sum(1.0, -lambda), lambda);  // λ(1−λ)
  *value = dd_round(dd_mul(w, rs));
  return true;
}

void residual(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double out[3]) noexcept {
  double q[sym];
  double l[sym];
  combine(lambda, q1, q2, q);
  if (!cholesky_decomp(q, l)) {
    out[0] = out[1] = out[2] = NAN;
    return;
  }
  double q12[sym];
  for (int i = 0; i < sym; ++i) q12[i] = q2[i] - q1[i];
  double s[dim], u[dim], v[dim];
  cholesky_solve(l, r, s);  // s = Q⁻¹·r
  sym_mul(q12, s, u);       // u = Q12·s
  cholesky_solve(l, u, v);  // v = Q⁻¹·u
  double const rs = dot(r, s);
  double const su = dot(s, u);
  double const uv = dot(u, v);
  double const w = lambda * (1.0 - lambda);
  if (!f_accurate(lambda, r, q1, q2, &out[0])) out[0] = w * rs;  // ch. 4 (4)
  out[1] = (2.0 * lambda - 1.0) * rs + w * su;                   // ch. 5 (4)
  out[2] = 2.0 * rs + 2.0 * (1.0 - 2.0 * lambda) * su - 2.0 * w * uv;  // (5)
}

bool is_positive_definite(double const q[sym]) noexcept {
  // Symmetric diagonal scaling by powers of two, D·Q·D with D = diag(2^-hᵢ)
  // and Qᵢᵢ ≈ 4^hᵢ: exact, preserves definiteness, and brings the diagonal
  // to [1/4, 1) so that no square overflows or underflows however widely
  // the diagonal entries range.
  for (int k = 0; k < sym; ++k)
    if (!std::isfinite(q[k])) return false;
  int h[dim];
  for (int i = 0; i < dim; ++i) {
    if (!(q[diag_of[i]] > 0.0)) return false;
    h[i] = exponent(q[diag_of[i]]) / 2;
  }
  double scaled[sym];
  for (int k = 0; k < sym; ++k)
    scaled[k] = std::ldexp(q[k], -(h[row_of[k]] + h[col_of[k]]));
  double l[sym];
  return cholesky_decomp(scaled, l);
}

int check_input(double const *r, double const *q1, double const *q2,
                double const *out) noexcept {
  if (r == nullptr || q1 == nullptr || q2 == nullptr || out == nullptr)
    return PW85_EFAULT;
  if (!all_finite(r, dim) || !all_finite(q1, sym) || !all_finite(q2, sym))
    return PW85_EDOM;
  if (!is_positive_definite(q1) || !is_positive_definite(q2))
    return PW85_ENOTPOSDEF;
  return PW85_SUCCESS;
}

int contact_function(double const r[dim], double const q1[sym],
                     double const q2[sym], double out[2]) noexcept {
  double const rmax = max_abs(r, dim);
  if (rmax == 0.0) {  // coincident centres: f ≡ 0, λ is arbitrary
    out[0] = 0.0;
    out[1] = 0.5;
    return PW85_SUCCESS;
  }

  // μ²(t·r, s·Q1, s·Q2) = (t²/s)·μ²(r, Q1, Q2) with λ unchanged (ch. 3,
  // eq. (6)). Powers of two make the rescaling exact. r is brought to order
  // one; Q1 and Q2 so that their diagonals (which bound every entry of a
  // positive definite matrix) straddle one: at order one for ordinary
  // input, and within range even for aspect ratios near 1e150.
  int const er = exponent(rmax);
  int emin = 0;
  int emax = 0;
  for (int k = 0; k < 2; ++k) {
    double const *q = k == 0 ? q1 : q2;
    for (int i : diag_of) {
      int const e = exponent(q[i]);
      emin = (k == 0 && i == 0) ? e : std::min(emin, e);
      emax = (k == 0 && i == 0) ? e : std::max(emax, e);
    }
  }
  int const eq = emin + (emax - emin) / 2;
  Problem p;
  for (int i = 0; i < dim; ++i) p.r[i] = std::ldexp(r[i], -er);
  for (int i = 0; i < sym; ++i) {
    p.q1[i] = std::ldexp(q1[i], -eq);
    p.q2[i] = std::ldexp(q2[i], -eq);
  }
  // Only when the diagonals of Q1 and Q2 span more than the range of a
  // double can the rescaling have flushed an entry that mattered to zero.
  if (!is_positive_definite(p.q1) || !is_positive_definite(p.q2))
    return PW85_ERANGE;

  // Brent's method on −f over [0, 1] from λ = ½ (ch. 5). f(0) = f(1) = 0 and
  // f(½) > 0, so the bracket encloses the maximum; checked all the same,
  // since gsl_min_fminimizer_set_with_values calls GSL's error handler
  // otherwise.
  double const f_mid = brent_objective(0.5, &p);
  double lambda = 0.5;
  if (f_mid < 0.0) {
    alignas(std::max_align_t) unsigned char state[minimizer_state_size];
    gsl_min_fminimizer_type const *type = gsl_min_fminimizer_brent;
    if (type->size > sizeof state) return PW85_ENOMEM;
    gsl_min_fminimizer s{};
    s.type = type;
    s.state = state;
    gsl_function objective{&brent_objective, &p};
    gsl_min_fminimizer_set_with_values(&s, &objective, 0.5, f_mid, 0.0, 0.0,
                                       1.0, 0.0);
    for (int iter = 0; iter < PW85_MAX_ITER; ++iter) {
      if (gsl_min_fminimizer_iterate(&s) != GSL_SUCCESS) break;
      if (gsl_min_test_interval(s.x_lower, s.x_upper, PW85_LAMBDA_ATOL, 0.0) ==
          GSL_SUCCESS)
        break;
    }
    lambda = s.x_minimum;
  }
  double const lambda_brent = lambda;

  // Newton–Raphson refinement (ch. 5). The root of g = μ2² − μ1² is sought
  // as that of ω = μ2/μ1 − 1 scaled by (1−λ): ω(λ) = λ·ρ(λ) − (1 − λ) with
  // ρ = √(P2/P1), Pᵢ = sᵀ·Qᵢ·s, since μ1² = (1−λ)²·P1 and μ2² = λ²·P2
  // (ch. 5, eq. (1)). ω has the sign of g but is linear for two spheres and
  // nearly so otherwise, where g varies sharply near λ = 0 or 1 and Newton's
  // steps on g overshoot. The steps are safeguarded: ω(0) = −1 < 0 < ω(1),
  // every evaluation narrows [lo, hi], and a step leaving it bisects.
  // μ² is then f at the last iterate, evaluated with compensated arithmetic
  // (f_accurate); the plain f that Brent's method compares is off by up to
  // cond(Q)·ε.
  double lo = 0.0;
  double hi = 1.0;
  bool converged = false;
  double domega = 0.0;  // ω′ at the last iterate, once converged
  for (int k = 0; k < PW85_NR_ITER; ++k) {
    NewtonTerms t;
    if (!newton_terms(lambda, p, &t)) break;
    domega = t.domega;
    if (t.omega == 0.0) {
      converged = true;
      break;
    }
    (t.omega < 0.0 ? lo : hi) = lambda;
    // Newton's step; where it leaves [lo, hi] (ρ′ is computed with
    // cancellation when P1 and P2 vary fast), the sphere model's 1/(1 + ρ),
    // exact when ρ is constant; bisection as a last resort.
    double next = t.newton;
    if (std::fabs(next - lambda) <= newton_noise * std::fmin(lambda, 1.0 - lambda)) {
      // Converged as far as the plain ω can tell: its rounding noise
      // (cond·ε) would make further steps, and the signs that set [lo, hi],
      // jitter. The step on the compensated ω below finishes.
      if (next > 0.0 && next < 1.0) lambda = next;
      converged = true;
      break;
    }
    if (!(next > lo && next < hi)) next = t.fixed;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    lambda = next;
  }
  // A last Newton step on ω computed from the refined s: the plain ω is off
  // by up to cond(Q)·ε, and so was λ (by 6e-9 on the reference data).
  if (converged && domega > 0.0) {
    double s[dim], rho[dim];
    if (refined_solve(lambda, p.r, p.q1, p.q2, s, rho)) {
      double const rho12 =
          std::sqrt(quad_form_dd(p.q2, s) / quad_form_dd(p.q1, s));
      double const omega = lambda * rho12 - (1.0 - lambda);
      // [lo, hi] came from the signs of the plain ω, unreliable at this
      // scale: the step is only bounded, by Brent's tolerance.
      double const step = omega / domega;
      if (std::fabs(step) <= PW85_LAMBDA_ATOL && lambda - step > 0.0 &&
          lambda - step < 1.0)
        lambda -= step;
    }
  }
  double best = 0.0;
  if (!f_accurate(lambda, p.r, p.q1, p.q2, &best)) best = 0.0;
  // Should Newton's steps have failed to converge, Brent's estimate may be
  // the better one: every f(λ) is a lower bound of μ², keep the larger.
  double at_brent = 0.0;
  if (!converged && f_accurate(lambda_brent, p.r, p.q1, p.q2, &at_brent) &&
      at_brent > best) {
    best = at_brent;
    lambda = lambda_brent;
  }

  double const mu2 = std::ldexp(best, 2 * er - eq);
  out[1] = lambda;
  if (std::isinf(mu2)) {
    out[0] = HUGE_VAL;
    return PW85_ERANGE;
  }
  out[0] = mu2;
  return PW85_SUCCESS;
}

}  // namespace pw85::detail
