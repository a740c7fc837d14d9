/* SPDX-License-Identifier: BSD-3-Clause */
/* Packing ellipsoids (docs/packing.rst): N triaxial ellipsoids 1 : 0.5 :
 * 0.2, isotropic, packed by pw85_pack() to a packing fraction in a
 * periodic cube, then checked as a user would: the all-pairs query finds
 * no overlapping pair, and the overlap energy of the packing is 0.
 *
 * Usage: pack [N [FRACTION [THREADS]]]  (default: 1000 ellipsoids at 0.5,
 * 2 threads). Exit status 0 when the checks pass. */
#include <stdio.h>
#include <stdlib.h>

#include <pw85/pw85_index.h>
#include <pw85/pw85_pack.h>

static int progress(pw85_pack_progress const *p, void *data) {
  (void)data;
  printf("  step %5zu: %6zu overlapping pairs, energy per ellipsoid %.2e\n",
         p->steps, p->pairs, p->energy);
  return 0; /* non-zero would stop the packer */
}

int main(int argc, char **argv) {
  size_t const n = argc > 1 ? strtoul(argv[1], NULL, 10) : 1000;
  double const fraction = argc > 2 ? strtod(argv[2], NULL) : 0.5;
  int const threads = argc > 3 ? atoi(argv[3]) : 2;
  double *a = malloc(3 * n * sizeof *a), *c = malloc(3 * n * sizeof *c),
         *p = malloc(4 * n * sizeof *p), *q = malloc(6 * n * sizeof *q);
  size_t *ids = malloc(n * sizeof *ids);
  if (!a || !c || !p || !q || !ids) return 1;
  for (size_t i = 0; i < n; i++) { /* any mix of sizes and shapes */
    a[3 * i] = 1.0, a[3 * i + 1] = 0.5, a[3 * i + 2] = 0.2;
    ids[i] = i;
  }

  pw85_pack_options options;
  pw85_pack_options_init(&options); /* the defaults, then what differs */
  options.target = fraction;
  options.seed = 1;
  options.threads = threads;
  options.time_limit = 60.0; /* seconds */
  options.progress = progress;
  options.progress_every = 100;
  double box[3], phi;
  int outcome;
  int status = pw85_pack(n, a, &options, box, c, p, q, &phi, &outcome);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_pack: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("%zu ellipsoids in a box of side %.3f: packing fraction %.4f (%s)\n",
         n, box[0], phi, outcome == PW85_PACK_TARGET ? "target reached"
                         : outcome == PW85_PACK_JAMMED ? "jammed" : "stopped");

  /* The check: every pair and image, decided as pw85_overlap() does. */
  pw85_index *index = NULL;
  size_t count = 0;
  double energy = -1.0;
  status = pw85_index_create(box, &index);
  if (status == PW85_SUCCESS)
    status = pw85_index_insert_many(index, n, ids, c, q);
  if (status == PW85_SUCCESS)
    status = pw85_index_overlapping_pairs(index, threads, 0, NULL, NULL, NULL,
                                          &count);
  /* The overlap energy Σ(1 − μ)² over the pairs with μ < 1: here 0. */
  if (status == PW85_SUCCESS)
    status = pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL, NULL,
                               threads, n, &energy, NULL, NULL);
  pw85_index_destroy(index);
  free(a), free(c), free(p), free(q), free(ids);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "check: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("overlapping pairs: %zu, overlap energy: %g\n", count, energy);
  return count == 0 && energy == 0.0 && outcome == PW85_PACK_TARGET ? 0 : 1;
}
