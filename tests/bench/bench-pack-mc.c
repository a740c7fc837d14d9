/* SPDX-License-Identifier: BSD-3-Clause */
/* meson test --benchmark: pw85_pack() against a Monte Carlo compression
 * written as a user of pw85 2.3 would write it with the public API alone
 * (the loop of tutorial/rsa.c to a starting fraction, then sweeps of
 * random moves each accepted by pw85_index_overlap_any(), and after each
 * sweep an attempt to shrink the box by a factor, affinely, accepted when
 * pw85_index_overlapping_pairs() finds no pair; the factor grows by 10%
 * after a success and halves after a failure). Both pack N triaxial
 * ellipsoids 1 : 0.5 : 0.2, isotropic; prints the time of each to the
 * fraction that the Monte Carlo reaches (or to the target), and the ratio.
 * Usage: bench-pack-mc [N [TARGET [MC_TIME_LIMIT [THREADS]]]]. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "pw85.h"
#include "pw85_index.h"
#include "pw85_pack.h"

#define PI 3.14159265358979323846

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t state = 2026;
static double uniform(void) { /* splitmix64 */
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

static void random_quaternion(double p[4]) {
  double u1 = uniform(), u2 = uniform(), u3 = uniform();
  p[0] = sqrt(1 - u1) * sin(2 * PI * u2);
  p[1] = sqrt(1 - u1) * cos(2 * PI * u2);
  p[2] = sqrt(u1) * sin(2 * PI * u3);
  p[3] = sqrt(u1) * cos(2 * PI * u3);
}

/* p ← exp(w/2)·p, normalised */
static void turn(double const w[3], double p[4]) {
  double t = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  double s = t > 0 ? sin(0.5 * t) / t : 0.5;
  double r[4] = {cos(0.5 * t), s * w[0], s * w[1], s * w[2]}, o[4];
  o[0] = r[0] * p[0] - r[1] * p[1] - r[2] * p[2] - r[3] * p[3];
  o[1] = r[0] * p[1] + r[1] * p[0] + r[2] * p[3] - r[3] * p[2];
  o[2] = r[0] * p[2] - r[1] * p[3] + r[2] * p[0] + r[3] * p[1];
  o[3] = r[0] * p[3] + r[1] * p[2] - r[2] * p[1] + r[3] * p[0];
  double nn = sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + o[3] * o[3]);
  for (int k = 0; k < 4; k++) p[k] = o[k] / nn;
}

static pw85_index *build(double const box[3], size_t n, size_t const *ids,
                         double const *c, double const *q) {
  pw85_index *index = NULL;
  if (pw85_index_create(box, &index) != 0 ||
      pw85_index_insert_many(index, n, ids, c, q) != 0)
    exit(1);
  return index;
}

int main(int argc, char **argv) {
  size_t const n = argc > 1 ? (size_t)atol(argv[1]) : 10000;
  double const target = argc > 2 ? atof(argv[2]) : 0.5;
  double const limit = argc > 3 ? atof(argv[3]) : 300.0;
  int const threads = argc > 4 ? atoi(argv[4]) : 2;
  double const axes[3] = {1.0, 0.5, 0.2};
  double const volume = 4.0 / 3.0 * PI * (double)n * 0.1;
  double *c = malloc(3 * n * sizeof *c), *p = malloc(4 * n * sizeof *p),
         *q = malloc(6 * n * sizeof *q), *c2 = malloc(3 * n * sizeof *c2);
  size_t *ids = malloc(n * sizeof *ids);
  for (size_t i = 0; i < n; i++) ids[i] = i;

  /* 1. Random sequential addition to 0.25 (tutorial/rsa.c). */
  double const start = 0.25;
  double side = cbrt(volume / start);
  double box[3] = {side, side, side};
  double const t0 = now();
  pw85_index *index = NULL;
  pw85_index_create(box, &index);
  for (size_t i = 0; i < n;) {
    double cc[3] = {uniform() * side, uniform() * side, uniform() * side};
    random_quaternion(p + 4 * i);
    pw85_ellipsoid_quaternion(axes, p + 4 * i, q + 6 * i);
    int result;
    size_t hit;
    pw85_index_overlap_any(index, cc, q + 6 * i, PW85_INDEX_NO_ID, &result,
                           &hit);
    if (result > 0) {
      for (int k = 0; k < 3; k++) c[3 * i + k] = cc[k];
      pw85_index_insert(index, i, cc, q + 6 * i);
      i++;
    }
  }
  /* 2. Moves and box shrinking. */
  double step = 0.1, factor = 0.01, phi = start;
  size_t sweeps = 0;
  while (phi < target && now() - t0 < limit) {
    size_t accepted = 0;
    for (size_t i = 0; i < n; i++) {
      double cc[3], pp[4] = {p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]},
             w[3], qq[6];
      for (int k = 0; k < 3; k++) {
        cc[k] = c[3 * i + k] + step * (2 * uniform() - 1);
        cc[k] -= floor(cc[k] / box[k]) * box[k];
        w[k] = step * (2 * uniform() - 1);
      }
      turn(w, pp);
      pw85_ellipsoid_quaternion(axes, pp, qq);
      int result;
      size_t hit;
      pw85_index_overlap_any(index, cc, qq, i, &result, &hit);
      if (result > 0) {
        pw85_index_update(index, i, cc, qq);
        for (int k = 0; k < 3; k++) c[3 * i + k] = cc[k];
        for (int k = 0; k < 4; k++) p[4 * i + k] = pp[k];
        for (int k = 0; k < 6; k++) q[6 * i + k] = qq[k];
        accepted++;
      }
    }
    /* keep the acceptance near one half */
    step *= (double)accepted / (double)n > 0.5 ? 1.1 : 0.9;
    double const s = 1.0 - factor;
    double nb[3] = {box[0] * s, box[1] * s, box[2] * s};
    for (size_t k = 0; k < 3 * n; k++) c2[k] = c[k] * s;
    pw85_index *trial = build(nb, n, ids, c2, q);
    size_t count = 0;
    pw85_index_overlapping_pairs(trial, threads, 0, NULL, NULL, NULL, &count);
    if (count == 0) {
      pw85_index_destroy(index);
      index = trial;
      for (int k = 0; k < 3; k++) box[k] = nb[k];
      for (size_t k = 0; k < 3 * n; k++) c[k] = c2[k];
      phi = volume / (box[0] * box[1] * box[2]);
      factor *= 1.1;
    } else {
      pw85_index_destroy(trial);
      factor *= 0.5;
    }
    sweeps++;
  }
  double const t_mc = now() - t0;
  double const reached = phi < target ? phi : target;
  pw85_index_destroy(index);

  /* 3. pw85_pack() to the same fraction. */
  double *a = malloc(3 * n * sizeof *a);
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < 3; k++) a[3 * i + k] = axes[k];
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = reached;
  o.threads = threads;
  double pbox[3], pphi;
  int outcome;
  double const t1 = now();
  int const st = pw85_pack(n, a, &o, pbox, c, p, q, &pphi, &outcome);
  double const t_pack = now() - t1;
  if (st != 0 || outcome != PW85_PACK_TARGET) {
    fprintf(stderr, "pw85_pack: status %d, outcome %d\n", st, outcome);
    return 1;
  }
  printf("N=%zu 1:0.5:0.2  Monte Carlo (public API, %zu sweeps): phi %.4f "
         "in %.1f s%s;  pw85_pack to %.4f: %.1f s;  ratio %.1f%s\n",
         n, sweeps, phi, t_mc, phi < target ? " (time limit)" : "", reached,
         t_pack, t_mc / t_pack, phi < target ? " (at least)" : "");
  free(a);
  free(c);
  free(c2);
  free(p);
  free(q);
  free(ids);
  return 0;
}
