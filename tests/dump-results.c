/* SPDX-License-Identifier: BSD-3-Clause */
/* Every answer of the library on the data files, written raw to one binary
 * file, so that two runs can be compared byte for byte (tests/test-nofma.sh
 * compares a native run, FMA clones, with a run under qemu-x86_64 -cpu
 * Nehalem, default clones). Usage:
 *   dump-results OUT REF_DATA GENERAL_PAIRS HARD_PAIRS FINISH_PAIRS F_CASES
 *                PAIRS_2D
 * Records, in this order, native byte order:
 *   - pw85_ref_data.h5: for every MU2[i][j][k][m], the status and out[2] of
 *     pw85_contact_function, the status and answer of pw85_overlap; for
 *     every F[i][j][k][l], pw85_f_neg(lambdas[l]) and pw85__residual;
 *   - each pairs file (general, hard, finish): per pair, contact function
 *     and overlap as above, then pw85_f_neg and pw85__residual at the
 *     reference λ;
 *   - pw85_f_cases.h5: per case, pw85_f_neg and pw85__residual at its λ;
 *   - pw85_2d_pairs.h5 (ellipses, pw85_2d.h): per pair, the status and
 *     outputs of pw85_2d_contact_derivatives (geometry and derivatives),
 *     of pw85_2d_contact_function and of pw85_2d_overlap, and
 *     pw85_2d_f_neg at the reference λ.
 * Statuses are recorded, not checked: the test programs check them; this
 * program only makes every difference visible. */
#include <pw85.h>
#include <pw85/pw85_2d.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "refdata.h"

static FILE *out;

static void put(void const *p, size_t size) {
  if (fwrite(p, 1, size, out) != size) {
    perror("dump-results: write");
    exit(1);
  }
}

static void pair(double const r[PW85_DIM], double const q1[PW85_SYM],
                 double const q2[PW85_SYM]) {
  double res[2] = {0., 0.};
  int const status = pw85_contact_function(r, q1, q2, res);
  put(&status, sizeof status);
  put(res, sizeof res);
  int answer = -1;
  int const ostatus = pw85_overlap(r, q1, q2, &answer);
  put(&ostatus, sizeof ostatus);
  put(&answer, sizeof answer);
}

static void f_at(double lambda, double const r[PW85_DIM],
                 double const q1[PW85_SYM], double const q2[PW85_SYM]) {
  double params[PW85_DIM + 2 * PW85_SYM];
  memcpy(params, r, PW85_DIM * sizeof(double));
  memcpy(params + PW85_DIM, q1, PW85_SYM * sizeof(double));
  memcpy(params + PW85_DIM + PW85_SYM, q2, PW85_SYM * sizeof(double));
  double const f = pw85_f_neg(lambda, params);
  put(&f, sizeof f);
  double residual[3];
  pw85__residual(lambda, r, q1, q2, residual);
  put(residual, sizeof residual);
}

static void fail(char const *path, GError *error) {
  fprintf(stderr, "dump-results: %s: %s\n", path, error->message);
  exit(1);
}

static size_t dump_ref_data(char const *path) {
  RefData d;
  GError *error = NULL;
  if (!ref_data_load(path, &d, &error)) fail(path, error);
  size_t n = 0;
  for (size_t i = 0; i < d.num_spheroids; i++)
    for (size_t j = 0; j < d.num_spheroids; j++)
      for (size_t k = 0; k < d.num_directions; k++) {
        double const *q1 = d.spheroids + 6 * i, *q2 = d.spheroids + 6 * j;
        for (size_t m = 0; m < d.num_distances; m++, n++) {
          double r[PW85_DIM];
          ref_data_r12(&d, k, m, r);
          pair(r, q1, q2);
        }
        for (size_t l = 0; l < d.num_lambdas; l++, n++)
          f_at(d.lambdas[l], d.directions + 3 * k, q1, q2);
      }
  ref_data_clear(&d);
  return n;
}

static size_t dump_pairs(GeneralPairs const *p) {
  for (size_t n = 0; n < p->count; n++) {
    double const *r = p->r12 + 3 * n;
    double const *q1 = p->q1 + 6 * n, *q2 = p->q2 + 6 * n;
    pair(r, q1, q2);
    f_at(p->LAMBDA[n], r, q1, q2);
  }
  return p->count;
}

static size_t dump_general_pairs(char const *path) {
  GeneralPairs p;
  GError *error = NULL;
  if (!general_pairs_load(path, &p, &error)) fail(path, error);
  size_t const n = dump_pairs(&p);
  general_pairs_clear(&p);
  return n;
}

static size_t dump_hard_pairs(char const *path) {
  HardPairs h;
  GError *error = NULL;
  if (!hard_pairs_load(path, &h, &error)) fail(path, error);
  size_t const n = dump_pairs(&h.pairs);
  hard_pairs_clear(&h);
  return n;
}

static size_t dump_f_cases(char const *path) {
  FCases c;
  GError *error = NULL;
  if (!f_cases_load(path, &c, &error)) fail(path, error);
  for (size_t n = 0; n < c.count; n++)
    f_at(c.lambda[n], c.r12 + 3 * n, c.q1 + 6 * n, c.q2 + 6 * n);
  size_t const count = c.count;
  f_cases_clear(&c);
  return count;
}

static size_t dump_2d_pairs(char const *path) {
  GError *error = NULL;
  size_t n = 0, rows = 0;
  double *r = NULL, *q1 = NULL, *q2 = NULL, *lambda = NULL;
  if (!ref_read_columns(path, "R12", 2, &n, &r, &error) ||
      !ref_read_columns(path, "Q1", 3, &rows, &q1, &error) ||
      !ref_read_columns(path, "Q2", 3, &rows, &q2, &error) ||
      !ref_read_columns(path, "LAMBDA", 1, &rows, &lambda, &error))
    fail(path, error);
  for (size_t k = 0; k < n; k++) {
    double const *rk = r + 2 * k, *a = q1 + 3 * k, *b = q2 + 3 * k;
    double g[PW85_2D_GEOM_SIZE] = {0.}, d[PW85_2D_DERIV_SIZE] = {0.};
    int const gstatus = pw85_2d_contact_derivatives(rk, a, b, g, d);
    put(&gstatus, sizeof gstatus);
    put(g, sizeof g);
    put(d, sizeof d);
    double res[2] = {0., 0.};
    int const status = pw85_2d_contact_function(rk, a, b, res);
    put(&status, sizeof status);
    put(res, sizeof res);
    int answer = -1;
    int const ostatus = pw85_2d_overlap(rk, a, b, &answer);
    put(&ostatus, sizeof ostatus);
    put(&answer, sizeof answer);
    double params[PW85_2D_DIM + 2 * PW85_2D_SYM];
    memcpy(params, rk, 2 * sizeof(double));
    memcpy(params + 2, a, 3 * sizeof(double));
    memcpy(params + 5, b, 3 * sizeof(double));
    double const f = pw85_2d_f_neg(lambda[k], params);
    put(&f, sizeof f);
  }
  g_free(r), g_free(q1), g_free(q2), g_free(lambda);
  return n;
}

int main(int argc, char **argv) {
  if (argc != 8) {
    fprintf(stderr, "usage: %s OUT REF_DATA GENERAL_PAIRS HARD_PAIRS "
                    "FINISH_PAIRS F_CASES PAIRS_2D\n", argv[0]);
    return 2;
  }
  out = fopen(argv[1], "wb");
  if (out == NULL) {
    perror(argv[1]);
    return 1;
  }
  size_t const counts[6] = {
      dump_ref_data(argv[2]),     dump_general_pairs(argv[3]),
      dump_hard_pairs(argv[4]),   dump_general_pairs(argv[5]),
      dump_f_cases(argv[6]),      dump_2d_pairs(argv[7])};
  if (fclose(out) != 0) {
    perror(argv[1]);
    return 1;
  }
  printf("records: ref-data %zu, general %zu, hard %zu, finish %zu, "
         "f-cases %zu, 2d pairs %zu\n",
         counts[0], counts[1], counts[2], counts[3], counts[4], counts[5]);
  return 0;
}
