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
//
// Dimension: written once for D = 3 (ellipsoids, pw85_index.h) and D = 2
// (ellipses in a plane or a periodic rectangle, pw85_2d_index.h), every
// type and function of namespace spatial a template on D; "3 axes",
// "ellipsoid" below read "D axes", "ellipse" in 2D.
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

// Where an id is stored: level −1 when absent.
struct Slot {
  std::int32_t level = -1;
  std::uint32_t cell = 0;
  std::uint32_t index = 0;
};

// ⌊a / b⌋ for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  std::int64_t const d = a / b;
  return (a % b != 0 && a < 0) ? d - 1 : d;
}

namespace spatial {

// A stored ellipsoid, as its cell holds it. What the broad phase reads
// (id, wrap, centre, half-widths) fills the first cache line; the form,
// read by the narrow phase only, the second.
template <int D>
struct alignas(64) Entry {
  std::uint32_t id;
  std::int32_t wrap[D];      // ⌊c_k/L_k⌋ (periodic), else 0
  double c[D];               // centre, as given
  double h[D];               // AABB half-widths √Q_kk
  double q[sym_size(D)];     // quadratic form
  double rho;                // inscribed_radius(q)
};

template <int D>
using Cell = Buffer<Entry<D>>;

// Cell coordinates are packed into a key of cell_bits bits per axis
// (coordinates below 2²¹: margins.hpp, max_span and open_half), axis 0
// in the highest bits.
constexpr int cell_bits = 21;
constexpr std::uint64_t cell_mask = (std::uint64_t{1} << cell_bits) - 1;

template <int D>
struct Level {
  int exponent = 0;       // H ≤ 2^exponent
  double side[D] = {};    // cell sides
  double inv[D] = {};     // 1/side, as n_k/L_k (periodic) or 2^−exponent
  std::int64_t n[D] = {};  // periodic: cells per axis; open: 0
  double hmax[D] = {};    // ≥ every h_k of the level (reset when emptied)
  std::size_t count = 0;
  CellMap map;
  Buffer<Cell<D>> cells;
  // A periodic level of at most dense_cells cells finds them in a dense
  // array instead of the hash map: the position in `cells` of the cell of
  // coordinates u (row-major, in 3D (u0·n1 + u1)·n2 + u2), or
  // CellMap::absent. A row of cells along the last axis is then one cache
  // line or two (random sequential addition visits ~100 cells per attempt;
  // each probe of the hash map was a cache miss).
  Buffer<std::uint32_t> dense;

  static std::uint64_t pack(std::uint64_t const u[D]) noexcept {
    std::uint64_t key = u[0];
    for (int k = 1; k < D; ++k) key = (key << cell_bits) | u[k];
    return key;
  }
  static void unpack(std::uint64_t key, std::uint64_t u[D]) noexcept {
    for (int k = D - 1; k >= 0; --k, key >>= cell_bits) u[k] = key & cell_mask;
  }
  std::size_t dense_index(std::uint64_t const u[D]) const noexcept {
    std::uint64_t i = u[0];
    for (int k = 1; k < D; ++k) i = i * std::uint64_t(n[k]) + u[k];
    return static_cast<std::size_t>(i);
  }
  // The position of the cell of coordinates u in `cells`, or absent.
  std::uint32_t find(std::uint64_t const u[D]) const noexcept {
    return dense.empty() ? map.find(pack(u)) : dense[dense_index(u)];
  }
};

// A result of a query on a candidate: a stored ellipsoid's image.
template <int D>
struct Hit {
  std::uint32_t id;
  std::int32_t shift[D];
  double mu2, lambda;
};

// A result of an all-pairs query: (i, j, n), i ≤ j; result (overlap
// mode: −1 or 0) or μ² and λ (μ² < t).
template <int D>
struct PairHit {
  std::uint32_t i, j;
  std::int32_t shift[D];
  int result;
  double mu2, lambda;
};
static_assert(sizeof(PairHit<3>) == 40 && sizeof(PairHit<2>) == 40,
              "pw85_index_energy()'s and pw85_2d_index_energy()'s memory "
              "figures");

// A result of the overlapping-pairs query alone, (i, j, n) and the
// result: PairHit without μ² and λ, which that query does not compute.
// Its pairs are held twice during the query (the threads' lists and the
// merged output): 48 bytes a pair in 3D instead of 80.
template <int D>
struct OverlapPair {
  std::uint32_t i, j;
  std::int32_t shift[D];
  int result;
};
static_assert(sizeof(OverlapPair<3>) == 24 && sizeof(OverlapPair<2>) == 20,
              "pw85_index.h's and pw85_2d_index.h's memory figures");

// The index in D = 2 or 3 dimensions: its members are defined in
// index.cpp, queries.cpp, pairs.cpp and bulk.cpp, and each is
// instantiated there for both.
template <int D>
class Index {
 public:
  static constexpr int S = sym_size(D);

  // box: nullptr (open) or D sides, finite and > 0 (checked by the
  // caller).
  explicit Index(double const *box) noexcept;

  bool periodic() const noexcept { return periodic_; }
  std::size_t count() const noexcept { return count_; }
  // The id table's size: every stored id is below it.
  std::size_t id_bound() const noexcept { return slots_.size(); }

  // The statuses of pw85_index.h; pointers are checked by the caller.
  // Centres are D doubles, forms S.
  Status insert(std::size_t id, double const *c, double const *q) noexcept;
  // As n calls of insert(), in order, all or none; on `threads` OpenMP
  // threads (≥ 1, checked by the caller) for n ≥ bulk_min (bulk.cpp),
  // with the same resulting index for any count.
  Status insert_many(std::size_t n, std::size_t const *ids,
                     double const *c, double const *q,
                     int threads = 1) noexcept;
  Status update(std::size_t id, double const *c, double const *q) noexcept;
  Status remove(std::size_t id) noexcept;
  Status get(std::size_t id, double *c, double *q) const noexcept;

  Status overlap_any(double const *c, double const *q, std::size_t exclude,
                     int *result, std::size_t *id) const noexcept;
  // Hits sorted by (id, shift).
  Status within(double const *c, double const *q, double t,
                std::size_t exclude, Buffer<Hit<D>> *hits) const noexcept;
  // Pairs sorted by (i, j, shift). within = false: overlap mode (t = 1,
  // pw85_overlap's decision); true: μ² < t. candidates, if not null,
  // receives the number of pairs that passed the broad phase.
  Status pairs(bool within, double t, int threads, Buffer<PairHit<D>> *out,
               std::size_t *candidates) const noexcept;
  // The pairs of pairs(false, 1, ...) in the smaller record.
  Status overlapping_pairs(int threads, Buffer<OverlapPair<D>> *out,
                           std::size_t *candidates) const noexcept;

  // For pairs.cpp.
  double const *box() const noexcept { return box_; }
  // Where id is stored (for the tests of the core).
  Slot slot(std::size_t id) const noexcept {
    return id < slots_.size() ? slots_[id] : Slot{};
  }
  Buffer<Level<D>> const &levels() const noexcept { return levels_; }
  double coordinate_bound() const noexcept { return cmax_; }

 private:
  // pairs() and overlapping_pairs(), for either record (pairs.cpp).
  template <class H>
  Status pairs_into(bool within, double t, int threads, Buffer<H> *out,
                    std::size_t *candidates) const noexcept;
  Status check_ellipsoid(double const *c, double const *q) const noexcept;
  Status check_centre(double const *c) const noexcept;
  // The side rule of a periodic box: 2·h_k·(1 + broad_margin) < L_k.
  bool fits_box(double const *h) const noexcept;
  // Fills *e, the entry of an ellipsoid; returns the exponent of its
  // level (H ≤ 2^exponent).
  int make_entry(std::size_t id, double const *c, double const *q,
                 Entry<D> *e) const noexcept;
  // The position in levels_ of the level of that exponent, or
  // levels_.size() when there is none yet.
  int level_of(int exponent) const noexcept;
  // ⌊c_k/L_k⌋ (periodic), else 0: Entry::wrap.
  void wraps(double const *c, std::int32_t *w) const noexcept;
  void cell_coords(Level<D> const &lv, double const *c,
                   std::int32_t const *wrap, std::uint64_t *u) const noexcept;
  // insert_many() of n ≥ bulk_min ellipsoids (bulk.cpp).
  Status insert_bulk(std::size_t n, std::size_t const *ids, double const *c,
                     double const *q, int threads) noexcept;
  // Every allocation insert_entry(e, exponent) needs; false on failure
  // (the index is unchanged but for spare capacity, or an empty new
  // level).
  bool reserve_for(Entry<D> const &e, int exponent) noexcept;
  void insert_entry(Entry<D> const &e, int exponent) noexcept;  // after reserve_for()
  // A new level of that exponent, with its dense array of cells when
  // small enough; false on failure.
  bool add_level(int exponent) noexcept;
  void erase(std::size_t id) noexcept;
  void init_level(Level<D> *lv, int exponent) const noexcept;

  // The broad phase of the queries on a candidate (broad.hpp): calls
  // f(entry, shift, r, slack_sum) for every image of every stored
  // ellipsoid but `exclude` that passes the box test against the
  // candidate (centre c, half-widths h, scaled by √t): r is r̂ of the box
  // test, slack_sum its Σσ_k; f makes the rest of the tests and returns
  // false to stop. Returns Status::out_of_range when the reach spans too
  // many images (max_span). With nearest_first, the cells nearest to c
  // are visited before the others (for a query that stops early).
  template <typename F>
  Status visit(double const *c, double const *h, double sqrt_t,
               std::uint32_t exclude, bool nearest_first, F &&f) const
      noexcept;
  template <typename F>
  Status visit_level(Level<D> const &lv, double const *c, double const *h,
                     double sqrt_t, std::uint32_t exclude,
                     bool nearest_first, bool *go_on, F &f) const noexcept;
  // A level wider than the reach: every entry, with its shifts in reach
  // (nearest_first: first each entry's image nearest to c, which is then
  // visited twice).
  template <typename Test>
  Status visit_every_entry(Level<D> const &lv, double const *c,
                           Reach<D> const &rc, std::uint32_t exclude,
                           bool nearest_first, bool *go_on,
                           Test &test) const noexcept;

  bool periodic_;
  double box_[D] = {};
  double cmax_ = 0.0;  // ≥ every |c_k| ever stored (for rounding margins)
  std::size_t count_ = 0;
  Buffer<Slot> slots_;  // by id
  // The blocks of the cells that insert_many() created (bulk.cpp), freed
  // with the index, after the levels (members are destroyed in reverse).
  BlockList blocks_;
  Buffer<Level<D>> levels_;
};

// The exponent e of the level of an ellipsoid of AABB half-widths h:
// H = max_k h_k ≤ 2^e (index.hpp, "Grid").
template <int D>
inline int level_exponent(double const *h) noexcept {
  double m = h[0];
  for (int k = 1; k < D; ++k) m = std::max(m, h[k]);
  int exponent = 0;
  std::frexp(m, &exponent);
  return exponent;
}

}  // namespace spatial

// The 3D index, as the rest of the core names it (energy, packer).
using Index = spatial::Index<3>;
using Entry = spatial::Entry<3>;
using Cell = spatial::Cell<3>;
using Level = spatial::Level<3>;
using Hit = spatial::Hit<3>;
using PairHit = spatial::PairHit<3>;
using OverlapPair = spatial::OverlapPair<3>;
using ImageVector = spatial::ImageVector<3>;

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_INDEX_HPP
