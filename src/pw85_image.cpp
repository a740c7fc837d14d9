// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the voxel image (include/pw85/pw85_image.h):
// check arguments, call the core (src/image/), map statuses.
#include "pw85_image.h"

#include <cfenv>
#include <cstdint>

#include "checks.hpp"
#include "facade.hpp"
#include "image/raster.hpp"

namespace core = pw85::detail;
using pw85::facade::to_code;

namespace {

// The caller's floating-point exception flags, restored on every return
// (pw85_image.h: "the caller's exception flags are left as they were";
// the checks and the guesses raise FE_INEXACT, an overflowing 2²⁹·L_k
// FE_OVERFLOW). OpenMP's other threads have flags of their own.
class KeepFlags {
 public:
  KeepFlags() noexcept { std::fegetexceptflag(&saved_, FE_ALL_EXCEPT); }
  ~KeepFlags() { std::fesetexceptflag(&saved_, FE_ALL_EXCEPT); }
  KeepFlags(KeepFlags const &) = delete;
  KeepFlags &operator=(KeepFlags const &) = delete;

 private:
  std::fexcept_t saved_;
};

// The number of voxels, if dims are valid and the image's bytes fit a
// size_t; else a status.
int voxel_count(size_t const dims[PW85_DIM], std::size_t &count) noexcept {
  std::size_t total = sizeof(std::int32_t);
  for (int k = 0; k < PW85_DIM; ++k) {
    if (dims[k] == 0) return PW85_EINVAL;
    if (total > SIZE_MAX / dims[k]) return PW85_ERANGE;
    total *= dims[k];
  }
  count = total / sizeof(std::int32_t);
  return PW85_SUCCESS;
}

}  // namespace

extern "C" {

int pw85_image_voxels(size_t n, double const *centres, double const *q,
                      double const origin[PW85_DIM],
                      double const sides[PW85_DIM], int periodic,
                      size_t const dims[PW85_DIM], int32_t *image,
                      int threads) noexcept {
  KeepFlags const keep;
  if (sides == nullptr || dims == nullptr || image == nullptr ||
      (n > 0 && (centres == nullptr || q == nullptr)))
    return PW85_EFAULT;
  if (!core::all_finite<PW85_DIM>(sides) ||
      (origin != nullptr && !core::all_finite<PW85_DIM>(origin)))
    return PW85_EDOM;
  core::Grid grid{};
  for (int k = 0; k < PW85_DIM; ++k) {
    if (!(sides[k] > 0.0)) return PW85_EINVAL;
    if (dims[k] == 0 || dims[k] > PW85_IMAGE_MAX_DIM) return PW85_EINVAL;
    grid.origin[k] = origin != nullptr ? origin[k] : 0.0;
    grid.sides[k] = sides[k];
    grid.dims[k] = static_cast<std::int64_t>(dims[k]);
  }
  static_assert(PW85_IMAGE_MAX_DIM == static_cast<size_t>(core::image_max_dim),
                "pw85_image.h and the core disagree on dims");
  grid.periodic = periodic != 0;
  if (n > static_cast<size_t>(INT32_MAX) || threads < 0) return PW85_EINVAL;
  std::size_t voxels = 0;
  int const code = voxel_count(dims, voxels);
  if (code != PW85_SUCCESS) return code;
  core::Status const status = core::check_image_input(grid, n, centres, q);
  if (status != core::Status::success) return to_code(status);
  core::voxel_image(grid, n, centres, q, image, threads);
  return PW85_SUCCESS;
}

int pw85_image_fraction(size_t const dims[PW85_DIM], int32_t const *image,
                        size_t *count, double *fraction) noexcept {
  if (dims == nullptr || image == nullptr) return PW85_EFAULT;
  std::size_t voxels = 0;
  int const code = voxel_count(dims, voxels);
  if (code != PW85_SUCCESS) return code;
  std::size_t inside = 0;
  for (std::size_t v = 0; v < voxels; ++v) inside += image[v] >= 0;
  if (count != nullptr) *count = inside;
  // Both below 2⁵³ (an image of 2⁵³ voxels does not fit in memory): one
  // rounding, the division's.
  if (fraction != nullptr)
    *fraction = static_cast<double>(inside) / static_cast<double>(voxels);
  return PW85_SUCCESS;
}

}  // extern "C"
