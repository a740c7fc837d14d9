/* SPDX-License-Identifier: BSD-3-Clause */
/* Random sequential addition: triaxial ellipsoids (semi-axes 1, 0.5, 0.2,
 * random orientations) dropped one at a time at random places of a
 * periodic cube, each kept only if it overlaps none already there, until a
 * target packing fraction is reached or too many attempts in a row fail.
 * The packing is then checked by the all-pairs query: no overlapping pair.
 *
 * Usage: rsa [N [FRACTION]]  (default: 10000 ellipsoids at 0.25)
 * Prints the packing fraction reached and the time; exit status 0 when the
 * check passes. */
#include <math.h>
#include <pw85/pw85_index.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* A small, portable random generator (xorshift64*), uniform in [0, 1). */
static double uniform(uint64_t *state) {
  *state ^= *state >> 12;
  *state ^= *state << 25;
  *state ^= *state >> 27;
  return (double)((*state * 2685821657736338717ull) >> 11) * 0x1p-53;
}

/* Q = R·diag(a²)·Rᵀ for a random rotation R (a random unit quaternion,
 * drawn by rejection in the unit ball of R⁴). */
static void random_form(uint64_t *state, double const a[3], double q[6]) {
  double w, x, y, z, n;
  do {
    w = 2. * uniform(state) - 1., x = 2. * uniform(state) - 1.;
    y = 2. * uniform(state) - 1., z = 2. * uniform(state) - 1.;
    n = w * w + x * x + y * y + z * z;
  } while (n > 1. || n < 1e-6);
  n = sqrt(n);
  w /= n, x /= n, y /= n, z /= n;
  double const r[3][3] = {
      {1. - 2. * (y * y + z * z), 2. * (x * y - w * z), 2. * (x * z + w * y)},
      {2. * (x * y + w * z), 1. - 2. * (x * x + z * z), 2. * (y * z - w * x)},
      {2. * (x * z - w * y), 2. * (y * z + w * x), 1. - 2. * (x * x + y * y)}};
  int k = 0;
  for (int i = 0; i < 3; i++)
    for (int j = i; j < 3; j++, k++)
      q[k] = r[i][0] * a[0] * a[0] * r[j][0] + r[i][1] * a[1] * a[1] * r[j][1] +
             r[i][2] * a[2] * a[2] * r[j][2];
}

int main(int argc, char **argv) {
  size_t const n = argc > 1 ? (size_t)strtoul(argv[1], NULL, 10) : 10000;
  double const target = argc > 2 ? strtod(argv[2], NULL) : 0.25;
  double const a[3] = {1., .5, .2};
  double const pi = 3.14159265358979323846;
  double const volume = 4. / 3. * pi * a[0] * a[1] * a[2];
  /* The cube that n ellipsoids fill to the target fraction. */
  double const side = cbrt((double)n * volume / target);
  double const box[3] = {side, side, side};

  pw85_index *index = NULL;
  int status = pw85_index_create(box, &index);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_index_create: %s\n", pw85_strerror(status));
    return 1;
  }
  uint64_t state = 0x9E3779B97F4A7C15ull;
  size_t placed = 0, attempts = 0, failures_in_a_row = 0;
  clock_t const t0 = clock();
  while (placed < n && failures_in_a_row < 100000) {
    double c[3], q[6];
    for (int k = 0; k < 3; k++) c[k] = side * uniform(&state);
    random_form(&state, a, q);
    attempts++;
    int result;
    size_t id;
    status = pw85_index_overlap_any(index, c, q, PW85_INDEX_NO_ID, &result, &id);
    if (status != PW85_SUCCESS) break;
    if (result <= 0) { /* overlaps (or touches) ellipsoid id: rejected */
      failures_in_a_row++;
      continue;
    }
    status = pw85_index_insert(index, placed, c, q);
    if (status != PW85_SUCCESS) break;
    placed++;
    failures_in_a_row = 0;
  }
  double const seconds = (double)(clock() - t0) / CLOCKS_PER_SEC;
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_index: %s\n", pw85_strerror(status));
    pw85_index_destroy(index);
    return 1;
  }

  /* The check: the all-pairs query, on 2 threads, finds no overlap. Asked
   * with no room, it returns the number of pairs. */
  size_t overlapping = 0;
  status = pw85_index_overlapping_pairs(index, 2, 0, NULL, NULL, NULL, &overlapping);
  pw85_index_destroy(index);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_index_overlapping_pairs: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("%zu ellipsoids placed in %zu attempts, packing fraction %.4f "
         "(target %.4f), %.3f s\n", placed, attempts,
         (double)placed * volume / (side * side * side), target, seconds);
  printf("overlapping pairs: %zu\n", overlapping);
  return overlapping == 0 ? 0 : 1;
}
