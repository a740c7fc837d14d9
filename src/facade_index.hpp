// SPDX-License-Identifier: BSD-3-Clause
// The facade of the spatial index, written once for pw85_index.h (3D,
// pw85_index.cpp) and pw85_2d_index.h (2D, pw85_2d_index.cpp): check
// pointers, call the core (src/index/, spatial::Index<D>), copy results
// out, map statuses. Handle: the opaque struct of the header, holding
// `index`, a spatial::Index<Handle::dim>. Included by those two facades
// only (private).
#ifndef PW85_SRC_FACADE_INDEX_HPP
#define PW85_SRC_FACADE_INDEX_HPP

#include <algorithm>
#include <cstddef>
#include <new>

#include "checks.hpp"
#include "facade.hpp"
#include "index/energy.hpp"
#include "index/index.hpp"

namespace pw85::facade::index {

using pw85::detail::Status;
template <int D>
using Index = pw85::detail::spatial::Index<D>;
template <int D>
using PairHit = pw85::detail::spatial::PairHit<D>;
template <int D>
using OverlapPair = pw85::detail::spatial::OverlapPair<D>;
template <int D>
using Hit = pw85::detail::spatial::Hit<D>;
template <class T>
using Buffer = pw85::detail::Buffer<T>;

// Arrays of results may be NULL only when there is no room in them.
inline bool outputs_ok(std::size_t capacity, void const *a, void const *b,
                       void const *c) noexcept {
  return capacity == 0 || (a != nullptr && b != nullptr && c != nullptr);
}

// The ids and shifts of the first n pairs: ids[2k], ids[2k + 1] and
// shifts[D·k + a].
template <int D, class H>
void copy_pairs(Buffer<H> const &pairs, std::size_t n, std::size_t *ids,
                int *shifts) noexcept {
  for (std::size_t k = 0; k < n; ++k) {
    ids[2 * k] = pairs[k].i;
    ids[2 * k + 1] = pairs[k].j;
    for (int a = 0; a < D; ++a) shifts[D * k + a] = pairs[k].shift[a];
  }
}

template <class Handle>
int create(double const *box, Handle **index) noexcept {
  constexpr int D = Handle::dim;
  if (index == nullptr) return PW85_EFAULT;
  if (box != nullptr) {
    if (!pw85::detail::all_finite<D>(box)) return PW85_EDOM;
    for (int k = 0; k < D; ++k)
      if (!(box[k] > 0.0 && box[k] <= pw85::detail::max_side))
        return PW85_EINVAL;
  }
  Handle *p = new (std::nothrow) Handle(box);
  if (p == nullptr) return PW85_ENOMEM;
  *index = p;
  return PW85_SUCCESS;
}

template <class Handle>
int count(Handle const *index, std::size_t *n) noexcept {
  if (index == nullptr || n == nullptr) return PW85_EFAULT;
  *n = index->index.count();
  return PW85_SUCCESS;
}

// insert() or update() of one ellipsoid (update: true).
template <class Handle>
int store(Handle *index, std::size_t id, double const *centre,
          double const *q, bool update) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr)
    return PW85_EFAULT;
  return to_code(update ? index->index.update(id, centre, q)
                        : index->index.insert(id, centre, q));
}

// insert_many (threads = 1) and insert_many_threads.
template <class Handle>
int insert_many(Handle *index, std::size_t n, std::size_t const *ids,
                double const *centres, double const *q, int threads) noexcept {
  if (index == nullptr ||
      (n > 0 && (ids == nullptr || centres == nullptr || q == nullptr)))
    return PW85_EFAULT;
  if (threads < 1) return PW85_EINVAL;
  return to_code(index->index.insert_many(n, ids, centres, q, threads));
}

template <class Handle>
int remove(Handle *index, std::size_t id) noexcept {
  if (index == nullptr) return PW85_EFAULT;
  return to_code(index->index.remove(id));
}

template <class Handle>
int get(Handle const *index, std::size_t id, double *centre,
        double *q) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr)
    return PW85_EFAULT;
  return to_code(index->index.get(id, centre, q));
}

template <class Handle>
int overlap_any(Handle const *index, double const *centre, double const *q,
                std::size_t exclude, int *result, std::size_t *id) noexcept {
  if (index == nullptr || centre == nullptr || q == nullptr ||
      result == nullptr || id == nullptr)
    return PW85_EFAULT;
  return to_code(index->index.overlap_any(centre, q, exclude, result, id));
}

// no_id: the header's PW85_INDEX_NO_ID (exclude == NULL).
template <class Handle>
int overlap_any_batch(Handle const *index, std::size_t n,
                      double const *centres, std::size_t centre_stride,
                      double const *q, std::size_t q_stride,
                      std::size_t const *exclude, int *results,
                      std::size_t *ids, int *status, int threads,
                      std::size_t no_id) noexcept {
  constexpr int D = Handle::dim;
  return run_items(
      n,
      index != nullptr && centres != nullptr && q != nullptr &&
          results != nullptr && ids != nullptr,
      valid_stride(centre_stride, D) &&
          valid_stride(q_stride, pw85::detail::sym_size(D)),
      status, threads, [=](std::size_t i) noexcept {
        return to_code(index->index.overlap_any(
            centres + i * centre_stride, q + i * q_stride,
            exclude == nullptr ? no_id : exclude[i], results + i, ids + i));
      });
}

template <class Handle>
int within(Handle const *index, double const *centre, double const *q,
           double t, std::size_t exclude, std::size_t capacity,
           std::size_t *ids, int *shifts, double *mu2_lambda,
           std::size_t *count) noexcept {
  constexpr int D = Handle::dim;
  if (index == nullptr || centre == nullptr || q == nullptr ||
      count == nullptr || !outputs_ok(capacity, ids, shifts, mu2_lambda))
    return PW85_EFAULT;
  Buffer<Hit<D>> hits;
  Status const s = index->index.within(centre, q, t, exclude, &hits);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, hits.size());
  for (std::size_t k = 0; k < n; ++k) {
    ids[k] = hits[k].id;
    for (int a = 0; a < D; ++a) shifts[D * k + a] = hits[k].shift[a];
    mu2_lambda[2 * k] = hits[k].mu2;
    mu2_lambda[2 * k + 1] = hits[k].lambda;
  }
  *count = hits.size();
  return PW85_SUCCESS;
}

template <class Handle>
int overlapping_pairs(Handle const *index, int threads, std::size_t capacity,
                      std::size_t *ids, int *shifts, int *results,
                      std::size_t *count) noexcept {
  constexpr int D = Handle::dim;
  if (index == nullptr || count == nullptr ||
      !outputs_ok(capacity, ids, shifts, results))
    return PW85_EFAULT;
  Buffer<OverlapPair<D>> pairs;
  Status const s = index->index.overlapping_pairs(threads, &pairs, nullptr);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, pairs.size());
  copy_pairs<D>(pairs, n, ids, shifts);
  for (std::size_t k = 0; k < n; ++k) results[k] = pairs[k].result;
  *count = pairs.size();
  return PW85_SUCCESS;
}

template <class Handle>
int pairs_within(Handle const *index, double t, int threads,
                 std::size_t capacity, std::size_t *ids, int *shifts,
                 double *mu2_lambda, std::size_t *count) noexcept {
  constexpr int D = Handle::dim;
  if (index == nullptr || count == nullptr ||
      !outputs_ok(capacity, ids, shifts, mu2_lambda))
    return PW85_EFAULT;
  Buffer<PairHit<D>> pairs;
  Status const s = index->index.pairs(true, t, threads, &pairs, nullptr);
  if (s != Status::success) return to_code(s);
  std::size_t const n = std::min(capacity, pairs.size());
  copy_pairs<D>(pairs, n, ids, shifts);
  for (std::size_t k = 0; k < n; ++k) {
    mu2_lambda[2 * k] = pairs[k].mu2;
    mu2_lambda[2 * k + 1] = pairs[k].lambda;
  }
  *count = pairs.size();
  return PW85_SUCCESS;
}

// pw85_index_energy() and pw85_2d_index_energy(); the kinds are
// PW85_ENERGY_OVERLAP and PW85_ENERGY_USER of pw85_index.h.
template <class Handle>
int sum_energy(Handle const *index, int kind, double param,
           pw85::detail::EnergyFn fn, void *data, int threads, std::size_t n,
           double *energy, double *forces, double *torques) noexcept {
  namespace core = pw85::detail;
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

}  // namespace pw85::facade::index

#endif  // PW85_SRC_FACADE_INDEX_HPP
