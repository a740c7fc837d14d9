// SPDX-License-Identifier: BSD-3-Clause
// The voxel image of a set of ellipsoids (include/pw85/pw85_image.h): each
// voxel centre decided exactly, per ellipsoid over its bounding box.
#ifndef PW85_SRC_IMAGE_RASTER_HPP
#define PW85_SRC_IMAGE_RASTER_HPP

#include <cstddef>
#include <cstdint>

#include "status.hpp"

namespace pw85::detail {

// The grid: the box [origin, origin + sides] cut into dims[0]×dims[1]×
// dims[2] voxels; voxel (i, j, k) stands for the point
// origin + ((i + ½)·sides[0]/dims[0], …), periodic or not.
struct Grid {
  double origin[3];
  double sides[3];
  std::int64_t dims[3];
  bool periodic;
};

// The largest side of an image, in voxels (so that 4·n_a·n_b and 2i + 1
// are exact doubles for every index used: raster.cpp).
inline constexpr std::int64_t image_max_dim = std::int64_t{1} << 20;
// |c_k − o_k| + √Q_kk ≤ image_reach·L_k for every ellipsoid.
inline constexpr double image_reach = 536870912.0;  // 2²⁹

// Checks the ellipsoids against the grid (finite, positive definite,
// within reach): Status::success, not_finite, not_positive_definite or
// invalid_argument (out of reach), for the first one that fails.
Status check_image_input(Grid const &grid, std::size_t n,
                         double const *centres, double const *q) noexcept;

// Writes the image (dims[0]·dims[1]·dims[2] int32, index (i·n1 + j)·n2 + k):
// the least position of an ellipsoid (or, periodic, of an image of one)
// containing the voxel's point, or −1. Inputs checked by
// check_image_input(); threads ≥ 1 (OpenMP threads when built with it).
void voxel_image(Grid const &grid, std::size_t n, double const *centres,
                 double const *q, std::int32_t *image, int threads) noexcept;

// Point-in-ellipsoid for one point of the grid, unwrapped indices (i, j, k)
// (the point origin + ((i + ½)·L0/n0, …), whatever the box): +1 if the
// point is outside {m : (m − c)ᵀQ⁻¹(m − c) ≤ 1}, else −1 (inside or on
// the surface), certified. For the tests (tests/test-core.cpp).
int voxel_outside(Grid const &grid, double const c[3], double const q[6],
                  std::int64_t i, std::int64_t j, std::int64_t k) noexcept;

}  // namespace pw85::detail

#endif
