/* SPDX-License-Identifier: BSD-3-Clause */
/* The accuracy comparison of docs/implementation.rst, "Accuracy": histograms of the number of
 * correct decimal digits, prec = floor(−log10(relative error)) in bins
 * 0..16 (an exact result goes to the top bin), of
 * - f over the whole dataset F of data/pw85_ref_data.h5, for
 *   implementation #1 (−pw85_f_neg, libpw85), implementation #2
 *   (pw85_legacy_f2, rational fraction) and, for reference, the plain
 *   Cholesky implementation of the seed (pw85_legacy_f1);
 * - μ² over the whole dataset MU2, for pw85_contact_function and the two
 *   legacy contact functions.
 * Writes OUTDIR/accuracy-f.csv and OUTDIR/accuracy-mu2.csv (percentages)
 * and prints a summary.
 * Usage: accuracy-report DATA.h5 OUTDIR */
#include <errno.h>
#include <pw85_legacy.h>
#include <stdio.h>
#include <string.h>

#include <math.h>
#include "refdata.h"

#define NUM_BINS 17

/* The bin of one result: the number of correct digits, 0 to 16. */
static int digits(double act, double exp) {
  if (act == exp) return NUM_BINS - 1; /* also exp = act = 0 */
  double const err = fabs((act - exp) / exp);
  if (!(err > 0.)) return isnan(err) ? 0 : NUM_BINS - 1;
  double const prec = floor(-log10(err));
  if (!(prec > 0.)) return 0; /* also NaN and exp = 0 ≠ act */
  return prec >= NUM_BINS - 1 ? NUM_BINS - 1 : (int)prec;
}

typedef struct {
  const char *column;
  size_t count[NUM_BINS];
  size_t total;
} Histogram;

static void add(Histogram *h, double act, double exp) {
  h->count[digits(act, exp)]++;
  h->total++;
}

static double percent(Histogram const *h, int bin) {
  return 100. * (double)h->count[bin] / (double)h->total;
}

static int write_csv(const char *path, Histogram const *hs, size_t n) {
  FILE *file = fopen(path, "w");
  if (file == NULL) {
    fprintf(stderr, "accuracy-report: cannot write %s: %s\n", path,
            strerror(errno));
    return 1;
  }
  fprintf(file, "digits");
  for (size_t k = 0; k < n; k++) fprintf(file, ",%s", hs[k].column);
  fprintf(file, "\n");
  for (int bin = 0; bin < NUM_BINS; bin++) {
    fprintf(file, "%d", bin);
    for (size_t k = 0; k < n; k++) fprintf(file, ",%.6f", percent(&hs[k], bin));
    fprintf(file, "\n");
  }
  if (fclose(file) != 0) {
    fprintf(stderr, "accuracy-report: cannot write %s\n", path);
    return 1;
  }
  return 0;
}

static void print_summary(const char *title, Histogram const *hs, size_t n) {
  printf("%s (%zu cases; percent of cases per number of correct digits)\n",
         title, hs[0].total);
  printf("%6s", "digits");
  for (size_t k = 0; k < n; k++) printf(" %32s", hs[k].column);
  printf("\n");
  for (int bin = 0; bin < NUM_BINS; bin++) {
    printf("%6d", bin);
    for (size_t k = 0; k < n; k++) printf(" %32.4f", percent(&hs[k], bin));
    printf("\n");
  }
}

int main(int argc, char **argv) {
  if (argc != 3) {
    fprintf(stderr, "usage: %s DATA.h5 OUTDIR\n", argv[0]);
    return 2;
  }
  RefData d;
  GError *error = NULL;
  if (!ref_data_load(argv[1], &d, &error)) {
    fprintf(stderr, "accuracy-report: %s\n", error->message);
    g_error_free(error);
    return 1;
  }

  Histogram hf[3] = {{"percent_impl1", {0}, 0},
                     {"percent_impl2", {0}, 0},
                     {"percent_impl1_plain", {0}, 0}};
  Histogram hm[3] = {{"percent_contact_function", {0}, 0},
                     {"percent_legacy_contact_function1", {0}, 0},
                     {"percent_legacy_contact_function2", {0}, 0}};
  double params[PW85_DIM + 2 * PW85_SYM];
  for (size_t i = 0; i < d.num_spheroids; i++) {
    memcpy(params + PW85_DIM, d.spheroids + PW85_SYM * i,
           PW85_SYM * sizeof(double));
    for (size_t j = 0; j < d.num_spheroids; j++) {
      double const *q1 = params + PW85_DIM;
      double const *q2 = params + PW85_DIM + PW85_SYM;
      memcpy(params + PW85_DIM + PW85_SYM, d.spheroids + PW85_SYM * j,
             PW85_SYM * sizeof(double));
      for (size_t k = 0; k < d.num_directions; k++) {
        double const *dir = d.directions + PW85_DIM * k;
        memcpy(params, dir, PW85_DIM * sizeof(double));
        for (size_t l = 0; l < d.num_lambdas; l++) {
          double const exp = d.F[ref_data_f_index(&d, i, j, k, l)];
          double const lambda = d.lambdas[l];
          add(&hf[0], -pw85_f_neg(lambda, params), exp);
          add(&hf[1], pw85_legacy_f2(lambda, params, q1, q2, NULL), exp);
          add(&hf[2], pw85_legacy_f1(lambda, params, q1, q2, NULL), exp);
        }
        for (size_t m = 0; m < d.num_distances; m++) {
          double const exp = d.MU2[ref_data_mu2_index(&d, i, j, k, m)];
          double r[PW85_DIM], out[2] = {NAN, NAN};
          for (int c = 0; c < PW85_DIM; c++) r[c] = d.distances[m] * dir[c];
          /* A failed call counts with out[0] as it is (NaN: 0 digits). */
          pw85_contact_function(r, q1, q2, out);
          add(&hm[0], out[0], exp);
          out[0] = NAN;
          pw85_legacy_contact_function1(r, q1, q2, out);
          add(&hm[1], out[0], exp);
          out[0] = NAN;
          pw85_legacy_contact_function2(r, q1, q2, out);
          add(&hm[2], out[0], exp);
        }
      }
    }
  }
  ref_data_clear(&d);

  print_summary("f", hf, 3);
  print_summary("mu2", hm, 3);
  char *path_f = g_build_filename(argv[2], "accuracy-f.csv", NULL);
  char *path_mu2 = g_build_filename(argv[2], "accuracy-mu2.csv", NULL);
  int const status = write_csv(path_f, hf, 3) | write_csv(path_mu2, hm, 3);
  if (status == 0) printf("wrote %s and %s\n", path_f, path_mu2);
  g_free(path_f);
  g_free(path_mu2);
  return status;
}
