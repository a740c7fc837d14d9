// SPDX-License-Identifier: BSD-3-Clause
// The spatial index of ellipsoids (private; include/pw85/pw85_index.h is
// its contract, docs/index.rst its account).
//
// Broad phase: the axis-aligned bounding box (AABB) of {x : xᵀQ⁻¹x ≤ 1}
// has half-widths h_k = √Q_kk exactly, and that of the ellipsoid scaled by
// √t half-widths √t·h_k; two scaled ellipsoids that meet have meeting
// AABBs, so |r_k| > √t·(h_k + h'_k) for some k proves μ² > t. The test
// below inflates the bound by 1 + 2⁻²⁰ (broad_margin), far more than its
// few roundings: a pair it discards has μ² > t·(1 + 2⁻²⁰), outside any
// rounding band of the narrow phase. Pairs whose AABBs meet are then
// tested along the line of centres (separated_along_r()), with the same
// margin.
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

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "buffer.hpp"
#include "cell_map.hpp"
#include "status.hpp"
#include "sym3.hpp"

// A hint that *p will be read soon (no effect on results).
#if defined(__GNUC__)
#define PW85_INDEX_PREFETCH(p) __builtin_prefetch(p)
#else
#define PW85_INDEX_PREFETCH(p) ((void)0)
#endif

namespace pw85::detail {

// The AABB test's inflation (see above).
constexpr double broad_margin = 0x1p-20;
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
// The side rule of a periodic box: 2·h_k·(1 + broad_margin) < L_k.
// Centres: |c_k| ≤ max_wraps·L_k, so that wraps and shifts fit an int32.
constexpr double max_wraps = 0x1p29;
// The most cells (or image shifts) a query visits along an axis.
constexpr double max_span = 0x1p20;
// Ids fit 32 bits; 0xFFFFFFFF is no id.
constexpr std::uint32_t no_id = 0xFFFFFFFFu;
constexpr std::size_t max_id = 0xFFFFFFFEu;

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

// The most cells of a dense level (16 MiB of positions).
constexpr double dense_cells = 0x1p22;

// A result of a query on a candidate: a stored ellipsoid's image.
struct Hit {
  std::uint32_t id;
  std::int32_t shift[dim];
  int result;  // overlap queries
  double mu2, lambda;  // within queries
};

// A result of an all-pairs query: (i, j, n), i ≤ j.
struct PairHit {
  std::uint32_t i, j;
  std::int32_t shift[dim];
  int result;
  double mu2, lambda;
};

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
  Status insert_many(std::size_t n, std::size_t const *ids,
                     double const *c, double const *q) noexcept;
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
  Buffer<Level> const &levels() const noexcept { return levels_; }
  double coordinate_bound() const noexcept { return cmax_; }

 private:
  Status check_ellipsoid(double const c[dim], double const q[sym]) const
      noexcept;
  Status check_centre(double const c[dim]) const noexcept;
  // The entry of an ellipsoid, its level's exponent and cell key.
  void make_entry(std::size_t id, double const c[dim], double const q[sym],
                  Entry *e) const noexcept;
  // Where insert_entry() would put e: the level (maybe levels_.size(),
  // a new one) and the cell key.
  int level_of(Entry const &e) const noexcept;
  void cell_coords(Level const &lv, Entry const &e, std::uint64_t u[dim]) const
      noexcept;
  // Every allocation insert_entry(e) needs; false on failure (the index
  // is unchanged but for spare capacity, or an empty new level).
  bool reserve_for(Entry const &e) noexcept;
  void insert_entry(Entry const &e) noexcept;  // after reserve_for()
  void erase(std::size_t id) noexcept;
  void init_level(Level *lv, int exponent) const noexcept;

  // Calls f(entry, shift, r) for every image of every stored ellipsoid
  // but `exclude` whose AABB, scaled by √t, meets the candidate's (centre
  // c, half-widths h) inflated by broad_margin (r: the vector to it, as
  // pw85_index.h defines it; f makes the rest of the tests); stops when f
  // returns false. Returns Status::out_of_range when the reach spans too many
  // cells or images (max_span). With nearest_first, the cells nearest to
  // c are visited before the others (for a query that stops early).
  template <typename F>
  Status visit(double const c[dim], double const h[dim], double sqrt_t,
               std::uint32_t exclude, bool nearest_first, F &&f) const
      noexcept;
  template <typename F>
  Status visit_level(Level const &lv, double const c[dim],
                     double const h[dim], double sqrt_t,
                     std::uint32_t exclude, bool nearest_first, bool *go_on,
                     F &f) const noexcept;

  bool periodic_;
  double box_[dim] = {};
  double cmax_ = 0.0;  // ≥ every |c_k| ever stored (for rounding margins)
  std::size_t count_ = 0;
  Buffer<Slot> slots_;  // by id
  Buffer<Level> levels_;
};

// The AABB half-widths of q, and whether every entry is finite and q
// positive definite (the rule of pw85.h).
void half_widths(double const q[sym], double h[dim]) noexcept;

// The second test of the broad phase, for pairs whose AABBs meet: are the
// projections of the two ellipsoids scaled by √t on the line of centres
// disjoint? The projection of {x : xᵀQ⁻¹x ≤ 1} on a unit vector u has
// half-width √(uᵀQu); with u = r/|r|, a plane normal to r separates the
// scaled ellipsoids when |r|² > √t·(√(rᵀQ1r) + √(rᵀQ2r)), and then μ² > t.
// Each rᵀQr is computed with an error below 2⁻⁴⁰·(Σ_k h_k·|r_k|)² (h_k =
// √Q_kk bounds |Q_ij| by h_i·h_j), added to it, and the test carries
// broad_margin as the AABB test does: true means μ² > t·(1 + 2⁻²⁰).
inline bool separated_along_r(double const r[dim], double const q1[sym],
                              double const h1[dim], double const q2[sym],
                              double const h2[dim], double sqrt_t) noexcept {
  double y[dim];
  sym_mul(q1, r, y);
  double const a1 = dot(r, y);
  sym_mul(q2, r, y);
  double const a2 = dot(r, y);
  double b1 = 0.0, b2 = 0.0;
  for (int k = 0; k < dim; ++k) {
    double const x = r[k] < 0 ? -r[k] : r[k];
    b1 += h1[k] * x;
    b2 += h2[k] * x;
  }
  double const reach = std::sqrt(a1 + 0x1p-40 * b1 * b1) +
                       std::sqrt(a2 + 0x1p-40 * b2 * b2);
  return dot(r, r) > sqrt_t * reach * (1.0 + broad_margin);
}

// A radius ρ ≥ 0 of a ball about the centre inside the ellipsoid
// {x : xᵀQ⁻¹x ≤ 1}: ρ² < λmin(Q), certified (0 when not found; always 0
// unless every Q_kk is in [2⁻³⁰⁰, 2³⁰⁰], so that nothing below over- or
// underflows and two forms with ρ > 0 are within the range that
// pw85_overlap() accepts). An estimate s₀ of λmin(Q) (index.cpp) is
// checked: the Cholesky factorisation of Q − s·I, s = s₀ + 2⁻⁴⁶·M
// (M = max Q_kk), completes only if Q − s·I + E is positive definite for
// some ‖E‖₂ ≤ 3·γ₄·M + 2⁻⁵³·M < 2⁻⁴⁸·M (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., th. 10.3, and the rounding of the
// diagonal), so that λmin(Q) > s₀. Within 2⁻¹⁷ of √λmin(Q) for forms of
// moderate condition.
double inscribed_radius(double const q[sym]) noexcept;

// ⌊a / b⌋ for b > 0.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  std::int64_t const d = a / b;
  return (a % b != 0 && a < 0) ? d - 1 : d;
}

// The absolute rounding margin of the cell arithmetic along an axis: the
// roundings of the wrap, of the products by 1/side and of c ± reach are
// each below 2⁻⁵⁰ of these magnitudes.
inline double cell_slack(double cmax, double c, double reach,
                         double box) noexcept {
  return 0x1p-40 * (cmax + (c < 0 ? -c : c) + reach + box);
}

}  // namespace pw85::detail

#endif  // PW85_SRC_INDEX_INDEX_HPP
