// SPDX-License-Identifier: BSD-3-Clause
// The problem as the search solves it: the rescaled input and the
// factorisations of Q1 and Q2 (seed ch. 5; docs/optimisation.rst, step 2).
#ifndef PW85_SRC_PROBLEM_HPP
#define PW85_SRC_PROBLEM_HPP

#include <cmath>

#include "ldl.hpp"
#include "scaling.hpp"
#include "status.hpp"
#include "tolerances.hpp"

namespace pw85::detail {

struct Problem : Scaled {
  Ldl f1;  // Q1 = L·D·Lᵀ
  Ldl f2;  // Q2 = L·D·Lᵀ
};

// Why prepare() failed, from the input forms (problem.cpp):
// Status::not_positive_definite, or Status::out_of_range when they are
// definite but their diagonals span more than the range of a double.
Status why_unprepared(double const q1[sym], double const q2[sym]) noexcept;

// rescale(), then the factorisations of Q1 and Q2, which decide their
// definiteness (the rule of checks.hpp, applied to Q scaled by a power of
// two). Input: finite. Returns Status::success, or the status of
// why_unprepared(). Inline: it runs on every call.
inline Status prepare(double const r[dim], double const q1[sym],
                      double const q2[sym], Problem *p) noexcept {
  if (rescale(r, q1, q2, p) && ldl_decomp(p->q1, &p->f1) &&
      ldl_decomp(p->q2, &p->f2))
    return Status::success;
  return why_unprepared(q1, q2);
}

// A lower bound of μ² valid for every input: each ellipsoid lies in the
// sphere of radius √λmax(Qᵢ) ≤ √tr(Qᵢ) about its centre, and those spheres
// meet only once scaled by |r|/(√tr Q1 + √tr Q2). Computed with a few
// roundings, whatever the conditioning of Q1 and Q2: the factor
// 1 − sphere_margin keeps it a lower bound.
inline double sphere_lower_bound(Problem const &p) noexcept {
  double const radii = std::sqrt(trace(p.q1)) + std::sqrt(trace(p.q2));
  return dot(p.r, p.r) / (radii * radii) * (1.0 - sphere_margin);
}

}  // namespace pw85::detail

#endif  // PW85_SRC_PROBLEM_HPP
