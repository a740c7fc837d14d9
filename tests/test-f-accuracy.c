/* SPDX-License-Identifier: BSD-3-Clause */
/* The accuracy of f(λ) = −pw85_f_neg(λ, params) as cond(Q(λ)) grows
 * (issue 13, item 1: f within one ulp for cond(Q(λ)) up to 1e16), on the
 * cases of data/pw85_f_cases.h5 (data/README.md: 300 seeded cases per
 * decade of cond(Q(λ)) from 1e0 to 1e16, in six classes; F correctly
 * rounded for the stored doubles, from mpmath at 100 digits and exact
 * rational arithmetic). One test per decade,
 * /pw85/f_neg/accuracy/cond-1eK, for the cases with 1eK ≤ COND < 1e(K+1):
 *   - |f − F| ≤ 1 ulp of F (the spacing of the doubles above F);
 *   - below cond 1e12, f == F: correctly rounded (the measured behaviour
 *     of the compensated f, refined from the double factors up to 1e10 and
 *     factorised in double-double beyond).
 * Every failing case is reported (index, class, inputs in %a, actual,
 * expected, error in ulps) and the test goes on; a summary line per decade
 * gives the count not correctly rounded and the worst error in ulps.
 * The file is PW85_F_CASES, which meson sets. */
#include <math.h>
#include <pw85.h>

#include "refdata.h"
#include "testutil.h"

enum { NUM_DECADES = 16 };

/* Below this condition number f must be correctly rounded. */
static double const correctly_rounded_below = 1e12;

static FCases cases;

static int decade_of(double cond) { return (int)floor(log10(cond)); }

static void report_case(size_t n, double f, double F, double ulps,
                        const char *what) {
  double const *r = cases.r12 + 3 * n, *q1 = cases.q1 + 6 * n,
               *q2 = cases.q2 + 6 * n;
  test_mismatch(
      "case %zu (%s, cond %.3g): %s: f %.17g (%a), expected %.17g (%a), "
      "error %.3g ulps; lambda %a, r12 {%a, %a, %a}, "
      "q1 {%a, %a, %a, %a, %a, %a}, q2 {%a, %a, %a, %a, %a, %a}",
      n, cases.class_names[cases.klass[n]], cases.COND[n], what, f, f, F, F,
      ulps, cases.lambda[n], r[0], r[1], r[2], q1[0], q1[1], q1[2], q1[3],
      q1[4], q1[5], q2[0], q2[1], q2[2], q2[3], q2[4], q2[5]);
}

static void test_decade(gconstpointer data) {
  int const decade = GPOINTER_TO_INT(data);
  size_t count = 0, not_rounded = 0, worst_index = 0;
  double worst = 0.;
  for (size_t n = 0; n < cases.count; n++) {
    if (decade_of(cases.COND[n]) != decade) continue;
    count++;
    double params[PW85_DIM + 2 * PW85_SYM];
    for (int i = 0; i < PW85_DIM; i++) params[i] = cases.r12[3 * n + i];
    for (int i = 0; i < PW85_SYM; i++) {
      params[PW85_DIM + i] = cases.q1[6 * n + i];
      params[PW85_DIM + PW85_SYM + i] = cases.q2[6 * n + i];
    }
    double const F = cases.F[n];
    double const f = -pw85_f_neg(cases.lambda[n], params);
    double const ulp = nextafter(F, INFINITY) - F;
    double const ulps = fabs(f - F) / ulp; /* NaN if f is */
    if (f != F) not_rounded++;
    if (!(ulps <= worst)) worst = ulps, worst_index = n;
    if (!(ulps <= 1.))
      report_case(n, f, F, ulps, "more than 1 ulp");
    else if (f != F && cases.COND[n] < correctly_rounded_below)
      report_case(n, f, F, ulps, "not correctly rounded below cond 1e12");
  }
  if (not_rounded == 0)
    g_test_message("cond 1e%d: %zu cases, all correctly rounded", decade,
                   count);
  else
    g_test_message("cond 1e%d: %zu cases, %zu not correctly rounded, worst "
                   "error %.3g ulps (case %zu)",
                   decade, count, not_rounded, worst, worst_index);
  if (count == 0) test_mismatch("cond 1e%d: no case in the file", decade);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  GError *error = NULL;
  if (!f_cases_load(f_cases_path(), &cases, &error))
    g_error("f cases: %s", error->message);
  for (size_t n = 0; n < cases.count; n++)
    if (!(decade_of(cases.COND[n]) >= 0 &&
          decade_of(cases.COND[n]) < NUM_DECADES))
      g_error("f cases: case %zu: cond %g outside [1, 1e%d)", n,
              cases.COND[n], NUM_DECADES);
  for (int k = 0; k < NUM_DECADES; k++) {
    char *path = g_strdup_printf("/pw85/f_neg/accuracy/cond-1e%d", k);
    g_test_add_data_func(path, GINT_TO_POINTER(k), test_decade);
    g_free(path);
  }
  int const status = g_test_run();
  f_cases_clear(&cases);
  return status;
}
