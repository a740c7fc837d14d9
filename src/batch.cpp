// SPDX-License-Identifier: BSD-3-Clause
// Batches on OpenMP threads (PW85_OPENMP, meson option 'openmp'), or in
// the calling thread.
#include "batch.hpp"

#include <algorithm>
#include <atomic>

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail {

int batch_threads(int requested, std::size_t n) noexcept {
#if defined(PW85_OPENMP)
  // One thread beyond 2^56 pairs (run_batch packs an index in 56 bits).
  if (n >= (std::size_t{1} << 56)) return 1;
  return team_size(requested == 0 ? omp_get_max_threads() : requested,
                   n / batch_grain);
#else
  (void)requested;
  (void)n;
  return 1;
#endif
}

BatchFailure run_batch(std::size_t n, int threads, BatchRange range,
                       void const *context) noexcept {
  BatchFailure first{n, 0};
  if (threads <= 1) {
    // One range: no chunking in the calling thread.
    return n == 0 ? first : range(context, 0, n);
  }
#if defined(PW85_OPENMP)
  // Dynamic: the cost of a pair varies (the search takes more steps near
  // hard cases), and the cores may be shared. About batch_chunks_per_thread
  // chunks per thread, at least batch_grain pairs each: handing out a chunk
  // costs a cache line moved between cores (~1 µs on the 2-core test
  // machine), so chunks of 256 overlaps (16 µs) lost 6–8% of 2 threads'
  // speed-up at n = 1e5 (1.72×; 1.88× with chunks of ~1600).
  std::size_t const grain =
      std::max(batch_grain, n / (batch_chunks_per_thread *
                                 static_cast<std::size_t>(threads)));
  std::size_t const chunks = (n + grain - 1) / grain;

  // The first failure is the minimum of index·2^8 + code over the
  // threads, kept in one atomic word (no lock: a named critical section
  // would be a global symbol of default visibility, exported even from the
  // static archive; an unnamed one is shared with the application's).
  // Codes are below 2^8; n < 2^56 is checked by the caller's thread count
  // (batch_threads() returns 1 beyond).
  std::atomic<unsigned long long> packed{~0ull};
#pragma omp parallel num_threads(threads)
  {
    BatchFailure mine{n, 0};
#pragma omp for schedule(dynamic, 1) nowait
    for (std::size_t c = 0; c < chunks; ++c) {
      BatchFailure const f =
          range(context, c * grain, std::min(n, (c + 1) * grain));
      if (f.code != 0 && f.index < mine.index) mine = f;
    }
    if (mine.code != 0) {
      unsigned long long const v =
          (static_cast<unsigned long long>(mine.index) << 8) |
          static_cast<unsigned long long>(mine.code);
      unsigned long long seen = packed.load(std::memory_order_relaxed);
      while (v < seen &&
             !packed.compare_exchange_weak(seen, v, std::memory_order_relaxed)) {
      }
    }
  }
  unsigned long long const p = packed.load(std::memory_order_relaxed);
  if (p != ~0ull)
    first = BatchFailure{static_cast<std::size_t>(p >> 8),
                         static_cast<int>(p & 0xffu)};
#endif
  return first;
}

}  // namespace pw85::detail
