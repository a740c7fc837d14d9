// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85_2d_pack.hpp
 * @brief pw85::d2::pack(): the certified packer of ellipses of
 *        pw85_2d_pack.h, its outputs owned by std::vector, its progress
 *        through any callable.
 *
 * Header-only over the C ABI of pw85_2d_pack.h, whose description is the
 * contract here; pw85::pack() (pw85_pack.hpp) for ellipses, written once
 * with it, taking the same PackOptions (read as pw85_2d_pack.h says: the
 * first two entries of aspect, and of axis with PW85_PACK_ALIGNED). Link
 * the same -lpw85. C++11. Every function returns the PW85_* status of
 * pw85_2d_pack() and none throws; on error the output is unchanged.
 *
 * @since 2.5.0
 */
#ifndef PW85_2D_PACK_HPP
#define PW85_2D_PACK_HPP

#include <array>
#include <vector>

#include "pw85_2d_pack.h"
#include "pw85_pack.hpp"

namespace pw85 {

namespace d2 {

/** The result of pack(): the rectangle, and per ellipse its centre (2
 *  doubles), angle (1) and form (3: Q00, Q01, Q11), row by row.
 *  @since 2.5.0 */
struct Packing {
  std::array<double, 2> box{};    ///< the sides L0, L1
  std::vector<double> centres;    ///< 2·n, in [0, L_k)
  std::vector<double> angles;     ///< n, radians, in [−π, π]
  std::vector<double> forms;      ///< 3·n
  double phi = 0.0;               ///< the packing fraction
  int outcome = PW85_PACK_LIMIT;  ///< PW85_PACK_TARGET, ..._LIMIT, ...
};

/**
 * @brief Pack the ellipses of `semi_axes` (2 per ellipse) with the options
 *        (pw85_2d_pack()); the callback of the options is used as set
 *        there.
 * @return the statuses of pw85_2d_pack(); PW85_EINVAL also if the size of
 *         semi_axes is odd; PW85_ENOMEM if a vector cannot grow. `out` is
 *         unchanged on error.
 * @since 2.5.0
 */
inline int pack(std::vector<double> const &semi_axes,
                PackOptions const &options, Packing &out) noexcept {
  return detail_pack::run<2, 1, 3>(pw85_2d_pack, &Packing::angles,
                                   semi_axes, options, out);
}

/**
 * @brief pack() with a progress callable `bool progress(pw85_pack_progress
 *        const &)`, called every options.progress_every steps in the
 *        calling thread: false (or an exception, not rethrown) stops the
 *        packer (outcome PW85_PACK_CANCELLED).
 * @since 2.5.0
 */
template <typename F>
int pack(std::vector<double> const &semi_axes, PackOptions const &options,
         F &&progress, Packing &out) noexcept {
  return detail_pack::run_with<2, 1, 3>(pw85_2d_pack, &Packing::angles,
                                        semi_axes, options, progress, out);
}

}  // namespace d2

}  // namespace pw85

#endif  // PW85_2D_PACK_HPP
