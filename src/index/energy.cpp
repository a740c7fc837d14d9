// SPDX-License-Identifier: BSD-3-Clause
// Energy, forces and torques over the pairs of an index (energy.hpp),
// written once for D = 3 and D = 2 ("ellipsoid" reads "ellipse" in 2D).
//
// For a pair (i, j, n), r = (c_j + n∘L) − c_i, the derivatives of μ²
// (pw85.h, pw85_contact_derivatives(), and pw85_2d.h,
// pw85_2d_contact_derivatives(); docs/geometry.rst): g = ∂μ²/∂r,
// and ∂μ²/∂ω_i, ∂μ²/∂ω_j for rotations of each ellipsoid about its
// centre (a rotation vector in 3D, the angle θ in 2D), computed from the
// maximiser λ of the all-pairs query (one search per pair). With
// U′ = dU/dμ²: force on j −U′·g, on i +U′·g; torque on i −U′·∂μ²/∂ω_i,
// on j −U′·∂μ²/∂ω_j. Overlap energy (docs/packing.rst):
// U = ε(1 − μ)² for μ < 1, 0 beyond, so U′ = dU/dμ·dμ/dμ² = −ε(1 − μ)/μ;
// at μ = 0 (r = 0, coincident centres) every derivative of μ² is 0 and
// the pair adds U = ε and no force.
#include "energy.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "batch.hpp"
#include "broad.hpp"
#include "geometry.hpp"
#include "ldl.hpp"

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail {

namespace {

// The doubles of a torque: 3 in 3D, 1 in 2D.
template <int D>
constexpr int rot = Outputs<D>::rot_size;

// What a pair adds: U, −U′·g (the force on j), and the torques on i and j.
template <int D>
struct PairTerm {
  double u;
  double f[D];
  double ti[rot<D>];
  double tj[rot<D>];
};

// Pairs computed per block: the terms of a block are held, then summed in
// order (bounded memory whatever the number of pairs).
constexpr std::size_t block_pairs = std::size_t(1) << 16;

// The derivatives of μ² from the maximiser λ of the pair's search
// (pw85.h, pw85_contact_derivatives(), by the envelope theorem), with
// s = Q(λ)⁻¹·r solved in double on Q(λ) scaled by a power of two:
// g = 2λ(1 − λ)·s, ∂μ²/∂ω1 = 2λ(1 − λ)²·s × (Q1·s),
// ∂μ²/∂ω2 = 2λ²(1 − λ)·s × (Q2·s) (in 2D the one component along z of
// these cross products, as geometry.cpp's cross_dd()). False when Q(λ)
// does not factorise or a result is not finite (the caller then takes
// the full contact_geometry()).
template <int D>
bool derivatives_at(double const *r, double const *q1, double const *q2,
                    double lambda, double g[D], double w1[rot<D>],
                    double w2[rot<D>]) noexcept {
  constexpr int S = sym_size(D);
  double q[S];
  for (int k = 0; k < S; ++k) q[k] = (1.0 - lambda) * q1[k] + lambda * q2[k];
  double const tr = trace<D>(q);
  if (!(tr > 0.0) || !std::isfinite(tr)) return false;
  int const e = -std::ilogb(tr);
  for (int k = 0; k < S; ++k) q[k] = std::ldexp(q[k], e);
  Ldl<D> f;
  if (!ldl_decomp(q, &f)) return false;
  double sv[D];
  ldl_solve(f, r, sv);
  for (int k = 0; k < D; ++k) sv[k] = std::ldexp(sv[k], e);
  double t1[D], t2[D];
  sym_mul<D>(q1, sv, t1);
  sym_mul<D>(q2, sv, t2);
  double const a = 2.0 * lambda * (1.0 - lambda);
  double const b1 = a * (1.0 - lambda), b2 = a * lambda;
  for (int k = 0; k < D; ++k) g[k] = a * sv[k];
  for (int m = 0; m < rot<D>; ++m) {
    int const k = D == 3 ? m : 2;  // the component
    int const j = (k + 1) % 3, l = (k + 2) % 3;
    w1[m] = b1 * (sv[j] * t1[l] - sv[l] * t1[j]);
    w2[m] = b2 * (sv[j] * t2[l] - sv[l] * t2[j]);
  }
  for (int k = 0; k < D; ++k)
    if (!std::isfinite(g[k])) return false;
  for (int m = 0; m < rot<D>; ++m)
    if (!std::isfinite(w1[m]) || !std::isfinite(w2[m])) return false;
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
template <int D>
struct Stored {
  double c[D];
  double q[sym_size(D)];
};

// Every stored ellipsoid into all[id], read in the order of the cells'
// storage: the pairs then read two records each, not the index's slots,
// cells and entries (Index::get(): about four cache misses a call, 15 % of
// the time of the overlap energy at N = 1e6, perf).
template <int D>
bool gather(spatial::Index<D> const &index, Buffer<Stored<D>> *all) noexcept {
  if (!all->resize_uninitialised(index.id_bound())) return false;
  Buffer<spatial::Level<D>> const &levels = index.levels();
  for (std::size_t l = 0; l < levels.size(); ++l) {
    Buffer<spatial::Cell<D>> const &cells = levels[l].cells;
    for (std::size_t m = 0; m < cells.size(); ++m) {
      spatial::Cell<D> const &cell = cells[m];
      for (std::size_t k = 0; k < cell.size(); ++k) {
        spatial::Entry<D> const &e = cell[k];
        Stored<D> &s = (*all)[e.id];
        for (int a = 0; a < D; ++a) s.c[a] = e.c[a];
        for (int a = 0; a < sym_size(D); ++a) s.q[a] = e.q[a];
      }
    }
  }
  return true;
}

template <int D>
Status pair_term(spatial::Index<D> const &index, Stored<D> const *all,
                 spatial::PairHit<D> const &p, double overlap, double u,
                 double du, PairTerm<D> *out) noexcept {
  double const *ci = all[p.i].c, *qi = all[p.i].q;
  double const *cj = all[p.j].c, *qj = all[p.j].q;
  Status st = Status::success;
  spatial::ImageVector<D> v;
  spatial::image_vector_exact<D>(ci, cj, p.shift, index.box(), &v);
  double mu2 = p.mu2, lambda = p.lambda;
  if (overlap >= 0.0) {
    double ml[2] = {NAN, NAN};
    st = spatial::image_contact(v, qi, qj, ml);
    if (st != Status::success) return st;
    mu2 = ml[0];
    lambda = ml[1];
    overlap_energy(overlap, mu2, &u, &du);
  }
  out->u = u;
  for (int k = 0; k < D; ++k) out->f[k] = 0.0;
  for (int m = 0; m < rot<D>; ++m) out->ti[m] = out->tj[m] = 0.0;
  if (du == 0.0 || mu2 == 0.0) return Status::success;  // no force
  // r rounded to doubles (v.r): exact where r is a double (pw85_index.h,
  // "Images"), else within 2⁻⁵³ relative.
  using O = Outputs<D>;
  double g[D], w1[rot<D>], w2[rot<D>];
  if (!derivatives_at<D>(v.r, qi, qj, lambda, g, w1, w2)) {
    double geometry[O::size], d[O::deriv_size];
    st = contact_geometry<D>(v.r, qi, qj, geometry, d);
    if (st != Status::success) return st;
    for (int k = 0; k < D; ++k) g[k] = d[O::r12 + k];
    for (int m = 0; m < rot<D>; ++m) {
      w1[m] = d[O::rot1 + m];
      w2[m] = d[O::rot2 + m];
    }
  }
  for (int k = 0; k < D; ++k) out->f[k] = -du * g[k];
  for (int m = 0; m < rot<D>; ++m) {
    out->ti[m] = -du * w1[m];
    out->tj[m] = -du * w2[m];
  }
  return Status::success;
}

// The largest stored id plus one (0 when empty).
template <int D>
std::size_t ids_in_use(spatial::Index<D> const &index) noexcept {
  double c[D], q[sym_size(D)];
  for (std::size_t id = index.id_bound(); id > 0; --id)
    if (index.get(id - 1, c, q) == Status::success) return id;
  return 0;
}

}  // namespace

template <int D>
Status assembly_energy(spatial::Index<D> const &index,
                       EnergySpec const &spec, int threads, std::size_t n,
                       double *energy, double *forces, double *torques,
                       std::size_t *npairs) noexcept {
  constexpr int R = rot<D>;
  if (!std::isfinite(spec.param)) return Status::not_finite;
  if ((spec.kind != EnergyKind::overlap && spec.kind != EnergyKind::user) ||
      !(spec.param > 0.0) ||
      (spec.kind == EnergyKind::user && spec.fn == nullptr) || threads < 1 ||
      n < ids_in_use(index))
    return Status::invalid_argument;
  bool const want = forces != nullptr || torques != nullptr;
  // Rows of D·n doubles that no array can hold (D·n would wrap around).
  if (want && n > std::size_t(-1) / (D * sizeof(double)))
    return Status::no_memory;
#if !defined(PW85_OPENMP)
  threads = 1;
#endif
  // The pairs: for a caller's energy, those with μ² < t, with μ² and λ;
  // for the overlap energy, the overlapping or tangent ones (the others
  // have U = 0), decided by the filters of pw85_overlap(), then searched
  // (μ², λ) in pair_term(): one search per pair that has a force.
  Buffer<spatial::PairHit<D>> pairs;
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
  if (want && (!f.resize(D * n) || !t.resize(R * n))) return Status::no_memory;
  Buffer<Stored<D>> all;
  if (!gather(index, &all)) return Status::no_memory;
  Buffer<PairTerm<D>> terms;
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
    int const nt = team_size(threads, m / 256 + 1);
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
      PairTerm<D> const &x = terms[k];
      spatial::PairHit<D> const &p = pairs[b0 + k];
      sum += x.u;
      if (!want) continue;
      for (int a = 0; a < D; ++a) {
        f[D * p.j + a] += x.f[a];
        f[D * p.i + a] -= x.f[a];
      }
      for (int a = 0; a < R; ++a) {
        t[R * p.i + a] += x.ti[a];
        t[R * p.j + a] += x.tj[a];
      }
    }
  }
  // A sum beyond the range of a double (finite pair terms, too many or
  // too large) is reported, not returned as an infinity.
  if (!std::isfinite(sum)) return Status::out_of_range;
  for (std::size_t k = 0; forces != nullptr && k < D * n; ++k)
    if (!std::isfinite(f[k])) return Status::out_of_range;
  for (std::size_t k = 0; torques != nullptr && k < R * n; ++k)
    if (!std::isfinite(t[k])) return Status::out_of_range;
  *energy = sum;
  if (npairs != nullptr) *npairs = pairs.size();
  if (forces != nullptr && n > 0)
    std::memcpy(forces, f.data(), D * n * sizeof(double));
  if (torques != nullptr && n > 0)
    std::memcpy(torques, t.data(), R * n * sizeof(double));
  return Status::success;
}

template Status assembly_energy<2>(spatial::Index<2> const &,
                                   EnergySpec const &, int, std::size_t,
                                   double *, double *, double *,
                                   std::size_t *) noexcept;
template Status assembly_energy<3>(spatial::Index<3> const &,
                                   EnergySpec const &, int, std::size_t,
                                   double *, double *, double *,
                                   std::size_t *) noexcept;

}  // namespace pw85::detail
