/* SPDX-License-Identifier: BSD-3-Clause */
/* Pair energies and callbacks shared by the tests of the energy of an
 * assembly and of the packer, in both dimensions (test-energy.c,
 * test-2d-energy.c, test-pack.c, test-2d-pack.c; header-only, test code). */
#ifndef PW85_ENERGY_UTIL_H
#define PW85_ENERGY_UTIL_H

#include <glib.h>
#include <math.h>

#include "pw85_pack.h"

/* The overlap energy and dU/dμ² of a pair (the formula of pw85_index.h):
 * U = ε(1 − μ)² and U′ = −ε(1 − μ)/μ for μ < 1, 0 beyond. */
static inline void overlap_u(double mu2, double eps, double out[2]) {
  double const mu = sqrt(mu2);
  out[0] = mu < 1.0 ? eps * (1.0 - mu) * (1.0 - mu) : 0.0;
  out[1] = mu < 1.0 && mu > 0.0 ? -eps * (1.0 - mu) / mu : 0.0;
}

/* PW85_ENERGY_USER with the overlap energy's formula; data: &ε. */
static inline int overlap_callback(double mu2, void *data, double out[2]) {
  overlap_u(mu2, *(double const *)data, out);
  return 0;
}

/* U(μ²) = (t − μ²)²/2 for μ² < t: dU/dμ² = μ² − t; data: &t. */
static inline int soft_callback(double mu2, void *data, double out[2]) {
  double const t = *(double const *)data;
  out[0] = 0.5 * (t - mu2) * (t - mu2);
  out[1] = mu2 - t;
  return 0;
}

/* Asks to stop at the first pair (PW85_ECANCELLED). */
static inline int stop_callback(double mu2, void *data, double out[2]) {
  (void)mu2;
  (void)data;
  out[0] = out[1] = 0.0;
  return 1;
}

/* A progress callback of the packer that stops at its third call; data:
 * the int that counts the calls. */
static inline int cancel_at_third(pw85_pack_progress const *p, void *data) {
  int *calls = (int *)data;
  g_assert_cmpfloat(p->phi_trial, >, 0.0);
  g_assert_cmpfloat(p->energy, >=, 0.0);
  return ++*calls == 3;
}

/* A progress callback: the most overlapping pairs a run reported, in the
 * size_t at data (to check that a run's energy had work for its threads:
 * it runs on min(threads, pairs/256 + 1) of them). */
static inline int most_pairs(pw85_pack_progress const *p, void *data) {
  size_t *most = (size_t *)data;
  if (p->pairs > *most) *most = p->pairs;
  return 0;
}

/* o on `threads` threads, its progress callback recording in *most the
 * most overlapping pairs of the run (most_pairs()), called every step. */
static inline void watch_pairs(pw85_pack_options *o, int threads,
                               size_t *most) {
  *most = 0;
  o->threads = threads;
  o->progress = most_pairs;
  o->progress_data = most;
  o->progress_every = 1;
}

#endif /* PW85_ENERGY_UTIL_H */
