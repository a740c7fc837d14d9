/* SPDX-License-Identifier: BSD-3-Clause */
/* One definiteness rule, the same answer from every entry point (pw85.h,
 * "Positive definite, as stored"): each form of data/pw85_definite_forms.txt,
 * whose verdict was decided exactly in rational arithmetic by
 * data/gen_definite.py (not by pw85), through every function that takes a
 * form. A form that is not positive definite must be refused
 * (PW85_ENOTPOSDEF, NaN where a function returns a double), one that is
 * must never be refused as not positive definite (an ill-conditioned one
 * may meet PW85_ERANGE where it must be factorised). */
#include <glib.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "pw85.h"
#include "pw85_index.h"
#ifdef PW85_TEST_LEGACY
#include "pw85_legacy.h"
#endif

typedef struct {
  int definite;
  double q[PW85_SYM];
} Form;

static Form *forms;
static size_t n_forms;

static void load_forms(void) {
  gchar *path = g_strdup(g_getenv("PW85_DEFINITE_FORMS"));
  if (path == NULL) g_error("PW85_DEFINITE_FORMS is not set (meson test sets it)");
  FILE *f = fopen(path, "r");
  if (f == NULL) g_error("cannot open %s", path);
  char line[512];
  size_t cap = 0;
  while (fgets(line, sizeof line, f) != NULL) {
    if (line[0] == '#') continue;
    if (n_forms == cap) {
      cap = cap ? 2 * cap : 1024;
      forms = g_renew(Form, forms, cap);
    }
    Form *form = &forms[n_forms];
    char *p = line, *end = NULL;
    form->definite = (int)strtol(p, &end, 10);
    for (int k = 0; k < PW85_SYM; k++) {
      p = end;
      form->q[k] = strtod(p, &end); /* hexadecimal floats: exact */
      if (end == p) g_error("%s: bad line %zu", path, n_forms + 1);
    }
    n_forms++;
  }
  fclose(f);
  g_free(path);
  /* The file holds both verdicts in numbers (gen_definite.py). */
  g_assert_cmpuint(n_forms, >, 2000);
}

static double const unit[PW85_SYM] = {1, 0, 0, 1, 0, 1};
static double const ex[PW85_DIM] = {1, 0, 0};

/* status of a function for a form known (not) positive definite */
static void check_status(char const *what, Form const *form, int status) {
  if (!form->definite && status != PW85_ENOTPOSDEF)
    g_test_fail_printf("%s accepts an indefinite form (status %d): q = {%a, "
                       "%a, %a, %a, %a, %a}",
                       what, status, form->q[0], form->q[1], form->q[2],
                       form->q[3], form->q[4], form->q[5]);
  if (form->definite && status == PW85_ENOTPOSDEF)
    g_test_fail_printf("%s refuses a positive definite form: q = {%a, %a, "
                       "%a, %a, %a, %a}",
                       what, form->q[0], form->q[1], form->q[2], form->q[3],
                       form->q[4], form->q[5]);
}

/* Functions without a status, which answer NaN for a form that is not
 * positive definite, and also where they must factorise one that is but
 * is singular to the precision of double (pw85.h): one direction only. */
static void check_nan(char const *what, Form const *form, double value) {
  if (!form->definite && !isnan(value))
    g_test_fail_printf("%s accepts an indefinite form (%a): q = {%a, %a, %a, "
                       "%a, %a, %a}",
                       what, value, form->q[0], form->q[1], form->q[2],
                       form->q[3], form->q[4], form->q[5]);
}

static void test_pair_functions(void) {
  for (size_t i = 0; i < n_forms; i++) {
    Form const *form = &forms[i];
    double out[2], geometry[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
    int result;
    /* the form as q1 and as q2, against the unit sphere and itself */
    check_status("contact_function(q, I)", form,
                 pw85_contact_function(ex, form->q, unit, out));
    check_status("contact_function(I, q)", form,
                 pw85_contact_function(ex, unit, form->q, out));
    check_status("contact_function(q, q)", form,
                 pw85_contact_function(ex, form->q, form->q, out));
    check_status("overlap(q, I)", form,
                 pw85_overlap(ex, form->q, unit, &result));
    check_status("overlap(I, q)", form,
                 pw85_overlap(ex, unit, form->q, &result));
    check_status("contact_geometry", form,
                 pw85_contact_geometry(ex, form->q, unit, geometry));
    check_status("contact_derivatives", form,
                 pw85_contact_derivatives(ex, unit, form->q, geometry, d));
    /* A zero r12 and one that underflows in the scaled problem. */
    double const zero[PW85_DIM] = {0, 0, 0};
    double const tiny[PW85_DIM] = {0, 0x1p-1060, 0x1p-1070};
    check_status("contact_function(r = 0)", form,
                 pw85_contact_function(zero, form->q, unit, out));
    check_status("overlap(r tiny)", form,
                 pw85_overlap(tiny, unit, form->q, &result));
  }
}

static void test_batches(void) {
  size_t const n = n_forms;
  double *q = g_new(double, PW85_SYM * n);
  double *out = g_new(double, 2 * n);
  int *status = g_new(int, n), *result = g_new(int, n);
  for (size_t i = 0; i < n; i++)
    for (int k = 0; k < PW85_SYM; k++) q[PW85_SYM * i + k] = forms[i].q[k];
  pw85_contact_function_batch(n, ex, 0, q, PW85_SYM, unit, 0, out, status, 1);
  for (size_t i = 0; i < n; i++)
    check_status("contact_function_batch", &forms[i], status[i]);
  pw85_overlap_batch(n, ex, 0, unit, 0, q, PW85_SYM, result, status, 2);
  for (size_t i = 0; i < n; i++)
    check_status("overlap_batch", &forms[i], status[i]);
  double *a = g_new(double, PW85_DIM * n), *rot = g_new(double, 9 * n);
  pw85_principal_axes_batch(n, q, PW85_SYM, a, rot, status, 1);
  for (size_t i = 0; i < n; i++)
    check_status("principal_axes_batch", &forms[i], status[i]);
  g_free(a);
  g_free(rot);
  g_free(q);
  g_free(out);
  g_free(status);
  g_free(result);
}

static void test_form_functions(void) {
  for (size_t i = 0; i < n_forms; i++) {
    Form const *form = &forms[i];
    double a[PW85_DIM], rot[9], l[PW85_SYM];
    check_status("principal_axes", form, pw85_principal_axes(form->q, a, rot));
    pw85__cholesky_decomp(form->q, l);
    check_nan("cholesky_decomp", form, l[0]);
    /* pw85_f_neg, λ inside (0, 1) and at both ends */
    double params[15] = {1, 0, 0};
    for (int k = 0; k < PW85_SYM; k++) {
      params[3 + k] = form->q[k];
      params[9 + k] = unit[k];
    }
    check_nan("f_neg(q, I)", form, pw85_f_neg(0.5, params));
    check_nan("f_neg(q, I), λ = 1", form, pw85_f_neg(1.0, params));
  }
}

static void test_index(void) {
  pw85_index *index = NULL;
  g_assert_cmpint(pw85_index_create(NULL, &index), ==, PW85_SUCCESS);
  double const c[PW85_DIM] = {0, 0, 0};
  for (size_t i = 0; i < n_forms; i++) {
    int const s = pw85_index_insert(index, i, c, forms[i].q);
    check_status("index_insert", &forms[i], s);
  }
  pw85_index_destroy(index);
}

#ifdef PW85_TEST_LEGACY
static void test_legacy(void) {
  for (size_t i = 0; i < n_forms; i++) {
    Form const *form = &forms[i];
    double out[3];
    check_status("legacy_contact_function1", form,
                 pw85_legacy_contact_function1(ex, form->q, unit, out));
    check_status("legacy_contact_function2", form,
                 pw85_legacy_contact_function2(ex, unit, form->q, out));
    check_nan("legacy_f1", form, pw85_legacy_f1(0.5, ex, form->q, unit, out));
    check_nan("legacy_f2", form, pw85_legacy_f2(0.5, ex, unit, form->q, out));
  }
}
#endif

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  load_forms();
  g_test_add_func("/pw85/definite/pair-functions", test_pair_functions);
  g_test_add_func("/pw85/definite/batches", test_batches);
  g_test_add_func("/pw85/definite/form-functions", test_form_functions);
  g_test_add_func("/pw85/definite/index", test_index);
#ifdef PW85_TEST_LEGACY
  g_test_add_func("/pw85/definite/legacy", test_legacy);
#endif
  int const status = g_test_run();
  g_free(forms);
  return status;
}
