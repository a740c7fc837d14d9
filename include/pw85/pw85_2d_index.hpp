// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file pw85_2d_index.hpp
 * @brief pw85::d2::Index, the C++ owner of a pw85_2d_index
 *        (pw85_2d_index.h): the spatial index of ellipses, its queries
 *        returning std::vector.
 *
 * Header-only over the C ABI of pw85_2d_index.h, whose description of each
 * function is the contract here; link the same -lpw85. The class is
 * pw85::Index (pw85_index.hpp) for ellipses: the same members, written
 * once for both (index_detail::BasicIndex), with centres and image shifts
 * of 2 coordinates and forms of 3 stored entries (Q00, Q01, Q11); its
 * energy members (overlap_energy(), energy(); pw85_2d_index_energy()) give
 * forces of 2 coordinates and one torque (∂/∂θ) per ellipse. Needs C++11.
 *
 * Conventions, memory, threads and the rule on failed calls: those of
 * pw85_index.hpp.
 *
 * @since 2.5.0
 */
#ifndef PW85_2D_INDEX_HPP
#define PW85_2D_INDEX_HPP

#include <cstddef>

#include "pw85_2d_index.h"
#include "pw85_index.hpp"

namespace pw85 {

namespace index_detail {

/// @cond INTERNAL
// The C functions of pw85_2d_index.h, for BasicIndex (pw85_index.hpp).
PW85_INDEX_CXX_API(Api2, pw85_2d_index, pw85_2d_index, PW85_2D_DIM,
                   PW85_2D_SYM);
/// @endcond

}  // namespace index_detail

namespace d2 {

/**
 * @brief A spatial index of ellipses (pw85_2d_index.h), owned: created by
 *        open() (an open plane) or periodic() (a periodic rectangle),
 *        destroyed with the object.
 *
 * Move-only, with the rule of pw85::Index for an object that holds no
 * index (default-constructed, moved from, or whose creation failed): its
 * members return PW85_EFAULT and change nothing. Results: Neighbour,
 * OverlappingPair and Pair, with image shifts of 2 ints.
 * @since 2.5.0
 */
class Index
    : public index_detail::BasicIndex<Index, index_detail::Api2> {
 public:
  using BasicIndex::BasicIndex;
};

}  // namespace d2

}  // namespace pw85

#endif  // PW85_2D_INDEX_HPP
