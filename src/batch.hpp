// SPDX-License-Identifier: BSD-3-Clause
// Batches: N independent calls, in the calling thread or on OpenMP threads
// (private; pw85.h, "Batches"). batch.cpp is compiled with OpenMP (as are
// the index's threaded queries, src/index/); the per-pair work is the
// caller's, through a function pointer called once per chunk of
// consecutive indices.
#ifndef PW85_SRC_BATCH_HPP
#define PW85_SRC_BATCH_HPP

#include <algorithm>
#include <cstddef>

namespace pw85::detail {

// The most threads any parallel region of libpw85 starts; a larger count
// runs on this many (every threaded result is the same for any count).
// libgomp reserves the start data of a team's threads on the caller's
// stack (gcc 12's: about 100 bytes a thread): pw85_pack() with 100 000
// threads died of SIGSEGV in GOMP_parallel, and libgomp exits the process
// where a thread cannot be created.
constexpr int max_threads = 1024;

// The threads a parallel region over `work` units runs on: the count asked
// (≥ 1), at most one per unit and at most max_threads, at least 1.
inline int team_size(int requested, std::size_t work) noexcept {
  std::size_t const most =
      std::min(work, static_cast<std::size_t>(max_threads));
  return requested < 1 ? 1
         : static_cast<std::size_t>(requested) < most
             ? requested
             : std::max(1, static_cast<int>(most));
}

// The consecutive indices handed to one call of a BatchRange, and the
// least number of them per thread: no thread is started for fewer than
// 2·batch_grain items. A chunk of the cheapest call (pw85_overlap, ~0.1
// µs) costs ~25 µs, far above the cost of handing it out.
constexpr std::size_t batch_grain = 256;
// Chunks per thread of a threaded batch (fewer when that would make them
// smaller than batch_grain): enough for the dynamic schedule to even out
// the threads' loads, few enough that handing them out costs nothing.
constexpr std::size_t batch_chunks_per_thread = 32;

// The first failure met: the lowest index whose code is not 0, with its
// code; index == n (the batch's size) and code 0 when there is none.
struct BatchFailure {
  std::size_t index;
  int code;
};

// Does every item of [begin, end) of the batch described by context;
// returns the first failure among them (code 0 if none). Must be safe to call
// concurrently on disjoint ranges.
using BatchRange = BatchFailure (*)(void const *context, std::size_t begin,
                                    std::size_t end) noexcept;

// The number of threads a batch of n items runs on for a requested count
// ≥ 0: 0 means OpenMP's default (omp_get_max_threads(), which honours
// OMP_NUM_THREADS); then at most n / batch_grain (rounded down), at least
// 1. Always 1 without OpenMP.
int batch_threads(int requested, std::size_t n) noexcept;

// Runs range over [0, n) on `threads` threads (from batch_threads()):
// with 1, in one call of range in the calling thread, no OpenMP call made;
// otherwise in chunks of max(batch_grain, n / (batch_chunks_per_thread ·
// threads)) consecutive indices handed out dynamically. Returns the lowest
// failure over all chunks: the same for any thread count, since every
// item is computed alone.
BatchFailure run_batch(std::size_t n, int threads, BatchRange range,
                       void const *context) noexcept;

}  // namespace pw85::detail

#endif  // PW85_SRC_BATCH_HPP
