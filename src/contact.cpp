// SPDX-License-Identifier: BSD-3-Clause
// The contact function (contact.hpp): the stages of the search in the order
// and with the numbers of docs/optimisation.rst, "The algorithm". Step 1
// (input) is the facade's.
#include "contact.hpp"

#include <algorithm>
#include <cmath>

#include "brent_certify.hpp"
#include "compiler.hpp"
#include "evaluate.hpp"
#include "finish.hpp"
#include "newton.hpp"
#include "polish.hpp"
#include "tolerances.hpp"
#include "warm_start.hpp"

namespace pw85::detail {

template <bool Fast>
Status solve(Problem const &p, double out[2], double const *r_lo) noexcept {
  // 3. Warm start (eq. (5.9)); 4. Newton on ω from there.
  return solve_after_newton<Fast>(
      p, newton_on_omega<Fast>(p, warm_start(p), warm_newton_iter), out, r_lo);
}

template <bool Fast>
Status solve_after_newton(Problem const &p, NewtonResult newton, double out[2],
                          double const *r_lo) noexcept {
  // 5. Brent's method certifies the maximum, about Newton's last point if
  // the estimate lies well inside the bracket there (f at that point is
  // then known), else about the estimate.
  double centre = newton.lambda;
  double neg_f = 0.0;
  if (newton.last_within(brent_reuse_fraction * first_bracket_width)) {
    centre = newton.last.lambda;
    neg_f = -newton.last.f;
  } else {
    neg_f = neg_f_or_zero<Fast>(centre, p);
  }
  BrentResult brent;
  Status const status =
      certify_with_brent<Fast>(p, centre, neg_f, brent_max_iter, &brent);
  if (status != Status::success) return status;

  // 6. Fallback: Newton restarts from Brent's estimate if it did not
  // converge, or converged outside Brent's bracket (widened by its
  // tolerance).
  if (!newton.converged() || newton.lambda < brent.lower - lambda_atol ||
      newton.lambda > brent.upper + lambda_atol) {
    newton = newton_on_omega<Fast>(p, brent.estimate, restart_newton_iter);
    if (!newton.converged()) {
      // The finish starts from Brent's estimate, where no slope is known
      // (the last ω′ was computed elsewhere).
      newton.lambda = brent.estimate;
      newton.last.domega = NAN;
    }
  }

  // 7. Compensated finish, from Newton's last point (whose factors it
  // reuses) when Newton's last step from there was below finish_reuse
  // (relative), else from the estimate.
  double const c = newton.last.lambda;
  FinishStart start{newton.lambda, newton.last.domega, nullptr, r_lo};
  if (newton.last_within(finish_reuse * std::min(c, 1.0 - c))) {
    start.lambda = c;
    start.plain = &newton.last.sol;
  }
  Finished finished;
  if (!finish(p, start, &finished)) {
    // Q(λ) failed to factorise in double-double (rounding only): Brent's
    // estimate in plain arithmetic.
    finished.lambda = brent.estimate;
    finished.mu2 = -neg_f_or_zero<Fast>(brent.estimate, p);
    finished.slope = NAN;
  }
  // 7b. A flat maximum (tolerances.hpp, flat_slope), or a finish that
  // ended without a Newton step: λ polished with ω in double-double (μ²
  // stands: f is flat there).
  double const near = std::min(finished.lambda, 1.0 - finished.lambda);
  double const h = near * finished.slope;
  double const cond = std::max(trace(p.q1) * p.tinv1, trace(p.q2) * p.tinv2);
  if (PW85_UNLIKELY(!(h >= flat_slope && h * h >= flat_cond_slope2 * cond)) &&
      r_lo == nullptr)
    finished.lambda = polish<Fast>(p, finished.lambda);
  out[0] = finished.mu2;
  out[1] = finished.lambda;
  return Status::success;
}

template Status solve<true>(Problem const &, double[2], double const *) noexcept;
template Status solve<false>(Problem const &, double[2], double const *) noexcept;
template Status solve_after_newton<true>(Problem const &, NewtonResult,
                                         double[2], double const *) noexcept;
template Status solve_after_newton<false>(Problem const &, NewtonResult,
                                          double[2], double const *) noexcept;

namespace {

// Inline, so that contact_function() keeps the problem in its own frame.
// r_lo: nullptr, or the low part of r (contact_function_dd()).
PW85_INLINE Status search(double const r[dim], double const q1[sym],
                          double const q2[sym], Contact *c,
                          double const *r_lo = nullptr) noexcept {
  // 2. Rescaling, and the factorisations of Q1 and Q2.
  Problem &p = c->p;
  Status status = prepare(r, q1, q2, &p);
  if (status != Status::success) return status;
  if (p.r_is_zero) {  // coincident centres: f ≡ 0, λ is arbitrary
    c->mu2 = 0.0;
    c->lambda = 0.5;
    return Status::success;
  }
  quads(&p);
  orient(&p);
  // r_lo scaled as r (exact but for underflow, an error below 2⁻¹⁰⁷⁴ of
  // the scaled |r| ≥ ½); orient() leaves r as it is.
  double lo[dim];
  if (r_lo != nullptr)
    for (int k = 0; k < dim; ++k) lo[k] = times_pow2(r_lo[k], -p.r_exp);
  double const *const scaled_lo = r_lo != nullptr ? lo : nullptr;
  // 3.–7.
  double res[2];
  status = p.moderate ? solve<true>(p, res, scaled_lo)
                      : solve<false>(p, res, scaled_lo);
  if (status != Status::success) return status;
  // Far beyond the domain (forms singular in double, cond(Qᵢ) ≳ 1e300) the
  // search's f may be NaN: the forms cannot be worked with in double.
  if (std::isnan(res[0])) return Status::out_of_range;
  // 8.–9. (λ of the input's orientation: the caller's).
  c->mu2 = floored_mu2(p, res[0]);
  c->lambda = res[1];
  return Status::success;
}

}  // namespace

double floored_mu2(Problem const &p, double mu2) noexcept {
  // 8. Floor: beyond the documented domain (cond(Qᵢ) far above 1/ε) the
  // computed f can be meaningless; μ² never falls below the rigorous sphere
  // bound (sphere_lower_bound_x256()) ≤ |r|²/(tr Q1 + tr Q2), which is
  // computed only when μ² is below the latter. Both scaled by 2^8, so that
  // neither overflows.
  int shift = p.shift;
  constexpr double s = 0x1p-8;
  double const tr_s = s * p.q1[0] + s * p.q1[3] + s * p.q1[5] + s * p.q2[0] +
                      s * p.q2[3] + s * p.q2[5];
  if (!(mu2 * tr_s >= s * dot(p.r, p.r))) {
    double const floor_x256 = sphere_lower_bound_x256(p);
    if (!(mu2 * 256.0 >= floor_x256)) {  // also when mu2 is NaN
      mu2 = floor_x256;
      shift -= 8;
    }
  }
  // 9. Scaling back.
  return times_pow2(mu2, shift);
}

Status contact_search(double const r[dim], double const q1[sym],
                      double const q2[sym], Contact *c) noexcept {
  return search(r, q1, q2, c);
}

namespace {

PW85_INLINE Status contact_out(Status status, Contact const &c,
                               double out[2]) noexcept {
  if (status != Status::success) return status;
  out[1] = c.p.swapped ? 1.0 - c.lambda : c.lambda;
  if (std::isinf(c.mu2)) {
    out[0] = HUGE_VAL;
    return Status::out_of_range;
  }
  out[0] = c.mu2;
  return Status::success;
}

}  // namespace

Status contact_function(double const r[dim], double const q1[sym],
                        double const q2[sym], double out[2]) noexcept {
  Contact c;
  Status const status = search(r, q1, q2, &c);
  return contact_out(status, c, out);
}

Status contact_function_dd(double const r[dim], double const r_lo[dim],
                           double const q1[sym], double const q2[sym],
                           double out[2]) noexcept {
  Contact c;
  Status const status = search(r, q1, q2, &c, r_lo);
  return contact_out(status, c, out);
}

}  // namespace pw85::detail
