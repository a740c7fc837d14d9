/* SPDX-License-Identifier: BSD-3-Clause */
/* meson test --benchmark: pw85_pack() on the cases of issue 27, each
 * checked by the all-pairs query. Usage:
 *   bench-pack CASE [N [THREADS [TIME_LIMIT [TARGET]]]]
 * CASE: spheres (0.60), triaxial (1 : 0.8 : 0.6, 0.65), needles
 * (1 : 0.5 : 0.2, 0.55), prolate (1 : 0.2 : 0.2 along z, 0.55), poly
 * (sizes uniform in 1–3, 1 : 0.5 : 0.2, 0.50); ellipses (pw85_2d_pack(),
 * aspect 1.3, 0.85) and ellipses5 (aspect 5, 0.80); TARGET overrides the
 * packing fraction of the case. Prints one line per case: φ reached,
 * outcome, wall time, steps, time per ellipsoid; for ellipses also the
 * time over that of the all-pairs overlap query on the result (the
 * yardstick, in the same run). Exit status 1 if a packing has an
 * overlapping pair or the call fails. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pw85.h"
#include "pw85_index.h"
#include "pw85_2d_index.h"
#include "pw85_2d_pack.h"
#include "pw85_pack.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static size_t last_steps;

static int progress(pw85_pack_progress const *p, void *data) {
  (void)data;
  last_steps = p->steps;
  if (getenv("PW85_PACK_VERBOSE"))
    fprintf(stderr, "  step %zu  phi %.4f  trial %.4f  U/N %.3g  pairs %zu  %.1f s\n",
            p->steps, p->phi, p->phi_trial, p->energy, p->pairs, p->elapsed);
  return 0;
}

static const char *outcome_name(int o) {
  static const char *names[] = {"target", "limit", "jammed", "cancelled"};
  return o >= 0 && o < 4 ? names[o] : "?";
}

static void options(pw85_pack_options *o, double target, int threads,
                    double limit) {
  pw85_pack_options_init(o);
  o->target = target;
  o->seed = 27;
  o->threads = threads;
  o->time_limit = limit;
  o->progress = progress;
  o->progress_every = 100;
}

/* n ellipses of the given aspect with pw85_2d_pack(), checked and timed
 * against the all-pairs query of the index of ellipses. */
static int ellipses(char const *which, size_t n, double aspect,
                    double target, int threads, double limit) {
  double *a = malloc(2 * n * sizeof *a), *c = malloc(2 * n * sizeof *c),
         *q = malloc(3 * n * sizeof *q);
  size_t *ids = malloc(n * sizeof *ids), count = 1;
  for (size_t i = 0; i < n; i++) {
    a[2 * i] = 1.0;
    a[2 * i + 1] = 1.0 / aspect;
    ids[i] = i;
  }
  pw85_pack_options o;
  options(&o, target, threads, limit);
  double box[2], phi = 0;
  int outcome = -1;
  double const t0 = now();
  int st = pw85_2d_pack(n, a, &o, box, c, NULL, q, &phi, &outcome);
  double const t = now() - t0;
  if (st != PW85_SUCCESS) {
    fprintf(stderr, "pw85_2d_pack: %s\n", pw85_strerror(st));
    return 1;
  }
  pw85_2d_index *index = NULL;
  double t1 = 0;
  if (pw85_2d_index_create(box, &index) != 0 ||
      pw85_2d_index_insert_many(index, n, ids, c, q) != 0 ||
      (t1 = now(), pw85_2d_index_overlapping_pairs(index, threads, 0, NULL,
                                                   NULL, NULL, &count)) != 0 ||
      count != 0) {
    fprintf(stderr, "%s: %zu overlapping pairs\n", which, count);
    return 1;
  }
  double const yardstick = now() - t1;
  printf("%-9s N=%-7zu threads=%d target=%.3f phi=%.4f outcome=%-9s "
         "time=%.1f s steps>=%zu us/ellipse=%.0f time/all-pairs-query=%.0f\n",
         which, n, threads, target, phi, outcome_name(outcome), t, last_steps,
         1e6 * t / (double)n, t / yardstick);
  pw85_2d_index_destroy(index);
  free(ids);
  free(a);
  free(c);
  free(q);
  return 0;
}

int main(int argc, char **argv) {
  const char *which = argc > 1 ? argv[1] : "spheres";
  size_t const n = argc > 2 ? (size_t)atol(argv[2]) : 10000;
  int const threads = argc > 3 ? atoi(argv[3]) : 2;
  double const limit = argc > 4 ? atof(argv[4]) : 600.0;
  double shape[3] = {1, 1, 1}, target = 0.6;
  int orientation = PW85_PACK_ISOTROPIC, poly = 0;
  if (strcmp(which, "spheres") == 0) {
    target = 0.60;
  } else if (strcmp(which, "triaxial") == 0) {
    shape[1] = 0.8, shape[2] = 0.6, target = 0.65;
  } else if (strcmp(which, "needles") == 0) {
    shape[1] = 0.5, shape[2] = 0.2, target = 0.55;
  } else if (strcmp(which, "prolate") == 0) {
    shape[1] = 0.2, shape[2] = 0.2, target = 0.55;
    orientation = PW85_PACK_ALIGNED;
  } else if (strcmp(which, "poly") == 0) {
    shape[1] = 0.5, shape[2] = 0.2, target = 0.50, poly = 1;
  } else if (strcmp(which, "ellipses") == 0 ||
             strcmp(which, "ellipses5") == 0) {
    int const five = which[8] == '5';
    return ellipses(which, n, five ? 5.0 : 1.3,
                    argc > 5 ? atof(argv[5]) : five ? 0.80 : 0.85, threads,
                    limit);
  } else {
    fprintf(stderr, "unknown case %s\n", which);
    return 2;
  }
  if (argc > 5) target = atof(argv[5]);
  double *a = malloc(3 * n * sizeof *a), *c = malloc(3 * n * sizeof *c),
         *p = malloc(4 * n * sizeof *p), *q = malloc(6 * n * sizeof *q);
  for (size_t i = 0; i < n; i++) {
    /* sizes uniform in [1, 3] by a fixed low-discrepancy sequence */
    double const s = poly ? 1.0 + 2.0 * fmod(0.5 + 0.6180339887498949 * (double)i, 1.0)
                          : 1.0;
    for (int k = 0; k < 3; k++) a[3 * i + k] = s * shape[k];
  }
  pw85_pack_options o;
  options(&o, target, threads, limit);
  o.orientation = orientation;
  double box[3], phi = 0;
  int outcome = -1;
  double const t0 = now();
  int const st = pw85_pack(n, a, &o, box, c, p, q, &phi, &outcome);
  double const t = now() - t0;
  if (st != PW85_SUCCESS) {
    fprintf(stderr, "pw85_pack: %s\n", pw85_strerror(st));
    return 1;
  }
  /* The check of a user: every pair and image, by the all-pairs query. */
  pw85_index *index = NULL;
  size_t *ids = malloc(n * sizeof *ids), count = 1;
  for (size_t i = 0; i < n; i++) ids[i] = i;
  if (pw85_index_create(box, &index) != 0 ||
      pw85_index_insert_many(index, n, ids, c, q) != 0 ||
      pw85_index_overlapping_pairs(index, threads, 0, NULL, NULL, NULL,
                                   &count) != 0 ||
      count != 0) {
    fprintf(stderr, "%s: %zu overlapping pairs\n", which, count);
    return 1;
  }
  printf("%-9s N=%-7zu threads=%d target=%.3f phi=%.4f outcome=%-9s "
         "time=%.1f s steps>=%zu us/ellipsoid=%.0f\n",
         which, n, threads, target, phi, outcome_name(outcome), t, last_steps,
         1e6 * t / (double)n);
  pw85_index_destroy(index);
  free(ids);
  free(a);
  free(c);
  free(p);
  free(q);
  return 0;
}
