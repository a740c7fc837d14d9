// SPDX-License-Identifier: BSD-3-Clause
// The extern "C" facade of the index (include/pw85/pw85_index.h): check
// pointers, call the core (src/index/), copy results out, map statuses.
#include "pw85_index.h"

#include <algorithm>
#include <new>

#include "checks.hpp"
#include "facade.hpp"
#include "index/energy.hpp"
#include "index/index.hpp"

namespace core = pw85::detail;
using core::Status;
using pw85::facade::run_items;
using pw85::facade::to_code;
using pw85::facade::valid_stride;

struct pw85_index {
  explicit pw85_index(double const box[PW85_DIM]) noexcept : index(box) {}
  core::Index index;
};

static_assert(PW85_INDEX_MAX_ID == core::max_id,
              "pw85_index.h and the core disagree on ids");

namespace {

// Arrays of results may be NULL only when there is no room in them.
bool outputs_ok(std::size_t capacity, void const *a, void const *b,
                void const *c) noexcept {
  return capacity == 0 || (a != nullptr && b != nullptr && c != nullptr);
}

// The ids and shifts of the first n pairs, in the layout of pw85_index.h.
void copy_pairs(core::Buffer<core::PairHit> const &pairs, std::size_t n,
                size_t *ids, int *shifts) noexcept {
  for (std::size_t k = 0; k < n; ++k) {
    ids[2 * k] = pairs[k].i;
    ids[2 * k + 1] = pairs[k].j;
    for (int a = 0; a < PW85_DIM; ++a) shifts[3 * k + a] = pairs[k].shift[a];
  }
}

// insert() or update() (member) of one ellipsoid, pointers checked.
int store(pw85_index *index, size_t id, double const centre[PW85_DIM],
          double const q[PW85_SYM],
          Status (core::Index::*member)(std::size_t, double const *,
                                        double const *)) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr)
    return PW85_EFAULT;
  return to_code((index->index.*member)(id, centre, q));
}

}  // namespace

extern "C" {

int pw85_index_create(double const box[PW85_DIM],
                      pw85_index **index) noexcept {
  if (index == nullptr) return PW85_EFAULT;
  if (box != nullptr) {
    if (!core::all_finite<PW85_DIM>(box)) return PW85_EDOM;
    for (int k = 0; k < PW85_DIM; ++k)
      if (!(box[k] > 0.0)) return PW85_EINVAL;
  }
  pw85_index *p = new (std::nothrow) pw85_index(box);
  if (p == nullptr) return PW85_ENOMEM;
  *index = p;
  return PW85_SUCCESS;
}

void pw85_index_destroy(pw85_index *index) noexcept { delete index; }

int pw85_index_openmp(void) noexcept {
#if defined(PW85_OPENMP)
  return 1;
#else
  return 0;
#endif
}

int pw85_index_count(pw85_index const *index, size_t *count) noexcept {
  if (index == nullptr || count == nullptr) return PW85_EFAULT;
  *count = index->index.count();
  return PW85_SUCCESS;
}

int pw85_index_insert(pw85_index *index, size_t id,
                      double const centre[PW85_DIM],
                      double const q[PW85_SYM]) noexcept {
  return store(index, id, centre, q, &core::Index::insert);
}

int pw85_index_insert_many(pw85_index *index, size_t n, size_t const *ids,
                           double const *centres, double const *q) noexcept {
  if (index == nullptr ||
      (n > 0 && (ids == nullptr || centres == nullptr || q == nullptr)))
    return PW85_EFAULT;
  return to_code(index->index.insert_many(n, ids, centres, q));
}

int pw85_index_insert_many_threads(pw85_index *index, size_t n,
                                   size_t const *ids, double const *centres,
                                   double const *q, int threads) noexcept {
  if (index == nullptr ||
      (n > 0 && (ids == nullptr || centres == nullptr || q == nullptr)))
    return PW85_EFAULT;
  if (threads < 1) return PW85_EINVAL;
  return to_code(index->index.insert_many(n, ids, centres, q, threads));
}

int pw85_index_update(pw85_index *index, size_t id,
                      double const centre[PW85_DIM],
                      double const q[PW85_SYM]) noexcept {
  return store(index, id, centre, q, &core::Index::update);
}

int pw85_index_remove(pw85_index *index, size_t id) noexcept {
  if (index == nullptr) return PW85_EFAULT;
  return to_code(index->index.remove(id));
}

int pw85_index_get(pw85_index const *index, size_t id,
                   double centre[PW85_DIM], double q[PW85_SYM]) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr)
    return PW85_EFAULT;
  return to_code(index->index.get(id, centre, q));
}

int pw85_index_overlap_any(pw85_index const *index,
                           double const centre[PW85_DIM],
                           double const q[PW85_SYM], size_t exclude,
                           int *result, size_t *id) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr ||
      result == nullptr || id == nullptr)
    return PW85_EFAULT;
  return to_code(index->index.overlap_any(centre, q, exclude, result, id));
}

int pw85_index_overlap_any_batch(pw85_index const *index, size_t n,
                                 double const *centres, size_t centre_stride,
                                 double const *q, size_t q_stride,
                                 size_t const *exclude, int *results,
                                 size_t *ids, int *status,
                                 int threads) noexcept {
  return run_items(
      n,
      index != nullptr && centres != nullptr && q != nullptr &&
          results != nullptr && ids != nullptr,
      valid_stride(centre_stride, PW85_DIM) && valid_stride(q_stride, PW85_SYM),
      status, threads, [=](std::size_t i) noexcept {
        return to_code(index->index.overlap_any(
            centres + i * centre_stride, q + i * q_stride,
            exclude == nullptr ? PW85_INDEX_NO_ID : exclude[i], results + i,
            ids + i));
      });
}

int pw85_index_within(pw85_index const *index, double const centre[PW85_DIM],
                      double const q[PW85_SYM], double t, size_t exclude,
                      size_t capacity, size_t *ids, int *shifts,
                      double *mu2_lambda, size_t *count) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr ||
      count == nullptr || !outputs_ok(capacity, ids, shifts, mu2_lambda))
    return PW85_EFAULT;
  core::Buffer<core::Hit> hits;
  Status const s = index->index.within(centre, q, t, exclude, &hits);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, hits.size());
  for (std::size_t k = 0; k < n; ++k) {
    ids[k] = hits[k].id;
    for (int a = 0; a < PW85_DIM; ++a) shifts[3 * k + a] = hits[k].shift[a];
    mu2_lambda[2 * k] = hits[k].mu2;
    mu2_lambda[2 * k + 1] = hits[k].lambda;
  }
  *count = hits.size();
  return PW85_SUCCESS;
}

int pw85_index_overlapping_pairs(pw85_index const *index, int threads,
                                 size_t capacity, size_t *ids, int *shifts,
                                 int *results, size_t *count) noexcept {
  if (index == nullptr || count == nullptr ||
      !outputs_ok(capacity, ids, shifts, results))
    return PW85_EFAULT;
  core::Buffer<core::PairHit> pairs;
  Status const s = index->index.pairs(false, 1.0, threads, &pairs, nullptr);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, pairs.size());
  copy_pairs(pairs, n, ids, shifts);
  for (std::size_t k = 0; k < n; ++k) results[k] = pairs[k].result;
  *count = pairs.size();
  return PW85_SUCCESS;
}

int pw85_index_pairs_within(pw85_index const *index, double t, int threads,
                            size_t capacity, size_t *ids, int *shifts,
                            double *mu2_lambda, size_t *count) noexcept {
  if (index == nullptr || count == nullptr ||
      !outputs_ok(capacity, ids, shifts, mu2_lambda))
    return PW85_EFAULT;
  core::Buffer<core::PairHit> pairs;
  Status const s = index->index.pairs(true, t, threads, &pairs, nullptr);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, pairs.size());
  copy_pairs(pairs, n, ids, shifts);
  for (std::size_t k = 0; k < n; ++k) {
    mu2_lambda[2 * k] = pairs[k].mu2;
    mu2_lambda[2 * k + 1] = pairs[k].lambda;
  }
  *count = pairs.size();
  return PW85_SUCCESS;
}

int pw85_index_energy(pw85_index const *index, int kind, double param,
                      pw85_pair_energy fn, void *data, int threads, size_t n,
                      double *energy, double *forces,
                      double *torques) noexcept {
  if (index == nullptr || energy == nullptr) return PW85_EFAULT;
  if (kind != PW85_ENERGY_OVERLAP && kind != PW85_ENERGY_USER)
    return PW85_EINVAL;
  core::EnergySpec const spec{kind == PW85_ENERGY_OVERLAP
                                  ? core::EnergyKind::overlap
                                  : core::EnergyKind::user,
                              param, fn, data};
  return to_code(core::assembly_energy(index->index, spec, threads, n, energy,
                                       forces, torques));
}

}  // extern "C"
