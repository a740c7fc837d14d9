// SPDX-License-Identifier: BSD-3-Clause
// The voxel image (raster.hpp; docs/microstructures.rst, "Voxel image").
//
// The predicate. A point m is in the ellipsoid {m : dᵀQ⁻¹d ≤ 1}, d = m − c,
// iff P = eᵀ adj(Q′) e − det(Q′) ≤ 0, where, with N = diag(2·n_k) and the
// grid point m_k = o_k + (i_k + ½)·L_k/n_k,
//   e = N·d,     e_k = (2i_k + 1)·L_k − 2n_k·c_k + 2n_k·o_k,
//   Q′ = N·Q·N,  Q′_ab = (4·n_a·n_b)·Q_ab,
// since dᵀQ⁻¹d = eᵀQ′⁻¹e and Q′⁻¹ = adj(Q′)/det(Q′), det(Q′) > 0. Every
// factor above is a double (2i + 1, 2n_k and 4n_a·n_b are integers below
// 2⁵³: |i| ≤ 2⁴⁹ and n_k ≤ 2²⁰, raster.hpp), so P is a polynomial in
// doubles: its sign is exact_sign() of its 114 monomials (exact.cpp).
// Along a row (i, j fixed) P is a convex quadratic in e₂, whose derivative
// has the sign of G = A′₂₀e₀ + A′₂₁e₁ + A′₂₂e₂ (A′ = adj(Q′), A′₂₂ > 0),
// also decided exactly (18 monomials).
//
// The filter (Shewchuk's adaptive pattern): each predicate is first
// evaluated in doubles, in the order written below, together with the same
// expression on absolute values, M. The longest chain of rounded operations
// has 11 of them (e: 3, A′: 3, A′·e·e: 5, the sum: 8, − det: 9; det: 6),
// so |fl(P) − P| ≤ γ₁₁·M ≤ γ₁₁/(1 − γ₁₁)·fl(M) < 2⁻⁴⁹·fl(M) (Higham,
// Accuracy and Stability, §3.1), without underflow nor overflow; the sign
// of fl(P) is taken when |fl(P)| > 2⁻⁴⁶·fl(M) (8 times that bound) and no
// underflow, overflow or invalid operation was flagged while the row was
// evaluated; otherwise the row is evaluated again, exactly. (Where the
// environment does not raise the underflow flag, flags_work(), every
// predicate is exact.) The caller's floating-point exception flags are
// restored.
//
// The row. By convexity, the indices k of a row whose point is inside form
// an interval, contained in the ellipsoid's bounding box [kmin, kmax]
// (half-widths √Q_kk, with a margin of 2 voxels: bbox() below). Let k be
// the first index of the box with G(k) ≥ 0 (kmax if none): P decreases
// before k − 1 and increases after k, so the interval, if not empty,
// contains k − 1 or k; its ends are then found by monotone steps from
// floating-point guesses of the roots. The voxels tested are decided by the
// certified predicates, the others by convexity.
//
// Threads. The planes i are cut into chunks; a thread draws into its
// chunk's planes every ellipsoid (and image) that meets them, each voxel
// taking the least position that covers it: the image does not depend on
// the order, hence neither on the number of threads.
#include "image/raster.hpp"

#include <algorithm>
#include <cfenv>
#include <cmath>
#include <cstring>

#include "batch.hpp"
#include "checks.hpp"
#include "compiler.hpp"
#include "image/exact.hpp"

#if defined(PW85_OPENMP)
#include <omp.h>
#endif

namespace pw85::detail {
namespace {

constexpr int fe_bad = FE_UNDERFLOW | FE_OVERFLOW | FE_INVALID;
constexpr double filter_ratio = 0x1p-46;

// Q′ index pairs of the adjugate: A′_s = Q′[x]·Q′[y] − Q′[z]·Q′[w], s in
// the storage order of pw85.h (00, 01, 02, 11, 12, 22).
constexpr int adj[6][4] = {{3, 5, 4, 4}, {2, 4, 1, 5}, {1, 4, 2, 3},
                           {0, 5, 2, 2}, {1, 2, 0, 4}, {0, 3, 1, 1}};
// The axes (a, b) of each stored entry, and the entry of (a, b).
constexpr int axis_a[6] = {0, 0, 0, 1, 1, 2};
constexpr int axis_b[6] = {0, 1, 2, 1, 2, 2};
constexpr int entry[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};

// What the grid gives every predicate.
struct Axes {
  double L[3], o[3], two_n[3], w[6];  // w: 4·n_a·n_b
  double n[3];
  bool has_origin;
  bool exact_only;  // no filter at all (flags_work() is false)
};

Axes make_axes(Grid const &g) noexcept {
  Axes a{};
  a.has_origin = false;
  a.exact_only = false;
  for (int k = 0; k < 3; ++k) {
    a.L[k] = g.sides[k];
    a.o[k] = g.origin[k];
    a.n[k] = static_cast<double>(g.dims[k]);
    a.two_n[k] = 2.0 * a.n[k];
    if (a.o[k] != 0.0) a.has_origin = true;
  }
  for (int s = 0; s < 6; ++s) a.w[s] = 4.0 * a.n[axis_a[s]] * a.n[axis_b[s]];
  return a;
}

// One ellipsoid: its exact data, and what the filter and the guesses use.
struct Ell {
  double c[3], q[6];
  double qp[6];                   // fl(Q′)
  double A[6], Aa[6], det, deta;  // fl(A′), on absolute values; det(Q′)
  std::int64_t lo[3], hi[3];      // bounding box, unwrapped indices
  bool exact_only;                // the filter flagged: exact everywhere
};

// The unwrapped indices whose points may lie in [c − r, c + r] along axis
// k: (c − o ± r)·n/L − ½ is below 2⁴⁹ in magnitude (raster.hpp's reach,
// n ≤ 2²⁰) and computed with a relative error of a few ulps, an absolute
// error below ¼ of an index: 2 indices of margin on each side are safe.
void bbox(Axes const &a, Ell &e) noexcept {
  for (int k = 0; k < 3; ++k) {
    double const r = std::sqrt(e.q[entry[k][k]]);
    double const s = a.n[k] / a.L[k];
    e.lo[k] = static_cast<std::int64_t>(std::floor((e.c[k] - a.o[k] - r) * s - 0.5)) - 2;
    e.hi[k] = static_cast<std::int64_t>(std::floor((e.c[k] - a.o[k] + r) * s - 0.5)) + 2;
  }
}

void prepare(Axes const &a, double const c[3], double const q[6],
             Ell &e) noexcept {
  std::memcpy(e.c, c, sizeof e.c);
  std::memcpy(e.q, q, sizeof e.q);
  if (std::fetestexcept(fe_bad) != 0) std::feclearexcept(fe_bad);
  for (int s = 0; s < 6; ++s) e.qp[s] = a.w[s] * q[s];
  for (int s = 0; s < 6; ++s) {
    double const *p = e.qp;
    int const *t = adj[s];
    e.A[s] = p[t[0]] * p[t[1]] - p[t[2]] * p[t[3]];
    e.Aa[s] = std::fabs(p[t[0]]) * std::fabs(p[t[1]]) +
              std::fabs(p[t[2]]) * std::fabs(p[t[3]]);
  }
  e.det = (e.qp[0] * e.A[0] + e.qp[1] * e.A[1]) + e.qp[2] * e.A[2];
  e.deta = (std::fabs(e.qp[0]) * e.Aa[0] + std::fabs(e.qp[1]) * e.Aa[1]) +
           std::fabs(e.qp[2]) * e.Aa[2];
  e.exact_only = a.exact_only || std::fetestexcept(fe_bad) != 0;
  if (e.exact_only) std::feclearexcept(fe_bad);
  bbox(a, e);
}

// e_k = (2i + 1)·L_k − 2n_k·c_k + 2n_k·o_k in doubles, and on absolute
// values.
struct Coord {
  double e, ea;
};
PW85_INLINE Coord coord(Axes const &a, Ell const &el, int k,
                        std::int64_t i) noexcept {
  double const m = 2.0 * static_cast<double>(i) + 1.0;  // exact: |i| ≤ 2⁴⁹
  double const u = m * a.L[k], v = a.two_n[k] * el.c[k];
  double e = u - v, ea = std::fabs(u) + std::fabs(v);
  if (a.has_origin) {
    double const w = a.two_n[k] * a.o[k];
    e = e + w;
    ea = ea + std::fabs(w);
  }
  return {e, ea};
}

// The monomials of e_k: (factor, factor, sign), 2 or 3 of them.
int e_parts(Axes const &a, Ell const &el, int k, std::int64_t i,
            double f[3][2], int sg[3]) noexcept {
  f[0][0] = 2.0 * static_cast<double>(i) + 1.0, f[0][1] = a.L[k], sg[0] = 1;
  f[1][0] = a.two_n[k], f[1][1] = el.c[k], sg[1] = -1;
  if (!a.has_origin) return 2;
  f[2][0] = a.two_n[k], f[2][1] = a.o[k], sg[2] = 1;
  return 3;
}

// Exact sign of P at unwrapped indices idx.
int exact_p(Axes const &a, Ell const &el, std::int64_t const idx[3]) noexcept {
  Monomial m[128];
  int count = 0;
  double f[3][3][2];
  int sg[3][3], np[3];
  for (int k = 0; k < 3; ++k) np[k] = e_parts(a, el, k, idx[k], f[k], sg[k]);
  for (int s = 0; s < 6; ++s) {
    int const x = axis_a[s], y = axis_b[s];
    int const mult = x == y ? 1 : 2;
    for (int half = 0; half < 2; ++half) {
      int const p0 = adj[s][2 * half], p1 = adj[s][2 * half + 1];
      for (int u = 0; u < np[x]; ++u)
        for (int v = 0; v < np[y]; ++v) {
          Monomial &t = m[count++];
          t.coef = mult * (half == 0 ? 1 : -1) * sg[x][u] * sg[y][v];
          t.nf = 8;
          double const g[8] = {a.w[p0], el.q[p0], a.w[p1], el.q[p1],
                               f[x][u][0], f[x][u][1], f[y][v][0], f[y][v][1]};
          std::memcpy(t.f, g, sizeof g);
        }
    }
  }
  // − det(Q′) = −(Q′₀·A′₀ + Q′₁·A′₁ + Q′₂·A′₂)
  for (int s = 0; s < 3; ++s)
    for (int half = 0; half < 2; ++half) {
      int const p0 = adj[s][2 * half], p1 = adj[s][2 * half + 1];
      Monomial &t = m[count++];
      t.coef = half == 0 ? -1 : 1;
      t.nf = 6;
      double const g[6] = {a.w[s], el.q[s], a.w[p0], el.q[p0], a.w[p1], el.q[p1]};
      std::memcpy(t.f, g, sizeof g);
    }
  return exact_sign(m, count);
}

// Exact sign of G = A′₂₀e₀ + A′₂₁e₁ + A′₂₂e₂ at unwrapped indices idx.
int exact_g(Axes const &a, Ell const &el, std::int64_t const idx[3]) noexcept {
  Monomial m[24];
  int count = 0;
  for (int b = 0; b < 3; ++b) {
    double f[3][2];
    int sg[3];
    int const np = e_parts(a, el, b, idx[b], f, sg);
    int const s = entry[2][b];
    for (int half = 0; half < 2; ++half) {
      int const p0 = adj[s][2 * half], p1 = adj[s][2 * half + 1];
      for (int u = 0; u < np; ++u) {
        Monomial &t = m[count++];
        t.coef = (half == 0 ? 1 : -1) * sg[u];
        t.nf = 6;
        double const g[6] = {a.w[p0], el.q[p0], a.w[p1], el.q[p1], f[u][0], f[u][1]};
        std::memcpy(t.f, g, sizeof g);
      }
    }
  }
  return exact_sign(m, count);
}

// A row (i, j): the predicates at k, filtered or exact.
struct Row {
  Axes const &a;
  Ell const &el;
  std::int64_t i, j;
  bool exact;
  // Row constants of the filter: e₀, e₁ and the terms without e₂.
  double e0, e1, e0a, e1a;
  double s01, s01a, t01, t01a, b2, b2a;

  Row(Axes const &axes, Ell const &ell, std::int64_t ii, std::int64_t jj,
      bool ex) noexcept
      : a(axes), el(ell), i(ii), j(jj), exact(ex) {
    Coord const c0 = coord(a, el, 0, i), c1 = coord(a, el, 1, j);
    e0 = c0.e, e0a = c0.ea, e1 = c1.e, e1a = c1.ea;
    double const *A = el.A, *Aa = el.Aa;
    s01 = (A[0] * e0) * e0 + (A[3] * e1) * e1;
    s01a = (Aa[0] * e0a) * e0a + (Aa[3] * e1a) * e1a;
    t01 = (A[1] * e0) * e1;
    t01a = (Aa[1] * e0a) * e1a;
    b2 = A[2] * e0 + A[4] * e1;  // A′₀₂e₀ + A′₁₂e₁
    b2a = Aa[2] * e0a + Aa[4] * e1a;
  }

  // The point (i, j, k) is inside or on the surface.
  bool in(std::int64_t k) const noexcept {
    if (!exact) {
      Coord const c2 = coord(a, el, 2, k);
      double const *A = el.A, *Aa = el.Aa;
      // S = (A₀₀e₀e₀ + A₁₁e₁e₁ + A₂₂e₂e₂) + 2·(A₀₁e₀e₁ + A₀₂e₀e₂ + A₁₂e₁e₂)
      double const s = s01 + (A[5] * c2.e) * c2.e;
      double const sa = s01a + (Aa[5] * c2.ea) * c2.ea;
      double const t = t01 + ((A[2] * e0) * c2.e + (A[4] * e1) * c2.e);
      double const ta = t01a + ((Aa[2] * e0a) * c2.ea + (Aa[4] * e1a) * c2.ea);
      double const p = (s + 2.0 * t) - el.det;
      double const pa = (sa + 2.0 * ta) + el.deta;
      if (std::fabs(p) > filter_ratio * pa) return p < 0.0;
    }
    std::int64_t const idx[3] = {i, j, k};
    return exact_p(a, el, idx) <= 0;
  }

  // P does not decrease from k on: G(k) ≥ 0.
  bool up(std::int64_t k) const noexcept {
    if (!exact) {
      Coord const c2 = coord(a, el, 2, k);
      double const g = b2 + el.A[5] * c2.e;
      double const ga = b2a + el.Aa[5] * c2.ea;
      if (std::fabs(g) > filter_ratio * ga) return g > 0.0;
    }
    std::int64_t const idx[3] = {i, j, k};
    return exact_g(a, el, idx) >= 0;
  }
};

// Guesses along a row, as indices k (doubles): the minimum of P and its
// roots (equal to the minimum when P > 0 there). Not certified.
struct Guess {
  double kmid, klo, khi;
};
Guess guess_row(Axes const &a, Ell const &el, std::int64_t i,
                std::int64_t j) noexcept {
  Coord const c0 = coord(a, el, 0, i), c1 = coord(a, el, 1, j);
  double const *A = el.A;
  double const beta = A[2] * c0.e + A[4] * c1.e;
  double const gamma = A[0] * c0.e * c0.e + 2.0 * A[1] * c0.e * c1.e + A[3] * c1.e * c1.e;
  double const e2 = -beta / A[5];
  double const disc = beta * beta - A[5] * (gamma - el.det);
  double const half = disc > 0.0 ? std::sqrt(disc) / A[5] : 0.0;
  // e₂ = (2k + 1)·L₂ − 2n₂(c₂ − o₂)
  double const shift = a.two_n[2] * (el.c[2] - a.o[2]);
  auto const k_of = [&](double e) { return ((e + shift) / a.L[2] - 1.0) * 0.5; };
  return {k_of(e2), k_of(e2 - half), k_of(e2 + half)};
}

std::int64_t clamp_index(double x, std::int64_t lo, std::int64_t hi) noexcept {
  if (!(x > static_cast<double>(lo))) return lo;  // NaN too
  if (!(x < static_cast<double>(hi))) return hi;
  return static_cast<std::int64_t>(std::floor(x));
}

// The inside interval [lo, hi] of a row within [kmin, kmax]; false if
// empty. See the file's description ("The row").
bool row_interval(Row const &r, Guess const &gs, std::int64_t kmin,
                  std::int64_t kmax, std::int64_t &lo,
                  std::int64_t &hi) noexcept {
  std::int64_t k = clamp_index(gs.kmid + 0.5, kmin, kmax);
  if (r.up(k)) {
    while (k > kmin && r.up(k - 1)) --k;
  } else {
    while (k < kmax && !r.up(k)) ++k;
  }
  std::int64_t kin;
  if (r.in(k))
    kin = k;
  else if (k > kmin && r.in(k - 1))
    kin = k - 1;
  else
    return false;
  hi = clamp_index(gs.khi, kin, kmax);
  if (r.in(hi)) {
    while (hi < kmax && r.in(hi + 1)) ++hi;
  } else {
    do --hi;
    while (hi > kin && !r.in(hi));
  }
  lo = clamp_index(gs.klo + 1.0, kmin, kin);
  if (r.in(lo)) {
    while (lo > kmin && r.in(lo - 1)) --lo;
  } else {
    do ++lo;
    while (lo < kin && !r.in(lo));
  }
  return true;
}

// ⌊a/b⌋ for b > 0.
std::int64_t floor_div(std::int64_t a, std::int64_t b) noexcept {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

std::int64_t wrap(std::int64_t i, std::int64_t n) noexcept {
  std::int64_t const r = i % n;
  return r < 0 ? r + n : r;
}

// Draws ellipsoid p (Ell el) into the planes [p0, p1) of the image (planes
// unwrapped [u0, u1), wrapped by the caller's shift).
void draw(Grid const &g, Axes const &a, Ell const &el, std::int32_t p,
          std::int64_t u0, std::int64_t u1, std::int32_t *image) noexcept {
  std::int64_t const n0 = g.dims[0], n1 = g.dims[1], n2 = g.dims[2];
  std::int64_t jlo = el.lo[1], jhi = el.hi[1], kmin = el.lo[2], kmax = el.hi[2];
  if (!g.periodic) {
    jlo = jlo < 0 ? 0 : jlo, jhi = jhi > n1 - 1 ? n1 - 1 : jhi;
    kmin = kmin < 0 ? 0 : kmin, kmax = kmax > n2 - 1 ? n2 - 1 : kmax;
    if (jlo > jhi || kmin > kmax) return;
  }
  std::uint32_t const value = static_cast<std::uint32_t>(p);
  for (std::int64_t i = u0; i < u1; ++i) {
    std::int64_t const ii = g.periodic ? wrap(i, n0) : i;
    for (std::int64_t j = jlo; j <= jhi; ++j) {
      std::int64_t const jj = g.periodic ? wrap(j, n1) : j;
      Guess const gs = guess_row(a, el, i, j);
      std::int64_t lo = 0, hi = -1;
      bool found;
      if (el.exact_only) {
        found = row_interval(Row(a, el, i, j, true), gs, kmin, kmax, lo, hi);
      } else {
        // The flags are clear here (draw_chunk() clears them, and so does
        // every row that finds them raised): testing is cheap, clearing
        // is not (glibc's feclearexcept() saves and loads the x87
        // environment), so it is done only when needed.
        if (std::fetestexcept(fe_bad) != 0) std::feclearexcept(fe_bad);  // guess_row()
        found = row_interval(Row(a, el, i, j, false), gs, kmin, kmax, lo, hi);
        if (PW85_UNLIKELY(std::fetestexcept(fe_bad) != 0)) {
          found = row_interval(Row(a, el, i, j, true), gs, kmin, kmax, lo, hi);
          std::feclearexcept(fe_bad);
        }
      }
      if (!found) continue;
      std::uint32_t *row = reinterpret_cast<std::uint32_t *>(image) + (ii * n1 + jj) * n2;
      // Least position kept: −1 (the matrix) is the largest uint32. Runs
      // of the row between wraps, each a loop the compiler vectorises.
      std::int64_t kk = g.periodic ? wrap(lo, n2) : lo, left = hi - lo + 1;
      while (left > 0) {
        std::int64_t const run = left < n2 - kk ? left : n2 - kk;
        std::uint32_t *cell = row + kk;
        for (std::int64_t t = 0; t < run; ++t)
          cell[t] = cell[t] < value ? cell[t] : value;
        left -= run;
        kk = 0;
      }
    }
  }
}

// Planes [p0, p1) of the image: set to −1, then every ellipsoid meeting them
// drawn, through each of its images along axis 0 (periodic).
void draw_chunk(Grid const &g, Axes const &a, std::size_t n,
                double const *centres, double const *q, std::int64_t p0,
                std::int64_t p1, std::int32_t *image) noexcept {
  std::int64_t const n0 = g.dims[0], plane = g.dims[1] * g.dims[2];
  std::memset(image + p0 * plane, 0xff,
              static_cast<std::size_t>((p1 - p0) * plane) * sizeof(std::int32_t));
  std::fexcept_t saved;
  std::fegetexceptflag(&saved, fe_bad);
  std::feclearexcept(fe_bad);
  for (std::size_t p = 0; p < n; ++p) {
    double const *c = centres + 3 * p;
    // Planes first, from the bounding box alone (cheap).
    double const r = std::sqrt(q[6 * p]);
    double const s = a.n[0] / a.L[0];
    std::int64_t const ilo =
        static_cast<std::int64_t>(std::floor((c[0] - a.o[0] - r) * s - 0.5)) - 2;
    std::int64_t const ihi =
        static_cast<std::int64_t>(std::floor((c[0] - a.o[0] + r) * s - 0.5)) + 2;
    bool prepared = false;
    Ell el;
    // Unwrapped planes i ≡ [p0, p1) (mod n0) in [ilo, ihi]: shifts t·n0.
    std::int64_t tlo = 0, thi = 0;
    if (g.periodic) {
      tlo = -floor_div(p1 - 1 - ilo, n0);  // ⌈(ilo − p1 + 1)/n0⌉
      thi = floor_div(ihi - p0, n0);
    }
    for (std::int64_t t = tlo; t <= thi; ++t) {
      std::int64_t u0 = p0 + t * n0, u1 = p1 + t * n0;
      if (u0 < ilo) u0 = ilo;
      if (u1 > ihi + 1) u1 = ihi + 1;
      if (u0 >= u1) continue;
      if (!prepared) {
        prepare(a, c, q + 6 * p, el);
        prepared = true;
      }
      // draw() maps unwrapped planes to planes; for an open grid the range
      // is within [p0, p1) already.
      draw(g, a, el, static_cast<std::int32_t>(p), u0, u1, image);
    }
  }
  std::fesetexceptflag(&saved, fe_bad);
}

}  // namespace

Status check_image_input(Grid const &grid, std::size_t n,
                         double const *centres, double const *q) noexcept {
  for (std::size_t p = 0; p < n; ++p) {
    if (!all_finite<3>(centres + 3 * p) || !all_finite<6>(q + 6 * p))
      return Status::not_finite;
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (!is_positive_definite(q + 6 * p)) return Status::not_positive_definite;
  }
  for (std::size_t p = 0; p < n; ++p) {
    for (int k = 0; k < 3; ++k) {
      double const reach =
          std::fabs(centres[3 * p + k] - grid.origin[k]) + std::sqrt(q[6 * p + entry[k][k]]);
      // (2²⁹·L_k may overflow to +∞: reach must then still be finite, so
      // that the bounding boxes' indices are.)
      if (!(std::isfinite(reach) && reach <= image_reach * grid.sides[k]))
        return Status::invalid_argument;
    }
  }
  return Status::success;
}

// Does this thread's floating-point environment raise the underflow flag?
// (An emulator may not: valgrind's does not.) If not, the filter cannot
// see underflow, and every predicate is decided exactly.
bool flags_work() noexcept {
  std::fexcept_t saved;
  std::fegetexceptflag(&saved, FE_UNDERFLOW);
  std::feclearexcept(FE_UNDERFLOW);
  volatile double tiny = 0x1p-1000;
  volatile double product = tiny * tiny;
  (void)product;
  bool const raised = std::fetestexcept(FE_UNDERFLOW) != 0;
  std::fesetexceptflag(&saved, FE_UNDERFLOW);
  return raised;
}

void voxel_image(Grid const &grid, std::size_t n, double const *centres,
                 double const *q, std::int32_t *image, int threads) noexcept {
  Axes a = make_axes(grid);
  a.exact_only = !flags_work();
  std::int64_t const n0 = grid.dims[0];
#if defined(PW85_OPENMP)
  if (threads == 0) threads = omp_get_max_threads();
#endif
  // No more threads than there is work for: one per 4096 voxels at
  // least (as the index's queries), and per plane along x; at most
  // max_threads (batch.hpp). (0 without OpenMP: 1, as the loop below.)
  std::int64_t const voxels = n0 * grid.dims[1] * grid.dims[2];
  std::int64_t const most = std::min(n0, voxels / 4096 + 1);
  threads = team_size(threads, static_cast<std::size_t>(most));
  // Chunks of planes: about 16 per thread, for the dynamic schedule.
  std::int64_t per = n0 / (16 * threads);
  if (per < 1) per = 1;
  std::int64_t const chunks = (n0 + per - 1) / per;
#if defined(PW85_OPENMP)
  if (threads > 1) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (std::int64_t c = 0; c < chunks; ++c) {
      std::int64_t const p1 = (c + 1) * per < n0 ? (c + 1) * per : n0;
      draw_chunk(grid, a, n, centres, q, c * per, p1, image);
    }
    return;
  }
#endif
  for (std::int64_t c = 0; c < chunks; ++c) {
    std::int64_t const p1 = (c + 1) * per < n0 ? (c + 1) * per : n0;
    draw_chunk(grid, a, n, centres, q, c * per, p1, image);
  }
}

int voxel_outside(Grid const &grid, double const c[3], double const q[6],
                  std::int64_t i, std::int64_t j, std::int64_t k) noexcept {
  Axes const a = make_axes(grid);
  Ell el;
  prepare(a, c, q, el);
  std::int64_t const idx[3] = {i, j, k};
  return exact_p(a, el, idx) > 0 ? 1 : -1;
}

}  // namespace pw85::detail
