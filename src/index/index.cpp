// SPDX-License-Identifier: BSD-3-Clause
// The index's storage and the queries on a candidate (index.hpp).
#include "index.hpp"

#include <algorithm>
#include <cmath>

#include "checks.hpp"
#include "cholesky.hpp"
#include "contact.hpp"
#include "overlap.hpp"

namespace pw85::detail {

void half_widths(double const q[sym], double h[dim]) noexcept {
  for (int k = 0; k < dim; ++k) h[k] = std::sqrt(q[diag_of[k]]);
}

namespace {

// Is every Q_kk in [2⁻³⁰⁰, 2³⁰⁰]? The range in which the shortcuts of
// overlap_any() work (inscribed radii, the candidate's factor): nothing
// below over- or underflows, and two such forms are within the range that
// pw85_overlap() accepts.
bool moderate_diagonal(double const q[sym]) noexcept {
  double const lo = std::min(std::min(q[0], q[3]), q[5]);
  double const hi = std::max(std::max(q[0], q[3]), q[5]);
  return lo >= 0x1p-300 && hi <= 0x1p300;
}

// Does the Cholesky factorisation of Q − s·I (cholesky_decomp()) complete
// with every pivot > 0? (Then Q − s·I + E is positive definite for some
// ‖E‖₂ < 2⁻⁴⁸·M, M = max Q_kk ≥ s: see inscribed_radius() in index.hpp.)
bool definite_after_shift(double const q[sym], double s) noexcept {
  double a[sym], l[sym];
  for (int k = 0; k < sym; ++k) a[k] = q[k];
  for (int k = 0; k < dim; ++k) a[diag_of[k]] -= s;
  return cholesky_decomp(a, l);
}

// An estimate of λmin(Q), not certified: the trigonometric solution of
// the characteristic cubic (O. K. Smith, Commun. ACM 4(4), 168, 1961).
double least_eigenvalue_estimate(double const q[sym]) noexcept {
  double const off = q[1] * q[1] + q[2] * q[2] + q[4] * q[4];
  double const m = (q[0] + q[3] + q[5]) / 3.0;
  double const b0 = q[0] - m, b1 = q[3] - m, b2 = q[5] - m;
  double const p = std::sqrt((b0 * b0 + b1 * b1 + b2 * b2 + 2.0 * off) / 6.0);
  if (!(p > 0.0)) return m;  // Q = m·I
  // det(B)/2 for B = (Q − m·I)/p.
  double const c0 = b0 / p, c1 = b1 / p, c2 = b2 / p;
  double const e01 = q[1] / p, e02 = q[2] / p, e12 = q[4] / p;
  double const half_det = 0.5 * (c0 * (c1 * c2 - e12 * e12) -
                                 e01 * (e01 * c2 - e12 * e02) +
                                 e02 * (e01 * e12 - c1 * e02));
  double const phi =
      std::acos(std::min(1.0, std::max(-1.0, half_det))) / 3.0;
  return m + 2.0 * p * std::cos(phi + 2.0943951023931957);  // + 2π/3
}

}  // namespace

double inscribed_radius(double const q[sym]) noexcept {
  if (!moderate_diagonal(q)) return 0.0;
  double const m = std::max(std::max(q[0], q[3]), q[5]);
  double const margin = 0x1p-46 * m;
  // First the cubic's estimate, lowered by 2⁻¹⁶ of itself; if the check
  // fails (an ill-conditioned Q, whose λmin the estimate gets wrong), the
  // bound λmin(Q) ≥ 1/‖Q⁻¹‖_F (Q⁻¹ = adj(Q)/det(Q)), lowered by 2⁻¹⁰.
  double est = least_eigenvalue_estimate(q) * (1.0 - 0x1p-16);
  if (!(est >= 0x1p-900 && est <= m &&
        definite_after_shift(q, est + margin))) {
    double const a00 = q[3] * q[5] - q[4] * q[4];
    double const a01 = q[2] * q[4] - q[1] * q[5];
    double const a02 = q[1] * q[4] - q[2] * q[3];
    double const a11 = q[0] * q[5] - q[2] * q[2];
    double const a12 = q[1] * q[2] - q[0] * q[4];
    double const a22 = q[0] * q[3] - q[1] * q[1];
    double const det = q[0] * a00 + q[1] * a01 + q[2] * a02;
    double const frob = std::sqrt(a00 * a00 + a11 * a11 + a22 * a22 +
                                  2.0 * (a01 * a01 + a02 * a02 + a12 * a12));
    est = det / frob * (1.0 - 0x1p-10);
    if (!(est >= 0x1p-900 && est <= m &&
          definite_after_shift(q, est + margin)))
      return 0.0;  // also NaN
  }
  // λmin(Q) > est; √est rounds up by half an ulp at most: lowered below.
  return std::sqrt(est) * (1.0 - 0x1p-50);
}

Index::Index(double const box[dim]) noexcept : periodic_(box != nullptr) {
  if (periodic_)
    for (int k = 0; k < dim; ++k) box_[k] = box[k];
}

Status Index::check_centre(double const c[dim]) const noexcept {
  if (!all_finite<dim>(c)) return Status::not_finite;
  if (periodic_)
    for (int k = 0; k < dim; ++k)
      if (!(std::fabs(c[k]) <= max_wraps * box_[k]))
        return Status::invalid_argument;
  return Status::success;
}

Status Index::check_ellipsoid(double const c[dim], double const q[sym]) const
    noexcept {
  if (!(all_finite<dim>(c) && all_finite<sym>(q))) return Status::not_finite;
  if (!is_positive_definite(q)) return Status::not_positive_definite;
  return check_centre(c);
}

void Index::make_entry(std::size_t id, double const c[dim],
                       double const q[sym], Entry *e) const noexcept {
  for (int k = 0; k < dim; ++k) {
    e->c[k] = c[k];
    e->wrap[k] = periodic_
                     ? static_cast<std::int32_t>(std::floor(c[k] / box_[k]))
                     : 0;
  }
  for (int k = 0; k < sym; ++k) e->q[k] = q[k];
  half_widths(q, e->h);
  e->rho = inscribed_radius(q);
  e->id = static_cast<std::uint32_t>(id);
}

void Index::init_level(Level *lv, int exponent) const noexcept {
  lv->exponent = exponent;
  double const side = std::ldexp(1.0, exponent + hash_cell_octaves);
  for (int k = 0; k < dim; ++k) {
    if (periodic_) {
      double const n = std::min(std::max(std::floor(box_[k] / side), 1.0),
                                max_span);
      lv->n[k] = static_cast<std::int64_t>(n);
      lv->side[k] = box_[k] / n;
      lv->inv[k] = n / box_[k];
    } else {
      lv->n[k] = 0;
      lv->side[k] = side;
      lv->inv[k] = std::ldexp(1.0, -exponent - hash_cell_octaves);
    }
  }
}

int Index::level_of(Entry const &e) const noexcept {
  int exponent = 0;
  std::frexp(std::max(std::max(e.h[0], e.h[1]), e.h[2]), &exponent);
  int l = 0;
  while (l < int(levels_.size()) && levels_[l].exponent != exponent) ++l;
  return l;
}

namespace {

// An open domain's cell coordinates are clamped to [−2²⁰, 2²⁰) (the clamp
// is monotone: a range of positions maps onto the range of their cells).
constexpr double open_half = 0x1p20;

double clamp_open(double m) noexcept {
  return std::min(std::max(m, -open_half), open_half - 1.0);
}

}  // namespace

void Index::cell_coords(Level const &lv, Entry const &e,
                        std::uint64_t u[dim]) const noexcept {
  for (int k = 0; k < dim; ++k) {
    if (periodic_) {
      double const w = e.c[k] - e.wrap[k] * box_[k];
      double const m = std::min(std::max(std::floor(w * lv.inv[k]), 0.0),
                                double(lv.n[k] - 1));
      u[k] = static_cast<std::uint64_t>(m);
    } else {
      u[k] = static_cast<std::uint64_t>(
          clamp_open(std::floor(e.c[k] * lv.inv[k])) + open_half);
    }
  }
}

bool Index::reserve_for(Entry const &e) noexcept {
  int const l = level_of(e);
  if (l == int(levels_.size())) {
    int exponent = 0;
    std::frexp(std::max(std::max(e.h[0], e.h[1]), e.h[2]), &exponent);
    Level lv;
    init_level(&lv, exponent);
    if (periodic_) {
      double const cells = double(lv.n[0]) * double(lv.n[1]) * double(lv.n[2]);
      if (cells <= dense_cells) {
        std::size_t const n = static_cast<std::size_t>(cells);
        if (!lv.dense.resize_uninitialised(n)) return false;
        for (std::size_t i = 0; i < n; ++i) lv.dense[i] = CellMap::absent;
      }
    }
    if (!levels_.push_back(static_cast<Level &&>(lv))) return false;
  }
  Level &lv = levels_[l];
  std::uint64_t u[dim];
  cell_coords(lv, e, u);
  std::uint32_t c = lv.find(u);
  if (c == CellMap::absent) {
    // A new empty cell is a valid state: it is registered at once.
    Cell cell;
    if (lv.cells.size() >= no_id || (lv.dense.empty() && !lv.map.reserve_one()) ||
        !lv.cells.grow_for(1) || !cell.grow_for(1))
      return false;
    c = static_cast<std::uint32_t>(lv.cells.size());
    lv.cells.push_back_reserved(static_cast<Cell &&>(cell));
    if (lv.dense.empty())
      lv.map.insert_reserved(Level::pack(u), c);
    else
      lv.dense[lv.dense_index(u)] = c;
  }
  return lv.cells[c].grow_for(1);
}

void Index::insert_entry(Entry const &e) noexcept {
  int const l = level_of(e);
  Level &lv = levels_[l];
  std::uint64_t u[dim];
  cell_coords(lv, e, u);
  std::uint32_t const c = lv.find(u);
  Cell &cell = lv.cells[c];
  Entry copy = e;
  cell.push_back_reserved(static_cast<Entry &&>(copy));
  slots_[e.id] = Slot{l, c, static_cast<std::uint32_t>(cell.size() - 1)};
  ++lv.count;
  for (int k = 0; k < dim; ++k) {
    lv.hmax[k] = std::max(lv.hmax[k], e.h[k]);
    cmax_ = std::max(cmax_, std::fabs(e.c[k]));
  }
  ++count_;
}

void Index::erase(std::size_t id) noexcept {
  Slot const s = slots_[id];
  Level &lv = levels_[s.level];
  Cell &cell = lv.cells[s.cell];
  if (s.index + 1 != cell.size()) {  // the last entry takes its place
    cell[s.index] = cell.back();
    slots_[cell[s.index].id].index = s.index;
  }
  cell.pop_back();
  slots_[id] = Slot{};
  if (--lv.count == 0)
    for (int k = 0; k < dim; ++k) lv.hmax[k] = 0.0;
  --count_;
}

Status Index::insert(std::size_t id, double const c[dim],
                     double const q[sym]) noexcept {
  Status const s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (id > max_id || (id < slots_.size() && slots_[id].level >= 0))
    return Status::invalid_argument;
  Entry e;
  make_entry(id, c, q, &e);
  if (periodic_)
    for (int k = 0; k < dim; ++k)
      if (!(2.0 * e.h[k] * (1.0 + broad_margin) < box_[k]))
        return Status::invalid_argument;
  if ((id >= slots_.size() && !slots_.resize(id + 1)) || !reserve_for(e))
    return Status::no_memory;
  insert_entry(e);
  return Status::success;
}

Status Index::insert_many(std::size_t n, std::size_t const *ids,
                          double const *c, double const *q) noexcept {
  std::size_t top = 0;
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, ids[i]);
  if (n > 0 && top <= max_id && top >= slots_.size() &&
      !slots_.resize(top + 1))
    return Status::no_memory;
  // One by one; on error, the ones inserted are removed in reverse order,
  // each the last entry of its cell then, which restores every cell as it
  // was.
  for (std::size_t i = 0; i < n; ++i) {
    Status const s = insert(ids[i], c + dim * i, q + sym * i);
    if (s != Status::success) {
      while (i-- > 0) erase(ids[i]);
      return s;
    }
  }
  return Status::success;
}

Status Index::update(std::size_t id, double const c[dim],
                     double const q[sym]) noexcept {
  Status const s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  Entry e;
  make_entry(id, c, q, &e);
  if (periodic_)
    for (int k = 0; k < dim; ++k)
      if (!(2.0 * e.h[k] * (1.0 + broad_margin) < box_[k]))
        return Status::invalid_argument;
  if (!reserve_for(e)) return Status::no_memory;
  erase(id);
  insert_entry(e);
  return Status::success;
}

Status Index::remove(std::size_t id) noexcept {
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  erase(id);
  return Status::success;
}

Status Index::get(std::size_t id, double c[dim], double q[sym]) const
    noexcept {
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  Slot const s = slots_[id];
  Entry const &e = levels_[s.level].cells[s.cell][s.index];
  for (int k = 0; k < dim; ++k) c[k] = e.c[k];
  for (int k = 0; k < sym; ++k) q[k] = e.q[k];
  return Status::success;
}

// ---- queries on a candidate -------------------------------------------

template <typename F>
Status Index::visit_level(Level const &lv, double const c[dim],
                          double const h[dim],
                          double sqrt_t, std::uint32_t exclude,
                          bool nearest_first, bool *go_on, F &f) const
    noexcept {
  double reach[dim], lo[dim], hi[dim];
  double cells = 1.0;
  for (int k = 0; k < dim; ++k) {
    reach[k] = sqrt_t * (h[k] + lv.hmax[k]) * (1.0 + broad_margin);
    double const slack = cell_slack(cmax_, c[k], reach[k], box_[k]);
    lo[k] = std::floor((c[k] - reach[k] - slack) * lv.inv[k]);
    hi[k] = std::floor((c[k] + reach[k] + slack) * lv.inv[k]);
    if (!periodic_) {
      lo[k] = clamp_open(lo[k]);
      hi[k] = clamp_open(hi[k]);
    }
    cells *= hi[k] - lo[k] + 1.0;
  }
  // The AABB test of one image, then f (which tests the rest); false
  // stops the visit.
  auto test = [&](Entry const &e, std::int32_t const shift[dim]) {
    double r[dim];
    for (int k = 0; k < dim; ++k) {
      r[k] = (e.c[k] + shift[k] * box_[k]) - c[k];
      if (!(std::fabs(r[k]) <= sqrt_t * (h[k] + e.h[k]) * (1.0 + broad_margin)))
        return true;
    }
    return f(e, shift, r);
  };

  if (cells > 2.0 * double(lv.cells.size()) + 8.0) {
    // Wider than the level: every entry, with the shifts in reach.
    for (std::size_t ci = 0; ci < lv.cells.size(); ++ci) {
      Cell const &cell = lv.cells[ci];
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry const &e = cell[ei];
        if (e.id == exclude) continue;
        std::int64_t nlo[dim] = {0, 0, 0}, nhi[dim] = {0, 0, 0};
        if (periodic_) {
          for (int k = 0; k < dim; ++k) {
            double const slack = cell_slack(cmax_, c[k], reach[k], box_[k]);
            double const a = std::floor((c[k] - reach[k] - slack - e.c[k]) / box_[k]);
            double const b = std::floor((c[k] + reach[k] + slack - e.c[k]) / box_[k]) + 1.0;
            if (b - a + 1.0 > max_span) return Status::out_of_range;
            nlo[k] = static_cast<std::int64_t>(a);
            nhi[k] = static_cast<std::int64_t>(b);
          }
        }
        std::int32_t shift[dim];
        for (std::int64_t a = nlo[0]; a <= nhi[0]; ++a)
          for (std::int64_t b = nlo[1]; b <= nhi[1]; ++b)
            for (std::int64_t d = nlo[2]; d <= nhi[2]; ++d) {
              shift[0] = std::int32_t(a);
              shift[1] = std::int32_t(b);
              shift[2] = std::int32_t(d);
              if (!test(e, shift)) {
                *go_on = false;
                return Status::success;
              }
            }
      }
    }
    return Status::success;
  }

  // The cells in reach are gathered in batches, then their entries are
  // tested: the cache misses of a batch (cell headers, then entries) are
  // issued together (prefetches), not one dependent chain per cell, which
  // made most of the time of random sequential addition (perf).
  struct Pending {
    Cell const *cell;
    std::int64_t copy[dim];
  };
  constexpr int batch = 64;
  Pending pending[batch];
  int np = 0;
  auto flush = [&]() {  // false when the visit stops
    for (int i = 0; i < np; ++i) {
      Cell const &cell = *pending[i].cell;
      // Both cache lines of each entry: the second (form, inscribed
      // radius) is read for every entry whose AABB meets the candidate's;
      // random sequential addition of 1e5 (bench-index) took 12% less
      // time per attempt than with the first line alone.
      for (std::size_t ei = 0; ei < cell.size(); ++ei)
        PW85_INDEX_PREFETCH(&cell[ei]), PW85_INDEX_PREFETCH(&cell[ei].q[2]);
    }
    std::int32_t shift[dim];
    for (int i = 0; i < np; ++i) {
      Cell const &cell = *pending[i].cell;
      for (std::size_t ei = 0; ei < cell.size(); ++ei) {
        Entry const &e = cell[ei];
        if (e.id == exclude) continue;
        for (int k = 0; k < dim; ++k)
          shift[k] = static_cast<std::int32_t>(pending[i].copy[k] - e.wrap[k]);
        if (!test(e, shift)) return false;
      }
    }
    np = 0;
    return true;
  };
  // Visits the cells m (unwrapped) of the block [from, to] but those of
  // the block [skip_lo, skip_hi]; false when the visit stops. Cell m along
  // axis k is the cell u = m − copy·n_k of the copy ⌊m / n_k⌋ of the box
  // (periodic), followed incrementally along each axis, without a
  // division per cell.
  auto scan = [&](std::int64_t const from[dim], std::int64_t const to[dim],
                  std::int64_t const skip_lo[dim],
                  std::int64_t const skip_hi[dim]) {
    std::int64_t u0[dim], copy0[dim];
    for (int k = 0; k < dim; ++k) {
      if (periodic_) {
        copy0[k] = floor_div(from[k], lv.n[k]);
        u0[k] = from[k] - copy0[k] * lv.n[k];
      } else {
        copy0[k] = 0;
        u0[k] = from[k] + std::int64_t(open_half);
      }
    }
    auto advance = [&](int k, std::uint64_t *u, std::int64_t *copy) {
      ++*u;
      if (periodic_ && std::int64_t(*u) == lv.n[k]) {
        *u = 0;
        ++*copy;
      }
    };
    std::uint64_t u[dim];
    std::int64_t copy[dim];
    if (!lv.dense.empty()) {  // the rows' first cells, fetched together
      u[0] = std::uint64_t(u0[0]);
      copy[0] = copy0[0];
      for (std::int64_t a = from[0]; a <= to[0]; ++a) {
        u[1] = std::uint64_t(u0[1]);
        copy[1] = copy0[1];
        for (std::int64_t b = from[1]; b <= to[1]; ++b) {
          u[2] = std::uint64_t(u0[2]);
          PW85_INDEX_PREFETCH(&lv.dense[lv.dense_index(u)]);
          advance(1, &u[1], &copy[1]);
        }
        advance(0, &u[0], &copy[0]);
      }
    }
    u[0] = std::uint64_t(u0[0]);
    copy[0] = copy0[0];
    for (std::int64_t a = from[0]; a <= to[0]; ++a) {
      bool const in0 = skip_lo[0] <= a && a <= skip_hi[0];
      u[1] = std::uint64_t(u0[1]);
      copy[1] = copy0[1];
      for (std::int64_t b = from[1]; b <= to[1]; ++b) {
        bool const in01 = in0 && skip_lo[1] <= b && b <= skip_hi[1];
        u[2] = std::uint64_t(u0[2]);
        copy[2] = copy0[2];
        for (std::int64_t d = from[2]; d <= to[2]; ++d) {
          std::uint32_t const ci =
              in01 && skip_lo[2] <= d && d <= skip_hi[2] ? CellMap::absent
                                                          : lv.find(u);
          if (ci != CellMap::absent) {
            Pending &p = pending[np++];
            p.cell = &lv.cells[ci];
            PW85_INDEX_PREFETCH(p.cell);
            for (int k = 0; k < dim; ++k) p.copy[k] = copy[k];
            if (np == batch && !flush()) return false;
          }
          advance(2, &u[2], &copy[2]);
        }
        advance(1, &u[1], &copy[1]);
      }
      advance(0, &u[0], &copy[0]);
    }
    return flush();
  };
  std::int64_t from[dim], to[dim], none_lo[dim], none_hi[dim];
  for (int k = 0; k < dim; ++k) {
    from[k] = std::int64_t(lo[k]);
    to[k] = std::int64_t(hi[k]);
    none_lo[k] = 1;  // an empty block: nothing skipped
    none_hi[k] = 0;
  }
  if (nearest_first) {
    // First the cells that hold points within half a cell of c (at most
    // two along each axis, inside the reach): a query that stops at the
    // first overlap finds one there most often (random sequential
    // addition near saturation rejects most candidates), before fetching
    // the rest of the block. Every cell is still visited once.
    std::int64_t near_lo[dim], near_hi[dim];
    for (int k = 0; k < dim; ++k) {
      double const half = 0.5 * lv.side[k];
      double a = std::floor((c[k] - half) * lv.inv[k]);
      double b = std::floor((c[k] + half) * lv.inv[k]);
      if (!periodic_) {
        a = clamp_open(a);
        b = clamp_open(b);
      }
      near_lo[k] = std::max(from[k], std::int64_t(a));
      near_hi[k] = std::min(to[k], std::int64_t(b));
    }
    if (!scan(near_lo, near_hi, none_lo, none_hi) ||
        !scan(from, to, near_lo, near_hi))
      *go_on = false;
    return Status::success;
  }
  if (!scan(from, to, none_lo, none_hi)) *go_on = false;
  return Status::success;
}

template <typename F>
Status Index::visit(double const c[dim], double const h[dim], double sqrt_t,
                    std::uint32_t exclude, bool nearest_first, F &&f) const
    noexcept {
  bool go_on = true;
  for (std::size_t l = 0; l < levels_.size() && go_on; ++l) {
    if (levels_[l].count == 0) continue;
    Status const s =
        visit_level(levels_[l], c, h, sqrt_t, exclude, nearest_first,
                    &go_on, f);
    if (s != Status::success) return s;
  }
  return Status::success;
}

namespace {

std::uint32_t to_exclude(std::size_t id) noexcept {
  return id > max_id ? no_id : static_cast<std::uint32_t>(id);
}

// The shortcut of overlap_any() for deep overlaps: the point p of the
// segment from the candidate's centre c to the stored one's, c + r, at distance
// ρ_e·(1 − 2⁻²⁰) from c + r, lies inside the stored ellipsoid scaled by
// 1 − 2⁻²⁰ (its inscribed ball); is it inside the candidate so scaled,
// ((p − c)ᵀQ⁻¹(p − c) ≤ (1 − 2⁻²⁰)²)? With p − c = (t/|r|)·r, t = |r| −
// ρ_e·(1 − 2⁻²⁰): t·√(rᵀQ⁻¹r) ≤ |r|·(1 − 2⁻²⁰). rᵀQ⁻¹r = |L⁻¹r|², L the
// Cholesky factor of Q (lq): the computed factor and forward substitution
// give the exact |y|² of some Q + E, ‖E‖₂ ≤ (γ₄ + 2γ₃ + γ₃²)·tr(Q) <
// 2⁻⁴⁸·tr(Q) (Higham, Accuracy and Stability of Numerical Algorithms, 2nd
// ed., th. 10.3 and 8.5, with ‖|L||Lᵀ|‖₂ ≤ ‖L‖_F² ≈ tr(Q)), so that
// rᵀQ⁻¹r ≤ |y|²/(1 − η), η = ‖E‖₂/(λmin(Q) − ‖E‖₂) < 2⁻²⁷ when
// tr(Q) ≤ 2²⁰·λmin(Q) (line_factor() checks it). The test below
// inflates |y|² by 2⁻²², t by 2⁻⁴⁸·(|r| + ρ_e) (its rounding error and
// that of |r|) and lowers the bound to |r|·(1 − 2⁻¹⁹): a margin far
// above the few roundings of the products and square roots. d2 = |r|²
// as computed.
bool deep_overlap(double const lq[sym], double const r[dim], double d2,
                  double rho_e) noexcept {
  double y[dim];
  forward_solve(lq, r, y);
  double const a = dot(y, y) * (1.0 + 0x1p-22);
  double const d = std::sqrt(d2);
  double const t = d - rho_e * (1.0 - 0x1p-20) + 0x1p-48 * (d + rho_e);
  return t <= 0.0 || t * std::sqrt(a) < d * (1.0 - 0x1p-19);
}

// The candidate's side of deep_overlap(): its Cholesky factor l, when
// moderate_diagonal(q) (as for an inscribed radius) and tr(Q) ≤ 2²⁰·s for a
// certified lower bound s of λmin(Q). The computed factor L is that of
// some Q + ΔA, ‖ΔA‖₂ ≤ γ₄·‖L‖_F² < 2⁻⁵⁰·tr(Q) (Higham th. 10.3), and for a
// 3×3 matrix σmin(L) = |det L|/(σ₁σ₂) ≥ 2·|det L|/‖L‖_F², so λmin(Q) ≥
// (2·L₀₀L₁₁L₂₂/‖L‖_F²)² − 2⁻⁵⁰·tr(Q); s lowers the first term by 2⁻⁴⁰ (its
// dozen roundings) and the second is taken as 2⁻⁴⁸·tr(Q). No eigenvalue
// is computed: a query factors its candidate once.
bool line_factor(double const q[sym], double l[sym]) noexcept {
  if (!moderate_diagonal(q) || !cholesky_decomp(q, l)) return false;
  double const tr = q[0] + q[3] + q[5];
  double f = 0.0;
  for (int k = 0; k < sym; ++k) f += l[k] * l[k];
  double const g = 2.0 * (l[0] * l[3] * l[5]) / f;
  double const s = g * g * (1.0 - 0x1p-40) - 0x1p-48 * tr;
  return s > 0.0 && tr <= 0x1p20 * s;
}

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
  // The candidate's Cholesky factor for deep_overlap() (line = 1; 0 when
  // not usable, −1 not yet known), and a bound of its semi-axes.
  double lq[sym], reach = 0.0;
  int line = -1;
  s = visit(c, h, 1.0, to_exclude(exclude), true,
            [&](Entry const &e, std::int32_t const *, double const r[dim]) {
              // Deep overlaps, decided without the narrow phase: a point
              // inside both ellipsoids scaled by 1 − 2⁻²⁰, so μ² ≤
              // (1 − 2⁻²⁰)² < 1 − 2⁻²⁰ and pw85_overlap() would give −1,
              // far outside its 4-ulp band (deep_overlap(); ρ_e > 0 and
              // line_factor() keep the pair within the range of
              // pw85_overlap()).
              if (e.rho > 0.0) {
                if (line < 0) {
                  line = line_factor(q, lq);
                  reach = 1.5 * std::sqrt(q[0] + q[3] + q[5]);  // > every semi-axis
                }
                // Only if the candidate may reach the stored ellipsoid's
                // ball (a filter: it decides nothing).
                double const d2 = dot(r, r);
                double const gap = reach + e.rho;
                if (line > 0 && d2 < gap * gap && deep_overlap(lq, r, d2, e.rho)) {
                  best = -1;
                  best_id = e.id;
                  return false;
                }
              }
              if (separated_along_r(r, q, h, e.q, e.h, 1.0)) return true;
              int res = 1;
              failed = overlap(r, q, e.q, &res);
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
            [&](Entry const &e, std::int32_t const *shift,
                double const r[dim]) {
              if (separated_along_r(r, q, h, e.q, e.h, sqrt_t))
                return true;
              double out[2] = {NAN, NAN};
              Status const st = contact_function(r, q, e.q, out);
              if (st == Status::out_of_range && out[0] == HUGE_VAL)
                return true;  // μ² overflows: not within t
              if (st != Status::success) {
                failed = st;
                return false;
              }
              if (!(out[0] < t)) return true;
              Hit hit{e.id, {shift[0], shift[1], shift[2]}, 0, out[0], out[1]};
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
