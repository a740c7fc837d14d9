// SPDX-License-Identifier: BSD-3-Clause
// fuzz-index: a small configuration (up to 8 ellipsoids, open domain or
// periodic box) at a length scale 2^k, k in [−500, 500], through the
// spatial index (pw85_index.h), against a brute force over every pair and
// image with pw85_overlap(). Centres and box sides lie on a grid of
// 2^(k−24), so that every image vector is a double and the brute force
// decides the configuration as stored, as the index must (issue 25: the
// index was blind below lengths of 2^−268).
//
// Bytes after the configuration (zeros when absent: the corpus decodes as
// before) spread it: each ellipsoid shrunk by 2^−u (u < 31: sizes over
// 2³⁰, several levels of the index) and its centre moved by m·L, |m| up
// to 2^s (s < 22: centres far outside the box, or spread in an open
// domain; still on the grid, below 2^(k+29), so r stays exact). The
// snapshot's grid of such a level was miscounted (a SIGSEGV).
#include <pw85/pw85_index.h>

#include <cmath>
#include <vector>

#include "fuzz_common.h"

namespace {

struct Pair {
  size_t i, j;
  int n[3];
  int result;
};

bool same(Pair const &a, Pair const &b) {
  return a.i == b.i && a.j == b.j && a.n[0] == b.n[0] && a.n[1] == b.n[1] &&
         a.n[2] == b.n[2] && a.result == b.result;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  fuzz::Bytes in(data, size);
  bool const periodic = in.u8() & 1;
  int const k = int(in.u16() % 1001) - 500;
  int const count = 2 + in.u8() % 7;
  // Box sides: integers 8..71 times 2^k.
  int side[3];
  double L[3];
  for (int d = 0; d < 3; ++d) {
    side[d] = 8 + in.u8() % 64;
    L[d] = std::ldexp(side[d], k);
  }
  double const side_min = std::fmin(L[0], std::fmin(L[1], L[2]));
  std::vector<double> c(3 * count), q(6 * count);
  for (int e = 0; e < count; ++e) {
    // Centres in [0, L) on the grid of 2^(k−24) (exact in double).
    for (int d = 0; d < 3; ++d) {
      uint32_t const g =
          (uint32_t(in.u16()) << 16 | in.u16()) % (uint32_t(side[d]) << 24);
      c[3 * e + d] = std::ldexp(double(g), k - 24);
    }
    // Semi-axes up to 0.4 of the smallest side (narrower than the box),
    // a rotation from a quaternion.
    double a[3], p[4];
    for (double &x : a) x = side_min * (0.01 + 0.39 * (in.u16() / 65535.0));
    for (double &x : p) x = double(int(in.u16()) - 32768) + 0.5;
    double const norm =
        std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    for (double &x : p) x /= norm;
    if (pw85_ellipsoid_quaternion(a, p, &q[6 * e]) != PW85_SUCCESS) return 0;
  }

  int const spread = in.u8() % 22;
  double h[3 * 8];
  for (int e = 0; e < count; ++e) {
    int const u = in.u8() % 31;
    for (int m = 0; m < 6; ++m) q[6 * e + m] = std::ldexp(q[6 * e + m], -2 * u);
    for (int d = 0; d < 3; ++d) {
      uint32_t const w = uint32_t(in.u16()) << 16 | in.u16();
      int64_t const m =
          int64_t(w % ((uint32_t(2) << spread) + 1)) - (int64_t(1) << spread);
      c[3 * e + d] += double(m) * L[d];  // exact: on the grid, < 2^(k+29)
    }
    for (int d = 0; d < 3; ++d)
      h[3 * e + d] = std::sqrt(q[6 * e + (d == 0 ? 0 : d == 1 ? 3 : 5)]);
  }

  pw85_index *index = nullptr;
  CHECK(pw85_index_create(periodic ? L : nullptr, &index) == PW85_SUCCESS,
        "create");
  for (int e = 0; e < count; ++e) {
    int const st = pw85_index_insert(index, size_t(e), &c[3 * e], &q[6 * e]);
    if (st != PW85_SUCCESS) {  // a form the rule refuses, or too wide
      CHECK(st == PW85_ENOTPOSDEF || st == PW85_EINVAL || st == PW85_ERANGE,
            "insert %d", st);
      pw85_index_destroy(index);
      return 0;
    }
  }

  // The brute force: every pair i < j, every shift n whose image's
  // bounding box may meet i's, widened by one (the ellipsoids are
  // narrower than the box, so no ellipsoid meets its own images).
  std::vector<Pair> brute;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) {
      int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
      for (int d = 0; d < 3 && periodic; ++d) {
        double const gap = c[3 * i + d] - c[3 * j + d];
        double const reach = 2.0 * (h[3 * i + d] + h[3 * j + d]);
        lo[d] = int(std::floor((gap - reach) / L[d])) - 1;
        hi[d] = int(std::ceil((gap + reach) / L[d])) + 1;
      }
      for (int n0 = lo[0]; n0 <= hi[0]; ++n0)
        for (int n1 = lo[1]; n1 <= hi[1]; ++n1)
          for (int n2 = lo[2]; n2 <= hi[2]; ++n2) {
            int const n[3] = {n0, n1, n2};
            double r[3];
            for (int d = 0; d < 3; ++d)
              r[d] = (c[3 * j + d] + n[d] * (periodic ? L[d] : 0.0)) -
                     c[3 * i + d];  // exact on the grid
            int res = 2;
            int const st = pw85_overlap(r, &q[6 * i], &q[6 * j], &res);
            if (st != PW85_SUCCESS) {
              pw85_index_destroy(index);
              return 0;  // beyond the domain of pw85_overlap()
            }
            if (res <= 0)
              brute.push_back(Pair{size_t(i), size_t(j), {n0, n1, n2}, res});
          }
    }

  size_t found = 0;
  std::vector<size_t> ids(2 * 512);
  std::vector<int> shifts(3 * 512), results(512);
  int const st = pw85_index_overlapping_pairs(
      index, 1, 512, ids.data(), shifts.data(), results.data(), &found);
  CHECK(st == PW85_SUCCESS, "overlapping_pairs %d", st);
  CHECK(found == brute.size(), "scale 2^%d, %s: index %zu pairs, brute %zu", k,
        periodic ? "periodic" : "open", found, brute.size());
  // The index sorts by i, j, n; so does the brute force's loop order.
  for (size_t m = 0; m < found; ++m) {
    Pair const p{ids[2 * m],
                 ids[2 * m + 1],
                 {shifts[3 * m], shifts[3 * m + 1], shifts[3 * m + 2]},
                 results[m]};
    CHECK(same(p, brute[m]),
          "scale 2^%d: pair %zu (%zu, %zu, %d %d %d) result %d, brute "
          "(%zu, %zu, %d %d %d) %d",
          k, m, p.i, p.j, p.n[0], p.n[1], p.n[2], p.result, brute[m].i,
          brute[m].j, brute[m].n[0], brute[m].n[1], brute[m].n[2],
          brute[m].result);
  }

  // overlap_any of ellipsoid 0 (excluding itself) against the others: the
  // least result of its pairs. (Its own images are not queried.)
  int least = 1;
  for (Pair const &p : brute)
    if (p.i == 0 && p.result < least) least = p.result;
  int any = 2;
  size_t id = 0;
  CHECK(
      pw85_index_overlap_any(index, &c[0], &q[0], 0, &any, &id) == PW85_SUCCESS,
      "overlap_any");
  CHECK(any == least, "scale 2^%d: overlap_any %d, brute %d", k, any, least);
  pw85_index_destroy(index);
  return 0;
}
