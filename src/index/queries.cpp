// SPDX-License-Identifier: BSD-3-Clause
// The queries on a candidate (index.hpp): the visit of the grid's cells
// within reach (the broad phase of broad.hpp), and overlap_any() and
// within(), its visitors.
#include <algorithm>
#include <cmath>

#include "compiler.hpp"
#include "deep.hpp"
#include "index.hpp"

namespace pw85::detail::spatial {

namespace {

// The visit of blocks of cells of a level: the cells in reach are
// gathered in batches, then their entries are tested; the cache misses of
// a batch (cell headers, then entries) are issued together (prefetches),
// not one dependent chain per cell, which made most of the time of random
// sequential addition (perf). Cell m along axis k (unwrapped) is the cell
// u = m − copy·n_k of the copy ⌊m / n_k⌋ of the box (periodic), followed
// incrementally along each axis, without a division per cell. test(e,
// shift) tests an entry's image; false stops the visit.
template <int D, typename Test>
class CellScan {
 public:
  CellScan(Level<D> const &lv, bool periodic, std::uint32_t exclude,
           Test &test) noexcept
      : lv_(lv), periodic_(periodic), exclude_(exclude), test_(test) {}

  // Visits the cells of the block [from, to] but those of the block
  // [skip_lo, skip_hi] (none when empty); false when the visit stops.
  bool scan(std::int64_t const from[D], std::int64_t const to[D],
            std::int64_t const skip_lo[D],
            std::int64_t const skip_hi[D]) noexcept {
    Block b{from, to, skip_lo, skip_hi, {}, {}};
    start(from, b.u0, b.copy0);
    if (!lv_.dense.empty()) prefetch_rows(b);
    std::uint64_t u[D];
    std::int64_t copy[D];
    return axis<0>(b, true, u, copy) && flush();
  }

 private:
  // The block of scan(), and the cell coordinates and box copy of its
  // first cell.
  struct Block {
    std::int64_t const *from, *to, *skip_lo, *skip_hi;
    std::uint64_t u0[D];
    std::int64_t copy0[D];
  };

  // The loop along axis K over the block, nesting those along the axes
  // after it (D nested loops once inlined); in: the cell is in the
  // skipped block along the axes before K.
  template <int K>
  PW85_INLINE bool axis(Block const &b, bool in, std::uint64_t u[D],
                        std::int64_t copy[D]) noexcept {
    u[K] = b.u0[K], copy[K] = b.copy0[K];
    for (std::int64_t m = b.from[K]; m <= b.to[K]; ++m) {
      bool const inside = in && b.skip_lo[K] <= m && m <= b.skip_hi[K];
      if constexpr (K + 1 < D) {
        if (!axis<K + 1>(b, inside, u, copy)) return false;
      } else {
        std::uint32_t const ci = inside ? CellMap::absent : lv_.find(u);
        if (ci != CellMap::absent && !add(&lv_.cells[ci], copy)) return false;
      }
      advance(K, &u[K], &copy[K]);
    }
    return true;
  }

  static constexpr int batch = 64;
  struct Pending {
    Cell<D> const *cell;
    std::int64_t copy[D];
  };

  // The cell coordinates u and box copy of the unwrapped cell m = from.
  void start(std::int64_t const from[D], std::uint64_t u[D],
             std::int64_t copy[D]) const noexcept {
    for (int k = 0; k < D; ++k) {
      copy[k] = periodic_ ? floor_div(from[k], lv_.n[k]) : 0;
      u[k] = std::uint64_t(periodic_ ? from[k] - copy[k] * lv_.n[k]
                                     : from[k] + std::int64_t(open_half));
    }
  }
  void advance(int k, std::uint64_t *u, std::int64_t *copy) const noexcept {
    ++*u;
    if (periodic_ && std::int64_t(*u) == lv_.n[k]) {
      *u = 0;
      ++*copy;
    }
  }
  // The dense array's entries of the rows' first cells (rows along the
  // last axis), fetched together: loops along the axes K < D − 1.
  PW85_INLINE void prefetch_rows(Block const &b) const noexcept {
    std::uint64_t u[D];
    std::int64_t copy[D];
    for (int k = 0; k < D; ++k) u[k] = b.u0[k], copy[k] = b.copy0[k];
    prefetch_axis<0>(b, u, copy);
  }
  template <int K>
  PW85_INLINE void prefetch_axis(Block const &b, std::uint64_t u[D],
                                 std::int64_t copy[D]) const noexcept {
    u[K] = b.u0[K], copy[K] = b.copy0[K];
    for (std::int64_t m = b.from[K]; m <= b.to[K]; ++m) {
      if constexpr (K + 2 < D)
        prefetch_axis<K + 1>(b, u, copy);
      else
        PW85_PREFETCH(&lv_.dense[lv_.dense_index(u)]);
      advance(K, &u[K], &copy[K]);
    }
  }
  bool add(Cell<D> const *cell, std::int64_t const copy[D]) noexcept {
    Pending &p = pending_[np_++];
    p.cell = cell;
    PW85_PREFETCH(cell);
    for (int k = 0; k < D; ++k) p.copy[k] = copy[k];
    return np_ < batch || flush();
  }
  // Tests the entries of the pending cells; false when the visit stops.
  bool flush() noexcept {
    for (int i = 0; i < np_; ++i) {
      Cell<D> const &cell = *pending_[i].cell;
      // Both cache lines of each entry: the second (form, inscribed
      // radius) is read for every entry whose AABB meets the candidate's;
      // random sequential addition of 1e5 (bench-index) took 12% less
      // time per attempt than with the first line alone.
      for (std::size_t ei = 0; ei < cell.size(); ++ei)
        PW85_PREFETCH(&cell[ei]), PW85_PREFETCH(&cell[ei].q[2]);
    }
    std::int32_t shift[D];
    for (int i = 0; i < np_; ++i) {
      Cell<D> const &cell = *pending_[i].cell;
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry<D> const &e = cell[ei];
        if (e.id == exclude_) continue;
        for (int k = 0; k < D; ++k)
          shift[k] = static_cast<std::int32_t>(pending_[i].copy[k] - e.wrap[k]);
        if (!test_(e, static_cast<std::int32_t const *>(shift))) return false;
      }
    }
    np_ = 0;
    return true;
  }

  Level<D> const &lv_;
  bool periodic_;
  std::uint32_t exclude_;
  Test &test_;
  Pending pending_[batch];
  int np_ = 0;
};

// The cells that hold points within half a cell of c (at most two along
// each axis), inside the block [from, to].
template <int D>
PW85_INLINE void nearest_cells(Level<D> const &lv, bool periodic,
                               double const *c, std::int64_t const *from,
                               std::int64_t const *to, std::int64_t *lo,
                               std::int64_t *hi) noexcept {
  for (int k = 0; k < D; ++k) {
    double const half = 0.5 * lv.side[k];
    double a = std::floor((c[k] - half) * lv.inv[k]);
    double b = std::floor((c[k] + half) * lv.inv[k]);
    if (!periodic) {
      a = std::min(std::max(a, -open_half), open_half - 1.0);
      b = std::min(std::max(b, -open_half), open_half - 1.0);
    }
    lo[k] = std::max(from[k], std::int64_t(a));
    hi[k] = std::min(to[k], std::int64_t(b));
  }
}

std::uint32_t to_exclude(std::size_t id) noexcept {
  return id > max_id ? no_id : static_cast<std::uint32_t>(id);
}

}  // namespace

template <int D>
template <typename Test>
Status Index<D>::visit_every_entry(Level<D> const &lv, double const *c,
                                   Reach<D> const &rc, std::uint32_t exclude,
                                   bool nearest_first, bool *go_on,
                                   Test &test) const noexcept {
  // Every entry but `exclude`, with the shifts [lo, hi] of its images in
  // reach: visit(e, lo, hi), false to stop the visit.
  auto entries = [&](auto &&visit) {
    for (std::size_t ci = 0; ci < lv.cells.size(); ++ci) {
      Cell<D> const &cell = lv.cells[ci];
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry<D> const &e = cell[ei];
        if (e.id == exclude) continue;
        std::int64_t lo[D], hi[D];
        if (!shift_range<D>(periodic_, c, rc.reach, rc.slack, e.c, box_, lo,
                            hi))
          return Status::out_of_range;
        if (!visit(e, static_cast<std::int64_t const *>(lo),
                   static_cast<std::int64_t const *>(hi))) {
          *go_on = false;
          return Status::success;
        }
      }
    }
    return Status::success;
  };
  if (nearest_first && periodic_) {
    // First each entry's image nearest to c: a candidate wider than the
    // box holds it, and the shifts' lexicographic order below reached it
    // only after a face of its reach, (2·reach)² images in 3D (1.8 s for
    // a candidate 2¹² sides wide; about two hours, extrapolated, at 2¹⁸).
    Status const s = entries([&](Entry<D> const &e, std::int64_t const *lo,
                                 std::int64_t const *hi) {
      std::int32_t shift[D];
      for (int k = 0; k < D; ++k) {
        double const n = std::round((c[k] - e.c[k]) / box_[k]);
        shift[k] = std::int32_t(std::min<double>(
            std::max<double>(n, double(lo[k])), double(hi[k])));
      }
      return test(e, static_cast<std::int32_t const *>(shift));
    });
    if (s != Status::success || !*go_on) return s;
  }
  return entries([&](Entry<D> const &e, std::int64_t const *lo,
                     std::int64_t const *hi) {
    return for_each_shift<D>(
        lo, hi, [&](std::int32_t const *shift) { return test(e, shift); });
  });
}

template <int D>
template <typename F>
Status Index<D>::visit_level(Level<D> const &lv, double const *c,
                             double const *h, double sqrt_t,
                             std::uint32_t exclude, bool nearest_first,
                             bool *go_on, F &f) const noexcept {
  Reach<D> const rc = reach_of<D>(c, h, lv.hmax, sqrt_t, cmax_, box_);
  // The box test of one image, then f (which tests the rest); false stops
  // the visit.
  auto test = [&](Entry<D> const &e, std::int32_t const *shift) {
    double r[D];
    if (!boxes_meet<D>(c, h, e.c, e.h, shift, box_, sqrt_t, rc.slack, r))
      return true;
    return f(e, shift, static_cast<double const *>(r), rc.slack_sum);
  };
  double const zero[D] = {};
  double first[D], last[D], lo[D], hi[D];
  for (int k = 0; k < D; ++k) {
    first[k] = periodic_ ? -HUGE_VAL : -open_half;
    last[k] = periodic_ ? HUGE_VAL : open_half - 1.0;
  }
  double const cells = cell_range(rc, c, zero, lv.inv, first, last, lo, hi);
  if (cells > 2.0 * double(lv.cells.size()) + 8.0)
    return visit_every_entry(lv, c, rc, exclude, nearest_first, go_on, test);

  CellScan<D, decltype(test)> scan(lv, periodic_, exclude, test);
  std::int64_t from[D], to[D], none_lo[D], none_hi[D];
  for (int k = 0; k < D; ++k) {
    from[k] = std::int64_t(lo[k]);
    to[k] = std::int64_t(hi[k]);
    none_lo[k] = 1;  // an empty block: nothing skipped
    none_hi[k] = 0;
  }
  if (nearest_first) {
    // First the cells nearest to c: a query that stops at the first
    // overlap finds one there most often (random sequential addition near
    // saturation rejects most candidates), before fetching the rest of the
    // block. Every cell is still visited once.
    std::int64_t near_lo[D], near_hi[D];
    nearest_cells<D>(lv, periodic_, c, from, to, near_lo, near_hi);
    if (!scan.scan(near_lo, near_hi, none_lo, none_hi) ||
        !scan.scan(from, to, near_lo, near_hi))
      *go_on = false;
    return Status::success;
  }
  if (!scan.scan(from, to, none_lo, none_hi)) *go_on = false;
  return Status::success;
}

template <int D>
template <typename F>
Status Index<D>::visit(double const *c, double const *h, double sqrt_t,
                       std::uint32_t exclude, bool nearest_first, F &&f) const
    noexcept {
  bool go_on = true;
  for (std::size_t l = 0; l < levels_.size() && go_on; ++l) {
    if (levels_[l].count == 0) continue;
    Status const s = visit_level(levels_[l], c, h, sqrt_t, exclude,
                                 nearest_first, &go_on, f);
    if (s != Status::success) return s;
  }
  return Status::success;
}

namespace {

// The candidate's side of the deep-overlap shortcut (deep.hpp), made on
// the first stored ellipsoid with an inscribed ball: its Cholesky factor,
// the certified lower bound of its λmin, and a bound of its semi-axes.
template <int D>
struct CandidateFactor {
  int known = -1;  // 1: usable; 0: not; −1: not yet computed
  double l[sym_size(D)];
  double lambda_min = 0.0;
  double reach = 0.0;

  bool usable(double const *q) noexcept {
    if (known < 0) {
      known = line_factor<D>(q, l, &lambda_min);
      reach = 1.5 * std::sqrt(trace<D>(q));  // > every semi-axis
    }
    return known > 0;
  }
};

}  // namespace

template <int D>
Status Index<D>::overlap_any(double const *c, double const *q,
                             std::size_t exclude, int *result,
                             std::size_t *id) const noexcept {
  Status s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  double h[D];
  half_widths<D>(q, h);
  Status failed = Status::success;
  int best = 1;
  std::uint32_t best_id = no_id;
  CandidateFactor<D> cf;
  s = visit(c, h, 1.0, to_exclude(exclude), true,
            [&](Entry<D> const &e, std::int32_t const *shift,
                double const *r, double slack_sum) {
              // Deep overlaps, decided without the narrow phase
              // (deep.hpp); only if the candidate may reach the stored
              // ellipsoid's ball (a filter: it decides nothing).
              if (e.rho > 0.0 && cf.usable(q)) {
                double const d2 = dot<D>(r, r);
                double const gap = cf.reach + e.rho;
                if (d2 < gap * gap &&
                    slack_sum * slack_sum <= deep_slack * cf.lambda_min &&
                    deep_overlap<D>(cf.l, r, d2, e.rho)) {
                  best = -1;
                  best_id = e.id;
                  return false;
                }
              }
              if (separated_along_r<D>(r, q, h, e.q, e.h, 1.0, slack_sum))
                return true;
              ImageVector<D> v;
              image_vector_exact(c, e.c, shift, box_, &v);
              int res = 1;
              failed = image_overlap(v, q, e.q, &res);
              if (failed != Status::success) return false;
              if (res < best) {
                best = res;
                best_id = e.id;
              }
              return best > -1;
            });
  if (s == Status::success) s = failed;
  if (s != Status::success) return s;
  *result = best;
  *id = best_id == no_id ? std::size_t(-1) : std::size_t(best_id);
  return Status::success;
}

template <int D>
Status Index<D>::within(double const *c, double const *q, double t,
                        std::size_t exclude, Buffer<Hit<D>> *hits) const
    noexcept {
  Status s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (!std::isfinite(t)) return Status::not_finite;
  if (!(t > 0.0)) return Status::invalid_argument;
  double h[D];
  half_widths<D>(q, h);
  Status failed = Status::success;
  double const sqrt_t = std::sqrt(t);
  s = visit(c, h, sqrt_t, to_exclude(exclude), false,
            [&](Entry<D> const &e, std::int32_t const *shift,
                double const *r, double slack_sum) {
              if (separated_along_r<D>(r, q, h, e.q, e.h, sqrt_t, slack_sum))
                return true;
              ImageVector<D> v;
              image_vector_exact(c, e.c, shift, box_, &v);
              double out[2] = {NAN, NAN};
              Status const st = image_contact(v, q, e.q, out);
              if (st == Status::out_of_range && out[0] == HUGE_VAL)
                return true;  // μ² overflows: not within t
              if (st != Status::success) {
                failed = st;
                return false;
              }
              if (!(out[0] < t)) return true;
              Hit<D> hit{e.id, {}, out[0], out[1]};
              for (int k = 0; k < D; ++k) hit.shift[k] = shift[k];
              if (!hits->push_back(hit)) {
                failed = Status::no_memory;
                return false;
              }
              return true;
            });
  if (s == Status::success) s = failed;
  if (s != Status::success) return s;
  std::sort(hits->data(), hits->data() + hits->size(),
            [](Hit<D> const &a, Hit<D> const &b) {
              if (a.id != b.id) return a.id < b.id;
              for (int k = 0; k < D; ++k)
                if (a.shift[k] != b.shift[k]) return a.shift[k] < b.shift[k];
              return false;
            });
  return Status::success;
}

#define PW85_INDEX_QUERIES(D)                                                 \
  template Status Index<D>::overlap_any(double const *, double const *,       \
                                        std::size_t, int *, std::size_t *)    \
      const noexcept;                                                         \
  template Status Index<D>::within(double const *, double const *, double,    \
                                   std::size_t, Buffer<Hit<D>> *) const       \
      noexcept;
PW85_INDEX_QUERIES(2)
PW85_INDEX_QUERIES(3)
#undef PW85_INDEX_QUERIES

}  // namespace pw85::detail::spatial
