/* SPDX-License-Identifier: BSD-3-Clause */
/* The certified packer of pw85_pack.h (or of pw85_2d_pack.h in 2D) as a
 * method of pw85-pack (pack.h): config->target identical ellipsoids (or
 * ellipses) of config->axes, at the packing
 * fraction of config->box (its sides as the aspect), with the seed, the
 * threads, the time limit; progress() returning non-zero (Ctrl-C) cancels
 * the packer. The packer starts from nothing: a state that already
 * holds ellipsoids (a resumed file) is refused by the command, not here.
 * The state receives the configuration the packer returns, always
 * certified; its box is config->box where the target was reached, a larger
 * one (the certified packing fraction) otherwise. */
#include <pw85/pw85_pack.h>
#include <stdlib.h>
#include <string.h>

#include "pack.h"

struct relay {
  pack_progress progress;
  void *context;
  struct pack_state *state;
};

/* pw85_pack()'s progress, shown through the command's callback: the state
 * holds no ellipsoid yet, only the certified fraction and the steps. */
static int relay_progress(pw85_pack_progress const *p, void *data) {
  struct relay *r = data;
  r->state->phi = p->phi;
  r->state->steps = p->steps;
  return r->progress(r->context, r->state);
}

int pack_fire(struct pack_config const *cf, struct pack_state *st,
              pack_progress progress, void *context) {
  struct dim_ops const *d = cf->dims;
  size_t const n = cf->target, dim = (size_t)d->dim;
  double const v = d->measure(cf->axes);
  double *semi_axes = malloc(n * dim * sizeof *semi_axes);
  if (semi_axes == NULL) return -PW85_ENOMEM;
  for (size_t i = 0; i < n; i++)
    memcpy(semi_axes + dim * i, cf->axes, dim * sizeof *semi_axes);
  struct relay relay = {progress, context, st};
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  double box_measure = 1;
  for (size_t k = 0; k < dim; k++) box_measure *= cf->box[k];
  o.target = (double)n * v / box_measure;
  o.seed = cf->seed;
  memcpy(o.aspect, cf->box, sizeof o.aspect); /* 2D: aspect[2] not read */
  o.threads = cf->threads;
  o.time_limit = cf->time_limit;
  o.progress_every = 10; /* a prompt Ctrl-C at large n */
  o.progress = relay_progress;
  o.progress_data = &relay;
  st->count = 0, st->attempts = 0, st->steps = 0;
  st->phi = 0;
  double phi = 0;
  int outcome = PW85_PACK_TARGET;
  int const status = d->pack(n, semi_axes, &o, st->box, st->centres, st->orientations,
                             st->forms, &phi, &outcome);
  if (status != PW85_SUCCESS) {
    free(semi_axes);
    return -status;
  }
  memcpy(st->axes, semi_axes, n * dim * sizeof *semi_axes);
  free(semi_axes);
  st->count = n;
  st->phi = phi;
  switch (outcome) {
    case PW85_PACK_TARGET:
      return PACK_DONE;
    case PW85_PACK_JAMMED:
      return PACK_SATURATED;
    default:
      return PACK_STOPPED; /* LIMIT, CANCELLED: out of time, interrupted */
  }
}
