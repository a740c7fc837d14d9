/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmark (meson test --benchmark): the two-dimensional functions
 * (pw85_2d.h) against the three-dimensional ones (pw85.h) on comparable
 * pairs, timed in the same run (issue 29: the 2D contact function at most
 * 0.5 times the 3D one, the 2D overlap test at most 0.5 times the 3D
 * overlap test). Every figure is a ratio, the 2D time over the 3D time.
 *
 * Pairs (drawn here from fixed seeds, the same recipe in both dimensions):
 * semi-axes 10^U(−1, 0), the largest over the smallest up to 10^3 (in 3D
 * the middle one log-uniform between them), random orientations (a uniform
 * angle in 2D, a uniform unit quaternion in 3D), r12 along a random
 * direction, scaled so that μ² lands on a target (μ² ∝ |r12|²):
 * - near_contact: |μ² − 1| log-uniform in 1e-12 … 1e-3, on both sides;
 * - far: μ² log-uniform in 0.01 … 0.5 and 2 … 100.
 * Times are the CPU time of the thread, in interleaved rounds (3D, then
 * 2D, on their pairs, round after round, about 50 ms each), each round's
 * ratio taken, and the median printed with the spread of the rounds, so
 * that load shared with other processes moves both sides of a ratio.
 *
 * Usage: bench-2d [--rounds N] (default 7). */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include <math.h>
#include <pw85/pw85.h>
#include <pw85/pw85_2d.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { pairs_per_workload = 4000 };

static double const PI = 3.14159265358979323846;

/* splitmix64: a fixed stream per seed. */
static uint64_t next_u64(uint64_t *s) {
  uint64_t z = (*s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

static double uniform(uint64_t *s, double lo, double hi) {
  return lo + (hi - lo) * (double)(next_u64(s) >> 11) * 0x1p-53;
}

static double normal(uint64_t *s) {
  double const u = uniform(s, 0x1p-53, 1.), v = uniform(s, 0., 2. * PI);
  return sqrt(-2. * log(u)) * cos(v);
}

/* The semi-axes: the largest 10^U(−1, 0), the smallest that over
 * 10^U(0, 3), in 3D the middle one log-uniform between them. */
static void semi_axes(uint64_t *s, int dim, double a[3]) {
  double const big = pow(10., uniform(s, -1., 0.));
  double const small = big / pow(10., uniform(s, 0., 3.));
  a[0] = big;
  a[dim - 1] = small;
  if (dim == 3) a[1] = exp(uniform(s, log(small), log(big)));
}

static void form_2d(uint64_t *s, double q[3]) {
  double a[3];
  semi_axes(s, 2, a);
  if (pw85_2d_ellipse(a, uniform(s, -PI, PI), q) != PW85_SUCCESS) abort();
}

static void form_3d(uint64_t *s, double q[6]) {
  double a[3], p[4];
  semi_axes(s, 3, a);
  for (int k = 0; k < 4; k++) p[k] = normal(s);
  double const n = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
  for (int k = 0; k < 4; k++) p[k] /= n;
  if (pw85_ellipsoid_quaternion(a, p, q) != PW85_SUCCESS) abort();
}

typedef struct {
  int dim, count;
  double *r, *q1, *q2; /* count × dim, count × sym, count × sym */
} Pairs;

static int sym_of(int dim) { return dim * (dim + 1) / 2; }

static int contact(int dim, double const *r, double const *q1,
                   double const *q2, double out[2]) {
  return dim == 2 ? pw85_2d_contact_function(r, q1, q2, out)
                  : pw85_contact_function(r, q1, q2, out);
}

/* count pairs of dimension dim; near: the near-contact targets, else the
 * far ones. */
static Pairs draw(int dim, int near, uint64_t seed) {
  int const sym = sym_of(dim);
  Pairs p = {dim, pairs_per_workload, NULL, NULL, NULL};
  p.r = malloc(sizeof(double) * dim * p.count);
  p.q1 = malloc(sizeof(double) * sym * p.count);
  p.q2 = malloc(sizeof(double) * sym * p.count);
  uint64_t s = seed;
  for (int i = 0; i < p.count; i++) {
    double *r = p.r + dim * i, *q1 = p.q1 + sym * i, *q2 = p.q2 + sym * i;
    if (dim == 2) {
      form_2d(&s, q1);
      form_2d(&s, q2);
    } else {
      form_3d(&s, q1);
      form_3d(&s, q2);
    }
    double norm = 0.;
    for (int k = 0; k < dim; k++) r[k] = normal(&s), norm += r[k] * r[k];
    norm = sqrt(norm);
    for (int k = 0; k < dim; k++) r[k] /= norm;
    double out[2];
    if (contact(dim, r, q1, q2, out) != PW85_SUCCESS) abort();
    double target;
    if (near) {
      double const d = pow(10., uniform(&s, -12., -3.));
      target = i % 2 ? 1. + d : 1. - d;
    } else {
      target = i % 2 ? pow(10., uniform(&s, -2., log10(0.5)))
                     : pow(10., uniform(&s, log10(2.), 2.));
    }
    double const t = sqrt(target / out[0]);
    for (int k = 0; k < dim; k++) r[k] *= t;
  }
  return p;
}

static void release(Pairs *p) {
  free(p->r), free(p->q1), free(p->q2);
}

static double thread_seconds(void) {
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static volatile double sink;

/* One pass over the pairs: the contact function (overlap = 0) or the
 * overlap test. */
static void pass(Pairs const *p, int overlap) {
  int const sym = sym_of(p->dim);
  double acc = 0.;
  for (int i = 0; i < p->count; i++) {
    double const *r = p->r + p->dim * i, *q1 = p->q1 + sym * i,
                 *q2 = p->q2 + sym * i;
    if (overlap) {
      int result = 0;
      int const s = p->dim == 2 ? pw85_2d_overlap(r, q1, q2, &result)
                                : pw85_overlap(r, q1, q2, &result);
      acc += s + result;
    } else {
      double out[2];
      acc += contact(p->dim, r, q1, q2, out) + out[0];
    }
  }
  sink = acc;
}

/* Seconds per call over passes repeated for about 50 ms. */
static double time_per_call(Pairs const *p, int overlap, int passes) {
  double const t0 = thread_seconds();
  for (int k = 0; k < passes; k++) pass(p, overlap);
  return (thread_seconds() - t0) / ((double)passes * p->count);
}

static int compare(void const *a, void const *b) {
  double const x = *(double const *)a, y = *(double const *)b;
  return (x > y) - (x < y);
}

static double median(double *v, int n) {
  qsort(v, (size_t)n, sizeof *v, compare);
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* One row: the ratio 2D/3D of the contact function and of the overlap
 * test, medians over the rounds, their spreads, and ns per call. */
static void workload(const char *name, int near, int rounds) {
  Pairs p2 = draw(2, near, 2901 + (uint64_t)near);
  Pairs p3 = draw(3, near, 3901 + (uint64_t)near);
  /* passes for about 50 ms of 3D contact function per round */
  double const probe = time_per_call(&p3, 0, 1);
  int passes = (int)(0.05 / (probe * p3.count));
  if (passes < 1) passes = 1;
  double *cf = malloc(sizeof(double) * rounds),
         *ov = malloc(sizeof(double) * rounds),
         *ns[4] = {malloc(sizeof(double) * rounds),
                   malloc(sizeof(double) * rounds),
                   malloc(sizeof(double) * rounds),
                   malloc(sizeof(double) * rounds)};
  for (int k = 0; k < rounds; k++) {
    double const cf3 = time_per_call(&p3, 0, passes);
    double const cf2 = time_per_call(&p2, 0, passes);
    double const ov3 = time_per_call(&p3, 1, passes);
    double const ov2 = time_per_call(&p2, 1, passes);
    cf[k] = cf2 / cf3;
    ov[k] = ov2 / ov3;
    ns[0][k] = 1e9 * cf3, ns[1][k] = 1e9 * cf2;
    ns[2][k] = 1e9 * ov3, ns[3][k] = 1e9 * ov2;
  }
  double lo_cf = cf[0], hi_cf = cf[0], lo_ov = ov[0], hi_ov = ov[0];
  for (int k = 1; k < rounds; k++) {
    lo_cf = fmin(lo_cf, cf[k]), hi_cf = fmax(hi_cf, cf[k]);
    lo_ov = fmin(lo_ov, ov[k]), hi_ov = fmax(hi_ov, ov[k]);
  }
  double const m_cf = median(cf, rounds), m_ov = median(ov, rounds);
  printf("%-14s %6d %8.3f %6.0f%% %8.3f %6.0f%% %8.0f %8.0f %8.0f %8.0f\n",
         name, p2.count, m_cf, 100. * (hi_cf - lo_cf) / m_cf, m_ov,
         100. * (hi_ov - lo_ov) / m_ov, median(ns[0], rounds),
         median(ns[1], rounds), median(ns[2], rounds),
         median(ns[3], rounds));
  free(cf), free(ov);
  for (int j = 0; j < 4; j++) free(ns[j]);
  release(&p2);
  release(&p3);
}

int main(int argc, char **argv) {
  int rounds = 7;
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--rounds") == 0 && i + 1 < argc) {
      rounds = atoi(argv[++i]);
    } else {
      fprintf(stderr, "usage: %s [--rounds N]\n", argv[0]);
      return 2;
    }
  }
  if (rounds < 1) rounds = 1;
  printf("pw85 %s: 2D (pw85_2d.h) against 3D (pw85.h) on comparable pairs, "
         "the same run\n(cf, ov: 2D time / 3D time of the contact function "
         "and of the overlap test, median of %d interleaved rounds; spread: "
         "(max - min)/median of the rounds' ratios; ns per call, medians)\n",
         pw85_version(), rounds);
  printf("%-14s %6s %8s %7s %8s %7s %8s %8s %8s %8s\n", "workload", "pairs",
         "cf 2D/3D", "spread", "ov 2D/3D", "spread", "cf3 ns", "cf2 ns",
         "ov3 ns", "ov2 ns");
  workload("near_contact", 1, rounds);
  workload("far", 0, rounds);
  return 0;
}
