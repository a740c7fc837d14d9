/* SPDX-License-Identifier: BSD-3-Clause */
/* The indexes (pw85_index.h, pw85_2d_index.h) at the ends of their
 * domain: periodic sides up to 2⁹⁹², open-domain centres up to 2¹⁰²¹,
 * and every query on ellipsoids placed there. Beyond these bounds, sums
 * of centres and sides overflowed: an all-pairs query in an open domain
 * with centres ±DBL_MAX read outside its grid (AddressSanitizer: a
 * heap-buffer-overflow), and boxes of sides 2⁹⁹⁴ to DBL_MAX, accepted,
 * answered PW85_ERANGE with a single ellipsoid. Also the all-pairs
 * snapshot's grid at the end of its range (grid-cells). The expected
 * answers are those of the geometry: unit disks or balls whose centres
 * differ by exactly 0 (overlap, μ² = 0) or by at least 2⁹⁹² (far apart).
 */
#include <float.h>
#include <glib.h>
#include <math.h>
#include <string.h>

#include "pw85.h"
#include "pw85_2d_index.h"
#include "pw85_index.h"

#define MAX_SIDE 0x1p992
#define MAX_CENTRE 0x1p1021

/* One index of either dimension (dim 2 or 3), through one set of calls. */
typedef struct {
  int dim;
  pw85_index *i3;
  pw85_2d_index *i2;
} Index;

static int create(int dim, double const *box, Index *x) {
  x->dim = dim;
  x->i3 = NULL;
  x->i2 = NULL;
  return dim == 3 ? pw85_index_create(box, &x->i3)
                  : pw85_2d_index_create(box, &x->i2);
}

static void destroy(Index *x) {
  pw85_index_destroy(x->i3);
  pw85_2d_index_destroy(x->i2);
}

static double const unit3[6] = {1., 0., 0., 1., 0., 1.};
static double const unit2[3] = {1., 0., 1.};

static int insert(Index *x, size_t id, double const *c) {
  return x->dim == 3 ? pw85_index_insert(x->i3, id, c, unit3)
                     : pw85_2d_index_insert(x->i2, id, c, unit2);
}

static int overlap_any(Index *x, double const *c, int *result, size_t *id) {
  return x->dim == 3 ? pw85_index_overlap_any(x->i3, c, unit3, PW85_INDEX_NO_ID,
                                              result, id)
                     : pw85_2d_index_overlap_any(x->i2, c, unit2,
                                                 PW85_INDEX_NO_ID, result, id);
}

static int within(Index *x, double const *c, double t, size_t cap, size_t *ids,
                  int *shifts, double *ml, size_t *count) {
  return x->dim == 3
             ? pw85_index_within(x->i3, c, unit3, t, PW85_INDEX_NO_ID, cap, ids,
                                 shifts, ml, count)
             : pw85_2d_index_within(x->i2, c, unit2, t, PW85_INDEX_NO_ID, cap,
                                    ids, shifts, ml, count);
}

static int pairs(Index *x, int threads, size_t cap, size_t *ids, int *shifts,
                 int *results, size_t *count) {
  return x->dim == 3 ? pw85_index_overlapping_pairs(x->i3, threads, cap, ids,
                                                    shifts, results, count)
                     : pw85_2d_index_overlapping_pairs(x->i2, threads, cap, ids,
                                                       shifts, results, count);
}

static int pairs_within(Index *x, double t, size_t *count) {
  return x->dim == 3
             ? pw85_index_pairs_within(x->i3, t, 2, 0, NULL, NULL, NULL, count)
             : pw85_2d_index_pairs_within(x->i2, t, 2, 0, NULL, NULL, NULL,
                                          count);
}

static int energy(Index *x, double *e) {
  return x->dim == 3 ? pw85_index_energy(x->i3, PW85_ENERGY_OVERLAP, 1., NULL,
                                         NULL, 2, 2, e, NULL, NULL)
                     : pw85_2d_index_energy(x->i2, PW85_ENERGY_OVERLAP, 1.,
                                            NULL, NULL, 2, 2, e, NULL, NULL);
}

/* A centre (x0, 0[, 0]). */
static void at(double x0, double *c) { c[0] = x0, c[1] = c[2] = 0.; }

/* create: sides up to 2⁹⁹², EINVAL above (the handle untouched). */
static void test_sides(gconstpointer data) {
  int const dim = GPOINTER_TO_INT(data);
  double const good[] = {MAX_SIDE, 1.0, DBL_MIN};
  double const bad[] = {nextafter(MAX_SIDE, HUGE_VAL), 0x1p994, 1e300, DBL_MAX};
  for (size_t i = 0; i < G_N_ELEMENTS(good); ++i) {
    double box[3] = {1., 1., 1.};
    box[dim - 1] = good[i];
    Index x;
    g_assert_cmpint(create(dim, box, &x), ==, PW85_SUCCESS);
    destroy(&x);
  }
  for (size_t i = 0; i < G_N_ELEMENTS(bad); ++i)
    for (int k = 0; k < dim; ++k) {
      double box[3] = {1., 1., 1.};
      box[k] = bad[i];
      pw85_index *sentinel3 = (pw85_index *)&box;
      pw85_2d_index *sentinel2 = (pw85_2d_index *)&box;
      pw85_index *i3 = sentinel3;
      pw85_2d_index *i2 = sentinel2;
      if (dim == 3) {
        g_assert_cmpint(pw85_index_create(box, &i3), ==, PW85_EINVAL);
        g_assert_true(i3 == sentinel3);
      } else {
        g_assert_cmpint(pw85_2d_index_create(box, &i2), ==, PW85_EINVAL);
        g_assert_true(i2 == sentinel2);
      }
    }
}

/* An open domain: centres up to 2¹⁰²¹, EINVAL beyond (stored ones and
 * candidates), nothing stored on error. */
static void test_open_centres(gconstpointer data) {
  int const dim = GPOINTER_TO_INT(data);
  Index x;
  g_assert_cmpint(create(dim, NULL, &x), ==, PW85_SUCCESS);
  double c[3];
  double const bad[] = {nextafter(MAX_CENTRE, HUGE_VAL), DBL_MAX};
  for (size_t i = 0; i < G_N_ELEMENTS(bad); ++i)
    for (int s = -1; s <= 1; s += 2) {
      at(s * bad[i], c);
      g_assert_cmpint(insert(&x, 0, c), ==, PW85_EINVAL);
      int result = 7;
      size_t id = 7, count = 7;
      g_assert_cmpint(overlap_any(&x, c, &result, &id), ==, PW85_EINVAL);
      g_assert_cmpint(result, ==, 7);
      g_assert_cmpint(within(&x, c, 2., 0, NULL, NULL, NULL, &count), ==,
                      PW85_EINVAL);
      g_assert_cmpuint(count, ==, 7);
    }
  size_t n = 7;
  g_assert_cmpint(pairs(&x, 1, 0, NULL, NULL, NULL, &n), ==, PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 0);
  at(MAX_CENTRE, c);
  g_assert_cmpint(insert(&x, 0, c), ==, PW85_SUCCESS);
  at(-MAX_CENTRE, c);
  g_assert_cmpint(insert(&x, 1, c), ==, PW85_SUCCESS);
  destroy(&x);
}

/* Every query on unit shapes at ±2¹⁰²¹ in an open domain, and at the same
 * centres in a periodic box of sides 2⁹⁹², where 2¹⁰²¹ = 2²⁹·L: there the
 * two centres differ by 2³⁰ sides, and the image n = (2³⁰, 0[, 0]) of the
 * second coincides with the first. */
static void test_extreme_queries(gconstpointer data) {
  int const dim = GPOINTER_TO_INT(data);
  for (int periodic = 0; periodic <= 1; ++periodic) {
    double const box[3] = {MAX_SIDE, MAX_SIDE, MAX_SIDE};
    Index x;
    g_assert_cmpint(create(dim, periodic ? box : NULL, &x), ==, PW85_SUCCESS);
    double c0[3], c1[3];
    at(MAX_CENTRE, c0);
    at(-MAX_CENTRE, c1);
    g_assert_cmpint(insert(&x, 0, c0), ==, PW85_SUCCESS);
    g_assert_cmpint(insert(&x, 1, c1), ==, PW85_SUCCESS);
    for (int threads = 1; threads <= 2; ++threads) {
      size_t ids[4] = {9, 9, 9, 9}, n = 9;
      int shifts[6] = {9, 9, 9, 9, 9, 9}, results[2] = {9, 9};
      g_assert_cmpint(pairs(&x, threads, 2, ids, shifts, results, &n), ==,
                      PW85_SUCCESS);
      g_assert_cmpuint(n, ==, periodic ? 1 : 0);
      if (periodic) {
        g_assert_cmpuint(ids[0], ==, 0);
        g_assert_cmpuint(ids[1], ==, 1);
        g_assert_cmpint(shifts[0], ==, 1 << 30); /* c1 + 2³⁰·L − c0 = 0 */
        for (int k = 1; k < dim; ++k) g_assert_cmpint(shifts[k], ==, 0);
        g_assert_cmpint(results[0], ==, -1);
      }
    }
    size_t n = 9;
    g_assert_cmpint(pairs_within(&x, 4., &n), ==, PW85_SUCCESS);
    g_assert_cmpuint(n, ==, periodic ? 1 : 0);
    double e = -1.;
    g_assert_cmpint(energy(&x, &e), ==, PW85_SUCCESS);
    /* ε·(1 − μ)² per pair: μ = 0 for the coincident images. */
    g_assert_cmpfloat(e, ==, periodic ? 1. : 0.);
    /* A candidate on each stored centre, and one midway (the origin),
     * 2¹⁰²¹ from both in an open domain, a multiple of L from both in the
     * box (so on their images there too). */
    double const cands[3] = {MAX_CENTRE, -MAX_CENTRE, 0.};
    for (int i = 0; i < 3; ++i) {
      double c[3];
      at(cands[i], c);
      int result = 9;
      size_t id = 9, count = 9, wids[2] = {9, 9};
      int wshifts[6];
      double ml[4] = {-1., -1., -1., -1.};
      g_assert_cmpint(overlap_any(&x, c, &result, &id), ==, PW85_SUCCESS);
      gboolean const meets = periodic || i < 2;
      g_assert_cmpint(result, ==, meets ? -1 : 1);
      g_assert_cmpint(within(&x, c, 4., 2, wids, wshifts, ml, &count), ==,
                      PW85_SUCCESS);
      g_assert_cmpuint(count, ==, periodic ? 2 : (i < 2 ? 1 : 0));
      for (size_t k = 0; k < count; ++k) g_assert_cmpfloat(ml[2 * k], ==, 0.);
    }
    destroy(&x);
  }
}

/* The all-pairs snapshot's grid of a level: in an open domain, as many
 * cells per axis as the spread of its centres holds (at most 2²⁰), then
 * the widest axis halved until the cells are no more than 2·count + 64.
 * Two unit balls (cells of side 2) whose centres differ by 2·(n_k − 1)
 * start at n = (1039794, 488814, 724987) and end at (4, 4, 3): 48 cells,
 * which the product of doubles, divided and multiplied as the axes were
 * halved, counted 47 (truncated), and the last cell's run was read past
 * the offsets (AddressSanitizer: heap-buffer-overflow; a SIGSEGV in a
 * sweep of configurations over 2³⁰ of sizes). Far apart: no pair. */
static void test_grid_cells(void) {
  pw85_index *ix;
  g_assert_cmpint(pw85_index_create(NULL, &ix), ==, PW85_SUCCESS);
  double const c0[3] = {0., 0., 0.};
  double const c1[3] = {2. * 1039793., 2. * 488813., 2. * 724986.};
  g_assert_cmpint(pw85_index_insert(ix, 0, c0, unit3), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_index_insert(ix, 1, c1, unit3), ==, PW85_SUCCESS);
  for (int threads = 1; threads <= 2; ++threads) {
    size_t n = 9;
    g_assert_cmpint(
        pw85_index_overlapping_pairs(ix, threads, 0, NULL, NULL, NULL, &n), ==,
        PW85_SUCCESS);
    g_assert_cmpuint(n, ==, 0);
    g_assert_cmpint(
        pw85_index_pairs_within(ix, 4., threads, 0, NULL, NULL, NULL, &n), ==,
        PW85_SUCCESS);
    g_assert_cmpuint(n, ==, 0);
  }
  /* A third ball on the second: one pair, μ² = 0 (it changes the count,
   * and so the grid: the first query above is the regression). */
  g_assert_cmpint(pw85_index_insert(ix, 2, c1, unit3), ==, PW85_SUCCESS);
  size_t ids[2] = {9, 9}, n = 9;
  int shifts[3] = {9, 9, 9}, results[1] = {9};
  g_assert_cmpint(
      pw85_index_overlapping_pairs(ix, 1, 1, ids, shifts, results, &n), ==,
      PW85_SUCCESS);
  g_assert_cmpuint(n, ==, 1);
  g_assert_cmpuint(ids[0], ==, 1);
  g_assert_cmpuint(ids[1], ==, 2);
  g_assert_cmpint(results[0], ==, -1);
  pw85_index_destroy(ix);
}

int main(int argc, char *argv[]) {
  g_test_init(&argc, &argv, NULL);
  for (int dim = 2; dim <= 3; ++dim) {
    char name[64];
    g_snprintf(name, sizeof name, "/pw85/index-range/%dd/sides", dim);
    g_test_add_data_func(name, GINT_TO_POINTER(dim), test_sides);
    g_snprintf(name, sizeof name, "/pw85/index-range/%dd/open-centres", dim);
    g_test_add_data_func(name, GINT_TO_POINTER(dim), test_open_centres);
    g_snprintf(name, sizeof name, "/pw85/index-range/%dd/queries", dim);
    g_test_add_data_func(name, GINT_TO_POINTER(dim), test_extreme_queries);
  }
  g_test_add_func("/pw85/index-range/grid-cells", test_grid_cells);
  return g_test_run();
}
