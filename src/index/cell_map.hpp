// SPDX-License-Identifier: BSD-3-Clause
// An open-addressing hash map from a cell's packed coordinates to the
// position of the cell in its level (private). Linear probing in a table
// of a power-of-two size, at most half full; keys are never removed (an
// emptied cell stays, ready for the next ellipsoid).
#ifndef PW85_SRC_INDEX_CELL_MAP_HPP
#define PW85_SRC_INDEX_CELL_MAP_HPP

#include <cstdint>

#include "buffer.hpp"

namespace pw85::detail {

class CellMap {
 public:
  static constexpr std::uint32_t absent = 0xFFFFFFFFu;

  // The value of key, or absent.
  std::uint32_t find(std::uint64_t key) const noexcept {
    if (slots_.empty()) return absent;
    std::size_t const mask = slots_.size() - 1;
    for (std::size_t i = hash(key) & mask;; i = (i + 1) & mask) {
      Slot const &s = slots_[i];
      if (s.key == key) return s.value;
      if (s.key == empty) return absent;
    }
  }
  // Room for one more key; false (nothing changed) when the allocation
  // fails.
  [[nodiscard]] bool reserve_one() noexcept {
    if (2 * (used_ + 1) <= slots_.size()) return true;
    Buffer<Slot> bigger;
    std::size_t const n = slots_.empty() ? 16 : 2 * slots_.size();
    if (!bigger.reserve(n)) return false;
    for (std::size_t i = 0; i < n; ++i) bigger.push_back_reserved(Slot{});
    std::size_t const mask = n - 1;
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      Slot const &s = slots_[k];
      if (s.key == empty) continue;
      std::size_t i = hash(s.key) & mask;
      while (bigger[i].key != empty) i = (i + 1) & mask;
      bigger[i] = s;
    }
    slots_ = static_cast<Buffer<Slot> &&>(bigger);
    return true;
  }
  // After reserve_one(), for a key not present: cannot fail.
  void insert_reserved(std::uint64_t key, std::uint32_t value) noexcept {
    std::size_t const mask = slots_.size() - 1;
    std::size_t i = hash(key) & mask;
    while (slots_[i].key != empty) i = (i + 1) & mask;
    slots_[i] = Slot{key, value};
    ++used_;
  }

 private:
  static constexpr std::uint64_t empty = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t key = empty;
    std::uint32_t value = 0;
  };
  // Fibonacci hashing of the 63-bit key (the high bits mix best).
  static std::size_t hash(std::uint64_t key) noexcept {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 20);
  }

  Buffer<Slot> slots_;
  std::size_t used_ = 0;
};

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_CELL_MAP_HPP
