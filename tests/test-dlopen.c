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
  index_create_fn index_create_p;
  index_destroy_fn index_destroy_p;
  index_openmp_fn index_openmp_p;
  index_count_fn index_count_p;
  index_insert_fn index_insert_p, index_update_p;
  index_insert_many_fn index_insert_many_p;
  index_remove_fn index_remove_p;
  index_get_fn index_get_p;
  index_overlap_any_fn index_overlap_any_p;
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
  CHECK(index_within_p(index, centres + 3, unit, 1., 1, 1, pair, shift, ml, &n) == 0);
  CHECK(n == 1 && pair[0] == 0 && ml[0] == 0.5625);
  CHECK(index_insert_p(index, 0, centres, unit) == 7); /* PW85_EINVAL */
  index_destroy_p(index);

  CHECK(dlclose(lib) == 0);
  printf("dlopen: every exported function called\n");
  return 0;
}
