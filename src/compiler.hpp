// SPDX-License-Identifier: BSD-3-Clause
// Compiler and portability macros of the core (private). Every other file
// of src/ that needs one includes this header rather than defining its own.
#ifndef PW85_SRC_COMPILER_HPP
#define PW85_SRC_COMPILER_HPP

// PW85_INLINE forces inlining, so that the small kernels are compiled for
// the target of the function that uses them (see PW85_FMA_CLONES).
// PW85_UNROLL before a loop of 3 to 9 iterations unrolls it completely, so
// that index arithmetic (sym_index, row_of, col_of) folds into constants:
// -O2 does not unroll by itself.
// PW85_UNLIKELY(c) marks a condition rarely true (a path for
// ill-conditioned input), so that the common path is laid out first.
#if defined(__GNUC__)
#define PW85_INLINE inline __attribute__((always_inline))
#define PW85_UNROLL _Pragma("GCC unroll 9")
#define PW85_UNLIKELY(c) __builtin_expect(!!(c), 0)
#else
#define PW85_INLINE inline
#define PW85_UNROLL
#define PW85_UNLIKELY(c) (c)
#endif

// PW85_PREFETCH(p): a hint that *p will be read soon (the index's cell
// visits); no effect on results.
#if defined(__GNUC__)
#define PW85_PREFETCH(p) __builtin_prefetch(p)
#else
#define PW85_PREFETCH(p) ((void)0)
#endif

// PW85_ADVISE_HUGEPAGES(p, bytes): a hint to the kernel that the block
// [p, p + bytes) be mapped with transparent huge pages (Linux, where
// MADV_HUGEPAGE exists; nothing elsewhere). Its failure changes nothing.
#if defined(__linux__)
#include <sys/mman.h>
#endif
#if defined(__linux__) && defined(MADV_HUGEPAGE)
#define PW85_ADVISE_HUGEPAGES(p, bytes) ((void)madvise((p), (bytes), MADV_HUGEPAGE))
#else
#define PW85_ADVISE_HUGEPAGES(p, bytes) ((void)(p), (void)(bytes))
#endif

// Compile a function twice, for CPUs with and without FMA, and pick one at
// load time (an ifunc): where the CPU has FMA, std::fma becomes one
// instruction; elsewhere it stays the exact libm routine. The build itself
// stays portable. PW85_NO_FMA_CLONES (meson option fma_clones=false)
// compiles each function once, for the build's own target: ThreadSanitizer
// (gcc 12, clang 14) crashes at start-up in the ifunc resolver, which the
// dynamic loader runs before the sanitizer's runtime is initialised.
#if defined(PW85_NO_FMA_CLONES)
#define PW85_FMA_CLONES
#elif defined(__x86_64__) && defined(__GNUC__) && defined(__linux__) && \
    (defined(__clang__) ? __clang_major__ >= 14 : __GNUC__ >= 8)
#define PW85_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define PW85_FMA_CLONES
#endif

// Benchmark builds only (-DPW85_COUNT_EVALUATIONS): the number of times
// Q(λ) was formed on the calling thread, each one evaluation of f or of its
// terms (counters.cpp).
#ifdef PW85_COUNT_EVALUATIONS
namespace pw85::detail {
extern thread_local unsigned long long evaluations;
unsigned long long evaluation_count() noexcept;
}  // namespace pw85::detail
#define PW85_COUNT_EVALUATION() (++::pw85::detail::evaluations)
#else
#define PW85_COUNT_EVALUATION() ((void)0)
#endif

#endif  // PW85_SRC_COMPILER_HPP
