// SPDX-License-Identifier: BSD-3-Clause
// Batches on OpenMP threads (PW85_OPENMP, meson option 'openmp'), or in
// the calling thread.
#include "batch.hpp"

#include <algorithm>

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail {

int batch_threads(int requested, std::size_t n) noexcept {
#if defined(PW85_OPENMP)
  std::size_t const wanted = static_cast<std::size_t>(
      requested == 0 ? omp_get_max_threads() : requested);
  return static_cast<int>(
      std::max<std::size_t>(1, std::min(wanted, n / batch_grain)));
#else
  (void)requested;
  (void)n;
  return 1;
#endif
}

BatchFailure run_batch(std::size_t n, int threads, BatchRange range,
                       void const *context) noexcept {
  std::size_t const chunks = (n + batch_grain - 1) / batch_grain;
  BatchFailure first{n, 0};
  if (threads <= 1) {
    for (std::size_t c = 0; c < chunks; ++c) {
      BatchFailure const f = range(context, c * batch_grain,
                                   std::min(n, (c + 1) * batch_grain));
      if (f.code != 0 && first.code == 0) first = f;
    }
    return first;
  }
#if defined(PW85_OPENMP)
  // Dynamic: the cost of a pair varies (the search takes more steps near
  // hard cases), and the cores may be shared.
#pragma omp parallel num_threads(threads)
  {
    BatchFailure mine{n, 0};
#pragma omp for schedule(dynamic, 1) nowait
    for (std::size_t c = 0; c < chunks; ++c) {
      BatchFailure const f = range(context, c * batch_grain,
                                   std::min(n, (c + 1) * batch_grain));
      if (f.code != 0 && f.index < mine.index) mine = f;
    }
#pragma omp critical(pw85_batch_first_failure)
    if (mine.index < first.index) first = mine;
  }
#endif
  return first;
}

}  // namespace pw85::detail
