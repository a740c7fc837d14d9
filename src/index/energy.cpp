// SPDX-License-Identifier: BSD-3-Clause
// Energy, forces and torques over the pairs of an index (energy.hpp).
//
// For a pair (i, j, n), r = (c_j + n∘L) − c_i, the derivatives of μ²
// (pw85.h, pw85_contact_derivatives(); docs/geometry.rst): g = ∂μ²/∂r,
// and ∂μ²/∂ω_i, ∂μ²/∂ω_j for rotations of each ellipsoid about its
// centre. With U′ = dU/dμ²: force on j −U′·g, on i +U′·g; torque on i
// −U′·∂μ²/∂ω_i, on j −U′·∂μ²/∂ω_j. Overlap energy (docs/packing.rst):
// U = ε(1 − μ)² for μ < 1, 0 beyond, so U′ = dU/dμ·dμ/dμ² = −ε(1 − μ)/μ;
// at μ = 0 (r = 0, coincident centres) every derivative of μ² is 0 and
// the pair adds U = ε and no force.
#include "energy.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "broad.hpp"
#include "geometry.hpp"

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

// The pair term of a pair (i, j, n) given its U and U′ (μ² from `mu2`, or
// from the derivatives when kind is overlap).
Status pair_term(Index const &index, PairHit const &p, EnergySpec const &spec,
                 double u_user, double du_user, PairTerm *out) noexcept {
  double ci[dim], cj[dim], qi[sym], qj[sym];
  Status st = index.get(p.i, ci, qi);
  if (st == Status::success) st = index.get(p.j, cj, qj);
  if (st != Status::success) return st;
  ImageVector v;
  image_vector_exact(ci, cj, p.shift, index.box(), &v);
  // The derivatives at r rounded to doubles (v.r): exact where r is a
  // double (pw85_index.h, "Images"), else within 2⁻⁵³ relative.
  double geometry[geom::size], d[deriv::size];
  st = contact_geometry(v.r, qi, qj, geometry, d);
  if (st != Status::success) return st;
  double u, du;
  if (spec.kind == EnergyKind::overlap) {
    double const mu2 = geometry[geom::mu2];
    double const mu = std::sqrt(mu2);
    if (!(mu < 1.0)) {
      u = 0.0;
      du = 0.0;
    } else {
      u = spec.param * (1.0 - mu) * (1.0 - mu);
      du = mu > 0.0 ? -spec.param * (1.0 - mu) / mu : 0.0;
    }
  } else {
    u = u_user;
    du = du_user;
  }
  out->u = u;
  for (int k = 0; k < dim; ++k) {
    out->f[k] = du == 0.0 ? 0.0 : -du * d[deriv::r12 + k];
    out->ti[k] = du == 0.0 ? 0.0 : -du * d[deriv::rot1 + k];
    out->tj[k] = du == 0.0 ? 0.0 : -du * d[deriv::rot2 + k];
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
                       double *forces, double *torques) noexcept {
  if (!std::isfinite(spec.param)) return Status::not_finite;
  if ((spec.kind != EnergyKind::overlap && spec.kind != EnergyKind::user) ||
      !(spec.param > 0.0) ||
      (spec.kind == EnergyKind::user && spec.fn == nullptr) || threads < 1 ||
      n < ids_in_use(index))
    return Status::invalid_argument;
#if !defined(PW85_OPENMP)
  threads = 1;
#endif
  // The pairs: overlapping or tangent ones for the overlap energy (the
  // others have U = 0), those with μ² < t for a caller's energy.
  Buffer<PairHit> pairs;
  bool const user = spec.kind == EnergyKind::user;
  Status st = index.pairs(user, user ? spec.param : 1.0, threads, &pairs,
                          nullptr);
  if (st != Status::success) return st;
  // U and U′ of a caller's energy, at the μ² of the query, in pair order,
  // in the calling thread.
  Buffer<double> uu;
  if (user) {
    if (!uu.resize_uninitialised(2 * pairs.size())) return Status::no_memory;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      double out[2] = {NAN, NAN};
      if (spec.fn(pairs[k].mu2, spec.data, out) != 0) return Status::cancelled;
      if (!std::isfinite(out[0]) || !std::isfinite(out[1]))
        return Status::not_finite;
      uu[2 * k] = out[0];
      uu[2 * k + 1] = out[1];
    }
  }
  bool const want = forces != nullptr || torques != nullptr;
  Buffer<double> f, t;
  if (want && (!f.resize(3 * n) || !t.resize(3 * n))) return Status::no_memory;
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
      return pair_term(index, pairs[p], spec, user ? uu[2 * p] : 0.0,
                       user ? uu[2 * p + 1] : 0.0, &terms[k]);
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
#pragma omp parallel for num_threads(nt) schedule(dynamic, 256)
      for (long long k = 0; k < mm; ++k) {
        Status const s = one(std::size_t(k));
        if (s != Status::success) {
#pragma omp critical(pw85_energy_failure)
          if (std::size_t(k) < failed) {
            failed = std::size_t(k);
            failure = s;
          }
        }
      }
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
  *energy = sum;
  if (forces != nullptr && n > 0)
    std::memcpy(forces, f.data(), 3 * n * sizeof(double));
  if (torques != nullptr && n > 0)
    std::memcpy(torques, t.data(), 3 * n * sizeof(double));
  return Status::success;
}

}  // namespace pw85::detail
