// SPDX-License-Identifier: BSD-3-Clause
// A growable array that reports a failed allocation instead of throwing
// (private): the core is built without exceptions, and the index must
// return PW85_ENOMEM, never abort. Growth reserves first (reserve(),
// grow_for()), so that a caller can make every allocation of an operation
// before it changes anything.
//
// Buffers of 1 MiB and more (the all-pairs queries' snapshot and pair
// lists, insert_many()'s cells and per-item arrays: tens to hundreds of
// megabytes at N = 1e6) are rounded up to whole 2 MiB pages, aligned to
// 2 MiB and, on Linux, marked for huge pages (PW85_ADVISE_HUGEPAGES,
// compiler.hpp): with transparent huge pages in "madvise" mode (the
// default of Debian 12) a page fault then maps 2 MiB instead of 4 KiB, at
// the cost of at most one partly used huge page per buffer.
// Faults on fresh memory cost a quarter of the all-pairs query at N = 1e6
// without it (measured with perf on a virtual machine, where a 4 KiB
// fault costs tens of microseconds). The advice is a hint to the kernel:
// its failure changes nothing.
#ifndef PW85_SRC_INDEX_BUFFER_HPP
#define PW85_SRC_INDEX_BUFFER_HPP

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "compiler.hpp"

namespace pw85::detail {

// Allocates `bytes` aligned to `align` (a power of two, a multiple of
// alignof(max_align_t) or 0 for malloc's); large blocks as above. (With
// a threshold of 8 MiB, the arrays of 4 to 8 bytes per item of
// insert_many() and the first blocks of the pair lists took 9,300 faults
// of 4 KiB in `bench-index first`, 10^6 ellipsoids; 1 MiB leaves fewer
// than 1,000.)
inline void *buffer_alloc(std::size_t bytes, std::size_t align) noexcept {
  constexpr std::size_t huge = std::size_t(1) << 21;
  if (bytes >= huge / 2) {
    std::size_t const rounded = (bytes + huge - 1) & ~(huge - 1);
    if (rounded < bytes) return nullptr;
    void *p = std::aligned_alloc(huge, rounded);
    if (p != nullptr) PW85_ADVISE_HUGEPAGES(p, rounded);
    return p;
  }
  if (align > alignof(std::max_align_t)) return std::aligned_alloc(align, bytes);
  return std::malloc(bytes);
}

// Blocks of memory whose parts buffers borrow (Buffer::borrow(); the cells
// that insert_many() creates: one allocation, with huge pages when large,
// instead of one per cell, whose first-touch page faults cost more than
// the rest of the insertion on a virtual machine). The buffers never free
// a part; the list frees its blocks when it is destroyed, after them.
class BlockList {
 public:
  BlockList() noexcept = default;
  BlockList(BlockList const &) = delete;
  BlockList &operator=(BlockList const &) = delete;
  ~BlockList() {
    while (head_ != nullptr) {
      Header *const next = head_->next;
      std::free(head_);
      head_ = next;
    }
  }
  // A new block of `bytes` bytes aligned to 64, or nullptr when the
  // allocation fails.
  void *allocate(std::size_t bytes) noexcept {
    constexpr std::size_t a = alignof(Header);
    if (bytes > std::size_t(-1) - sizeof(Header) - a) return nullptr;
    // A multiple of the alignment, as aligned_alloc() requires.
    std::size_t const total = (sizeof(Header) + bytes + a - 1) & ~(a - 1);
    void *p = buffer_alloc(total, a);
    if (p == nullptr) return nullptr;
    head_ = new (p) Header{head_};
    return head_ + 1;
  }

 private:
  struct alignas(64) Header {
    Header *next;
  };
  Header *head_ = nullptr;
};

template <typename T>
class Buffer {
  static_assert(std::is_nothrow_move_constructible_v<T>,
                "elements are moved when the buffer grows");

 public:
  Buffer() noexcept = default;
  Buffer(Buffer const &) = delete;
  Buffer &operator=(Buffer const &) = delete;
  Buffer(Buffer &&o) noexcept : data_(o.data_), size_(o.size_), cap_(o.cap_) {
    o.data_ = nullptr;
    o.size_ = o.cap_ = 0;
  }
  Buffer &operator=(Buffer &&o) noexcept {
    if (this != &o) {
      release();
      data_ = o.data_;
      size_ = o.size_;
      cap_ = o.cap_;
      o.data_ = nullptr;
      o.size_ = o.cap_ = 0;
    }
    return *this;
  }
  ~Buffer() { release(); }

  std::size_t size() const noexcept { return size_; }
  std::size_t capacity() const noexcept { return cap_ & ~borrowed; }
  bool empty() const noexcept { return size_ == 0; }
  T *data() noexcept { return data_; }
  T const *data() const noexcept { return data_; }
  T &operator[](std::size_t i) noexcept { return data_[i]; }
  T const &operator[](std::size_t i) const noexcept { return data_[i]; }
  T &back() noexcept { return data_[size_ - 1]; }

  // Capacity for at least n elements; false (nothing changed) when the
  // allocation fails.
  [[nodiscard]] bool reserve(std::size_t n) noexcept {
    if (n <= capacity()) return true;
    if (n > std::size_t(-1) / sizeof(T) || n >= borrowed) return false;
    // sizeof(T) is a multiple of alignof(T), as aligned_alloc requires.
    T *p = static_cast<T *>(buffer_alloc(n * sizeof(T), alignof(T)));
    if (p == nullptr) return false;
    if constexpr (std::is_trivially_copyable_v<T>) {
      if (size_ > 0) std::memcpy(static_cast<void *>(p), data_, size_ * sizeof(T));
    } else {
      for (std::size_t i = 0; i < size_; ++i) {
        new (p + i) T(std::move(data_[i]));
        data_[i].~T();
      }
    }
    free_memory();
    data_ = p;
    cap_ = n;
    return true;
  }
  // Takes room for n elements at p, a part of a block of a BlockList,
  // instead of memory of its own, for an empty buffer with no memory
  // (size() = capacity() = 0); p aligned for T. The buffer never frees
  // it: it moves to memory of its own when it grows beyond n.
  void borrow(T *p, std::size_t n) noexcept {
    data_ = p;
    cap_ = n | borrowed;
  }
  // Capacity for `extra` more elements, doubling (amortised O(1)).
  [[nodiscard]] bool grow_for(std::size_t extra) noexcept {
    std::size_t const cap = capacity();
    if (size_ + extra <= cap) return true;
    std::size_t n = cap < 4 ? 4 : cap;
    while (n < size_ + extra) {
      if (n > std::size_t(-1) / 2) return false;
      n *= 2;
    }
    return reserve(n);
  }
  // After reserve() or grow_for(): cannot fail.
  void push_back_reserved(T &&x) noexcept {
    new (data_ + size_) T(std::move(x));
    ++size_;
  }
  [[nodiscard]] bool push_back(T x) noexcept {
    if (!grow_for(1)) return false;
    push_back_reserved(std::move(x));
    return true;
  }
  // Grows to n value-initialised elements (n ≥ size()); false on failure.
  // The capacity grows as grow_for()'s (at least doubling), so that growing
  // one element at a time (the index's table of ids, as ids are inserted in
  // order) is O(1) amortised, not a copy of the whole table each time.
  [[nodiscard]] bool resize(std::size_t n) noexcept {
    if (n > size_ && !grow_for(n - size_)) return false;
    while (size_ < n) new (data_ + size_++) T();
    return true;
  }
  // Grows to n elements left uninitialised (n ≥ size(); trivial types
  // only, to be written before they are read); false on failure.
  [[nodiscard]] bool resize_uninitialised(std::size_t n) noexcept {
    static_assert(std::is_trivial_v<T>, "for trivial types only");
    if (n > size_ && !grow_for(n - size_)) return false;
    size_ = n;
    return true;
  }
  void pop_back() noexcept { data_[--size_].~T(); }
  void clear() noexcept {
    while (size_ > 0) pop_back();
  }
  // Empties the buffer and frees its memory.
  void reset() noexcept { release(); }

 private:
  void release() noexcept {
    clear();
    free_memory();
    data_ = nullptr;
    cap_ = 0;
  }
  // The buffer's memory freed, unless borrowed.
  void free_memory() noexcept {
    if ((cap_ & borrowed) == 0) std::free(data_);
  }

  // The top bit of cap_: data_ is borrowed (borrow()). No capacity
  // reaches it (n·sizeof(T) < 2^64).
  static constexpr std::size_t borrowed = ~(std::size_t(-1) >> 1);

  T *data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t cap_ = 0;
};

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_BUFFER_HPP
