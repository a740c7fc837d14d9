// SPDX-License-Identifier: BSD-3-Clause
// What the facades (pw85.cpp, pw85_index.cpp, legacy/pw85_legacy.cpp)
// share: the map from the core's status to the PW85_* codes of pw85.h, and
// the runner of batches. Included by the facades only (private).
#ifndef PW85_SRC_FACADE_HPP
#define PW85_SRC_FACADE_HPP

#include <cstddef>

#include "batch.hpp"
#include "pw85.h"
#include "status.hpp"
#include "sym.hpp"

namespace pw85::facade {

inline int to_code(pw85::detail::Status status) noexcept {
  using pw85::detail::Status;
  switch (status) {
    case Status::success:
      return PW85_SUCCESS;
    case Status::null_pointer:
      return PW85_EFAULT;
    case Status::not_finite:
      return PW85_EDOM;
    case Status::not_positive_definite:
      return PW85_ENOTPOSDEF;
    case Status::out_of_range:
      return PW85_ERANGE;
    case Status::no_memory:
      return PW85_ENOMEM;
    case Status::no_convergence:
      return PW85_ENOCONV;
    case Status::invalid_argument:
      return PW85_EINVAL;
    case Status::cancelled:
      return PW85_ECANCELLED;
  }
  return PW85_ENOMEM;  // not reached: every Status is mapped above
}

// ---------------------------------------------------------------------------
// Batches (pw85.h, "Batches"), shared with pw85_index.cpp.

// A stride is 0 (one record for every pair) or at least the record's size.
constexpr bool valid_stride(std::size_t stride, std::size_t size) noexcept {
  return stride == 0 || stride >= size;
}

// A batch: Pair is a callable `int (std::size_t i) const noexcept` that
// computes pair i and returns its PW85_* status.
template <class Pair>
struct Batch {
  Pair pair;
  int *status;  // NULL or n entries
};

template <class Pair>
pw85::detail::BatchFailure run_range(void const *context, std::size_t begin,
                                     std::size_t end) noexcept {
  auto const &batch = *static_cast<Batch<Pair> const *>(context);
  pw85::detail::BatchFailure first{end, PW85_SUCCESS};
  for (std::size_t i = begin; i < end; ++i) {
    int const code = batch.pair(i);
    if (batch.status != nullptr) batch.status[i] = code;
    if (code != PW85_SUCCESS && first.code == PW85_SUCCESS) first = {i, code};
  }
  return first;
}

// The checks of the call itself (pointers_ok: no input or output pointer
// is NULL; strides_ok: every stride valid), then every item on the threads
// asked for.
template <class Item>
int run_items(std::size_t n, bool pointers_ok, bool strides_ok, int *status,
              int threads, Item item) noexcept {
  if (n == 0) return PW85_SUCCESS;
  int code = PW85_SUCCESS;
  if (!pointers_ok)
    code = PW85_EFAULT;
  else if (!strides_ok || threads < 0)
    code = PW85_EINVAL;
  if (code != PW85_SUCCESS) {
    if (status != nullptr)
      for (std::size_t i = 0; i < n; ++i) status[i] = code;
    return code;
  }
  Batch<Item> const batch{item, status};
  return pw85::detail::run_batch(n, pw85::detail::batch_threads(threads, n),
                                 run_range<Item>, &batch)
      .code;
}

// The inputs of a batch of pairs: base pointers and strides in doubles.
struct Pairs {
  double const *r12, *q1, *q2;
  std::size_t r12_stride, q1_stride, q2_stride;
  double const *r(std::size_t i) const noexcept { return r12 + i * r12_stride; }
  double const *a(std::size_t i) const noexcept { return q1 + i * q1_stride; }
  double const *b(std::size_t i) const noexcept { return q2 + i * q2_stride; }
};

// A batch of pairs in D dimensions (vectors of D doubles, forms of
// sym_size(D)), shared by pw85.cpp and pw85_2d.cpp. outputs_ok: no output
// pointer is NULL.
template <int D, class Pair>
int run_pairs(std::size_t n, Pairs const &in, bool outputs_ok, int *status,
              int threads, Pair pair) noexcept {
  constexpr std::size_t sym = pw85::detail::sym_size(D);
  return run_items(
      n, in.r12 != nullptr && in.q1 != nullptr && in.q2 != nullptr && outputs_ok,
      valid_stride(in.r12_stride, D) && valid_stride(in.q1_stride, sym) &&
          valid_stride(in.q2_stride, sym),
      status, threads, pair);
}

// A batch of pairs in D dimensions whose pair i writes `out + size·i`
// (outputs of type T) by one(r12, q1, q2, out_i), a single-pair function
// that returns a PW85_* status.
template <int D, class T, class One>
int pairs_batch(std::size_t n, Pairs const &in, T *out, std::size_t size,
                int *status, int threads, One one) noexcept {
  return run_pairs<D>(n, in, out != nullptr, status, threads,
                      [in, out, size, one](std::size_t i) noexcept {
                        return one(in.r(i), in.a(i), in.b(i), out + size * i);
                      });
}

// The same with two outputs, `out + size·i` and `out2 + size2·i`.
template <int D, class One>
int pairs_batch2(std::size_t n, Pairs const &in, double *out,
                 std::size_t size, double *out2, std::size_t size2,
                 int *status, int threads, One one) noexcept {
  return run_pairs<D>(
      n, in, out != nullptr && out2 != nullptr, status, threads,
      [in, out, size, out2, size2, one](std::size_t i) noexcept {
        return one(in.r(i), in.a(i), in.b(i), out + size * i,
                   out2 + size2 * i);
      });
}

}  // namespace pw85::facade

#endif  // PW85_SRC_FACADE_HPP
