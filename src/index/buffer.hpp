// SPDX-License-Identifier: BSD-3-Clause
// A growable array that reports a failed allocation instead of throwing
// (private): the core is built without exceptions, and the index must
// return PW85_ENOMEM, never abort. Growth reserves first (reserve(),
// grow_for()), so that a caller can make every allocation of an operation
// before it changes anything.
#ifndef PW85_SRC_INDEX_BUFFER_HPP
#define PW85_SRC_INDEX_BUFFER_HPP

#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace pw85::detail {

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
  bool empty() const noexcept { return size_ == 0; }
  T *data() noexcept { return data_; }
  T const *data() const noexcept { return data_; }
  T &operator[](std::size_t i) noexcept { return data_[i]; }
  T const &operator[](std::size_t i) const noexcept { return data_[i]; }
  T &back() noexcept { return data_[size_ - 1]; }

  // Capacity for at least n elements; false (nothing changed) when the
  // allocation fails.
  [[nodiscard]] bool reserve(std::size_t n) noexcept {
    if (n <= cap_) return true;
    if (n > std::size_t(-1) / sizeof(T)) return false;
    // sizeof(T) is a multiple of alignof(T), as aligned_alloc requires.
    T *p = static_cast<T *>(alignof(T) > alignof(std::max_align_t)
                                ? std::aligned_alloc(alignof(T), n * sizeof(T))
                                : std::malloc(n * sizeof(T)));
    if (p == nullptr) return false;
    for (std::size_t i = 0; i < size_; ++i) {
      new (p + i) T(std::move(data_[i]));
      data_[i].~T();
    }
    std::free(data_);
    data_ = p;
    cap_ = n;
    return true;
  }
  // Capacity for `extra` more elements, doubling (amortised O(1)).
  [[nodiscard]] bool grow_for(std::size_t extra) noexcept {
    if (size_ + extra <= cap_) return true;
    std::size_t n = cap_ < 4 ? 4 : cap_;
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
  [[nodiscard]] bool resize(std::size_t n) noexcept {
    if (!reserve(n)) return false;
    while (size_ < n) new (data_ + size_++) T();
    return true;
  }
  void pop_back() noexcept { data_[--size_].~T(); }
  void clear() noexcept {
    while (size_ > 0) pop_back();
  }

 private:
  void release() noexcept {
    clear();
    std::free(data_);
    data_ = nullptr;
    cap_ = 0;
  }

  T *data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t cap_ = 0;
};

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_BUFFER_HPP
