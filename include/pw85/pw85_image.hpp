// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85_image.hpp
 * @brief pw85::image_voxels() and pw85::image_fraction(): the voxel image
 *        of pw85_image.h with std::vector.
 *
 * Header-only over the C ABI of pw85_image.h, whose description (the grid,
 * the values, exactness, threads) is the contract here; link -lpw85.
 * Needs C++11. No function throws; each returns the PW85_* status of the C
 * function it calls, and a failed call leaves its outputs as they were. An
 * image that cannot be allocated is PW85_ENOMEM (under -fno-exceptions,
 * the C++ library's rule: an abort).
 *
 * @since 2.4.0
 */
#ifndef PW85_IMAGE_HPP
#define PW85_IMAGE_HPP

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pw85.hpp"
#include "pw85_image.h"

namespace pw85 {

/**
 * @brief The voxel image of the ellipsoids (centres: 3 doubles each, q: 6
 *        each), periodic or open, into `image` (resized to the product of
 *        dims; C order, first index along x). pw85_image_voxels().
 * @return the statuses of pw85_image_voxels(); PW85_EINVAL also if the
 *         sizes of centres and q are not 3·n and 6·n; PW85_ENOMEM if the
 *         image cannot be allocated. `image` is unchanged on error.
 * @since 2.4.0
 */
inline int image_voxels(std::vector<double> const &centres,
                        std::vector<double> const &q,
                        std::array<double, 3> const &origin,
                        std::array<double, 3> const &sides, bool periodic,
                        std::array<std::size_t, 3> const &dims,
                        std::vector<std::int32_t> &image,
                        int threads = 1) noexcept {
  std::size_t const n = centres.size() / 3;
  if (centres.size() != 3 * n || q.size() != 6 * n) return PW85_EINVAL;
  std::size_t voxels = 1;
  for (std::size_t d : dims) {
    if (d == 0 || d > PW85_IMAGE_MAX_DIM) return PW85_EINVAL;
    if (voxels > static_cast<std::size_t>(-1) / sizeof(std::int32_t) / d)
      return PW85_ERANGE;
    voxels *= d;
  }
  std::vector<std::int32_t> out;
  int const grown = detail_vector::resize(out, voxels);
  if (grown != PW85_SUCCESS) return grown;
  int const status = pw85_image_voxels(
      n, centres.data(), q.data(), origin.data(), sides.data(),
      periodic ? 1 : 0, dims.data(), out.data(), threads);
  if (status == PW85_SUCCESS) image.swap(out);
  return status;
}

/**
 * @brief The number and fraction of voxels of `image` that hold a position
 *        (≥ 0). pw85_image_fraction().
 * @since 2.4.0
 */
inline int image_fraction(std::array<std::size_t, 3> const &dims,
                          std::vector<std::int32_t> const &image,
                          std::size_t &count, double &fraction) noexcept {
  if (image.size() != dims[0] * dims[1] * dims[2]) return PW85_EINVAL;
  return pw85_image_fraction(dims.data(), image.data(), &count, &fraction);
}

}  // namespace pw85

#endif  // PW85_IMAGE_HPP
