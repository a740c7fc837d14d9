/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_spheroid: Q = a²·I + (c² − a²)·n·nᵀ has n as an eigenvector with
 * eigenvalue c², the plane normal to n as an eigenspace with eigenvalue a²,
 * trace 2a² + c² and determinant a⁴c². */
#include <pw85.h>

#include "testutil.h"

typedef struct {
  double a, c;
  double n[PW85_DIM];
} Case;

/* Unit n: axes, the exactly representable (0.6, 0.8, 0) up to rounding of
 * its entries, and (1, 2, 2)/3. */
static Case const cases[] = {
    {10., 0.1, {0., 0., 1.}},
    {0.5, 5., {1., 0., 0.}},
    {2., 3., {0., 1., 0.}},
    {1., 7., {0.6, 0.8, 0.}},
    {3., 0.25, {1. / 3., 2. / 3., 2. / 3.}},
    {1e-3, 2e3, {1. / 3., -2. / 3., 2. / 3.}},
};

static void sym_mul(double const q[PW85_SYM], double const x[PW85_DIM],
                    double y[PW85_DIM]) {
  y[0] = q[0] * x[0] + q[1] * x[1] + q[2] * x[2];
  y[1] = q[1] * x[0] + q[3] * x[1] + q[4] * x[2];
  y[2] = q[2] * x[0] + q[4] * x[1] + q[5] * x[2];
}

/* |y − s·x| / (max(a², c²)·|x|) for unit x: the eigen-residual relative to
 * the norm of Q; its rounding bound is a few ulps (measured: 1.7e-16). */
static double eigen_residual(double const q[PW85_SYM], double const x[PW85_DIM],
                             double s, double scale) {
  double y[PW85_DIM];
  sym_mul(q, x, y);
  double e = 0.0;
  for (int i = 0; i < PW85_DIM; i++) e = fmax(e, fabs(y[i] - s * x[i]));
  return e / scale;
}

static void test_eigen(void) {
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    Case const *c = &cases[k];
    double q[PW85_SYM];
    pw85_spheroid(c->a, c->c, c->n, q);
    double const a2 = c->a * c->a, c2 = c->c * c->c;
    double const scale = fmax(a2, c2);
    /* n: eigenvalue c². */
    g_assert_cmpfloat(eigen_residual(q, c->n, c2, scale), <=, 4.5e-16);
    /* t1 = n × e, t2 = n × t1 span the plane normal to n: eigenvalue a². */
    double const e[PW85_DIM] = {fabs(c->n[0]) < 0.5 ? 1. : 0.,
                                fabs(c->n[0]) < 0.5 ? 0. : 1., 0.};
    double t1[PW85_DIM] = {c->n[1] * e[2] - c->n[2] * e[1],
                           c->n[2] * e[0] - c->n[0] * e[2],
                           c->n[0] * e[1] - c->n[1] * e[0]};
    double const norm1 = sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (int i = 0; i < PW85_DIM; i++) t1[i] /= norm1;
    double const t2[PW85_DIM] = {c->n[1] * t1[2] - c->n[2] * t1[1],
                                 c->n[2] * t1[0] - c->n[0] * t1[2],
                                 c->n[0] * t1[1] - c->n[1] * t1[0]};
    g_assert_cmpfloat(eigen_residual(q, t1, a2, scale), <=, 4.5e-16);
    g_assert_cmpfloat(eigen_residual(q, t2, a2, scale), <=, 4.5e-16);
  }
}

static void test_trace_det(void) {
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    Case const *c = &cases[k];
    double q[PW85_SYM];
    pw85_spheroid(c->a, c->c, c->n, q);
    double const a2 = c->a * c->a, c2 = c->c * c->c;
    assert_close("trace, case %zu", q[0] + q[3] + q[5], 2. * a2 + c2, 4.5e-16,
                 k);
    double const det = q[0] * (q[3] * q[5] - q[4] * q[4]) -
                       q[1] * (q[1] * q[5] - q[4] * q[2]) +
                       q[2] * (q[1] * q[4] - q[3] * q[2]);
    /* Computed from the entries, det has an absolute error of order
     * ε·‖Q‖³, that is a relative error of order ε·cond(Q)² with
     * cond(Q) = max(a², c²)/min(a², c²): meaningful only for moderate
     * aspect ratios (measured: 1.1e-16 up to cond 49, 5.8e-13 at 1e4). */
    double const cond = fmax(a2 / c2, c2 / a2);
    if (cond > 1e4) continue;
    assert_close("det, case %zu", det, a2 * a2 * c2,
                 8. * cond * cond * 2.2e-16, k);
  }
}

static void test_axis_aligned_exact(void) {
  /* With n on an axis every entry is exact: the tutorial's spheroids. */
  double const n1[PW85_DIM] = {0., 0., 1.};
  double const n2[PW85_DIM] = {1., 0., 0.};
  double q1[PW85_SYM], q2[PW85_SYM];
  pw85_spheroid(10., 0.1, n1, q1);
  pw85_spheroid(0.5, 5., n2, q2);
  double const e1[PW85_SYM] = {100., 0., 0., 100., 0., 0.1 * 0.1};
  double const e2[PW85_SYM] = {25., 0., 0., 0.25, 0., 0.25};
  for (int i = 0; i < PW85_SYM; i++) {
    g_assert_cmpfloat(q1[i], ==, e1[i]);
    g_assert_cmpfloat(q2[i], ==, e2[i]);
  }
}

static void test_null(void) {
  double const n[PW85_DIM] = {0., 0., 1.};
  double q[PW85_SYM] = {1., 1., 1., 1., 1., 1.};
  pw85_spheroid(1., 2., n, NULL); /* nothing to write: must not crash */
  pw85_spheroid(1., 2., NULL, q);
  for (int i = 0; i < PW85_SYM; i++) g_assert_true(isnan(q[i]));
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  g_test_add_func("/pw85/spheroid/eigen", test_eigen);
  g_test_add_func("/pw85/spheroid/trace-det", test_trace_det);
  g_test_add_func("/pw85/spheroid/axis-aligned", test_axis_aligned_exact);
  g_test_add_func("/pw85/spheroid/null", test_null);
  return g_test_run();
}
