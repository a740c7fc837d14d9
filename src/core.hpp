// SPDX-License-Identifier: BSD-3-Clause
// The numerical core of pw85 (private: never installed). Storage conventions
// are those of include/pw85/pw85.h. Equation numbers refer to the seed
// documentation (shared/seeds/pw85-1.0-documentation.txt), "ch. N, eq. (k)".
#ifndef PW85_SRC_CORE_HPP
#define PW85_SRC_CORE_HPP

namespace pw85::detail {

constexpr int dim = 3;
constexpr int sym = 6;

// True when the n entries of x are all finite.
bool all_finite(double const *x, int n) noexcept;

// A = L·Lᵀ. Returns false, with l partly written, when a pivot is not > 0
// (A not positive definite to the resolution of the factorisation, or NaN).
bool cholesky_decomp(double const a[sym], double l[sym]) noexcept;

// Solves L·y = b (forward substitution). y may alias b.
void forward_solve(double const l[sym], double const b[dim],
                   double y[dim]) noexcept;

// Solves L·Lᵀ·x = b. x may alias b.
void cholesky_solve(double const l[sym], double const b[dim],
                    double x[dim]) noexcept;

// Q = a²·I + (c² − a²)·n·nᵀ (ch. 3, eq. (2) for a spheroid).
void spheroid(double a, double c, double const n[dim], double q[sym]) noexcept;

// f(λ) = λ(1−λ)·rᵀ·Q(λ)⁻¹·r, Q(λ) = (1−λ)Q1 + λQ2 (ch. 4, eqs. (1)–(4)),
// in plain double arithmetic. Returns false when Q(λ) is not positive
// definite; *f is then unspecified.
bool f(double lambda, double const r[dim], double const q1[sym],
       double const q2[sym], double *f) noexcept;

// f(λ) as f() does, but accurate to about one ulp for any Q(λ) whose
// condition number is below ~1e10 (seed ch. 4, eq. (4), with compensated
// arithmetic; linalg.hpp, accurate_terms): Q(λ) is formed in double-double
// and f = λ(1−λ)·(r·s + s·ρ) with ρ = r − Q·s computed with error-free
// transformations, s refined once when cond(Q) > 1e6. Since
// r·s + s·ρ = rᵀQ⁻¹r − eᵀQe, e = Q⁻¹r − s, the error is second order in
// that of s. Returns false when Q(λ) is not positive definite.
bool f_accurate(double lambda, double const r[dim], double const q1[sym],
                double const q2[sym], double *f) noexcept;

// out = {f(λ), g(λ), g′(λ)} with g = μ2² − μ1² (ch. 5, eqs. (4)–(5)).
// Precondition: Q(λ) positive definite; otherwise out holds NaN.
void residual(double lambda, double const r[dim], double const q1[sym],
              double const q2[sym], double out[3]) noexcept;

// True when the stored matrix is positive definite to the resolution of a
// double Cholesky factorisation, after an exact power-of-two rescaling of
// its rows and columns. Entries must be finite.
bool is_positive_definite(double const q[sym]) noexcept;

// 2^k, built from its bits when it is a normal double (a libm call would
// cost more than the rest of the rescaling); ldexp otherwise.
double pow2(int k) noexcept;

// x·2^k, as std::ldexp(x, k) computes it, without a libm call when 2^k is a
// normal double.
double times_pow2(double x, int k) noexcept;

// r, Q1, Q2 rescaled exactly by powers of two (seed ch. 3, eq. (6):
// μ²(t·r, s·Q1, s·Q2) = (t²/s)·μ²(r, Q1, Q2), λ unchanged): r to order
// one, Q1 and Q2 so that their diagonals (which bound every entry of a
// positive definite matrix) straddle one. μ²(input) = μ²(scaled)·2^shift.
struct Scaled {
  double r[dim];
  double q1[sym];
  double q2[sym];
  int shift;
  bool r_is_zero;
  // Every rescaled diagonal entry of Q1 and Q2, hence of Q(λ), a convex
  // combination of them, lies in [2^−400, 2^400]: the range in which
  // ldl_decomp_fast() (linalg.hpp) may be used.
  bool moderate;
};

// Fills *s from finite input. Returns false when the diagonals of Q1 and
// Q2 span more than the range of a double, so that a rescaled diagonal
// entry overflows (decided from the exponents; an off-diagonal entry that
// overflows leaves the form indefinite, which its factorisation rejects).
bool rescale(double const r[dim], double const q1[sym], double const q2[sym],
             Scaled *s) noexcept;

// PW85_EFAULT if a pointer is NULL, PW85_EDOM if an entry of r (3), q1 or
// q2 (6 each) is not finite, PW85_SUCCESS otherwise.
// out is only tested against NULL (a double[2] or, for the overlap test, an
// int).
int check_pointers_and_finite(double const *r, double const *q1,
                              double const *q2, void const *out) noexcept;

// The input contract shared by every contact function of pw85 and
// pw85_legacy: check_pointers_and_finite(), then PW85_ENOTPOSDEF if q1 or
// q2 is not positive definite.
int check_input(double const *r, double const *q1, double const *q2,
                double const *out) noexcept;

// The contact function (contact.cpp) for input that passed
// check_pointers_and_finite(): returns PW85_SUCCESS, PW85_ENOTPOSDEF,
// PW85_ERANGE or PW85_ENOMEM (pw85.h); out = {μ², λ}.
int contact_function(double const r[dim], double const q1[sym],
                     double const q2[sym], double out[2]) noexcept;

// The certified overlap test (contact.cpp), same contract; *result = −1, 0
// or +1 as documented for pw85_overlap().
int overlap(double const r[dim], double const q1[sym], double const q2[sym],
            int *result) noexcept;

// GSL's Brent minimiser, given a bracket [a, b], evaluates its objective
// first at a + golden·(b − a) (gsl/min/brent.c). golden_bracket() returns
// in *a, *b a bracket of width about w about c (c − 0.38·w to c + 0.62·w)
// for which that point, computed in double, is c itself, nearly always
// (contact.cpp). 0 < w, and c ± w finite.
extern double const gsl_brent_golden;
void golden_bracket(double c, double w, double *a, double *b) noexcept;

#ifdef PW85_COUNT_EVALUATIONS
// Benchmark builds only: the number of times Q(λ) was formed (each is one
// evaluation of f or of its derivatives) on the calling thread.
unsigned long long evaluation_count() noexcept;
#endif

}  // namespace pw85::detail

#endif  // PW85_SRC_CORE_HPP
