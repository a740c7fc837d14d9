// SPDX-License-Identifier: BSD-3-Clause
// The spatial index of ellipsoids (private; include/pw85/pw85_index.h is
// its contract, docs/assemblies.rst its account). Its broad phase, shared
// by every query: broad.hpp; its margins and limits: margins.hpp.
//
// Grid: ellipsoids are sorted into levels by the largest half-width of
// their AABB, H = max_k h_k; level e holds those with 2^(e−1) < H ≤ 2^e
// (polydisperse sizes cost one level per octave), in cells of side about
// 2^e (periodic: L_k/n_k ≥ that side). A query visits, in each level, the cells
// within its reach, √t·(its h + the level's largest h) per axis. Cells are
// found through a hash map of their packed coordinates (cell_map.hpp), so
// that an open domain needs no bounds; the all-pairs queries (pairs.cpp)
// work on a dense snapshot instead.
//
// Periodic box: a cell index m along axis k, unwrapped, is the cell
// m mod n_k of the copy ⌊m / n_k⌋ of the box; an ellipsoid of centre c
// lies in the copy w = ⌊c/L⌋ (its wrap), so the copy p of a cell holds
// the image shift p − w. Cells are visited over the unwrapped range, so
// every image in reach is found, however many.
#ifndef PW85_SRC_INDEX_INDEX_HPP
#define PW85_SRC_INDEX_INDEX_HPP

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "broad.hpp"
#include "buffer.hpp"
#include "cell_map.hpp"
#include "margins.hpp"
#include "status.hpp"
#include "sym.hpp"

namespace pw85::detail {

// The cells of a level's grid are 2^hash_cell_octaves times 2^e, and
// those of the all-pairs snapshot 2^snapshot_cell_octaves times 2^e:
// larger cells, fewer to visit, more ellipsoids tested in each. Measured
// on random sequential addition of 1e5 ellipsoids (1 : 0.8 : 0.6 to 0.3,
// 1 : 0.5 : 0.2 to 0.2 and 0.25) with the dense cell array and batched
// prefetches: one octave above 2^e took 1.4 µs per attempt, against 3.2 µs
// at 2^e (the rows of cells, each a cache miss, dominated) and about the
// same at two octaves (more entries tested per cell); the all-pairs
// snapshot is best at 2^e (1 : 0.5 : 0.2 at packing fractions 0.2 to 0.4).
constexpr int hash_cell_octaves = 1;
constexpr int snapshot_cell_octaves = 0;

// insert_many() of at least this many ellipsoids takes the bulk path
// (bulk.cpp: passes over the whole call, on threads), fewer the loop of
// insert(); both leave the same index (but for spare capacity).
constexpr std::size_t bulk_min = 1024;

// A stored ellipsoid, as its cell holds it. What the broad phase reads
// (id, wrap, centre, half-widths) fills the first cache line; the form,
// read by the narrow phase only, the second.
struct alignas(64) Entry {
  std::uint32_t id;
  std::int32_t wrap[dim];  // ⌊c_k/L_k⌋ (periodic), else 0
  double c[dim];           // centre, as given
  double h[dim];           // AABB half-widths √Q_kk
  double q[sym];           // quadratic form
  double rho;              // inscribed_radius(q)
};

// Where an id is stored: level −1 when absent.
struct Slot {
  std::int32_t level = -1;
  std::uint32_t cell = 0;
  std::uint32_t index = 0;
};

using Cell = Buffer<Entry>;

struct Level {
  int exponent = 0;       // H ≤ 2^exponent
  double side[dim] = {};  // cell sides
  double inv[dim] = {};   // 1/side, as n_k/L_k (periodic) or 2^−exponent
  std::int64_t n[dim] = {};  // periodic: cells per axis; open: 0
  double hmax[dim] = {};  // ≥ every h_k of the level (reset when emptied)
  std::size_t count = 0;
  CellMap map;
  Buffer<Cell> cells;
  // A periodic level of at most dense_cells cells finds them in a dense
  // array instead of the hash map: the position in `cells` of the cell of
  // coordinates u (row-major, (u0·n1 + u1)·n2 + u2), or CellMap::absent.
  // A row of cells along axis 2 is then one cache line or two (random
  // sequential addition visits ~100 cells per attempt; each probe of the
  // hash map was a cache miss).
  Buffer<std::uint32_t> dense;

  static std::uint64_t pack(std::uint64_t const u[dim]) noexcept {
    return (u[0] << 42) | (u[1] << 21) | u[2];
  }
  std::size_t dense_index(std::uint64_t const u[dim]) const noexcept {
    return static_cast<std::size_t>((u[0] * std::uint64_t(n[1]) + u[1]) *
                                        std::uint64_t(n[2]) + u[2]);
  }
  // The position of the cell of coordinates u in `cells`, or absent.
  std::uint32_t find(std::uint64_t const u[dim]) const noexcept {
    return dense.empty() ? map.find(pack(u)) : dense[dense_index(u)];
  }
};

// A result of a query on a candidate: a stored ellipsoid's image.
struct Hit {
  std::uint32_t id;
  std::int32_t shift[dim];
  double mu2, lambda;
};

// A result of an all-pairs query: (i, j, n), i ≤ j; result (overlap
// mode: −1 or 0) or μ² and λ (μ² < t).
struct PairHit {
  std::uint32_t i, j;
  std::int32_t shift[dim];
  int result;
  double mu2, lambda;
};
static_assert(sizeof(PairHit) == 40, "pw85_index_energy()'s memory figure");

class Index {
 public:
  // box: nullptr (open) or three sides, finite and > 0 (checked by the
  // caller).
  explicit Index(double const box[dim]) noexcept;

  bool periodic() const noexcept { return periodic_; }
  std::size_t count() const noexcept { return count_; }
  // The id table's size: every stored id is below it.
  std::size_t id_bound() const noexcept { return slots_.size(); }

  // The statuses of pw85_index.h; pointers are checked by the caller.
  Status insert(std::size_t id, double const c[dim],
                double const q[sym]) noexcept;
  // As n calls of insert(), in order, all or none; on `threads` OpenMP
  // threads (≥ 1, checked by the caller) for n ≥ bulk_min (bulk.cpp),
  // with the same resulting index for any count.
  Status insert_many(std::size_t n, std::size_t const *ids,
                     double const *c, double const *q,
                     int threads = 1) noexcept;
  Status update(std::size_t id, double const c[dim],
                double const q[sym]) noexcept;
  Status remove(std::size_t id) noexcept;
  Status get(std::size_t id, double c[dim], double q[sym]) const noexcept;

  Status overlap_any(double const c[dim], double const q[sym],
                     std::size_t exclude, int *result,
                     std::size_t *id) const noexcept;
  // Hits sorted by (id, shift).
  Status within(double const c[dim], double const q[sym], double t,
                std::size_t exclude, Buffer<Hit> *hits) const noexcept;
  // Pairs sorted by (i, j, shift). within = false: overlap mode (t = 1,
  // pw85_overlap's decision); true: μ² < t. candidates, if not null,
  // receives the number of pairs that passed the broad phase.
  Status pairs(bool within, double t, int threads, Buffer<PairHit> *out,
               std::size_t *candidates) const noexcept;

  // For pairs.cpp.
  double const *box() const noexcept { return box_; }
  // Where id is stored (for the tests of the core).
  Slot slot(std::size_t id) const noexcept {
    return id < slots_.size() ? slots_[id] : Slot{};
  }
  Buffer<Level> const &levels() const noexcept { return levels_; }
  double coordinate_bound() const noexcept { return cmax_; }

 private:
  Status check_ellipsoid(double const c[dim], double const q[sym]) const
      noexcept;
  Status check_centre(double const c[dim]) const noexcept;
  // The side rule of a periodic box: 2·h_k·(1 + broad_margin) < L_k.
  bool fits_box(double const h[dim]) const noexcept;
  // Fills *e, the entry of an ellipsoid; returns the exponent of its
  // level (H ≤ 2^exponent).
  int make_entry(std::size_t id, double const c[dim], double const q[sym],
                 Entry *e) const noexcept;
  // The position in levels_ of the level of that exponent, or
  // levels_.size() when there is none yet.
  int level_of(int exponent) const noexcept;
  // ⌊c_k/L_k⌋ (periodic), else 0: Entry::wrap.
  void wraps(double const c[dim], std::int32_t w[dim]) const noexcept;
  void cell_coords(Level const &lv, double const c[dim],
                   std::int32_t const wrap[dim], std::uint64_t u[dim]) const
      noexcept;
  // insert_many() of n ≥ bulk_min ellipsoids (bulk.cpp).
  Status insert_bulk(std::size_t n, std::size_t const *ids, double const *c,
                     double const *q, int threads) noexcept;
  // Every allocation insert_entry(e, exponent) needs; false on failure
  // (the index is unchanged but for spare capacity, or an empty new
  // level).
  bool reserve_for(Entry const &e, int exponent) noexcept;
  void insert_entry(Entry const &e, int exponent) noexcept;  // after reserve_for()
  // A new level of that exponent, with its dense array of cells when
  // small enough; false on failure.
  bool add_level(int exponent) noexcept;
  void erase(std::size_t id) noexcept;
  void init_level(Level *lv, int exponent) const noexcept;

  // The broad phase of the queries on a candidate (broad.hpp): calls
  // f(entry, shift, r, slack_sum) for every image of every stored
  // ellipsoid but `exclude` that passes the box test against the
  // candidate (centre c, half-widths h, scaled by √t): r is r̂ of the box
  // test, slack_sum its Σσ_k; f makes the rest of the tests and returns
  // false to stop. Returns Status::out_of_range when the reach spans too
  // many images (max_span). With nearest_first, the cells nearest to c
  // are visited before the others (for a query that stops early).
  template <typename F>
  Status visit(double const c[dim], double const h[dim], double sqrt_t,
               std::uint32_t exclude, bool nearest_first, F &&f) const
      noexcept;
  template <typename F>
  Status visit_level(Level const &lv, double const c[dim],
                     double const h[dim], double sqrt_t,
                     std::uint32_t exclude, bool nearest_first, bool *go_on,
                     F &f) const noexcept;
  // A level wider than the reach: every entry, with its shifts in reach.
  template <typename Test>
  Status visit_every_entry(Level const &lv, double const c[dim],
                           Reach const &rc, std::uint32_t exclude,
                           bool *go_on, Test &test) const noexcept;

  bool periodic_;
  double box_[dim] = {};
  double cmax_ = 0.0;  // ≥ every |c_k| ever stored (for rounding margins)
  std::size_t count_ = 0;
  Buffer<Slot> slots_;  // by id
  Buffer<Level> levels_;
};

// The exponent e of the level of an ellipsoid of AABB half-widths h:
// H = max_k h_k ≤ 2^e (index.hpp, "Grid").
inline int level_exponent(double const h[dim]) noexcept {
  int exponent = 0;
  std::frexp(std::max(std::max(h[0], h[1]), h[2]), &exponent);
  return exponent;
}

// ⌊a / b⌋ for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  std::int64_t const d = a / b;
  return (a % b != 0 && a < 0) ? d - 1 : d;
}

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_INDEX_HPP
