/* SPDX-License-Identifier: BSD-3-Clause */
/* The spatial index (pw85_index.h) against a brute force over every pair
 * and every periodic image, which calls pw85_overlap() and
 * pw85_contact_function() itself: on random configurations (monodisperse,
 * polydisperse, needles, discs, dense and dilute, centres straddling the
 * faces and corners of the box or outside it, boxes small enough for
 * several images), after random sequences of insert, update and remove;
 * the all-pairs queries on 1, 2, 8 and INT_MAX threads, bit for bit;
 * pw85_index_insert_many_threads() on 1, 2 and 8 threads against a loop of
 * pw85_index_insert(); every bad input. PW85_TEST_SMALL (set for the sanitizer and valgrind runs) makes
 * the configurations smaller. */
#include <limits.h>
#include <pw85/pw85_index.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

/* ---- configurations ---------------------------------------------------- */

typedef enum { MONO, POLY, NEEDLES, DISCS } Shapes;

typedef struct {
  const char *name;
  Shapes shapes;
  int periodic;
  int n;            /* ellipsoids (divided by 5 when small) */
  double fraction;  /* packing fraction of the box (or of the open cube) */
  int straddle;     /* centres on the faces, edges and corners */
} Config;

static gboolean small_run(void) { return g_getenv("PW85_TEST_SMALL") != NULL; }

/* The mirror of an index: what the brute force sees. */
typedef struct {
  int periodic;
  double box[3];
  size_t cap; /* ids 0 .. cap-1 */
  gboolean *present;
  double *c, *q;
} Mirror;

static void semi_axes(GRand *rng, Shapes shapes, double a[3]) {
  double s = 1.;
  a[0] = a[1] = a[2] = 1.;
  switch (shapes) {
    case MONO:
      a[0] = 1., a[1] = .5, a[2] = .2;
      return;
    case POLY: /* radius ratio 10 */
      s = pow(10., g_rand_double(rng));
      a[0] = s, a[1] = .6 * s, a[2] = .3 * s;
      return;
    case NEEDLES: /* aspect ratio 100 */
      s = g_rand_double_range(rng, .5, 1.);
      a[0] = s, a[1] = .01 * s, a[2] = .01 * s;
      return;
    case DISCS:
      s = g_rand_double_range(rng, .5, 1.);
      a[0] = s, a[1] = s, a[2] = .01 * s;
      return;
  }
}

static double mean_volume(Shapes shapes) {
  switch (shapes) {
    case MONO: return 4. / 3. * G_PI * .1;
    case POLY: return 4. / 3. * G_PI * .18 * 144.8; /* E[s³], s = 10^U */
    case NEEDLES: return 4. / 3. * G_PI * 1e-4 * .586;
    case DISCS: return 4. / 3. * G_PI * .01 * .586;
  }
  return 1.;
}

/* x rounded to a multiple of 2⁻²⁴. The brute force forms the image vector
 * r = (c_j + n∘L) − c in double, as pw85_overlap() and
 * pw85_contact_function() take it; the index forms it exactly. Centres and
 * box sides on this grid, below 2²⁸ in magnitude, make every such sum
 * exact, so that both see the same configuration (tests/test-index-exact.c
 * tests the exact vectors against high-precision references). */
static double on_grid(double x) { return ldexp(nearbyint(ldexp(x, 24)), -24); }

static void random_ellipsoid(GRand *rng, Config const *cf, double side,
                             double c[3], double q[6]) {
  double a[3], e[3];
  semi_axes(rng, cf->shapes, a);
  for (int k = 0; k < 3; k++) e[k] = a[k] * a[k];
  random_form_with_eigenvalues(rng, e, q);
  for (int k = 0; k < 3; k++) {
    if (cf->straddle) { /* near 0 or L, either side; or anywhere */
      double const u = g_rand_double(rng);
      double const base = u < .4 ? 0. : (u < .8 ? side : g_rand_double(rng) * side);
      c[k] = base + g_rand_double_range(rng, -1., 1.);
    } else {
      c[k] = g_rand_double_range(rng, -.5 * side, 1.5 * side); /* unwrapped */
    }
    c[k] = on_grid(c[k]);
  }
}

/* ---- brute force ------------------------------------------------------- */

typedef struct {
  size_t i, j;
  int n[3];
  int result;
  double mu2, lambda;
} Ref;

static int ref_cmp(const void *pa, const void *pb) {
  Ref const *a = pa, *b = pb;
  if (a->i != b->i) return a->i < b->i ? -1 : 1;
  if (a->j != b->j) return a->j < b->j ? -1 : 1;
  for (int k = 0; k < 3; k++)
    if (a->n[k] != b->n[k]) return a->n[k] < b->n[k] ? -1 : 1;
  return 0;
}

/* The radius of a sphere containing the ellipsoid: √tr Q. */
static double radius(double const q[6]) { return sqrt(q[0] + q[3] + q[5]); }

/* Every image shift n of ellipsoid j that could be within μ² < t of
 * ellipsoid (c, q): μ² > t wherever |r| > √t·(√tr Q + √tr Q_j) (the
 * bounding spheres), widened by 1%; independent of the index's own
 * bounds. */
static void image_range(Mirror const *m, double const c[3], double const q[6],
                        size_t j, double t, int lo[3], int hi[3]) {
  double const reach = 1.01 * sqrt(t) * (radius(q) + radius(m->q + 6 * j));
  for (int k = 0; k < 3; k++) {
    if (!m->periodic) {
      lo[k] = hi[k] = 0;
      continue;
    }
    double const d = c[k] - m->c[3 * j + k];
    lo[k] = (int)floor((d - reach) / m->box[k]);
    hi[k] = (int)ceil((d + reach) / m->box[k]);
  }
}

static void image_vector(Mirror const *m, double const c[3], size_t j,
                         int const n[3], double r[3]) {
  for (int k = 0; k < 3; k++)
    r[k] = (m->c[3 * j + k] + (double)n[k] * (m->periodic ? m->box[k] : 0.)) - c[k];
}

static gboolean shift_positive(int const n[3]) {
  for (int k = 0; k < 3; k++)
    if (n[k] != 0) return n[k] > 0;
  return FALSE;
}

/* Every pair of the mirror: overlap mode (within = FALSE, results ≤ 0) or
 * μ² < t. Sorted. */
static GArray *brute_pairs(Mirror const *m, gboolean within, double t) {
  GArray *out = g_array_new(FALSE, FALSE, sizeof(Ref));
  for (size_t i = 0; i < m->cap; i++) {
    if (!m->present[i]) continue;
    for (size_t j = i; j < m->cap; j++) {
      if (!m->present[j]) continue;
      int lo[3], hi[3], n[3];
      image_range(m, m->c + 3 * i, m->q + 6 * i, j, t, lo, hi);
      for (n[0] = lo[0]; n[0] <= hi[0]; n[0]++)
        for (n[1] = lo[1]; n[1] <= hi[1]; n[1]++)
          for (n[2] = lo[2]; n[2] <= hi[2]; n[2]++) {
            if (j == i && !shift_positive(n)) continue;
            double r[3];
            image_vector(m, m->c + 3 * i, j, n, r);
            Ref ref = {i, j, {n[0], n[1], n[2]}, 0, 0., 0.};
            if (within) {
              double out2[2];
              int const s = pw85_contact_function(r, m->q + 6 * i, m->q + 6 * j, out2);
              g_assert_cmpint(s, ==, PW85_SUCCESS);
              if (!(out2[0] < t)) continue;
              ref.mu2 = out2[0], ref.lambda = out2[1];
            } else {
              int res;
              g_assert_cmpint(pw85_overlap(r, m->q + 6 * i, m->q + 6 * j, &res), ==,
                              PW85_SUCCESS);
              if (res > 0) continue;
              ref.result = res;
            }
            g_array_append_val(out, ref);
          }
    }
  }
  g_array_sort(out, ref_cmp);
  return out;
}

/* The candidate (c, q) against every stored ellipsoid but exclude. */
static GArray *brute_candidate(Mirror const *m, double const c[3],
                               double const q[6], size_t exclude,
                               gboolean within, double t) {
  GArray *out = g_array_new(FALSE, FALSE, sizeof(Ref));
  for (size_t j = 0; j < m->cap; j++) {
    if (!m->present[j] || j == exclude) continue;
    int lo[3], hi[3], n[3];
    image_range(m, c, q, j, t, lo, hi);
    for (n[0] = lo[0]; n[0] <= hi[0]; n[0]++)
      for (n[1] = lo[1]; n[1] <= hi[1]; n[1]++)
        for (n[2] = lo[2]; n[2] <= hi[2]; n[2]++) {
          double r[3];
          image_vector(m, c, j, n, r);
          Ref ref = {PW85_INDEX_NO_ID, j, {n[0], n[1], n[2]}, 0, 0., 0.};
          if (within) {
            double o[2];
            g_assert_cmpint(pw85_contact_function(r, q, m->q + 6 * j, o), ==,
                            PW85_SUCCESS);
            if (!(o[0] < t)) continue;
            ref.mu2 = o[0], ref.lambda = o[1];
          } else {
            int res;
            g_assert_cmpint(pw85_overlap(r, q, m->q + 6 * j, &res), ==, PW85_SUCCESS);
            if (res > 0) continue;
            ref.result = res;
          }
          g_array_append_val(out, ref);
        }
  }
  g_array_sort(out, ref_cmp);
  return out;
}

/* ---- the index's answers ----------------------------------------------- */

typedef struct {
  size_t count;
  size_t *ids;
  int *shifts;
  int *results;
  double *mu2_lambda;
} Pairs;

static void pairs_clear(Pairs *p) {
  g_free(p->ids), g_free(p->shifts), g_free(p->results), g_free(p->mu2_lambda);
  memset(p, 0, sizeof *p);
}

/* The all-pairs query, asked for its count first, then with room. */
static Pairs index_pairs(pw85_index const *ix, gboolean within, double t,
                         int threads) {
  Pairs p = {0, NULL, NULL, NULL, NULL};
  size_t count = 0;
  int s = within ? pw85_index_pairs_within(ix, t, threads, 0, NULL, NULL, NULL, &count)
                 : pw85_index_overlapping_pairs(ix, threads, 0, NULL, NULL, NULL, &count);
  g_assert_cmpint(s, ==, PW85_SUCCESS);
  size_t const cap = count + 1;
  p.ids = g_new0(size_t, 2 * cap);
  p.shifts = g_new0(int, 3 * cap);
  p.results = g_new0(int, cap);
  p.mu2_lambda = g_new0(double, 2 * cap);
  s = within ? pw85_index_pairs_within(ix, t, threads, cap, p.ids, p.shifts,
                                       p.mu2_lambda, &p.count)
             : pw85_index_overlapping_pairs(ix, threads, cap, p.ids, p.shifts,
                                            p.results, &p.count);
  g_assert_cmpint(s, ==, PW85_SUCCESS);
  g_assert_cmpuint(p.count, ==, count);
  return p;
}

static void compare_pairs(const char *what, Pairs const *p, GArray *ref,
                          gboolean within) {
  if (p->count != ref->len)
    test_mismatch("%s: %zu pairs, brute force %u", what, p->count, ref->len);
  size_t const n = MIN(p->count, (size_t)ref->len);
  for (size_t k = 0; k < n; k++) {
    Ref const *r = &g_array_index(ref, Ref, k);
    gboolean same = p->ids[2 * k] == r->i && p->ids[2 * k + 1] == r->j &&
                    memcmp(p->shifts + 3 * k, r->n, sizeof r->n) == 0;
    if (same && within)
      same = p->mu2_lambda[2 * k] == r->mu2 && p->mu2_lambda[2 * k + 1] == r->lambda;
    if (same && !within) same = p->results[k] == r->result;
    if (!same) {
      test_mismatch("%s: pair %zu is (%zu, %zu, [%d %d %d]), brute force "
                    "(%zu, %zu, [%d %d %d]) mu2 %.17g", what, k, p->ids[2 * k],
                    p->ids[2 * k + 1], p->shifts[3 * k], p->shifts[3 * k + 1],
                    p->shifts[3 * k + 2], r->i, r->j, r->n[0], r->n[1], r->n[2],
                    r->mu2);
      return;
    }
  }
}

static gboolean pairs_equal(Pairs const *a, Pairs const *b) {
  return a->count == b->count &&
         memcmp(a->ids, b->ids, 2 * a->count * sizeof(size_t)) == 0 &&
         memcmp(a->shifts, b->shifts, 3 * a->count * sizeof(int)) == 0 &&
         memcmp(a->results, b->results, a->count * sizeof(int)) == 0 &&
         memcmp(a->mu2_lambda, b->mu2_lambda, 2 * a->count * sizeof(double)) == 0;
}

/* ---- the test of a configuration --------------------------------------- */

static void check_candidates(pw85_index const *ix, Mirror const *m,
                             GRand *rng, Config const *cf, double side,
                             int count) {
  for (int k = 0; k < count; k++) {
    double c[3], q[6];
    random_ellipsoid(rng, cf, side, c, q);
    size_t exclude = PW85_INDEX_NO_ID;
    if (k % 3 == 1) { /* a Monte Carlo move: skip a stored one */
      exclude = (size_t)g_rand_int_range(rng, 0, (gint32)m->cap);
    }
    /* overlap_any: the least result of the brute force */
    GArray *ref = brute_candidate(m, c, q, exclude, FALSE, 1.);
    int best = 1;
    for (guint a = 0; a < ref->len; a++)
      best = MIN(best, g_array_index(ref, Ref, a).result);
    int result = 99;
    size_t id = 0;
    g_assert_cmpint(pw85_index_overlap_any(ix, c, q, exclude, &result, &id), ==,
                    PW85_SUCCESS);
    if (result != best)
      test_mismatch("%s candidate %d: overlap_any %d, brute force %d", cf->name,
                    k, result, best);
    if (best == 1) {
      g_assert_cmpuint(id, ==, PW85_INDEX_NO_ID);
    } else { /* the id named has that result through some image */
      gboolean found = FALSE;
      for (guint a = 0; a < ref->len; a++) {
        Ref const *r = &g_array_index(ref, Ref, a);
        found = found || (r->j == id && r->result == best);
      }
      if (!found)
        test_mismatch("%s candidate %d: id %zu does not have result %d",
                      cf->name, k, id, best);
    }
    g_array_unref(ref);

    /* within t, t = 1 and 2.5 */
    double const t = k % 2 ? 1. : 2.5;
    ref = brute_candidate(m, c, q, exclude, TRUE, t);
    size_t n = 0;
    g_assert_cmpint(pw85_index_within(ix, c, q, t, exclude, 0, NULL, NULL, NULL, &n),
                    ==, PW85_SUCCESS);
    size_t const cap = n > 1 ? n - 1 : n; /* one short: snprintf's truncation */
    size_t *ids = g_new0(size_t, cap + 1);
    int *shifts = g_new0(int, 3 * (cap + 1));
    double *ml = g_new0(double, 2 * (cap + 1));
    ids[cap] = 12345;
    size_t n2 = 0;
    g_assert_cmpint(pw85_index_within(ix, c, q, t, exclude, cap, ids, shifts, ml, &n2),
                    ==, PW85_SUCCESS);
    g_assert_cmpuint(n2, ==, n);
    g_assert_cmpuint(ids[cap], ==, 12345); /* nothing beyond capacity */
    if (n != ref->len)
      test_mismatch("%s candidate %d: within %g finds %zu, brute force %u",
                    cf->name, k, t, n, ref->len);
    for (size_t a = 0; a < MIN(cap, (size_t)ref->len); a++) {
      Ref const *r = &g_array_index(ref, Ref, a);
      if (ids[a] != r->j || memcmp(shifts + 3 * a, r->n, sizeof r->n) != 0 ||
          ml[2 * a] != r->mu2 || ml[2 * a + 1] != r->lambda) {
        test_mismatch("%s candidate %d: hit %zu differs from the brute force",
                      cf->name, k, a);
        break;
      }
    }
    g_free(ids), g_free(shifts), g_free(ml);
    g_array_unref(ref);
  }
}

static void check_pairs(pw85_index const *ix, Mirror const *m,
                        Config const *cf, const char *stage) {
  for (int within = 0; within <= 1; within++) {
    double const t = within ? (m->periodic ? 3. : 1.5) : 1.;
    GArray *ref = brute_pairs(m, within, t);
    Pairs one = index_pairs(ix, within, t, 1);
    char *what = g_strdup_printf("%s %s %s", cf->name, stage,
                                 within ? "pairs_within" : "overlapping_pairs");
    compare_pairs(what, &one, ref, within);
    /* INT_MAX: far above the work (one thread per 256 ellipsoids at most)
     * and above the cap of 1024 (pw85_index.h); it gave PW85_ENOMEM, and
     * 100 000 crashed in libgomp (test-pack.c, many-threads). */
    int const counts[] = {2, 8, INT_MAX};
    for (size_t k = 0; k < G_N_ELEMENTS(counts); k++) {
      Pairs more = index_pairs(ix, within, t, counts[k]);
      if (!pairs_equal(&one, &more))
        test_mismatch("%s: %d threads differ from 1", what, counts[k]);
      pairs_clear(&more);
    }
    g_test_message("%s: %u pairs", what, ref->len);
    g_free(what);
    pairs_clear(&one);
    g_array_unref(ref);
  }
}

static void test_config(gconstpointer data) {
  Config const *cf = data;
  GRand *rng = g_rand_new_with_seed(g_str_hash(cf->name));
  int const n = small_run() ? MAX(cf->n / 10, 8) : cf->n;
  /* The box's sides are (1, 1.1, 0.9) times side, at least 2.3 times the
   * largest semi-axis (the side rule of pw85_index.h). */
  double const amax = cf->shapes == POLY ? 10. : 1.;
  double const side = MAX(cbrt(n * mean_volume(cf->shapes) / cf->fraction),
                          2.3 * amax / .9);
  Mirror m = {cf->periodic, {on_grid(side), on_grid(side * 1.1), on_grid(side * .9)},
              (size_t)n + n / 2,
              NULL, NULL, NULL};
  m.present = g_new0(gboolean, m.cap);
  m.c = g_new0(double, 3 * m.cap);
  m.q = g_new0(double, 6 * m.cap);
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? m.box : NULL, &ix), ==,
                  PW85_SUCCESS);

  /* The first half in one call, the rest one by one, ids shuffled. */
  size_t *ids = g_new(size_t, n);
  for (int i = 0; i < n; i++) ids[i] = (size_t)i;
  for (int i = n - 1; i > 0; i--) {
    int const k = g_rand_int_range(rng, 0, i + 1);
    size_t const x = ids[i];
    ids[i] = ids[k], ids[k] = x;
  }
  double *c = g_new(double, 3 * n), *q = g_new(double, 6 * n);
  for (int i = 0; i < n; i++) {
    random_ellipsoid(rng, cf, side, c + 3 * i, q + 6 * i);
    m.present[ids[i]] = TRUE;
    memcpy(m.c + 3 * ids[i], c + 3 * i, 3 * sizeof(double));
    memcpy(m.q + 6 * ids[i], q + 6 * i, 6 * sizeof(double));
  }
  g_assert_cmpint(pw85_index_insert_many(ix, (size_t)n / 2, ids, c, q), ==,
                  PW85_SUCCESS);
  for (int i = n / 2; i < n; i++)
    g_assert_cmpint(pw85_index_insert(ix, ids[i], c + 3 * i, q + 6 * i), ==,
                    PW85_SUCCESS);
  size_t count = 0;
  g_assert_cmpint(pw85_index_count(ix, &count), ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, (size_t)n);
  check_pairs(ix, &m, cf, "inserted");
  check_candidates(ix, &m, rng, cf, side, small_run() ? 3 : 30);

  /* Random updates (moves, reshapes), removals and new ids. */
  for (int step = 0; step < 2 * n; step++) {
    size_t const id = (size_t)g_rand_int_range(rng, 0, (gint32)m.cap);
    double cc[3], qq[6];
    random_ellipsoid(rng, cf, side, cc, qq);
    if (!m.present[id]) {
      g_assert_cmpint(pw85_index_insert(ix, id, cc, qq), ==, PW85_SUCCESS);
      m.present[id] = TRUE;
    } else if (g_rand_double(rng) < .3) {
      g_assert_cmpint(pw85_index_remove(ix, id), ==, PW85_SUCCESS);
      m.present[id] = FALSE;
      continue;
    } else {
      if (g_rand_boolean(rng)) /* a small move, same shape */
        for (int k = 0; k < 3; k++) {
          memcpy(qq, m.q + 6 * id, sizeof qq);
          cc[k] = on_grid(m.c[3 * id + k] + g_rand_double_range(rng, -.3, .3));
        }
      g_assert_cmpint(pw85_index_update(ix, id, cc, qq), ==, PW85_SUCCESS);
    }
    memcpy(m.c + 3 * id, cc, sizeof cc);
    memcpy(m.q + 6 * id, qq, sizeof qq);
  }
  /* get() returns what was stored. */
  for (size_t id = 0; id < m.cap; id++) {
    double cc[3], qq[6];
    int const s = pw85_index_get(ix, id, cc, qq);
    if (!m.present[id]) {
      g_assert_cmpint(s, ==, PW85_EINVAL);
      continue;
    }
    g_assert_cmpint(s, ==, PW85_SUCCESS);
    g_assert_cmpmem(cc, sizeof cc, m.c + 3 * id, sizeof cc);
    g_assert_cmpmem(qq, sizeof qq, m.q + 6 * id, sizeof qq);
  }
  check_pairs(ix, &m, cf, "after moves");
  check_candidates(ix, &m, rng, cf, side, small_run() ? 3 : 30);

  pw85_index_destroy(ix);
  g_free(ids), g_free(c), g_free(q);
  g_free(m.present), g_free(m.c), g_free(m.q);
  g_rand_free(rng);
}

/* ---- large configurations: threads ------------------------------------- */

/* Configurations large enough (N ≥ 4096 per thread) for the all-pairs
 * queries to build their snapshot and merge their pairs on several
 * threads: the output on 2 and 8 threads is the output on 1, bit for bit
 * (which the brute-force tests above check on the serial paths). */
static void test_threads_large(gconstpointer data) {
  Config const *cf = data;
  GRand *rng = g_rand_new_with_seed(g_str_hash(cf->name));
  int const n = small_run() ? cf->n / 2 : cf->n;
  double const side = cbrt(n * mean_volume(cf->shapes) / cf->fraction);
  double const box[3] = {side, side * 1.1, side * .9};
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &ix), ==,
                  PW85_SUCCESS);
  for (int i = 0; i < n; i++) {
    double c[3], q[6];
    random_ellipsoid(rng, cf, side, c, q);
    g_assert_cmpint(pw85_index_insert(ix, (size_t)(n - 1 - i), c, q), ==,
                    PW85_SUCCESS);
  }
  for (int within = 0; within <= 1; within++) {
    double const t = within ? 2. : 1.;
    Pairs one = index_pairs(ix, within, t, 1);
    g_assert_cmpuint(one.count, >, (size_t)n / 4);
    for (int threads = 2; threads <= 8; threads *= 4) {
      Pairs more = index_pairs(ix, within, t, threads);
      if (!pairs_equal(&one, &more))
        test_mismatch("%s %s: %d threads differ from 1", cf->name,
                      within ? "pairs_within" : "overlapping_pairs", threads);
      pairs_clear(&more);
    }
    g_test_message("%s %s: %zu pairs", cf->name,
                   within ? "pairs_within" : "overlapping_pairs", one.count);
    pairs_clear(&one);
  }
  pw85_index_destroy(ix);
  g_rand_free(rng);
}

static Config const large_configs[] = {
    {"mono-periodic", MONO, 1, 20000, .4, 0},
    {"mono-open", MONO, 0, 20000, 2., 0}, /* centres over 8 times the cube */
    {"poly-periodic", POLY, 1, 20000, .3, 0},
};

/* ---- insert_many on threads ------------------------------------------- */

/* The observable state of an index: every id's centre and form; both
 * overlapping pairs; and, for probes (every
 * 7th stored ellipsoid, 2.5 times larger, itself excluded),
 * pw85_index_overlap_any()'s result and id (which one, among the several
 * that a large probe meets, depends on the order in which the index
 * stores them: a check of that order) and pw85_index_within() (μ² < 1.5,
 * its first 16 results). Two indexes that should be the same are compared
 * through it. */
typedef struct {
  size_t cap, count;
  double *c, *q; /* NaN where absent */
  Pairs overlapping;
  int *any;       /* status, result, per probe */
  size_t *any_id; /* per probe */
  size_t *n_near;    /* per probe */
  size_t *near_ids;  /* 16 per probe */
  double *near_mu2;  /* 32 per probe */
} State;

enum { near_room = 16 };

static State state_of(pw85_index const *ix, size_t cap) {
  State st = {cap, 0, g_new(double, 3 * cap), g_new(double, 6 * cap),
              {0, NULL, NULL, NULL, NULL}, NULL, NULL, NULL, NULL, NULL};
  g_assert_cmpint(pw85_index_count(ix, &st.count), ==, PW85_SUCCESS);
  for (size_t id = 0; id < cap; id++)
    if (pw85_index_get(ix, id, st.c + 3 * id, st.q + 6 * id) != PW85_SUCCESS) {
      for (int k = 0; k < 3; k++) st.c[3 * id + k] = NAN;
      for (int k = 0; k < 6; k++) st.q[6 * id + k] = NAN;
    }
  st.overlapping = index_pairs(ix, FALSE, 1., 1);
  size_t const probes = (cap + 6) / 7;
  st.any = g_new0(int, 2 * probes);
  st.any_id = g_new0(size_t, probes);
  st.n_near = g_new0(size_t, probes);
  st.near_ids = g_new0(size_t, near_room * probes);
  st.near_mu2 = g_new0(double, 2 * near_room * probes);
  for (size_t p = 0; p < probes; p++) {
    size_t const id = 7 * p;
    double c[3], q[6];
    if (pw85_index_get(ix, id, c, q) != PW85_SUCCESS) continue;
    for (int k = 0; k < 6; k++) q[k] *= 6.25;
    st.any[2 * p] = pw85_index_overlap_any(ix, c, q, id, &st.any[2 * p + 1], &st.any_id[p]);
    int shifts[3 * near_room];
    g_assert_cmpint(pw85_index_within(ix, c, q, 1.5, PW85_INDEX_NO_ID, near_room,
                                      st.near_ids + near_room * p, shifts,
                                      st.near_mu2 + 2 * near_room * p, &st.n_near[p]),
                    ==, PW85_SUCCESS);
  }
  return st;
}

static void state_clear(State *st) {
  g_free(st->c), g_free(st->q), g_free(st->any), g_free(st->any_id);
  g_free(st->n_near), g_free(st->near_ids), g_free(st->near_mu2);
  pairs_clear(&st->overlapping);
}

static void assert_same_state(State const *a, pw85_index const *ix, char const *what) {
  State b = state_of(ix, a->cap);
  size_t const probes = (a->cap + 6) / 7;
  if (b.count != a->count) test_mismatch("%s: %zu ellipsoids, expected %zu", what, b.count, a->count);
  if (memcmp(a->c, b.c, 3 * a->cap * sizeof(double)) != 0 ||
      memcmp(a->q, b.q, 6 * a->cap * sizeof(double)) != 0)
    test_mismatch("%s: the stored centres or forms differ", what);
  if (!pairs_equal(&a->overlapping, &b.overlapping))
    test_mismatch("%s: overlapping_pairs differ", what);
  if (memcmp(a->any, b.any, 2 * probes * sizeof(int)) != 0 ||
      memcmp(a->any_id, b.any_id, probes * sizeof(size_t)) != 0)
    test_mismatch("%s: overlap_any differs", what);
  if (memcmp(a->n_near, b.n_near, probes * sizeof(size_t)) != 0 ||
      memcmp(a->near_ids, b.near_ids, near_room * probes * sizeof(size_t)) != 0 ||
      memcmp(a->near_mu2, b.near_mu2, 2 * near_room * probes * sizeof(double)) != 0)
    test_mismatch("%s: within differs", what);
  state_clear(&b);
}

/* pw85_index_insert_many_threads() on 1, 2 and 8 threads against the
 * loop of pw85_index_insert() that it stands for (whose answers the
 * brute-force tests above check), on a seeded configuration: a third
 * inserted one at a time first (cells and levels that exist), the rest in
 * one call (≥ 1024: the bulk path), ids shuffled. Then failing calls:
 * the first error in the order of the arrays, and the index unchanged. */
static void test_insert_many_threads(gconstpointer data) {
  Config const *cf = data;
  GRand *rng = g_rand_new_with_seed(g_str_hash(cf->name) ^ 0x1234u);
  int const n = small_run() ? cf->n / 4 : cf->n;
  double const side = cbrt(n * mean_volume(cf->shapes) / cf->fraction);
  double const box[3] = {side, side * 1.1, side * .9};
  size_t *ids = g_new(size_t, n);
  double *c = g_new(double, 3 * n), *q = g_new(double, 6 * n);
  for (int i = 0; i < n; i++) ids[i] = (size_t)i;
  for (int i = n - 1; i > 0; i--) {
    int const k = g_rand_int_range(rng, 0, i + 1);
    size_t const x = ids[i];
    ids[i] = ids[k], ids[k] = x;
  }
  for (int i = 0; i < n; i++) random_ellipsoid(rng, cf, side, c + 3 * i, q + 6 * i);
  int const first = n / 3;

  pw85_index *ref = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &ref), ==, PW85_SUCCESS);
  for (int i = 0; i < n; i++)
    g_assert_cmpint(pw85_index_insert(ref, ids[i], c + 3 * i, q + 6 * i), ==,
                    PW85_SUCCESS);
  State const expected = state_of(ref, (size_t)n);
  size_t hits = 0;
  for (size_t p = 0; p < ((size_t)n + 6) / 7; p++) hits += expected.any[2 * p + 1] < 0;
  g_assert_cmpuint(hits, >, (size_t)n / 7 / 4); /* the probes do meet others */
  g_assert_cmpuint(expected.overlapping.count, >, (size_t)n / 10);
  int const counts[] = {1, 2, 8};
  for (size_t t = 0; t < G_N_ELEMENTS(counts); t++) {
    pw85_index *ix = NULL;
    g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &ix), ==, PW85_SUCCESS);
    for (int i = 0; i < first; i++)
      g_assert_cmpint(pw85_index_insert(ix, ids[i], c + 3 * i, q + 6 * i), ==,
                      PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert_many_threads(ix, (size_t)(n - first), ids + first,
                                                   c + 3 * first, q + 6 * first,
                                                   counts[t]), ==, PW85_SUCCESS);
    char *what = g_strdup_printf("%s, %d threads", cf->name, counts[t]);
    assert_same_state(&expected, ix, what);
    g_free(what);
    pw85_index_destroy(ix);
  }
  /* From an empty index, and through pw85_index_insert_many(). */
  pw85_index *all = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &all), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert_many(all, (size_t)n, ids, c, q), ==, PW85_SUCCESS);
  assert_same_state(&expected, all, cf->name);
  pw85_index_destroy(all);

  /* Failing calls on an index holding the first third: the status of the
   * first failing item, and nothing inserted. */
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &ix), ==, PW85_SUCCESS);
  pw85_index *part = NULL;
  g_assert_cmpint(pw85_index_create(cf->periodic ? box : NULL, &part), ==, PW85_SUCCESS);
  for (int i = 0; i < first; i++) {
    g_assert_cmpint(pw85_index_insert(ix, ids[i], c + 3 * i, q + 6 * i), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert(part, ids[i], c + 3 * i, q + 6 * i), ==, PW85_SUCCESS);
  }
  size_t const rest = (size_t)(n - first);
  size_t *bad_ids = g_new(size_t, rest);
  double *bad_q = g_new(double, 6 * rest);
  double const indefinite[6] = {1., 2., 0., 1., 0., 1.};
  struct {
    size_t dup_at, dup_of;  /* ids[dup_at] = ids[dup_of] (dup_at = rest: none) */
    size_t bad_at;          /* an indefinite form there (rest: none) */
    size_t used_at;         /* an id in use there (rest: none) */
    size_t huge_at;         /* PW85_INDEX_MAX_ID + 1 there (rest: none) */
    int expected;
  } const cases[] = {
      {rest - 5, 100, rest, rest, rest, PW85_EINVAL},
      {rest - 5, 100, rest / 2, rest, rest, PW85_ENOTPOSDEF},
      {rest / 3, rest / 3 - 1, rest / 2, rest, rest, PW85_EINVAL},
      {rest / 2, rest / 4, rest / 2, rest, rest, PW85_ENOTPOSDEF}, /* same item */
      {rest, 0, rest - 1, rest / 2, rest, PW85_EINVAL},
      {rest, 0, rest / 2, rest, rest / 3, PW85_EINVAL},
      {rest, 0, rest / 3, rest, rest / 2, PW85_ENOTPOSDEF},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    memcpy(bad_ids, ids + first, rest * sizeof(size_t));
    memcpy(bad_q, q + 6 * first, 6 * rest * sizeof(double));
    if (cases[k].dup_at < rest) bad_ids[cases[k].dup_at] = bad_ids[cases[k].dup_of];
    if (cases[k].bad_at < rest) memcpy(bad_q + 6 * cases[k].bad_at, indefinite, sizeof indefinite);
    if (cases[k].used_at < rest) bad_ids[cases[k].used_at] = ids[0];
    if (cases[k].huge_at < rest) bad_ids[cases[k].huge_at] = PW85_INDEX_MAX_ID + 1;
    g_assert_cmpint(pw85_index_insert_many_threads(ix, rest, bad_ids, c + 3 * first,
                                                   bad_q, 1 + (int)k % 2), ==,
                    cases[k].expected);
  }
  g_assert_cmpint(pw85_index_insert_many_threads(ix, rest, ids + first, c + 3 * first,
                                                 q + 6 * first, 0), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_insert_many_threads(ix, rest, NULL, c, q, 2), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert_many_threads(NULL, 0, NULL, NULL, NULL, 2), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert_many_threads(ix, 0, NULL, NULL, NULL, 2), ==,
                  PW85_SUCCESS);
  State partial = state_of(part, (size_t)n);
  assert_same_state(&partial, ix, "after the failing calls");
  state_clear(&partial);
  /* and the good call still gives the serial index */
  g_assert_cmpint(pw85_index_insert_many_threads(ix, rest, ids + first, c + 3 * first,
                                                 q + 6 * first, 2), ==, PW85_SUCCESS);
  assert_same_state(&expected, ix, "after the failing calls, inserted");
  state_clear((State *)&expected);
  pw85_index_destroy(ix), pw85_index_destroy(part), pw85_index_destroy(ref);
  g_free(bad_ids), g_free(bad_q), g_free(ids), g_free(c), g_free(q);
  g_rand_free(rng);
}

/* insert_many_threads() from an empty periodic index with enough items
 * for up to 9 threads (one per 4096): as many hash tables in its pass 3,
 * not a power of two for 3, 5 and 7 (test_insert_many_threads() above
 * runs at most 2 with its 8000 items). Each leaves the index of 1 thread:
 * the state that assert_same_state() compares, bit for bit. */
static void test_insert_many_tables(void) {
  Config const cf = {"tables", MONO, 1, 40000, .4, 0};
  int const n = small_run() ? 12300 : cf.n; /* 12300: 3 threads still */
  GRand *rng = g_rand_new_with_seed(0x7ab1e5u);
  double const side = cbrt(n * mean_volume(cf.shapes) / cf.fraction);
  double const box[3] = {side, side * 1.1, side * .9};
  size_t *ids = g_new(size_t, n);
  double *c = g_new(double, 3 * n), *q = g_new(double, 6 * n);
  for (int i = 0; i < n; i++) ids[i] = (size_t)(n - 1 - i);
  for (int i = 0; i < n; i++) random_ellipsoid(rng, &cf, side, c + 3 * i, q + 6 * i);
  State expected = {0};
  int const counts[] = {1, 3, 5, 7, 9};
  for (size_t t = 0; t < G_N_ELEMENTS(counts); t++) {
    pw85_index *ix = NULL;
    g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert_many_threads(ix, (size_t)n, ids, c, q, counts[t]), ==,
                    PW85_SUCCESS);
    if (t == 0) {
      expected = state_of(ix, (size_t)n);
      /* a dense set: pairs to compare */
      g_assert_cmpuint(expected.overlapping.count, >, (size_t)n / 2);
    } else {
      char *what = g_strdup_printf("insert_many_threads on %d threads", counts[t]);
      assert_same_state(&expected, ix, what);
      g_free(what);
    }
    pw85_index_destroy(ix);
  }
  state_clear(&expected);
  g_free(ids), g_free(c), g_free(q);
  g_rand_free(rng);
}

static Config const insert_configs[] = {
    {"mono-periodic", MONO, 1, 8000, .4, 1},
    {"mono-open", MONO, 0, 8000, 2., 0},
    {"poly-periodic", POLY, 1, 8000, .3, 0},
};

/* ---- bad input ----------------------------------------------------------- */

static void test_bad_input(void) {
  double const box[3] = {10., 10., 10.};
  double const c[3] = {1., 2., 3.};
  double const q[6] = {1., 0., 0., .25, 0., .04};
  double const q_bad[6] = {1., 2., 0., 1., 0., 1.};  /* indefinite */
  double const q_nan[6] = {NAN, 0., 0., 1., 0., 1.};
  double const c_inf[3] = {INFINITY, 0., 0.};
  double const q_wide[6] = {26., 0., 0., 1., 0., 1.}; /* 2·√26 > 10 */
  double const c_far[3] = {1e300, 0., 0.};             /* open: fine */
  double const c_farther[3] = {6e9, 0., 0.};           /* > 2²⁹·10 */
  pw85_index *ix = NULL, *open = NULL;

  double const box_nan[3] = {10., NAN, 10.}, box_zero[3] = {10., 0., 10.};
  double const box_neg[3] = {10., 10., -1.};
  g_assert_cmpint(pw85_index_create(box, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_create(box_nan, &ix), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_create(box_zero, &ix), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_create(box_neg, &ix), ==, PW85_EINVAL);
  g_assert_null(ix);
  g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_create(NULL, &open), ==, PW85_SUCCESS);
  pw85_index_destroy(NULL);

  size_t n = 99;
  g_assert_cmpint(pw85_index_count(NULL, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_count(ix, NULL), ==, PW85_EFAULT);

  /* insert */
  g_assert_cmpint(pw85_index_insert(NULL, 0, c, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert(ix, 0, NULL, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert(ix, 0, c, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert(ix, 0, c_inf, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_insert(ix, 0, c, q_nan), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_insert(ix, 0, c, q_bad), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_index_insert(ix, 0, c, q_wide), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_insert(open, 0, c, q_wide), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 0, c_farther, q), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_insert(open, 1, c_far, q), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, PW85_INDEX_MAX_ID + 1, c, q), ==,
                  PW85_EINVAL);
  g_assert_cmpint(pw85_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 0);
  g_assert_cmpint(pw85_index_insert(ix, 3, c, q), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 3, c, q), ==, PW85_EINVAL); /* in use */

  /* insert_many: all or none */
  size_t const ids[3] = {4, 5, 3};
  double const cs[9] = {0., 0., 0., 5., 5., 5., 1., 1., 1.};
  double qs[18];
  for (int k = 0; k < 3; k++) memcpy(qs + 6 * k, q, sizeof q);
  g_assert_cmpint(pw85_index_insert_many(ix, 3, NULL, cs, qs), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_insert_many(ix, 3, ids, cs, qs), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);
  memcpy(qs + 6, q_bad, sizeof q_bad);
  size_t const ids2[3] = {4, 5, 6};
  g_assert_cmpint(pw85_index_insert_many(ix, 3, ids2, cs, qs), ==, PW85_ENOTPOSDEF);
  size_t const dup[2] = {7, 7};
  memcpy(qs + 6, q, sizeof q);
  g_assert_cmpint(pw85_index_insert_many(ix, 2, dup, cs, qs), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);
  g_assert_cmpint(pw85_index_insert_many(ix, 0, NULL, NULL, NULL), ==, PW85_SUCCESS);

  /* update, remove, get: unknown ids, bad forms; the index unchanged */
  double cc[3], qq[6];
  g_assert_cmpint(pw85_index_update(ix, 4, c, q), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_update(ix, 3, c, q_bad), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_index_update(ix, 3, c_inf, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_update(ix, 3, c, q_wide), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_update(NULL, 3, c, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_get(ix, 3, cc, qq), ==, PW85_SUCCESS);
  g_assert_cmpmem(cc, sizeof cc, c, sizeof c);
  g_assert_cmpmem(qq, sizeof qq, q, sizeof q);
  g_assert_cmpint(pw85_index_get(ix, 2, cc, qq), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_get(ix, 1u << 30, cc, qq), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_get(ix, 3, NULL, qq), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_get(NULL, 3, cc, qq), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_remove(ix, 2), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_remove(ix, PW85_INDEX_NO_ID), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_remove(NULL, 3), ==, PW85_EFAULT);

  /* queries on a candidate */
  int result = 7;
  size_t id = 7;
  g_assert_cmpint(pw85_index_overlap_any(NULL, c, q, PW85_INDEX_NO_ID, &result, &id), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any(ix, NULL, q, PW85_INDEX_NO_ID, &result, &id), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, NULL, &id), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, &result, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any(ix, c_inf, q, PW85_INDEX_NO_ID, &result, &id), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_overlap_any(ix, c, q_bad, PW85_INDEX_NO_ID, &result, &id), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_index_overlap_any(ix, c_farther, q, PW85_INDEX_NO_ID, &result, &id), ==, PW85_EINVAL);
  g_assert_cmpint(result, ==, 7); /* untouched on error */
  g_assert_cmpuint(id, ==, 7);
  g_assert_cmpint(pw85_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, &result, &id), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  g_assert_cmpuint(id, ==, 3);
  g_assert_cmpint(pw85_index_overlap_any(ix, c, q, 3, &result, &id), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
  g_assert_cmpuint(id, ==, PW85_INDEX_NO_ID);

  size_t ids_out[4];
  int shifts[12];
  double ml[8];
  g_assert_cmpint(pw85_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 4, NULL, shifts, ml, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 4, ids_out, NULL, ml, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 4, ids_out, shifts, NULL, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_within(ix, c, q, NAN, PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_within(ix, c, q, INFINITY, PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_within(ix, c, q, 0., PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_within(ix, c, q, -1., PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_within(ix, c, q_nan, 1., PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_within(ix, c, q, 1e300, PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 4, ids_out, shifts, ml, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);
  g_assert_cmpuint(ids_out[0], ==, 3);

  /* all pairs */
  g_assert_cmpint(pw85_index_overlapping_pairs(NULL, 1, 0, NULL, NULL, NULL, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlapping_pairs(ix, 1, 0, NULL, NULL, NULL, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlapping_pairs(ix, 1, 2, NULL, shifts, shifts, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlapping_pairs(ix, 0, 0, NULL, NULL, NULL, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_overlapping_pairs(ix, -3, 0, NULL, NULL, NULL, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_pairs_within(ix, 1., 0, 0, NULL, NULL, NULL, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_pairs_within(ix, NAN, 1, 0, NULL, NULL, NULL, &n), ==, PW85_EDOM);
  g_assert_cmpint(pw85_index_pairs_within(ix, 0., 1, 0, NULL, NULL, NULL, &n), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_pairs_within(ix, 1., 1, 1, ids_out, NULL, ml, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_pairs_within(NULL, 1., 1, 0, NULL, NULL, NULL, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_pairs_within(ix, 1e300, 1, 0, NULL, NULL, NULL, &n), ==, PW85_ERANGE);

  /* Forms whose diagonals together span more than a double's range:
   * both valid, the pair out of range (as pw85_overlap()). */
  pw85_index *wide = NULL;
  double const tiny[6] = {1e-320, 0., 0., 1e-320, 0., 1e-320};
  double const huge[6] = {1e308, 0., 0., 1e308, 0., 1e308};
  g_assert_cmpint(pw85_index_create(NULL, &wide), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(wide, 0, c, tiny), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(wide, 1, c, huge), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_overlapping_pairs(wide, 2, 0, NULL, NULL, NULL, &n), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_index_pairs_within(wide, 1., 2, 0, NULL, NULL, NULL, &n), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_index_remove(wide, 0), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_overlap_any(wide, c, tiny, PW85_INDEX_NO_ID, &result, &id), ==, PW85_ERANGE);
  g_assert_cmpint(pw85_index_within(wide, c, tiny, 1., PW85_INDEX_NO_ID, 0, NULL, NULL, NULL, &n), ==, PW85_ERANGE);
  pw85_index_destroy(wide);

  /* A candidate whose reach spans more than 2^20 images of the box (a
   * needle of half-length 2^19 in a unit box): PW85_ERANGE, as the header
   * says; half-length 2^17 is decided (−1, the sphere inside the needle). */
  pw85_index *unit = NULL;
  double const unit_box[3] = {1., 1., 1.}, origin[3] = {0., 0., 0.},
               ball[6] = {0.01, 0., 0., 0.01, 0., 0.01},
               needle_centre[3] = {0.5, 0., 0.};
  g_assert_cmpint(pw85_index_create(unit_box, &unit), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(unit, 0, origin, ball), ==, PW85_SUCCESS);
  double needle[6] = {0x1p34, 0., 0., 0.01, 0., 0.01};
  g_assert_cmpint(pw85_index_overlap_any(unit, needle_centre, needle, PW85_INDEX_NO_ID, &result, &id), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  needle[0] = 0x1p38;
  g_assert_cmpint(pw85_index_overlap_any(unit, needle_centre, needle, PW85_INDEX_NO_ID, &result, &id), ==, PW85_ERANGE);
  pw85_index_destroy(unit);

  g_assert_cmpint(pw85_index_remove(ix, 3), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 0);
  pw85_index_destroy(ix);
  pw85_index_destroy(open);
}

/* A candidate wider than the box by 2¹⁸ (below the limit of 2²⁰ boxes of
 * reach), in a unit box holding one small ball: the images of the ball
 * nearest the candidate's centre lie inside it. overlap_any visited the
 * images in lexicographic order of their shifts, from a corner of the
 * reach, through (2¹⁹)² images of its first face before one inside the
 * candidate (time quadratic in the reach: 1.8 s at 2¹², about two hours
 * here, extrapolated); it tries the nearest image of each ellipsoid
 * first. */
static void test_wide_candidate(void) {
  double const box[3] = {1., 1., 1.};
  double const ball[6] = {0.01, 0., 0., 0.01, 0., 0.01};
  double const centre[3] = {0.5, 0.5, 0.5};
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 7, centre, ball), ==, PW85_SUCCESS);
  double const r = 0x1p18, r2 = r * r;
  double const wide[6] = {r2, 0., 0., r2, 0., r2};
  double const at[3] = {0.25, -3., 1e3};
  int result = 2;
  size_t id = 0;
  g_assert_cmpint(pw85_index_overlap_any(ix, at, wide, PW85_INDEX_NO_ID,
                                         &result, &id), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  g_assert_cmpuint(id, ==, 7);
  /* excluded: no other ellipsoid */
  g_assert_cmpint(pw85_index_overlap_any(ix, at, wide, 7, &result, &id), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(result, ==, 1);
  g_assert_cmpuint(id, ==, PW85_INDEX_NO_ID);
  pw85_index_destroy(ix);
}

/* A stored ellipsoid meets other ellipsoids through several images when
 * the box is small: a box barely wider than the ellipsoids. */
static void test_several_images(void) {
  double const box[3] = {2.1, 2.1, 2.1};
  double const q[6] = {1., 0., 0., 1., 0., 1.}; /* unit spheres */
  double const c0[3] = {0., 0., 0.}, c1[3] = {1.05, 0., 0.};
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 0, c0, q), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 1, c1, q), ==, PW85_SUCCESS);
  size_t ids[8];
  int shifts[12], results[4];
  size_t n = 0;
  g_assert_cmpint(pw85_index_overlapping_pairs(ix, 1, 4, ids, shifts, results, &n),
                  ==, PW85_SUCCESS);
  /* 1.05 apart through n = 0 and through n = (−1, 0, 0); 2 ≥ 1.05 */
  g_assert_cmpuint(n, ==, 2);
  g_assert_cmpint(shifts[0], ==, -1);
  g_assert_cmpint(shifts[3], ==, 0);
  /* μ² < 4.5 reaches the images across the box: more pairs, and each
   * sphere its own images, (0, 0, n) with n positive. */
  g_assert_cmpint(pw85_index_pairs_within(ix, 4.5, 1, 0, NULL, NULL, NULL, &n), ==,
                  PW85_SUCCESS);
  double *ml = g_new(double, 2 * n);
  size_t *ids2 = g_new(size_t, 2 * n);
  int *sh2 = g_new(int, 3 * n);
  size_t const cap = n;
  g_assert_cmpint(pw85_index_pairs_within(ix, 4.5, 1, cap, ids2, sh2, ml, &n), ==,
                  PW85_SUCCESS);
  g_assert_cmpuint(n, ==, cap);
  gboolean self = FALSE;
  for (size_t k = 0; k < n; k++) {
    g_assert_cmpfloat(ml[2 * k], <, 4.5);
    if (ids2[2 * k] == 0 && ids2[2 * k + 1] == 0) {
      self = TRUE;
      g_assert_true(shift_positive(sh2 + 3 * k));
    }
  }
  g_assert_true(self);
  g_test_message("%zu pairs with mu^2 < 4.5", n);
  g_free(ml), g_free(ids2), g_free(sh2);
  pw85_index_destroy(ix);
}

/* Queries only read an index: several threads querying one index at once
 * get the answers of one thread, bit for bit (and ThreadSanitizer, in its
 * build, sees no race). */
#define QUERY_THREADS 4
#define QUERY_CANDIDATES 40

typedef struct {
  pw85_index const *index;
  double const *c, *q; /* the candidates */
  int results[QUERY_CANDIDATES];
  size_t ids[QUERY_CANDIDATES], counts[QUERY_CANDIDATES];
  double mu2_sum[QUERY_CANDIDATES];
  size_t pairs;
} Queries;

static gpointer run_queries(gpointer data) {
  Queries *w = data;
  for (int k = 0; k < QUERY_CANDIDATES; k++) {
    double const *c = w->c + 3 * k, *q = w->q + 6 * k;
    g_assert_cmpint(pw85_index_overlap_any(w->index, c, q, PW85_INDEX_NO_ID,
                                           &w->results[k], &w->ids[k]), ==, PW85_SUCCESS);
    size_t ids[64];
    int shifts[3 * 64];
    double ml[2 * 64];
    g_assert_cmpint(pw85_index_within(w->index, c, q, 2., PW85_INDEX_NO_ID, 64, ids,
                                      shifts, ml, &w->counts[k]), ==, PW85_SUCCESS);
    w->mu2_sum[k] = 0.;
    for (size_t a = 0; a < MIN(w->counts[k], (size_t)64); a++) w->mu2_sum[k] += ml[2 * a];
  }
  g_assert_cmpint(pw85_index_overlapping_pairs(w->index, 1, 0, NULL, NULL, NULL,
                                               &w->pairs), ==, PW85_SUCCESS);
  return NULL;
}

static void test_concurrent_queries(void) {
  Config const cf = {"concurrent", MONO, 1, small_run() ? 40 : 300, .3, 0};
  GRand *rng = g_rand_new_with_seed(11);
  double const side = cbrt(cf.n * mean_volume(MONO) / cf.fraction);
  double const box[3] = {side, side, side};
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
  double c[3], q[6];
  for (int i = 0; i < cf.n; i++) {
    random_ellipsoid(rng, &cf, side, c, q);
    g_assert_cmpint(pw85_index_insert(ix, (size_t)i, c, q), ==, PW85_SUCCESS);
  }
  double cs[3 * QUERY_CANDIDATES], qs[6 * QUERY_CANDIDATES];
  for (int k = 0; k < QUERY_CANDIDATES; k++)
    random_ellipsoid(rng, &cf, side, cs + 3 * k, qs + 6 * k);
  Queries serial = {ix, cs, qs, {0}, {0}, {0}, {0}, 0};
  run_queries(&serial);
  Queries parallel[QUERY_THREADS];
  GThread *threads[QUERY_THREADS];
  for (int t = 0; t < QUERY_THREADS; t++) {
    parallel[t] = (Queries){ix, cs, qs, {0}, {0}, {0}, {0}, 0};
    threads[t] = g_thread_new("query", run_queries, &parallel[t]);
  }
  for (int t = 0; t < QUERY_THREADS; t++) {
    g_thread_join(threads[t]);
    g_assert_cmpmem(parallel[t].results, sizeof serial.results, serial.results,
                    sizeof serial.results);
    g_assert_cmpmem(parallel[t].ids, sizeof serial.ids, serial.ids, sizeof serial.ids);
    g_assert_cmpmem(parallel[t].counts, sizeof serial.counts, serial.counts,
                    sizeof serial.counts);
    g_assert_cmpmem(parallel[t].mu2_sum, sizeof serial.mu2_sum, serial.mu2_sum,
                    sizeof serial.mu2_sum);
    g_assert_cmpuint(parallel[t].pairs, ==, serial.pairs);
  }
  pw85_index_destroy(ix);
  g_rand_free(rng);
}

static Config const configs[] = {
    {"mono-dense-periodic", MONO, 1, 400, .4, 0},
    {"mono-dilute-periodic", MONO, 1, 300, .05, 0},
    {"mono-dense-open", MONO, 0, 400, .4, 0},
    {"poly-periodic", POLY, 1, 300, .3, 0},
    {"poly-open", POLY, 0, 300, .3, 0},
    {"needles-periodic", NEEDLES, 1, 400, .01, 0},
    {"discs-periodic", DISCS, 1, 300, .1, 0},
    {"needles-open", NEEDLES, 0, 300, .01, 0},
    {"straddling-periodic", MONO, 1, 300, .3, 1},
    {"small-box", MONO, 1, 6, .3, 1},
};

/* ---- near contact ------------------------------------------------------- */

/* overlap_any on pairs placed at μ² = 1 + δ, δ from ±1e-2 to ±1e-13 (and
 * 0), between spheres, near-spheres and triaxial ellipsoids of different
 * sizes, in an open domain and in a periodic box (the stored one near a
 * corner, the candidate through the box's faces): its result and id are
 * those of pw85_overlap() on the one pair. Close to contact the index may
 * not decide anything by its own shortcuts (a bound on inscribed balls, the
 * AABB and line-of-centres tests); a shortcut too generous shows here. */
static void test_near_contact(void) {
  GRand *rng = g_rand_new_with_seed(1616);
  static double const deltas[] = {1e-2, 1e-4, 1e-7, 1e-10, 1e-13, 0.};
  double const box[3] = {10., 11., 12.};
  int mismatches = 0, overlapping = 0, separate = 0;
  for (int periodic = 0; periodic < 2; periodic++) {
    for (int n = 0; n < 6000; n++) {
      double q[2][6], a[3], e[3];
      for (int k = 0; k < 2; k++) {
        double const size = k == 0 ? 1. : g_rand_double_range(rng, .3, 3.);
        int const kind = g_rand_int_range(rng, 0, 3);
        for (int d = 0; d < 3; d++)
          a[d] = size * (kind == 0 ? 1. : kind == 1 ? 1. - 1e-3 * d
                                                     : g_rand_double_range(rng, .3, 1.));
        for (int d = 0; d < 3; d++) e[d] = a[d] * a[d];
        if (kind == 0) { /* a sphere, exactly */
          double const qs[6] = {e[0], 0., 0., e[0], 0., e[0]};
          memcpy(q[k], qs, sizeof qs);
        } else {
          random_form_with_eigenvalues(rng, e, q[k]);
        }
      }
      double p[4], rot[9], dir[3], out[2];
      random_unit_quaternion(rng, p);
      quaternion_rotation(p, rot);
      for (int d = 0; d < 3; d++) dir[d] = rot[d];
      /* μ is homogeneous of degree 1 in r: scaled to μ² = 1 + δ. */
      g_assert_cmpint(pw85_contact_function(dir, q[1], q[0], out), ==, PW85_SUCCESS);
      double const delta = deltas[n % G_N_ELEMENTS(deltas)] * (n % 12 < 6 ? 1. : -1.);
      double const scale = sqrt((1. + delta) / out[0]);
      double stored[3] = {.3, .2, .1}, cand[3], r[3];
      if (periodic) for (int d = 0; d < 3; d++) stored[d] = box[d] - .2;
      for (int d = 0; d < 3; d++) stored[d] = ldexp(nearbyint(ldexp(stored[d], 40)), -40);
      for (int d = 0; d < 3; d++) /* on a grid of 2⁻⁴⁰: r below is exact */
        cand[d] = ldexp(nearbyint(ldexp(stored[d] - scale * dir[d], 40)), -40);
      pw85_index *ix = NULL;
      g_assert_cmpint(pw85_index_create(periodic ? box : NULL, &ix), ==, PW85_SUCCESS);
      g_assert_cmpint(pw85_index_insert(ix, 7, stored, q[0]), ==, PW85_SUCCESS);
      if (periodic) /* the candidate in the box, the stored one's image near it */
        for (int d = 0; d < 3; d++) cand[d] -= box[d];
      int shift = periodic ? 1 : 0;
      for (int d = 0; d < 3; d++) r[d] = (stored[d] - shift * box[d]) - cand[d];
      int ref = 9, result = 9;
      size_t id = 0;
      g_assert_cmpint(pw85_overlap(r, q[1], q[0], &ref), ==, PW85_SUCCESS);
      g_assert_cmpint(pw85_index_overlap_any(ix, cand, q[1], PW85_INDEX_NO_ID, &result, &id),
                      ==, PW85_SUCCESS);
      if (result != ref || id != (ref == 1 ? PW85_INDEX_NO_ID : 7)) {
        if (mismatches++ < 5)
          g_test_message("near contact %d (δ = %g, periodic %d): index %d (id %zu), "
                         "pw85_overlap %d", n, delta, periodic, result, id, ref);
      }
      overlapping += ref == -1;
      separate += ref == 1;
      pw85_index_destroy(ix);
    }
  }
  g_test_message("near contact: %d overlapping, %d separate, %d mismatches",
                 overlapping, separate, mismatches);
  g_assert_cmpint(mismatches, ==, 0);
  g_assert_cmpint(overlapping, >, 4000); /* both sides of contact tested */
  g_assert_cmpint(separate, >, 4000);
  g_rand_free(rng);
}

/* ---- length scales ------------------------------------------------------- */

/* A fixed configuration scaled by 2^e, e from −500 to 500: centres and box
 * sides by 2^e, forms by 2^2e, exactly (entries on a grid of 2⁻²⁴, forms'
 * nonzero entries above 2⁻²⁰: none leaves the normal range). μ² and λ
 * are invariant under that scaling, and so are pw85_overlap()'s and
 * pw85_contact_function()'s answers: at every scale, every query of the
 * index must give the brute force's answers at that scale, and those of
 * scale 1, bit for bit. (Below 2⁻²⁶⁸ the line-of-centres test once formed
 * rᵀQr in underflow and discarded every pair.) */
#define SCALE_N 16
#define SCALE_CANDIDATES 6

typedef struct {
  int overlap_any[SCALE_CANDIDATES];
  size_t any_id[SCALE_CANDIDATES];
  GArray *within[SCALE_CANDIDATES]; /* Ref */
  GArray *pairs, *pairs_within;      /* Ref */
} ScaleAnswers;

static void scale_answers_clear(ScaleAnswers *a) {
  for (int k = 0; k < SCALE_CANDIDATES; k++) g_array_unref(a->within[k]);
  g_array_unref(a->pairs), g_array_unref(a->pairs_within);
}

/* The index's answers on the configuration scaled by 2^e. */
static void index_answers(Mirror const *m, double const *cand_c,
                          double const *cand_q, ScaleAnswers *out) {
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(m->periodic ? m->box : NULL, &ix), ==, PW85_SUCCESS);
  for (size_t i = 0; i < m->cap; i++)
    g_assert_cmpint(pw85_index_insert(ix, i, m->c + 3 * i, m->q + 6 * i), ==, PW85_SUCCESS);
  for (int k = 0; k < SCALE_CANDIDATES; k++) {
    double const *c = cand_c + 3 * k, *q = cand_q + 6 * k;
    g_assert_cmpint(pw85_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, &out->overlap_any[k],
                                           &out->any_id[k]), ==, PW85_SUCCESS);
    size_t ids[64], n = 0;
    int shifts[3 * 64];
    double ml[2 * 64];
    g_assert_cmpint(pw85_index_within(ix, c, q, 1.5, PW85_INDEX_NO_ID, 64, ids, shifts, ml,
                                      &n), ==, PW85_SUCCESS);
    g_assert_cmpuint(n, <=, 64);
    out->within[k] = g_array_new(FALSE, FALSE, sizeof(Ref));
    for (size_t a = 0; a < n; a++) {
      Ref r = {PW85_INDEX_NO_ID, ids[a], {shifts[3 * a], shifts[3 * a + 1], shifts[3 * a + 2]},
               0, ml[2 * a], ml[2 * a + 1]};
      g_array_append_val(out->within[k], r);
    }
  }
  for (int within = 0; within <= 1; within++) {
    Pairs p = index_pairs(ix, within, 2., 1);
    GArray *a = g_array_new(FALSE, FALSE, sizeof(Ref));
    for (size_t k = 0; k < p.count; k++) {
      Ref r = {p.ids[2 * k], p.ids[2 * k + 1],
               {p.shifts[3 * k], p.shifts[3 * k + 1], p.shifts[3 * k + 2]},
               within ? 0 : p.results[k], within ? p.mu2_lambda[2 * k] : 0.,
               within ? p.mu2_lambda[2 * k + 1] : 0.};
      g_array_append_val(a, r);
    }
    if (within) out->pairs_within = a; else out->pairs = a;
    pairs_clear(&p);
  }
  pw85_index_destroy(ix);
}

static gboolean refs_equal(GArray *a, GArray *b) {
  if (a->len != b->len) return FALSE;
  for (guint k = 0; k < a->len; k++) {
    Ref const *x = &g_array_index(a, Ref, k), *y = &g_array_index(b, Ref, k);
    if (x->j != y->j || memcmp(x->n, y->n, sizeof x->n) != 0 || x->result != y->result ||
        x->mu2 != y->mu2 || x->lambda != y->lambda ||
        (x->i != y->i && x->i != PW85_INDEX_NO_ID))
      return FALSE;
  }
  return TRUE;
}

/* The brute force's answers on the same configuration, and the index's
 * against them and against those at scale 1 (first, NULL at scale 1). */
static int check_scale(Mirror const *m, double const *cand_c, double const *cand_q,
                       ScaleAnswers const *first, ScaleAnswers *got, int e) {
  int bad = 0;
  index_answers(m, cand_c, cand_q, got);
  for (int k = 0; k < SCALE_CANDIDATES; k++) {
    GArray *ref = brute_candidate(m, cand_c + 3 * k, cand_q + 6 * k, PW85_INDEX_NO_ID,
                                  FALSE, 1.);
    int best = 1;
    for (guint a = 0; a < ref->len; a++) best = MIN(best, g_array_index(ref, Ref, a).result);
    g_array_unref(ref);
    ref = brute_candidate(m, cand_c + 3 * k, cand_q + 6 * k, PW85_INDEX_NO_ID, TRUE, 1.5);
    if (got->overlap_any[k] != best || !refs_equal(got->within[k], ref) ||
        (first != NULL && (got->overlap_any[k] != first->overlap_any[k] ||
                           got->any_id[k] != first->any_id[k] ||
                           !refs_equal(got->within[k], first->within[k])))) {
      test_mismatch("scale 2^%d, %s, candidate %d: overlap_any %d (brute force %d), "
                    "within finds %u (brute force %u)", e, m->periodic ? "periodic" : "open",
                    k, got->overlap_any[k], best, got->within[k]->len, ref->len);
      bad++;
    }
    g_array_unref(ref);
  }
  for (int within = 0; within <= 1; within++) {
    GArray *ref = brute_pairs(m, within, 2.);
    GArray *mine = within ? got->pairs_within : got->pairs;
    if (!refs_equal(mine, ref) ||
        (first != NULL && !refs_equal(mine, within ? first->pairs_within : first->pairs))) {
      test_mismatch("scale 2^%d, %s, %s: %u pairs (brute force %u)", e,
                    m->periodic ? "periodic" : "open",
                    within ? "pairs_within" : "overlapping_pairs", mine->len, ref->len);
      bad++;
    }
    g_array_unref(ref);
  }
  return bad;
}

/* A form of semi-axes a (random orientation) with entries on a grid of
 * 2⁻²⁰, nonzero ones above 2⁻²⁰ in magnitude; positive definite (checked
 * by the index on insertion). */
static void grid_form(GRand *rng, double const a[3], double q[6]) {
  double e[3];
  for (int k = 0; k < 3; k++) e[k] = a[k] * a[k];
  random_form_with_eigenvalues(rng, e, q);
  for (int k = 0; k < 6; k++) q[k] = ldexp(nearbyint(ldexp(q[k], 20)), -20);
}

static void test_length_scales(void) {
  GRand *rng = g_rand_new_with_seed(2268);
  double c[3 * SCALE_N], q[6 * SCALE_N], cc[3 * SCALE_CANDIDATES], cq[6 * SCALE_CANDIDATES];
  double const box[3] = {4., 4.5, 5.};
  double const axes[3] = {1.2, .8, .5};
  for (int i = 0; i < SCALE_N + SCALE_CANDIDATES; i++) {
    double *ci = i < SCALE_N ? c + 3 * i : cc + 3 * (i - SCALE_N);
    double *qi = i < SCALE_N ? q + 6 * i : cq + 6 * (i - SCALE_N);
    for (int k = 0; k < 3; k++) ci[k] = on_grid(g_rand_double_range(rng, -.5, box[k] + .5));
    grid_form(rng, axes, qi);
  }
  int bad = 0, overlaps = 0;
  for (int periodic = 0; periodic <= 1; periodic++) {
    ScaleAnswers first;
    for (int step = 0; step <= 50; step++) {
      int const e = step == 0 ? 0 : -500 + 20 * (step - 1); /* scale 1 first */
      double sc[3 * SCALE_N], sq[6 * SCALE_N], scc[3 * SCALE_CANDIDATES],
          scq[6 * SCALE_CANDIDATES];
      for (int k = 0; k < 3 * SCALE_N; k++) sc[k] = ldexp(c[k], e);
      for (int k = 0; k < 6 * SCALE_N; k++) sq[k] = ldexp(q[k], 2 * e);
      for (int k = 0; k < 3 * SCALE_CANDIDATES; k++) scc[k] = ldexp(cc[k], e);
      for (int k = 0; k < 6 * SCALE_CANDIDATES; k++) scq[k] = ldexp(cq[k], 2 * e);
      gboolean present[SCALE_N];
      for (int i = 0; i < SCALE_N; i++) present[i] = TRUE;
      Mirror m = {periodic, {ldexp(box[0], e), ldexp(box[1], e), ldexp(box[2], e)},
                  SCALE_N, present, sc, sq};
      ScaleAnswers got;
      bad += check_scale(&m, scc, scq, step == 0 ? NULL : &first, &got, e);
      if (step == 0) {
        first = got;
        overlaps = (int)got.pairs->len;
      } else {
        scale_answers_clear(&got);
      }
    }
    scale_answers_clear(&first);
  }
  g_test_message("length scales 2^-500 to 2^500: %d overlapping pairs at scale 1", overlaps);
  g_assert_cmpint(overlaps, >, 0); /* the configuration has something to find */
  g_assert_cmpint(bad, ==, 0);
  g_rand_free(rng);
}

/* The reproducer of issue 25: two spheres of radius 2⁻²⁸⁰ whose centres
 * are 1.2·2⁻²⁸¹ apart, stored and candidate, in an open domain and in a
 * periodic box: pw85_overlap() answers −1, and so must every query. */
static void test_tiny_reproducer(void) {
  double const c1[3] = {0x1.999999999999ap-284, 0x1.999999999999ap-283, 0x1.3333333333333p-282};
  double const c2[3] = {0x1.ccccccccccccdp-281, 0x1p-281, 0x1.6666666666666p-281};
  double const q[6] = {0x1p-560, 0, 0, 0x1p-560, 0, 0x1p-560};
  double const box[3] = {0x1p-270, 0x1p-270, 0x1p-270};
  double r[3];
  for (int k = 0; k < 3; k++) r[k] = c2[k] - c1[k]; /* exact (Sterbenz) */
  int ref = 9;
  g_assert_cmpint(pw85_overlap(r, q, q, &ref), ==, PW85_SUCCESS);
  g_assert_cmpint(ref, ==, -1);
  for (int periodic = 0; periodic <= 1; periodic++) {
    pw85_index *ix = NULL;
    g_assert_cmpint(pw85_index_create(periodic ? box : NULL, &ix), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert(ix, 0, c1, q), ==, PW85_SUCCESS);
    int result = 9;
    size_t id = 7, n = 0;
    g_assert_cmpint(pw85_index_overlap_any(ix, c2, q, PW85_INDEX_NO_ID, &result, &id), ==,
                    PW85_SUCCESS);
    g_assert_cmpint(result, ==, -1);
    g_assert_cmpuint(id, ==, 0);
    g_assert_cmpint(pw85_index_within(ix, c2, q, 1., PW85_INDEX_NO_ID, 0, NULL, NULL, NULL,
                                      &n), ==, PW85_SUCCESS);
    g_assert_cmpuint(n, ==, 1);
    g_assert_cmpint(pw85_index_insert(ix, 1, c2, q), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_overlapping_pairs(ix, 1, 0, NULL, NULL, NULL, &n), ==,
                    PW85_SUCCESS);
    g_assert_cmpuint(n, ==, 1);
    g_assert_cmpint(pw85_index_pairs_within(ix, 1., 1, 0, NULL, NULL, NULL, &n), ==,
                    PW85_SUCCESS);
    g_assert_cmpuint(n, ==, 1);
    pw85_index_destroy(ix);
  }
}

/* ---- overlap_any in batches -------------------------------------------- */

/* pw85_index_overlap_any_batch() against one call of
 * pw85_index_overlap_any() per candidate (which the brute-force tests
 * check): the same results, ids and statuses on 1, 2, 8 and OpenMP's
 * default count of threads, with excluded ids, strides 0 and longer
 * records, and failing candidates among the others; then the errors of the
 * call itself. */
static void test_overlap_any_batch(void) {
  GRand *rng = g_rand_new_with_seed(2404);
  Config const cf = {"batch", MONO, 1, 2000, .05, 0};
  int const n = small_run() ? 400 : cf.n;
  size_t const m = small_run() ? 600 : 3000; /* candidates: ≥ 512 for threads */
  double const side = cbrt(n * mean_volume(MONO) / cf.fraction);
  double const box[3] = {side, side * 1.1, side * .9};
  pw85_index *ix = NULL;
  g_assert_cmpint(pw85_index_create(box, &ix), ==, PW85_SUCCESS);
  for (int i = 0; i < n; i++) {
    double c[3], q[6];
    random_ellipsoid(rng, &cf, side, c, q);
    g_assert_cmpint(pw85_index_insert(ix, (size_t)i, c, q), ==, PW85_SUCCESS);
  }
  /* Records of 4 doubles (centre) and 7 (form): strides above the size. */
  double *c = g_new(double, 4 * m), *q = g_new(double, 7 * m);
  size_t *exclude = g_new(size_t, m), *ref_ids = g_new(size_t, m);
  int *ref = g_new(int, m), *ref_status = g_new(int, m);
  for (size_t i = 0; i < m; i++) {
    random_ellipsoid(rng, &cf, side, c + 4 * i, q + 7 * i);
    exclude[i] = i % 3 == 0 ? PW85_INDEX_NO_ID : (size_t)g_rand_int_range(rng, 0, n + 5);
    if (i % 3 == 1) { /* a Monte Carlo move of the excluded one, which it overlaps */
      exclude[i] %= (size_t)n;
      g_assert_cmpint(pw85_index_get(ix, exclude[i], c + 4 * i, q + 7 * i), ==,
                      PW85_SUCCESS);
      for (int d = 0; d < 3; d++) c[4 * i + d] += g_rand_double_range(rng, -.05, .05);
    }
  }
  c[4 * (m / 3)] = NAN;          /* PW85_EDOM */
  q[7 * (2 * m / 3) + 3] = -1.;  /* PW85_ENOTPOSDEF */
  int counts[3] = {0, 0, 0};
  for (size_t i = 0; i < m; i++) {
    ref[i] = 99, ref_ids[i] = 12345;
    ref_status[i] = pw85_index_overlap_any(ix, c + 4 * i, q + 7 * i, exclude[i],
                                           ref + i, ref_ids + i);
    if (ref_status[i] == PW85_SUCCESS) counts[ref[i] + 1]++;
  }
  g_assert_cmpint(ref_status[m / 3], ==, PW85_EDOM);
  g_assert_cmpint(ref_status[2 * m / 3], ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(counts[0], >, (int)m / 10); /* both answers well represented */
  g_assert_cmpint(counts[2], >, (int)m / 10);
  /* without their exclusions, the moves overlap */
  for (size_t i = 1; i < m; i += 30) {
    int r = 99;
    size_t id = 0;
    if (ref_status[i] == PW85_SUCCESS && ref[i] == 1) {
      g_assert_cmpint(pw85_index_overlap_any(ix, c + 4 * i, q + 7 * i, PW85_INDEX_NO_ID, &r,
                                             &id), ==, PW85_SUCCESS);
      g_assert_cmpint(r, ==, -1);
    }
  }

  int *results = g_new(int, m), *status = g_new(int, m);
  size_t *ids = g_new(size_t, m);
  int const threads[] = {1, 2, 8, 0};
  for (size_t t = 0; t < G_N_ELEMENTS(threads); t++) {
    for (size_t i = 0; i < m; i++) results[i] = 99, ids[i] = 12345, status[i] = 77;
    g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, q, 7, exclude, results,
                                                 ids, status, threads[t]),
                    ==, PW85_EDOM); /* the first failing candidate's */
    for (size_t i = 0; i < m; i++) {
      g_assert_cmpint(status[i], ==, ref_status[i]);
      g_assert_cmpint(results[i], ==, ref[i]); /* 99: left untouched */
      g_assert_cmpuint(ids[i], ==, ref_ids[i]);
    }
  }
  /* exclude = NULL is PW85_INDEX_NO_ID; strides 0 repeat one record. */
  size_t const k = 5;
  int one = 99;
  size_t one_id = 0;
  g_assert_cmpint(pw85_index_overlap_any(ix, c + 4 * k, q + 7 * k, PW85_INDEX_NO_ID,
                                         &one, &one_id), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, 600, c + 4 * k, 0, q + 7 * k, 0, NULL,
                                               results, ids, NULL, 2), ==, PW85_SUCCESS);
  for (size_t i = 0; i < 600; i++) {
    g_assert_cmpint(results[i], ==, one);
    g_assert_cmpuint(ids[i], ==, one_id);
  }

  /* The call itself: nothing computed, status filled with its code. */
  for (size_t i = 0; i < m; i++) results[i] = 99, status[i] = 77;
  g_assert_cmpint(pw85_index_overlap_any_batch(NULL, m, c, 4, q, 7, NULL, results,
                                               ids, status, 1), ==, PW85_EFAULT);
  g_assert_cmpint(status[m - 1], ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, q, 7, NULL, NULL, ids,
                                               NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, q, 7, NULL, results,
                                               NULL, NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, NULL, 4, q, 7, NULL, results,
                                               ids, NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, NULL, 7, NULL, results,
                                               ids, NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 2, q, 7, NULL, results,
                                               ids, status, 1), ==, PW85_EINVAL);
  g_assert_cmpint(status[0], ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, q, 5, NULL, results,
                                               ids, NULL, 1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_index_overlap_any_batch(ix, m, c, 4, q, 7, NULL, results,
                                               ids, NULL, -1), ==, PW85_EINVAL);
  for (size_t i = 0; i < m; i++) g_assert_cmpint(results[i], ==, 99);
  g_assert_cmpint(pw85_index_overlap_any_batch(NULL, 0, NULL, 1, NULL, 1, NULL, NULL,
                                               NULL, NULL, -1), ==, PW85_SUCCESS);

  pw85_index_destroy(ix);
  g_free(c), g_free(q), g_free(exclude), g_free(ref_ids), g_free(ref);
  g_free(ref_status), g_free(results), g_free(status), g_free(ids);
  g_rand_free(rng);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/index/bad-input", test_bad_input);
  g_test_add_func("/pw85/index/several-images", test_several_images);
  g_test_add_func("/pw85/index/wide-candidate", test_wide_candidate);
  g_test_add_func("/pw85/index/concurrent-queries", test_concurrent_queries);
  g_test_add_func("/pw85/index/near-contact", test_near_contact);
  g_test_add_func("/pw85/index/length-scales", test_length_scales);
  g_test_add_func("/pw85/index/tiny-reproducer", test_tiny_reproducer);
  g_test_add_func("/pw85/index/overlap-any-batch", test_overlap_any_batch);
  for (size_t k = 0; k < G_N_ELEMENTS(configs); k++) {
    char *path = g_strdup_printf("/pw85/index/brute-force/%s", configs[k].name);
    g_test_add_data_func(path, &configs[k], test_config);
    g_free(path);
  }
  for (size_t k = 0; k < G_N_ELEMENTS(large_configs); k++) {
    char *path = g_strdup_printf("/pw85/index/threads-large/%s", large_configs[k].name);
    g_test_add_data_func(path, &large_configs[k], test_threads_large);
    g_free(path);
  }
  for (size_t k = 0; k < G_N_ELEMENTS(insert_configs); k++) {
    char *path = g_strdup_printf("/pw85/index/threads-large/insert-many-%s",
                                 insert_configs[k].name);
    g_test_add_data_func(path, &insert_configs[k], test_insert_many_threads);
    g_free(path);
  }
  g_test_add_func("/pw85/index/threads-large/insert-many-tables", test_insert_many_tables);
  return g_test_run();
}
