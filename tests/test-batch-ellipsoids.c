/* SPDX-License-Identifier: BSD-3-Clause */
/* The batches of the constructors and of pw85_principal_axes (pw85.h,
 * "Batches"): every item as the single function computes it, bit for bit,
 * with its status, for thread counts 1, 2, 8 and 0 and every layout
 * (contiguous, one record for every item, records side by side); good and
 * bad items mixed; the errors of the call itself; n = 0. */
#include <math.h>
#include <pw85.h>
#include <string.h>

#include "testutil.h"

/* Enough items for 8 threads of 256 (pw85.h: at most n/256 threads). */
#define N 2100
/* A byte that no result has: untouched outputs keep it. */
#define SENTINEL 0xA5

/* One function in its two forms. Up to three inputs, of `size` doubles
 * each; the outputs of item i of n at their offsets in `out` (for
 * pw85_principal_axes: a at out + 3i, rot at out + 3n + 9i). */
typedef struct {
  const char *name;
  int inputs;
  size_t size[3];
  size_t doubles; /* of output per item */
  int (*single_at)(size_t i, size_t n, double const *const in[3],
                   double *out);
  int (*batch)(size_t n, double const *const in[3], size_t const stride[3],
               double *out, int *status, int threads);
} Kind;

/* pw85_spheroid has no status: the batch's rule (pw85.h), written here
 * from the documentation. */
static int spheroid_at(size_t i, size_t n, double const *const in[3],
                       double *out) {
  (void)n;
  double const a = in[0][0], c = in[1][0], *axis = in[2];
  if (!isfinite(a) || !isfinite(c) || !isfinite(axis[0]) ||
      !isfinite(axis[1]) || !isfinite(axis[2]))
    return PW85_EDOM;
  double *q = out + PW85_SYM * i;
  pw85_spheroid(a, c, axis, q);
  for (int k = 0; k < PW85_SYM; k++)
    if (!isfinite(q[k])) return PW85_ERANGE;
  return PW85_SUCCESS;
}
static int spheroid_batch(size_t n, double const *const in[3],
                          size_t const s[3], double *out, int *status,
                          int threads) {
  return pw85_spheroid_batch(n, in[0], s[0], in[1], s[1], in[2], s[2], out,
                             status, threads);
}

static int rotation_at(size_t i, size_t n, double const *const in[3],
                       double *out) {
  (void)n;
  return pw85_ellipsoid_rotation(in[0], in[1], out + PW85_SYM * i);
}
static int rotation_batch(size_t n, double const *const in[3],
                          size_t const s[3], double *out, int *status,
                          int threads) {
  return pw85_ellipsoid_rotation_batch(n, in[0], s[0], in[1], s[1], out,
                                       status, threads);
}

static int quaternion_at(size_t i, size_t n, double const *const in[3],
                         double *out) {
  (void)n;
  return pw85_ellipsoid_quaternion(in[0], in[1], out + PW85_SYM * i);
}
static int quaternion_batch(size_t n, double const *const in[3],
                            size_t const s[3], double *out, int *status,
                            int threads) {
  return pw85_ellipsoid_quaternion_batch(n, in[0], s[0], in[1], s[1], out,
                                         status, threads);
}

static int axes_at(size_t i, size_t n, double const *const in[3],
                   double *out) {
  return pw85_principal_axes(in[0], out + 3 * i, out + 3 * n + 9 * i);
}
static int axes_batch(size_t n, double const *const in[3], size_t const s[3],
                      double *out, int *status, int threads) {
  return pw85_principal_axes_batch(n, in[0], s[0], out, out + 3 * n, status,
                                   threads);
}

static Kind const kinds[] = {
    {"spheroid", 3, {1, 1, 3}, PW85_SYM, spheroid_at, spheroid_batch},
    {"ellipsoid_rotation", 2, {3, 9, 0}, PW85_SYM, rotation_at,
     rotation_batch},
    {"ellipsoid_quaternion", 2, {3, 4, 0}, PW85_SYM, quaternion_at,
     quaternion_batch},
    {"principal_axes", 1, {6, 0, 0}, 12, axes_at, axes_batch},
};

/* The inputs of N good items of a kind, contiguous, one array per input. */
typedef struct {
  double *in[3];
} Items;

/* Semi-axes from 0.01 to 100; rotations from unit quaternions (orthonormal
 * to a few ulps); forms with eigenvalues from 1e-4 to 1e4. */
static Items make_items(Kind const *kind, guint32 seed) {
  GRand *rng = g_rand_new_with_seed(seed);
  Items items = {{NULL, NULL, NULL}};
  for (int k = 0; k < kind->inputs; k++)
    items.in[k] = g_new(double, N * kind->size[k]);
  for (size_t i = 0; i < N; i++) {
    double p[4], e[3];
    for (int k = 0; k < 3; k++)
      e[k] = pow(10., g_rand_double_range(rng, -2., 2.));
    random_unit_quaternion(rng, p);
    if (kind->single_at == spheroid_at) {
      items.in[0][i] = e[0], items.in[1][i] = e[1];
      double const norm = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      for (int k = 0; k < 3; k++) items.in[2][3 * i + k] = p[k] / norm;
    } else if (kind->single_at == rotation_at) {
      memcpy(items.in[0] + 3 * i, e, sizeof e);
      quaternion_rotation(p, items.in[1] + 9 * i);
    } else if (kind->single_at == quaternion_at) {
      memcpy(items.in[0] + 3 * i, e, sizeof e);
      memcpy(items.in[1] + 4 * i, p, sizeof p);
    } else {
      for (int k = 0; k < 3; k++) e[k] *= e[k];
      random_form_with_eigenvalues(rng, e, items.in[0] + 6 * i);
    }
  }
  g_rand_free(rng);
  return items;
}

static void free_items(Items items) {
  for (int k = 0; k < 3; k++) g_free(items.in[k]);
}

/* The batch of kind on n items (inputs at in, strides in doubles) for each
 * thread count, against the single calls: return value, every status,
 * every output byte; and the same with status NULL. */
static void check_batch(Kind const *kind, size_t n, double const *const in[3],
                        size_t const stride[3], const char *what) {
  size_t const bytes = n * kind->doubles * sizeof(double);
  double *expected = g_malloc(bytes + 1), *actual = g_malloc(bytes + 1);
  int *expected_status = g_new(int, n + 1), *status = g_new(int, n + 1);
  memset(expected, SENTINEL, bytes);
  int first = PW85_SUCCESS;
  for (size_t i = 0; i < n; i++) {
    double const *item[3] = {NULL, NULL, NULL};
    for (int k = 0; k < kind->inputs; k++) item[k] = in[k] + i * stride[k];
    expected_status[i] = kind->single_at(i, n, item, expected);
    if (first == PW85_SUCCESS) first = expected_status[i];
  }
  int const threads[] = {1, 2, 8, 0};
  for (size_t t = 0; t < G_N_ELEMENTS(threads); t++) {
    memset(actual, SENTINEL, bytes);
    memset(status, SENTINEL, n * sizeof(int));
    int const code = kind->batch(n, in, stride, actual, status, threads[t]);
    if (code != first)
      test_mismatch("%s, %s, %d threads: returned %d, first failure %d",
                    kind->name, what, threads[t], code, first);
    for (size_t i = 0; i < n; i++)
      if (status[i] != expected_status[i]) {
        test_mismatch("%s, %s, %d threads: item %zu: status %d, expected %d",
                      kind->name, what, threads[t], i, status[i],
                      expected_status[i]);
        break;
      }
    if (memcmp(actual, expected, bytes) != 0)
      test_mismatch("%s, %s, %d threads: outputs differ from the single "
                    "calls", kind->name, what, threads[t]);
    memset(actual, SENTINEL, bytes);
    int const code_nostatus = kind->batch(n, in, stride, actual, NULL,
                                          threads[t]);
    if (code_nostatus != first || memcmp(actual, expected, bytes) != 0)
      test_mismatch("%s, %s, %d threads, status NULL: returned %d (expected "
                    "%d) or outputs differ", kind->name, what, threads[t],
                    code_nostatus, first);
  }
  g_free(expected);
  g_free(actual);
  g_free(expected_status);
  g_free(status);
}

static void contiguous_strides(Kind const *kind, size_t stride[3]) {
  for (int k = 0; k < 3; k++) stride[k] = kind->size[k];
}

/* Contiguous, then each input given once for every item (stride 0), then
 * every input of an item side by side in one record. */
static void test_layouts(gconstpointer data) {
  Kind const *kind = data;
  Items items = make_items(kind, 20261124);
  double const *in[3] = {items.in[0], items.in[1], items.in[2]};
  size_t stride[3];
  contiguous_strides(kind, stride);
  check_batch(kind, N, in, stride, "contiguous");
  for (int k = 0; k < kind->inputs; k++) {
    double const *one[3] = {in[0], in[1], in[2]};
    size_t s[3];
    contiguous_strides(kind, s);
    one[k] = in[k] + 17 * kind->size[k];
    s[k] = 0;
    char *what = g_strdup_printf("input %d broadcast", k);
    check_batch(kind, N, one, s, what);
    g_free(what);
  }
  size_t record = 0, offset[3];
  for (int k = 0; k < kind->inputs; k++)
    offset[k] = record, record += kind->size[k];
  record += 1; /* a spare double: records longer than their fields */
  double *records = g_new0(double, N * record);
  double const *rec_in[3] = {NULL, NULL, NULL};
  size_t rec_stride[3] = {record, record, record};
  for (int k = 0; k < kind->inputs; k++) {
    for (size_t i = 0; i < N; i++)
      memcpy(records + i * record + offset[k], in[k] + i * kind->size[k],
             kind->size[k] * sizeof(double));
    rec_in[k] = records + offset[k];
  }
  check_batch(kind, N, rec_in, rec_stride, "records");
  g_free(records);
  free_items(items);
}

/* Bad items of each kind at indices in different chunks, each status of
 * the single function; the first failure returned, and every suffix
 * starting at a failure. */
static void test_mixed(gconstpointer data) {
  Kind const *kind = data;
  Items items = make_items(kind, 7);
  double **in = items.in;
  size_t const bad[] = {300, 900, 1500, 2099};
  int codes[4];
  if (kind->single_at == spheroid_at) {
    in[0][300] = NAN, codes[0] = PW85_EDOM;
    in[2][3 * 900 + 1] = INFINITY, codes[1] = PW85_EDOM;
    in[1][1500] = 1e200, codes[2] = PW85_ERANGE; /* c² overflows */
    in[0][2099] = -INFINITY, codes[3] = PW85_EDOM;
  } else if (kind->single_at == rotation_at) {
    in[0][3 * 300] = 0., codes[0] = PW85_EINVAL;
    in[1][9 * 900 + 4] += 1e-3, codes[1] = PW85_EINVAL;
    in[0][3 * 1500 + 2] = 1e200, codes[2] = PW85_ERANGE;
    in[1][9 * 2099] = NAN, codes[3] = PW85_EDOM;
  } else if (kind->single_at == quaternion_at) {
    in[0][3 * 300 + 1] = -1., codes[0] = PW85_EINVAL;
    for (int k = 0; k < 4; k++) in[1][4 * 900 + k] *= 1.01; /* |p|² 1.02 */
    codes[1] = PW85_EINVAL;
    in[0][3 * 1500] = 1e-200, codes[2] = PW85_ERANGE;
    in[1][4 * 2099 + 3] = NAN, codes[3] = PW85_EDOM;
  } else {
    in[0][6 * 300 + 5] = -1., codes[0] = PW85_ENOTPOSDEF;
    in[0][6 * 900] = NAN, codes[1] = PW85_EDOM;
    in[0][6 * 1500 + 3] = 0., codes[2] = PW85_ENOTPOSDEF;
    in[0][6 * 2099 + 1] = INFINITY, codes[3] = PW85_EDOM;
  }
  size_t stride[3];
  contiguous_strides(kind, stride);
  double const *all[3] = {in[0], in[1], in[2]};
  check_batch(kind, N, all, stride, "mixed");
  /* The statuses meant, and no others. */
  size_t const bytes = N * kind->doubles * sizeof(double);
  double *out = g_malloc(bytes);
  int *status = g_new(int, N);
  g_assert_cmpint(kind->batch(N, all, stride, out, status, 2), ==, codes[0]);
  for (size_t i = 0, b = 0; i < N; i++) {
    int const expected = b < 4 && i == bad[b] ? codes[b++] : PW85_SUCCESS;
    if (status[i] != expected)
      test_mismatch("%s: item %zu: status %d, expected %d", kind->name, i,
                    status[i], expected);
  }
  g_free(out);
  g_free(status);
  for (size_t b = 1; b < 4; b++) {
    double const *from[3] = {NULL, NULL, NULL};
    for (int k = 0; k < kind->inputs; k++)
      from[k] = in[k] + bad[b] * kind->size[k];
    char *what = g_strdup_printf("mixed, from item %zu", bad[b]);
    check_batch(kind, N - bad[b], from, stride, what);
    g_free(what);
  }
  free_items(items);
}

/* Errors of the call itself: no output written, every status set to the
 * code. n = 0: success, nothing read nor written. */
static void test_call_errors(gconstpointer data) {
  Kind const *kind = data;
  Items items = make_items(kind, 11);
  enum { n = 600 };
  size_t const bytes = n * kind->doubles * sizeof(double);
  double *out = g_malloc(bytes);
  unsigned char *untouched = g_malloc(bytes);
  memset(untouched, SENTINEL, bytes);
  int status[n];
  size_t good[3];
  contiguous_strides(kind, good);
  /* Each input NULL; each stride between 1 and its size − 1 (none for a
   * size of 1); threads < 0. */
  for (int c = 0; c < 2 * kind->inputs + 1; c++) {
    double const *in[3] = {items.in[0], items.in[1], items.in[2]};
    size_t stride[3] = {good[0], good[1], good[2]};
    int threads = 2, code;
    if (c < kind->inputs) {
      in[c] = NULL, code = PW85_EFAULT;
    } else if (c < 2 * kind->inputs) {
      int const k = c - kind->inputs;
      if (kind->size[k] == 1) continue;
      stride[k] = kind->size[k] - 1, code = PW85_EINVAL;
    } else {
      threads = -1, code = PW85_EINVAL;
    }
    memset(out, SENTINEL, bytes);
    memset(status, 0, sizeof status);
    int const returned = kind->batch(n, in, stride, out, status, threads);
    if (returned != code)
      test_mismatch("%s, case %d: returned %d, expected %d", kind->name, c,
                    returned, code);
    if (memcmp(out, untouched, bytes) != 0)
      test_mismatch("%s, case %d: an output was written", kind->name, c);
    for (size_t i = 0; i < n; i++)
      if (status[i] != code) {
        test_mismatch("%s, case %d: status[%zu] = %d, expected %d",
                      kind->name, c, i, status[i], code);
        break;
      }
  }
  double const *in[3] = {items.in[0], items.in[1], items.in[2]};
  /* The output NULL (for principal_axes, a and rot each). */
  g_assert_cmpint(kind->batch(n, in, good, NULL, status, 1), ==,
                  PW85_EFAULT);
  g_assert_cmpint(status[n - 1], ==, PW85_EFAULT);
  if (kind->single_at == axes_at) {
    double a[3 * n];
    memset(a, SENTINEL, sizeof a);
    g_assert_cmpint(pw85_principal_axes_batch(n, in[0], 6, a, NULL, NULL, 1),
                    ==, PW85_EFAULT);
    g_assert_true(memcmp(a, untouched, sizeof a) == 0);
  }
  /* n = 0. */
  status[0] = -1;
  double const *none[3] = {NULL, NULL, NULL};
  size_t const bad_strides[3] = {2, 2, 2};
  g_assert_cmpint(kind->batch(0, none, bad_strides, NULL, status, -1), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(status[0], ==, -1);
  g_free(out);
  g_free(untouched);
  free_items(items);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  for (size_t k = 0; k < G_N_ELEMENTS(kinds); k++) {
    static const struct {
      const char *name;
      GTestDataFunc func;
    } tests[] = {{"layouts", test_layouts},
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
