// SPDX-License-Identifier: BSD-3-Clause
// Batches: N independent calls, in the calling thread or on OpenMP threads
// (private; pw85.h, "Batches"). batch.cpp is compiled with OpenMP (as are
// the index's threaded queries, src/index/); the per-pair work is the
// caller's, through a function pointer called once per chunk of
// consecutive indices.
#ifndef PW85_SRC_BATCH_HPP
#define PW85_SRC_BATCH_HPP

#include <cstddef>

namespace pw85::detail {

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
