/* SPDX-License-Identifier: BSD-3-Clause */
/* f, the residual and the contact function against closed forms and the
 * tutorial's case (reference computed with mpmath at 50 digits). */
#include <pw85.h>

#include "testutil.h"

/* Two spheres of radii a1, a2 (Q = a²·I): with R = |r12|²,
 * f(λ) = λ(1−λ)·R / ((1−λ)a1² + λa2²), maximal at λ = a1/(a1 + a2) where
 * μ² = R/(a1 + a2)². */
typedef struct {
  double a1, a2;
  double r[PW85_DIM];
} Spheres;

static Spheres const spheres[] = {
    {1., 1., {0.5, 0., 0.}},      {1., 3., {1., 2., 2.}},
    {0.1, 10., {3., -4., 12.}},   {7., 0.01, {-0.3, 0.2, 0.1}},
    {1e-3, 1e3, {1e3, 1e3, 1e3}}, {2.5, 2.5, {0., 0., 5.}},
};

static void sphere_q(double a, double q[PW85_SYM]) {
  q[0] = q[3] = q[5] = a * a;
  q[1] = q[2] = q[4] = 0.;
}

static double norm2(double const r[PW85_DIM]) {
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

static double sphere_f(Spheres const *s, double lambda) {
  double const d = (1. - lambda) * s->a1 * s->a1 + lambda * s->a2 * s->a2;
  return lambda * (1. - lambda) * norm2(s->r) / d;
}

/* f′(λ) = R·[(1−2λ)·d − λ(1−λ)·(a2² − a1²)] / d². */
static double sphere_df(Spheres const *s, double lambda) {
  double const a12 = s->a1 * s->a1, a22 = s->a2 * s->a2;
  double const d = (1. - lambda) * a12 + lambda * a22;
  return norm2(s->r) *
         ((1. - 2. * lambda) * d - lambda * (1. - lambda) * (a22 - a12)) /
         (d * d);
}

static void fill_params(double const r[PW85_DIM], double const q1[PW85_SYM],
                        double const q2[PW85_SYM], double params[15]) {
  for (int i = 0; i < PW85_DIM; i++) params[i] = r[i];
  for (int i = 0; i < PW85_SYM; i++) {
    params[PW85_DIM + i] = q1[i];
    params[PW85_DIM + PW85_SYM + i] = q2[i];
  }
}

/* Q1, Q2 of the case, and params as pw85_f_neg takes them (if not NULL). */
static void sphere_problem(Spheres const *s, double q1[PW85_SYM],
                           double q2[PW85_SYM], double *params) {
  sphere_q(s->a1, q1);
  sphere_q(s->a2, q2);
  if (params != NULL) fill_params(s->r, q1, q2, params);
}

static void test_f_spheres(void) {
  for (size_t k = 0; k < G_N_ELEMENTS(spheres); k++) {
    Spheres const *s = &spheres[k];
    double q1[PW85_SYM], q2[PW85_SYM], params[15];
    sphere_problem(s, q1, q2, params);
    for (int l = 0; l <= 10; l++) {
      double const lambda = l / 10.;
      /* Both sides round a handful of operations (measured: 4.4e-16). */
      assert_close("f, spheres %zu, lambda %g", -pw85_f_neg(lambda, params),
                   sphere_f(s, lambda), 1.1e-15, k, lambda);
    }
  }
}

static void test_residual_spheres(void) {
  for (size_t k = 0; k < G_N_ELEMENTS(spheres); k++) {
    Spheres const *s = &spheres[k];
    double q1[PW85_SYM], q2[PW85_SYM], params[15];
    sphere_problem(s, q1, q2, params);
    for (int l = 1; l <= 9; l++) {
      double const lambda = l / 10.;
      double out[3];
      pw85__residual(lambda, s->r, q1, q2, out);
      /* f from rᵀ·s against f from |L⁻¹r|²: two roundings apart
       * (measured: 2.2e-16). */
      assert_close("residual f, spheres %zu, lambda %g", out[0],
                   -pw85_f_neg(lambda, params), 4.5e-16, k, lambda);
      /* g = −f′ (docs/optimisation.rst, eq. (5.4) and ch. 4, eq. (6)); absolute error
       * relative to the size of the terms, R/d (measured: 1.3e-15). */
      double const scale = norm2(s->r) / fmin(s->a1 * s->a1, s->a2 * s->a2);
      g_assert_cmpfloat(fabs(out[1] + sphere_df(s, lambda)) / scale, <=,
                        1e-14);
      /* g′ against a central difference of −f′ (step h, error O(h²)). */
      double const h = 1e-5;
      double const fd =
          -(sphere_df(s, lambda + h) - sphere_df(s, lambda - h)) / (2. * h);
      g_assert_cmpfloat(fabs(out[2] - fd) / (scale / fmin(lambda, 1. - lambda)),
                        <=, 1e-6);
    }
  }
}

static void test_contact_spheres(void) {
  for (size_t k = 0; k < G_N_ELEMENTS(spheres); k++) {
    Spheres const *s = &spheres[k];
    double q1[PW85_SYM], q2[PW85_SYM], out[2];
    sphere_problem(s, q1, q2, NULL);
    g_assert_cmpint(pw85_contact_function(s->r, q1, q2, out), ==,
                    PW85_SUCCESS);
    double const sum = s->a1 + s->a2;
    /* Measured worst: 4.4e-16 (μ²), 1.1e-16 (λ). */
    assert_close("mu2, spheres %zu", out[0], norm2(s->r) / (sum * sum),
                 1.1e-15, k);
    assert_close("lambda, spheres %zu", out[1], s->a1 / sum, 1e-12, k);
  }
}

static void test_contact_equal(void) {
  /* Q1 = Q2 = L·Lᵀ with L = [[2,0,0],[1,3,0],[-1,2,4]] and r = L·(1,2,3):
   * f = λ(1−λ)·|(1,2,3)|², so μ² = 14/4 and λ = ½ exactly. */
  double const q[PW85_SYM] = {4., 2., -2., 10., 5., 21.};
  double const r[PW85_DIM] = {2., 7., 15.};
  double out[2];
  g_assert_cmpint(pw85_contact_function(r, q, q, out), ==, PW85_SUCCESS);
  assert_close("mu2, equal ellipsoids", out[0], 3.5, 4.5e-16);
  assert_close("lambda, equal ellipsoids", out[1], 0.5, 1e-12);
}

static void test_tutorial(void) {
  double const x1[PW85_DIM] = {-0.5, 0.4, -0.7};
  double const x2[PW85_DIM] = {0.2, -0.3, 0.4};
  double const n1[PW85_DIM] = {0., 0., 1.};
  double const n2[PW85_DIM] = {1., 0., 0.};
  double r[PW85_DIM], q1[PW85_SYM], q2[PW85_SYM], out[2];
  for (int i = 0; i < PW85_DIM; i++) r[i] = x2[i] - x1[i];
  pw85_spheroid(10., 0.1, n1, q1);
  pw85_spheroid(0.5, 5., n2, q2);
  g_assert_cmpint(pw85_contact_function(r, q1, q2, out), ==, PW85_SUCCESS);
  /* mpmath, 50 digits, from the same double inputs. */
  assert_close("tutorial mu2", out[0], 3.3627060406386292212312137, 1e-15);
  assert_close("tutorial lambda", out[1], 0.16685895534055480919223318,
               1e-12);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/f/spheres", test_f_spheres);
  g_test_add_func("/pw85/residual/spheres", test_residual_spheres);
  g_test_add_func("/pw85/contact_function/spheres", test_contact_spheres);
  g_test_add_func("/pw85/contact_function/equal", test_contact_equal);
  g_test_add_func("/pw85/contact_function/tutorial", test_tutorial);
  return g_test_run();
}
