/* SPDX-License-Identifier: BSD-3-Clause */
/* The index of ellipses (pw85_2d_index.h) against a brute force over every
 * pair and every periodic image that decides each image pair itself, with
 * pw85_2d_overlap() and pw85_2d_contact_function() on the image vector
 * (exact: centres and sides on a grid of 2⁻¹², so that the index's exact
 * vector and the brute force's double are the same number). Seeded random
 * configurations in an open plane and in periodic rectangles, down to
 * rectangles as narrow as the side rule 2·√Q_kk·(1 + 2⁻²⁰) < L_k allows
 * (many images of each ellipse in reach), after insert_many (loop and bulk
 * paths), update, remove and insert; every query (overlap_any and its
 * batch, within, overlapping_pairs, pairs_within) on 1, 2 and 8 threads,
 * bit for bit; insert_many_threads on 1, 2 and 8 threads; every bad input,
 * with the outputs untouched. The configurations are small enough that
 * the library runs them on one thread (a thread per 4096 ellipses):
 * /pw85/2d-index/threads-large checks 40000 ellipses, where insert_many,
 * the all-pairs queries and overlap_any_batch (10000 candidates) run on
 * 2, 3 and 8 threads, against 1, bit for bit. PW85_TEST_SMALL (sanitizer
 * and valgrind runs) makes the configurations smaller. */
#include <float.h>
#include <limits.h>
#include <pw85/pw85_2d_index.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static gboolean small_run(void) { return g_getenv("PW85_TEST_SMALL") != NULL; }

/* x on the grid of 2⁻¹²; below 2²⁰ in magnitude, every sum c_j + n·L − c
 * of the brute force is then exact in double. */
static double grid(double x) { return ldexp(nearbyint(ldexp(x, 12)), -12); }

/* ---- configurations ---------------------------------------------------- */

typedef struct {
  const char *name;
  int periodic;
  int n;            /* ellipses (a fifth when small) */
  double fraction;  /* area fraction */
  double aspect;    /* largest aspect ratio */
  int tight;        /* periodic: sides as small as the side rule allows */
} Config;

/* What the brute force sees: the caller's copy of the index. */
typedef struct {
  int periodic;
  double box[2];
  size_t cap;
  gboolean *present;
  double *c, *q;
} World;

static void random_ellipse(GRand *rng, Config const *cf, double c[2],
                           double q[3], double const span[2]) {
  double const a0 = g_rand_double_range(rng, .5, 1.);
  double const a[2] = {a0, a0 / g_rand_double_range(rng, 1., cf->aspect)};
  double const theta = g_rand_double_range(rng, -G_PI, G_PI);
  g_assert_cmpint(pw85_2d_ellipse(a, theta, q), ==, PW85_SUCCESS);
  for (int k = 0; k < 2; k++) /* unwrapped: up to half a span outside */
    c[k] = grid(g_rand_double_range(rng, -.5 * span[k], 1.5 * span[k]));
}

/* √Q_kk of the widest ellipse drawn with that aspect (a0 ≤ 1). */
static double largest_half_width(void) { return 1.; }

/* ---- brute force ------------------------------------------------------- */

typedef struct {
  size_t i, j;
  int n[2];
  int result;
  double mu2, lambda;
} Found;

static int found_cmp(const void *pa, const void *pb) {
  Found const *a = pa, *b = pb;
  if (a->i != b->i) return a->i < b->i ? -1 : 1;
  if (a->j != b->j) return a->j < b->j ? -1 : 1;
  for (int k = 0; k < 2; k++)
    if (a->n[k] != b->n[k]) return a->n[k] < b->n[k] ? -1 : 1;
  return 0;
}

/* Calls pair(n, r) for every image n of ellipse j that the bounding
 * circles do not separate at μ² = t, √tr Q being a circle's radius
 * (widened by a quarter: a bound of the brute force's own, not the
 * index's). r = (c_j + n∘L) − c, exact on the grid. */
typedef void (*ImageFn)(int const n[2], double const r[2], void *data);

static void for_images(World const *w, double const c[2], double const q[3],
                       size_t j, double t, ImageFn fn, void *data) {
  double const *cj = w->c + 2 * j, *qj = w->q + 3 * j;
  double const reach = 1.25 * sqrt(t) * (sqrt(q[0] + q[2]) + sqrt(qj[0] + qj[2]));
  int lo[2] = {0, 0}, hi[2] = {0, 0};
  if (w->periodic)
    for (int k = 0; k < 2; k++) {
      lo[k] = (int)floor((c[k] - cj[k] - reach) / w->box[k]);
      hi[k] = (int)ceil((c[k] - cj[k] + reach) / w->box[k]);
    }
  int n[2];
  for (n[0] = lo[0]; n[0] <= hi[0]; n[0]++)
    for (n[1] = lo[1]; n[1] <= hi[1]; n[1]++) {
      double r[2];
      for (int k = 0; k < 2; k++)
        r[k] = (cj[k] + n[k] * (w->periodic ? w->box[k] : 0.)) - c[k];
      fn(n, r, data);
    }
}

typedef struct {
  double const *q, *qj;
  size_t i, j;
  gboolean within, self; /* self: i = j, n lexicographically positive only */
  double t;
  GArray *out;
} Decide;

static void decide(int const n[2], double const r[2], void *data) {
  Decide *d = data;
  if (d->self && !(n[0] > 0 || (n[0] == 0 && n[1] > 0))) return;
  Found f = {d->i, d->j, {n[0], n[1]}, 0, 0., 0.};
  if (d->within) {
    double o[2];
    g_assert_cmpint(pw85_2d_contact_function(r, d->q, d->qj, o), ==, PW85_SUCCESS);
    if (!(o[0] < d->t)) return;
    f.mu2 = o[0], f.lambda = o[1];
  } else {
    g_assert_cmpint(pw85_2d_overlap(r, d->q, d->qj, &f.result), ==, PW85_SUCCESS);
    if (f.result > 0) return;
  }
  g_array_append_val(d->out, f);
}

/* A candidate (c, q) against every stored ellipse but exclude (i = NO_ID),
 * or every stored pair (c, q ignored): overlaps (within = FALSE) or
 * μ² < t. Sorted by (i, j, n). */
static GArray *brute(World const *w, double const c[2], double const q[3],
                     size_t exclude, gboolean pairs, gboolean within, double t) {
  GArray *out = g_array_new(FALSE, FALSE, sizeof(Found));
  Decide d = {q, NULL, PW85_INDEX_NO_ID, 0, within, FALSE, t, out};
  for (size_t i = 0; i < (pairs ? w->cap : 1); i++) {
    if (pairs && !w->present[i]) continue;
    double const *ci = pairs ? w->c + 2 * i : c;
    d.q = pairs ? w->q + 3 * i : q;
    d.i = pairs ? i : PW85_INDEX_NO_ID;
    for (size_t j = pairs ? i : 0; j < w->cap; j++) {
      if (!w->present[j] || (!pairs && j == exclude)) continue;
      d.j = j, d.qj = w->q + 3 * j, d.self = pairs && j == i;
      for_images(w, ci, d.q, j, t, decide, &d);
    }
  }
  g_array_sort(out, found_cmp);
  return out;
}

/* ---- the index's answers ----------------------------------------------- */

/* An all-pairs answer, or within's (i unused). */
typedef struct {
  size_t count;
  size_t *ids;
  int *shifts, *results;
  double *ml;
} Answer;

static void answer_free(Answer *a) {
  g_free(a->ids), g_free(a->shifts), g_free(a->results), g_free(a->ml);
}

static Answer all_pairs(pw85_2d_index const *ix, gboolean within, double t,
                        int threads) {
  Answer a = {0, NULL, NULL, NULL, NULL};
  size_t count = 7;
  int s = within ? pw85_2d_index_pairs_within(ix, t, threads, 0, NULL, NULL, NULL, &count)
                 : pw85_2d_index_overlapping_pairs(ix, threads, 0, NULL, NULL, NULL, &count);
  g_assert_cmpint(s, ==, PW85_SUCCESS);
  size_t const cap = count + 1;
  a.ids = g_new0(size_t, 2 * cap), a.shifts = g_new0(int, 2 * cap);
  a.results = g_new0(int, cap), a.ml = g_new0(double, 2 * cap);
  s = within ? pw85_2d_index_pairs_within(ix, t, threads, cap, a.ids, a.shifts, a.ml, &a.count)
             : pw85_2d_index_overlapping_pairs(ix, threads, cap, a.ids, a.shifts,
                                               a.results, &a.count);
  g_assert_cmpint(s, ==, PW85_SUCCESS);
  g_assert_cmpuint(a.count, ==, count);
  return a;
}

static gboolean same_answer(Answer const *a, Answer const *b) {
  return a->count == b->count &&
         memcmp(a->ids, b->ids, 2 * a->count * sizeof(size_t)) == 0 &&
         memcmp(a->shifts, b->shifts, 2 * a->count * sizeof(int)) == 0 &&
         memcmp(a->results, b->results, a->count * sizeof(int)) == 0 &&
         memcmp(a->ml, b->ml, 2 * a->count * sizeof(double)) == 0;
}

/* The index's answer against the brute force, entry by entry (pairs: ids
 * at 2k, 2k + 1; within: at k). */
static void compare(const char *what, Answer const *a, GArray *ref,
                    gboolean pairs, gboolean within) {
  if (a->count != ref->len) {
    test_mismatch("%s: %zu results, brute force %u", what, a->count, ref->len);
    return;
  }
  for (size_t k = 0; k < a->count; k++) {
    Found const *f = &g_array_index(ref, Found, k);
    gboolean same = pairs ? a->ids[2 * k] == f->i && a->ids[2 * k + 1] == f->j
                          : a->ids[k] == f->j;
    same = same && a->shifts[2 * k] == f->n[0] && a->shifts[2 * k + 1] == f->n[1];
    if (within)
      same = same && a->ml[2 * k] == f->mu2 && a->ml[2 * k + 1] == f->lambda;
    else
      same = same && a->results[k] == f->result;
    if (!same) {
      test_mismatch("%s: result %zu is (%zu, %zu, [%d %d]) mu2 %.17g, brute force "
                    "(%zu, %zu, [%d %d]) mu2 %.17g", what, k,
                    pairs ? a->ids[2 * k] : 0, pairs ? a->ids[2 * k + 1] : a->ids[k],
                    a->shifts[2 * k], a->shifts[2 * k + 1], a->ml[2 * k],
                    pairs ? f->i : 0, f->j, f->n[0], f->n[1], f->mu2);
      return;
    }
  }
}

/* Every all-pairs query on 1, 2, 8 and INT_MAX threads (above the cap of
 * pw85_index.h; it gave PW85_ENOMEM): the same bytes, and the brute
 * force's pairs. */
static void check_pairs(pw85_2d_index const *ix, World const *w,
                        const char *name, const char *step) {
  double const ts[] = {1., 2.25};
  for (int mode = 0; mode < 3; mode++) {
    gboolean const within = mode > 0;
    double const t = within ? ts[mode - 1] : 1.;
    GArray *ref = brute(w, NULL, NULL, PW85_INDEX_NO_ID, TRUE, within, t);
    Answer one = all_pairs(ix, within, t, 1);
    char *what = g_strdup_printf("%s %s %s t=%g", name, step,
                                 within ? "pairs_within" : "overlapping_pairs", t);
    compare(what, &one, ref, TRUE, within);
    int const threads[] = {2, 8, INT_MAX};
    for (size_t k = 0; k < G_N_ELEMENTS(threads); k++) {
      Answer more = all_pairs(ix, within, t, threads[k]);
      if (!same_answer(&one, &more))
        test_mismatch("%s: %d threads differ from 1", what, threads[k]);
      answer_free(&more);
    }
    g_test_message("%s: %zu pairs", what, one.count);
    g_free(what);
    answer_free(&one);
    g_array_unref(ref);
  }
}

/* Candidates: overlap_any (the least result, an id that has it),
 * overlap_any_batch (the same, per candidate, on 1, 2 and 8 threads) and
 * within at t = 1 and 3. */
static void check_candidates(pw85_2d_index const *ix, World const *w,
                             GRand *rng, Config const *cf, double const span[2],
                             int count, const char *step) {
  double *cs = g_new(double, 2 * count), *qs = g_new(double, 3 * count);
  size_t *exclude = g_new(size_t, count), *ids = g_new(size_t, count);
  int *results = g_new(int, count);
  for (int k = 0; k < count; k++) {
    double *c = cs + 2 * k, *q = qs + 3 * k;
    random_ellipse(rng, cf, c, q, span);
    exclude[k] = k % 3 == 1 ? (size_t)g_rand_int_range(rng, 0, (gint32)w->cap)
                            : PW85_INDEX_NO_ID;
    GArray *ref = brute(w, c, q, exclude[k], FALSE, FALSE, 1.);
    int best = 1;
    for (guint a = 0; a < ref->len; a++) best = MIN(best, g_array_index(ref, Found, a).result);
    int result = 99;
    size_t id = 0;
    g_assert_cmpint(pw85_2d_index_overlap_any(ix, c, q, exclude[k], &result, &id),
                    ==, PW85_SUCCESS);
    results[k] = result, ids[k] = id;
    if (result != best)
      test_mismatch("%s %s candidate %d: overlap_any %d, brute force %d", cf->name,
                    step, k, result, best);
    gboolean named = best == 1 && id == PW85_INDEX_NO_ID;
    for (guint a = 0; a < ref->len; a++) {
      Found const *f = &g_array_index(ref, Found, a);
      named = named || (f->j == id && f->result == best);
    }
    if (!named)
      test_mismatch("%s %s candidate %d: id %zu has not result %d", cf->name, step,
                    k, id, best);
    g_array_unref(ref);

    double const ts[] = {1., 3.};
    for (int a = 0; a < 2; a++) {
      GArray *near = brute(w, c, q, exclude[k], FALSE, TRUE, ts[a]);
      Answer got = {0, g_new0(size_t, near->len + 1), g_new0(int, 2 * near->len + 2),
                    g_new0(int, 1), g_new0(double, 2 * near->len + 2)};
      g_assert_cmpint(pw85_2d_index_within(ix, c, q, ts[a], exclude[k], near->len + 1,
                                           got.ids, got.shifts, got.ml, &got.count),
                      ==, PW85_SUCCESS);
      char *what = g_strdup_printf("%s %s candidate %d within t=%g", cf->name,
                                   step, k, ts[a]);
      compare(what, &got, near, FALSE, TRUE);
      g_free(what);
      answer_free(&got);
      g_array_unref(near);
    }
  }
  int const threads[] = {1, 2, 8};
  for (int a = 0; a < 3; a++) {
    int *r2 = g_new(int, count), *st = g_new(int, count);
    size_t *i2 = g_new(size_t, count);
    g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, (size_t)count, cs, 2, qs, 3,
                                                    exclude, r2, i2, st, threads[a]),
                    ==, PW85_SUCCESS);
    for (int k = 0; k < count; k++)
      if (st[k] != PW85_SUCCESS || r2[k] != results[k] || i2[k] != ids[k])
        test_mismatch("%s %s batch on %d threads, candidate %d: %d %d %zu, alone %d %zu",
                      cf->name, step, threads[a], k, st[k], r2[k], i2[k], results[k],
                      ids[k]);
    g_free(r2), g_free(st), g_free(i2);
  }
  g_free(cs), g_free(qs), g_free(exclude), g_free(ids), g_free(results);
}

/* ---- a configuration through insert, update, remove -------------------- */

static void test_config(gconstpointer data) {
  Config const *cf = data;
  GRand *rng = g_rand_new_with_seed(0x2d1dULL ^ (guint32)g_str_hash(cf->name));
  int const n = small_run() ? MAX(cf->n / 5, 8) : cf->n;
  double const mean_area = G_PI * .75 * .75 / (1. + .5 * (cf->aspect - 1.));
  double side = grid(sqrt(n * mean_area / cf->fraction)) + 0x1p-12;
  World w = {cf->periodic, {side, side}, (size_t)n + n / 4,
             NULL, NULL, NULL};
  if (cf->tight) { /* the least sides on the grid that the side rule allows */
    double const h = largest_half_width();
    w.box[0] = grid(2. * h * (1. + 0x1p-20)) + 0x1p-12;
    w.box[1] = w.box[0] + 0x1p-12 * 37.;
  }
  double const span[2] = {w.box[0], w.box[1]};
  w.present = g_new0(gboolean, w.cap);
  w.c = g_new0(double, 2 * w.cap), w.q = g_new0(double, 3 * w.cap);
  pw85_2d_index *ix = NULL;
  g_assert_cmpint(pw85_2d_index_create(cf->periodic ? w.box : NULL, &ix), ==,
                  PW85_SUCCESS);

  /* insert_many of ids 0 .. n−1 out of order: i·7919 mod n (7919 is a
   * prime that divides no n here, so this is a permutation) */
  size_t *ids = g_new(size_t, n);
  g_assert_cmpint(n % 7919, !=, 0);
  for (int i = 0; i < n; i++) ids[i] = (size_t)i * 7919u % (size_t)n;
  double *c = g_new(double, 2 * n), *q = g_new(double, 3 * n);
  for (int i = 0; i < n; i++) {
    random_ellipse(rng, cf, c + 2 * i, q + 3 * i, span);
    size_t const id = ids[i];
    memcpy(w.c + 2 * id, c + 2 * i, 2 * sizeof(double));
    memcpy(w.q + 3 * id, q + 3 * i, 3 * sizeof(double));
    w.present[id] = TRUE;
  }
  g_assert_cmpint(pw85_2d_index_insert_many(ix, (size_t)n, ids, c, q), ==, PW85_SUCCESS);
  size_t stored = 0;
  g_assert_cmpint(pw85_2d_index_count(ix, &stored), ==, PW85_SUCCESS);
  g_assert_cmpuint(stored, ==, (size_t)n);

  /* insert_many_threads on 2 and 8 threads leaves the index that answers
   * as this one, bit for bit */
  Answer ref = all_pairs(ix, TRUE, 2.25, 1);
  for (int t = 2; t <= 8; t *= 4) {
    pw85_2d_index *other = NULL;
    g_assert_cmpint(pw85_2d_index_create(cf->periodic ? w.box : NULL, &other), ==,
                    PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_index_insert_many_threads(other, (size_t)n, ids, c, q, t),
                    ==, PW85_SUCCESS);
    Answer a = all_pairs(other, TRUE, 2.25, 1);
    if (!same_answer(&ref, &a))
      test_mismatch("%s: insert_many_threads on %d threads differs", cf->name, t);
    answer_free(&a);
    pw85_2d_index_destroy(other);
  }
  answer_free(&ref);

  int const candidates = small_run() ? 10 : 40;
  check_pairs(ix, &w, cf->name, "inserted");
  check_candidates(ix, &w, rng, cf, span, candidates, "inserted");

  /* update a fifth, remove a fifth, insert new ids */
  for (int k = 0; k < n / 5; k++) {
    size_t const id = (size_t)g_rand_int_range(rng, 0, n);
    double cn[2], qn[3];
    random_ellipse(rng, cf, cn, qn, span);
    int const s = pw85_2d_index_update(ix, id, cn, qn);
    g_assert_cmpint(s, ==, w.present[id] ? PW85_SUCCESS : PW85_EINVAL);
    if (s == PW85_SUCCESS)
      memcpy(w.c + 2 * id, cn, sizeof cn), memcpy(w.q + 3 * id, qn, sizeof qn);
  }
  for (int k = 0; k < n / 5; k++) {
    size_t const id = (size_t)g_rand_int_range(rng, 0, n);
    g_assert_cmpint(pw85_2d_index_remove(ix, id), ==,
                    w.present[id] ? PW85_SUCCESS : PW85_EINVAL);
    w.present[id] = FALSE;
  }
  for (size_t id = (size_t)n; id < w.cap; id++) {
    double cn[2], qn[3];
    random_ellipse(rng, cf, cn, qn, span);
    g_assert_cmpint(pw85_2d_index_insert(ix, id, cn, qn), ==, PW85_SUCCESS);
    memcpy(w.c + 2 * id, cn, sizeof cn), memcpy(w.q + 3 * id, qn, sizeof qn);
    w.present[id] = TRUE;
  }
  for (size_t id = 0; id < w.cap; id++) { /* get: as stored, or EINVAL */
    double cg[2] = {-1., -1.}, qg[3] = {-1., -1., -1.};
    int const s = pw85_2d_index_get(ix, id, cg, qg);
    g_assert_cmpint(s, ==, w.present[id] ? PW85_SUCCESS : PW85_EINVAL);
    if (w.present[id])
      g_assert_true(memcmp(cg, w.c + 2 * id, sizeof cg) == 0 &&
                    memcmp(qg, w.q + 3 * id, sizeof qg) == 0);
    else
      g_assert_true(cg[0] == -1. && cg[1] == -1. && qg[0] == -1. && qg[2] == -1.);
  }
  check_pairs(ix, &w, cf->name, "changed");
  check_candidates(ix, &w, rng, cf, span, candidates, "changed");

  pw85_2d_index_destroy(ix);
  g_free(ids), g_free(c), g_free(q);
  g_free(w.present), g_free(w.c), g_free(w.q);
  g_rand_free(rng);
}

/* ---- exact image vectors ----------------------------------------------- */

/* data/pw85_2d_index_images.txt (PW85_2D_INDEX_IMAGES): pairs whose image
 * vector r = (c_j + n∘L) − c_i is not a double, with μ² of the exact
 * configuration correctly rounded (data/gen_2d_index_images.py, exact
 * rationals, checked by mpmath). within() reports that μ² bit for bit
 * through n; overlap_any() and overlapping_pairs() decide as its sign of
 * μ² − 1 outside the 4-ulp band of pw85_2d_overlap(). The fields of a
 * record, in the file's order: L[2], ci[2], qi[3], cj[2], qj[3], n[2], μ². */
enum { IMAGE_FIELDS = 15 };

static void test_exact_images(void) {
  const char *path = g_getenv("PW85_2D_INDEX_IMAGES");
  g_assert_nonnull(path);
  gchar *text = NULL;
  g_assert_true(g_file_get_contents(path, &text, NULL, NULL));
  gchar **lines = g_strsplit(text, "\n", -1);
  int records = 0, rounded_differs = 0, decided = 0;
  for (gchar **line = lines; *line != NULL; line++) {
    if (**line == '#' || **line == '\0') continue;
    double v[IMAGE_FIELDS];
    char *p = *line;
    for (int k = 0; k < IMAGE_FIELDS; k++) {
      char *end = NULL;
      v[k] = strtod(p, &end);
      g_assert_true(end != p);
      p = end;
    }
    double const *box = v, *ci = v + 2, *qi = v + 4, *cj = v + 7, *qj = v + 9;
    int const n[2] = {(int)v[12], (int)v[13]};
    double const mu2 = v[14];
    records++;
    /* what a brute force on the rounded r would say: another μ² often */
    double r[2], o[2];
    for (int k = 0; k < 2; k++) r[k] = (cj[k] + n[k] * box[k]) - ci[k];
    g_assert_cmpint(pw85_2d_contact_function(r, qi, qj, o), ==, PW85_SUCCESS);
    rounded_differs += o[0] != mu2;

    pw85_2d_index *ix = NULL;
    g_assert_cmpint(pw85_2d_index_create(box, &ix), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_index_insert(ix, 7, cj, qj), ==, PW85_SUCCESS);
    size_t ids[8], count = 0;
    int shifts[16];
    double ml[16];
    g_assert_cmpint(pw85_2d_index_within(ix, ci, qi, 8., PW85_INDEX_NO_ID, 8, ids, shifts,
                                         ml, &count), ==, PW85_SUCCESS);
    size_t at = count;
    for (size_t a = 0; a < MIN(count, (size_t)8); a++)
      if (shifts[2 * a] == n[0] && shifts[2 * a + 1] == n[1]) at = a;
    if (at == count)
      test_mismatch("record %d: within misses the image [%d %d]", records, n[0], n[1]);
    else if (ml[2 * at] != mu2)
      test_mismatch("record %d: within gives mu2 %a, exact configuration %a (rounded r: %a)",
                    records, ml[2 * at], mu2, o[0]);
    /* The decisions consider every image: only records whose other images
     * the bounding boxes separate (with a margin far above the rounding of
     * r, below 1e-6 here) are decided by the record's μ² alone. */
    gboolean alone = TRUE;
    for (int a = -2; a <= 2; a++)
      for (int b = -2; b <= 2; b++) {
        if (a == 0 && b == 0) continue;
        gboolean apart = FALSE;
        int const m[2] = {a, b};
        for (int k = 0; k < 2; k++) {
          double const reach = 1.001 * (sqrt(qi[2 * k]) + sqrt(qj[2 * k])) + 1e-6;
          apart = apart || fabs(r[k] + m[k] * box[k]) > reach;
        }
        alone = alone && apart;
      }
    if (alone && fabs(mu2 - 1.) > 4. * DBL_EPSILON) {
      int const want = mu2 < 1. ? -1 : 1;
      int any = 9, pair = 1, results[2] = {9, 9};
      size_t id = 0, np = 0, pids[4];
      int pshifts[4];
      g_assert_cmpint(pw85_2d_index_overlap_any(ix, ci, qi, PW85_INDEX_NO_ID, &any, &id), ==,
                      PW85_SUCCESS);
      g_assert_cmpint(pw85_2d_index_insert(ix, 2, ci, qi), ==, PW85_SUCCESS);
      g_assert_cmpint(pw85_2d_index_overlapping_pairs(ix, 1, 2, pids, pshifts, results, &np),
                      ==, PW85_SUCCESS);
      if (np > 0) pair = results[0];
      decided++;
      if (any != want || pair != want)
        test_mismatch("record %d: mu2 %a: overlap_any %d, overlapping_pairs %d, exact %d",
                      records, mu2, any, pair, want);
    }
    pw85_2d_index_destroy(ix);
  }
  g_test_message("%d records; the rounded r gives another mu2 in %d; %d decided", records,
                 rounded_differs, decided);
  g_assert_cmpint(records, >=, 200);
  g_assert_cmpint(rounded_differs, >, records / 4); /* the file tests what it is for */
  g_assert_cmpint(decided, >, records / 2);
  g_strfreev(lines);
  g_free(text);
}

/* ---- bad input --------------------------------------------------------- */

static void test_errors(void) {
  double const box[2] = {4., 3.}, c[2] = {1., 1.}, q[3] = {.25, 0., .25};
  double const nan2[2] = {NAN, 1.}, bad_q[3] = {1., 2., 1.};
  pw85_2d_index *ix = (pw85_2d_index *)&box, *keep = ix;

  /* create */
  double const zero[2] = {4., 0.}, neg[2] = {-1., 1.}, inf[2] = {1., INFINITY};
  g_assert_cmpint(pw85_2d_index_create(box, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_create(nan2, &ix), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_create(inf, &ix), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_create(zero, &ix), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_create(neg, &ix), ==, PW85_EINVAL);
  g_assert_true(ix == keep);
  pw85_2d_index_destroy(NULL);
  g_assert_cmpint(pw85_2d_index_create(box, &ix), ==, PW85_SUCCESS);

  /* insert, update: every status, the index unchanged */
  size_t n = 99;
  g_assert_cmpint(pw85_2d_index_insert(NULL, 0, c, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, NULL, q), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, c, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, nan2, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, c, bad_q), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_2d_index_insert(ix, PW85_INDEX_MAX_ID + 1, c, q), ==, PW85_EINVAL);
  /* the side rule, 2·√Q00·(1 + 2⁻²⁰) < L0 = 4: √Q00 = 2 (an ellipse
   * that touches its own image) is refused, √Q00 = 1.98 accepted */
  double const wide[3] = {4., 0., .25};
  double const fits[3] = {1.98 * 1.98, 0., .25};
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, c, wide), ==, PW85_EINVAL);
  double const far[2] = {1., 0x1p29 * 3. * 1.5};
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, far, q), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 0);
  g_assert_cmpint(pw85_2d_index_count(NULL, &n), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_count(ix, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, c, fits), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_insert(ix, 0, c, q), ==, PW85_EINVAL); /* in use */
  g_assert_cmpint(pw85_2d_index_update(ix, 1, c, q), ==, PW85_EINVAL); /* not stored */
  g_assert_cmpint(pw85_2d_index_update(ix, 0, c, wide), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_update(ix, 0, nan2, q), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_update(ix, 0, c, bad_q), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_2d_index_update(NULL, 0, c, q), ==, PW85_EFAULT);
  double cg[2] = {7., 7.}, qg[3] = {7., 7., 7.};
  g_assert_cmpint(pw85_2d_index_get(ix, 0, cg, qg), ==, PW85_SUCCESS);
  g_assert_true(memcmp(qg, fits, sizeof fits) == 0); /* updates failed */
  cg[0] = qg[0] = 7.;
  g_assert_cmpint(pw85_2d_index_get(ix, 1, cg, qg), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_get(ix, 0, NULL, qg), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_get(NULL, 0, cg, qg), ==, PW85_EFAULT);
  g_assert_true(cg[0] == 7. && qg[0] == 7.);
  g_assert_cmpint(pw85_2d_index_remove(ix, 1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_remove(NULL, 0), ==, PW85_EFAULT);

  /* insert_many: all or none */
  size_t const ids[3] = {5, 6, 5};
  double const cs[6] = {1., 1., 2., 2., 3., 1.}, qs[9] = {.1, 0., .1, .1, 0., .1, .1, 0., .1};
  g_assert_cmpint(pw85_2d_index_insert_many(ix, 3, ids, cs, qs), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_insert_many(ix, 3, NULL, cs, qs), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert_many(NULL, 3, ids, cs, qs), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert_many_threads(ix, 2, ids, cs, qs, 0), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_insert_many_threads(ix, 2, ids, NULL, qs, 2), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_insert_many(ix, 0, NULL, NULL, NULL), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_count(ix, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);

  /* overlap_any: outputs untouched on error */
  int result = 42;
  size_t id = 42;
  g_assert_cmpint(pw85_2d_index_overlap_any(NULL, c, q, PW85_INDEX_NO_ID, &result, &id),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, NULL, &id), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, &result, NULL),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, nan2, q, PW85_INDEX_NO_ID, &result, &id),
                  ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, c, bad_q, PW85_INDEX_NO_ID, &result, &id),
                  ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, far, q, PW85_INDEX_NO_ID, &result, &id),
                  ==, PW85_EINVAL);
  g_assert_cmpint(result, ==, 42);
  g_assert_cmpuint(id, ==, 42);
  g_assert_cmpint(pw85_2d_index_overlap_any(ix, c, q, PW85_INDEX_NO_ID, &result, &id),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  g_assert_cmpuint(id, ==, 0);

  /* overlap_any_batch: the call's statuses, then an item's */
  int results[2] = {42, 42}, status[2] = {42, 42};
  size_t found[2] = {42, 42};
  double const c2[4] = {1., 1., NAN, 1.};
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 2, c2, 1, q, 0, NULL, results, found,
                                                  status, 1), ==, PW85_EINVAL);
  g_assert_cmpint(status[0], ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 2, c2, 2, q, 2, NULL, results, found,
                                                  NULL, 1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 2, c2, 2, q, 0, NULL, results, found,
                                                  NULL, -1), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(NULL, 2, c2, 2, q, 0, NULL, results,
                                                  found, NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 2, c2, 2, q, 0, NULL, NULL, found,
                                                  NULL, 1), ==, PW85_EFAULT);
  g_assert_cmpint(results[0], ==, 42);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 2, c2, 2, q, 0, NULL, results, found,
                                                  status, 1), ==, PW85_EDOM);
  g_assert_cmpint(status[0], ==, PW85_SUCCESS);
  g_assert_cmpint(status[1], ==, PW85_EDOM);
  g_assert_cmpint(results[0], ==, -1);
  g_assert_cmpint(results[1], ==, 42);
  g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, 0, NULL, 0, NULL, 0, NULL, NULL,
                                                  NULL, NULL, 1), ==, PW85_SUCCESS);

  /* within */
  size_t count = 42, wid[1] = {42};
  int shifts[2] = {42, 42};
  double ml[2] = {42., 42.};
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, NAN, PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, 0., PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, -1., PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 1, NULL, shifts,
                                       ml, &count), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, 1., PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, NULL), ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_within(ix, nan2, q, 1., PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_within(ix, c, bad_q, 1., PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_ENOTPOSDEF);
  /* a reach of √t·(h + h') = 1e7·2.5 spans more than 2²⁰ sides of 4 */
  g_assert_cmpint(pw85_2d_index_within(ix, c, q, 1e14, PW85_INDEX_NO_ID, 1, wid, shifts,
                                       ml, &count), ==, PW85_ERANGE);
  g_assert_cmpuint(count, ==, 42);
  g_assert_true(wid[0] == 42 && shifts[0] == 42 && ml[0] == 42.);

  /* the all-pairs queries */
  int res[1] = {42};
  g_assert_cmpint(pw85_2d_index_overlapping_pairs(ix, 0, 1, wid, shifts, res, &count),
                  ==, PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_overlapping_pairs(ix, 1, 1, wid, NULL, res, &count), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlapping_pairs(NULL, 1, 0, NULL, NULL, NULL, &count),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_overlapping_pairs(ix, 1, 0, NULL, NULL, NULL, NULL), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, INFINITY, 1, 1, wid, shifts, ml, &count),
                  ==, PW85_EDOM);
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, 0., 1, 1, wid, shifts, ml, &count), ==,
                  PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, 1., 0, 1, wid, shifts, ml, &count), ==,
                  PW85_EINVAL);
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, 1e14, 1, 1, wid, shifts, ml, &count),
                  ==, PW85_ERANGE);
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, 1., 1, 1, NULL, shifts, ml, &count), ==,
                  PW85_EFAULT);
  g_assert_cmpuint(count, ==, 42);
  g_assert_true(wid[0] == 42 && shifts[0] == 42 && ml[0] == 42. && res[0] == 42);
  pw85_2d_index_destroy(ix);

  /* A candidate whose reach spans more than 2^20 images of the rectangle
   * (a needle of half-length 2^19 in a unit square): PW85_ERANGE, as the
   * header says; half-length 2^17 is decided (−1). */
  pw85_2d_index *unit = NULL;
  double const unit_box[2] = {1., 1.}, origin[2] = {0., 0.},
               disc[3] = {0.01, 0., 0.01}, needle_centre[2] = {0.5, 0.};
  g_assert_cmpint(pw85_2d_index_create(unit_box, &unit), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_insert(unit, 0, origin, disc), ==, PW85_SUCCESS);
  double needle[3] = {0x1p34, 0., 0.01};
  g_assert_cmpint(pw85_2d_index_overlap_any(unit, needle_centre, needle, PW85_INDEX_NO_ID,
                                            &result, &id), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, -1);
  needle[0] = 0x1p38;
  g_assert_cmpint(pw85_2d_index_overlap_any(unit, needle_centre, needle, PW85_INDEX_NO_ID,
                                            &result, &id), ==, PW85_ERANGE);
  pw85_2d_index_destroy(unit);
}

/* An ellipse and its own images in the narrowest rectangle: μ² of each
 * image pair with n lexicographically positive, as pw85_2d_contact_function
 * gives it (the rectangle 2.5 × 1.25 holds an ellipse of half-widths
 * √Q00 = 1.2 and √Q11 = 0.6). */
static void test_own_images(void) {
  double const box[2] = {2.5, 1.25}, c[2] = {0.25, -3.5}, q[3] = {1.44, 0.25, 0.36};
  pw85_2d_index *ix = NULL;
  g_assert_cmpint(pw85_2d_index_create(box, &ix), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_index_insert(ix, 3, c, q), ==, PW85_SUCCESS);
  size_t count = 0, ids[64];
  int shifts[128];
  double ml[128];
  double const t = 16.;
  g_assert_cmpint(pw85_2d_index_pairs_within(ix, t, 1, 64, ids, shifts, ml, &count), ==,
                  PW85_SUCCESS);
  g_assert_cmpuint(count, <=, 64);
  size_t k = 0;
  for (int a = -8; a <= 8; a++)
    for (int b = -8; b <= 8; b++) {
      if (!(a > 0 || (a == 0 && b > 0))) continue;
      double const r[2] = {a * box[0], b * box[1]};
      double o[2];
      g_assert_cmpint(pw85_2d_contact_function(r, q, q, o), ==, PW85_SUCCESS);
      if (!(o[0] < t)) continue;
      g_assert_cmpuint(k, <, count);
      g_assert_cmpuint(ids[2 * k], ==, 3);
      g_assert_cmpuint(ids[2 * k + 1], ==, 3);
      g_assert_cmpint(shifts[2 * k], ==, a);
      g_assert_cmpint(shifts[2 * k + 1], ==, b);
      g_assert_true(ml[2 * k] == o[0] && ml[2 * k + 1] == o[1]);
      k++;
    }
  g_assert_cmpuint(k, ==, count);
  g_assert_cmpuint(count, >, 4);
  pw85_2d_index_destroy(ix);
}

/* Thread counts that the smaller configurations above never reach (a
 * thread per 4096 ellipses): 40000 ellipses in a periodic rectangle,
 * insert_many_threads on 1, 3 and 8 threads (as many hash tables in its
 * bulk path), then every all-pairs query, and overlap_any_batch of 10000
 * candidates, on 1, 2, 3 and 8 threads, bit for bit. (Their agreement
 * with the brute force: test_config().) */
static void test_threads_large(void) {
  Config const cf = {"large", 1, 40000, .4, 4., 0};
  int const n = small_run() ? 12300 : cf.n; /* 12300: 3 threads still */
  GRand *rng = g_rand_new_with_seed(0x2d7a3eu);
  double const mean_area = G_PI * .75 * .75 / (1. + .5 * (cf.aspect - 1.));
  double const side = grid(sqrt(n * mean_area / cf.fraction)) + 0x1p-12;
  double const box[2] = {side, .8 * side}, span[2] = {side, .8 * side};
  size_t *ids = g_new(size_t, n);
  double *c = g_new(double, 2 * n), *q = g_new(double, 3 * n);
  for (int i = 0; i < n; i++) ids[i] = (size_t)(n - 1 - i);
  for (int i = 0; i < n; i++) random_ellipse(rng, &cf, c + 2 * i, q + 3 * i, span);
  Answer ref[2];
  int const inserts[] = {1, 3, 8};
  for (size_t a = 0; a < G_N_ELEMENTS(inserts); a++) {
    pw85_2d_index *ix = NULL;
    g_assert_cmpint(pw85_2d_index_create(box, &ix), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_2d_index_insert_many_threads(ix, (size_t)n, ids, c, q, inserts[a]),
                    ==, PW85_SUCCESS);
    for (int mode = 0; mode < 2; mode++) {
      gboolean const within = mode == 1;
      int const threads[] = {1, 2, 3, 8};
      for (size_t k = 0; k < G_N_ELEMENTS(threads); k++) {
        Answer more = all_pairs(ix, within, within ? 2.25 : 1., threads[k]);
        if (a == 0 && k == 0) {
          ref[mode] = more;
          g_assert_cmpuint(more.count, >, (size_t)n / 2); /* pairs to compare */
          continue;
        }
        if (!same_answer(&ref[mode], &more))
          test_mismatch("%s after insert_many on %d threads: %d threads differ from 1",
                        within ? "pairs_within" : "overlapping_pairs", inserts[a],
                        threads[k]);
        answer_free(&more);
      }
    }
    if (a == 0) { /* overlap_any_batch: every 4th ellipse grown 1.5 times */
      int const m = n / 4;
      double *qs = g_new(double, 3 * (size_t)m);
      size_t *exclude = g_new(size_t, m), *hit = g_new(size_t, 2 * (size_t)m);
      int *res = g_new(int, 2 * (size_t)m), *st = g_new(int, 2 * (size_t)m);
      for (int k = 0; k < m; k++) {
        for (int j = 0; j < 3; j++) qs[3 * k + j] = 2.25 * q[3 * (4 * k) + j];
        exclude[k] = ids[4 * k];
      }
      int const batch_threads[] = {1, 2, 3, 8};
      for (size_t b = 0; b < G_N_ELEMENTS(batch_threads); b++) {
        size_t const o = b == 0 ? 0 : (size_t)m;
        g_assert_cmpint(pw85_2d_index_overlap_any_batch(ix, (size_t)m, c, 8, qs, 3, exclude,
                                                        res + o, hit + o, st + o,
                                                        batch_threads[b]),
                        ==, PW85_SUCCESS);
        if (b == 0) {
          int overlapping = 0;
          for (int k = 0; k < m; k++) overlapping += res[k] < 0;
          g_assert_cmpint(overlapping, >, m / 4); /* answers of both kinds */
          g_assert_cmpint(overlapping, <, m);
        } else if (memcmp(res, res + m, (size_t)m * sizeof(int)) != 0 ||
                   memcmp(st, st + m, (size_t)m * sizeof(int)) != 0 ||
                   memcmp(hit, hit + m, (size_t)m * sizeof(size_t)) != 0) {
          test_mismatch("overlap_any_batch on %d threads differs from 1", batch_threads[b]);
        }
      }
      g_free(qs), g_free(exclude), g_free(hit), g_free(res), g_free(st);
    }
    pw85_2d_index_destroy(ix);
  }
  answer_free(&ref[0]), answer_free(&ref[1]);
  g_free(ids), g_free(c), g_free(q);
  g_rand_free(rng);
}

static Config const configs[] = {
    {"open-sparse", 0, 300, .2, 3., 0},
    {"open-dense", 0, 300, .6, 1.5, 0},
    {"open-bulk", 0, 1500, .3, 4., 0},
    {"periodic-sparse", 1, 300, .2, 3., 0},
    {"periodic-dense", 1, 300, .6, 1.5, 0},
    {"periodic-needles", 1, 200, .3, 50., 0},
    {"periodic-bulk", 1, 1500, .3, 4., 0},
    {"periodic-tight", 1, 12, 1., 2., 1},
};

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  for (size_t k = 0; k < G_N_ELEMENTS(configs); k++) {
    char *path = g_strdup_printf("/pw85/2d-index/brute/%s", configs[k].name);
    g_test_add_data_func(path, &configs[k], test_config);
    g_free(path);
  }
  g_test_add_func("/pw85/2d-index/threads-large", test_threads_large);
  g_test_add_func("/pw85/2d-index/own-images", test_own_images);
  g_test_add_func("/pw85/2d-index/errors", test_errors);
  g_test_add_func("/pw85/2d-index/exact-images", test_exact_images);
  return g_test_run();
}
