// SPDX-License-Identifier: BSD-3-Clause
// The queries on a candidate (index.hpp): the visit of the grid's cells
// within reach (the broad phase of broad.hpp), and overlap_any() and
// within(), its visitors.
#include <algorithm>
#include <cmath>

#include "compiler.hpp"
#include "deep.hpp"
#include "index.hpp"

namespace pw85::detail {

namespace {

// The visit of blocks of cells of a level: the cells in reach are
// gathered in batches, then their entries are tested; the cache misses of
// a batch (cell headers, then entries) are issued together (prefetches),
// not one dependent chain per cell, which made most of the time of random
// sequential addition (perf). Cell m along axis k (unwrapped) is the cell
// u = m − copy·n_k of the copy ⌊m / n_k⌋ of the box (periodic), followed
// incrementally along each axis, without a division per cell. test(e,
// shift) tests an entry's image; false stops the visit.
template <typename Test>
class CellScan {
 public:
  CellScan(Level const &lv, bool periodic, std::uint32_t exclude,
           Test &test) noexcept
      : lv_(lv), periodic_(periodic), exclude_(exclude), test_(test) {}

  // Visits the cells of the block [from, to] but those of the block
  // [skip_lo, skip_hi] (none when empty); false when the visit stops.
  bool scan(std::int64_t const from[dim], std::int64_t const to[dim],
            std::int64_t const skip_lo[dim],
            std::int64_t const skip_hi[dim]) noexcept {
    std::uint64_t u0[dim], u[dim];
    std::int64_t copy0[dim], copy[dim];
    start(from, u0, copy0);
    if (!lv_.dense.empty()) prefetch_rows(from, to, u0, copy0);
    u[0] = u0[0], copy[0] = copy0[0];
    for (std::int64_t a = from[0]; a <= to[0]; ++a) {
      bool const in0 = skip_lo[0] <= a && a <= skip_hi[0];
      u[1] = u0[1], copy[1] = copy0[1];
      for (std::int64_t b = from[1]; b <= to[1]; ++b) {
        bool const in01 = in0 && skip_lo[1] <= b && b <= skip_hi[1];
        u[2] = u0[2], copy[2] = copy0[2];
        for (std::int64_t d = from[2]; d <= to[2]; ++d) {
          bool const skip = in01 && skip_lo[2] <= d && d <= skip_hi[2];
          std::uint32_t const ci = skip ? CellMap::absent : lv_.find(u);
          if (ci != CellMap::absent && !add(&lv_.cells[ci], copy))
            return false;
          advance(2, &u[2], &copy[2]);
        }
        advance(1, &u[1], &copy[1]);
      }
      advance(0, &u[0], &copy[0]);
    }
    return flush();
  }

 private:
  static constexpr int batch = 64;
  struct Pending {
    Cell const *cell;
    std::int64_t copy[dim];
  };

  // The cell coordinates u and box copy of the unwrapped cell m = from.
  void start(std::int64_t const from[dim], std::uint64_t u[dim],
             std::int64_t copy[dim]) const noexcept {
    for (int k = 0; k < dim; ++k) {
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
  // The dense array's entries of the rows' first cells, fetched together.
  void prefetch_rows(std::int64_t const from[dim], std::int64_t const to[dim],
                     std::uint64_t const u0[dim],
                     std::int64_t const copy0[dim]) const noexcept {
    std::uint64_t u[dim] = {u0[0], u0[1], u0[2]};
    std::int64_t copy[dim] = {copy0[0], copy0[1], copy0[2]};
    for (std::int64_t a = from[0]; a <= to[0]; ++a) {
      u[1] = u0[1], copy[1] = copy0[1];
      for (std::int64_t b = from[1]; b <= to[1]; ++b) {
        PW85_PREFETCH(&lv_.dense[lv_.dense_index(u)]);
        advance(1, &u[1], &copy[1]);
      }
      advance(0, &u[0], &copy[0]);
    }
  }
  bool add(Cell const *cell, std::int64_t const copy[dim]) noexcept {
    Pending &p = pending_[np_++];
    p.cell = cell;
    PW85_PREFETCH(cell);
    for (int k = 0; k < dim; ++k) p.copy[k] = copy[k];
    return np_ < batch || flush();
  }
  // Tests the entries of the pending cells; false when the visit stops.
  bool flush() noexcept {
    for (int i = 0; i < np_; ++i) {
      Cell const &cell = *pending_[i].cell;
      // Both cache lines of each entry: the second (form, inscribed
      // radius) is read for every entry whose AABB meets the candidate's;
      // random sequential addition of 1e5 (bench-index) took 12% less
      // time per attempt than with the first line alone.
      for (std::size_t ei = 0; ei < cell.size(); ++ei)
        PW85_PREFETCH(&cell[ei]), PW85_PREFETCH(&cell[ei].q[2]);
    }
    std::int32_t shift[dim];
    for (int i = 0; i < np_; ++i) {
      Cell const &cell = *pending_[i].cell;
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry const &e = cell[ei];
        if (e.id == exclude_) continue;
        for (int k = 0; k < dim; ++k)
          shift[k] = static_cast<std::int32_t>(pending_[i].copy[k] - e.wrap[k]);
        if (!test_(e, static_cast<std::int32_t const *>(shift))) return false;
      }
    }
    np_ = 0;
    return true;
  }

  Level const &lv_;
  bool periodic_;
  std::uint32_t exclude_;
  Test &test_;
  Pending pending_[batch];
  int np_ = 0;
};

// The cells that hold points within half a cell of c (at most two along
// each axis), inside the block [from, to].
PW85_INLINE void nearest_cells(Level const &lv, bool periodic, double const c[dim],
                   std::int64_t const from[dim], std::int64_t const to[dim],
                   std::int64_t lo[dim], std::int64_t hi[dim]) noexcept {
  for (int k = 0; k < dim; ++k) {
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

template <typename Test>
Status Index::visit_every_entry(Level const &lv, double const c[dim],
                                Reach const &rc, std::uint32_t exclude,
                                bool *go_on, Test &test) const noexcept {
  for (std::size_t ci = 0; ci < lv.cells.size(); ++ci) {
    Cell const &cell = lv.cells[ci];
    for (std::size_t ei = 0; ei < cell.size(); ++ei) {
      Entry const &e = cell[ei];
      if (e.id == exclude) continue;
      std::int64_t lo[dim], hi[dim];
      if (!shift_range(periodic_, c, rc.reach, rc.slack, e.c, box_, lo, hi))
        return Status::out_of_range;
      if (!for_each_shift(lo, hi, [&](std::int32_t const *shift) {
            return test(e, shift);
          })) {
        *go_on = false;
        return Status::success;
      }
    }
  }
  return Status::success;
}

template <typename F>
Status Index::visit_level(Level const &lv, double const c[dim],
                          double const h[dim], double sqrt_t,
                          std::uint32_t exclude, bool nearest_first,
                          bool *go_on, F &f) const noexcept {
  Reach const rc = reach_of(c, h, lv.hmax, sqrt_t, cmax_, box_);
  // The box test of one image, then f (which tests the rest); false stops
  // the visit.
  auto test = [&](Entry const &e, std::int32_t const *shift) {
    double r[dim];
    if (!boxes_meet(c, h, e.c, e.h, shift, box_, sqrt_t, rc.slack, r))
      return true;
    return f(e, shift, static_cast<double const *>(r), rc.slack_sum);
  };
  double const zero[dim] = {0.0, 0.0, 0.0};
  double first[dim], last[dim], lo[dim], hi[dim];
  for (int k = 0; k < dim; ++k) {
    first[k] = periodic_ ? -HUGE_VAL : -open_half;
    last[k] = periodic_ ? HUGE_VAL : open_half - 1.0;
  }
  double const cells = cell_range(rc, c, zero, lv.inv, first, last, lo, hi);
  if (cells > 2.0 * double(lv.cells.size()) + 8.0)
    return visit_every_entry(lv, c, rc, exclude, go_on, test);

  CellScan<decltype(test)> scan(lv, periodic_, exclude, test);
  std::int64_t from[dim], to[dim], none_lo[dim], none_hi[dim];
  for (int k = 0; k < dim; ++k) {
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
    std::int64_t near_lo[dim], near_hi[dim];
    nearest_cells(lv, periodic_, c, from, to, near_lo, near_hi);
    if (!scan.scan(near_lo, near_hi, none_lo, none_hi) ||
        !scan.scan(from, to, near_lo, near_hi))
      *go_on = false;
    return Status::success;
  }
  if (!scan.scan(from, to, none_lo, none_hi)) *go_on = false;
  return Status::success;
}

template <typename F>
Status Index::visit(double const c[dim], double const h[dim], double sqrt_t,
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
struct CandidateFactor {
  int known = -1;  // 1: usable; 0: not; −1: not yet computed
  double l[sym];
  double lambda_min = 0.0;
  double reach = 0.0;

  bool usable(double const q[sym]) noexcept {
    if (known < 0) {
      known = line_factor(q, l, &lambda_min);
      reach = 1.5 * std::sqrt(q[0] + q[3] + q[5]);  // > every semi-axis
    }
    return known > 0;
  }
};

}  // namespace

Status Index::overlap_any(double const c[dim], double const q[sym],
                          std::size_t exclude, int *result,
                          std::size_t *id) const noexcept {
  Status s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  double h[dim];
  half_widths(q, h);
  Status failed = Status::success;
  int best = 1;
  std::uint32_t best_id = no_id;
  CandidateFactor cf;
  s = visit(c, h, 1.0, to_exclude(exclude), true,
            [&](Entry const &e, std::int32_t const *shift, double const *r,
                double slack_sum) {
              // Deep overlaps, decided without the narrow phase
              // (deep.hpp); only if the candidate may reach the stored
              // ellipsoid's ball (a filter: it decides nothing).
              if (e.rho > 0.0 && cf.usable(q)) {
                double const d2 = dot(r, r);
                double const gap = cf.reach + e.rho;
                if (d2 < gap * gap &&
                    slack_sum * slack_sum <= deep_slack * cf.lambda_min &&
                    deep_overlap(cf.l, r, d2, e.rho)) {
                  best = -1;
                  best_id = e.id;
                  return false;
                }
              }
              if (separated_along_r(r, q, h, e.q, e.h, 1.0, slack_sum))
                return true;
              ImageVector v;
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

Status Index::within(double const c[dim], double const q[sym], double t,
                     std::size_t exclude, Buffer<Hit> *hits) const noexcept {
  Status s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (!std::isfinite(t)) return Status::not_finite;
  if (!(t > 0.0)) return Status::invalid_argument;
  double h[dim];
  half_widths(q, h);
  Status failed = Status::success;
  double const sqrt_t = std::sqrt(t);
  s = visit(c, h, sqrt_t, to_exclude(exclude), false,
            [&](Entry const &e, std::int32_t const *shift, double const *r,
                double slack_sum) {
              if (separated_along_r(r, q, h, e.q, e.h, sqrt_t, slack_sum))
                return true;
              ImageVector v;
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
              Hit hit{e.id, {shift[0], shift[1], shift[2]}, out[0], out[1]};
              if (!hits->push_back(hit)) {
                failed = Status::no_memory;
                return false;
              }
              return true;
            });
  if (s == Status::success) s = failed;
  if (s != Status::success) return s;
  std::sort(hits->data(), hits->data() + hits->size(),
            [](Hit const &a, Hit const &b) {
              if (a.id != b.id) return a.id < b.id;
              for (int k = 0; k < dim; ++k)
                if (a.shift[k] != b.shift[k]) return a.shift[k] < b.shift[k];
              return false;
            });
  return Status::success;
}

}  // namespace pw85::detail
