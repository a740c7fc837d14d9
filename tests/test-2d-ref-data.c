/* SPDX-License-Identifier: BSD-3-Clause */
/* The two-dimensional functions (pw85_2d.h) on the reference pairs of
 * ellipses of issue 29 (data/pw85_2d_pairs.h5, data/README.md, "Ellipses
 * (2D)": 3000 pairs in 10 named classes, every reference the correctly
 * rounded double of the exact value for the stored doubles, computed in
 * rational and mpmath arithmetic by data/gen_2d_data.py, which imports
 * nothing from the library). One test per class,
 * /pw85/2d/ref-data/<class>, so that a failure names the class. For every
 * pair of the class:
 *   - μ² of pw85_2d_contact_function equals MU2, bit for bit (correct
 *     rounding);
 *   - λ lies where f is within one ulp of μ²: |λ − λ*| ≤ LAMBDA_WINDOW + one
 *     ulp of λ* (measured below in windows: at most 0.17, in class
 *     lambda_near_1, where 1 − λ* < 2⁻⁵⁴ for 62 pairs and the window is
 *     below an ulp of 1);
 *   - pw85_2d_overlap agrees with the sign of μ² − 1 (MU2_MINUS_1) outside
 *     the 4-ulp band |μ² − 1| ≤ 4 DBL_EPSILON, where 0 is also allowed;
 *   - the swapped call (−r12, q2, q1) gives the same μ² bit for bit and
 *     λ_sw within the same tolerance of 1 − λ;
 *   - pw85_2d_f_neg at the four λ of F_LAMBDA equals −F, bit for bit
 *     (correctly rounded, as pw85.h measures pw85_f_neg below cond 1e14;
 *     measured here for every form, to cond 1e15), where the inputs meet
 *     its documented range (no rescaling: every non-zero entry and |r12|²
 *     in [1e-150, 1e150]; the other pairs of extreme_scales and tiny_r12
 *     are skipped for f, and counted).
 * Each failing pair is reported (index, inputs in hex, actual and
 * expected) and the test goes on; a summary line per class gives the
 * counts and the worst λ error in windows. The file is PW85_2D_PAIRS or
 * the first argument after the options.
 *
 * /pw85/2d/ref-data/constructors: pw85_2d_ellipse() and
 * pw85_2d_principal_axes() on the 264 constructor cases of
 * data/pw85_2d_geometry.h5 (PW85_2D_GEOMETRY; group constructors/, exact
 * θ, references correctly rounded): see test_constructors().
 * /pw85/2d/ref-data/geometry: pw85_2d_contact_derivatives() on the 400
 * pairs of the same file (40 of each class): see test_geometry(). */
#include <float.h>
#include <math.h>
#include <pw85/pw85_2d.h>
#include <string.h>

#include "refdata.h"
#include "testutil.h"

typedef struct {
  size_t count;
  double *r12, *q1, *q2, *mu2, *lambda, *mu2_minus_1, *one_minus_lambda,
      *window, *klass, *f_lambda, *f;
  gchar **class_names;
} Pairs2D;

static Pairs2D pairs;

static gboolean load(const char *path, GError **error) {
  struct {
    const char *name;
    size_t cols;
    double **data;
  } const columns[] = {
      {"R12", 2, &pairs.r12},           {"Q1", 3, &pairs.q1},
      {"Q2", 3, &pairs.q2},             {"MU2", 1, &pairs.mu2},
      {"LAMBDA", 1, &pairs.lambda},     {"MU2_MINUS_1", 1, &pairs.mu2_minus_1},
      {"ONE_MINUS_LAMBDA", 1, &pairs.one_minus_lambda},
      {"LAMBDA_WINDOW", 1, &pairs.window},
      {"CLASS", 1, &pairs.klass},       {"F_LAMBDA", 4, &pairs.f_lambda},
      {"F", 4, &pairs.f},
  };
  for (size_t c = 0; c < G_N_ELEMENTS(columns); c++) {
    size_t rows = 0;
    if (!ref_read_columns(path, columns[c].name, columns[c].cols, &rows,
                          columns[c].data, error))
      return FALSE;
    if (c == 0) pairs.count = rows;
    if (rows != pairs.count || rows == 0) {
      g_set_error(error, g_quark_from_static_string("pw85-2d"), 1,
                  "%s: %zu rows, not %zu", columns[c].name, rows,
                  pairs.count);
      return FALSE;
    }
  }
  pairs.class_names = ref_read_class_names(path, "PW85_2D_PAIRS", error);
  return pairs.class_names != NULL;
}

/* Error of x in units of the last place of the reference e. */
static double ulps(double x, double e) {
  if (x == e) return 0.;
  return fabs(x - e) / (nextafter(fabs(e), INFINITY) - fabs(e));
}

/* |λ − λ*|, with 1 − λ* from ONE_MINUS_LAMBDA above ½ (λ* rounded to
 * double may be 1 where 1 − λ* is not 0). */
static double lambda_error(double lambda, size_t n) {
  double const star = pairs.lambda[n];
  if (star <= 0.5) return fabs(lambda - star);
  return fabs((1. - lambda) - pairs.one_minus_lambda[n]);
}

/* The inputs meet pw85_2d_f_neg's range: no rescaling there. */
static gboolean f_in_range(size_t n) {
  double const *r = pairs.r12 + 2 * n;
  double entries[8];
  memcpy(entries, r, 2 * sizeof(double));
  memcpy(entries + 2, pairs.q1 + 3 * n, 3 * sizeof(double));
  memcpy(entries + 5, pairs.q2 + 3 * n, 3 * sizeof(double));
  for (int k = 0; k < 8; k++)
    if (entries[k] != 0. &&
        !(fabs(entries[k]) >= 1e-150 && fabs(entries[k]) <= 1e150))
      return FALSE;
  double const r2 = r[0] * r[0] + r[1] * r[1];
  return r2 >= 1e-150 && r2 <= 1e150;
}

static void print_inputs(size_t n) {
  double const *r = pairs.r12 + 2 * n, *a = pairs.q1 + 3 * n,
               *b = pairs.q2 + 3 * n;
  g_test_message("  case %zu: r12 {%a, %a}; q1 {%a, %a, %a}; "
                 "q2 {%a, %a, %a}",
                 n, r[0], r[1], a[0], a[1], a[2], b[0], b[1], b[2]);
}

/* The three calls on pair n: the contact function direct and swapped,
 * and the overlap test. FALSE, with the test failed and the inputs
 * printed, unless every status is PW85_SUCCESS. */
static gboolean run_pair(const char *name, size_t n, double out[2],
                         double sw[2], int *result) {
  double const *r = pairs.r12 + 2 * n, *a = pairs.q1 + 3 * n,
               *b = pairs.q2 + 3 * n;
  double const mr[2] = {-r[0], -r[1]};
  int const statuses[3] = {pw85_2d_contact_function(r, a, b, out),
                           pw85_2d_contact_function(mr, b, a, sw),
                           pw85_2d_overlap(r, a, b, result)};
  for (int k = 0; k < 3; k++)
    if (statuses[k] != PW85_SUCCESS) {
      g_test_fail_printf("%s case %zu: statuses %d, %d (swapped), %d "
                         "(overlap)", name, n, statuses[0], statuses[1],
                         statuses[2]);
      print_inputs(n);
      return FALSE;
    }
  return TRUE;
}

static void test_class(gconstpointer data) {
  int const klass = GPOINTER_TO_INT(data);
  const char *name = pairs.class_names[klass];
  size_t count = 0, wrong_mu = 0, wrong_lambda = 0, wrong_overlap = 0,
         wrong_swap = 0, wrong_f = 0, bad_status = 0, f_checked = 0,
         f_skipped = 0;
  double worst_windows = 0.;
  for (size_t n = 0; n < pairs.count; n++) {
    if ((int)pairs.klass[n] != klass) continue;
    count++;
    double const *r = pairs.r12 + 2 * n, *a = pairs.q1 + 3 * n,
                 *b = pairs.q2 + 3 * n;
    double const mu2 = pairs.mu2[n], star = pairs.lambda[n],
                 m1 = pairs.mu2_minus_1[n];
    double const tol =
        pairs.window[n] + (nextafter(star, INFINITY) - star);
    double out[2] = {NAN, NAN}, sw[2] = {NAN, NAN};
    int result = 42;
    if (!run_pair(name, n, out, sw, &result)) {
      bad_status++;
      continue;
    }
    size_t const failures =
        wrong_mu + wrong_lambda + wrong_overlap + wrong_swap + wrong_f;
    if (!(out[0] == mu2)) {
      wrong_mu++;
      g_test_fail_printf("%s case %zu: mu^2 %a (%.17g), expected %a "
                         "(%.17g), %.3g ulps", name, n, out[0], out[0], mu2,
                         mu2, ulps(out[0], mu2));
    }
    double const dl = lambda_error(out[1], n);
    if (!(dl / tol <= worst_windows)) worst_windows = dl / tol;
    if (!(dl <= tol)) {
      wrong_lambda++;
      g_test_fail_printf("%s case %zu: lambda %a (%.17g), expected %a, "
                         "1 - lambda* %a: |dlambda| %.3g > %.3g (window + "
                         "ulp)", name, n, out[1], out[1], star,
                         pairs.one_minus_lambda[n], dl, tol);
    }
    int const sign = m1 < 0. ? -1 : 1;
    if (!(result == sign || (result == 0 && fabs(m1) <= 4. * DBL_EPSILON))) {
      wrong_overlap++;
      g_test_fail_printf("%s case %zu: pw85_2d_overlap gives %d, mu^2 - 1 "
                         "= %.3g (%a)", name, n, result, m1, m1);
    }
    /* λ_sw against 1 − λ*, as λ against λ*. */
    double const dsw = star <= 0.5
                           ? fabs((1. - sw[1]) - star)
                           : fabs(sw[1] - pairs.one_minus_lambda[n]);
    double const tol_sw =
        pairs.window[n] + (nextafter(fmax(star, 1. - star), INFINITY) -
                           fmax(star, 1. - star));
    if (!(sw[0] == out[0]) || !(dsw <= tol_sw)) {
      wrong_swap++;
      g_test_fail_printf("%s case %zu: swapped mu^2 %a, direct %a; "
                         "swapped lambda %a, |l_sw - (1 - l*)| %.3g > %.3g",
                         name, n, sw[0], out[0], sw[1], dsw, tol_sw);
    }
    if (f_in_range(n)) {
      double params[PW85_2D_DIM + 2 * PW85_2D_SYM];
      memcpy(params, r, 2 * sizeof(double));
      memcpy(params + 2, a, 3 * sizeof(double));
      memcpy(params + 5, b, 3 * sizeof(double));
      for (int j = 0; j < 4; j++) {
        double const lam = pairs.f_lambda[4 * n + j];
        double const expected = pairs.f[4 * n + j];
        double const f = -pw85_2d_f_neg(lam, params);
        f_checked++;
        if (!(f == expected)) {
          wrong_f++;
          g_test_fail_printf("%s case %zu: f(%a) = %a (%.17g), expected %a "
                             "(%.17g), %.3g ulps", name, n, lam, f, f,
                             expected, expected, ulps(f, expected));
        }
      }
    } else {
      f_skipped++;
    }
    if (wrong_mu + wrong_lambda + wrong_overlap + wrong_swap + wrong_f >
        failures)
      print_inputs(n);
  }
  g_test_message("%s: %zu pairs, %zu mu^2 not correctly rounded, %zu "
                 "lambda beyond window + ulp (worst %.3g windows), %zu "
                 "misjudged overlaps, %zu swap asymmetries, %zu of %zu f "
                 "not correctly rounded (%zu pairs out of f's range), %zu "
                 "bad statuses",
                 name, count, wrong_mu, wrong_lambda, worst_windows,
                 wrong_overlap, wrong_swap, wrong_f, f_checked, f_skipped,
                 bad_status);
  if (count == 0) g_test_fail_printf("class %s: no pairs", name);
}

/* pw85_2d_ellipse(a, θ) against Q = R(θ)·diag(a²)·R(θ)ᵀ for the exact θ:
 * the library takes cos θ and sin θ from the C library, each within an
 * ulp, then rounds each entry once; the bound of pw85_2d.h,
 * |q[k] − Q_k| ≤ 2u·(|Q_k| + Σₘ |R_im·R_jm|·aₘ²) (u = 2⁻⁵³; measured at
 * most 1.3 u·(…)). pw85_2d_principal_axes(Q) against the semi-axes and
 * angle of the stored Q, correctly rounded: aⱼ within
 * u·(1 + u·(a0/aⱼ)²) relative (pw85_2d.h; measured: every one exact), θ
 * within 2 ulps of the reference (θ = ½·atan2(2·Q01, Q00 − Q11), off by
 * the rounding of Q00 − Q11 and of atan2; measured at most 1 ulp), modulo
 * π; no θ for the circles (EIG_THETA NaN: any direction). */
static void test_constructors(void) {
  const char *path = g_getenv("PW85_2D_GEOMETRY");
  if (path == NULL) {
    g_test_skip("PW85_2D_GEOMETRY is not set");
    return;
  }
  GError *error = NULL;
  size_t rows = 0, r2 = 0, r3 = 0, r4 = 0, r5 = 0;
  double *a = NULL, *theta = NULL, *q = NULL, *eig_a = NULL,
         *eig_theta = NULL;
  gboolean const ok =
      ref_read_columns(path, "constructors/A", 2, &rows, &a, &error) &&
      ref_read_columns(path, "constructors/THETA", 1, &r2, &theta, &error) &&
      ref_read_columns(path, "constructors/Q", 3, &r3, &q, &error) &&
      ref_read_columns(path, "constructors/EIG_A", 2, &r4, &eig_a, &error) &&
      ref_read_columns(path, "constructors/EIG_THETA", 1, &r5, &eig_theta,
                       &error);
  g_assert_no_error(error);
  g_assert_true(ok && rows > 0 && r2 == rows && r3 == rows && r4 == rows &&
                r5 == rows);
  double const u = 0x1p-53;
  double worst_q = 0., worst_a = 0., worst_t = 0.;
  for (size_t n = 0; n < rows; n++) {
    double const *an = a + 2 * n;
    double out[3];
    g_assert_cmpint(pw85_2d_ellipse(an, theta[n], out), ==, PW85_SUCCESS);
    double const c = cos(theta[n]), s = sin(theta[n]);
    /* Σₘ |R_im·R_jm|·aₘ² for entries (0,0), (0,1), (1,1) */
    double const a0 = an[0] * an[0], a1 = an[1] * an[1];
    double const mag[3] = {c * c * a0 + s * s * a1,
                           fabs(c * s) * (a0 + a1),
                           s * s * a0 + c * c * a1};
    for (int k = 0; k < 3; k++) {
      double const ref = q[3 * n + k];
      double const bound = 2. * u * (fabs(ref) + mag[k]);
      double const err = fabs(out[k] - ref);
      if (err / bound > worst_q) worst_q = err / bound;
      if (!(err <= bound))
        g_test_fail_printf("case %zu: q[%d] = %a, expected %a (error %.3g > "
                           "%.3g)", n, k, out[k], ref, err, bound);
    }
    double axes[2], t;
    g_assert_cmpint(pw85_2d_principal_axes(q + 3 * n, axes, &t), ==,
                    PW85_SUCCESS);
    double const *ea = eig_a + 2 * n;
    for (int j = 0; j < 2; j++) {
      double const ratio = ea[0] / ea[j];
      double const bound = u * (1. + u * ratio * ratio) * ea[j];
      double const err = fabs(axes[j] - ea[j]);
      if (err / bound > worst_a) worst_a = err / bound;
      if (!(err <= bound))
        g_test_fail_printf("case %zu: a[%d] = %.17g, expected %.17g", n, j,
                           axes[j], ea[j]);
    }
    if (!isnan(eig_theta[n])) {
      double const ref = eig_theta[n];
      double d = fabs(t - ref);
      if (d > 1.) d = fabs(d - G_PI); /* the same axis, π apart */
      double const ulp = nextafter(fabs(ref), INFINITY) - fabs(ref);
      if (d / ulp > worst_t) worst_t = d / ulp;
      if (!(d <= 2. * ulp))
        g_test_fail_printf("case %zu: theta = %.17g, expected %.17g", n, t,
                           ref);
    }
  }
  g_test_message("constructors: %zu cases; worst q error %.3g of its bound, "
                 "a %.3g of its bound, theta %.3g ulps", rows, worst_q,
                 worst_a, worst_t);
  g_free(a), g_free(theta), g_free(q), g_free(eig_a), g_free(eig_theta);
}

/* ‖x − y‖₂ over n entries, scaled so that no square overflows (the
 * derivatives of extreme_scales reach 1e299). */
static double dist(double const *x, double const *y, int n) {
  double m = 0., s = 0.;
  for (int i = 0; i < n; i++) m = fmax(m, fabs(x[i] - y[i]));
  if (m == 0. || isinf(m)) return m;
  for (int i = 0; i < n; i++) s += ((x[i] - y[i]) / m) * ((x[i] - y[i]) / m);
  return m * sqrt(s);
}

/* Every output of pw85_2d_contact_derivatives() on the 400 pairs of
 * data/pw85_2d_geometry.h5 (references at 60 digits and more, from s =
 * Q(λ*)⁻¹·r12 at the certified λ*). μ² equal to the reference; λ within
 * 8·u·cond(Q(λ*)) relative to min(λ*, 1 − λ*) (as test-geometry-refs in
 * 3D: the root of the compensated ω; near 1 through 1 − λ less the
 * half-ulp of its rounding; measured 0.98); every block (point, normal,
 * ∂μ²/∂r12, ∂μ²/∂θᵢ, ∂μ²/∂qᵢ) within 8·u·(cond(Q(λ*)) + 1/min(λ*,
 * 1 − λ*)) relative to its norm (the torques to their scale
 * |∂μ²/∂r12|·|x − cᵢ| where larger: a torque may vanish). The second term:
 * the weights λ^i(1 − λ)^j are formed from the search's λ, which is a
 * double near 1 where the search kept λ, not 1 − λ, as its variable (as
 * pw85.h says of λ), so that 1 − λ is known to u/(1 − λ*) relative only
 * (measured: ∂μ²/∂q2 47·u·cond off on a pair with 1 − λ* = 3.1e-3 and
 * cond 2.4, 1.1 in the units above). Measured worsts: 1.10 (∂μ²/∂q2)
 * and under 0.5 for the other blocks, in those units; printed. */
static void test_geometry(void) {
  const char *path = g_getenv("PW85_2D_GEOMETRY");
  if (path == NULL) {
    g_test_skip("PW85_2D_GEOMETRY is not set");
    return;
  }
  struct {
    const char *name;
    size_t cols;
    double *data;
  } col[] = {{"R12", 2, NULL},     {"Q1", 3, NULL},
             {"Q2", 3, NULL},      {"MU2", 1, NULL},
             {"LAMBDA", 1, NULL},  {"ONE_MINUS_LAMBDA", 1, NULL},
             {"COND_Q", 1, NULL},  {"POINT", 2, NULL},
             {"NORMAL", 2, NULL},  {"D_R12", 2, NULL},
             {"D_THETA1", 1, NULL}, {"D_THETA2", 1, NULL},
             {"D_Q1", 3, NULL},    {"D_Q2", 3, NULL}};
  enum { R12, Q1, Q2, MU2, LAMBDA, OML, COND, POINT, NORMAL, DR12, DT1, DT2,
         DQ1, DQ2, NCOL };
  size_t n = 0;
  GError *error = NULL;
  for (int c = 0; c < NCOL; c++) {
    size_t rows = 0;
    ref_read_columns(path, col[c].name, col[c].cols, &rows, &col[c].data,
                     &error);
    g_assert_no_error(error);
    if (c == 0) n = rows;
    g_assert_true(rows == n && n > 0);
  }
  double const u = 0x1p-53;
  double worst_lambda = 0., worst[7] = {0};
  const char *names[7] = {"point", "normal", "d_r12", "d_theta1",
                          "d_theta2", "d_q1", "d_q2"};
  for (size_t k = 0; k < n; k++) {
    double g[PW85_2D_GEOM_SIZE], d[PW85_2D_DERIV_SIZE];
    double const *r = col[R12].data + 2 * k;
    int const status = pw85_2d_contact_derivatives(
        r, col[Q1].data + 3 * k, col[Q2].data + 3 * k, g, d);
    if (status != PW85_SUCCESS) {
      g_test_fail_printf("pair %zu: status %d", k, status);
      continue;
    }
    if (!(g[PW85_2D_GEOM_MU2] == col[MU2].data[k]))
      g_test_fail_printf("pair %zu: mu^2 %a, expected %a", k,
                         g[PW85_2D_GEOM_MU2], col[MU2].data[k]);
    double const star = col[LAMBDA].data[k], oml = col[OML].data[k];
    double const cond = fmax(1., col[COND].data[k]);
    double const l = g[PW85_2D_GEOM_LAMBDA];
    double const e_lam =
        star <= 0.5 ? fabs(l - star) / star
                    : fmax(0., fabs((1. - l) - oml) - u / 2. - u * oml) / oml;
    if (e_lam / (u * cond) > worst_lambda) worst_lambda = e_lam / (u * cond);
    if (!(e_lam <= 8. * u * cond))
      g_test_fail_printf("pair %zu: lambda %.17g, expected %.17g (1 - "
                         "lambda* %a)", k, l, star, oml);
    double const scale = u * (cond + 1. / fmin(star, oml));
    double const *got[7] = {g + PW85_2D_GEOM_POINT, g + PW85_2D_GEOM_NORMAL,
                            d + PW85_2D_DERIV_R12, d + PW85_2D_DERIV_THETA1,
                            d + PW85_2D_DERIV_THETA2, d + PW85_2D_DERIV_Q1,
                            d + PW85_2D_DERIV_Q2};
    double const *ref[7] = {col[POINT].data + 2 * k, col[NORMAL].data + 2 * k,
                            col[DR12].data + 2 * k,  col[DT1].data + k,
                            col[DT2].data + k,       col[DQ1].data + 3 * k,
                            col[DQ2].data + 3 * k};
    int const len[7] = {2, 2, 2, 1, 1, 3, 3};
    double const zero[3] = {0., 0., 0.};
    double const gr = dist(ref[2], zero, 2);
    double const arm1 = dist(ref[0], zero, 2), arm2 = dist(ref[0], r, 2);
    for (int b = 0; b < 7; b++) {
      double size = dist(ref[b], zero, len[b]);
      if (b == 3) size = fmax(size, gr * arm1);
      if (b == 4) size = fmax(size, gr * arm2);
      double const err = dist(got[b], ref[b], len[b]);
      double const e = err == 0. ? 0. : err / size;
      if (e / scale > worst[b]) worst[b] = e / scale;
      if (!(e <= 8. * scale))
        g_test_fail_printf("pair %zu: %s (%.17g, ...), expected (%.17g, "
                           "...): %.3g > 8 u (cond + 1/min(l, 1 - l)) = "
                           "%.3g", k, names[b], got[b][0], ref[b][0], e,
                           8. * scale);
    }
  }
  g_test_message("geometry: %zu pairs; worst lambda %.3g u cond", n,
                 worst_lambda);
  for (int b = 0; b < 7; b++)
    g_test_message("  %s: worst %.3g u (cond + 1/min(l, 1 - l))", names[b],
                   worst[b]);
  for (int c = 0; c < NCOL; c++) g_free(col[c].data);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  const char *path = argc > 1 ? argv[1] : g_getenv("PW85_2D_PAIRS");
  GError *error = NULL;
  if (path == NULL || !load(path, &error)) {
    g_printerr("cannot load the 2D pairs (%s): %s\n",
               path ? path : "PW85_2D_PAIRS unset",
               error ? error->message : "");
    return 1;
  }
  for (int k = 0; pairs.class_names[k] != NULL; k++) {
    char *test = g_strdup_printf("/pw85/2d/ref-data/%s",
                                 pairs.class_names[k]);
    g_test_add_data_func(test, GINT_TO_POINTER(k), test_class);
    g_free(test);
  }
  g_test_add_func("/pw85/2d/ref-data/constructors", test_constructors);
  g_test_add_func("/pw85/2d/ref-data/geometry", test_geometry);
  return g_test_run();
}
