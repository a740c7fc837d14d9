/* SPDX-License-Identifier: BSD-3-Clause */
/* The batch calls (pw85.h, "Batches"): every pair as the single-pair
 * function computes it, bit for bit, with its status, for every function,
 * thread count (1, 2, 8, 0) and layout (contiguous, broadcast, records);
 * statuses and first error with good and bad pairs mixed; the errors of
 * the call itself; n = 0; the thread policy; no thread without asking. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <limits.h>
#include <math.h>
#include <pw85.h>
#include <stdint.h>
#include <string.h>

#include "testutil.h"

/* Enough pairs for 8 threads of 256 pairs (pw85.h: at most n/256). */
#define N 2100
/* A byte that no result has: untouched outputs keep it. */
#define SENTINEL 0xA5

static double r12[N][PW85_DIM], q1[N][PW85_SYM], q2[N][PW85_SYM];

/* One function of pw85.h in its two forms, both writing the layout of the
 * batch (pair i of n at its offset in `out`). */
typedef struct {
  const char *name;
  size_t bytes; /* per pair */
  int (*single_at)(size_t i, size_t n, double const *r, double const *a,
                   double const *b, void *out);
  int (*batch)(size_t n, double const *r, size_t rs, double const *a,
               size_t as, double const *b, size_t bs, void *out,
               int *status, int threads);
} Kind;

static int cf_single(size_t i, size_t n, double const *r, double const *a,
                     double const *b, void *out) {
  (void)n;
  return pw85_contact_function(r, a, b, (double *)out + 2 * i);
}
static int cf_batch(size_t n, double const *r, size_t rs, double const *a,
                    size_t as, double const *b, size_t bs, void *out,
                    int *status, int threads) {
  return pw85_contact_function_batch(n, r, rs, a, as, b, bs, out, status,
                                     threads);
}
static int ov_single(size_t i, size_t n, double const *r, double const *a,
                     double const *b, void *out) {
  (void)n;
  return pw85_overlap(r, a, b, (int *)out + i);
}
static int ov_batch(size_t n, double const *r, size_t rs, double const *a,
                    size_t as, double const *b, size_t bs, void *out,
                    int *status, int threads) {
  return pw85_overlap_batch(n, r, rs, a, as, b, bs, out, status, threads);
}
static int geo_single(size_t i, size_t n, double const *r, double const *a,
                      double const *b, void *out) {
  (void)n;
  return pw85_contact_geometry(r, a, b, (double *)out + PW85_GEOM_SIZE * i);
}
static int geo_batch(size_t n, double const *r, size_t rs, double const *a,
                     size_t as, double const *b, size_t bs, void *out,
                     int *status, int threads) {
  return pw85_contact_geometry_batch(n, r, rs, a, as, b, bs, out, status,
                                     threads);
}
/* Derivatives: geometry for the n pairs, then d for the n pairs. */
static int der_single(size_t i, size_t n, double const *r, double const *a,
                      double const *b, void *out) {
  double *g = out;
  return pw85_contact_derivatives(r, a, b, g + PW85_GEOM_SIZE * i,
                                  g + PW85_GEOM_SIZE * n + PW85_DERIV_SIZE * i);
}
static int der_batch(size_t n, double const *r, size_t rs, double const *a,
                     size_t as, double const *b, size_t bs, void *out,
                     int *status, int threads) {
  double *g = out;
  return pw85_contact_derivatives_batch(n, r, rs, a, as, b, bs, g,
                                        g + PW85_GEOM_SIZE * n, status,
                                        threads);
}

static Kind const kinds[] = {
    {"contact_function", 2 * sizeof(double), cf_single, cf_batch},
    {"overlap", sizeof(int), ov_single, ov_batch},
    {"contact_geometry", PW85_GEOM_SIZE * sizeof(double), geo_single,
     geo_batch},
    {"contact_derivatives", (PW85_GEOM_SIZE + PW85_DERIV_SIZE) * sizeof(double),
     der_single, der_batch},
};

/* Random triaxial pairs: semi-axes from 0.1 to 10 (aspect ratios to 100),
 * centres from overlapping to far apart. */
static void make_pairs(void) {
  GRand *rng = g_rand_new_with_seed(20250717);
  for (size_t i = 0; i < N; i++) {
    double e1[3], e2[3];
    for (int k = 0; k < 3; k++) {
      e1[k] = pow(10., g_rand_double_range(rng, -2., 2.));
      e2[k] = pow(10., g_rand_double_range(rng, -2., 2.));
    }
    random_form_with_eigenvalues(rng, e1, q1[i]);
    random_form_with_eigenvalues(rng, e2, q2[i]);
    for (int k = 0; k < 3; k++) r12[i][k] = g_rand_double_range(rng, -10., 10.);
  }
  g_rand_free(rng);
}

/* The first failing pair and the single-pair statuses and outputs of pairs
 * [0, n) read with the given strides (in doubles). */
static int reference(Kind const *kind, size_t n, double const *r, size_t rs,
                     double const *a, size_t as, double const *b, size_t bs,
                     void *out, int *status) {
  int first = PW85_SUCCESS;
  memset(out, SENTINEL, n * kind->bytes);
  for (size_t i = 0; i < n; i++) {
    status[i] = kind->single_at(i, n, r + i * rs, a + i * as, b + i * bs, out);
    if (first == PW85_SUCCESS) first = status[i];
  }
  return first;
}

/* The batch of kind on the given pairs, for each thread count, against
 * reference(): return value, every status, every output byte. */
static void check_batch(Kind const *kind, size_t n, double const *r,
                        size_t rs, double const *a, size_t as,
                        double const *b, size_t bs, const char *what) {
  void *expected = g_malloc(n * kind->bytes + 1);
  void *actual = g_malloc(n * kind->bytes + 1);
  int *expected_status = g_new(int, n + 1);
  int *status = g_new(int, n + 1);
  int const first = reference(kind, n, r, rs, a, as, b, bs, expected,
                              expected_status);
  int const threads[] = {1, 2, 8, 0};
  for (size_t t = 0; t < G_N_ELEMENTS(threads); t++) {
    memset(actual, SENTINEL, n * kind->bytes);
    memset(status, SENTINEL, n * sizeof(int));
    int const code = kind->batch(n, r, rs, a, as, b, bs, actual, status,
                                 threads[t]);
    if (code != first)
      test_mismatch("%s, %s, %d threads: returned %d, first failure %d",
                    kind->name, what, threads[t], code, first);
    for (size_t i = 0; i < n; i++)
      if (status[i] != expected_status[i]) {
        test_mismatch("%s, %s, %d threads: pair %zu: status %d, expected %d",
                      kind->name, what, threads[t], i, status[i],
                      expected_status[i]);
        break;
      }
    if (memcmp(actual, expected, n * kind->bytes) != 0)
      test_mismatch("%s, %s, %d threads: outputs differ from the single "
                    "calls", kind->name, what, threads[t]);
    /* status may be NULL: the same outputs and return value. */
    memset(actual, SENTINEL, n * kind->bytes);
    int const code_nostatus = kind->batch(n, r, rs, a, as, b, bs, actual,
                                          NULL, threads[t]);
    if (code_nostatus != first ||
        memcmp(actual, expected, n * kind->bytes) != 0)
      test_mismatch("%s, %s, %d threads, status NULL: returned %d (expected "
                    "%d) or outputs differ", kind->name, what, threads[t],
                    code_nostatus, first);
  }
  g_free(expected);
  g_free(actual);
  g_free(expected_status);
  g_free(status);
}

/* Contiguous n×3 and n×6 arrays, all good pairs. */
static void test_contiguous(gconstpointer data) {
  Kind const *kind = data;
  check_batch(kind, N, r12[0], PW85_DIM, q1[0], PW85_SYM, q2[0], PW85_SYM,
              "contiguous");
}

/* Stride 0 (one r12, one q1 or one q2 for every pair), and records of 15
 * doubles (r12, q1, q2 of a pair side by side). */
static void test_strides(gconstpointer data) {
  Kind const *kind = data;
  check_batch(kind, N, r12[0], PW85_DIM, q1[7], 0, q2[0], PW85_SYM,
              "q1 broadcast");
  check_batch(kind, N, r12[0], PW85_DIM, q1[0], PW85_SYM, q2[3], 0,
              "q2 broadcast");
  check_batch(kind, N, r12[5], 0, q1[0], PW85_SYM, q2[0], PW85_SYM,
              "r12 broadcast");
  double *records = g_new(double, 15 * N);
  for (size_t i = 0; i < N; i++) {
    memcpy(records + 15 * i, r12[i], sizeof r12[i]);
    memcpy(records + 15 * i + 3, q1[i], sizeof q1[i]);
    memcpy(records + 15 * i + 9, q2[i], sizeof q2[i]);
  }
  check_batch(kind, N, records, 15, records + 3, 15, records + 9, 15,
              "records of 15 doubles");
  g_free(records);
}

/* Good and bad pairs mixed, in different chunks of 256: every status of
 * the single-pair functions, the first failure returned, each failing
 * pair's outputs as the single call leaves them (untouched, or written
 * for PW85_ERANGE). */
static void test_mixed(gconstpointer data) {
  Kind const *kind = data;
  double (*r)[PW85_DIM] = g_memdup2(r12, sizeof r12);
  double (*a)[PW85_SYM] = g_memdup2(q1, sizeof q1);
  double (*b)[PW85_SYM] = g_memdup2(q2, sizeof q2);
  /* PW85_ERANGE, outputs written: μ² = 1e400/4e-200 overflows. */
  double const tiny[PW85_SYM] = {1e-200, 0., 0., 1e-200, 0., 1e-200};
  r[1900][0] = 1e200, r[1900][1] = r[1900][2] = 0.;
  memcpy(a[1900], tiny, sizeof tiny);
  memcpy(b[1900], tiny, sizeof tiny);
  /* PW85_ERANGE, outputs untouched: diagonals spanning 1e308 to 5e-324. */
  double const huge[PW85_SYM] = {1e308, 0., 0., 1e308, 0., 1e308};
  double const least[PW85_SYM] = {5e-324, 0., 0., 5e-324, 0., 5e-324};
  memcpy(a[1300], huge, sizeof huge);
  memcpy(b[1300], least, sizeof least);
  r[2099][2] = NAN;     /* PW85_EDOM, the last pair */
  a[1000][5] = -1.;     /* PW85_ENOTPOSDEF */
  b[700][1] = INFINITY; /* PW85_EDOM */
  check_batch(kind, N, r[0], PW85_DIM, a[0], PW85_SYM, b[0], PW85_SYM,
              "mixed, first failure at 700");
  /* The statuses meant, and no others (pw85_overlap: μ² overflowing is
   * disjoint, a success). */
  int *status = g_new(int, N);
  void *out = g_malloc(N * kind->bytes);
  g_assert_cmpint(kind->batch(N, r[0], PW85_DIM, a[0], PW85_SYM, b[0],
                              PW85_SYM, out, status, 2),
                  ==, PW85_EDOM);
  for (size_t i = 0; i < N; i++) {
    int const expected = i == 700 || i == 2099 ? PW85_EDOM
                         : i == 1000           ? PW85_ENOTPOSDEF
                         : i == 1300 ? PW85_ERANGE
                         : i == 1900 && kind->batch != ov_batch ? PW85_ERANGE
                                                                : PW85_SUCCESS;
    if (status[i] != expected)
      test_mismatch("%s: pair %zu: status %d, expected %d", kind->name, i,
                    status[i], expected);
  }
  g_free(out);
  g_free(status);
  /* Each kind of failure first, with a failure in a later chunk. */
  check_batch(kind, N - 700, r[700], PW85_DIM, a[700], PW85_SYM, b[700],
              PW85_SYM, "mixed, first failure PW85_EDOM (q2)");
  check_batch(kind, N - 1000, r[1000], PW85_DIM, a[1000], PW85_SYM, b[1000],
              PW85_SYM, "mixed, first failure PW85_ENOTPOSDEF");
  check_batch(kind, N - 1300, r[1300], PW85_DIM, a[1300], PW85_SYM, b[1300],
              PW85_SYM, "mixed, first failure PW85_ERANGE (untouched)");
  check_batch(kind, N - 1900, r[1900], PW85_DIM, a[1900], PW85_SYM, b[1900],
              PW85_SYM, "mixed, first failure PW85_ERANGE (written)");
  /* Only the last pair fails, in the last chunk, which 8 threads may
   * finish before the others. */
  check_batch(kind, N, r12[0], PW85_DIM, q1[0], PW85_SYM, q2[0], PW85_SYM,
              "all good");
  double (*r_last)[PW85_DIM] = g_memdup2(r12, sizeof r12);
  r_last[N - 1][0] = NAN;
  check_batch(kind, N, r_last[0], PW85_DIM, q1[0], PW85_SYM, q2[0], PW85_SYM,
              "only the last pair fails");
  g_free(r_last);
  g_free(r);
  g_free(a);
  g_free(b);
}

/* Errors of the call itself: nothing computed, no output written, every
 * status set to the code. n = 0: success, nothing read nor written. */
static void test_call_errors(gconstpointer data) {
  Kind const *kind = data;
  enum { n = 600 };
  size_t const bytes = n * kind->bytes;
  unsigned char *out = g_malloc(bytes), *untouched = g_malloc(bytes);
  memset(untouched, SENTINEL, bytes);
  int status[n];
  struct {
    const char *what;
    double const *r, *a, *b;
    size_t rs, as, bs;
    int threads, code;
  } const cases[] = {
      {"r12 NULL", NULL, q1[0], q2[0], 3, 6, 6, 1, PW85_EFAULT},
      {"q1 NULL", r12[0], NULL, q2[0], 3, 6, 6, 2, PW85_EFAULT},
      {"q2 NULL", r12[0], q1[0], NULL, 3, 6, 6, 0, PW85_EFAULT},
      {"r12 stride 1", r12[0], q1[0], q2[0], 1, 6, 6, 1, PW85_EINVAL},
      {"r12 stride 2", r12[0], q1[0], q2[0], 2, 6, 6, 2, PW85_EINVAL},
      {"q1 stride 5", r12[0], q1[0], q2[0], 3, 5, 6, 1, PW85_EINVAL},
      {"q2 stride 3", r12[0], q1[0], q2[0], 3, 6, 3, 8, PW85_EINVAL},
      {"threads -1", r12[0], q1[0], q2[0], 3, 6, 6, -1, PW85_EINVAL},
      {"threads INT_MIN", r12[0], q1[0], q2[0], 3, 6, 6, -2147483647 - 1,
       PW85_EINVAL},
  };
  for (size_t c = 0; c < G_N_ELEMENTS(cases); c++) {
    memset(out, SENTINEL, bytes);
    memset(status, 0, sizeof status);
    int const code = kind->batch(n, cases[c].r, cases[c].rs, cases[c].a,
                                 cases[c].as, cases[c].b, cases[c].bs, out,
                                 status, cases[c].threads);
    if (code != cases[c].code)
      test_mismatch("%s, %s: returned %d, expected %d", kind->name,
                    cases[c].what, code, cases[c].code);
    if (memcmp(out, untouched, bytes) != 0)
      test_mismatch("%s, %s: an output was written", kind->name,
                    cases[c].what);
    for (size_t i = 0; i < n; i++)
      if (status[i] != cases[c].code) {
        test_mismatch("%s, %s: status[%zu] = %d, expected %d", kind->name,
                      cases[c].what, i, status[i], cases[c].code);
        break;
      }
    /* The same with status NULL. */
    g_assert_cmpint(kind->batch(n, cases[c].r, cases[c].rs, cases[c].a,
                                cases[c].as, cases[c].b, cases[c].bs, out,
                                NULL, cases[c].threads),
                    ==, cases[c].code);
  }
  /* An output NULL. */
  memset(status, 0, sizeof status);
  g_assert_cmpint(kind->batch(n, r12[0], 3, q1[0], 6, q2[0], 6, NULL, status,
                              2),
                  ==, PW85_EFAULT);
  g_assert_cmpint(status[0], ==, PW85_EFAULT);
  g_assert_cmpint(status[n - 1], ==, PW85_EFAULT);
  if (kind->batch == der_batch) { /* d NULL, geometry not */
    memset(out, SENTINEL, bytes);
    g_assert_cmpint(pw85_contact_derivatives_batch(n, r12[0], 3, q1[0], 6,
                                                   q2[0], 6, (double *)out,
                                                   NULL, NULL, 1),
                    ==, PW85_EFAULT);
    g_assert_true(memcmp(out, untouched, bytes) == 0);
  }
  /* n = 0: success whatever the pointers, strides and count; nothing
   * written. */
  status[0] = -1;
  g_assert_cmpint(kind->batch(0, NULL, 1, NULL, 1, NULL, 1, NULL, status, -1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(status[0], ==, -1);
  memset(out, SENTINEL, bytes);
  g_assert_cmpint(kind->batch(0, r12[0], 3, q1[0], 6, q2[0], 6, out, status,
                              8),
                  ==, PW85_SUCCESS);
  g_assert_true(memcmp(out, untouched, bytes) == 0 && status[0] == -1);
  g_free(out);
  g_free(untouched);
}

/* pw85_batch_threads: the policy of pw85.h. meson sets OMP_NUM_THREADS=3
 * for this program, and PW85_TEST_OPENMP when libpw85 has OpenMP. */
static void test_thread_policy(void) {
  g_assert_cmpint(pw85_batch_threads(-1, 100000), ==, 0);
  g_assert_cmpint(pw85_batch_threads(1, 100000), ==, 1);
  g_assert_cmpint(pw85_batch_threads(8, 0), ==, 1);
  g_assert_cmpint(pw85_batch_threads(8, 511), ==, 1);
  g_assert_cmpint(pw85_batch_threads(0, 511), ==, 1);
#ifdef PW85_TEST_OPENMP
  g_assert_cmpint(pw85_batch_threads(8, 512), ==, 2);
  g_assert_cmpint(pw85_batch_threads(8, 1000), ==, 3);
  g_assert_cmpint(pw85_batch_threads(8, 2048), ==, 8);
  g_assert_cmpint(pw85_batch_threads(2, 100000), ==, 2);
  g_assert_cmpint(pw85_batch_threads(0, 100000), ==, 3); /* OMP_NUM_THREADS */
  g_assert_cmpint(pw85_batch_threads(0, 600), ==, 2);
  /* At most 1024 (pw85.h), however many pairs. */
  g_assert_cmpint(pw85_batch_threads(100000, (size_t)1 << 40), ==, 1024);
  g_assert_cmpint(pw85_batch_threads(INT_MAX, (size_t)1 << 40), ==, 1024);
  g_assert_cmpint(pw85_batch_threads(1024, (size_t)1 << 40), ==, 1024);
  g_assert_cmpint(pw85_batch_threads(1000, (size_t)1 << 40), ==, 1000);
#else
  g_assert_cmpint(pw85_batch_threads(8, 100000), ==, 1);
  g_assert_cmpint(pw85_batch_threads(0, 100000), ==, 1);
#endif
}

/* The threads of this process (Linux: the entries of /proc/self/task), or
 * 0 if they cannot be counted. */
static int count_threads(void) {
  DIR *dir = opendir("/proc/self/task");
  if (dir == NULL) return 0;
  int count = 0;
  for (struct dirent *e; (e = readdir(dir)) != NULL;)
    if (e->d_name[0] != '.') count++;
  closedir(dir);
  return count;
}

/* Registered first: a call that does not ask for threads starts none (n
 * small, or threads = 1), one that asks does (with OpenMP). */
static void test_no_thread_unasked(void) {
  if (count_threads() != 1) {
    g_test_skip("threads cannot be counted, or already running");
    return;
  }
  double *out = g_new(double, 2 * N);
  int status[N];
  g_assert_cmpint(pw85_contact_function_batch(N, r12[0], 3, q1[0], 6, q2[0],
                                              6, out, status, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_contact_function_batch(511, r12[0], 3, q1[0], 6,
                                              q2[0], 6, out, status, 0),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(count_threads(), ==, 1);
  g_assert_cmpint(pw85_contact_function_batch(N, r12[0], 3, q1[0], 6, q2[0],
                                              6, out, status, 2),
                  ==, PW85_SUCCESS);
#ifdef PW85_TEST_OPENMP
  g_assert_cmpint(count_threads(), >, 1);
#else
  g_assert_cmpint(count_threads(), ==, 1);
#endif
  g_free(out);
}

/* Batches called from 4 threads at once (each asking for 1 or 2 threads),
 * on shared inputs: each gets the single-thread results. Under
 * ThreadSanitizer (scripts/run-tests.sh), a race would be reported. */
static gpointer concurrent_worker(gpointer data) {
  double *out = data;
  int const threads = out[0] == 2. ? 2 : 1;
  int const code = pw85_contact_derivatives_batch(N, r12[0], 3, q1[0], 6,
                                                  q2[7], 0, out,
                                                  out + PW85_GEOM_SIZE * N,
                                                  NULL, threads);
  return GINT_TO_POINTER(code);
}

static void test_concurrent(void) {
  size_t const size = (PW85_GEOM_SIZE + PW85_DERIV_SIZE) * N;
  double *expected = g_new(double, size);
  g_assert_cmpint(pw85_contact_derivatives_batch(N, r12[0], 3, q1[0], 6,
                                                 q2[7], 0, expected,
                                                 expected + PW85_GEOM_SIZE * N,
                                                 NULL, 1),
                  ==, PW85_SUCCESS);
  GThread *workers[4];
  double *outs[4];
  for (int t = 0; t < 4; t++) {
    outs[t] = g_new(double, size);
    outs[t][0] = t % 2 ? 2. : 1.; /* the count to ask for */
    workers[t] = g_thread_new("batch", concurrent_worker, outs[t]);
  }
  for (int t = 0; t < 4; t++) {
    g_assert_cmpint(GPOINTER_TO_INT(g_thread_join(workers[t])), ==,
                    PW85_SUCCESS);
    g_assert_cmpmem(outs[t], size * sizeof(double), expected,
                    size * sizeof(double));
    g_free(outs[t]);
  }
  g_free(expected);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  make_pairs();
  g_test_add_func("/pw85/batch/no_thread_unasked", test_no_thread_unasked);
  g_test_add_func("/pw85/batch/thread_policy", test_thread_policy);
  g_test_add_func("/pw85/batch/concurrent", test_concurrent);
  for (size_t k = 0; k < G_N_ELEMENTS(kinds); k++) {
    static const struct {
      const char *name;
      GTestDataFunc func;
    } tests[] = {{"contiguous", test_contiguous},
                 {"strides", test_strides},
                 {"mixed", test_mixed},
                 {"call_errors", test_call_errors}};
    for (size_t t = 0; t < G_N_ELEMENTS(tests); t++) {
      char *path = g_strdup_printf("/pw85/batch/%s/%s", kinds[k].name,
                                   tests[t].name);
      g_test_add_data_func(path, &kinds[k], tests[t].func);
      g_free(path);
    }
  }
  return g_test_run();
}
