/* SPDX-License-Identifier: BSD-3-Clause */
/* The certified packer of pw85_pack.h as a method of pw85-pack (pack.h):
 * config->target identical ellipsoids of config->axes, at the packing
 * fraction of config->box (its sides as the aspect), with the seed, the
 * threads, the time limit; progress() returning non-zero (Ctrl-C) cancels
 * pw85_pack(). pw85_pack() starts from nothing: a state that already
 * holds ellipsoids (a resumed file) is refused by the command, not here.
 * The state receives the configuration pw85_pack() returns, always
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
  size_t const n = cf->target;
  double const pi = 3.14159265358979323846;
  double const v = 4.0 / 3.0 * pi * cf->axes[0] * cf->axes[1] * cf->axes[2];
  double *semi_axes = malloc(n * 3 * sizeof *semi_axes);
  if (semi_axes == NULL) return -PW85_ENOMEM;
  for (size_t i = 0; i < n; i++)
    memcpy(semi_axes + 3 * i, cf->axes, sizeof cf->axes);
  struct relay relay = {progress, context, st};
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = (double)n * v / (cf->box[0] * cf->box[1] * cf->box[2]);
  o.seed = cf->seed;
  memcpy(o.aspect, cf->box, sizeof o.aspect);
  o.threads = cf->threads;
  o.time_limit = cf->time_limit;
  o.progress_every = 10; /* a prompt Ctrl-C at large n */
  o.progress = relay_progress;
  o.progress_data = &relay;
  st->count = 0, st->attempts = 0, st->steps = 0;
  st->phi = 0;
  double phi = 0;
  int outcome = PW85_PACK_TARGET;
  int const status = pw85_pack(n, semi_axes, &o, st->box, st->centres,
                               st->quaternions, st->forms, &phi, &outcome);
  if (status != PW85_SUCCESS) {
    free(semi_axes);
    return -status;
  }
  memcpy(st->axes, semi_axes, n * 3 * sizeof *semi_axes);
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
