// SPDX-License-Identifier: BSD-3-Clause
// Energy, forces and torques over the pairs of an index (energy.hpp).
//
// For a pair (i, j, n), r = (c_j + n∘L) − c_i, the derivatives of μ²
// (pw85.h, pw85_contact_derivatives(); docs/geometry.rst): g = ∂μ²/∂r,
// and ∂μ²/∂ω_i, ∂μ²/∂ω_j for rotations of each ellipsoid about its
// centre, computed from the maximiser λ of the all-pairs query (one search
// per pair). With U′ = dU/dμ²: force on j −U′·g, on i +U′·g; torque on i
// −U′·∂μ²/∂ω_i, on j −U′·∂μ²/∂ω_j. Overlap energy (docs/packing.rst):
// U = ε(1 − μ)² for μ < 1, 0 beyond, so U′ = dU/dμ·dμ/dμ² = −ε(1 − μ)/μ;
// at μ = 0 (r = 0, coincident centres) every derivative of μ² is 0 and
// the pair adds U = ε and no force.
#include "energy.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "broad.hpp"
#include "geometry.hpp"
#include "ldl.hpp"

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail {

namespace {

// What a pair adds: U, −U′·g (the force on j), and the torques on i and j.
struct PairTerm {
  double u;
  double f[dim];
  double ti[dim];
  double tj[dim];
};

// Pairs computed per block: the terms of a block are held, then summed in
// order (bounded memory whatever the number of pairs).
constexpr std::size_t block_pairs = std::size_t(1) << 16;

// The derivatives of μ² from the maximiser λ of the pair's search
// (pw85.h, pw85_contact_derivatives(), by the envelope theorem), with
// s = Q(λ)⁻¹·r solved in double on Q(λ) scaled by a power of two:
// g = 2λ(1 − λ)·s, ∂μ²/∂ω1 = 2λ(1 − λ)²·s × (Q1·s),
// ∂μ²/∂ω2 = 2λ²(1 − λ)·s × (Q2·s). False when Q(λ) does not factorise
// or a result is not finite (the caller then takes the full
// contact_geometry()).
bool derivatives_at(double const r[dim], double const q1[sym],
                    double const q2[sym], double lambda, double g[dim],
                    double w1[dim], double w2[dim]) noexcept {
  double q[sym];
  for (int k = 0; k < sym; ++k) q[k] = (1.0 - lambda) * q1[k] + lambda * q2[k];
  double const tr = q[0] + q[3] + q[5];
  if (!(tr > 0.0) || !std::isfinite(tr)) return false;
  int const e = -std::ilogb(tr);
  for (int k = 0; k < sym; ++k) q[k] = std::ldexp(q[k], e);
  Ldl f;
  if (!ldl_decomp(q, &f)) return false;
  double sv[dim];
  ldl_solve(f, r, sv);
  for (int k = 0; k < dim; ++k) sv[k] = std::ldexp(sv[k], e);
  double t1[dim], t2[dim];
  sym_mul(q1, sv, t1);
  sym_mul(q2, sv, t2);
  double const a = 2.0 * lambda * (1.0 - lambda);
  double const b1 = a * (1.0 - lambda), b2 = a * lambda;
  for (int k = 0; k < dim; ++k) {
    int const j = (k + 1) % dim, l = (k + 2) % dim;
    g[k] = a * sv[k];
    w1[k] = b1 * (sv[j] * t1[l] - sv[l] * t1[j]);
    w2[k] = b2 * (sv[j] * t2[l] - sv[l] * t2[j]);
  }
  for (int k = 0; k < dim; ++k)
    if (!std::isfinite(g[k]) || !std::isfinite(w1[k]) || !std::isfinite(w2[k]))
      return false;
  return true;
}

// U and U′ of the overlap energy at μ².
void overlap_energy(double eps, double mu2, double *u, double *du) noexcept {
  double const mu = std::sqrt(mu2);
  if (!(mu < 1.0)) {
    *u = *du = 0.0;
  } else {
    *u = eps * (1.0 - mu) * (1.0 - mu);
    *du = mu > 0.0 ? -eps * (1.0 - mu) / mu : 0.0;
  }
}

// The pair term of a pair (i, j, n): U and U′ given (a caller's energy,
// μ² and λ from the query), or, for the overlap energy (overlap ≥ 0: ε),
// μ² and λ from the search of pw85_contact_function() on the exact image
// vector, as the query with μ² would have found them (broad.hpp,
// image_contact()).
// A stored ellipsoid, by id (gather()).
struct Stored {
  double c[dim];
  double q[sym];
};

// Every stored ellipsoid into all[id], read in the order of the cells'
// storage: the pairs then read two records each, not the index's slots,
// cells and entries (Index::get(): about four cache misses a call, 15 % of
// the time of the overlap energy at N = 1e6, perf).
bool gather(Index const &index, Buffer<Stored> *all) noexcept {
  if (!all->resize_uninitialised(index.id_bound())) return false;
  Buffer<Level> const &levels = index.levels();
  for (std::size_t l = 0; l < levels.size(); ++l) {
    Buffer<Cell> const &cells = levels[l].cells;
    for (std::size_t m = 0; m < cells.size(); ++m) {
      Cell const &cell = cells[m];
      for (std::size_t k = 0; k < cell.size(); ++k) {
        Entry const &e = cell[k];
        Stored &s = (*all)[e.id];
        for (int a = 0; a < dim; ++a) s.c[a] = e.c[a];
        for (int a = 0; a < sym; ++a) s.q[a] = e.q[a];
      }
    }
  }
  return true;
}

Status pair_term(Index const &index, Stored const *all, PairHit const &p,
                 double overlap, double u, double du, PairTerm *out) noexcept {
  double const *ci = all[p.i].c, *qi = all[p.i].q;
  double const *cj = all[p.j].c, *qj = all[p.j].q;
  Status st = Status::success;
  ImageVector v;
  image_vector_exact(ci, cj, p.shift, index.box(), &v);
  double mu2 = p.mu2, lambda = p.lambda;
  if (overlap >= 0.0) {
    double ml[2] = {NAN, NAN};
    st = image_contact(v, qi, qj, ml);
    if (st != Status::success) return st;
    mu2 = ml[0];
    lambda = ml[1];
    overlap_energy(overlap, mu2, &u, &du);
  }
  out->u = u;
  for (int k = 0; k < dim; ++k) out->f[k] = out->ti[k] = out->tj[k] = 0.0;
  if (du == 0.0 || mu2 == 0.0) return Status::success;  // no force
  // r rounded to doubles (v.r): exact where r is a double (pw85_index.h,
  // "Images"), else within 2⁻⁵³ relative.
  double g[dim], w1[dim], w2[dim];
  if (!derivatives_at(v.r, qi, qj, lambda, g, w1, w2)) {
    double geometry[geom::size], d[deriv::size];
    st = contact_geometry(v.r, qi, qj, geometry, d);
    if (st != Status::success) return st;
    for (int k = 0; k < dim; ++k) {
      g[k] = d[deriv::r12 + k];
      w1[k] = d[deriv::rot1 + k];
      w2[k] = d[deriv::rot2 + k];
    }
  }
  for (int k = 0; k < dim; ++k) {
    out->f[k] = -du * g[k];
    out->ti[k] = -du * w1[k];
    out->tj[k] = -du * w2[k];
  }
  return Status::success;
}

// The largest stored id plus one (0 when empty).
std::size_t ids_in_use(Index const &index) noexcept {
  double c[dim], q[sym];
  for (std::size_t id = index.id_bound(); id > 0; --id)
    if (index.get(id - 1, c, q) == Status::success) return id;
  return 0;
}

}  // namespace

Status assembly_energy(Index const &index, EnergySpec const &spec,
                       int threads, std::size_t n, double *energy,
                       double *forces, double *torques,
                       std::size_t *npairs) noexcept {
  if (!std::isfinite(spec.param)) return Status::not_finite;
  if ((spec.kind != EnergyKind::overlap && spec.kind != EnergyKind::user) ||
      !(spec.param > 0.0) ||
      (spec.kind == EnergyKind::user && spec.fn == nullptr) || threads < 1 ||
      n < ids_in_use(index))
    return Status::invalid_argument;
  bool const want = forces != nullptr || torques != nullptr;
  // Rows of 3·n doubles that no array can hold (3·n would wrap around).
  if (want && n > std::size_t(-1) / (3 * sizeof(double)))
    return Status::no_memory;
#if !defined(PW85_OPENMP)
  threads = 1;
#endif
  // The pairs: for a caller's energy, those with μ² < t, with μ² and λ;
  // for the overlap energy, the overlapping or tangent ones (the others
  // have U = 0), decided by the filters of pw85_overlap(), then searched
  // (μ², λ) in pair_term(): one search per pair that has a force.
  Buffer<PairHit> pairs;
  bool const user = spec.kind == EnergyKind::user;
  Status st = index.pairs(user, user ? spec.param : 1.0, threads, &pairs,
                          nullptr);
  if (st != Status::success) return st;
  // U and U′ of a caller's energy at the μ² of the query, in pair order,
  // in the calling thread.
  Buffer<double> uu;
  if (user && !uu.resize_uninitialised(2 * pairs.size()))
    return Status::no_memory;
  for (std::size_t k = 0; user && k < pairs.size(); ++k) {
    double out[2] = {NAN, NAN};
    if (spec.fn(pairs[k].mu2, spec.data, out) != 0) return Status::cancelled;
    if (!std::isfinite(out[0]) || !std::isfinite(out[1]))
      return Status::not_finite;
    uu[2 * k] = out[0];
    uu[2 * k + 1] = out[1];
  }
  Buffer<double> f, t;
  if (want && (!f.resize(3 * n) || !t.resize(3 * n))) return Status::no_memory;
  Buffer<Stored> all;
  if (!gather(index, &all)) return Status::no_memory;
  Buffer<PairTerm> terms;
  if (!terms.resize_uninitialised(std::min(block_pairs, pairs.size())))
    return Status::no_memory;
  double sum = 0.0;
  for (std::size_t b0 = 0; b0 < pairs.size(); b0 += block_pairs) {
    std::size_t const m = std::min(block_pairs, pairs.size() - b0);
    // Each pair alone (the least failing pair's status is returned).
    std::size_t failed = m;
    Status failure = Status::success;
    auto one = [&](std::size_t k) -> Status {
      std::size_t const p = b0 + k;
      return user ? pair_term(index, all.data(), pairs[p], -1.0, uu[2 * p],
                              uu[2 * p + 1], &terms[k])
                  : pair_term(index, all.data(), pairs[p], spec.param, 0.0,
                              0.0, &terms[k]);
    };
    int const nt = int(std::min<std::size_t>(std::size_t(threads), m / 256 + 1));
    if (nt <= 1) {
      for (std::size_t k = 0; k < m && failed == m; ++k) {
        Status const s = one(k);
        if (s != Status::success) {
          failed = k;
          failure = s;
        }
      }
    } else {
#if defined(PW85_OPENMP)
      long long const mm = static_cast<long long>(m);
      // The least failing pair by an atomic minimum (a named critical
      // section would export a symbol from the static library), its status
      // computed again after the loop: each pair's term is a function of
      // the pair alone.
      std::atomic<std::size_t> first{m};
#pragma omp parallel for num_threads(nt) schedule(dynamic, 256)
      for (long long k = 0; k < mm; ++k) {
        if (one(std::size_t(k)) == Status::success) continue;
        std::size_t seen = first.load(std::memory_order_relaxed);
        while (std::size_t(k) < seen &&
               !first.compare_exchange_weak(seen, std::size_t(k),
                                            std::memory_order_relaxed)) {
        }
      }
      failed = first.load();
      if (failed < m) failure = one(failed);
#endif
    }
    if (failure != Status::success) return failure;
    // The sums, in pair order.
    for (std::size_t k = 0; k < m; ++k) {
      PairTerm const &x = terms[k];
      PairHit const &p = pairs[b0 + k];
      sum += x.u;
      if (!want) continue;
      for (int a = 0; a < dim; ++a) {
        f[3 * p.j + a] += x.f[a];
        f[3 * p.i + a] -= x.f[a];
        t[3 * p.i + a] += x.ti[a];
        t[3 * p.j + a] += x.tj[a];
      }
    }
  }
  // A sum beyond the range of a double (finite pair terms, too many or
  // too large) is reported, not returned as an infinity.
  if (!std::isfinite(sum)) return Status::out_of_range;
  for (std::size_t k = 0; want && k < 3 * n; ++k)
    if ((forces != nullptr && !std::isfinite(f[k])) ||
        (torques != nullptr && !std::isfinite(t[k])))
      return Status::out_of_range;
  *energy = sum;
  if (npairs != nullptr) *npairs = pairs.size();
  if (forces != nullptr && n > 0)
    std::memcpy(forces, f.data(), 3 * n * sizeof(double));
  if (torques != nullptr && n > 0)
    std::memcpy(torques, t.data(), 3 * n * sizeof(double));
  return Status::success;
}

}  // namespace pw85::detail
