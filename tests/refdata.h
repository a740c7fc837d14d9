/* SPDX-License-Identifier: BSD-3-Clause */
/* The one loader of data/pw85_ref_data.h5 (layout: data/README.md), shared
 * by every test and tool that replays it. */
#ifndef PW85_TESTS_REFDATA_H
#define PW85_TESTS_REFDATA_H

#include <glib.h>
#include <stddef.h>

typedef struct {
  size_t num_radii, num_directions, num_spheroids, num_lambdas, num_distances;
  double *radii;      /* [num_radii] */
  double *directions; /* [num_directions][3] */
  double *spheroids;  /* [num_spheroids][6] */
  double *lambdas;    /* [num_lambdas] */
  double *distances;  /* [num_distances] */
  double *F;      /* [num_spheroids][num_spheroids][num_directions][num_lambdas] */
  double *MU2;    /* [num_spheroids][num_spheroids][num_directions][num_distances] */
  double *LAMBDA; /* same shape as MU2 */
} RefData;

/* The path of the reference file: the environment variable PW85_REF_DATA,
 * which meson sets for the tests. NULL when unset. */
const char *ref_data_path(void);

/* Reads every dataset; on failure returns FALSE with *error set and data
 * cleared. A file whose datasets do not have the documented shapes fails. */
gboolean ref_data_load(const char *path, RefData *data, GError **error);

/* Frees what ref_data_load() allocated. */
void ref_data_clear(RefData *data);

/* Like ref_data_load(ref_data_path(), ...) but aborts the test on failure. */
void ref_data_load_or_fail(RefData *data);

/* The general pairs of data/pw85_general_pairs.h5 (data/README.md):
 * case n is r12[n][3], q1[n][6], q2[n][6] with references MU2[n], LAMBDA[n]
 * and MU2_MINUS_1[n] (μ² − 1, correctly rounded). */
typedef struct {
  size_t count;
  double *r12, *q1, *q2, *MU2, *LAMBDA, *MU2_MINUS_1;
} GeneralPairs;

/* The path of the general pairs: the environment variable
 * PW85_GENERAL_PAIRS, which meson sets. NULL when unset. */
const char *general_pairs_path(void);

gboolean general_pairs_load(const char *path, GeneralPairs *pairs,
                            GError **error);
void general_pairs_clear(GeneralPairs *pairs);
void general_pairs_load_or_fail(GeneralPairs *pairs);

/* The hard pairs of data/pw85_hard_pairs.h5 (data/README.md): the general
 * pairs' datasets plus the class of each case (class[n] indexes
 * class_names, read from the file attribute class_names) and cond(Q1),
 * cond(Q2) computed at high precision. */
typedef struct {
  GeneralPairs pairs;
  int *klass;         /* [pairs.count] */
  double *cond1, *cond2; /* [pairs.count] */
  gchar **class_names; /* NULL-terminated */
  size_t num_classes;
} HardPairs;

/* The path of the hard pairs: the environment variable PW85_HARD_PAIRS.
 * NULL when unset. */
const char *hard_pairs_path(void);

gboolean hard_pairs_load(const char *path, HardPairs *hard, GError **error);
void hard_pairs_clear(HardPairs *hard);

/* The accuracy cases of f of data/pw85_f_cases.h5 (data/README.md): case
 * n is lambda[n], r12[n][3], q1[n][6], q2[n][6], with F[n] = f(λ)
 * correctly rounded, COND[n] = cond₂(Q(λ)) at high precision, and its
 * class klass[n] (an index into class_names, read from the file attribute
 * class_names). */
typedef struct {
  size_t count;
  double *r12, *q1, *q2, *lambda, *F, *COND;
  int *klass;          /* [count] */
  gchar **class_names; /* NULL-terminated */
  size_t num_classes;
} FCases;

/* The path of the f cases: the environment variable PW85_F_CASES, which
 * meson sets. NULL when unset. */
const char *f_cases_path(void);

gboolean f_cases_load(const char *path, FCases *cases, GError **error);
void f_cases_clear(FCases *cases);

/* Index of F[i][j][k][l] and of MU2[i][j][k][m] / LAMBDA[i][j][k][m]. */
static inline size_t ref_data_f_index(RefData const *d, size_t i, size_t j,
                                      size_t k, size_t l) {
  return ((i * d->num_spheroids + j) * d->num_directions + k) *
             d->num_lambdas + l;
}
static inline size_t ref_data_mu2_index(RefData const *d, size_t i, size_t j,
                                        size_t k, size_t m) {
  return ((i * d->num_spheroids + j) * d->num_directions + k) *
             d->num_distances + m;
}

/* r12 of MU2[.][.][k][m]: distances[m] times directions[k]. */
static inline void ref_data_r12(RefData const *d, size_t k, size_t m,
                                double r[3]) {
  for (int c = 0; c < 3; c++)
    r[c] = d->distances[m] * d->directions[3 * k + c];
}

/* The contact geometry references of data/pw85_geometry_pairs.h5
 * (data/README.md): the environment variable PW85_GEOMETRY_PAIRS. */
const char *geometry_pairs_path(void);

/* Reads dataset `name` of the HDF5 file at `path`, of rank 1 (cols = 1) or
 * rank 2 with `cols` columns, into a new array (g_free it) of *rows × cols
 * doubles, row by row. */
gboolean ref_read_columns(const char *path, const char *name, size_t cols,
                          size_t *rows, double **data, GError **error);

/* The comma-separated attribute `class_names` of the root of the HDF5
 * file at `path` (env_name: the variable it came from, for the message),
 * split: a NULL-terminated vector (g_strfreev it), or NULL with *error
 * set. */
gchar **ref_read_class_names(const char *path, const char *env_name,
                             GError **error);

#endif /* PW85_TESTS_REFDATA_H */
