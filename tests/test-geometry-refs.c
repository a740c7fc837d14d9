/* SPDX-License-Identifier: BSD-3-Clause */
/* The contact geometry, the derivatives of μ² and the ellipsoid
 * constructors against the references of data/pw85_geometry_pairs.h5
 * (mpmath at 100 digits, rounded once; data/gen_geometry.py): 400 pairs with
 * aspect ratios to 1e6 (cond(Qᵢ) to 8.6e11), near tangency, λ near 0 and 1,
 * spheroids, r12 along principal axes; 310 constructor cases with aspect
 * ratios to 1e8.
 *
 * Each vector or matrix output is compared in the norm of the block,
 * relative to the norm of its reference (the torques: to their natural
 * scale, the lever arm times |∂μ²/∂r12|, as a torque may vanish), in units
 * of u·cond(Q(λ*)), the conditioning of s = Q(λ*)⁻¹·r12 from which every
 * output is formed (u = 2⁻⁵³). The tolerances are explained at each check
 * and the worst errors are printed (TAP comments). */
#include <float.h>
#include <glib.h>
#include <math.h>

#include "pw85.h"
#include "refdata.h"
#include "testutil.h"
#include "worst.h"

#define U (DBL_EPSILON / 2.0)

typedef struct {
  size_t n;
  double *r12, *q1, *q2, *mu2, *lambda, *one_minus_lambda, *point, *normal;
  double *d_r12, *d_rot1, *d_rot2, *d_q1, *d_q2, *cond_q;
} Pairs;

static double *column(const char *name, size_t cols, size_t *n) {
  GError *error = NULL;
  double *data = NULL;
  size_t rows = 0;
  if (!ref_read_columns(geometry_pairs_path(), name, cols, &rows, &data,
                        &error)) {
    g_test_fail_printf("%s", error->message);
    g_error_free(error);
    return NULL;
  }
  if (*n != 0 && rows != *n) {
    g_test_fail_printf("%s: %zu rows, not %zu", name, rows, *n);
    g_free(data);
    return NULL;
  }
  *n = rows;
  return data;
}

static gboolean load(Pairs *p) {
  p->n = 0;
  p->r12 = column("r12", 3, &p->n);
  p->q1 = column("q1", 6, &p->n);
  p->q2 = column("q2", 6, &p->n);
  p->mu2 = column("mu2", 1, &p->n);
  p->lambda = column("lambda", 1, &p->n);
  p->one_minus_lambda = column("one_minus_lambda", 1, &p->n);
  p->point = column("point", 3, &p->n);
  p->normal = column("normal", 3, &p->n);
  p->d_r12 = column("d_r12", 3, &p->n);
  p->d_rot1 = column("d_rot1", 3, &p->n);
  p->d_rot2 = column("d_rot2", 3, &p->n);
  p->d_q1 = column("d_q1", 6, &p->n);
  p->d_q2 = column("d_q2", 6, &p->n);
  p->cond_q = column("cond_q", 1, &p->n);
  return p->cond_q != NULL && p->n > 0;
}

static double norm(double const *x, int n) {
  double s = 0.0;
  for (int i = 0; i < n; i++) s += x[i] * x[i];
  return sqrt(s);
}

static double dist(double const *x, double const *y, int n) {
  double s = 0.0;
  for (int i = 0; i < n; i++) s += (x[i] - y[i]) * (x[i] - y[i]);
  return sqrt(s);
}

/* Every output of pw85_contact_derivatives() on every pair. μ² is
 * correctly rounded (equal to the reference); λ within 8·u·cond(Q(λ*))
 * relative to min(λ*, 1 − λ*) (the root of the compensated ω, whose
 * rounding moves it by about u·cond; measured 1.43); the vectors and
 * matrices within 8·u·cond(Q(λ*)) relative (s, solved to about u·cond,
 * then a few roundings: measured 1.0 to 3.75 by block; the worsts are
 * printed, and quoted in pw85.h and docs/geometry.rst). */
static void test_pairs(void) {
  Pairs p;
  if (!load(&p)) return;
  Worst mu2 = worst_init("mu2 (ulps)", 0.0);
  Worst lam = worst_init("lambda / (u cond)", 8.0);
  char const *names[7] = {"point", "normal", "d_r12", "d_rot1", "d_rot2",
                          "d_q1", "d_q2"};
  Worst w[7];
  for (int b = 0; b < 7; b++)
    w[b] = worst_init(g_strdup_printf("%s / (u cond)", names[b]), 8.0);
  for (size_t k = 0; k < p.n; k++) {
    double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
    double const *r = p.r12 + 3 * k;
    int const status =
        pw85_contact_derivatives(r, p.q1 + 6 * k, p.q2 + 6 * k, g, d);
    if (status != PW85_SUCCESS) {
      test_mismatch("pair %zu: status %d", k, status);
      continue;
    }
    double const scale = U * fmax(1.0, p.cond_q[k]);
    double const e_mu2 =
        fabs(g[PW85_GEOM_MU2] - p.mu2[k]) / (DBL_EPSILON * p.mu2[k]);
    worst_check(&mu2, k, g[PW85_GEOM_MU2], p.mu2[k], e_mu2);
    /* λ > ½ is compared through 1 − λ (exact for a double in [½, 1]),
     * less what no double near 1 can do better: the half-ulp u/2 of its
     * rounding, and the reference's own rounding. */
    double const l = g[PW85_GEOM_LAMBDA];
    double const e_lam =
        p.lambda[k] <= 0.5
            ? fabs(l - p.lambda[k]) / p.lambda[k]
            : fmax(0.0, fabs((1.0 - l) - p.one_minus_lambda[k]) - U / 2 -
                            U * p.one_minus_lambda[k]) /
                  p.one_minus_lambda[k];
    worst_check(&lam, k, l, p.lambda[k], e_lam / scale);
    double const *got[7] = {g + PW85_GEOM_POINT, g + PW85_GEOM_NORMAL,
                            d + PW85_DERIV_R12,  d + PW85_DERIV_ROT1,
                            d + PW85_DERIV_ROT2, d + PW85_DERIV_Q1,
                            d + PW85_DERIV_Q2};
    double const *ref[7] = {p.point + 3 * k,  p.normal + 3 * k,
                            p.d_r12 + 3 * k,  p.d_rot1 + 3 * k,
                            p.d_rot2 + 3 * k, p.d_q1 + 6 * k,
                            p.d_q2 + 6 * k};
    int const len[7] = {3, 3, 3, 3, 3, 6, 6};
    double const gr = norm(p.d_r12 + 3 * k, 3);
    double arm2[3];
    for (int i = 0; i < 3; i++) arm2[i] = p.point[3 * k + i] - r[i];
    for (int b = 0; b < 7; b++) {
      double size = norm(ref[b], len[b]);
      if (b == 3) size = fmax(size, gr * norm(p.point + 3 * k, 3));
      if (b == 4) size = fmax(size, gr * norm(arm2, 3));
      double const e = dist(got[b], ref[b], len[b]) / size;
      worst_check(&w[b], k, got[b][0], ref[b][0], e / scale);
    }
  }
  worst_report(&mu2);
  worst_report(&lam);
  for (int b = 0; b < 7; b++) {
    worst_report(&w[b]);
    g_free((char *)w[b].what);
  }
  double *all[] = {p.r12,    p.q1,     p.q2,     p.mu2,    p.lambda,
                   p.one_minus_lambda, p.point,  p.normal, p.d_r12,
                   p.d_rot1, p.d_rot2, p.d_q1,   p.d_q2,   p.cond_q};
  for (size_t i = 0; i < G_N_ELEMENTS(all); i++) g_free(all[i]);
}

/* The constructors against the exact forms rounded once: the bound of
 * pw85.h, |q[k] − Q_k| ≤ u·|Q_k| + 2⁻¹⁰⁰·Σ|R_im·R_jm|·aₘ² for a rotation
 * (2⁻¹⁰⁰·max aₘ² for a quaternion), less the reference's own rounding
 * (u·|Q_k|): the check is |q[k] − ref| ≤ 2u·|ref| + the second term, and
 * the count of entries equal to the reference is printed (measured: 3678
 * of 3720, the worst at 0.06 of the bound). Principal axes: the semi-axes
 * of the stored q_quat within 4·u·(1 + u·(a0/aⱼ)²/gapⱼ) relative, gapⱼ
 * the distance of aⱼ² to the other eigenvalues relative to a0² (pw85.h:
 * the Rayleigh quotient of a direction off by θ ≈ u/gapⱼ errs by
 * gap·θ²; measured 1.94). */
static void test_constructors(void) {
  size_t n = 0;
  double *a = column("constructors/a", 3, &n);
  double *rot = column("constructors/rot", 9, &n);
  double *q_rot = column("constructors/q_rot", 6, &n);
  double *q_rot_scale = column("constructors/q_rot_scale", 6, &n);
  double *quat = column("constructors/quat", 4, &n);
  double *q_quat = column("constructors/q_quat", 6, &n);
  double *eig_a = column("constructors/eig_a", 3, &n);
  double *eig_gap = column("constructors/eig_gap", 3, &n);
  if (eig_gap == NULL) return;
  Worst wr = worst_init("rotation: |q - ref| / bound", 1.0);
  Worst wq = worst_init("quaternion: |q - ref| / bound", 1.0);
  Worst wa = worst_init("principal axes: |a - ref| / (a u (1 + u cond/gap))", 4.0);
  size_t equal = 0;
  for (size_t k = 0; k < n; k++) {
    double q[6];
    g_assert_cmpint(pw85_ellipsoid_rotation(a + 3 * k, rot + 9 * k, q), ==,
                    PW85_SUCCESS);
    double amax2 = 0.0;
    for (int m = 0; m < 3; m++) amax2 = fmax(amax2, a[3 * k + m] * a[3 * k + m]);
    for (int m = 0; m < 6; m++) {
      double const ref = q_rot[6 * k + m];
      double const bound =
          2 * U * fabs(ref) + 0x1p-100 * q_rot_scale[6 * k + m];
      double const e = bound > 0.0 ? fabs(q[m] - ref) / bound
                                   : (q[m] == ref ? 0.0 : INFINITY);
      worst_check(&wr, 6 * k + m, q[m], ref, e);
      equal += q[m] == ref;
    }
    g_assert_cmpint(pw85_ellipsoid_quaternion(a + 3 * k, quat + 4 * k, q), ==,
                    PW85_SUCCESS);
    for (int m = 0; m < 6; m++) {
      double const ref = q_quat[6 * k + m];
      double const bound = 2 * U * fabs(ref) + 0x1p-98 * amax2;
      worst_check(&wq, 6 * k + m, q[m], ref, fabs(q[m] - ref) / bound);
      equal += q[m] == ref;
    }
    double axes[3], dirs[9];
    g_assert_cmpint(pw85_principal_axes(q_quat + 6 * k, axes, dirs), ==,
                    PW85_SUCCESS);
    for (int j = 0; j < 3; j++) {
      double const gap = eig_gap[3 * k + j];
      if (!(gap > 0.0)) continue;  /* a repeated eigenvalue: no gap term */
      double const ref = eig_a[3 * k + j];
      double const ratio = (eig_a[3 * k] / ref) * (eig_a[3 * k] / ref);
      double const predicted = U * (1.0 + U * ratio / gap);
      worst_check(&wa, 3 * k + j, axes[j], ref,
                  fabs(axes[j] - ref) / (ref * predicted));
    }
  }
  g_test_message("%zu of %zu entries equal to the rounded reference", equal,
                 12 * n);
  worst_report(&wr);
  worst_report(&wq);
  worst_report(&wa);
  double *all[] = {a, rot, q_rot, q_rot_scale, quat, q_quat, eig_a, eig_gap};
  for (size_t i = 0; i < G_N_ELEMENTS(all); i++) g_free(all[i]);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/geometry-refs/pairs", test_pairs);
  g_test_add_func("/pw85/geometry-refs/constructors", test_constructors);
  return g_test_run();
}
