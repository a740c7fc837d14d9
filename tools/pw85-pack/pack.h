/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85-pack: what the packing methods and the command share. A method is
 * one function (pack_method below): it grows a configuration from its
 * current state towards the target count, calling `progress` now and then,
 * and returns how it stopped. The command (pw85_pack.c) picks it by name
 * (pack_methods[]), and writes whatever state it returns: every ellipsoid
 * (or ellipse) in it must be certified free of overlaps at every return.
 * Both run in 3D (ellipsoids) or 2D (ellipses, --2d): what differs is in
 * dim.h. */
#ifndef PW85_PACK_TOOL_H
#define PW85_PACK_TOOL_H

#include <stddef.h>
#include <stdint.h>

#include "dim.h"

/* What is asked: the dimension (dims->dim, 2 or 3), a periodic box (a
 * square or cube; only its first dims->dim sides are read), identical
 * shapes of semi-axes `axes` (first dims->dim read), a target count, a
 * seed, threads, a time limit in seconds (0: none; the command also stops
 * a method through progress() when it is reached). */
struct pack_config {
  struct dim_ops const *dims;
  size_t target;
  double axes[3];
  double box[3];
  uint64_t seed;
  int threads;
  double time_limit;
};

/* The configuration, grown in place: count ellipsoids, each with its
 * centre (3), form (6, the q of pw85.h), semi-axes (3) and orientation, a
 * unit quaternion (4: w, x, y, z); or, in 2D, count ellipses with centre
 * (2), form (3, the q of pw85_2d.h), semi-axes (2) and orientation, the
 * angle θ of pw85_2d_ellipse() (1); capacity ≥ target; box: the periodic
 * box they are in
 * (the config's, or a larger one where a method certifies a lower packing
 * fraction than asked: the file holds this one). attempts: the candidates
 * drawn so far (the counter of the method's random stream, so that a
 * resumed packing draws what the uninterrupted one would have; 0 for a
 * method that cannot resume). phi, steps: for a method that does not grow
 * count (fire), the packing fraction certified so far and its steps, for
 * the progress bar; 0 otherwise (the command computes phi from count). */
struct pack_state {
  size_t count, capacity;
  double *centres, *forms, *axes, *orientations;
  double box[3];
  uint64_t attempts;
  double phi;
  size_t steps;
};

/* Called by a method every few milliseconds of work; nonzero: stop now
 * (interrupted, or out of time). */
typedef int (*pack_progress)(void *context, struct pack_state const *state);

/* How a method stopped (its return value); negative: a pw85 status, negated. */
enum pack_outcome {
  PACK_DONE = 0,      /* target count reached */
  PACK_STOPPED = 1,   /* progress() asked it to stop */
  PACK_SATURATED = 2, /* no candidate fits any more (by the method's rule) */
};

typedef int (*pack_method)(struct pack_config const *config,
                           struct pack_state *state, pack_progress progress,
                           void *context);

/* The certified packer of pw85_pack.h, or of pw85_2d_pack.h (pack_fire.c): starts from an empty
 * state, fills it with config->target ellipsoids at once. */
int pack_fire(struct pack_config const *config, struct pack_state *state,
              pack_progress progress, void *context);

/* Random sequential addition on the index of pw85_index.h, or of
 * pw85_2d_index.h (pack_rsa.c). */
int pack_rsa(struct pack_config const *config, struct pack_state *state,
             pack_progress progress, void *context);

#endif
