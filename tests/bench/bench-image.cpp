// SPDX-License-Identifier: BSD-3-Clause
// Benchmark (meson test --benchmark) of the voxel image (pw85_image.h):
// 10⁴ triaxial ellipsoids (semi-axes 1, 0.5, 0.2, random orientations and
// centres, overlaps allowed) filling a periodic cube to a nominal fraction
// of 0.55, imaged at 512³ (issue 28: under 10 s on 2 threads), and at 256³;
// on 1 and 2 threads. Yardsticks in the same run: a pass of memset over
// the image (the floor: the memory itself), and a naive rasteriser, one
// thread, that tests every voxel of each ellipsoid's bounding box in
// doubles without any certification (what a user writes by hand; its
// disagreements with the exact image are counted). Ratios matter, not
// absolute times: the machines are shared.
//
// Usage: bench-image [quick]  ("quick": 256³ only)
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "pw85_image.h"
#include "pw85_index.h"

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// xorshift64*, uniform in [0, 1).
double uniform(std::uint64_t &s) {
  s ^= s >> 12;
  s ^= s << 25;
  s ^= s >> 27;
  return static_cast<double>((s * 2685821657736338717ull) >> 11) * 0x1p-53;
}

struct Config {
  std::vector<double> c, q;
  double side;
};

Config make_config(std::size_t n, double fraction) {
  double const a[3] = {1.0, 0.5, 0.2};
  double const volume = 4.0 / 3.0 * M_PI * a[0] * a[1] * a[2];
  Config cf;
  cf.side = std::cbrt(static_cast<double>(n) * volume / fraction);
  std::uint64_t s = 0x2028;
  for (std::size_t p = 0; p < n; ++p) {
    double w, x, y, z, m;
    do {
      w = 2 * uniform(s) - 1, x = 2 * uniform(s) - 1, y = 2 * uniform(s) - 1,
      z = 2 * uniform(s) - 1;
      m = w * w + x * x + y * y + z * z;
    } while (m > 1 || m < 1e-6);
    m = std::sqrt(m), w /= m, x /= m, y /= m, z /= m;
    double const r[3][3] = {
        {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    for (int k = 0; k < 3; ++k) cf.c.push_back(cf.side * uniform(s));
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j)
        cf.q.push_back(r[i][0] * a[0] * a[0] * r[j][0] + r[i][1] * a[1] * a[1] * r[j][1] +
                       r[i][2] * a[2] * a[2] * r[j][2]);
  }
  return cf;
}

// The naive rasteriser: every voxel of each bounding box, (m − c)ᵀQ⁻¹(m − c)
// ≤ 1 in doubles, least position kept.
void naive(Config const &cf, std::size_t n, std::int32_t *img) {
  std::memset(img, 0xff, n * n * n * sizeof *img);
  std::size_t const count = cf.c.size() / 3;
  double const h = cf.side / static_cast<double>(n);
  for (std::size_t p = 0; p < count; ++p) {
    double const *q = &cf.q[6 * p], *c = &cf.c[3 * p];
    double const a00 = q[3] * q[5] - q[4] * q[4], a01 = q[2] * q[4] - q[1] * q[5],
                 a02 = q[1] * q[4] - q[2] * q[3], a11 = q[0] * q[5] - q[2] * q[2],
                 a12 = q[1] * q[2] - q[0] * q[4], a22 = q[0] * q[3] - q[1] * q[1];
    double const det = q[0] * a00 + q[1] * a01 + q[2] * a02;
    long lo[3], hi[3];
    int const diag[3] = {0, 3, 5};
    for (int k = 0; k < 3; ++k) {
      double const r = std::sqrt(q[diag[k]]);
      lo[k] = static_cast<long>(std::floor((c[k] - r) / h - 0.5));
      hi[k] = static_cast<long>(std::ceil((c[k] + r) / h - 0.5));
    }
    long const nn = static_cast<long>(n);
    for (long i = lo[0]; i <= hi[0]; ++i) {
      double const d0 = (i + 0.5) * h - c[0];
      long const ii = ((i % nn) + nn) % nn;
      for (long j = lo[1]; j <= hi[1]; ++j) {
        double const d1 = (j + 0.5) * h - c[1];
        long const jj = ((j % nn) + nn) % nn;
        for (long k = lo[2]; k <= hi[2]; ++k) {
          double const d2 = (k + 0.5) * h - c[2];
          double const v = a00 * d0 * d0 + a11 * d1 * d1 + a22 * d2 * d2 +
                           2 * (a01 * d0 * d1 + a02 * d0 * d2 + a12 * d1 * d2);
          if (v <= det) {
            long const kk = ((k % nn) + nn) % nn;
            std::uint32_t &cell = reinterpret_cast<std::uint32_t &>(
                img[(ii * nn + jj) * nn + kk]);
            if (cell > p) cell = static_cast<std::uint32_t>(p);
          }
        }
      }
    }
  }
}

}  // namespace

int main(int argc, char **argv) {
  bool const quick = argc > 1 && std::strcmp(argv[1], "quick") == 0;
  Config const cf = make_config(10000, 0.55);
  std::printf("10^4 ellipsoids (1, 0.5, 0.2), periodic cube of side %.4f, "
              "nominal fraction 0.55; OpenMP: %s\n",
              cf.side, pw85_index_openmp() ? "yes" : "no");
  std::size_t const sizes[] = {256, 512};
  for (std::size_t n : sizes) {
    if (quick && n > 256) continue;
    std::size_t const dims[3] = {n, n, n}, voxels = n * n * n;
    std::vector<std::int32_t> img(voxels), ref(voxels);
    double const L[3] = {cf.side, cf.side, cf.side};
    Clock::time_point t0 = Clock::now();
    std::memset(ref.data(), 0xff, voxels * sizeof(std::int32_t));
    double const t_memset = seconds_since(t0);
    double t[3] = {0, 0, 0};
    for (int threads = 1; threads <= 2; ++threads) {
      t0 = Clock::now();
      int const status = pw85_image_voxels(cf.c.size() / 3, cf.c.data(), cf.q.data(),
                                           nullptr, L, 1, dims, img.data(), threads);
      t[threads] = seconds_since(t0);
      if (status != PW85_SUCCESS) {
        std::printf("pw85_image_voxels: %s\n", pw85_strerror(status));
        return 1;
      }
    }
    std::size_t count = 0;
    double fraction = 0;
    pw85_image_fraction(dims, img.data(), &count, &fraction);
    t0 = Clock::now();
    naive(cf, n, ref.data());
    double const t_naive = seconds_since(t0);
    std::size_t differ = 0;
    for (std::size_t v = 0; v < voxels; ++v) differ += img[v] != ref[v];
    std::printf("%zu^3: phase fraction %.4f; exact image %.3f s (1 thread), "
                "%.3f s (2 threads, speed-up %.2f)\n",
                n, fraction, t[1], t[2], t[1] / t[2]);
    std::printf("  yardsticks: memset %.3f s (exact/memset %.1f on 2 threads); "
                "naive uncertified rasteriser %.3f s, 1 thread "
                "(exact/naive %.2f on 1 thread), %zu voxels differ\n",
                t_memset, t[2] / t_memset, t_naive, t[1] / t_naive, differ);
    if (n == 512)
      std::printf("  issue 28 target, under 10 s on 2 threads: %s (%.3f s)\n",
                  t[2] < 10.0 ? "met" : "NOT met", t[2]);
  }
  return 0;
}
