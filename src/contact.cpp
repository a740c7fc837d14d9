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

template <bool Fast, int D>
Status solve(Problem<D> const &p, double out[2], double const *r_lo) noexcept {
  // 3. Warm start (eq. (5.9); for ellipses, then the root of the quartic
  // (5.9b)); 4. Newton on ω from there.
  double start = warm_start(p);
  if constexpr (D == 2) start = rational_start(p, start);
  return solve_after_newton<Fast>(
      p, newton_on_omega<Fast>(p, start, warm_newton_iter), out, r_lo);
}

template <bool Fast, int D>
Status solve_after_newton(Problem<D> const &p, NewtonResult<D> newton,
                          double out[2], double const *r_lo) noexcept {
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
  FinishStart<D> start{newton.lambda, newton.last.domega, nullptr, r_lo};
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
  double const cond =
      std::max(trace<D>(p.q1) * p.tinv1, trace<D>(p.q2) * p.tinv2);
  if (PW85_UNLIKELY(!(h >= flat_slope && h * h >= flat_cond_slope2 * cond)) &&
      r_lo == nullptr)
    finished.lambda = polish<Fast>(p, finished.lambda);
  out[0] = finished.mu2;
  out[1] = finished.lambda;
  return Status::success;
}

#define PW85_SOLVE_INSTANCES(Fast, D)                                       \
  template Status solve<Fast, D>(Problem<D> const &, double[2],             \
                                 double const *) noexcept;                  \
  template Status solve_after_newton<Fast, D>(                              \
      Problem<D> const &, NewtonResult<D>, double[2], double const *) noexcept;
PW85_SOLVE_INSTANCES(true, 2)
PW85_SOLVE_INSTANCES(false, 2)
PW85_SOLVE_INSTANCES(true, 3)
PW85_SOLVE_INSTANCES(false, 3)

namespace {

// Inline, so that contact_function() keeps the problem in its own frame.
// r_lo: nullptr, or the low part of r (contact_function_dd()).
template <int D>
PW85_INLINE Status search(double const *r, double const *q1, double const *q2,
                          Contact<D> *c,
                          double const *r_lo = nullptr) noexcept {
  // 2. Rescaling, and the factorisations of Q1 and Q2.
  Problem<D> &p = c->p;
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
  double lo[D];
  if (r_lo != nullptr)
    for (int k = 0; k < D; ++k) lo[k] = times_pow2(r_lo[k], -p.r_exp);
  double const *const scaled_lo = r_lo != nullptr ? lo : nullptr;
  // 3.–7.
  double res[2];
  status = p.moderate ? solve<true, D>(p, res, scaled_lo)
                      : solve<false, D>(p, res, scaled_lo);
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

template <int D>
double floored_mu2(Problem<D> const &p, double mu2) noexcept {
  // 8. Floor: beyond the documented domain (cond(Qᵢ) far above 1/ε) the
  // computed f can be meaningless; μ² never falls below the rigorous sphere
  // bound (sphere_lower_bound_x256()) ≤ |r|²/(tr Q1 + tr Q2), which is
  // computed only when μ² is below the latter. Both scaled by 2^8, so that
  // neither overflows.
  int shift = p.shift;
  // (tr Q1 + tr Q2)·2^−8, summed term by term from Q1's first entry.
  constexpr double s = 0x1p-8;
  double tr_s = scaled_trace<D>(p.q1);
  PW85_UNROLL
  for (int i = 0; i < D; ++i) tr_s += s * p.q2[Layout<D>::diag[i]];
  if (!(mu2 * tr_s >= s * dot<D>(p.r, p.r))) {
    double const floor_x256 = sphere_lower_bound_x256(p);
    if (!(mu2 * 256.0 >= floor_x256)) {  // also when mu2 is NaN
      mu2 = floor_x256;
      shift -= 8;
    }
  }
  // 9. Scaling back.
  return times_pow2(mu2, shift);
}

template <int D>
Status contact_search(double const *r, double const *q1, double const *q2,
                      Contact<D> *c) noexcept {
  return search(r, q1, q2, c);
}

namespace {

template <int D>
PW85_INLINE Status contact_out(Status status, Contact<D> const &c,
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

template <int D>
Status contact_function(double const *r, double const *q1, double const *q2,
                        double out[2]) noexcept {
  Contact<D> c;
  Status const status = search(r, q1, q2, &c);
  return contact_out(status, c, out);
}

template <int D>
Status contact_function_dd(double const *r, double const *r_lo,
                           double const *q1, double const *q2,
                           double out[2]) noexcept {
  Contact<D> c;
  Status const status = search(r, q1, q2, &c, r_lo);
  return contact_out(status, c, out);
}

#define PW85_CONTACT_INSTANCES(D)                                           \
  template double floored_mu2<D>(Problem<D> const &, double) noexcept;      \
  template Status contact_search<D>(double const *, double const *,         \
                                    double const *, Contact<D> *) noexcept; \
  template Status contact_function<D>(double const *, double const *,       \
                                      double const *, double[2]) noexcept;  \
  template Status contact_function_dd<D>(double const *, double const *,    \
                                         double const *, double const *,    \
                                         double[2]) noexcept;
PW85_CONTACT_INSTANCES(2)
PW85_CONTACT_INSTANCES(3)

}  // namespace pw85::detail
