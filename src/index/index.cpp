// SPDX-License-Identifier: BSD-3-Clause
// The index's storage: insert, update, remove, get (index.hpp). The
// queries: queries.cpp (on a candidate) and pairs.cpp (all pairs).
#include "index.hpp"

#include <algorithm>
#include <cmath>

#include "checks.hpp"
#include "deep.hpp"

namespace pw85::detail::spatial {

template <int D>
Index<D>::Index(double const *box) noexcept : periodic_(box != nullptr) {
  if (periodic_)
    for (int k = 0; k < D; ++k) box_[k] = box[k];
}

template <int D>
Status Index<D>::check_centre(double const *c) const noexcept {
  if (!all_finite<D>(c)) return Status::not_finite;
  for (int k = 0; k < D; ++k)
    if (!(std::fabs(c[k]) <= (periodic_ ? max_wraps * box_[k] : max_centre)))
      return Status::invalid_argument;
  return Status::success;
}

template <int D>
bool Index<D>::fits_box(double const *h) const noexcept {
  if (periodic_)
    for (int k = 0; k < D; ++k)
      if (!(2.0 * h[k] * (1.0 + broad_margin) < box_[k])) return false;
  return true;
}

template <int D>
Status Index<D>::check_ellipsoid(double const *c, double const *q) const
    noexcept {
  if (!(all_finite<D>(c) && all_finite<S>(q))) return Status::not_finite;
  if (!is_positive_definite<D>(q)) return Status::not_positive_definite;
  return check_centre(c);
}

template <int D>
void Index<D>::wraps(double const *c, std::int32_t *w) const noexcept {
  for (int k = 0; k < D; ++k)
    w[k] = periodic_ ? static_cast<std::int32_t>(std::floor(c[k] / box_[k]))
                     : 0;
}

template <int D>
int Index<D>::make_entry(std::size_t id, double const *c, double const *q,
                         Entry<D> *e) const noexcept {
  for (int k = 0; k < D; ++k) e->c[k] = c[k];
  wraps(c, e->wrap);
  for (int k = 0; k < S; ++k) e->q[k] = q[k];
  half_widths<D>(q, e->h);
  e->rho = inscribed_radius<D>(q);
  e->id = static_cast<std::uint32_t>(id);
  return level_exponent<D>(e->h);
}

template <int D>
void Index<D>::init_level(Level<D> *lv, int exponent) const noexcept {
  lv->exponent = exponent;
  double const side = std::ldexp(1.0, exponent + hash_cell_octaves);
  for (int k = 0; k < D; ++k) {
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

template <int D>
int Index<D>::level_of(int exponent) const noexcept {
  int l = 0;
  while (l < int(levels_.size()) && levels_[l].exponent != exponent) ++l;
  return l;
}

namespace {

double clamp_open(double m) noexcept {
  return std::min(std::max(m, -open_half), open_half - 1.0);
}

}  // namespace

template <int D>
void Index<D>::cell_coords(Level<D> const &lv, double const *c,
                           std::int32_t const *wrap, std::uint64_t *u) const
    noexcept {
  for (int k = 0; k < D; ++k) {
    if (periodic_) {
      double const w = c[k] - wrap[k] * box_[k];
      double const m = std::min(std::max(std::floor(w * lv.inv[k]), 0.0),
                                double(lv.n[k] - 1));
      u[k] = static_cast<std::uint64_t>(m);
    } else {
      u[k] = static_cast<std::uint64_t>(
          clamp_open(std::floor(c[k] * lv.inv[k])) + open_half);
    }
  }
}

template <int D>
bool Index<D>::add_level(int exponent) noexcept {
  Level<D> lv;
  init_level(&lv, exponent);
  if (periodic_) {
    double cells = double(lv.n[0]);
    for (int k = 1; k < D; ++k) cells *= double(lv.n[k]);
    if (cells <= dense_cells) {
      std::size_t const n = static_cast<std::size_t>(cells);
      if (!lv.dense.resize_uninitialised(n)) return false;
      for (std::size_t i = 0; i < n; ++i) lv.dense[i] = CellMap::absent;
    }
  }
  return levels_.push_back(static_cast<Level<D> &&>(lv));
}

template <int D>
bool Index<D>::reserve_for(Entry<D> const &e, int exponent) noexcept {
  int const l = level_of(exponent);
  if (l == int(levels_.size()) && !add_level(exponent)) return false;
  Level<D> &lv = levels_[l];
  std::uint64_t u[D];
  cell_coords(lv, e.c, e.wrap, u);
  std::uint32_t c = lv.find(u);
  if (c == CellMap::absent) {
    // A new empty cell is a valid state: it is registered at once.
    Cell<D> cell;
    if (lv.cells.size() >= no_id || (lv.dense.empty() && !lv.map.reserve_one()) ||
        !lv.cells.grow_for(1) || !cell.grow_for(1))
      return false;
    c = static_cast<std::uint32_t>(lv.cells.size());
    lv.cells.push_back_reserved(static_cast<Cell<D> &&>(cell));
    if (lv.dense.empty())
      lv.map.insert_reserved(Level<D>::pack(u), c);
    else
      lv.dense[lv.dense_index(u)] = c;
  }
  return lv.cells[c].grow_for(1);
}

template <int D>
void Index<D>::insert_entry(Entry<D> const &e, int exponent) noexcept {
  int const l = level_of(exponent);
  Level<D> &lv = levels_[l];
  std::uint64_t u[D];
  cell_coords(lv, e.c, e.wrap, u);
  std::uint32_t const c = lv.find(u);
  Cell<D> &cell = lv.cells[c];
  Entry<D> copy = e;
  cell.push_back_reserved(static_cast<Entry<D> &&>(copy));
  slots_[e.id] = Slot{l, c, static_cast<std::uint32_t>(cell.size() - 1)};
  ++lv.count;
  for (int k = 0; k < D; ++k) {
    lv.hmax[k] = std::max(lv.hmax[k], e.h[k]);
    cmax_ = std::max(cmax_, std::fabs(e.c[k]));
  }
  ++count_;
}

template <int D>
void Index<D>::erase(std::size_t id) noexcept {
  Slot const s = slots_[id];
  Level<D> &lv = levels_[s.level];
  Cell<D> &cell = lv.cells[s.cell];
  if (s.index + 1 != cell.size()) {  // the last entry takes its place
    cell[s.index] = cell.back();
    slots_[cell[s.index].id].index = s.index;
  }
  cell.pop_back();
  slots_[id] = Slot{};
  if (--lv.count == 0)
    for (int k = 0; k < D; ++k) lv.hmax[k] = 0.0;
  --count_;
}

template <int D>
Status Index<D>::insert(std::size_t id, double const *c,
                        double const *q) noexcept {
  Status const s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (id > max_id || (id < slots_.size() && slots_[id].level >= 0))
    return Status::invalid_argument;
  Entry<D> e;
  int const exponent = make_entry(id, c, q, &e);
  if (!fits_box(e.h)) return Status::invalid_argument;
  if ((id >= slots_.size() && !slots_.resize(id + 1)) ||
      !reserve_for(e, exponent))
    return Status::no_memory;
  insert_entry(e, exponent);
  return Status::success;
}

template <int D>
Status Index<D>::insert_many(std::size_t n, std::size_t const *ids,
                          double const *c, double const *q,
                          int threads) noexcept {
  if (n >= bulk_min && n < no_id) return insert_bulk(n, ids, c, q, threads);
  std::size_t top = 0;
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, ids[i]);
  if (n > 0 && top <= max_id && top >= slots_.size() &&
      !slots_.resize(top + 1))
    return Status::no_memory;
  // One by one; on error, the ones inserted are removed in reverse order,
  // each the last entry of its cell then, which restores every cell as it
  // was.
  for (std::size_t i = 0; i < n; ++i) {
    Status const s = insert(ids[i], c + D * i, q + S * i);
    if (s != Status::success) {
      while (i-- > 0) erase(ids[i]);
      return s;
    }
  }
  return Status::success;
}

template <int D>
Status Index<D>::update(std::size_t id, double const *c,
                        double const *q) noexcept {
  Status const s = check_ellipsoid(c, q);
  if (s != Status::success) return s;
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  Entry<D> e;
  int const exponent = make_entry(id, c, q, &e);
  if (!fits_box(e.h)) return Status::invalid_argument;
  if (!reserve_for(e, exponent)) return Status::no_memory;
  erase(id);
  insert_entry(e, exponent);
  return Status::success;
}

template <int D>
Status Index<D>::remove(std::size_t id) noexcept {
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  erase(id);
  return Status::success;
}

template <int D>
Status Index<D>::get(std::size_t id, double *c, double *q) const noexcept {
  if (id >= slots_.size() || slots_[id].level < 0)
    return Status::invalid_argument;
  Slot const s = slots_[id];
  Entry<D> const &e = levels_[s.level].cells[s.cell][s.index];
  for (int k = 0; k < D; ++k) c[k] = e.c[k];
  for (int k = 0; k < S; ++k) q[k] = e.q[k];
  return Status::success;
}

// The members of this file, for both dimensions (the private ones that
// bulk.cpp also calls included).
#define PW85_INDEX_STORAGE(D)                                                 \
  template Index<D>::Index(double const *) noexcept;                          \
  template Status Index<D>::check_ellipsoid(double const *, double const *)   \
      const noexcept;                                                         \
  template bool Index<D>::fits_box(double const *) const noexcept;            \
  template int Index<D>::make_entry(std::size_t, double const *,              \
                                    double const *, Entry<D> *) const noexcept; \
  template void Index<D>::wraps(double const *, std::int32_t *) const noexcept; \
  template void Index<D>::cell_coords(Level<D> const &, double const *,       \
                                      std::int32_t const *, std::uint64_t *)  \
      const noexcept;                                                         \
  template bool Index<D>::add_level(int) noexcept;                            \
  template Status Index<D>::insert(std::size_t, double const *,               \
                                   double const *) noexcept;                  \
  template Status Index<D>::insert_many(std::size_t, std::size_t const *,     \
                                        double const *, double const *, int)  \
      noexcept;                                                               \
  template Status Index<D>::update(std::size_t, double const *,               \
                                   double const *) noexcept;                  \
  template Status Index<D>::remove(std::size_t) noexcept;                     \
  template Status Index<D>::get(std::size_t, double *, double *) const noexcept;
PW85_INDEX_STORAGE(2)
PW85_INDEX_STORAGE(3)
#undef PW85_INDEX_STORAGE

}  // namespace pw85::detail::spatial
