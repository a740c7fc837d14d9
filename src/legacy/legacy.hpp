// SPDX-License-Identifier: BSD-3-Clause
// The numerical core of libpw85_legacy (private: never installed): the two
// implementations of f and the two historical contact functions of
// docs/implementation.rst and docs/legacy-api.rst. Storage conventions
// are those of include/pw85/pw85.h. Equation (C.N) is that of the docs page
// of chapter C (docs/theory.rst: 3 theory, 4 implementation, 5
// optimisation, 6 testing).
#ifndef PW85_SRC_LEGACY_LEGACY_HPP
#define PW85_SRC_LEGACY_LEGACY_HPP

#include "status.hpp"
#include "sym.hpp"

namespace pw85::legacy::detail {

using pw85::detail::dim;
using pw85::detail::Status;
using pw85::detail::sym;

// The most Newton–Raphson steps contact_function1() takes (docs/legacy-api.rst).
constexpr int nr_max_iter = 50;
// contact_function1() stops when a Newton step moves λ by at most this much:
// the step after it would be of order nr_step_tol², far below the resolution
// of λ (Newton converges quadratically near a simple root of f′).
constexpr double nr_step_tol = 0x1p-32;
// The most bisection steps contact_function2() takes; the bracket [0, 1]
// reaches the resolution of a double (1 ulp of λ) well before.
constexpr int bisection_max_iter = 1100;

// det(A) by cofactor expansion along the first row.
double det_sym(double const a[sym]) noexcept;

// xᵀ·adj(A)·x, adj(A) the adjugate (transpose of the cofactor matrix).
double xT_adjA_x(double const x[dim], double const a[sym]) noexcept;

// b[0..3]: det[(1−λ)Q1 + λQ2] = b0 + b1λ + b2λ² + b3λ³ from its values at
// λ = 0, 1, −1, ½, that is det Q1, det Q2, det q3, det q4 with q3 = 2Q1 − Q2
// and q4 = (Q1 + Q2)/2 (ch. 4, eqs. (11b), (12d)–(12g)).
void detQ_as_poly(double const q1[sym], double const q2[sym],
                  double const q3[sym], double const q4[sym],
                  double b[dim + 1]) noexcept;

// a[0..2]: rᵀ·adj[(1−λ)Q1 + λQ2]·r = a0 + a1λ + a2λ² from its values at
// λ = 0, 1, −1 (ch. 4, eqs. (11a), (12a)–(12c)); q3 = 2Q1 − Q2.
void rT_adjQ_r_as_poly(double const r[dim], double const q1[sym],
                       double const q2[sym], double const q3[sym],
                       double a[dim]) noexcept;

// Implementation #1 (Cholesky, ch. 4, eqs. (3)–(9)): f(λ) and, when out is
// not null, out = {f, f′, f″}. Returns false when Q(λ) is not positive
// definite to the resolution of the factorisation (nothing written).
bool f1(double lambda, double const r[dim], double const q1[sym],
        double const q2[sym], double *f, double out[3]) noexcept;

// True when Q(λ) = (1−λ)Q1 + λQ2 is positive definite to the resolution of
// a double Cholesky factorisation.
bool q_positive_definite(double lambda, double const q1[sym],
                         double const q2[sym]) noexcept;

// Implementation #2 (rational fraction, ch. 4, eqs. (10)–(12g)):
// f(λ) = λ(1−λ)·a(λ)/b(λ). No definiteness check.
double f2(double lambda, double const r[dim], double const q1[sym],
          double const q2[sym]) noexcept;

// The contact functions, for input that passed pw85::detail::check_input().
// Both write out = {μ², λ} and return the status documented in
// include/pw85/pw85_legacy.h (Status::no_convergence for PW85_ENOCONV).

// Newton–Raphson on f′ from λ = ½, with f′ and f″ of f1() (ch. 7.3).
Status contact_function1(double const r[dim], double const q1[sym],
                         double const q2[sym], double out[2]) noexcept;

// Bisection on the numerator c(λ) of f′ (ch. 4, eqs. (13)–(15g)), then
// μ² = f(λ) by eq. (10).
Status contact_function2(double const r[dim], double const q1[sym],
                         double const q2[sym], double out[2]) noexcept;

}  // namespace pw85::legacy::detail

#endif  // PW85_SRC_LEGACY_LEGACY_HPP
