// SPDX-License-Identifier: BSD-3-Clause
// The two historical contact functions of docs/legacy-api.rst: Newton–Raphson on
// f′ of implementation #1, and bisection on the numerator of f′ of
// implementation #2.
#include <cmath>
#include <initializer_list>

#include "checks.hpp"
#include "legacy.hpp"
#include "scaling.hpp"

namespace pw85::legacy::detail {

namespace {

namespace core = pw85::detail;

using Scaled = core::Scaled<3>;

// The start of both contact functions, for input that passed
// core::check_input(): core::rescale(), then the answers that need no
// search. Returns true when *status (and out) is already the answer:
// Status::out_of_range when the diagonals of Q1 and Q2 together span more
// than the range of a double, or when a form (positive definite as stored:
// check_input()) cannot be factorised in double once rescaled with the
// other (singular to that precision); for coincident centres, μ² = 0 and λ = ½ (f ≡ 0, λ
// is arbitrary), as pw85_contact_function answers.
bool answered_before_search(double const r[dim], double const q1[sym],
                            double const q2[sym], Scaled *p, double out[2],
                            Status *status) noexcept {
  core::Ldl<3> f1, f2;
  if (!core::rescale(r, q1, q2, p) || !core::ldl_decomp(p->q1, &f1) ||
      !core::ldl_decomp(p->q2, &f2)) {
    *status = Status::out_of_range;
    return true;
  }
  if (p->r_is_zero) {
    out[0] = 0.0;
    out[1] = 0.5;
    *status = Status::success;
    return true;
  }
  return false;
}

// out = {μ², λ} from the rescaled problem's f; Status::out_of_range when μ²
// overflows (out[0] = +∞), as pw85_contact_function does.
Status unscale(Scaled const &p, double f, double lambda, Status status,
              double out[2]) noexcept {
  double const mu2 = std::ldexp(f, p.shift);
  out[1] = lambda;
  if (std::isinf(mu2)) {
    out[0] = HUGE_VAL;
    return Status::out_of_range;
  }
  out[0] = mu2;
  return status;
}

// Horner's scheme for p[0] + p[1]·x + ... + p[n−1]·x^(n−1).
template <int n>
double horner(double const (&p)[n], double x) noexcept {
  double v = p[n - 1];
  for (int i = n - 2; i >= 0; --i) v = v * x + p[i];
  return v;
}

}  // namespace

Status contact_function1(double const r[dim], double const q1[sym],
                         double const q2[sym], double out[2]) noexcept {
  Scaled p;
  if (Status status; answered_before_search(r, q1, q2, &p, out, &status))
    return status;

  // Plain Newton–Raphson on f′(λ) = 0 from λ = ½: λ ← λ − f′(λ)/f″(λ), f′
  // and f″ from docs/implementation.rst, eqs. (4.6) and (4.9), with no safeguard. docs/optimisation.rst
  // explains why it is not robust: f varies sharply near λ = 0 or 1 when the
  // ellipsoids differ in size or shape, and the steps overshoot, out of
  // [0, 1] (already for two spheres of radii 1 and 3, from where it comes
  // back; with radii 1 and 3.25 it does not). An iterate outside
  // [0, 1] is kept (f is a rational function defined wherever Q(λ) is
  // positive definite) and may come back. The method fails when Q(λ) is not
  // positive definite at an iterate, when f″(λ) = 0, when nr_max_iter steps
  // do not converge, or when it converges to a root of f′ outside [0, 1]
  // (inside, f′ has a single root, the maximiser). Each f(λ) with λ in
  // [0, 1] is a lower bound of μ² (μ² = max f): on failure the best one met
  // is returned, with Status::no_convergence; λ = ½ is always among them.
  double lambda = 0.5;
  double best_f = 0.0;
  double best_lambda = 0.5;
  for (int iter = 0; iter < nr_max_iter; ++iter) {
    double f = 0.0;
    double d[3];
    if (!f1(lambda, p.r, p.q1, p.q2, &f, d)) break;
    bool const inside = lambda >= 0.0 && lambda <= 1.0;
    if (inside && (f > best_f || iter == 0)) {
      best_f = f;
      best_lambda = lambda;
    }
    double const step = d[1] / d[2];
    if (!std::isfinite(step)) break;  // f″ = 0, or overflow
    lambda -= step;
    if (std::fabs(step) <= nr_step_tol) {
      // Converged: μ² = f(λ) at the last iterate (docs/implementation.rst, eq. (4.4)).
      if (!(lambda >= 0.0 && lambda <= 1.0)) break;
      if (!f1(lambda, p.r, p.q1, p.q2, &f, nullptr)) break;
      return unscale(p, f, lambda, Status::success, out);
    }
  }
  return unscale(p, best_f, best_lambda, Status::no_convergence, out);
}

Status contact_function2(double const r[dim], double const q1[sym],
                         double const q2[sym], double out[2]) noexcept {
  Scaled p;
  if (Status status; answered_before_search(r, q1, q2, &p, out, &status))
    return status;

  double q3[sym];
  double q4[sym];
  for (int i = 0; i < sym; ++i) {
    q3[i] = 2.0 * p.q1[i] - p.q2[i];    // Q(−1)
    q4[i] = 0.5 * (p.q1[i] + p.q2[i]);  // Q(½)
  }
  double a[dim];
  double b[dim + 1];
  rT_adjQ_r_as_poly(p.r, p.q1, p.q2, q3, a);  // docs/implementation.rst, eqs. (4.12a)–(4.12c)
  detQ_as_poly(p.q1, p.q2, q3, q4, b);        // docs/implementation.rst, eqs. (4.12d)–(4.12g)

  // f′ = c/b², c of degree 6 (docs/implementation.rst, eqs. (4.13)–(4.14)); c[k] from
  // docs/implementation.rst, eq. (4.15a) for k = 0 to eq. (4.15g) for k = 6.
  double const c[7] = {
      a[0] * b[0],
      2.0 * (a[1] - a[0]) * b[0],
      -a[0] * (b[1] + b[2]) + 3.0 * b[0] * (a[2] - a[1]) + a[1] * b[1],
      2.0 * (b[1] * (a[2] - a[1]) - a[0] * b[3]) - 4.0 * a[2] * b[0],
      (a[0] - a[1]) * b[3] + (a[2] - a[1]) * b[2] - 3.0 * a[2] * b[1],
      -2.0 * a[2] * b[2],
      -a[2] * b[3],
  };
  if (!core::all_finite<7>(c)) return Status::out_of_range;

  // Bisection on c over [0, 1]: c(0) = a0·b0 > 0 > c(1) = −a(1)·b(1) in
  // exact arithmetic, and c has one root there (docs/implementation.rst, "Implementation 2"). The bracket
  // halves until it is one ulp wide; the signs are those of the rounded c.
  double lo = 0.0;
  double hi = 1.0;
  for (int iter = 0; iter < bisection_max_iter; ++iter) {
    double const mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi)) break;
    double const c_mid = horner(c, mid);
    if (c_mid > 0.0) {
      lo = mid;
    } else if (c_mid < 0.0) {
      hi = mid;
    } else {
      lo = hi = mid;
    }
  }
  double const lambda = 0.5 * (lo + hi);
  // μ² = f(λ) = λ(1−λ)·a(λ)/b(λ), docs/implementation.rst, eq. (4.10).
  double const a_lambda = horner(a, lambda);
  double const b_lambda = horner(b, lambda);
  double const mu2 = lambda * (1.0 - lambda) * a_lambda / b_lambda;
  // The root lies strictly inside (0, 1), where a > 0 (adj Q(λ) is
  // positive definite) and b > 0. When the rounded coefficients have no
  // sign change of c inside (0, 1), bisection ends on 0 or 1, where
  // f = 0 (and b(1) may have rounded to 0 or below: docs/implementation.rst, "Accuracy"): the
  // method failed, and the only lower bound of μ² it knows is 0.
  if (!(lambda > 0.0 && lambda < 1.0 && a_lambda > 0.0 && b_lambda > 0.0 &&
        std::isfinite(mu2)))
    return unscale(p, 0.0, lambda, Status::no_convergence, out);
  return unscale(p, mu2, lambda, Status::success, out);
}

}  // namespace pw85::legacy::detail
