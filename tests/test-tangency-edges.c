/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_overlap() and pw85_2d_overlap() at the edges of the tangency band:
 * 0 exactly where the exact μ² lies within 4 ulps of 1 (|μ² − 1| ≤
 * 4·DBL_EPSILON, pw85.h), else the sign of μ² − 1, on pairs whose exact
 * μ² lies just inside or just beyond an edge, where the correctly rounded
 * μ² is the edge 1 ± 4·DBL_EPSILON itself
 * (data/pw85_tangency_edges.txt, data/gen_tangency_edges.py: μ² − 1
 * certified in rationals, never computed by pw85). Both argument orders,
 * and the batch calls. Before the fix, the "beyond" pairs were answered 0
 * (a held-out near-tangent pair, μ² − 1 = 4.49·DBL_EPSILON); without a
 * slack, "upper-edge" pairs (μ² exactly 1 + 4·DBL_EPSILON) were answered
 * 1 where f's rounding in double-double lifted it above the edge. */
#include <float.h>
#include <glib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pw85.h"
#include "pw85_2d.h"

enum { MAX_PAIRS = 512 };

typedef struct {
  int dim;
  char window[16];
  double r[3], q1[6], q2[6];
  double m1; /* μ² − 1, exact, rounded once */
} Pair;

static Pair pairs[MAX_PAIRS];
static int n_pairs;

static void load(void) {
  char const *path = g_getenv("PW85_TANGENCY_EDGES");
  if (path == NULL)
    g_error("PW85_TANGENCY_EDGES is not set (meson test sets it)");
  FILE *f = fopen(path, "r");
  if (f == NULL) g_error("cannot open %s", path);
  char line[4096];
  while (fgets(line, sizeof line, f) != NULL) {
    if (line[0] == '#') continue;
    g_assert_cmpint(n_pairs, <, MAX_PAIRS);
    Pair *p = &pairs[n_pairs++];
    char *tok = strtok(line, " \n");
    p->dim = atoi(tok);
    g_assert_true(p->dim == 2 || p->dim == 3);
    g_strlcpy(p->window, strtok(NULL, " \n"), sizeof p->window);
    int const sym = p->dim * (p->dim + 1) / 2;
    double *dst[4] = {p->r, p->q1, p->q2, &p->m1};
    int const len[4] = {p->dim, sym, sym, 1};
    for (int a = 0; a < 4; a++)
      for (int k = 0; k < len[a]; k++) {
        tok = strtok(NULL, " \n");
        if (tok == NULL) g_error("%s: short line %d", path, n_pairs);
        dst[a][k] = strtod(tok, NULL);
      }
  }
  fclose(f);
}

/* The answer pw85.h promises for the exact μ² − 1. */
static int expected(double m1) {
  if (fabs(m1) <= 4. * DBL_EPSILON) return 0;
  return m1 < 0. ? -1 : 1;
}

static int overlap(Pair const *p, int swapped) {
  double r[3];
  for (int k = 0; k < p->dim; k++) r[k] = swapped ? -p->r[k] : p->r[k];
  double const *a = swapped ? p->q2 : p->q1, *b = swapped ? p->q1 : p->q2;
  int result = 42;
  int const status = p->dim == 2 ? pw85_2d_overlap(r, a, b, &result)
                                 : pw85_overlap(r, a, b, &result);
  g_assert_cmpint(status, ==, PW85_SUCCESS);
  return result;
}

static void test_edges(gconstpointer data) {
  int const dim = GPOINTER_TO_INT(data);
  /* Each window must be represented, or the test proves nothing about it
   * (upper-edge: the exact μ² is 1 + 4·DBL_EPSILON itself). */
  enum { WINDOWS = 5 };
  char const *windows[WINDOWS] = {"upper-beyond", "upper-inside",
                                  "lower-inside", "lower-beyond",
                                  "upper-edge"};
  int seen[WINDOWS] = {0}, wrong = 0;
  for (int i = 0; i < n_pairs; i++) {
    Pair const *p = &pairs[i];
    if (p->dim != dim) continue;
    for (int w = 0; w < WINDOWS; w++)
      seen[w] += strcmp(p->window, windows[w]) == 0;
    /* the window's name agrees with μ² − 1 (the file is consistent) */
    gboolean const beyond = strstr(p->window, "beyond") != NULL;
    g_assert_true(beyond == (expected(p->m1) != 0));
    int const want = expected(p->m1);
    for (int swapped = 0; swapped < 2; swapped++) {
      int const got = overlap(p, swapped);
      if (got != want) {
        wrong++;
        g_test_message("%dD pair %d (%s%s): overlap %d, expected %d; "
                       "mu^2 - 1 = %a = %.4g DBL_EPSILON",
                       dim, i, p->window, swapped ? ", swapped" : "", got,
                       want, p->m1, p->m1 / DBL_EPSILON);
      }
    }
  }
  for (int w = 0; w < WINDOWS; w++) {
    g_test_message("%dD %s: %d pairs", dim, windows[w], seen[w]);
    g_assert_cmpint(seen[w], >, 0);
  }
  g_assert_cmpint(wrong, ==, 0);
}

/* The batch calls decide as the single-pair calls, on 2 threads. */
static void test_batch(gconstpointer data) {
  int const dim = GPOINTER_TO_INT(data);
  int const sym = dim * (dim + 1) / 2;
  size_t n = 0;
  double *r = g_new(double, 3 * MAX_PAIRS), *q1 = g_new(double, 6 * MAX_PAIRS),
         *q2 = g_new(double, 6 * MAX_PAIRS);
  int *want = g_new(int, MAX_PAIRS), *got = g_new(int, MAX_PAIRS),
      *statuses = g_new(int, MAX_PAIRS);
  for (int i = 0; i < n_pairs; i++) {
    Pair const *p = &pairs[i];
    if (p->dim != dim) continue;
    memcpy(r + dim * n, p->r, sizeof(double) * (size_t)dim);
    memcpy(q1 + sym * n, p->q1, sizeof(double) * (size_t)sym);
    memcpy(q2 + sym * n, p->q2, sizeof(double) * (size_t)sym);
    want[n++] = expected(p->m1);
  }
  g_assert_cmpuint(n, >, 0);
  int const status =
      dim == 2 ? pw85_2d_overlap_batch(n, r, (size_t)dim, q1, (size_t)sym, q2,
                                       (size_t)sym, got, statuses, 2)
               : pw85_overlap_batch(n, r, (size_t)dim, q1, (size_t)sym, q2,
                                    (size_t)sym, got, statuses, 2);
  g_assert_cmpint(status, ==, PW85_SUCCESS);
  for (size_t k = 0; k < n; k++) {
    g_assert_cmpint(statuses[k], ==, PW85_SUCCESS);
    g_assert_cmpint(got[k], ==, want[k]);
  }
  g_free(r), g_free(q1), g_free(q2), g_free(want), g_free(got),
      g_free(statuses);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  load();
  g_test_add_data_func("/pw85/tangency-edges/3d", GINT_TO_POINTER(3),
                       test_edges);
  g_test_add_data_func("/pw85/tangency-edges/2d", GINT_TO_POINTER(2),
                       test_edges);
  g_test_add_data_func("/pw85/tangency-edges/3d-batch", GINT_TO_POINTER(3),
                       test_batch);
  g_test_add_data_func("/pw85/tangency-edges/2d-batch", GINT_TO_POINTER(2),
                       test_batch);
  return g_test_run();
}
