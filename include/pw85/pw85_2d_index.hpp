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
 * of 2 coordinates and forms of 3 stored entries (Q00, Q01, Q11); it has
 * no energy members (pw85_index_energy() is 3D only). Needs C++11.
 *
 * Conventions, memory, threads and the rule on failed calls: those of
 * pw85_index.hpp.
 *
 * @since 2.6.0
 */
#ifndef PW85_2D_INDEX_HPP
#define PW85_2D_INDEX_HPP

#include <cstddef>

#include "pw85_2d_index.h"
#include "pw85_index.hpp"

namespace pw85 {

namespace index_detail {

/// @cond INTERNAL
// The C functions of pw85_2d_index.h, for BasicIndex.
struct Api2 {
  using handle = pw85_2d_index;
  static constexpr std::size_t dim = PW85_2D_DIM;
  static constexpr std::size_t sym = PW85_2D_SYM;
  static int create(double const *box, handle **h) noexcept {
    return pw85_2d_index_create(box, h);
  }
  static void destroy(handle *h) noexcept { pw85_2d_index_destroy(h); }
  static int count(handle const *h, std::size_t *n) noexcept {
    return pw85_2d_index_count(h, n);
  }
  static int insert(handle *h, std::size_t id, double const *c,
                    double const *q) noexcept {
    return pw85_2d_index_insert(h, id, c, q);
  }
  static int insert_many(handle *h, std::size_t n, std::size_t const *ids,
                         double const *c, double const *q) noexcept {
    return pw85_2d_index_insert_many(h, n, ids, c, q);
  }
  static int insert_many_threads(handle *h, std::size_t n,
                                 std::size_t const *ids, double const *c,
                                 double const *q, int threads) noexcept {
    return pw85_2d_index_insert_many_threads(h, n, ids, c, q, threads);
  }
  static int update(handle *h, std::size_t id, double const *c,
                    double const *q) noexcept {
    return pw85_2d_index_update(h, id, c, q);
  }
  static int remove(handle *h, std::size_t id) noexcept {
    return pw85_2d_index_remove(h, id);
  }
  static int get(handle const *h, std::size_t id, double *c,
                 double *q) noexcept {
    return pw85_2d_index_get(h, id, c, q);
  }
  static int overlap_any(handle const *h, double const *c, double const *q,
                         std::size_t exclude, int *result,
                         std::size_t *id) noexcept {
    return pw85_2d_index_overlap_any(h, c, q, exclude, result, id);
  }
  static int overlap_any_batch(handle const *h, std::size_t n,
                               double const *c, std::size_t cs,
                               double const *q, std::size_t qs,
                               std::size_t const *exclude, int *results,
                               std::size_t *ids, int *status,
                               int threads) noexcept {
    return pw85_2d_index_overlap_any_batch(h, n, c, cs, q, qs, exclude,
                                           results, ids, status, threads);
  }
  static int within(handle const *h, double const *c, double const *q,
                    double t, std::size_t exclude, std::size_t cap,
                    std::size_t *ids, int *shifts, double *values,
                    std::size_t *n) noexcept {
    return pw85_2d_index_within(h, c, q, t, exclude, cap, ids, shifts, values,
                                n);
  }
  static int overlapping_pairs(handle const *h, int threads, std::size_t cap,
                               std::size_t *ids, int *shifts, int *values,
                               std::size_t *n) noexcept {
    return pw85_2d_index_overlapping_pairs(h, threads, cap, ids, shifts,
                                           values, n);
  }
  static int pairs_within(handle const *h, double t, int threads,
                          std::size_t cap, std::size_t *ids, int *shifts,
                          double *values, std::size_t *n) noexcept {
    return pw85_2d_index_pairs_within(h, t, threads, cap, ids, shifts, values,
                                      n);
  }
};
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
 * @since 2.6.0
 */
class Index
    : public index_detail::BasicIndex<Index, index_detail::Api2> {
 public:
  using BasicIndex::BasicIndex;
};

}  // namespace d2

}  // namespace pw85

#endif  // PW85_2D_INDEX_HPP
