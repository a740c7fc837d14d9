/* SPDX-License-Identifier: BSD-3-Clause */
#include "refdata.h"

#include <hdf5.h>
#include <hdf5_hl.h>
#include <stdlib.h>
#include <string.h>

#define REF_DATA_ERROR (g_quark_from_static_string("pw85-ref-data"))

const char *ref_data_path(void) { return g_getenv("PW85_REF_DATA"); }

/* Reads dataset `name`, which must have `rank` dimensions; its dimensions
 * go to dims[]. */
static gboolean read_dataset(hid_t file, const char *name, int rank,
                             hsize_t dims[], double **buffer,
                             GError **error) {
  int actual_rank = -1;
  if (H5LTget_dataset_ndims(file, name, &actual_rank) < 0 ||
      actual_rank != rank) {
    g_set_error(error, REF_DATA_ERROR, 1, "%s: missing, or rank %d != %d",
                name, actual_rank, rank);
    return FALSE;
  }
  if (H5LTget_dataset_info(file, name, dims, NULL, NULL) < 0) {
    g_set_error(error, REF_DATA_ERROR, 1, "%s: cannot read its shape", name);
    return FALSE;
  }
  size_t size = 1;
  for (int i = 0; i < rank; i++) size *= dims[i];
  *buffer = g_new(double, size);
  if (H5LTread_dataset_double(file, name, *buffer) < 0) {
    g_set_error(error, REF_DATA_ERROR, 1, "%s: cannot read it", name);
    return FALSE;
  }
  return TRUE;
}

static gboolean expect(gboolean ok, const char *what, GError **error) {
  if (!ok) g_set_error(error, REF_DATA_ERROR, 2, "unexpected shape: %s", what);
  return ok;
}

/* Opens `path` (from the environment variable `var`) for reading, with
 * HDF5's own error printing off (errors come back as GError); a negative
 * id, with *error set, when path is NULL or the file does not open. */
static hid_t open_file(const char *path, const char *var, GError **error) {
  if (path == NULL) {
    g_set_error(error, REF_DATA_ERROR, 3, "%s is not set", var);
    return -1;
  }
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t const file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) g_set_error(error, REF_DATA_ERROR, 4, "cannot open %s", path);
  return file;
}

/* The comma-separated root attribute class_names of an open file, split
 * into *names (NULL-terminated; g_strfreev it); FALSE with *error set. */
static gboolean read_class_names(hid_t file, gchar ***names,
                                 GError **error) {
  hsize_t dims[1];
  H5T_class_t type_class;
  size_t type_size = 0;
  *names = NULL;
  if (!expect(H5LTget_attribute_info(file, "/", "class_names", dims,
                                     &type_class, &type_size) >= 0 &&
                  type_class == H5T_STRING,
              "attribute class_names", error))
    return FALSE;
  char *joined = g_malloc0(type_size + 1);
  gboolean const ok = expect(
      H5LTget_attribute_string(file, "/", "class_names", joined) >= 0,
      "attribute class_names", error);
  if (ok) *names = g_strsplit(joined, ",", -1);
  g_free(joined);
  return ok;
}

gboolean ref_data_load(const char *path, RefData *d, GError **error) {
  memset(d, 0, sizeof *d);
  hid_t const file = open_file(path, "PW85_REF_DATA", error);
  if (file < 0) return FALSE;
  hsize_t dims[4];
  gboolean ok =
      read_dataset(file, "/radii", 1, dims, &d->radii, error) &&
      (d->num_radii = dims[0], TRUE) &&
      read_dataset(file, "/directions", 2, dims, &d->directions, error) &&
      (d->num_directions = dims[0], expect(dims[1] == 3, "directions", error)) &&
      read_dataset(file, "/spheroids", 2, dims, &d->spheroids, error) &&
      (d->num_spheroids = dims[0], expect(dims[1] == 6, "spheroids", error)) &&
      read_dataset(file, "/lambdas", 1, dims, &d->lambdas, error) &&
      (d->num_lambdas = dims[0], TRUE) &&
      read_dataset(file, "/distances", 1, dims, &d->distances, error) &&
      (d->num_distances = dims[0], TRUE) &&
      read_dataset(file, "/F", 4, dims, &d->F, error) &&
      expect(dims[0] == d->num_spheroids && dims[1] == d->num_spheroids &&
                 dims[2] == d->num_directions && dims[3] == d->num_lambdas,
             "F", error) &&
      read_dataset(file, "/MU2", 4, dims, &d->MU2, error) &&
      expect(dims[0] == d->num_spheroids && dims[1] == d->num_spheroids &&
                 dims[2] == d->num_directions && dims[3] == d->num_distances,
             "MU2", error) &&
      read_dataset(file, "/LAMBDA", 4, dims, &d->LAMBDA, error) &&
      expect(dims[0] == d->num_spheroids && dims[1] == d->num_spheroids &&
                 dims[2] == d->num_directions && dims[3] == d->num_distances,
             "LAMBDA", error);
  H5Fclose(file);
  if (!ok) ref_data_clear(d);
  return ok;
}

void ref_data_clear(RefData *d) {
  g_free(d->radii);
  g_free(d->directions);
  g_free(d->spheroids);
  g_free(d->lambdas);
  g_free(d->distances);
  g_free(d->F);
  g_free(d->MU2);
  g_free(d->LAMBDA);
  memset(d, 0, sizeof *d);
}

void ref_data_load_or_fail(RefData *d) {
  GError *error = NULL;
  if (!ref_data_load(ref_data_path(), d, &error))
    g_error("reference data: %s", error->message);
  g_assert_cmpuint(d->num_spheroids, >, 0);
  g_assert_cmpuint(d->num_directions, >, 0);
}

const char *general_pairs_path(void) { return g_getenv("PW85_GENERAL_PAIRS"); }

gboolean general_pairs_load(const char *path, GeneralPairs *g,
                            GError **error) {
  memset(g, 0, sizeof *g);
  hid_t const file = open_file(path, "PW85_GENERAL_PAIRS", error);
  if (file < 0) return FALSE;
  hsize_t dims[2];
  gboolean ok =
      read_dataset(file, "/MU2", 1, dims, &g->MU2, error) &&
      (g->count = dims[0], TRUE) &&
      read_dataset(file, "/LAMBDA", 1, dims, &g->LAMBDA, error) &&
      expect(dims[0] == g->count, "LAMBDA", error) &&
      read_dataset(file, "/MU2_MINUS_1", 1, dims, &g->MU2_MINUS_1, error) &&
      expect(dims[0] == g->count, "MU2_MINUS_1", error) &&
      read_dataset(file, "/r12", 2, dims, &g->r12, error) &&
      expect(dims[0] == g->count && dims[1] == 3, "r12", error) &&
      read_dataset(file, "/q1", 2, dims, &g->q1, error) &&
      expect(dims[0] == g->count && dims[1] == 6, "q1", error) &&
      read_dataset(file, "/q2", 2, dims, &g->q2, error) &&
      expect(dims[0] == g->count && dims[1] == 6, "q2", error);
  H5Fclose(file);
  if (!ok) general_pairs_clear(g);
  return ok;
}

void general_pairs_clear(GeneralPairs *g) {
  g_free(g->r12);
  g_free(g->q1);
  g_free(g->q2);
  g_free(g->MU2);
  g_free(g->LAMBDA);
  g_free(g->MU2_MINUS_1);
  memset(g, 0, sizeof *g);
}

void general_pairs_load_or_fail(GeneralPairs *g) {
  GError *error = NULL;
  if (!general_pairs_load(general_pairs_path(), g, &error))
    g_error("general pairs: %s", error->message);
  g_assert_cmpuint(g->count, >, 0);
}

const char *hard_pairs_path(void) { return g_getenv("PW85_HARD_PAIRS"); }

gboolean hard_pairs_load(const char *path, HardPairs *h, GError **error) {
  memset(h, 0, sizeof *h);
  if (path == NULL) {
    g_set_error(error, REF_DATA_ERROR, 3, "PW85_HARD_PAIRS is not set");
    return FALSE;
  }
  if (!general_pairs_load(path, &h->pairs, error)) return FALSE;
  hid_t const file = open_file(path, "PW85_HARD_PAIRS", error);
  if (file < 0) {
    general_pairs_clear(&h->pairs);
    return FALSE;
  }
  size_t const n = h->pairs.count;
  hsize_t dims[1];
  int rank = -1;
  gboolean ok =
      read_dataset(file, "/cond1", 1, dims, &h->cond1, error) &&
      expect(dims[0] == n, "cond1", error) &&
      read_dataset(file, "/cond2", 1, dims, &h->cond2, error) &&
      expect(dims[0] == n, "cond2", error) &&
      expect(H5LTget_dataset_ndims(file, "/class", &rank) >= 0 && rank == 1 &&
                 H5LTget_dataset_info(file, "/class", dims, NULL, NULL) >= 0 &&
                 dims[0] == n,
             "class", error) &&
      (h->klass = g_new(int, n), TRUE) &&
      expect(H5LTread_dataset_int(file, "/class", h->klass) >= 0, "class",
             error) &&
      read_class_names(file, &h->class_names, error);
  H5Fclose(file);
  if (ok) {
    h->num_classes = g_strv_length(h->class_names);
    for (size_t i = 0; ok && i < n; i++)
      ok = expect(h->klass[i] >= 0 && (size_t)h->klass[i] < h->num_classes,
                  "class out of range", error);
  }
  if (!ok) hard_pairs_clear(h);
  return ok;
}

void hard_pairs_clear(HardPairs *h) {
  general_pairs_clear(&h->pairs);
  g_free(h->klass);
  g_free(h->cond1);
  g_free(h->cond2);
  g_strfreev(h->class_names);
  memset(h, 0, sizeof *h);
}

const char *f_cases_path(void) { return g_getenv("PW85_F_CASES"); }

gboolean f_cases_load(const char *path, FCases *c, GError **error) {
  memset(c, 0, sizeof *c);
  hid_t const file = open_file(path, "PW85_F_CASES", error);
  if (file < 0) return FALSE;
  hsize_t dims[2];
  int rank = -1;
  gboolean ok =
      read_dataset(file, "/F", 1, dims, &c->F, error) &&
      (c->count = dims[0], TRUE) &&
      read_dataset(file, "/lambda", 1, dims, &c->lambda, error) &&
      expect(dims[0] == c->count, "lambda", error) &&
      read_dataset(file, "/COND", 1, dims, &c->COND, error) &&
      expect(dims[0] == c->count, "COND", error) &&
      read_dataset(file, "/r12", 2, dims, &c->r12, error) &&
      expect(dims[0] == c->count && dims[1] == 3, "r12", error) &&
      read_dataset(file, "/q1", 2, dims, &c->q1, error) &&
      expect(dims[0] == c->count && dims[1] == 6, "q1", error) &&
      read_dataset(file, "/q2", 2, dims, &c->q2, error) &&
      expect(dims[0] == c->count && dims[1] == 6, "q2", error) &&
      expect(H5LTget_dataset_ndims(file, "/class", &rank) >= 0 && rank == 1 &&
                 H5LTget_dataset_info(file, "/class", dims, NULL, NULL) >= 0 &&
                 dims[0] == c->count,
             "class", error) &&
      (c->klass = g_new(int, c->count), TRUE) &&
      expect(H5LTread_dataset_int(file, "/class", c->klass) >= 0, "class",
             error) &&
      read_class_names(file, &c->class_names, error);
  H5Fclose(file);
  if (ok) {
    c->num_classes = g_strv_length(c->class_names);
    for (size_t i = 0; ok && i < c->count; i++)
      ok = expect(c->klass[i] >= 0 && (size_t)c->klass[i] < c->num_classes,
                  "class out of range", error);
  }
  if (!ok) f_cases_clear(c);
  return ok;
}

void f_cases_clear(FCases *c) {
  g_free(c->r12);
  g_free(c->q1);
  g_free(c->q2);
  g_free(c->lambda);
  g_free(c->F);
  g_free(c->COND);
  g_free(c->klass);
  g_strfreev(c->class_names);
  memset(c, 0, sizeof *c);
}

const char *geometry_pairs_path(void) {
  return g_getenv("PW85_GEOMETRY_PAIRS");
}

gboolean ref_read_columns(const char *path, const char *name, size_t cols,
                          size_t *rows, double **data, GError **error) {
  *data = NULL;
  hid_t const file = open_file(path, name, error);
  if (file < 0) return FALSE;
  int rank = -1;
  gboolean ok = H5LTget_dataset_ndims(file, name, &rank) >= 0 &&
                (rank == 1 || rank == 2);
  hsize_t dims[2] = {0, 1};
  ok = ok && H5LTget_dataset_info(file, name, dims, NULL, NULL) >= 0;
  if (ok && rank == 1) dims[1] = 1;
  if (!ok || dims[1] != cols) {
    g_set_error(error, REF_DATA_ERROR, 2, "%s: missing, or not %zu columns",
                name, cols);
    H5Fclose(file);
    return FALSE;
  }
  ok = read_dataset(file, name, rank, dims, data, error);
  H5Fclose(file);
  *rows = (size_t)dims[0];
  return ok;
}

gchar **ref_read_class_names(const char *path, const char *env_name,
                             GError **error) {
  hid_t const file = open_file(path, env_name, error);
  if (file < 0) return NULL;
  gchar **names = NULL;
  read_class_names(file, &names, error);
  H5Fclose(file);
  return names;
}
