// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the index of ellipses
// (include/pw85/pw85_2d_index.h): the calls of facade_index.hpp with
// D = 2, as pw85_index.cpp makes them with D = 3.
#include "pw85_2d_index.h"

#include "facade_index.hpp"

namespace {

namespace core = pw85::detail;
namespace calls = pw85::facade::index;

}  // namespace

struct pw85_2d_index {
  static constexpr int dim = PW85_2D_DIM;
  explicit pw85_2d_index(double const box[PW85_2D_DIM]) noexcept
      : index(box) {}
  core::spatial::Index<PW85_2D_DIM> index;
};

static_assert(PW85_2D_SYM == core::sym_size(PW85_2D_DIM),
              "pw85_2d_index.h and the core disagree on sizes");

extern "C" {

int pw85_2d_index_create(double const box[PW85_2D_DIM],
                         pw85_2d_index **index) noexcept {
  return calls::create(box, index);
}

void pw85_2d_index_destroy(pw85_2d_index *index) noexcept { delete index; }

int pw85_2d_index_count(pw85_2d_index const *index, size_t *count) noexcept {
  return calls::count(index, count);
}

int pw85_2d_index_insert(pw85_2d_index *index, size_t id,
                         double const centre[PW85_2D_DIM],
                         double const q[PW85_2D_SYM]) noexcept {
  return calls::store(index, id, centre, q, false);
}

int pw85_2d_index_insert_many(pw85_2d_index *index, size_t n,
                              size_t const *ids, double const *centres,
                              double const *q) noexcept {
  return calls::insert_many(index, n, ids, centres, q, 1);
}

int pw85_2d_index_insert_many_threads(pw85_2d_index *index, size_t n,
                                      size_t const *ids,
                                      double const *centres, double const *q,
                                      int threads) noexcept {
  return calls::insert_many(index, n, ids, centres, q, threads);
}

int pw85_2d_index_update(pw85_2d_index *index, size_t id,
                         double const centre[PW85_2D_DIM],
                         double const q[PW85_2D_SYM]) noexcept {
  return calls::store(index, id, centre, q, true);
}

int pw85_2d_index_remove(pw85_2d_index *index, size_t id) noexcept {
  return calls::remove(index, id);
}

int pw85_2d_index_get(pw85_2d_index const *index, size_t id,
                      double centre[PW85_2D_DIM],
                      double q[PW85_2D_SYM]) noexcept {
  return calls::get(index, id, centre, q);
}

int pw85_2d_index_overlap_any(pw85_2d_index const *index,
                              double const centre[PW85_2D_DIM],
                              double const q[PW85_2D_SYM], size_t exclude,
                              int *result, size_t *id) noexcept {
  return calls::overlap_any(index, centre, q, exclude, result, id);
}

int pw85_2d_index_overlap_any_batch(pw85_2d_index const *index, size_t n,
                                    double const *centres,
                                    size_t centre_stride, double const *q,
                                    size_t q_stride, size_t const *exclude,
                                    int *results, size_t *ids, int *status,
                                    int threads) noexcept {
  return calls::overlap_any_batch(index, n, centres, centre_stride, q,
                                  q_stride, exclude, results, ids, status,
                                  threads, PW85_INDEX_NO_ID);
}

int pw85_2d_index_within(pw85_2d_index const *index,
                         double const centre[PW85_2D_DIM],
                         double const q[PW85_2D_SYM], double t,
                         size_t exclude, size_t capacity, size_t *ids,
                         int *shifts, double *mu2_lambda,
                         size_t *count) noexcept {
  return calls::within(index, centre, q, t, exclude, capacity, ids, shifts,
                       mu2_lambda, count);
}

int pw85_2d_index_overlapping_pairs(pw85_2d_index const *index, int threads,
                                    size_t capacity, size_t *ids, int *shifts,
                                    int *results, size_t *count) noexcept {
  return calls::overlapping_pairs(index, threads, capacity, ids, shifts,
                                  results, count);
}

int pw85_2d_index_pairs_within(pw85_2d_index const *index, double t,
                               int threads, size_t capacity, size_t *ids,
                               int *shifts, double *mu2_lambda,
                               size_t *count) noexcept {
  return calls::pairs_within(index, t, threads, capacity, ids, shifts,
                             mu2_lambda, count);
}

int pw85_2d_index_energy(pw85_2d_index const *index, int kind, double param,
                         pw85_pair_energy fn, void *data, int threads,
                         size_t n, double *energy, double *forces,
                         double *torques) noexcept {
  return calls::sum_energy(index, kind, param, fn, data, threads, n, energy,
                       forces, torques);
}

}  // extern "C"
