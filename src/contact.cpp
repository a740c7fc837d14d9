// SPDX-License-Identifier: BSD-3-Clause
// The contact function μ² = max f over [0, 1] (seed ch. 5) and the certified
// overlap test. Equation numbers refer to the seed documentation.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>

#include "core.hpp"
#include "dd.hpp"
#include "linalg.hpp"
#include "pw85.h"

namespace pw85::detail {

// GSL's value (gsl/min/brent.c, brent_init).
double const gsl_brent_golden = 0.3819660;

// The point a + golden·(b − a) that GSL computes is moved onto c by
// corrections of a by the miss (as a moves by one ulp with b fixed, that
// point moves by about 0.62 ulp, so it can reach c), alternating with
// corrections of b by the miss over golden (needed where b − a rounds to a
// coarser binade than a, so that a's ulp steps skip c). Of 1.4 million
// random brackets 99.3% needed no correction, 0.4% one and the rest three
// (tests/test-core.cpp checks 68,384 against GSL itself); a bracket that
// missed would cost one evaluation of f, nothing else.
void golden_bracket(double c, double w, double *a, double *b) noexcept {
  double lo = c - gsl_brent_golden * w;
  double hi = lo + w;
  for (int k = 0; k < 6; ++k) {
    double const miss = c - (lo + gsl_brent_golden * (hi - lo));
    if (miss == 0.0) break;
    if (k % 2 == 0)
      lo += miss;
    else
      hi += miss / gsl_brent_golden;
  }
  *a = lo;
  *b = hi;
}

namespace {

// Working memory of the GSL minimiser, on the stack: no allocation (GSL's
// gsl_min_fminimizer_alloc calls the error handler when malloc fails).
// Brent's state is 8 doubles in every GSL release.
constexpr std::size_t minimizer_state_size = 512;

// Relative size of a Newton step on the plain ω after which the iteration
// stops (the step taken): its error is then O(step²) ≈ 1e-10, the rounding
// noise of the plain ω for cond(Q) near 1e6. (At 1e-4, λ ended 6e-14 off on
// the reference data, for 1% fewer evaluations.)
constexpr double newton_accept = 1e-5;

// Newton steps on ω from the warm start, before Brent's method certifies.
constexpr int warm_newton_iter = 8;

// The problem as solved: the rescaled input, with the factorisations of
// Q1 and Q2.
struct Problem : Scaled {
  Ldl f1;
  Ldl f2;
};

// rescale(), then the factorisations of Q1 and Q2, which decide their
// definiteness. Input: finite. Returns PW85_SUCCESS, PW85_ENOTPOSDEF, or
// PW85_ERANGE when the diagonals span more than the range of a double.
int prepare(double const r[dim], double const q1[sym], double const q2[sym],
            Problem *p) noexcept {
  if (rescale(r, q1, q2, p) && ldl_decomp(p->q1, &p->f1) &&
      ldl_decomp(p->q2, &p->f2))
    return PW85_SUCCESS;
  // Not definite, or definite but out of range once rescaled together.
  if (!is_positive_definite(q1) || !is_positive_definite(q2))
    return PW85_ENOTPOSDEF;
  return PW85_ERANGE;
}

// A lower bound of μ² valid for every input: each ellipsoid lies in the
// sphere of radius √λmax(Qᵢ) ≤ √tr(Qᵢ) about its centre, and those spheres
// meet only once scaled by |r|/(√tr Q1 + √tr Q2). Computed with a few
// roundings, whatever the conditioning of Q1 and Q2: the factor 1 − 16ε
// keeps it a lower bound.
double sphere_lower_bound(Problem const &p) noexcept {
  double const radii = std::sqrt(p.q1[0] + p.q1[3] + p.q1[5]) +
                       std::sqrt(p.q2[0] + p.q2[3] + p.q2[5]);
  return dot(p.r, p.r) / (radii * radii) * (1.0 - 16.0 * DBL_EPSILON);
}

// The largest double below 1: where a step rounds onto λ = 1 (the root
// lies within an ulp of it), λ goes here instead, where f ≠ 0.
constexpr double below_one = 1.0 - 0x1p-53;

// 1/(1 + √(x/y)) for x, y ≥ 0, computed as √y/(√y + √x): the square roots
// side by side, then one division (rather than a division, a square root
// and a division in a row), and no ratio x/y to overflow or underflow.
double sphere_root(double x, double y) noexcept {
  double const root_y = std::sqrt(y);
  return root_y / (root_y + std::sqrt(x));
}

// The sphere model's maximiser, exact for two spheres (Qᵢ = aᵢ²·I gives
// λ = a1/(a1 + a2)): λ0 = 1/(1 + √(a1/a2)) with aᵢ = rᵀQᵢ⁻¹r.
double warm_start(double a1, double a2) noexcept {
  double const lambda = sphere_root(a1, a2);
  if (lambda >= 1.0) return below_one;
  if (lambda > 0.0) return lambda;
  // 0 or NaN: a2 = 0, or a2 = ∞ (where λ0 → 1), or both 0 or both ∞.
  return a1 < a2 ? below_one : 0.5;
}

double warm_start(Problem const &p) noexcept {
  return warm_start(ldl_quad_inverse(p.f1, p.r), ldl_quad_inverse(p.f2, p.r));
}

// Where the search goes when a Newton step on ω (below) leaves the bracket
// of the root: Newton's step from the end of [0, 1] on the root's side. At
// λ = 0, ω = −1 and ω′ = 1 + ρ(0) (the λρ′ term vanishes), so the step
// lands on 1/(1 + ρ(0)); at λ = 1 the step on ω/ρ = λ − (1−λ)/ρ, whose
// value is 1 and slope 1 + 1/ρ(1), lands on 1/(1 + ρ(1)). Both are exact
// when ρ is constant (two spheres), and close to the root when it is near
// that end: a thin disc against a wide body, where ω has a plateau that
// defeats Newton's steps from the middle (9.8% of the reference pairs
// took more than 8 steps without them). s = Q1⁻¹r at λ = 0, where
// ρ(0)² = sᵀQ2s / rᵀQ1⁻¹r, and s = Q2⁻¹r at λ = 1, where
// ρ(1)² = rᵀQ2⁻¹r / sᵀQ1s, from the factors of Q1 and Q2. A NaN (both
// forms 0, or both infinite) is rejected where it is used, as any point
// outside the bracket.
double step_from_end(Problem const &p, bool from_zero) noexcept {
  double s[dim], t[dim];
  double const a = ldl_solve_quad(from_zero ? p.f1 : p.f2, p.r, s);
  sym_mul(from_zero ? p.q2 : p.q1, s, t);
  double const b = dot(s, t);
  return from_zero ? sphere_root(b, a) : sphere_root(a, b);
}

// −f(λ), the objective of Brent's method, in plain double; finite for
// every λ, as Brent's method requires (it calls GSL's error handler on a
// non-finite value): where Q(λ) fails to factorise (only possible through
// rounding), −f is taken as 0, the value at the ends of [0, 1], which
// Brent's method never prefers.
//
// The functions of the search take Fast = p.moderate as a template
// argument, so that each compiled search factorises Q(λ) one way
// (ldl_decomp_q() in linalg.hpp).
template <bool Fast>
double brent_objective(double lambda, Problem const &p) noexcept {
  double value = 0.0;
  if (!f_plain(lambda, p.r, p.q1, p.q2, Fast, &value) || !std::isfinite(value))
    return 0.0;
  return -value;
}

// GSL's Brent's method evaluates the objective once as it starts, at
// a + golden·(b − a) on the bracket [a, b] it is given (gsl/min/brent.c,
// brent_init). certify_with_brent() places the bracket so that this point
// is the centre λ (golden_bracket()), where brent_objective() is already
// known: the objective that GSL calls returns that value there, which is
// the value it would compute, and evaluates anywhere else. (Should a GSL
// release move that point, the objective is merely evaluated there.)
struct KnownCentre {
  Problem const *p;
  double lambda;
  double value;  // brent_objective(lambda, *p)
};

template <bool Fast>
double gsl_objective(double lambda, void *params) noexcept {
  auto const *c = static_cast<KnownCentre const *>(params);
  if (lambda == c->lambda) return c->value;
  return brent_objective<Fast>(lambda, *c->p);
}

// At λ, in plain double: f, μ1² = (1−λ)²·P1, μ2² = λ²·P2 (ch. 5,
// eqs. (1a)–(1b)), Pᵢ = sᵀ·Qᵢ·s, s = Q(λ)⁻¹·r, and Newton's step on
// ω(λ) = λ·ρ − (1 − λ), ρ = √(P2/P1). ω = (μ2 − μ1)/√P1 has the sign of
// g = μ2² − μ1² (ch. 5, eq. (4)) but is linear for two spheres and nearly
// so otherwise, where g varies sharply near λ = 0 or 1. With
// v = Q⁻¹·(Q2 − Q1)·s, s′ = −v (ch. 4, eq. (5)), so Pᵢ′ = −2·sᵀ·Qᵢ·v and
// ρ′ = (ρ/2)·(P2′/P2 − P1′/P1). Also an upper bound of cond(Q(λ)),
// tr(Q)·tr(Q⁻¹), for the rounding margins of the overlap test.
struct Terms {
  double f;       // as brent_objective() computes it, bit for bit
  double mu1, mu2;
  double omega;
  double domega;  // ω′ = 1 + ρ + λρ′
  double newton;  // λ − ω/ω′
  double rho;     // ρ: 1/(1 + ρ) is the root of ω if ρ were constant
  double cond;    // ≥ cond(Q(λ))
  Plain plain;    // the factors of Q(λ) and s
};

// What terms() computes beyond f, ω and ρ: each phase asks only for what
// it uses.
enum : unsigned { want_newton = 1u, want_bounds = 2u };

template <bool Fast>
bool terms(double lambda, Problem const &p, unsigned want, Terms *t) noexcept {
  double q[sym];
  combine(lambda, p.q1, p.q2, q);
  Ldl &fac = t->plain.fac;
  if (!ldl_decomp_q(q, &fac, Fast)) return false;
  double *s = t->plain.s;
  double q1s[dim], q2s[dim];
  double const quad = ldl_solve_quad(fac, p.r, s);
  sym_mul(p.q1, s, q1s);
  sym_mul(p.q2, s, q2s);
  double const p1 = dot(s, q1s);
  double const p2 = dot(s, q2s);
  if (!(p1 > 0.0 && p2 > 0.0)) return false;
  double const mu = 1.0 - lambda;
  double const m1 = std::sqrt(p1);
  double const m2 = std::sqrt(p2);
  double const rho = m2 / m1;
  t->f = lambda * mu * quad;  // the expression of f_plain() (linalg.hpp)
  t->omega = lambda * rho - mu;
  t->rho = rho;
  bool ok = std::isfinite(t->omega) && std::isfinite(t->f);
  if (want & want_newton) {
    // aᵢ = sᵀQᵢv = zᵢᵀ·D⁻¹·(z2 − z1) with zᵢ = L⁻¹Qᵢs, since
    // v = L⁻ᵀD⁻¹L⁻¹(Q2 − Q1)s: two forward substitutions side by side
    // instead of a forward and a backward one in a row.
    double z1[dim], z2[dim], y[dim];
    ldl_forward(fac, q1s, z1);
    ldl_forward(fac, q2s, z2);
    PW85_UNROLL
    for (int i = 0; i < dim; ++i) y[i] = (z2[i] - z1[i]) * fac.inv_d[i];
    double const a1 = dot(z1, y);
    double const a2 = dot(z2, y);
    // ρ′/ρ = sᵀQ1v/P1 − sᵀQ2v/P2. The step λ − ω/ω′ is computed as
    // (1 + λ²ρ′)/ω′, which does not cancel when the root is far smaller
    // than λ (ρ ≫ 1: a thin disc), and with both terms multiplied by
    // c = √P1·P1·P2: then ρ·c = √P2·P1·P2 and ρ′·c = √P2·(a1·P2 − a2·P1)
    // need neither ρ nor a division, and the step waits for the square
    // roots and one division only. Unless c leaves the normal range.
    double const p12 = p1 * p2;
    double const c = m1 * p12;
    if (c >= DBL_MIN && c <= DBL_MAX) {
      double const w = m2 * (a1 * p2 - a2 * p1);        // ρ′·c
      double const den = (m1 + m2) * p12 + lambda * w;  // ω′·c
      t->newton = (c + lambda * lambda * w) / den;
      t->domega = den / c;
    } else {
      double const drho = rho * (a1 / p1 - a2 / p2);
      t->domega = 1.0 + rho + lambda * drho;
      t->newton = (1.0 + lambda * lambda * drho) / t->domega;
    }
    ok = ok && std::isfinite(t->newton);
  }
  if (want & want_bounds) {
    t->mu1 = mu * mu * p1;
    t->mu2 = lambda * lambda * p2;
    t->cond = ldl_cond_bound(q, fac);
    ok = ok && std::isfinite(t->cond);
  }
  return ok;
}

// The outcome of newton_on_omega().
struct Search {
  double lambda;    // the estimate of the root: the last iterate
  double center;    // the last λ at which ω was evaluated
  double f_center;  // f there, as brent_objective() computes it
  double domega;    // ω′ there
  Plain plain;      // the factors of Q and s there
  bool converged;   // to the resolution of the plain ω
};

// Safeguarded Newton on ω from λ, at most n steps: [lo, hi] holds the root
// (ω(0) = −1 < 0 < ω(1) = ρ(1)) and narrows with every sign seen. A step
// leaving it takes Newton's step from the end of [0, 1] on the root's side
// (step_from_end(), at most once per end), else the sphere model's
// 1/(1 + ρ), else bisects.
template <bool Fast>
void newton_on_omega(Problem const &p, double lambda, int n,
                     Search *out) noexcept {
  bool tried_0 = false;
  bool tried_1 = false;
  double lo = 0.0;
  double hi = 1.0;
  *out = Search{lambda, lambda, 0.0, 0.0, {}, false};
  for (int k = 0; k < n; ++k) {
    Terms t;
    if (!terms<Fast>(lambda, p, want_newton, &t)) return;
    out->center = lambda;
    out->f_center = t.f;
    out->domega = t.domega;
    out->plain = t.plain;
    if (t.omega == 0.0) {
      out->converged = true;
      return;
    }
    double next = t.newton;
    if (std::fabs(next - lambda) <=
        newton_accept * std::min(lambda, 1.0 - lambda)) {
      // Newton's convergence is quadratic: after a step this small, λ is
      // within ~1e-10 relative, about the rounding noise of the plain ω,
      // whose further steps (and the signs that set [lo, hi]) would only
      // jitter. The compensated steps of finish() take over.
      if (next > 0.0 && next < 1.0) out->lambda = next;
      out->converged = true;
      return;
    }
    (t.omega < 0.0 ? lo : hi) = lambda;
    if (!(next > lo && next < hi)) {
      bool &tried = t.omega > 0.0 ? tried_0 : tried_1;
      if (!tried) next = step_from_end(p, t.omega > 0.0);
      tried = true;
    }
    if (!(next > lo && next < hi)) next = 1.0 / (1.0 + t.rho);
    if (next >= 1.0 && hi == 1.0) next = below_one;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    // No double strictly between lo and hi (the root lies within an ulp of
    // an end of [0, 1], say): λ, which is one of them and inside (0, 1), is
    // as close to the root as doubles allow. (The midpoint would round onto
    // an end, where λ(1−λ) = 0.)
    if (!(next > lo && next < hi)) {
      out->converged = true;
      return;
    }
    lambda = next;
    out->lambda = lambda;
  }
}

// The width of the first bracket of Brent's method, which already meets
// Brent's stopping test when it is verified.
constexpr double bracket_width = 0.98 * PW85_LAMBDA_ATOL;

// Brent's method on −f (ch. 5), GSL's gsl_min_fminimizer_brent, on a
// bracket about λ verified to enclose the maximum: golden_bracket() of
// width bracket_width (λ − 0.38·w to λ + 0.62·w), widened ×16 while
// rounding noise in f (up to cond(Q)·ε) defeats the check, up to [0, 1]
// where f(0) = f(1) = 0. fm = brent_objective(λ). Iterates to
// PW85_LAMBDA_ATOL or PW85_MAX_ITER. Writes Brent's estimate and final
// bracket; returns PW85_SUCCESS or PW85_ENOMEM.
template <bool Fast>
int certify_with_brent(Problem const &p, double lambda, double fm,
                       double *estimate, double *lower,
                       double *upper) noexcept {
  double a = 0.0, b = 1.0, fa = 0.0, fb = 0.0;
  bool enclosed = false;
  for (double width = bracket_width; !enclosed && width < 1.0; width *= 16.0) {
    golden_bracket(lambda, width, &a, &b);
    if (a <= 0.0 || b >= 1.0) break;
    fa = brent_objective<Fast>(a, p);
    fb = brent_objective<Fast>(b, p);
    enclosed = fm < fa && fm < fb;
  }
  if (!enclosed) {
    a = 0.0;
    b = 1.0;
    fa = fb = 0.0;
    if (!(fm < 0.0)) {  // only if f(λ) rounds to 0: keep λ, uncertified
      *estimate = lambda;
      *lower = 0.0;
      *upper = 1.0;
      return PW85_SUCCESS;
    }
  }
  alignas(std::max_align_t) unsigned char state[minimizer_state_size];
  gsl_min_fminimizer_type const *type = gsl_min_fminimizer_brent;
  if (type->size > sizeof state) return PW85_ENOMEM;
  gsl_min_fminimizer s{};
  s.type = type;
  s.state = state;
  KnownCentre centre{&p, lambda, fm};
  gsl_function objective{&gsl_objective<Fast>, &centre};
  // The preconditions that GSL checks (a < λ < b, f(λ) below both ends)
  // hold here, so its error handler is not reached.
  gsl_min_fminimizer_set_with_values(&s, &objective, lambda, fm, a, fa, b, fb);
  for (int iter = 0; iter < PW85_MAX_ITER; ++iter) {
    if (gsl_min_test_interval(s.x_lower, s.x_upper, PW85_LAMBDA_ATOL, 0.0) ==
        GSL_SUCCESS)
      break;
    if (gsl_min_fminimizer_iterate(&s) != GSL_SUCCESS) break;
  }
  *estimate = s.x_minimum;
  *lower = s.x_lower;
  *upper = s.x_upper;
  return PW85_SUCCESS;
}

// The last steps, in compensated arithmetic: f, P1 and P2 at λ from the
// refined solution (linalg.hpp, accurate_terms), and Newton steps on the
// accurate ω (slope: the plain ω′ first, then secants), at most
// accurate_iter of them, until the step is below accurate_accept. μ² is then
// f(λ) + ½·f′(λ)·Δλ, the quadratic model's maximum, with f′ = −g = −√P1·ω·(μ1 +
// μ2): a correction of order (cond·ε)² relative. Every accurate f is a lower
// bound of μ² (to rounding): the largest is kept.
constexpr int accurate_iter = 3;

// A compensated Newton step of relative size h leaves λ off by O(h²) and the
// quadratic model's μ² off by O(h³) relative: at h ≤ 1e-7 both are below
// the rounding of a double, so the step is taken and the iteration stops.
constexpr double accurate_accept = 1e-7;

// See solve().
constexpr double finish_from_center = 1e-8;

PW85_FMA_CLONES
bool finish(Problem const &p, double domega, double *lambda, double *mu2,
            Plain const *plain) noexcept {
  double best = 0.0, best_lambda = *lambda;
  double prev_lambda = 0.0, prev_omega = 0.0;
  bool found = false;
  for (int k = 0; k < accurate_iter; ++k) {
    double const l0 = *lambda;
    Accurate a;
    if (!accurate_terms(l0, p.r, p.q1, p.q2, p.moderate, true, &a,
                        k == 0 ? plain : nullptr))
      break;
    if (!found || a.f > best) best = a.f, best_lambda = l0;
    found = true;
    double const rho = std::sqrt(a.p2 / a.p1);
    double const omega = l0 * rho - (1.0 - l0);
    if (k > 0 && l0 != prev_lambda) {
      double const secant = (omega - prev_omega) / (l0 - prev_lambda);
      if (secant > 0.0) domega = secant;
    }
    if (!(domega > 0.0)) break;
    double const step = omega / domega;
    double const next = l0 - step;
    if (!(next > 0.0 && next < 1.0)) break;
    if (std::fabs(step) <= accurate_accept * std::min(l0, 1.0 - l0)) {
      double const root_p1 = std::sqrt(a.p1);
      double const sum_mu = (1.0 - l0) * root_p1 + l0 * std::sqrt(a.p2);
      double const correction = 0.5 * root_p1 * omega * sum_mu * step;
      if (correction >= 0.0 && correction <= 1e-10 * a.f) {
        *lambda = next;
        // Added to f before f is rounded: the correction can reach an ulp.
        *mu2 = std::max(a.f + (a.f_lo + correction), best);
        return true;
      }
    }
    prev_lambda = l0;
    prev_omega = omega;
    *lambda = next;
  }
  if (!found) return false;
  *lambda = best_lambda;
  *mu2 = best;
  return true;
}

// μ² and λ of a prepared problem with r ≠ 0; out = {μ²(problem), λ}.
template <bool Fast>
int solve(Problem const &p, double out[2]) noexcept {
  // 1. Warm start, refined by Newton on ω.
  Search search;
  newton_on_omega<Fast>(p, warm_start(p), warm_newton_iter, &search);
  // 2. Brent's method certifies the maximum on a bracket around the last
  // point where Newton evaluated f, if the root lies well inside that
  // bracket (f there is then known), else around the estimate.
  double center = search.lambda;
  double fm = 0.0;
  if (search.converged &&
      std::fabs(search.lambda - search.center) <= 0.125 * bracket_width) {
    center = search.center;
    fm = -search.f_center;
  } else {
    fm = brent_objective<Fast>(center, p);
  }
  double estimate = center, lower = 0.0, upper = 1.0;
  int const status =
      certify_with_brent<Fast>(p, center, fm, &estimate, &lower, &upper);
  if (status != PW85_SUCCESS) return status;
  // 3. Newton to finish: from the warm λ if Brent's bracket (widened by its
  // tolerance) confirms it, else from Brent's estimate, at most
  // PW85_NR_ITER plain steps; then compensated steps. These start from the
  // last point where Newton evaluated ω, whose factors they reuse, when
  // Newton's last step from there was below finish_from_center (relative):
  // the first compensated step is then as small, and leaves λ off by its
  // square.
  if (!search.converged || search.lambda < lower - PW85_LAMBDA_ATOL ||
      search.lambda > upper + PW85_LAMBDA_ATOL) {
    newton_on_omega<Fast>(p, estimate, PW85_NR_ITER, &search);
    if (!search.converged) search.lambda = estimate;
  }
  double lambda = search.lambda;
  Plain const *plain = nullptr;
  double const c = search.center;
  if (search.converged && std::fabs(search.lambda - c) <=
                              finish_from_center * std::min(c, 1.0 - c)) {
    lambda = c;
    plain = &search.plain;
  }
  double mu2 = 0.0;
  if (!finish(p, search.domega, &lambda, &mu2, plain)) {
    // Q(λ) failed to factorise in double-double (rounding only): fall back
    // to Brent's estimate in plain arithmetic.
    lambda = estimate;
    mu2 = -brent_objective<Fast>(lambda, p);
  }
  out[0] = mu2;
  out[1] = lambda;
  return PW85_SUCCESS;
}

// The rest of overlap(), from λ = lambda: the bounds at λ0 and one Newton
// step further, then the exact contact function. cond_q ≥ √cond(Qᵢ);
// one = 2^−shift.
template <bool Fast>
int overlap_from(Problem const &p, double lambda, double cond_q, double one,
                 int *result) noexcept {
  // At λ0, then (rarely needed) one Newton step on ω further.
  for (int k = 0; k < 2; ++k) {
    Terms t;
    if (!terms<Fast>(lambda, p, want_bounds, &t)) break;
    double const m_f = 32.0 * DBL_EPSILON * t.cond;
    double const m_mu = 32.0 * DBL_EPSILON * t.cond * (1.0 + cond_q);
    if (m_f < 0.5 && t.f * (1.0 - m_f) > one) {
      *result = 1;
      return PW85_SUCCESS;
    }
    if (m_mu < 0.5 && std::max(t.mu1, t.mu2) * (1.0 + m_mu) < one) {
      *result = -1;
      return PW85_SUCCESS;
    }
    if (k == 1 || !terms<Fast>(lambda, p, want_newton, &t)) break;
    double next = t.newton;
    if (!(next > 0.0 && next < 1.0)) next = 1.0 / (1.0 + t.rho);
    if (!(next > 0.0 && next < 1.0)) break;
    lambda = next;
  }
  // Nearly tangent, or too ill-conditioned for the plain bounds: the exact
  // contact function decides.
  double res[2];
  int const status = solve<Fast>(p, res);
  if (status != PW85_SUCCESS) return status;
  double const mu2 = std::ldexp(res[0], p.shift);
  double const tangency = 4.0 * DBL_EPSILON;
  *result = std::fabs(mu2 - 1.0) <= tangency ? 0 : (mu2 < 1.0 ? -1 : 1);
  return PW85_SUCCESS;
}

}  // namespace

int contact_function(double const r[dim], double const q1[sym],
                     double const q2[sym], double out[2]) noexcept {
  Problem p;
  int status = prepare(r, q1, q2, &p);
  if (status != PW85_SUCCESS) return status;
  if (p.r_is_zero) {  // coincident centres: f ≡ 0, λ is arbitrary
    out[0] = 0.0;
    out[1] = 0.5;
    return PW85_SUCCESS;
  }
  double res[2];
  status = p.moderate ? solve<true>(p, res) : solve<false>(p, res);
  if (status != PW85_SUCCESS) return status;
  // Beyond the documented domain (cond(Qᵢ) far above 1/ε) the computed f
  // can be meaningless; μ² never falls below the rigorous bound
  // sphere_lower_bound() ≤ |r|²/(tr Q1 + tr Q2), which is computed only when
  // μ² is below the latter.
  double mu2 = res[0];
  double const tr = p.q1[0] + p.q1[3] + p.q1[5] + p.q2[0] + p.q2[3] + p.q2[5];
  if (!(mu2 * tr >= dot(p.r, p.r))) {
    double const floor = sphere_lower_bound(p);
    mu2 = mu2 > floor ? mu2 : floor;  // also when mu2 is NaN
  }
  mu2 = times_pow2(mu2, p.shift);
  out[1] = res[1];
  if (std::isinf(mu2)) {
    out[0] = HUGE_VAL;
    return PW85_ERANGE;
  }
  out[0] = mu2;
  return PW85_SUCCESS;
}

int overlap(double const r[dim], double const q1[sym], double const q2[sym],
            int *result) noexcept {
  Problem p;
  int status = prepare(r, q1, q2, &p);
  if (status != PW85_SUCCESS) return status;
  if (p.r_is_zero) {  // μ² = 0
    *result = -1;
    return PW85_SUCCESS;
  }
  // μ² < 1 ⟺ μ²(problem) < 2^−shift (exact; 0 or +∞ out of range, which
  // decides the comparison correctly since μ²(problem) is finite and > 0).
  double const one = pow2(-p.shift);
  // Bounds that need no λ, the cheapest first: sphere_lower_bound(), then
  // at λ = 0 and 1, where the point x0 is a centre, μ² ≤ min(rᵀQ1⁻¹r,
  // rᵀQ2⁻¹r), computed from the factors of Q1 and Q2 with an error of a few
  // cond(Qᵢ)·ε relative: the margin takes 32 times the bound tr·tr(⁻¹) of
  // cond(Qᵢ).
  if (sphere_lower_bound(p) > one) {
    *result = 1;
    return PW85_SUCCESS;
  }
  double const cond1 = ldl_cond_bound(p.q1, p.f1);
  double const cond2 = ldl_cond_bound(p.q2, p.f2);
  double const a1 = ldl_quad_inverse(p.f1, p.r);
  double const a2 = ldl_quad_inverse(p.f2, p.r);
  double const m_a = 32.0 * DBL_EPSILON * std::max(cond1, cond2);
  if (m_a < 0.5 && std::min(a1, a2) * (1.0 + m_a) < one) {
    *result = -1;
    return PW85_SUCCESS;
  }
  // Bounds valid at every λ (ch. 5, eqs. (1a)–(1b)): f(λ) ≤ μ² because μ²
  // is the maximum of f; μ² ≤ max(μ1², μ2²) because the point x0(λ) lies in
  // both ellipsoids scaled by max(μ1, μ2), which therefore meet. In plain
  // double each is off by at most a few cond(Q(λ))·ε (f), or that times
  // √cond(Qᵢ) (μᵢ², a quadratic form in s), relative: the margins take 32
  // times the bounds tr·tr(⁻¹) of these condition numbers.
  double const cond_q = std::sqrt(std::max(cond1, cond2));
  double const lambda = warm_start(a1, a2);
  return p.moderate ? overlap_from<true>(p, lambda, cond_q, one, result)
                    : overlap_from<false>(p, lambda, cond_q, one, result);
}

}  // namespace pw85::detail
