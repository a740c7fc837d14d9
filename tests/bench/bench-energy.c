/* SPDX-License-Identifier: BSD-3-Clause */
/* meson test --benchmark: pw85_index_energy() (the overlap energy, forces
 * and torques) on N ellipsoids 1 : 0.5 : 0.2 at random centres and
 * orientations, packing fraction PHI (overlapping: the start of a
 * relaxation), on 1 and THREADS threads; the yardstick is the all-pairs
 * query pw85_index_pairs_within(t = 1) of the same run, which the energy
 * call makes first. Usage: bench-energy [N [PHI [THREADS]]]. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pw85.h"
#include "pw85_index.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static uint64_t state = 7;
static double uniform(void) { /* splitmix64 */
  uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return (double)((z ^ (z >> 31)) >> 11) * 0x1p-53;
}

int main(int argc, char **argv) {
  size_t const n = argc > 1 ? (size_t)atol(argv[1]) : 1000000;
  double const phi = argc > 2 ? atof(argv[2]) : 0.4;
  int const threads = argc > 3 ? atoi(argv[3]) : 2;
  double const axes[3] = {1.0, 0.5, 0.2};
  double const side = cbrt(4.0 / 3.0 * 3.14159265358979323846 * 0.1 *
                           (double)n / phi);
  double const box[3] = {side, side, side};
  double *c = malloc(3 * n * sizeof *c), *q = malloc(6 * n * sizeof *q);
  size_t *ids = malloc(n * sizeof *ids);
  for (size_t i = 0; i < n; i++) {
    double p[4], norm = 0;
    for (int k = 0; k < 4; k++) {
      p[k] = 2 * uniform() - 1;
      norm += p[k] * p[k];
    }
    for (int k = 0; k < 4; k++) p[k] /= sqrt(norm);
    pw85_ellipsoid_quaternion(axes, p, q + 6 * i);
    for (int k = 0; k < 3; k++) c[3 * i + k] = uniform() * side;
    ids[i] = i;
  }
  pw85_index *index = NULL;
  if (pw85_index_create(box, &index) != 0 ||
      pw85_index_insert_many(index, n, ids, c, q) != 0)
    return 1;
  double *f = malloc(3 * n * sizeof *f), *t = malloc(3 * n * sizeof *t);
  double *f1 = malloc(3 * n * sizeof *f1);
  int const counts[2] = {1, threads};
  double e[2], te[2], tp[2];
  size_t pairs = 0;
  for (int k = 0; k < 2; k++) {
    double t0 = now();
    if (pw85_index_pairs_within(index, 1.0, counts[k], 0, NULL, NULL, NULL,
                                &pairs) != 0)
      return 1;
    tp[k] = now() - t0;
    t0 = now();
    if (pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL, NULL,
                          counts[k], n, e + k, f, t) != 0)
      return 1;
    te[k] = now() - t0;
    if (k == 0) memcpy(f1, f, 3 * n * sizeof *f);
  }
  int const same = e[0] == e[1] && memcmp(f, f1, 3 * n * sizeof *f) == 0;
  printf("energy N=%zu phi=%.2f pairs=%zu: 1 thread %.2f s (pairs query "
         "%.2f s), %d threads %.2f s (pairs query %.2f s); energy/query "
         "%.2f; same bits: %s\n",
         n, phi, pairs, te[0], tp[0], threads, te[1], tp[1], te[1] / tp[1],
         same ? "yes" : "NO");
  pw85_index_destroy(index);
  free(c);
  free(q);
  free(ids);
  free(f);
  free(f1);
  free(t);
  return same ? 0 : 1;
}
