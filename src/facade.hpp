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

}  // namespace pw85::facade

#endif  // PW85_SRC_FACADE_HPP
