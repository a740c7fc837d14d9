/* SPDX-License-Identifier: BSD-3-Clause */
/* Loads libpw85 with dlopen, as other languages do, and calls every exported
 * function through dlsym. argv[1]: the path of the shared library. */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define CHECK(cond)                                             \
  do {                                                          \
    if (!(cond)) {                                              \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__,    \
              __LINE__, #cond);                                 \
      return 1;                                                 \
    }                                                           \
  } while (0)

typedef const char *(*strerror_fn)(int);
typedef const char *(*version_fn)(void);
typedef void (*decomp_fn)(double const *, double *);
typedef void (*solve_fn)(double const *, double const *, double *);
typedef void (*spheroid_fn)(double, double, double const *, double *);
typedef double (*f_neg_fn)(double, double const *);
typedef void (*residual_fn)(double, double const *, double const *,
                            double const *, double *);
typedef int (*contact_fn)(double const *, double const *, double const *,
                          double *);
typedef int (*overlap_fn)(double const *, double const *, double const *,
                          int *);
typedef int (*make_fn)(double const *, double const *, double *);
typedef int (*axes_fn)(double const *, double *, double *);
typedef int (*derivatives_fn)(double const *, double const *, double const *,
                              double *, double *);
typedef int (*threads_fn)(int, size_t);
typedef int (*batch_fn)(size_t, double const *, size_t, double const *,
                        size_t, double const *, size_t, void *, int *, int);
typedef int (*derivatives_batch_fn)(size_t, double const *, size_t,
                                    double const *, size_t, double const *,
                                    size_t, double *, double *, int *, int);
/* pw85_index.h, with the opaque handle as void * */
typedef int (*index_create_fn)(double const *, void **);
typedef void (*index_destroy_fn)(void *);
typedef int (*index_openmp_fn)(void);
typedef int (*index_count_fn)(void const *, size_t *);
typedef int (*index_insert_fn)(void *, size_t, double const *, double const *);
typedef int (*index_insert_many_fn)(void *, size_t, size_t const *,
                                    double const *, double const *);
typedef int (*index_remove_fn)(void *, size_t);
typedef int (*index_get_fn)(void const *, size_t, double *, double *);
typedef int (*index_overlap_any_fn)(void const *, double const *,
                                    double const *, size_t, int *, size_t *);
typedef int (*index_overlap_any_batch_fn)(void const *, size_t, double const *,
                                          size_t, double const *, size_t,
                                          size_t const *, int *, size_t *,
                                          int *, int);
typedef int (*index_within_fn)(void const *, double const *, double const *,
                               double, size_t, size_t, size_t *, int *,
                               double *, size_t *);
typedef int (*index_overlapping_fn)(void const *, int, size_t, size_t *, int *,
                                    int *, size_t *);
typedef int (*index_pairs_within_fn)(void const *, double, int, size_t,
                                     size_t *, int *, double *, size_t *);

static void *sym(void *lib, const char *name) {
  void *p = dlsym(lib, name);
  if (p == NULL) fprintf(stderr, "dlsym(%s): %s\n", name, dlerror());
  return p;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: %s LIBRARY\n", argv[0]);
    return 2;
  }
  void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
  if (lib == NULL) {
    fprintf(stderr, "dlopen: %s\n", dlerror());
    return 1;
  }
  /* Conversions from void * to function pointers go through memcpy, the
   * portable spelling. */
  strerror_fn strerror_p;
  version_fn version_p;
  decomp_fn decomp_p;
  solve_fn solve_p;
  spheroid_fn spheroid_p;
  f_neg_fn f_neg_p;
  residual_fn residual_p;
  contact_fn contact_p;
  overlap_fn overlap_p;
  make_fn rotation_p, quaternion_p;
  axes_fn axes_p;
  contact_fn geometry_p;
  derivatives_fn derivatives_p;
  threads_fn threads_p;
  batch_fn cf_batch_p, overlap_batch_p, geometry_batch_p;
  derivatives_batch_fn derivatives_batch_p;
  index_create_fn index_create_p;
  index_destroy_fn index_destroy_p;
  index_openmp_fn index_openmp_p;
  index_count_fn index_count_p;
  index_insert_fn index_insert_p, index_update_p;
  index_insert_many_fn index_insert_many_p;
  index_remove_fn index_remove_p;
  index_get_fn index_get_p;
  index_overlap_any_fn index_overlap_any_p;
  index_overlap_any_batch_fn index_overlap_any_batch_p;
  index_within_fn index_within_p;
  index_overlapping_fn index_overlapping_p;
  index_pairs_within_fn index_pairs_within_p;
  void *p;
#define LOAD(var, name)      \
  p = sym(lib, name);        \
  CHECK(p != NULL);          \
  memcpy(&var, &p, sizeof p);
  LOAD(strerror_p, "pw85_strerror");
  LOAD(version_p, "pw85_version");
  LOAD(decomp_p, "pw85__cholesky_decomp");
  LOAD(solve_p, "pw85__cholesky_solve");
  LOAD(spheroid_p, "pw85_spheroid");
  LOAD(f_neg_p, "pw85_f_neg");
  LOAD(residual_p, "pw85__residual");
  LOAD(contact_p, "pw85_contact_function");
  LOAD(overlap_p, "pw85_overlap");
  LOAD(rotation_p, "pw85_ellipsoid_rotation");
  LOAD(quaternion_p, "pw85_ellipsoid_quaternion");
  LOAD(axes_p, "pw85_principal_axes");
  LOAD(geometry_p, "pw85_contact_geometry");
  LOAD(derivatives_p, "pw85_contact_derivatives");
  LOAD(threads_p, "pw85_batch_threads");
  LOAD(cf_batch_p, "pw85_contact_function_batch");
  LOAD(overlap_batch_p, "pw85_overlap_batch");
  LOAD(geometry_batch_p, "pw85_contact_geometry_batch");
  LOAD(derivatives_batch_p, "pw85_contact_derivatives_batch");
  LOAD(index_create_p, "pw85_index_create");
  LOAD(index_destroy_p, "pw85_index_destroy");
  LOAD(index_openmp_p, "pw85_index_openmp");
  LOAD(index_count_p, "pw85_index_count");
  LOAD(index_insert_p, "pw85_index_insert");
  LOAD(index_update_p, "pw85_index_update");
  LOAD(index_insert_many_p, "pw85_index_insert_many");
  LOAD(index_remove_p, "pw85_index_remove");
  LOAD(index_get_p, "pw85_index_get");
  LOAD(index_overlap_any_p, "pw85_index_overlap_any");
  LOAD(index_overlap_any_batch_p, "pw85_index_overlap_any_batch");
  LOAD(index_within_p, "pw85_index_within");
  LOAD(index_overlapping_p, "pw85_index_overlapping_pairs");
  LOAD(index_pairs_within_p, "pw85_index_pairs_within");

  CHECK(strcmp(strerror_p(0), "success") == 0);
  CHECK(strcmp(version_p(), PW85_EXPECTED_VERSION) == 0);

  double const a[6] = {4., 2., -2., 10., 5., 21.};
  double l[6], x[3];
  double const b[3] = {2., 37., 71.};
  decomp_p(a, l);
  CHECK(l[0] == 2. && l[1] == 1. && l[2] == -1. && l[3] == 3. && l[4] == 2. &&
        l[5] == 4.);
  solve_p(l, b, x);
  CHECK(x[0] == 1. && x[1] == 2. && x[2] == 3.);

  double q1[6], q2[6];
  double const n1[3] = {0., 0., 1.}, n2[3] = {1., 0., 0.};
  spheroid_p(10., 0.1, n1, q1);
  spheroid_p(0.5, 5., n2, q2);
  CHECK(q1[0] == 100. && q2[0] == 25.);

  double const r[3] = {0.7, -0.7, 1.1};
  double params[15];
  memcpy(params, r, sizeof r);
  memcpy(params + 3, q1, sizeof q1);
  memcpy(params + 9, q2, sizeof q2);
  double const fm = f_neg_p(0.5, params);
  CHECK(isfinite(fm) && fm < 0.);

  double res[3];
  residual_p(0.5, r, q1, q2, res);
  CHECK(res[0] == -fm);

  double out[2];
  CHECK(contact_p(r, q1, q2, out) == 0);
  CHECK(fabs(out[0] - 3.3627060406386292) < 1e-12);
  CHECK(contact_p(r, q1, NULL, out) == 1);
  int answer = 0;
  CHECK(overlap_p(r, q1, q2, &answer) == 0 && answer == 1);

  /* Semi-axes (3, 2, 1) turned by a quarter turn about z, both ways. */
  double const semi[3] = {3., 2., 1.}, turn[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  double const unit[4] = {1., 0., 0., 0.};
  double q3[6], axes[3], rot[9];
  CHECK(rotation_p(semi, turn, q3) == 0 && q3[0] == 4. && q3[3] == 9.);
  CHECK(quaternion_p(semi, unit, q3) == 0 && q3[0] == 9. && q3[3] == 4.);
  CHECK(axes_p(q3, axes, rot) == 0 && axes[0] == 3. && axes[2] == 1.);
  double g[8], g2[8], d[21];
  CHECK(geometry_p(r, q1, q2, g) == 0 && g[0] == out[0]);
  CHECK(derivatives_p(r, q1, q2, g2, d) == 0 && g2[0] == out[0]);

  /* 600 copies of the pair (q1, q2 broadcast), on 2 threads where
   * libpw85 has OpenMP: then dlclose() must not unload the code of its
   * idle threads. */
  enum { n = 600 };
  static double rs[3 * n], outs[21 * n], ds[21 * n];
  static int results[n], statuses[n];
  for (int i = 0; i < n; i++) memcpy(rs + 3 * i, r, sizeof r);
  CHECK(threads_p(1, n) == 1 && threads_p(-1, n) == 0);
  CHECK(cf_batch_p(n, rs, 3, q1, 0, q2, 0, outs, statuses, 2) == 0 &&
        outs[2 * n - 2] == out[0] && statuses[n - 1] == 0);
  CHECK(overlap_batch_p(n, rs, 3, q1, 0, q2, 0, results, NULL, 2) == 0 &&
        results[n - 1] == 1);
  CHECK(geometry_batch_p(n, rs, 3, q1, 0, q2, 0, outs, NULL, 2) == 0 &&
        outs[8 * (n - 1)] == g[0]);
  CHECK(derivatives_batch_p(n, rs, 3, q1, 0, q2, 0, outs, ds, NULL, 2) == 0 &&
        ds[21 * (n - 1)] == d[0]);

  {
    /* The index: two unit spheres 1.5 apart in a periodic box of side 10,
     * the second also through its image at x − 10. */
    void *index = NULL;
    double const box[3] = {10., 10., 10.}, unit[6] = {1., 0., 0., 1., 0., 1.};
    double const centres[6] = {0., 0., 0., 1.5, 0., 0.};
    double units[12];
    memcpy(units, unit, sizeof unit);
    memcpy(units + 6, unit, sizeof unit);
    size_t const ids[2] = {0, 1};
    size_t n = 0, pair[2], found = 9;
    int shift[3], decision = 0;
    double c[3], q[6], ml[2];
    CHECK(index_openmp_p() == 0 || index_openmp_p() == 1);
    CHECK(index_create_p(box, &index) == 0);
    CHECK(index_insert_many_p(index, 2, ids, centres, units) == 0);
    CHECK(index_insert_p(index, 2, centres + 3, unit) == 0);
    CHECK(index_remove_p(index, 2) == 0);
    CHECK(index_update_p(index, 1, centres + 3, unit) == 0);
    CHECK(index_count_p(index, &n) == 0 && n == 2);
    CHECK(index_get_p(index, 1, c, q) == 0 && c[0] == 1.5 && q[5] == 1.);
    CHECK(index_overlapping_p(index, 2, 1, pair, shift, &decision, &n) == 0);
    CHECK(n == 1 && pair[0] == 0 && pair[1] == 1 && decision == -1);
    CHECK(index_pairs_within_p(index, 1., 1, 1, pair, shift, ml, &n) == 0);
    CHECK(n == 1 && ml[0] == 0.5625);
    CHECK(index_overlap_any_p(index, centres, unit, 0, &decision, &found) == 0);
    CHECK(decision == -1 && found == 1);
    CHECK(index_overlap_any_batch_p(index, 1, centres, 3, unit, 6, ids, &decision,
                                    &found, NULL, 1) == 0);
    CHECK(decision == -1 && found == 1);
    CHECK(index_within_p(index, centres + 3, unit, 1., 1, 1, pair, shift, ml, &n) == 0);
    CHECK(n == 1 && pair[0] == 0 && ml[0] == 0.5625);
    CHECK(index_insert_p(index, 0, centres, unit) == 7); /* PW85_EINVAL */
    index_destroy_p(index);
  }

  CHECK(dlclose(lib) == 0);
  printf("dlopen: every exported function called\n");
  return 0;
}
