/* SPDX-License-Identifier: BSD-3-Clause */
/* Random sequential addition (pack.h): candidate k (k = 0, 1, 2, … over the
 * whole packing, resumed ones included) is a uniform centre in the box and
 * a uniform rotation (3D) or angle (2D), drawn from a counter-based stream
 * of (seed, k) alone; it is kept if the index's overlap_any() finds it
 * overlapping (or touching) no ellipsoid (ellipse) kept before it.
 * Candidates are decided in batches on threads (overlap_any_batch()), then
 * accepted in their order, one that follows an acceptance in the same
 * batch decided again: the result of the serial loop, for any thread count
 * (pw85_index.h, pw85_2d_index.h). The packing saturates after 10⁶
 * rejections in a row. */
#include <math.h>
#include <pw85/pw85_index.h> /* PW85_INDEX_NO_ID, both dimensions */
#include <stdlib.h>
#include <string.h>

#include "pack.h"

enum { batch = 1024 };
static uint64_t const max_failures = 1000000;

/* SplitMix64's finaliser (Steele, Lea, Flood, OOPSLA 2014) on (seed, k,
 * draw): a counter-based stream, uniform doubles in [0, 1). */
static uint64_t mix(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
struct stream {
  uint64_t key, n;
};
static double next_unit(struct stream *s) {
  uint64_t const z = mix(s->key + 0x9E3779B97F4A7C15ull * ++s->n);
  return (double)(z >> 11) * 0x1p-53;
}

/* A uniform rotation: a unit quaternion (w, x, y, z; Marsaglia, Ann. Math.
 * Stat. 43(2), 645–646, 1972). */
static void uniform_quaternion(struct stream *s, double p[4]) {
  double w, x, y, z, s1, s2;
  do {
    w = 2 * next_unit(s) - 1, x = 2 * next_unit(s) - 1;
    s1 = w * w + x * x;
  } while (s1 >= 1);
  do {
    y = 2 * next_unit(s) - 1, z = 2 * next_unit(s) - 1;
    s2 = y * y + z * z;
  } while (s2 >= 1 || s2 == 0);
  double const f = sqrt((1 - s1) / s2);
  p[0] = w, p[1] = x, p[2] = y * f, p[3] = z * f;
}

/* Candidate k: centre, orientation (a quaternion, or an angle uniform in
 * [−π, π)), form. */
static int candidate(struct pack_config const *cf, uint64_t k, double *c, double *p,
                     double *q) {
  struct stream s = {mix(cf->seed ^ mix(k + 0x2028u)), 0};
  for (int d = 0; d < cf->dims->dim; d++) c[d] = cf->box[d] * next_unit(&s);
  if (cf->dims->orient == 4)
    uniform_quaternion(&s, p);
  else
    p[0] = 3.14159265358979323846 * (2 * next_unit(&s) - 1);
  return cf->dims->form(cf->axes, p, q);
}

int pack_rsa(struct pack_config const *cf, struct pack_state *st,
             pack_progress progress, void *context) {
  struct dim_ops const *d = cf->dims;
  size_t const dim = (size_t)d->dim, sym = (size_t)d->sym, orient = (size_t)d->orient;
  memcpy(st->box, cf->box, sizeof st->box);
  void *index = NULL;
  int status = d->index_create(cf->box, &index);
  if (status != PW85_SUCCESS) return -status;
  for (size_t i = 0; i < st->count && status == PW85_SUCCESS; i++)
    status = d->index_insert(index, i, st->centres + dim * i, st->forms + sym * i);
  if (status != PW85_SUCCESS) {
    d->index_destroy(index);
    return -status;
  }
  double *c = malloc(batch * dim * sizeof *c), *q = malloc(batch * sym * sizeof *q),
         *p = malloc(batch * orient * sizeof *p);
  int *results = malloc(batch * sizeof *results);
  size_t *ids = malloc(batch * sizeof *ids);
  int outcome = PACK_DONE;
  uint64_t failures = 0;
  if (!c || !q || !p || !results || !ids) outcome = -PW85_ENOMEM;
  while (outcome == PACK_DONE && st->count < cf->target) {
    if (progress(context, st)) {
      outcome = PACK_STOPPED;
      break;
    }
    for (int b = 0; b < batch && status == PW85_SUCCESS; b++)
      status = candidate(cf, st->attempts + (uint64_t)b, c + dim * b, p + orient * b,
                         q + sym * b);
    if (status == PW85_SUCCESS)
      status = d->index_overlap_any_batch(index, batch, c, dim, q, sym, NULL, results, ids,
                                          NULL, cf->threads);
    if (status != PW85_SUCCESS) {
      outcome = -status;
      break;
    }
    int accepted_in_batch = 0;
    for (int b = 0; b < batch && st->count < cf->target; b++) {
      st->attempts++;
      int result = results[b];
      if (result > 0 && accepted_in_batch) {
        size_t id;
        status = d->index_overlap_any(index, c + dim * b, q + sym * b, PW85_INDEX_NO_ID,
                                      &result, &id);
        if (status != PW85_SUCCESS) break;
      }
      if (result <= 0) {
        if (++failures >= max_failures) break;
        continue;
      }
      status = d->index_insert(index, st->count, c + dim * b, q + sym * b);
      if (status != PW85_SUCCESS) break;
      size_t const i = st->count++;
      memcpy(st->centres + dim * i, c + dim * b, dim * sizeof(double));
      memcpy(st->forms + sym * i, q + sym * b, sym * sizeof(double));
      memcpy(st->axes + dim * i, cf->axes, dim * sizeof(double));
      memcpy(st->orientations + orient * i, p + orient * b, orient * sizeof(double));
      failures = 0;
      accepted_in_batch = 1;
    }
    if (status != PW85_SUCCESS) outcome = -status;
    else if (failures >= max_failures) outcome = PACK_SATURATED;
  }
  free(c), free(q), free(p), free(results), free(ids);
  d->index_destroy(index);
  return outcome;
}
