// SPDX-License-Identifier: BSD-3-Clause
// The all-pairs queries (index.hpp): a dense snapshot of the grid, the
// search from every ellipsoid, on `threads` OpenMP threads, and a merge
// into the order (i, j, shift), which makes the output independent of the
// number of threads and of the schedule.
//
// Snapshot: per level e, a dense grid (cells of side ≥ 2^e, coarsened until
// there are at most 2·count + 64 cells) whose entries are sorted by cell
// (a counting sort), so that the entries of a row of cells along the last
// axis are contiguous, and neighbours in space are neighbours in memory. The
// hot fields (centre, half-widths, wrap, id) and the forms are separate
// arrays.
//
// Each pair is found from both ellipsoids and kept from the one earlier in
// the snapshot (from its own images, i = j, with a positive shift), so
// that the work of a thread depends on nothing but its ellipsoids; it is
// then tested in the output's orientation (i < j), so that its result does
// not depend on which end found it. The broad phase: broad.hpp.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "batch.hpp"
#include "broad.hpp"
#include "index.hpp"

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail::spatial {

namespace {

template <int D>
struct Hot {
  double c[D];
  double h[D];
  std::int32_t wrap[D];
  std::uint32_t id;
};

template <int D>
struct Form {
  double q[sym_size(D)];
};

template <int D>
struct Grid {
  double origin[D];  // open: the least centre; periodic: 0
  double inv[D];     // 1/side of a cell
  std::int64_t n[D];
  double hmax[D];
  std::size_t first;    // the level's entries: [first, first + count)
  std::size_t count;
  std::size_t cells;    // n0·n1·…
  Buffer<std::uint32_t> start;  // cells + 1 offsets, relative to first
};

template <int D>
struct Snapshot {
  Buffer<Grid<D>> grids;
  Buffer<Hot<D>> hot;
  Buffer<Form<D>> forms;
};

template <int D>
std::int64_t cell_along(Grid<D> const &g, double const *c,
                        std::int32_t const *wrap, double const *box,
                        bool periodic, int k) noexcept {
  double const x = periodic ? c[k] - wrap[k] * box[k] : c[k] - g.origin[k];
  double const m = std::floor(x * g.inv[k]);
  return static_cast<std::int64_t>(
      std::min(std::max(m, 0.0), double(g.n[k] - 1)));
}

// Row-major: in 3D (m0·n1 + m1)·n2 + m2.
template <int D>
std::size_t cell_of(Grid<D> const &g, double const *c,
                    std::int32_t const *wrap, double const *box,
                    bool periodic) noexcept {
  std::int64_t m = cell_along(g, c, wrap, box, periodic, 0);
  for (int k = 1; k < D; ++k)
    m = m * g.n[k] + cell_along(g, c, wrap, box, periodic, k);
  return static_cast<std::size_t>(m);
}

// The number of threads a loop of n iterations is worth (a thread per
// 4096 iterations at least).
int threads_for(int threads, std::size_t n) noexcept {
  return team_size(threads, n / 4096 + 1);
}

// The snapshot's counting sort keeps a histogram of the grid's cells per
// thread: at most this many threads build it.
constexpr int max_snapshot_threads = 16;

// The shape of the snapshot's grid of a level: origin, sides (1/inv) and
// cells per axis, then their product (g.cells).
template <int D>
void grid_shape(Level<D> const &lv, double const *box, bool periodic,
                Grid<D> *gp) noexcept {
  Grid<D> &g = *gp;
  std::size_t const ncells = lv.cells.size();
  double lo[D], hi[D];
  for (int k = 0; k < D; ++k) lo[k] = HUGE_VAL, hi[k] = -HUGE_VAL;
  if (!periodic)
    for (std::size_t ci = 0; ci < ncells; ++ci)
      for (std::size_t ei = 0; ei < lv.cells[ci].size(); ++ei)
        for (int k = 0; k < D; ++k) {
          lo[k] = std::min(lo[k], lv.cells[ci][ei].c[k]);
          hi[k] = std::max(hi[k], lv.cells[ci][ei].c[k]);
        }
  for (int k = 0; k < D; ++k) {
    g.hmax[k] = lv.hmax[k];
    double const side = std::ldexp(1.0, lv.exponent + snapshot_cell_octaves);
    if (periodic) {
      g.origin[k] = 0.0;
      g.n[k] = static_cast<std::int64_t>(std::min(
          std::max(std::floor(box[k] / side), 1.0), max_span));
      g.inv[k] = double(g.n[k]) / box[k];
    } else {
      g.origin[k] = lo[k];
      g.inv[k] = 1.0 / side;
      g.n[k] = static_cast<std::int64_t>(std::min(
          std::floor((hi[k] - lo[k]) * g.inv[k]) + 1.0, max_span));
    }
  }
  // Coarsen the widest axis until the grid is no larger than its entries.
  // The number of cells in integers (each n_k ≤ 2²⁰, their product below
  // 2⁶⁴): a product of doubles, divided and multiplied as the axes were
  // halved, drifted below the integer and was truncated (3·4·5 cells
  // counted 59, and the last cell read past the offsets).
  auto const product = [&g]() {
    std::uint64_t p = 1;
    for (int k = 0; k < D; ++k) p *= static_cast<std::uint64_t>(g.n[k]);
    return p;
  };
  std::uint64_t const most = 2 * std::uint64_t(lv.count) + 64;
  std::uint64_t cells = product();
  while (cells > most) {
    int k = 0;
    for (int a = 1; a < D; ++a)
      if (g.n[a] > g.n[k]) k = a;
    g.n[k] = (g.n[k] + 1) / 2;
    g.inv[k] = periodic ? double(g.n[k]) / box[k] : 0.5 * g.inv[k];
    cells = product();
  }
  g.cells = static_cast<std::size_t>(cells);
}

// The scatter of the counting sort reads the cursor of entry j +
// sort_ahead, and the places it goes, ahead of entry j.
constexpr std::size_t sort_ahead = 8;

// The level's entries sorted by the grid's cell into the snapshot, at
// g.first: a counting sort, in the order of the level's cells. On nt
// threads, thread t takes the level's cells [split[t], split[t + 1])
// (about count/nt entries) and counts its entries per dense cell in its
// own histogram; in each dense cell, thread t's entries then follow those
// of threads t' < t, which is the serial order: the snapshot is the same
// for any number of threads.
template <int D>
struct LevelSort {
  Level<D> const &lv;
  Grid<D> &g;
  Buffer<std::size_t> const &base;  // the level's cells: offsets of their entries
  double const *box;
  bool periodic;
  Buffer<std::uint32_t> &where;  // the grid's cell of each entry
  Buffer<std::uint32_t> &hist;   // nt histograms of g.cells counts
  Snapshot<D> *s;
  int nt = 1;
  std::size_t split[max_snapshot_threads + 1] = {};

  // The shares and the scratch arrays; false when an allocation fails.
  bool prepare(int threads) noexcept {
    std::size_t const ncells = lv.cells.size();
    nt = std::min(threads_for(threads, lv.count), max_snapshot_threads);
    for (int t = 1; t < nt; ++t)
      split[t] = static_cast<std::size_t>(
          std::lower_bound(base.data(), base.data() + ncells + 1,
                           lv.count / std::size_t(nt) * std::size_t(t)) -
          base.data());
    split[nt] = ncells;
    where.clear();
    hist.clear();
    return where.resize_uninitialised(lv.count) &&
           hist.resize(std::size_t(nt) * g.cells);
  }
  void locate(int t) noexcept {
    std::uint32_t *h = hist.data() + std::size_t(t) * g.cells;
    for (std::size_t ci = split[t]; ci < split[t + 1]; ++ci) {
      Cell<D> const &cell = lv.cells[ci];
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        std::uint32_t const w = static_cast<std::uint32_t>(
            cell_of(g, cell[ei].c, cell[ei].wrap, box, periodic));
        where[base[ci] + ei] = w;
        ++h[w];
      }
    }
  }
  void totals() noexcept {
    for (std::size_t c = 0; c < g.cells; ++c) {
      std::uint32_t k = 0;
      for (int t = 0; t < nt; ++t) k += hist[std::size_t(t) * g.cells + c];
      g.start[c + 1] = g.start[c] + k;
    }
  }
  // Each thread's histogram becomes its cursors in the cells [c0, c1).
  void cursors(std::size_t c0, std::size_t c1) noexcept {
    for (std::size_t c = c0; c < c1; ++c) {
      std::uint32_t at = g.start[c];
      for (int t = 0; t < nt; ++t) {
        std::uint32_t const k = hist[std::size_t(t) * g.cells + c];
        hist[std::size_t(t) * g.cells + c] = at;
        at += k;
      }
    }
  }
  void scatter(int t) noexcept {
    std::uint32_t *h = hist.data() + std::size_t(t) * g.cells;
    std::size_t const end = base[split[t + 1]];
    for (std::size_t ci = split[t]; ci < split[t + 1]; ++ci) {
      Cell<D> const &cell = lv.cells[ci];
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry<D> const &e = cell[ei];
        std::size_t const j = base[ci] + ei;
        if (j + 2 * sort_ahead < end) PW85_PREFETCH(&h[where[j + 2 * sort_ahead]]);
        if (j + sort_ahead < end) {
          std::size_t const ahead = g.first + h[where[j + sort_ahead]];
          PW85_PREFETCH(&s->hot[ahead]);
          PW85_PREFETCH(&s->forms[ahead]);
        }
        std::size_t const to = g.first + h[where[j]]++;
        Hot<D> &x = s->hot[to];
        for (int k = 0; k < D; ++k) {
          x.c[k] = e.c[k];
          x.h[k] = e.h[k];
          x.wrap[k] = e.wrap[k];
        }
        x.id = e.id;
        for (int k = 0; k < sym_size(D); ++k) s->forms[to].q[k] = e.q[k];
      }
    }
  }
  void run() noexcept {
    if (nt <= 1) {
      locate(0);
      totals();
      cursors(0, g.cells);
      scatter(0);
      return;
    }
#if defined(PW85_OPENMP)
    long long const ncell = static_cast<long long>(g.cells);
    // The shares t are handed out by `omp for`, not taken from the
    // thread's number: OpenMP may start fewer threads than asked
    // (OMP_THREAD_LIMIT, OMP_DYNAMIC, nesting), and every share must run.
#pragma omp parallel num_threads(nt)
    {
#pragma omp for schedule(static, 1)
      for (int t = 0; t < nt; ++t) locate(t);
#pragma omp single
      totals();
#pragma omp for schedule(static)
      for (long long c = 0; c < ncell; c += 4096)
        cursors(std::size_t(c), std::min(std::size_t(c) + 4096, g.cells));
#pragma omp for schedule(static, 1)
      for (int t = 0; t < nt; ++t) scatter(t);
    }
#endif
  }
};

// The snapshot of every non-empty level; false when an allocation fails.
// Each level's counting sort runs on `threads` threads (LevelSort), in an
// order that does not depend on their number; the loops over the level's
// cells here (offsets, and the bounds of an open domain) are serial.
template <int D>
bool take_snapshot(Index<D> const &index, int threads, Snapshot<D> *s) noexcept {
  Buffer<Level<D>> const &levels = index.levels();
  double const *box = index.box();
  bool const periodic = index.periodic();
  if (!s->hot.resize_uninitialised(index.count()) ||
      !s->forms.resize_uninitialised(index.count()) ||
      !s->grids.reserve(levels.size()))
    return false;
  Buffer<std::size_t> base;  // the level's cells: offsets of their entries
  Buffer<std::uint32_t> where, hist;
  std::size_t first = 0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    Level<D> const &lv = levels[l];
    if (lv.count == 0) continue;
    Grid<D> g;
    g.first = first;
    g.count = lv.count;
    first += lv.count;
    std::size_t const ncells = lv.cells.size();
    base.clear();
    if (!base.resize_uninitialised(ncells + 1)) return false;
    base[0] = 0;
    for (std::size_t ci = 0; ci < ncells; ++ci)
      base[ci + 1] = base[ci] + lv.cells[ci].size();
    grid_shape(lv, box, periodic, &g);
    LevelSort<D> sort{lv, g, base, box, periodic, where, hist, s};
    if (!g.start.resize(g.cells + 1) || !sort.prepare(threads)) return false;
    sort.run();
    s->grids.push_back_reserved(static_cast<Grid<D> &&>(g));
  }
  return true;
}

template <int D>
bool shift_positive(std::int32_t const *n) noexcept {
  for (int k = 0; k < D; ++k)
    if (n[k] != 0) return n[k] > 0;
  return false;
}

// The output's order, (i, j, shift) lexicographic, on either record.
template <class H>
bool pair_less(H const &a, H const &b) noexcept {
  if (a.i != b.i) return a.i < b.i;
  if (a.j != b.j) return a.j < b.j;
  for (std::size_t k = 0; k < sizeof a.shift / sizeof a.shift[0]; ++k)
    if (a.shift[k] != b.shift[k]) return a.shift[k] < b.shift[k];
  return false;
}

// The record of pair (i, j), its other fields zero (a failure's place).
template <class H>
H pair_at(std::uint32_t i, std::uint32_t j) noexcept {
  H h{};
  h.i = i, h.j = j;
  return h;
}

// A list of pairs (records H) in blocks that are never moved: the first
// of 4096 pairs, each next one twice as large up to 12 MiB (large enough
// for huge pages, buffer.hpp). A growing array would copy its content at
// each doubling, and the copies into fresh pages cost 8% of the all-pairs
// query at N = 1e6 (perf).
template <class H>
class PairList {
 public:
  std::size_t size() const noexcept { return size_; }
  std::size_t blocks() const noexcept { return blocks_.size(); }
  Buffer<H> const &block(std::size_t b) const noexcept { return blocks_[b]; }
  [[nodiscard]] bool push_back(H const &hit) noexcept {
    if (blocks_.empty() || blocks_.back().size() == blocks_.back().capacity()) {
      constexpr std::size_t most = (std::size_t(12) << 20) / sizeof(H);
      std::size_t const n =
          blocks_.empty() ? 4096
                          : std::min(2 * blocks_.back().capacity(), most);
      Buffer<H> block;
      if (!blocks_.grow_for(1) || !block.reserve(n)) return false;
      blocks_.push_back_reserved(static_cast<Buffer<H> &&>(block));
    }
    H copy = hit;
    blocks_.back().push_back_reserved(static_cast<H &&>(copy));
    ++size_;
    return true;
  }

 private:
  Buffer<Buffer<H>> blocks_;
  std::size_t size_ = 0;
};

// One thread's share: its pairs, its count of broad-phase candidates, and
// the least pair (in the output order) on which the narrow phase failed.
template <class H>
struct Share {
  PairList<H> pairs;
  std::size_t candidates = 0;
  Status status = Status::success;
  H failed_at{};
};

// The search, with results of type H: PairHit<D>, or OverlapPair<D> in
// overlap mode only.
template <int D, class H>
class Search {
 public:
  Search(Index<D> const &index, Snapshot<D> const &s, bool within, double t)
      : periodic_(index.periodic()),
        box_(index.box()),
        cmax_(index.coordinate_bound()),
        s_(s),
        within_(within),
        t_(t),
        sqrt_t_(std::sqrt(t)) {
    // The slack of test(): one for every pair, that of a query of centre
    // |c_k| ≤ cmax and reach the largest bound of a pair (twice the largest
    // h_k of any grid), above the σ_k of each pair (margins.hpp), and a
    // function of the index alone, as test() must be.
    slack_sum_ = 0.0;
    for (int k = 0; k < D; ++k) {
      double h = 0.0;
      for (std::size_t g = 0; g < s.grids.size(); ++g)
        h = std::max(h, s.grids[g].hmax[k]);
      slack_[k] = rounding_slack(cmax_, cmax_, box_bound(sqrt_t_, h, h), box_[k]);
      slack_sum_ += slack_[k];
    }
  }

  // The pairs found from entry a (an index into the snapshot).
  void from(std::size_t a, Share<H> *share) const noexcept {
    for (std::size_t g = 0; g < s_.grids.size(); ++g) {
      if (!grid(s_.grids[g], a, share)) return;
    }
  }

 private:
  void fail(Share<H> *share, Status status, H const &at) const
      noexcept {
    if (share->status == Status::success ||
        (share->status != Status::no_memory && pair_less(at, share->failed_at))) {
      share->status = status;
      share->failed_at = at;
    }
  }

  // The pair of entries a and b (positions in the snapshot, a ≤ b) with
  // b's image `shift` seen from a: put in the output's orientation, (i, j,
  // n) with i = min id, j = max id, n = ±shift, then tested from scratch in
  // that orientation (the box test with the pair's own bound, the
  // line test, the narrow phase on the exact r = (c_j + n∘L) − c_i), as a
  // brute force over (i, j, n) would. False stops (no memory).
  bool test(std::size_t a, std::size_t b, std::int32_t const *shift,
            Share<H> *share) const noexcept {
    std::int32_t n[D];
    for (int k = 0; k < D; ++k) n[k] = shift[k];
    if (s_.hot[b].id < s_.hot[a].id) {
      std::swap(a, b);
      for (int k = 0; k < D; ++k) n[k] = -n[k];
    }
    Hot<D> const &x = s_.hot[a];
    Hot<D> const &y = s_.hot[b];
    double r[D];
    if (!boxes_meet<D>(x.c, x.h, y.c, y.h, n, box_, sqrt_t_, slack_, r))
      return true;
    double const *q1 = s_.forms[a].q;
    double const *q2 = s_.forms[b].q;
    if (separated_along_r<D>(r, q1, x.h, q2, y.h, sqrt_t_, slack_sum_))
      return true;
    ++share->candidates;
    ImageVector<D> v;
    image_vector_exact(x.c, y.c, n, box_, &v);
    H hit = pair_at<H>(x.id, y.id);
    for (int k = 0; k < D; ++k) hit.shift[k] = n[k];
    if (!narrow(v, q1, q2, &hit, share)) return true;
    if (!share->pairs.push_back(hit)) {
      share->status = Status::no_memory;
      return false;
    }
    return true;
  }

  // The narrow phase of test(): true when the pair is reported (hit
  // filled); a failure is recorded in the share.
  bool narrow(ImageVector<D> const &v, double const *q1, double const *q2,
              H *hit, Share<H> *share) const noexcept {
    if constexpr (std::is_same_v<H, PairHit<D>>) {
      if (within_) {
        double out[2] = {NAN, NAN};
        Status const st = image_contact(v, q1, q2, out);
        if (st == Status::out_of_range && out[0] == HUGE_VAL) return false;
        if (st != Status::success) {
          fail(share, st, *hit);
          return false;
        }
        if (!(out[0] < t_)) return false;
        hit->mu2 = out[0];
        hit->lambda = out[1];
        return true;
      }
    }
    int res = 1;
    Status const st = image_overlap(v, q1, q2, &res);
    if (st != Status::success) {
      fail(share, st, *hit);
      return false;
    }
    hit->result = res;
    return res <= 0;
  }

  // Each pair is found from both entries (the broad phase is symmetric):
  // it is kept from the one earlier in the snapshot, b > a, or, for an
  // entry's own image (b = a), with a positive shift (the pair (a, a, −n)
  // is the same as (a, a, n)).
  bool grid(Grid<D> const &g, std::size_t a, Share<H> *share) const noexcept {
    Hot<D> const &x = s_.hot[a];
    Reach<D> const rc = reach_of<D>(x.c, x.h, g.hmax, sqrt_t_, cmax_, box_);
    double first[D], last[D], lo[D], hi[D];
    for (int k = 0; k < D; ++k) {  // open: clamped as the entries' cells
      first[k] = periodic_ ? -HUGE_VAL : 0.0;
      last[k] = periodic_ ? HUGE_VAL : double(g.n[k] - 1);
    }
    double const cells = cell_range(rc, x.c, g.origin, g.inv, first, last, lo, hi);
    if (cells > 2.0 * double(g.cells) + 8.0) return every_entry(g, a, rc, share);
    return runs(g, a, rc, lo, hi, share);
  }

  // A grid narrower than the reach: every entry, with the shifts in reach.
  // The check of the number of images (max_span, out_of_range) is made
  // from x against every entry y of the grid with y.id ≥ x.id, with the
  // grid's reach: whether the query fails is a function of each entry's
  // own view, not of the order of the snapshot. The images of y kept from
  // x are those within the pair's own bound plus the slack, a superset of
  // those that the box test keeps.
  bool every_entry(Grid<D> const &g, std::size_t a, Reach<D> const &rc,
                   Share<H> *share) const noexcept {
    Hot<D> const &x = s_.hot[a];
    std::int64_t lo[D], hi[D];
    for (std::size_t b = g.first; b < g.first + g.count; ++b) {
      Hot<D> const &y = s_.hot[b];
      if (y.id >= x.id &&
          !shift_range<D>(periodic_, x.c, rc.reach, rc.slack, y.c, box_, lo, hi)) {
        fail(share, Status::out_of_range, pair_at<H>(x.id, y.id));
        return true;
      }
    }
    for (std::size_t b = std::max(g.first, a); b < g.first + g.count; ++b) {
      Hot<D> const &y = s_.hot[b];
      double bound[D];
      for (int k = 0; k < D; ++k) bound[k] = box_bound(sqrt_t_, x.h[k], y.h[k]);
      if (!shift_range<D>(periodic_, x.c, bound, rc.slack, y.c, box_, lo, hi)) {
        // only if y.id < x.id (see above)
        std::uint32_t const i = std::min(x.id, y.id), j = std::max(x.id, y.id);
        fail(share, Status::out_of_range, pair_at<H>(i, j));
        return true;
      }
      if (!for_each_shift<D>(lo, hi, [&](std::int32_t const *shift) {
            return (b == a && !shift_positive<D>(shift)) ||
                   test(a, b, shift, share);
          }))
        return false;
    }
    return true;
  }

  // The cells [lo, hi] of the grid: along the last axis, one contiguous
  // run of entries per copy of the box. Runs of entries wholly before a
  // are skipped without reading them. The box test from x with the grid's
  // slack is a first filter, inlined: it discards only images that the
  // test in the output's orientation discards too (both slacks bound the
  // rounding of r̂, formed from either end: margins.hpp).
  bool runs(Grid<D> const &g, std::size_t a, Reach<D> const &rc,
            double const *lo, double const *hi, Share<H> *share) const
      noexcept {
    constexpr int z = D - 1;
    std::int64_t const lo_z = std::int64_t(lo[z]), hi_z = std::int64_t(hi[z]);
    Rows const rows{g, a, rc, lo, hi, share, lo_z, hi_z,
                    periodic_ ? floor_div(lo_z, g.n[z]) : 0,
                    periodic_ ? floor_div(hi_z, g.n[z]) : 0};
    std::int64_t p[D];
    return along<0>(rows, 0, p);
  }

  // What runs() hands down its loops: the block of cells, and along the
  // last axis its ends and the copies of the box they fall in.
  struct Rows {
    Grid<D> const &g;
    std::size_t a;
    Reach<D> const &rc;
    double const *lo, *hi;
    Share<H> *share;
    std::int64_t lo_z, hi_z, copy_lo, copy_hi;
  };

  // The loops along the axes K < D − 1 (nested once inlined): the cell
  // m of the copy p_K of the box; row: the position of the row's first
  // cell so far (row-major, in 3D (u0·n1 + u1)·n2).
  template <int K>
  PW85_INLINE bool along(Rows const &w, std::int64_t row,
                         std::int64_t p[D]) const noexcept {
    Grid<D> const &g = w.g;
    for (std::int64_t m = std::int64_t(w.lo[K]); m <= std::int64_t(w.hi[K]); ++m) {
      p[K] = periodic_ ? floor_div(m, g.n[K]) : 0;
      std::int64_t const inner = row * g.n[K] + (m - p[K] * g.n[K]);
      if constexpr (K + 2 < D) {
        if (!along<K + 1>(w, inner, p)) return false;
      } else if (!run(w, static_cast<std::size_t>(inner * g.n[D - 1]), p)) {
        return false;
      }
    }
    return true;
  }

  // The cells of a row along the last axis (p: the copies along the
  // others), one contiguous run of entries per copy of the box.
  PW85_INLINE bool run(Rows const &w, std::size_t row,
                       std::int64_t const p[D]) const noexcept {
    constexpr int z = D - 1;
    Grid<D> const &g = w.g;
    std::size_t const a = w.a;
    Hot<D> const &x = s_.hot[a];
    std::int32_t shift[D];
    double r[D];
    for (std::int64_t pz = w.copy_lo; pz <= w.copy_hi; ++pz) {
      std::int64_t const z0 = std::max(w.lo_z, pz * g.n[z]) - pz * g.n[z];
      std::int64_t const z1 = std::min(w.hi_z, pz * g.n[z] + g.n[z] - 1) - pz * g.n[z];
      std::size_t const b1 = g.first + g.start[row + std::size_t(z1) + 1];
      if (b1 <= a) continue;
      std::size_t const b0 = std::max(g.first + g.start[row + std::size_t(z0)], a);
      for (std::size_t b = b0; b < b1; ++b) {
        Hot<D> const &y = s_.hot[b];
        for (int k = 0; k < z; ++k) shift[k] = std::int32_t(p[k] - y.wrap[k]);
        shift[z] = std::int32_t(pz - y.wrap[z]);
        if (!boxes_meet<D>(x.c, x.h, y.c, y.h, shift, box_, sqrt_t_, w.rc.slack, r))
          continue;
        if (b == a && !shift_positive<D>(shift)) continue;
        if (!test(a, b, shift, w.share)) return false;
      }
    }
    return true;
  }

  bool periodic_;
  double const *box_;
  double cmax_;
  Snapshot<D> const &s_;
  bool within_;
  double t_, sqrt_t_;
  double slack_[D], slack_sum_;  // test()'s
};

// The merge reads the counters of pair q + merge_ahead, and the place
// it goes, ahead of pair q (both random accesses into large arrays).
constexpr std::size_t merge_ahead = 8;

// The pairs of every share into out, sorted by (i, j, shift); ids: the
// id table's size, total: the number of pairs. False when an allocation
// fails.
template <class H>
bool merge(Buffer<Share<H>> const &shares, int threads, std::size_t ids,
           std::size_t total, Buffer<H> *out) noexcept {
  // Merge: a counting sort by i, then each i's pairs sorted by (j, shift).
  // The keys (i, j, n) are distinct, so the order within an i before its
  // sort does not matter: the shares are scattered concurrently (slots
  // taken by atomic increments) and the output is still the same for any
  // number of threads.
  Buffer<std::size_t> first;
  if (!first.resize(ids + 1) || !out->resize_uninitialised(total)) return false;
  int const nt = threads_for(threads, total);
  auto count_share = [&](std::size_t k, bool atomic) {
    for (std::size_t b = 0; b < shares[k].pairs.blocks(); ++b) {
      Buffer<H> const &p = shares[k].pairs.block(b);
      for (std::size_t q = 0; q < p.size(); ++q) {
        if (q + merge_ahead < p.size())
          PW85_PREFETCH(&first[p[q + merge_ahead].i + 1]);
        std::size_t *c = &first[p[q].i + 1];
        if (atomic)
          __atomic_fetch_add(c, 1, __ATOMIC_RELAXED);
        else
          ++*c;
      }
    }
  };
  auto scatter_share = [&](std::size_t k, bool atomic) {
    for (std::size_t b = 0; b < shares[k].pairs.blocks(); ++b) {
      Buffer<H> const &p = shares[k].pairs.block(b);
      for (std::size_t q = 0; q < p.size(); ++q) {
        if (q + 2 * merge_ahead < p.size())
          PW85_PREFETCH(&first[p[q + 2 * merge_ahead].i]);
        if (q + merge_ahead < p.size()) {
          std::size_t const *c = &first[p[q + merge_ahead].i];
          PW85_PREFETCH(out->data() +
                        (atomic ? __atomic_load_n(c, __ATOMIC_RELAXED) : *c));
        }
        std::size_t *c = &first[p[q].i];
        std::size_t const to =
            atomic ? __atomic_fetch_add(c, 1, __ATOMIC_RELAXED) : (*c)++;
        (*out)[to] = p[q];
      }
    }
  };
  auto sort_from = [&](std::size_t i) {
    // first[i] is now the end of i's pairs, first[i − 1] their start.
    std::size_t const begin = i == 0 ? 0 : first[i - 1], end = first[i];
    if (end - begin > 1)
      std::sort(out->data() + begin, out->data() + end, pair_less<H>);
  };
  if (nt <= 1) {
    for (std::size_t k = 0; k < shares.size(); ++k) count_share(k, false);
    for (std::size_t i = 0; i < ids; ++i) first[i + 1] += first[i];
    for (std::size_t k = 0; k < shares.size(); ++k) scatter_share(k, false);
    for (std::size_t i = 0; i < ids; ++i) sort_from(i);
  } else {
#if defined(PW85_OPENMP)
    long long const nshares = static_cast<long long>(shares.size());
    long long const nids = static_cast<long long>(ids);
#pragma omp parallel num_threads(nt)
    {
#pragma omp for schedule(dynamic, 1)
      for (long long k = 0; k < nshares; ++k) count_share(std::size_t(k), true);
#pragma omp single
      for (std::size_t i = 0; i < ids; ++i) first[i + 1] += first[i];
#pragma omp for schedule(dynamic, 1)
      for (long long k = 0; k < nshares; ++k) scatter_share(std::size_t(k), true);
#pragma omp for schedule(dynamic, 4096)
      for (long long i = 0; i < nids; ++i) sort_from(std::size_t(i));
    }
#endif
  }
  return true;
}

}  // namespace

template <int D>
template <class H>
Status Index<D>::pairs_into(bool within, double t, int threads, Buffer<H> *out,
                            std::size_t *candidates) const noexcept {
  if (within) {
    if (!std::isfinite(t)) return Status::not_finite;
    if (!(t > 0.0)) return Status::invalid_argument;
  }
  if (threads < 1) return Status::invalid_argument;
#if !defined(PW85_OPENMP)
  threads = 1;
#endif
  Snapshot<D> snap;
  if (!take_snapshot(*this, threads, &snap)) return Status::no_memory;
  std::size_t const n = snap.hot.size();
  constexpr std::size_t chunk = 256;
  std::size_t const chunks = (n + chunk - 1) / chunk;
  // A share per thread: no more threads than chunks, nor than max_threads.
  threads = team_size(threads, chunks);
  Buffer<Share<H>> shares;
  if (!shares.resize(std::size_t(threads))) return Status::no_memory;
  Search<D, H> const search(*this, snap, within, within ? t : 1.0);
  auto run = [&](std::size_t k, Share<H> *share) {
    if (share->status == Status::no_memory) return;
    std::size_t const end = std::min(n, (k + 1) * chunk);
    for (std::size_t a = k * chunk; a < end; ++a) search.from(a, share);
  };
  if (threads == 1) {
    for (std::size_t k = 0; k < chunks; ++k) run(k, &shares[0]);
  } else {
#if defined(PW85_OPENMP)
    long long const nchunks = static_cast<long long>(chunks);
#pragma omp parallel num_threads(threads)
    {
      Share<H> *share = &shares[std::size_t(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 1)
      for (long long k = 0; k < nchunks; ++k) run(std::size_t(k), share);
    }
#endif
  }

  // The least failure in the output order, whatever the schedule.
  Status status = Status::success;
  H at{};
  std::size_t total = 0, found = 0;
  for (std::size_t k = 0; k < shares.size(); ++k) {
    Share<H> const &sh = shares[k];
    total += sh.pairs.size();
    found += sh.candidates;
    if (sh.status == Status::no_memory) return Status::no_memory;
    if (sh.status != Status::success &&
        (status == Status::success || pair_less<H>(sh.failed_at, at))) {
      status = sh.status;
      at = sh.failed_at;
    }
  }
  if (status != Status::success) return status;
  snap.hot.reset();  // spare the memory before the merge's
  snap.forms.reset();

  if (!merge(shares, threads, id_bound(), total, out)) return Status::no_memory;
  if (candidates != nullptr) *candidates = found;
  return Status::success;
}

template <int D>
Status Index<D>::pairs(bool within, double t, int threads,
                       Buffer<PairHit<D>> *out,
                       std::size_t *candidates) const noexcept {
  return pairs_into(within, t, threads, out, candidates);
}

template <int D>
Status Index<D>::overlapping_pairs(int threads, Buffer<OverlapPair<D>> *out,
                                   std::size_t *candidates) const noexcept {
  return pairs_into(false, 1.0, threads, out, candidates);
}

template Status Index<2>::pairs(bool, double, int, Buffer<PairHit<2>> *,
                                std::size_t *) const noexcept;
template Status Index<3>::pairs(bool, double, int, Buffer<PairHit<3>> *,
                                std::size_t *) const noexcept;
template Status Index<2>::overlapping_pairs(int, Buffer<OverlapPair<2>> *,
                                            std::size_t *) const noexcept;
template Status Index<3>::overlapping_pairs(int, Buffer<OverlapPair<3>> *,
                                            std::size_t *) const noexcept;

}  // namespace pw85::detail::spatial
