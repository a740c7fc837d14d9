/* SPDX-License-Identifier: BSD-3-Clause */
/* The two legacy contact functions (docs/legacy-api.rst) against MU2 and LAMBDA of
 * data/pw85_ref_data.h5 (correctly rounded references), over the whole
 * dataset: r12 = distances[m]·directions[k] (componentwise, in double),
 * q1 = spheroids[i], q2 = spheroids[j]. Each sweep prints its worst error
 * and where it occurred; tolerances are at most 10× the measured worst. */
#include <pw85_legacy.h>

#include "worst.h"
#include "refdata.h"

static RefData data;

static double const *spheroid(size_t i) { return data.spheroids + 6 * i; }

typedef int (*ContactFunc)(double const *, double const *, double const *,
                           double *);

typedef struct {
  const char *name;
  ContactFunc func;
  double tol_mu2;      /* where the method succeeds */
  double tol_lambda;   /* idem */
  size_t max_failures; /* PW85_ENOCONV, measured */
} Replay;

/* Replays MU2 and LAMBDA. Where the method fails (PW85_ENOCONV), out must
 * hold what the header documents: λ in [0, 1] and a lower bound of μ²
 * (f(λ) ≤ μ², up to the rounding of f: 1e-12). */
static void replay(gconstpointer user_data) {
  Replay const *rp = user_data;
  char *what_mu2 = g_strdup_printf("pw85_legacy_%s vs MU2", rp->name);
  char *what_lambda = g_strdup_printf("pw85_legacy_%s vs LAMBDA", rp->name);
  Worst wm = worst_init(what_mu2, rp->tol_mu2);
  Worst wl = worst_init(what_lambda, rp->tol_lambda);
  size_t failures = 0, bad_status = 0, first_failure = 0;
  double worst_excess = -1.; /* max of (out[0] − MU2)/MU2 over failures */
  for (size_t i = 0; i < data.num_spheroids; i++)
    for (size_t j = 0; j < data.num_spheroids; j++)
      for (size_t k = 0; k < data.num_directions; k++)
        for (size_t m = 0; m < data.num_distances; m++) {
          size_t const n = ref_data_mu2_index(&data, i, j, k, m);
          double r[PW85_DIM], out[2];
          ref_data_r12(&data, k, m, r);
          int const status = rp->func(r, spheroid(i), spheroid(j), out);
          if (status == PW85_ENOCONV) {
            if (failures++ == 0) first_failure = n;
            double const excess = (out[0] - data.MU2[n]) / data.MU2[n];
            worst_excess = fmax(worst_excess, excess);
            if (!(out[1] >= 0. && out[1] <= 1. && out[0] >= 0. &&
                  excess <= 1e-12)) {
              g_test_message(
                  "record %zu: failed with out = {%.17g, %.17g}, "
                  "MU2 = %.17g",
                  n, out[0], out[1], data.MU2[n]);
              g_test_fail();
            }
            continue;
          }
          if (status != PW85_SUCCESS) {
            if (bad_status++ < 10)
              g_test_message("record %zu: status %d (%s)", n, status,
                             pw85_strerror(status));
            g_test_fail();
            continue;
          }
          worst_check(&wm, n, out[0], data.MU2[n],
                      rel_err(out[0], data.MU2[n]));
          worst_check(&wl, n, out[1], data.LAMBDA[n],
                      rel_err(out[1], data.LAMBDA[n]));
        }
  worst_report(&wm);
  worst_report(&wl);
  g_test_message(
      "pw85_legacy_%s: %zu failures (PW85_ENOCONV) out of %zu "
      "cases (at most %zu expected), first at record %zu; their "
      "out[0] is below MU2 (largest relative excess %.3g)",
      rp->name, failures, wm.count + failures + bad_status, rp->max_failures,
      first_failure, worst_excess);
  g_assert_cmpuint(failures, <=, rp->max_failures);
  g_free(what_mu2);
  g_free(what_lambda);
}

/* Newton–Raphson on f′ from λ = ½ is not robust (docs/optimisation.rst and docs/legacy-api.rst).
 * Measured on the 419,904 cases: 246,816 failures (58.8%), all of one kind:
 * a step leaves [0, 1] and, further out, Q(λ) is no longer positive
 * definite (no iterate ever came back). Newton's iterates do not depend on
 * |r12|, so each failing (pair, direction) fails at the three distances
 * (82,272 of the 139,968). Where it converges (in at most 7 steps), the
 * errors are those of f′ of implementation #1: measured worst 1.66e-9 (μ²,
 * record 98113) and 3.31e-10 (λ, record 281239). */
static Replay const replay1 = {
    "contact_function1", pw85_legacy_contact_function1, 1e-8, 3e-9, 246816};

/* Bisection on the rounded c(λ), then f by the rational fraction: the
 * cancellation of eqs. (12a)–(12g) (docs/implementation.rst, "Accuracy") leaves some results with
 * no correct digit. Measured: 736 failures (bisection ends on λ = 0 or 1:
 * the rounded c has no sign change inside (0, 1)), and among the 419,168
 * successes worst relative errors 0.979 (μ², record 374148) and 0.00375
 * (λ, record 373249). */
static Replay const replay2 = {"contact_function2",
                               pw85_legacy_contact_function2, 1., 0.01, 736};

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  ref_data_load_or_fail(&data);
  g_test_add_data_func("/pw85/legacy/contact_function1/ref_data", &replay1,
                       replay);
  g_test_add_data_func("/pw85/legacy/contact_function2/ref_data", &replay2,
                       replay);
  int const status = g_test_run();
  ref_data_clear(&data);
  return status;
}
