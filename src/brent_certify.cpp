// SPDX-License-Identifier: BSD-3-Clause
// Certification of the maximum of f by GSL's Brent minimiser
// (brent_certify.hpp). The one file of the core that knows GSL's
// minimiser (principal_axes.cpp uses its eigensolver): its first
// evaluation point and the size of its state.
#include "brent_certify.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <cstddef>

#include "evaluate.hpp"
#include "tolerances.hpp"

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

// Working memory of the minimiser, on the stack: no allocation
// (gsl_min_fminimizer_alloc calls GSL's error handler when malloc fails).
// Brent's state is 6 doubles (48 bytes) in GSL 2.7.1; the size that the
// installed GSL declares is checked against this at run time.
constexpr std::size_t minimizer_state_size = 512;

// The objective GSL calls. certify_with_brent() places the bracket so that
// GSL's first evaluation falls on the centre λ (golden_bracket()), where
// −f is already known: the objective returns that value there, which is
// the value it would compute, and evaluates anywhere else. (Should a GSL
// release move that point, the objective is merely evaluated there.)
template <int D>
struct KnownCentre {
  Problem<D> const *p;
  double lambda;
  double neg_f;  // neg_f_or_zero(lambda, *p)
};

template <bool Fast, int D>
double objective(double lambda, void *params) noexcept {
  auto const *c = static_cast<KnownCentre<D> const *>(params);
  if (lambda == c->lambda) return c->neg_f;
  return neg_f_or_zero<Fast>(lambda, *c->p);
}

}  // namespace

template <bool Fast, int D>
Status certify_with_brent(Problem<D> const &p, double lambda, double neg_f,
                          int max_iter, BrentResult *out) noexcept {
  double a = 0.0, b = 1.0, fa = 0.0, fb = 0.0;
  bool enclosed = false;
  for (double width = first_bracket_width; !enclosed && width < 1.0;
       width *= bracket_growth) {
    golden_bracket(lambda, width, &a, &b);
    if (a <= 0.0 || b >= 1.0) break;
    fa = neg_f_or_zero<Fast>(a, p);
    fb = neg_f_or_zero<Fast>(b, p);
    enclosed = neg_f < fa && neg_f < fb;
  }
  if (!enclosed) {
    a = 0.0;
    b = 1.0;
    fa = fb = 0.0;
    if (!(neg_f < 0.0)) {  // only if f(λ) rounds to 0: keep λ, uncertified
      *out = BrentResult{lambda, 0.0, 1.0};
      return Status::success;
    }
  }
  alignas(std::max_align_t) unsigned char state[minimizer_state_size];
  gsl_min_fminimizer_type const *type = gsl_min_fminimizer_brent;
  if (type->size > sizeof state) return Status::no_memory;
  gsl_min_fminimizer s{};
  s.type = type;
  s.state = state;
  KnownCentre<D> centre{&p, lambda, neg_f};
  gsl_function fn{&objective<Fast, D>, &centre};
  // The preconditions that GSL checks (a < λ < b, −f(λ) below both ends)
  // hold here, so its error handler is not reached.
  gsl_min_fminimizer_set_with_values(&s, &fn, lambda, neg_f, a, fa, b, fb);
  for (int iter = 0; iter < max_iter; ++iter) {
    if (gsl_min_test_interval(s.x_lower, s.x_upper, lambda_atol, 0.0) ==
        GSL_SUCCESS)
      break;
    if (gsl_min_fminimizer_iterate(&s) != GSL_SUCCESS) break;
  }
  *out = BrentResult{s.x_minimum, s.x_lower, s.x_upper};
  return Status::success;
}

template PW85_CERTIFY_WITH_BRENT(true, 2);
template PW85_CERTIFY_WITH_BRENT(false, 2);
template PW85_CERTIFY_WITH_BRENT(true, 3);
template PW85_CERTIFY_WITH_BRENT(false, 3);

}  // namespace pw85::detail
