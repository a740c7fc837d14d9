/* SPDX-License-Identifier: BSD-3-Clause */
/* Every function is reentrant: 8 threads replaying the same pairs get
 * results bit-identical to a single-threaded run. */
#include <pw85.h>
#include <string.h>

#include "refdata.h"
#include "testutil.h"

#define NUM_THREADS 8

static GeneralPairs pairs;

typedef struct {
  double *mu2_lambda; /* [count][2] */
  int *overlap;       /* [count] */
  double *f;          /* [count] */
} Results;

static void compute(Results *res) {
  for (size_t n = 0; n < pairs.count; n++) {
    double const *r = pairs.r12 + 3 * n;
    double const *q1 = pairs.q1 + 6 * n, *q2 = pairs.q2 + 6 * n;
    g_assert_cmpint(pw85_contact_function(r, q1, q2, res->mu2_lambda + 2 * n),
                    ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_overlap(r, q1, q2, res->overlap + n), ==,
                    PW85_SUCCESS);
    double params[15];
    memcpy(params, r, 3 * sizeof(double));
    memcpy(params + 3, q1, 6 * sizeof(double));
    memcpy(params + 9, q2, 6 * sizeof(double));
    res->f[n] = pw85_f_neg(0.25, params);
  }
}

static void results_init(Results *res) {
  res->mu2_lambda = g_new(double, 2 * pairs.count);
  res->overlap = g_new(int, pairs.count);
  res->f = g_new(double, pairs.count);
}

static void results_clear(Results *res) {
  g_free(res->mu2_lambda);
  g_free(res->overlap);
  g_free(res->f);
}

static gpointer worker(gpointer data) {
  compute(data);
  return NULL;
}

static void test_threads(void) {
  Results serial, parallel[NUM_THREADS];
  results_init(&serial);
  compute(&serial);
  GThread *threads[NUM_THREADS];
  for (int t = 0; t < NUM_THREADS; t++) {
    results_init(&parallel[t]);
    threads[t] = g_thread_new("pw85", worker, &parallel[t]);
  }
  for (int t = 0; t < NUM_THREADS; t++) {
    g_thread_join(threads[t]);
    g_assert_cmpmem(parallel[t].mu2_lambda, 2 * pairs.count * sizeof(double),
                    serial.mu2_lambda, 2 * pairs.count * sizeof(double));
    g_assert_cmpmem(parallel[t].overlap, pairs.count * sizeof(int),
                    serial.overlap, pairs.count * sizeof(int));
    g_assert_cmpmem(parallel[t].f, pairs.count * sizeof(double), serial.f,
                    pairs.count * sizeof(double));
    results_clear(&parallel[t]);
  }
  results_clear(&serial);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  general_pairs_load_or_fail(&pairs);
  g_test_add_func("/pw85/threads/bit-identical", test_threads);
  int const status = g_test_run();
  general_pairs_clear(&pairs);
  return status;
}
