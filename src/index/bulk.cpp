// SPDX-License-Identifier: BSD-3-Clause
// insert_many() of many ellipsoids (index.hpp, bulk_min): the index that n
// calls of insert() would leave, in passes over the whole call, each on
// `threads` OpenMP threads, and the same for any count.
//
// What the loop of insert() decides, and how each pass finds it without
// depending on the schedule:
// - the status: that of the first item (in the call's order) that fails.
//   Pass 1 checks every item alone (the tests of insert(), an id in use
//   before the call counted as in use); a repeated id is found by an atomic
//   minimum of the item's position in its (free) slot of the id table
//   (pass 2); the first failure is the least position of either kind. An
//   allocation that fails reports PW85_ENOMEM when every item is valid.
// - a new level per new exponent, in the order of the first item of each
//   (a serial pass over one int per item: about 1 ms per 1e6 items);
// - a new cell per cell that no item finds, in the order of the first item
//   in each: the cells the call touches are keys of a temporary hash map
//   per level, in tables that one thread each fills in the order of the
//   items (a key's table set by its hash), with the first item and count
//   of each cell, and a new cell's position is the level's count of cells
//   plus the rank of its first item among the first items of new cells
//   (per chunk of items, then a prefix sum);
// - the entries of a cell in the order of the items: the items are
//   scattered to their cell's run of a list of positions (atomic cursors),
//   each run is sorted, and each cell is then filled from its run by one
//   thread.
// Largest bounds (hmax, cmax) are maxima: any order gives them. Every
// allocation is made before the index changes; on failure the index is as
// it was but for spare capacity and empty cells, as after insert().
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "batch.hpp"
#include "checks.hpp"
#include "index.hpp"

namespace pw85::detail::spatial {

namespace {

// Items (and slots of the maps) are handed to threads in chunks of this
// many; per-chunk results are combined in chunk order. A thread is
// started per bulk_per_thread items at most (each pass is a parallel
// region: on a loaded machine, a few milliseconds to gather the threads).
constexpr std::size_t bulk_chunk = 1024;
constexpr std::size_t bulk_per_thread = 4096;
// Items prefetched ahead of the one being handled (passes 6, 7).
constexpr std::size_t prefetch_ahead = 8;

// The range of exponents of frexp() on a positive finite double.
constexpr int min_exponent = -1073, max_exponent = 1024;
constexpr std::uint32_t none = 0xFFFFFFFFu;

// Runs f(k) for k in [0, count), on nt threads when nt > 1 (none started
// otherwise); the work of each k must not depend on the schedule.
template <typename F>
void for_each_chunk(int nt, std::size_t count, F &&f) noexcept {
#if defined(PW85_OPENMP)
  if (nt > 1 && count > 1) {
    long long const m = static_cast<long long>(count);
#pragma omp parallel for num_threads(nt) schedule(dynamic, 1)
    for (long long k = 0; k < m; ++k) f(std::size_t(k));
    return;
  }
#endif
  (void)nt;
  for (std::size_t k = 0; k < count; ++k) f(k);
}

// *p = min(*p, v), atomically.
void atomic_min(std::uint32_t *p, std::uint32_t v) noexcept {
  std::uint32_t old = __atomic_load_n(p, __ATOMIC_RELAXED);
  while (v < old && !__atomic_compare_exchange_n(p, &old, v, true, __ATOMIC_RELAXED,
                                                 __ATOMIC_RELAXED)) {
  }
}

// A cell that the call touches: its key (Level::pack of its coordinates),
// the first item in it, the number of items, its position in the level's
// cells (none until known), and the start of its run in the list of items
// by cell.
struct Touched {
  std::uint64_t key;
  std::uint32_t first;  // then the cursor of the scatter
  std::uint32_t count;
  std::uint32_t cell;
  std::uint32_t start;
};

// An insert-only hash map of the cells a level's items touch: open
// addressing, linear probing, in `parts` tables, each at most half full.
// A key belongs to the table of its hash's top bits (part_of()), and each
// table is filled by one thread, in the order of the items: no atomic
// operation, and no table written by two threads. (With a single table
// filled concurrently, an atomic count and minimum per item, pass 3 took
// longer on 2 threads than on 1, 118 to 135 against 96 ms for 10^6 items,
// the cache lines of its slots passing from core to core; 57 to 67 ms
// this way on 2 threads; bench-index first, timers not committed.)
class TouchedMap {
 public:
  static constexpr std::uint64_t empty = ~std::uint64_t{0};

  // parts tables (≥ 1), table p with room for keys[p] keys; false when an
  // allocation fails.
  bool init(std::size_t parts, std::size_t const *keys) noexcept {
    if (!start_.resize_uninitialised(parts + 1)) return false;
    start_[0] = 0;
    for (std::size_t p = 0; p < parts; ++p) {
      std::size_t n = keys[p] == 0 ? 0 : 16;
      while (n < 2 * keys[p]) n *= 2;
      start_[p + 1] = start_[p] + n;
    }
    if (!slots_.resize_uninitialised(start_[parts])) return false;
    for (std::size_t i = 0; i < slots_.size(); ++i)
      slots_[i] = Touched{empty, none, 0, none, 0};
    return true;
  }
  std::size_t size() const noexcept { return slots_.size(); }
  Touched &operator[](std::size_t i) noexcept { return slots_[i]; }

  // The table of a key, among `parts`.
  static std::size_t part_of(std::uint64_t key, std::size_t parts) noexcept {
    return static_cast<std::size_t>((((key * fibonacci) >> 44) * parts) >> 20);
  }
  // Adds item i to the cell of that key, in table p = part_of(key) (by
  // the thread that fills table p); returns the cell's slot.
  std::uint32_t add(std::size_t p, std::uint64_t key, std::uint32_t i) noexcept {
    std::size_t const base = start_[p], mask = start_[p + 1] - base - 1;
    for (std::size_t s = hash(key) & mask;; s = (s + 1) & mask) {
      Touched &t = slots_[base + s];
      if (t.key == empty) t.key = key, t.first = i;
      if (t.key == key) {
        ++t.count;
        return static_cast<std::uint32_t>(base + s);
      }
    }
  }

 private:
  static constexpr std::uint64_t fibonacci = 0x9E3779B97F4A7C15ull;
  // Fibonacci hashing, as CellMap's: bits 20 and up of the product (the
  // table's slot; part_of() maps bits 44 to 63 onto [0, parts), parts ≤
  // 1024, without a division; tables of 2^24 slots or more see them too).
  static std::size_t hash(std::uint64_t key) noexcept {
    return static_cast<std::size_t>((key * fibonacci) >> 20);
  }
  Buffer<Touched> slots_;
  Buffer<std::size_t> start_;  // table p: slots [start_[p], start_[p + 1])
};

// A cell that the call creates: its key and the count of its items.
struct NewCell {
  std::uint64_t key;
  std::size_t count;
};

// What a pass over a chunk of items found: its first failing item (n if
// none) and that item's status.
struct ChunkStatus {
  std::size_t at;
  Status status;
};

// The first failure over the chunks, in the order of the items.
ChunkStatus first_failure(Buffer<ChunkStatus> const &chunks, std::size_t n) noexcept {
  ChunkStatus first{n, Status::success};
  for (std::size_t k = 0; k < chunks.size(); ++k)
    if (chunks[k].at < first.at) first = chunks[k];
  return first;
}

}  // namespace

template <int D>
Status Index<D>::insert_bulk(std::size_t n, std::size_t const *ids,
                          double const *c, double const *q,
                          int threads) noexcept {
#if !defined(PW85_OPENMP)
  threads = 1;
#endif
  std::size_t const chunks = (n + bulk_chunk - 1) / bulk_chunk;
  int const nt = team_size(threads, n / bulk_per_thread + 1);
  auto items_of = [&](std::size_t k, std::size_t end) {
    return std::pair<std::size_t, std::size_t>{k * bulk_chunk,
                                               std::min(end, (k + 1) * bulk_chunk)};
  };

  // Pass 1: each item alone (insert()'s tests, in its order); its level's
  // exponent into `place` (then the level's position).
  Buffer<std::int32_t> place;  // per item
  Buffer<ChunkStatus> status;  // per chunk
  if (!place.resize_uninitialised(n) || !status.resize_uninitialised(chunks))
    return Status::no_memory;
  for_each_chunk(nt, chunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, n);
    status[k] = ChunkStatus{n, Status::success};
    for (std::size_t i = i0; i < i1; ++i) {
      double const *ci = c + D * i, *qi = q + S * i;
      Status s = check_ellipsoid(ci, qi);
      std::size_t const id = ids[i];
      double h[D];
      if (s == Status::success) {
        if (id > max_id || (id < slots_.size() && slots_[id].level >= 0)) {
          s = Status::invalid_argument;
        } else {
          half_widths<D>(qi, h);
          if (!fits_box(h)) s = Status::invalid_argument;
        }
      }
      if (s != Status::success) {
        status[k] = ChunkStatus{i, s};
        return;
      }
      place[i] = level_exponent<D>(h);
    }
  });
  ChunkStatus failed = first_failure(status, n);
  std::size_t const m = failed.at;  // items [0, m) are valid alone

  // Pass 2: a repeated id among items [0, m), in the free slots of the id
  // table (restored by fail() unless the insertion succeeds).
  std::size_t top = 0;
  for (std::size_t i = 0; i < m; ++i) top = std::max(top, ids[i]);
  if (m > 0 && top >= slots_.size() && !slots_.resize(top + 1))
    return Status::no_memory;
  std::size_t const mchunks = (m + bulk_chunk - 1) / bulk_chunk;
  for_each_chunk(nt, mchunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, m);
    for (std::size_t i = i0; i < i1; ++i)
      __atomic_store_n(&slots_[ids[i]].index, none, __ATOMIC_RELAXED);
  });
  for_each_chunk(nt, mchunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, m);
    for (std::size_t i = i0; i < i1; ++i)
      atomic_min(&slots_[ids[i]].index, std::uint32_t(i));
  });
  for_each_chunk(nt, mchunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, m);
    status[k] = ChunkStatus{n, Status::success};
    for (std::size_t i = i0; i < i1; ++i)
      if (slots_[ids[i]].index != i) {
        status[k] = ChunkStatus{i, Status::invalid_argument};
        return;
      }
  });
  for (std::size_t k = mchunks; k < chunks; ++k) status[k] = ChunkStatus{n, Status::success};
  ChunkStatus const repeated = first_failure(status, n);
  if (repeated.at < failed.at) failed = repeated;
  // Every failure from here on clears the marks, then returns its status.
  auto fail = [&](Status why) {
    for_each_chunk(nt, mchunks, [&](std::size_t k) {
      auto const [i0, i1] = items_of(k, m);
      for (std::size_t i = i0; i < i1; ++i) slots_[ids[i]] = Slot{};
    });
    return why;
  };
  if (failed.at < n) {
    return fail(failed.status);
  }

  // The levels, new ones in the order of their first item; the number of
  // items per level.
  Buffer<std::int32_t> level_at;  // by exponent − min_exponent
  Buffer<std::size_t> items_in;   // by level
  if (!level_at.resize_uninitialised(max_exponent - min_exponent + 1)) {
    return fail(Status::no_memory);
  }
  for (std::size_t e = 0; e < level_at.size(); ++e) level_at[e] = -1;
  for (std::size_t l = 0; l < levels_.size(); ++l)
    level_at[levels_[l].exponent - min_exponent] = std::int32_t(l);
  for (std::size_t i = 0; i < n; ++i) {
    std::int32_t &l = level_at[place[i] - min_exponent];
    if (l < 0) {
      if (!add_level(place[i])) {
        return fail(Status::no_memory);
      }
      l = std::int32_t(levels_.size() - 1);
    }
    place[i] = l;
  }
  std::size_t const nlevels = levels_.size();
  if (!items_in.resize(nlevels)) {
    return fail(Status::no_memory);
  }
  for (std::size_t i = 0; i < n; ++i) ++items_in[std::size_t(place[i])];

  // Pass 3: the cells touched, per level, with their first item and count:
  // the items' keys (in chunks), the number of items of each level in each
  // table of its map (a serial pass, which sizes the tables), then each
  // table filled by one thread, from the list of its items (a stable
  // counting sort by table: the work is n for any number of tables; each
  // thread reading every item for its own took n per table: at n = 2^21,
  // 3.6 to 4.3 s of CPU time on 513 threads, 1.7 to 2.1 s on 2). Which
  // thread fills which table changes no result: the passes below read the
  // maps per slot or per item, and the index they build does not depend
  // on the slots' order.
  std::size_t const parts = std::size_t(nt);
  Buffer<TouchedMap> maps;
  Buffer<std::uint32_t> slot_of;  // per item: its cell's slot in its map
  Buffer<std::uint64_t> key_of;   // per item: its cell's key
  Buffer<std::size_t> in_part;    // per level and table: items
  Buffer<std::size_t> part_end;   // per table: the end of its items in by_cell
  // Items by table (pass 3), then by cell (from pass 5).
  Buffer<std::uint32_t> by_cell;
  bool ok = maps.resize(nlevels) && slot_of.resize_uninitialised(n) &&
            key_of.resize_uninitialised(n) && in_part.resize(nlevels * parts) &&
            part_end.resize(parts) && by_cell.resize_uninitialised(n);
  if (!ok) {
    return fail(Status::no_memory);
  }
  for_each_chunk(nt, chunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, n);
    for (std::size_t i = i0; i < i1; ++i) {
      std::int32_t w[D];
      std::uint64_t u[D];
      wraps(c + D * i, w);
      cell_coords(levels_[std::size_t(place[i])], c + D * i, w, u);
      key_of[i] = Level<D>::pack(u);
    }
  });
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t const p = TouchedMap::part_of(key_of[i], parts);
    ++in_part[std::size_t(place[i]) * parts + p];
    ++part_end[p];
  }
  for (std::size_t p = 1; p < parts; ++p) part_end[p] += part_end[p - 1];
  for (std::size_t i = n; i-- > 0;)  // from the last: stable
    by_cell[--part_end[TouchedMap::part_of(key_of[i], parts)]] = std::uint32_t(i);
  for (std::size_t l = 0; ok && l < nlevels; ++l) {
    if (items_in[l] == 0) continue;
    if (periodic_) {  // no more keys than cells in a periodic box
      Level<D> const &lv = levels_[l];
      double cells = double(lv.n[0]);
      for (int k = 1; k < D; ++k) cells *= double(lv.n[k]);
      for (std::size_t p = 0; p < parts; ++p)
        in_part[l * parts + p] =
            std::size_t(std::min(double(in_part[l * parts + p]), cells));
    }
    ok = maps[l].init(parts, in_part.data() + l * parts);
  }
  if (!ok) {
    return fail(Status::no_memory);
  }
  // (Prefetching each table's slots 8 items ahead changed nothing
  // measurable when each thread read every item: 45 to 55 ms with it, 44
  // to 57 without, three runs each of bench-index first.)
  // part_end[p] is now the start of table p's items.
  for_each_chunk(nt, parts, [&](std::size_t p) {
    std::size_t const end = p + 1 < parts ? part_end[p + 1] : n;
    for (std::size_t k = part_end[p]; k < end; ++k) {
      std::size_t const i = by_cell[k];
      slot_of[i] = maps[std::size_t(place[i])].add(p, key_of[i], std::uint32_t(i));
    }
  });

  // Pass 4: the touched cells that exist, then the positions of the new
  // ones (ranks of their first items per level: counts per chunk and
  // level, then prefix sums from the level's count of cells).
  for (std::size_t l = 0; l < nlevels; ++l) {
    TouchedMap &map = maps[l];
    Level<D> const &lv = levels_[l];
    for_each_chunk(nt, (map.size() + bulk_chunk - 1) / bulk_chunk, [&](std::size_t k) {
      auto const [s0, s1] = items_of(k, map.size());
      for (std::size_t s = s0; s < s1; ++s) {
        std::uint64_t const key = map[s].key;
        if (key == TouchedMap::empty) continue;
        std::uint64_t u[D];
        Level<D>::unpack(key, u);
        map[s].cell = lv.find(u);
      }
    });
  }
  // Per chunk and level: the chunk's first rank, in rows of whole cache
  // lines (each row is written by the thread that runs its chunk).
  std::size_t const row = (nlevels + 7) & ~std::size_t(7);
  Buffer<std::size_t> rank;
  if (!rank.resize(chunks * row)) {
    return fail(Status::no_memory);
  }
  auto is_new_founder = [&](std::size_t i) {
    Touched const &t = maps[std::size_t(place[i])][slot_of[i]];
    return t.first == i && t.cell == CellMap::absent;
  };
  for_each_chunk(nt, chunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, n);
    for (std::size_t i = i0; i < i1; ++i)
      if (is_new_founder(i)) ++rank[k * row + std::size_t(place[i])];
  });
  Buffer<std::size_t> new_cells;  // per level
  if (!new_cells.resize(nlevels)) {
    return fail(Status::no_memory);
  }
  for (std::size_t l = 0; l < nlevels; ++l) {
    std::size_t at = levels_[l].cells.size();
    for (std::size_t k = 0; k < chunks; ++k) {
      std::size_t const count = rank[k * row + l];
      rank[k * row + l] = at;
      at += count;
    }
    new_cells[l] = at - levels_[l].cells.size();
    if (at >= no_id) return fail(Status::no_memory);  // as reserve_for()
  }
  // Per level, by new position: the key and the count of items of each
  // new cell.
  Buffer<Buffer<NewCell>> new_keys;
  ok = new_keys.resize(nlevels);
  for (std::size_t l = 0; ok && l < nlevels; ++l)
    ok = new_keys[l].resize_uninitialised(new_cells[l]) &&
         levels_[l].cells.reserve(levels_[l].cells.size() + new_cells[l]);
  if (!ok) {
    return fail(Status::no_memory);
  }
  for_each_chunk(nt, chunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, n);
    for (std::size_t i = i0; i < i1; ++i) {
      if (!is_new_founder(i)) continue;
      std::size_t const l = std::size_t(place[i]);
      std::size_t const p = rank[k * row + l]++;
      Touched &t = maps[l][slot_of[i]];
      new_keys[l][p - levels_[l].cells.size()] = NewCell{t.key, t.count};
      t.cell = std::uint32_t(p);  // read by is_new_founder() of this item only
    }
  });
  // is_new_founder() is false from here on.

  // The new cells, registered in order (as reserve_for() registers them).
  for (std::size_t l = 0; l < nlevels; ++l) {
    Level<D> &lv = levels_[l];
    for (std::size_t p = 0; p < new_cells[l]; ++p) {
      std::uint64_t const key = new_keys[l][p].key;
      if (lv.dense.empty() && !lv.map.reserve_one()) {
        return fail(Status::no_memory);
      }
      std::uint32_t const at = static_cast<std::uint32_t>(lv.cells.size());
      lv.cells.push_back_reserved(Cell<D>{});
      if (lv.dense.empty()) {
        lv.map.insert_reserved(key, at);
      } else {
        std::uint64_t u[D];
        Level<D>::unpack(key, u);
        lv.dense[lv.dense_index(u)] = at;
      }
    }
  }

  // Pass 5: room in every touched cell that existed before the call, and
  // the runs of the list of items by cell (prefix sums of the counts, in
  // the order of the maps' slots).
  std::size_t most = chunks;  // chunks of items or of a map's slots
  for (std::size_t l = 0; l < nlevels; ++l)
    most = std::max(most, (maps[l].size() + bulk_chunk - 1) / bulk_chunk);
  Buffer<double> bounds;  // per chunk of slots: max h_k, max |c_k|
  ok = bounds.resize_uninitialised((D + 1) * most) &&
       (most <= status.size() || status.resize_uninitialised(most));
  std::size_t at = 0;
  for (std::size_t l = 0; ok && l < nlevels; ++l) {
    TouchedMap &map = maps[l];
    for (std::size_t s = 0; s < map.size(); ++s) {
      if (map[s].key == TouchedMap::empty) continue;
      map[s].start = std::uint32_t(at);
      map[s].first = 0;
      at += map[s].count;
    }
  }
  for (std::size_t l = 0; ok && l < nlevels; ++l) {
    TouchedMap &map = maps[l];
    Level<D> &lv = levels_[l];
    std::size_t const first_new = lv.cells.size() - new_cells[l];
    std::size_t const mchunks_l = (map.size() + bulk_chunk - 1) / bulk_chunk;
    for_each_chunk(nt, mchunks_l, [&](std::size_t k) {
      auto const [s0, s1] = items_of(k, map.size());
      status[k] = ChunkStatus{n, Status::success};
      for (std::size_t s = s0; s < s1; ++s) {
        if (map[s].key == TouchedMap::empty) continue;
        if (map[s].cell >= first_new) continue;  // a part of the block, below
        Cell<D> &cell = lv.cells[map[s].cell];
        if (!cell.reserve(cell.size() + map[s].count)) {
          status[k] = ChunkStatus{s, Status::no_memory};
          return;
        }
      }
    });
    for (std::size_t k = 0; k < mchunks_l; ++k)
      if (status[k].status != Status::success) ok = false;
  }
  if (!ok) {
    return fail(Status::no_memory);
  }
  // The new cells' room: parts of one block (buffer.hpp, BlockList), in
  // the order of the cells, the call's last allocation.
  std::size_t entries = 0;
  for (std::size_t l = 0; l < nlevels; ++l)
    for (std::size_t p = 0; p < new_cells[l]; ++p) entries += new_keys[l][p].count;
  if (entries > 0) {
    if (entries > std::size_t(-1) / sizeof(Entry<D>)) return fail(Status::no_memory);
    void *const block = blocks_.allocate(entries * sizeof(Entry<D>));
    if (block == nullptr) return fail(Status::no_memory);
    Entry<D> *part = static_cast<Entry<D> *>(block);
    for (std::size_t l = 0; l < nlevels; ++l) {
      Buffer<Cell<D>> &cells = levels_[l].cells;
      std::size_t const first_new = cells.size() - new_cells[l];
      for (std::size_t p = 0; p < new_cells[l]; ++p) {
        std::size_t const count = new_keys[l][p].count;
        cells[first_new + p].borrow(part, count);
        part += count;
      }
    }
  }

  // Nothing fails from here on.

  // Pass 6: the items into their cells' runs, each run sorted.
  for_each_chunk(nt, chunks, [&](std::size_t k) {
    auto const [i0, i1] = items_of(k, n);
    for (std::size_t i = i0; i < i1; ++i) {
      if (i + prefetch_ahead < i1)
        PW85_PREFETCH(&maps[std::size_t(place[i + prefetch_ahead])][slot_of[i + prefetch_ahead]]);
      Touched &t = maps[std::size_t(place[i])][slot_of[i]];
      by_cell[t.start + __atomic_fetch_add(&t.first, 1u, __ATOMIC_RELAXED)] =
          std::uint32_t(i);
    }
  });

  // Pass 7: each touched cell filled from its run, in the items' order;
  // the ids' slots; the levels' bounds (maxima, in any order).
  for (std::size_t l = 0; l < nlevels; ++l) {
    TouchedMap &map = maps[l];
    Level<D> &lv = levels_[l];
    if (items_in[l] == 0) continue;
    std::size_t const mchunks_l = (map.size() + bulk_chunk - 1) / bulk_chunk;
    for_each_chunk(nt, mchunks_l, [&](std::size_t k) {
      auto const [s0, s1] = items_of(k, map.size());
      double b[D + 1] = {};  // max h_k, then max |c_k|
      for (std::size_t s = s0; s < s1; ++s) {
        Touched const &t = map[s];
        if (t.key == TouchedMap::empty) continue;
        std::uint32_t *run = by_cell.data() + t.start;
        std::sort(run, run + t.count);
        Cell<D> &cell = lv.cells[t.cell];
        for (std::uint32_t r = 0; r < t.count; ++r) {
          std::size_t const i = run[r];
          // The inputs of an item some way ahead in the list (the same
          // items, sorted per run or not yet): items in cell order are
          // scattered in the input arrays, each read a cache miss.
          std::size_t const ahead = by_cell[std::min<std::size_t>(t.start + r + prefetch_ahead, n - 1)];
          PW85_PREFETCH(c + D * ahead);
          PW85_PREFETCH(q + S * ahead);
          PW85_PREFETCH(q + S * ahead + S - 1);
          PW85_PREFETCH(ids + ahead);
          Entry<D> e;
          make_entry(ids[i], c + D * i, q + S * i, &e);
          for (int a = 0; a < D; ++a) {
            b[a] = std::max(b[a], e.h[a]);
            b[D] = std::max(b[D], std::fabs(e.c[a]));
          }
          cell.push_back_reserved(static_cast<Entry<D> &&>(e));
          slots_[ids[i]] = Slot{std::int32_t(l), t.cell,
                                static_cast<std::uint32_t>(cell.size() - 1)};
        }
      }
      for (int a = 0; a <= D; ++a) bounds[(D + 1) * k + a] = b[a];
    });
    for (std::size_t k = 0; k < mchunks_l; ++k) {
      for (int a = 0; a < D; ++a)
        lv.hmax[a] = std::max(lv.hmax[a], bounds[(D + 1) * k + a]);
      cmax_ = std::max(cmax_, bounds[(D + 1) * k + D]);
    }
    lv.count += items_in[l];
    count_ += items_in[l];
  }
  return Status::success;
}

template Status Index<2>::insert_bulk(std::size_t, std::size_t const *,
                                      double const *, double const *,
                                      int) noexcept;
template Status Index<3>::insert_bulk(std::size_t, std::size_t const *,
                                      double const *, double const *,
                                      int) noexcept;

}  // namespace pw85::detail::spatial
