/* SPDX-License-Identifier: BSD-3-Clause */
/* The voxel image (pw85_image.h) against independent brute forces:
 * - lattice spheres and axis-aligned ellipsoids whose data are small
 *   integers in voxel units, where "inside" is an integer inequality (and
 *   many voxel centres lie exactly on a surface);
 * - a 64³ image of random, overlapping triaxial ellipsoids, every voxel
 *   against every ellipsoid and every image of it, decided in doubles when
 *   far from the surface and by exact rational arithmetic (GMP) near it;
 * - the open domain with an origin; the same image for 1, 2 and 3 threads;
 * - the phase fraction; every status. */
#include <fenv.h>
#include <glib.h>
#include <gmp.h>
#include <math.h>
#include <pw85/pw85_image.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* xorshift64*, uniform in [0, 1). */
static double uniform(uint64_t *s) {
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return (double)((*s * 2685821657736338717ull) >> 11) * 0x1p-53;
}

/* Q = R diag(a²) Rᵀ, R from a random unit quaternion. */
static void random_form(uint64_t *s, double const a[3], double q[6]) {
  double w, x, y, z, n;
  do {
    w = 2 * uniform(s) - 1, x = 2 * uniform(s) - 1, y = 2 * uniform(s) - 1,
    z = 2 * uniform(s) - 1;
    n = w * w + x * x + y * y + z * z;
  } while (n > 1 || n < 1e-3);
  n = sqrt(n), w /= n, x /= n, y /= n, z /= n;
  double const r[3][3] = {
      {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
      {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
      {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  int k = 0;
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++, k++)
      q[k] = r[i][0] * a[0] * a[0] * r[j][0] + r[i][1] * a[1] * a[1] * r[j][1] +
             r[i][2] * a[2] * a[2] * r[j][2];
}

/* Exact: is the point o + (2·idx + 1)·L/(2n) (unwrapped idx) in the
 * ellipsoid (c, q)? Rational arithmetic on the exact values of the
 * doubles: d = m − c, inside iff dᵀ adj(Q) d ≤ det(Q). */
static int exact_inside(double const o[3], double const L[3],
                        size_t const n[3], long const idx[3],
                        double const c[3], double const q[6]) {
  mpq_t d[3], Q[3][3], A[3][3], t, u, lhs, det;
  for (int k = 0; k < 3; k++) {
    mpq_init(d[k]);
    for (int l = 0; l < 3; l++) mpq_init(Q[k][l]), mpq_init(A[k][l]);
  }
  mpq_inits(t, u, lhs, det, NULL);
  for (int k = 0; k < 3; k++) {
    mpq_set_d(t, L[k]);
    mpq_set_si(u, 2 * idx[k] + 1, 2 * n[k]);
    mpq_canonicalize(u);
    mpq_mul(d[k], t, u);
    mpq_set_d(t, o[k]);
    mpq_add(d[k], d[k], t);
    mpq_set_d(t, c[k]);
    mpq_sub(d[k], d[k], t);
  }
  int const ix[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
  for (int s = 0; s < 6; s++) {
    mpq_set_d(Q[ix[s][0]][ix[s][1]], q[s]);
    mpq_set_d(Q[ix[s][1]][ix[s][0]], q[s]);
  }
  /* cofactors: A[k][l] = (−1)^(k+l) minor(l, k) (symmetric here) */
  for (int k = 0; k < 3; k++)
    for (int l = 0; l < 3; l++) {
      int const r0 = (l + 1) % 3, r1 = (l + 2) % 3, c0 = (k + 1) % 3,
                c1 = (k + 2) % 3;
      mpq_mul(t, Q[r0][c0], Q[r1][c1]);
      mpq_mul(u, Q[r0][c1], Q[r1][c0]);
      mpq_sub(A[k][l], t, u);
    }
  mpq_set_ui(det, 0, 1);
  for (int l = 0; l < 3; l++) {
    mpq_mul(t, Q[0][l], A[l][0]);
    mpq_add(det, det, t);
  }
  mpq_set_ui(lhs, 0, 1);
  for (int k = 0; k < 3; k++)
    for (int l = 0; l < 3; l++) {
      mpq_mul(t, A[k][l], d[k]);
      mpq_mul(t, t, d[l]);
      mpq_add(lhs, lhs, t);
    }
  int const inside = mpq_cmp(lhs, det) <= 0;
  for (int k = 0; k < 3; k++) {
    mpq_clear(d[k]);
    for (int l = 0; l < 3; l++) mpq_clear(Q[k][l]), mpq_clear(A[k][l]);
  }
  mpq_clears(t, u, lhs, det, NULL);
  return inside;
}

/* Inside, decided in doubles when (m − c)ᵀ Q⁻¹ (m − c) is farther than
 * 1e-6 from 1 (its rounding error, for these well-conditioned forms, is
 * below 1e-13), else exactly. counted: how many went exact. */
static int brute_inside(double const o[3], double const L[3],
                        size_t const n[3], long const idx[3],
                        double const c[3], double const qinv[6],
                        double const q[6], size_t *exact_calls) {
  double d[3];
  for (int k = 0; k < 3; k++)
    d[k] = o[k] + (2.0 * (double)idx[k] + 1.0) * L[k] / (2.0 * (double)n[k]) - c[k];
  double const v = qinv[0] * d[0] * d[0] + qinv[3] * d[1] * d[1] +
                   qinv[5] * d[2] * d[2] +
                   2 * (qinv[1] * d[0] * d[1] + qinv[2] * d[0] * d[2] +
                        qinv[4] * d[1] * d[2]);
  if (v < 1 - 1e-6) return 1;
  if (v > 1 + 1e-6) return 0;
  ++*exact_calls;
  return exact_inside(o, L, n, idx, c, q);
}

static void invert(double const q[6], double b[6]) {
  double const a00 = q[3] * q[5] - q[4] * q[4], a01 = q[2] * q[4] - q[1] * q[5],
               a02 = q[1] * q[4] - q[2] * q[3], a11 = q[0] * q[5] - q[2] * q[2],
               a12 = q[1] * q[2] - q[0] * q[4], a22 = q[0] * q[3] - q[1] * q[1];
  double const det = q[0] * a00 + q[1] * a01 + q[2] * a02;
  b[0] = a00 / det, b[1] = a01 / det, b[2] = a02 / det, b[3] = a11 / det,
  b[4] = a12 / det, b[5] = a22 / det;
}

static size_t voxels(size_t const n[3]) { return n[0] * n[1] * n[2]; }

/* PW85_TEST_SMALL (sanitizer and valgrind runs; valgrind does not raise
 * the floating-point flags, so that every voxel is decided exactly there):
 * smaller images. */
static gboolean small_run(void) { return g_getenv("PW85_TEST_SMALL") != NULL; }

/* Lattice spheres and axis-aligned ellipsoids, periodic, box = n voxels of
 * side 1: centres at voxel centres (or faces), squared semi-axes integers;
 * inside iff Σ dx_k²/a_k² ≤ 1, i.e. Σ dx_k²·Π_{l≠k} a_l² ≤ Π a², with
 * dx_k half-integers doubled to integers. */
static void test_lattice(void) {
  size_t const n[3] = {20, 22, 24};
  double const L[3] = {20, 22, 24};
  /* centre (doubled coordinates, so that half-voxels are integers),
   * squared semi-axes (integers) */
  long const cc[][3] = {{1, 1, 1}, {20, 21, 30}, {39, 2, 47}, {10, 30, 0}};
  long const a2[][3] = {{9, 9, 9}, {4, 16, 25}, {16, 16, 4}, {25, 9, 36}};
  size_t const m = 4;
  double centres[12], q[24];
  for (size_t p = 0; p < m; p++) {
    for (int k = 0; k < 3; k++) centres[3 * p + k] = 0.5 * (double)cc[p][k];
    double const f[6] = {(double)a2[p][0], 0, 0, (double)a2[p][1], 0, (double)a2[p][2]};
    memcpy(q + 6 * p, f, sizeof f);
  }
  int32_t *img = g_new(int32_t, voxels(n));
  g_assert_cmpint(pw85_image_voxels(m, centres, q, NULL, L, 1, n, img, 1), ==,
                  PW85_SUCCESS);
  size_t on_surface = 0, mismatches = 0;
  for (long i = 0; i < (long)n[0]; i++)
    for (long j = 0; j < (long)n[1]; j++)
      for (long k = 0; k < (long)n[2]; k++) {
        long const v[3] = {2 * i + 1, 2 * j + 1, 2 * k + 1};
        int32_t want = -1;
        for (size_t p = 0; p < m && want < 0; p++) {
          /* every image: shifts of −1, 0, +1 box (ellipsoids < box/2) */
          for (int t0 = -1; t0 <= 1; t0++)
            for (int t1 = -1; t1 <= 1; t1++)
              for (int t2 = -1; t2 <= 1; t2++) {
                int const t[3] = {t0, t1, t2};
                long long dx[3];
                for (int a = 0; a < 3; a++)
                  dx[a] = v[a] - cc[p][a] - 2LL * t[a] * (long long)n[a];
                long long const lhs = dx[0] * dx[0] * a2[p][1] * a2[p][2] +
                                      dx[1] * dx[1] * a2[p][0] * a2[p][2] +
                                      dx[2] * dx[2] * a2[p][0] * a2[p][1];
                long long const rhs = 4LL * a2[p][0] * a2[p][1] * a2[p][2];
                if (lhs == rhs) on_surface++;
                if (lhs <= rhs) want = (int32_t)p;
              }
        }
        int32_t const got = img[((size_t)i * n[1] + (size_t)j) * n[2] + (size_t)k];
        if (got != want) {
          if (mismatches++ < 10)
            g_test_message("voxel (%ld, %ld, %ld): %d, expected %d", i, j, k,
                           got, want);
        }
      }
  g_test_message("%zu voxel centres exactly on a surface", on_surface);
  g_assert_cmpuint(mismatches, ==, 0);
  g_assert_cmpuint(on_surface, >=, 30);
  g_free(img);
}

/* A random configuration: m triaxial ellipsoids, overlapping, in the box. */
static void random_config(uint64_t seed, size_t m, double const L[3],
                          double *centres, double *q) {
  uint64_t s = seed;
  for (size_t p = 0; p < m; p++) {
    double const a[3] = {0.6 + 1.2 * uniform(&s), 0.4 + 0.6 * uniform(&s),
                         0.3 + 0.5 * uniform(&s)};
    for (int k = 0; k < 3; k++) centres[3 * p + k] = L[k] * uniform(&s);
    random_form(&s, a, q + 6 * p);
  }
}

/* Every voxel of a 64³ periodic image against every ellipsoid and every
 * image (27 shifts: the ellipsoids are narrower than half the box). */
static void test_brute_periodic(void) {
  size_t const side = small_run() ? 20 : 64;
  size_t const n[3] = {side, side, side};
  double const L[3] = {7.5, 8.0, 8.25}, o[3] = {0, 0, 0};
  size_t const m = 80;
  double centres[3 * 80], q[6 * 80], qinv[6 * 80];
  random_config(28, m, L, centres, q);
  for (size_t p = 0; p < m; p++) invert(q + 6 * p, qinv + 6 * p);
  int32_t *img = g_new(int32_t, voxels(n));
  g_assert_cmpint(pw85_image_voxels(m, centres, q, NULL, L, 1, n, img, 2), ==,
                  PW85_SUCCESS);
  size_t mismatches = 0, exact_calls = 0, covered = 0;
  long const s = (long)side;
  for (long i = 0; i < s; i++)
    for (long j = 0; j < s; j++)
      for (long k = 0; k < s; k++) {
        int32_t want = -1;
        for (size_t p = 0; p < m && want < 0; p++)
          for (int t = 0; t < 27 && want < 0; t++) {
            long const idx[3] = {i + s * (t % 3 - 1), j + s * (t / 3 % 3 - 1),
                                 k + s * (t / 9 - 1)};
            if (brute_inside(o, L, n, idx, centres + 3 * p, qinv + 6 * p,
                             q + 6 * p, &exact_calls))
              want = (int32_t)p;
          }
        int32_t const got = img[(i * s + j) * s + k];
        covered += want >= 0;
        if (got != want && mismatches++ < 10)
          g_test_message("voxel (%ld, %ld, %ld): %d, expected %d", i, j, k, got, want);
      }
  g_test_message("%zu voxels covered, %zu decided exactly by the brute force",
                 covered, exact_calls);
  g_assert_cmpuint(mismatches, ==, 0);
  g_assert_cmpuint(covered, >, voxels(n) / 5);
  size_t count = 0;
  double fraction = 0;
  g_assert_cmpint(pw85_image_fraction(n, img, &count, &fraction), ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, covered);
  g_assert_cmpfloat(fraction, ==, (double)covered / (double)voxels(n));
  g_free(img);
}

/* An open domain with an origin: only the ellipsoids themselves, clipped
 * to the box; every voxel against every ellipsoid. */
static void test_brute_open(void) {
  size_t const n[3] = {small_run() ? 10 : 40, 33, 37};
  double const L[3] = {6.0, 5.0, 5.5}, o[3] = {-1.25, 0.375, 10.1};
  size_t const m = 30;
  double centres[3 * 30], q[6 * 30], qinv[6 * 30];
  random_config(7, m, L, centres, q);
  for (size_t p = 0; p < m; p++) {
    for (int k = 0; k < 3; k++) centres[3 * p + k] += o[k];
    invert(q + 6 * p, qinv + 6 * p);
  }
  int32_t *img = g_new(int32_t, voxels(n));
  g_assert_cmpint(pw85_image_voxels(m, centres, q, o, L, 0, n, img, 1), ==,
                  PW85_SUCCESS);
  size_t mismatches = 0, exact_calls = 0;
  for (long i = 0; i < (long)n[0]; i++)
    for (long j = 0; j < (long)n[1]; j++)
      for (long k = 0; k < (long)n[2]; k++) {
        int32_t want = -1;
        long const idx[3] = {i, j, k};
        for (size_t p = 0; p < m && want < 0; p++)
          if (brute_inside(o, L, n, idx, centres + 3 * p, qinv + 6 * p, q + 6 * p,
                           &exact_calls))
            want = (int32_t)p;
        int32_t const got = img[((size_t)i * n[1] + (size_t)j) * n[2] + (size_t)k];
        if (got != want && mismatches++ < 10)
          g_test_message("voxel (%ld, %ld, %ld): %d, expected %d", i, j, k, got, want);
      }
  g_assert_cmpuint(mismatches, ==, 0);
  g_free(img);
}

/* Voxel centres placed on surfaces to the last bit: for a random
 * ellipsoid and a voxel centre m (dyadic: L = n, so m = i + ½), the centre
 * c = m − v/√(vᵀQ⁻¹v) for a random direction v, rounded: m lies within an
 * ulp or so of the surface, on either side, beyond what a floating-point
 * test can decide. Every voxel of each image against the exact decision
 * (GMP rationals) for every image of the ellipsoid. */
static void test_surface_points(void) {
  size_t const n[3] = {12, 12, 12};
  double const L[3] = {12, 12, 12}, o[3] = {0, 0, 0};
  int32_t img[12 * 12 * 12];
  uint64_t s = 0x5eed;
  size_t inside = 0, outside = 0, mismatches = 0, exact_calls = 0;
  int const trials = g_test_slow() ? 2000 : small_run() ? 40 : 300;
  for (int trial = 0; trial < trials; trial++) {
    double const a[3] = {1 + 3 * uniform(&s), 0.7 + 2 * uniform(&s), 0.5 + 2 * uniform(&s)};
    double q[6], qinv[6], c[3], v[3];
    random_form(&s, a, q);
    invert(q, qinv);
    long const target[3] = {(long)(12 * uniform(&s)), (long)(12 * uniform(&s)),
                            (long)(12 * uniform(&s))};
    for (int k = 0; k < 3; k++) v[k] = 2 * uniform(&s) - 1;
    double const norm = sqrt(qinv[0] * v[0] * v[0] + qinv[3] * v[1] * v[1] +
                             qinv[5] * v[2] * v[2] +
                             2 * (qinv[1] * v[0] * v[1] + qinv[2] * v[0] * v[2] +
                                  qinv[4] * v[1] * v[2]));
    for (int k = 0; k < 3; k++) c[k] = (double)target[k] + 0.5 - v[k] / norm;
    g_assert_cmpint(pw85_image_voxels(1, c, q, NULL, L, 1, n, img, 1), ==,
                    PW85_SUCCESS);
    size_t const before = exact_calls;
    for (long i = 0; i < 12; i++)
      for (long j = 0; j < 12; j++)
        for (long k = 0; k < 12; k++) {
          int want = 0;
          for (int t = 0; t < 27 && !want; t++) {
            long const idx[3] = {i + 12 * (t % 3 - 1), j + 12 * (t / 3 % 3 - 1),
                                 k + 12 * (t / 9 - 1)};
            want = brute_inside(o, L, n, idx, c, qinv, q, &exact_calls);
          }
          int const got = img[(i * 12 + j) * 12 + k] == 0;
          if (i == target[0] && j == target[1] && k == target[2])
            want ? inside++ : outside++;
          if (got != want && mismatches++ < 10)
            g_test_message("trial %d, voxel (%ld, %ld, %ld): %d, expected %d",
                           trial, i, j, k, got, want);
        }
    g_assert_cmpuint(exact_calls, >, before); /* the target at least */
  }
  g_test_message("targets: %zu inside, %zu outside; %zu exact decisions",
                 inside, outside, exact_calls);
  g_assert_cmpuint(mismatches, ==, 0);
  /* both sides of the surface are met (by rounding, about half each) */
  g_assert_cmpuint(inside, >, (size_t)trials / 5);
  g_assert_cmpuint(outside, >, (size_t)trials / 5);
}

/* Does arithmetic raise the floating-point flags here? (Not under
 * valgrind.) */
static int flags_raised(void) {
  feclearexcept(FE_ALL_EXCEPT);
  volatile double tiny = 0x1p-1000;
  volatile double product = tiny * tiny;
  (void)product;
  int const raised = fetestexcept(FE_UNDERFLOW) != 0;
  feclearexcept(FE_ALL_EXCEPT);
  return raised;
}

/* Scale invariance through the exact path: the lattice configuration
 * (voxel centres exactly on surfaces) with every length multiplied by 2^e
 * (exact) has the same image; there the filter underflows or overflows,
 * and the floating-point flags send the voxels to the exact integer
 * computation. */
static void test_extreme_scales(void) {
  size_t const n[3] = {12, 10, 14};
  double const L0[3] = {12, 10, 14};
  double const c0[3][3] = {{0.5, 0.5, 0.5}, {6, 5.5, 7}, {11.5, 2, 13}};
  double const q0[3][6] = {{9, 0, 0, 9, 0, 9},
                           {4, 0.5, -1, 6.25, 0.75, 5},
                           {2.25, -0.5, 0.25, 4, 0.5, 1}};
  int32_t ref[12 * 10 * 14], img[12 * 10 * 14];
  g_assert_cmpint(pw85_image_voxels(3, &c0[0][0], &q0[0][0], NULL, L0, 1, n, ref, 1),
                  ==, PW85_SUCCESS);
  size_t inside = 0;
  for (size_t v = 0; v < 12 * 10 * 14; v++) inside += ref[v] >= 0;
  g_assert_cmpuint(inside, >, 100);
  /* −300, −500: everything underflows; −175 to −186: the terms of the
   * predicate are subnormal, their rounding errors beyond the filter's
   * relative bound (only the underflow flag tells); 300, 480: overflow */
  int const check_flags = flags_raised();
  int const exps[] = {-300, -500, -175, -178, -180, -182, -184, -186, 300, 480};
  for (int e = 0; e < (int)(sizeof exps / sizeof *exps); e++) {
    double L[3], c[3][3], q[3][6];
    for (int k = 0; k < 3; k++) L[k] = ldexp(L0[k], exps[e]);
    for (int p = 0; p < 3; p++) {
      for (int k = 0; k < 3; k++) c[p][k] = ldexp(c0[p][k], exps[e]);
      for (int k = 0; k < 6; k++) q[p][k] = ldexp(q0[p][k], 2 * exps[e]);
    }
    /* 2^-1000 and 2^960 are exact doubles: the scaled data are exact.
     * The caller's flags are left as they were: clear, then raised. */
    int const bad = FE_UNDERFLOW | FE_OVERFLOW | FE_INVALID;
    for (int raised = 0; raised < 2; raised++) {
      feclearexcept(FE_ALL_EXCEPT);
      if (raised) feraiseexcept(bad);
      g_assert_cmpint(pw85_image_voxels(3, &c[0][0], &q[0][0], NULL, L, 1, n, img, 1),
                      ==, PW85_SUCCESS);
      if (check_flags) g_assert_cmpint(fetestexcept(bad), ==, raised ? bad : 0);
      g_assert_cmpmem(img, sizeof img, ref, sizeof ref);
    }
    feclearexcept(FE_ALL_EXCEPT);
    g_assert_cmpint(pw85_image_voxels(3, &c[0][0], &q[0][0], NULL, L, 1, n, img, 2), ==,
                    PW85_SUCCESS);
    g_assert_cmpmem(img, sizeof img, ref, sizeof ref);
  }
}

/* The same image for 1, 2 and 3 threads (and OpenMP's default). */
static void test_threads(void) {
  size_t const n[3] = {small_run() ? 16 : 48, 50, 52};
  double const L[3] = {10, 10, 10};
  size_t const m = 300;
  double *centres = g_new(double, 3 * m), *q = g_new(double, 6 * m);
  random_config(3, m, L, centres, q);
  int32_t *ref = g_new(int32_t, voxels(n)), *img = g_new(int32_t, voxels(n));
  g_assert_cmpint(pw85_image_voxels(m, centres, q, NULL, L, 1, n, ref, 1), ==, 0);
  int const counts[] = {2, 3, 0};
  for (int t = 0; t < 3; t++) {
    memset(img, 0x55, voxels(n) * sizeof *img);
    g_assert_cmpint(pw85_image_voxels(m, centres, q, NULL, L, 1, n, img, counts[t]),
                    ==, 0);
    g_assert_cmpmem(img, voxels(n) * sizeof *img, ref, voxels(n) * sizeof *ref);
  }
  g_free(centres), g_free(q), g_free(ref), g_free(img);
}

/* A failed call writes nothing; each status for its cause. */
static void test_errors(void) {
  size_t n[3] = {4, 4, 4};
  double L[3] = {2, 2, 2}, o[3] = {0, 0, 0};
  double c[3] = {1, 1, 1}, q[6] = {0.25, 0, 0, 0.25, 0, 0.25};
  int32_t img[64];
  for (int v = 0; v < 64; v++) img[v] = 77;
#define CALL(N, C, Q, O, LL, NN, IMG, T) \
  pw85_image_voxels((N), (C), (Q), (O), (LL), 1, (NN), (IMG), (T))
  g_assert_cmpint(CALL(1, NULL, q, o, L, n, img, 1), ==, PW85_EFAULT);
  g_assert_cmpint(CALL(1, c, NULL, o, L, n, img, 1), ==, PW85_EFAULT);
  g_assert_cmpint(CALL(1, c, q, o, NULL, n, img, 1), ==, PW85_EFAULT);
  g_assert_cmpint(CALL(1, c, q, o, L, NULL, img, 1), ==, PW85_EFAULT);
  g_assert_cmpint(CALL(1, c, q, o, L, n, NULL, 1), ==, PW85_EFAULT);
  double bad[3] = {2, NAN, 2};
  g_assert_cmpint(CALL(1, c, q, bad, L, n, img, 1), ==, PW85_EDOM);
  g_assert_cmpint(CALL(1, c, q, o, bad, n, img, 1), ==, PW85_EDOM);
  g_assert_cmpint(CALL(1, bad, q, o, L, n, img, 1), ==, PW85_EDOM);
  double qnan[6] = {0.25, 0, 0, INFINITY, 0, 0.25};
  g_assert_cmpint(CALL(1, c, qnan, o, L, n, img, 1), ==, PW85_EDOM);
  double qneg[6] = {0.25, 0.5, 0, 0.25, 0, 0.25};
  g_assert_cmpint(CALL(1, c, qneg, o, L, n, img, 1), ==, PW85_ENOTPOSDEF);
  double Lz[3] = {2, 0, 2};
  g_assert_cmpint(CALL(1, c, q, o, Lz, n, img, 1), ==, PW85_EINVAL);
  size_t n0[3] = {4, 0, 4}, nbig[3] = {4, PW85_IMAGE_MAX_DIM + 1, 4};
  g_assert_cmpint(CALL(1, c, q, o, L, n0, img, 1), ==, PW85_EINVAL);
  g_assert_cmpint(CALL(1, c, q, o, L, nbig, img, 1), ==, PW85_EINVAL);
  g_assert_cmpint(CALL(1, c, q, o, L, n, img, -1), ==, PW85_EINVAL);
  g_assert_cmpint(CALL((size_t)INT32_MAX + 1, c, q, o, L, n, img, 1), ==,
                  PW85_EINVAL);
  double far[3] = {1, 1, 0x1p31};
  g_assert_cmpint(CALL(1, far, q, o, L, n, img, 1), ==, PW85_EINVAL);
  for (int v = 0; v < 64; v++) g_assert_cmpint(img[v], ==, 77);
  /* n = 0: the matrix everywhere */
  g_assert_cmpint(CALL(0, NULL, NULL, NULL, L, n, img, 1), ==, PW85_SUCCESS);
  for (int v = 0; v < 64; v++) g_assert_cmpint(img[v], ==, PW85_IMAGE_MATRIX);
#undef CALL
  size_t count = 5;
  double fraction = 5;
  g_assert_cmpint(pw85_image_fraction(NULL, img, &count, &fraction), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_image_fraction(n, NULL, &count, &fraction), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_image_fraction(n0, img, &count, &fraction), ==, PW85_EINVAL);
  g_assert_cmpuint(count, ==, 5);
  g_assert_cmpint(pw85_image_fraction(n, img, &count, &fraction), ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, 0);
  g_assert_cmpfloat(fraction, ==, 0.0);
  img[5] = 0, img[6] = 3, img[7] = -2;
  g_assert_cmpint(pw85_image_fraction(n, img, &count, NULL), ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, 2);
}

/* The reach rule |c_k − o_k| + √Q_kk ≤ 2²⁹·L_k where 2²⁹·L_k is beyond
 * the range of a double: a centre whose distance to the origin is not
 * finite breaks it (PW85_EINVAL, nothing written; it was accepted, and the
 * index of its bounding box, ±∞ converted to an integer, undefined); a
 * huge box whose data are finite is drawn. */
static void test_reach_overflow(void) {
  double const L[3] = {1e300, 1e300, 1e300};
  double const o[3] = {-1.7e308, 0, 0}, c[3] = {1.7e308, 0.5e300, 0.5e300};
  double const q[6] = {1, 0, 0, 1, 0, 1};
  size_t const n[3] = {4, 4, 4};
  int32_t img[64];
  for (int periodic = 0; periodic < 2; periodic++) {
    for (int v = 0; v < 64; v++) img[v] = 77;
    g_assert_cmpint(pw85_image_voxels(1, c, q, o, L, periodic, n, img, 1), ==,
                    PW85_EINVAL);
    for (int v = 0; v < 64; v++) g_assert_cmpint(img[v], ==, 77);
  }
  /* A box of side 2⁹⁹⁷ (2²⁹·L = +∞), a sphere of radius 2⁵⁰⁰ centred on
   * the point of voxel (1, 1, 1), 3·2⁹⁹⁴: that voxel is inside, the
   * others are not. */
  double const Lp[3] = {0x1p997, 0x1p997, 0x1p997};
  double const c2[3] = {0x3p994, 0x3p994, 0x3p994};
  double const q2[6] = {0x1p1000, 0, 0, 0x1p1000, 0, 0x1p1000};
  g_assert_cmpint(pw85_image_voxels(1, c2, q2, NULL, Lp, 1, n, img, 1), ==,
                  PW85_SUCCESS);
  for (int v = 0; v < 64; v++)
    if (v != (1 * 4 + 1) * 4 + 1) g_assert_cmpint(img[v], ==, PW85_IMAGE_MATRIX);
  g_assert_cmpint(img[(1 * 4 + 1) * 4 + 1], ==, 0);
  g_assert_cmpint(img[0], ==, PW85_IMAGE_MATRIX);
}

/* The threads of the calling process (Linux: /proc/self/task). */
static int task_count(void) {
  GDir *dir = g_dir_open("/proc/self/task", 0, NULL);
  if (dir == NULL) return -1;
  int count = 0;
  while (g_dir_read_name(dir) != NULL) count++;
  g_dir_close(dir);
  return count;
}

/* No more threads than the image has work for (at most one per 4096
 * voxels, and per plane along x): 64 asked for a 2 × 2 × 2 image start
 * none (OpenMP's threads stay in its pool after the call: counted then).
 * They were all started, whatever the size: 10⁶ asked for killed the
 * process (libgomp cannot create them and exits). In a subprocess, whose
 * pool is empty. */
static void test_threads_bounded(void) {
  if (g_test_subprocess()) {
    /* a unit sphere at the centre: every voxel point, at √3/2, inside */
    double const L[3] = {2, 2, 2}, c[3] = {1, 1, 1};
    double const q[6] = {1, 0, 0, 1, 0, 1};
    size_t const n[3] = {2, 2, 2};
    int32_t img[8];
    int const before = task_count();
    g_assert_cmpint(pw85_image_voxels(1, c, q, NULL, L, 1, n, img, 64), ==,
                    PW85_SUCCESS);
    int const after = task_count();
    g_test_message("threads of the process: %d before, %d after", before,
                   after);
    g_assert_cmpint(after, ==, before);
    for (int v = 0; v < 8; v++) g_assert_cmpint(img[v], ==, 0);
    return;
  }
  if (task_count() < 0) {
    g_test_skip("no /proc/self/task");
    return;
  }
  g_test_trap_subprocess(NULL, 60 * G_USEC_PER_SEC, G_TEST_SUBPROCESS_DEFAULT);
  g_test_trap_assert_passed();
}

/* "The caller's exception flags are left as they were" (pw85_image.h):
 * every flag, clear or raised, after calls that succeed and that fail. The
 * checks of the arguments raised FE_OVERFLOW (2²⁹·L overflowing, in a box
 * of side 2⁹⁹⁷) and FE_INEXACT, which only the flags of the filter were
 * saved from. */
static void test_all_flags_kept(void) {
  if (!flags_raised()) {
    g_test_skip("the floating-point flags are not raised here");
    return;
  }
  double const Lp[3] = {0x1p997, 0x1p997, 0x1p997};
  double const c2[3] = {0x3p994, 0x3p994, 0x3p994};
  double const q2[6] = {0x1p1000, 0, 0, 0x1p1000, 0, 0x1p1000};
  double const L[3] = {10, 10, 10};
  size_t const m = 40;
  double *centres = g_new(double, 3 * m), *q = g_new(double, 6 * m);
  random_config(5, m, L, centres, q);
  double const far[3] = {1, 1, 0x1p40};
  size_t const n[3] = {8, 8, 8};
  int32_t img[512];
  int const patterns[] = {0, FE_ALL_EXCEPT, FE_INEXACT | FE_DIVBYZERO,
                          FE_OVERFLOW | FE_UNDERFLOW};
  for (size_t k = 0; k < G_N_ELEMENTS(patterns); k++) {
    for (int call = 0; call < 4; call++) {
      feclearexcept(FE_ALL_EXCEPT);
      feraiseexcept(patterns[k]);
      int st;
      if (call == 0) st = pw85_image_voxels(1, c2, q2, NULL, Lp, 1, n, img, 1);
      else if (call == 1) st = pw85_image_voxels(m, centres, q, NULL, L, 1, n, img, 1);
      else if (call == 2) st = pw85_image_voxels(m, centres, q, NULL, L, 0, n, img, 2);
      else st = pw85_image_voxels(1, far, q, NULL, L, 1, n, img, 1);
      int const flags = fetestexcept(FE_ALL_EXCEPT);
      feclearexcept(FE_ALL_EXCEPT);
      g_assert_cmpint(st, ==, call == 3 ? PW85_EINVAL : PW85_SUCCESS);
      if (flags != patterns[k])
        g_test_fail_printf("call %d: flags %#x after the call, %#x before",
                           call, (unsigned)flags, (unsigned)patterns[k]);
    }
  }
  g_free(centres), g_free(q);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  g_test_add_func("/pw85/image/lattice-surfaces", test_lattice);
  g_test_add_func("/pw85/image/brute-periodic-64", test_brute_periodic);
  g_test_add_func("/pw85/image/brute-open", test_brute_open);
  g_test_add_func("/pw85/image/surface-points", test_surface_points);
  g_test_add_func("/pw85/image/extreme-scales", test_extreme_scales);
  g_test_add_func("/pw85/image/threads", test_threads);
  g_test_add_func("/pw85/image/errors", test_errors);
  g_test_add_func("/pw85/image/reach-overflow", test_reach_overflow);
  g_test_add_func("/pw85/image/threads-bounded", test_threads_bounded);
  g_test_add_func("/pw85/image/all-flags-kept", test_all_flags_kept);
  return g_test_run();
}
