// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the two-dimensional functions
// (include/pw85/pw85_2d.h): check arguments, call the core (the same
// templates as pw85.cpp, with D = 2), map statuses.
#include "pw85_2d.h"

#include <cmath>

#include "ellipsoid.hpp"
#include "facade.hpp"
#include "facade_pairs.hpp"
#include "geometry.hpp"
#include "status.hpp"

namespace {

namespace core = pw85::detail;
using pw85::facade::to_code;

constexpr int D = 2;
static_assert(PW85_2D_DIM == D && PW85_2D_SYM == core::sym_size(D),
              "pw85_2d.h and the core disagree on sizes");

using Out = core::Outputs<D>;
static_assert(PW85_2D_GEOM_MU2 == Out::mu2 &&
                  PW85_2D_GEOM_LAMBDA == Out::lambda &&
                  PW85_2D_GEOM_POINT == Out::point &&
                  PW85_2D_GEOM_NORMAL == Out::normal &&
                  PW85_2D_GEOM_SIZE == Out::size &&
                  PW85_2D_DERIV_R12 == Out::r12 &&
                  PW85_2D_DERIV_THETA1 == Out::rot1 &&
                  PW85_2D_DERIV_THETA2 == Out::rot2 &&
                  PW85_2D_DERIV_Q1 == Out::q1 && PW85_2D_DERIV_Q2 == Out::q2 &&
                  PW85_2D_DERIV_SIZE == Out::deriv_size,
              "pw85_2d.h and the core disagree on the layouts of the outputs");

using pw85::facade::pairs_batch;
using pw85::facade::pairs_batch2;
using pw85::facade::run_items;
using pw85::facade::valid_stride;

using pw85::facade::contact_function_one;
using pw85::facade::f_neg_one;
using pw85::facade::geometry_only;
using pw85::facade::overlap_one;
using pw85::facade::with_derivatives;

}  // namespace

extern "C" {

double pw85_2d_f_neg(double lambda,
                     double const params[PW85_2D_DIM + 2 * PW85_2D_SYM]) noexcept {
  return f_neg_one<D>(lambda, params);
}

int pw85_2d_contact_function(double const r12[PW85_2D_DIM],
                             double const q1[PW85_2D_SYM],
                             double const q2[PW85_2D_SYM],
                             double out[2]) noexcept {
  return contact_function_one<D>(r12, q1, q2, out);
}

int pw85_2d_overlap(double const r12[PW85_2D_DIM], double const q1[PW85_2D_SYM],
                    double const q2[PW85_2D_SYM], int *result) noexcept {
  return overlap_one<D>(r12, q1, q2, result);
}

int pw85_2d_contact_geometry(double const r12[PW85_2D_DIM],
                             double const q1[PW85_2D_SYM],
                             double const q2[PW85_2D_SYM],
                             double out[PW85_2D_GEOM_SIZE]) noexcept {
  return geometry_only<D>(r12, q1, q2, out);
}

int pw85_2d_contact_derivatives(double const r12[PW85_2D_DIM],
                                double const q1[PW85_2D_SYM],
                                double const q2[PW85_2D_SYM],
                                double geometry[PW85_2D_GEOM_SIZE],
                                double d[PW85_2D_DERIV_SIZE]) noexcept {
  return with_derivatives<D>(r12, q1, q2, geometry, d);
}

int pw85_2d_ellipse(double const a[PW85_2D_DIM], double theta,
                    double q[PW85_2D_SYM]) noexcept {
  if (a == nullptr || q == nullptr) return PW85_EFAULT;
  return to_code(core::ellipse_angle(a, theta, q));
}

int pw85_2d_principal_axes(double const q[PW85_2D_SYM], double a[PW85_2D_DIM],
                           double *theta) noexcept {
  if (q == nullptr || a == nullptr || theta == nullptr) return PW85_EFAULT;
  return to_code(core::ellipse_principal_axes(q, a, theta));
}

// ---------------------------------------------------------------------------
// Batches (pw85.h, "Batches"; the machinery of facade.hpp).

int pw85_2d_contact_function_batch(size_t n, double const *r12,
                                   size_t r12_stride, double const *q1,
                                   size_t q1_stride, double const *q2,
                                   size_t q2_stride, double *out, int *status,
                                   int threads) noexcept {
  return pairs_batch<D>(n, {r12, q1, q2, r12_stride, q1_stride, q2_stride},
                        out, 2, status, threads, contact_function_one<D>);
}

int pw85_2d_overlap_batch(size_t n, double const *r12, size_t r12_stride,
                          double const *q1, size_t q1_stride,
                          double const *q2, size_t q2_stride, int *result,
                          int *status, int threads) noexcept {
  return pairs_batch<D>(n, {r12, q1, q2, r12_stride, q1_stride, q2_stride},
                        result, 1, status, threads, overlap_one<D>);
}

int pw85_2d_contact_geometry_batch(size_t n, double const *r12,
                                   size_t r12_stride, double const *q1,
                                   size_t q1_stride, double const *q2,
                                   size_t q2_stride, double *out, int *status,
                                   int threads) noexcept {
  return pairs_batch<D>(n, {r12, q1, q2, r12_stride, q1_stride, q2_stride},
                        out, Out::size, status, threads, geometry_only<D>);
}

int pw85_2d_contact_derivatives_batch(size_t n, double const *r12,
                                      size_t r12_stride, double const *q1,
                                      size_t q1_stride, double const *q2,
                                      size_t q2_stride, double *geometry,
                                      double *d, int *status,
                                      int threads) noexcept {
  return pairs_batch2<D>(n, {r12, q1, q2, r12_stride, q1_stride, q2_stride},
                         geometry, Out::size, d, Out::deriv_size, status,
                         threads, with_derivatives<D>);
}

int pw85_2d_ellipse_batch(size_t n, double const *a, size_t a_stride,
                          double const *theta, size_t theta_stride,
                          double *q, int *status, int threads) noexcept {
  return run_items(
      n, a != nullptr && theta != nullptr && q != nullptr,
      valid_stride(a_stride, PW85_2D_DIM) && valid_stride(theta_stride, 1),
      status, threads, [=](std::size_t i) noexcept {
        return to_code(core::ellipse_angle(a + i * a_stride,
                                           theta[i * theta_stride],
                                           q + PW85_2D_SYM * i));
      });
}

int pw85_2d_principal_axes_batch(size_t n, double const *q, size_t q_stride,
                                 double *a, double *theta, int *status,
                                 int threads) noexcept {
  return run_items(
      n, q != nullptr && a != nullptr && theta != nullptr,
      valid_stride(q_stride, PW85_2D_SYM), status, threads,
      [=](std::size_t i) noexcept {
        return to_code(core::ellipse_principal_axes(
            q + i * q_stride, a + PW85_2D_DIM * i, theta + i));
      });
}

}  // extern "C"
