/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_2d_index_energy(): the energy of an assembly of ellipses, its forces
 * and its torques (one number per ellipse, ∂/∂θ) against central
 * differences of the energy, a brute force over every pair and image
 * (pw85_2d_contact_function() on exact image vectors), the balance of
 * forces and moments, and itself on 1, 2 and 8 threads; the user kind;
 * every bad input, with the outputs untouched. */
#include <glib.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "energy-util.h"
#include "pw85_2d.h"
#include "pw85_2d_index.h"
#include "testutil.h"

#define U_ROUND 1.1102230246251565e-16 /* 2^-53 */

/* n ellipses of semi-axes s·(1, 1/aspect), s in [0.7, 1.3], at random
 * angles and at random centres on a grid of 2^-20 in a periodic square of
 * side L: every image vector is a double, so the brute force below and
 * the index decide the same exact configurations. */
typedef struct {
  size_t n;
  double box[2];
  double *a;     /* semi-axes, 2n */
  double *theta; /* angles, n */
  double *c;     /* centres, 2n */
  double *q;     /* forms, 3n */
} Ellipses;

static Ellipses draw(size_t n, double side, double aspect, guint32 seed) {
  Ellipses s = {n, {side, side}, NULL, NULL, NULL, NULL};
  s.a = g_new(double, 2 * n);
  s.theta = g_new(double, n);
  s.c = g_new(double, 2 * n);
  s.q = g_new(double, 3 * n);
  GRand *rng = g_rand_new_with_seed(seed);
  for (size_t i = 0; i < n; i++) {
    double const size = g_rand_double_range(rng, 0.7, 1.3);
    s.a[2 * i] = size;
    s.a[2 * i + 1] = size / aspect;
    s.theta[i] = g_rand_double_range(rng, -G_PI, G_PI);
    for (int k = 0; k < 2; k++)
      s.c[2 * i + k] = ldexp(floor(ldexp(g_rand_double(rng) * side, 20)), -20);
    g_assert_cmpint(pw85_2d_ellipse(s.a + 2 * i, s.theta[i], s.q + 3 * i), ==,
                    PW85_SUCCESS);
  }
  g_rand_free(rng);
  return s;
}

static void release(Ellipses *s) {
  g_free(s->a);
  g_free(s->theta);
  g_free(s->c);
  g_free(s->q);
}

static pw85_2d_index *indexed(Ellipses const *s) {
  pw85_2d_index *index = NULL;
  g_assert_cmpint(pw85_2d_index_create(s->box, &index), ==, PW85_SUCCESS);
  size_t *ids = g_new(size_t, s->n);
  for (size_t i = 0; i < s->n; i++) ids[i] = i;
  g_assert_cmpint(pw85_2d_index_insert_many(index, s->n, ids, s->c, s->q), ==,
                  PW85_SUCCESS);
  g_free(ids);
  return index;
}

/* The overlap energy alone (ε = 1, one thread). */
static double total(pw85_2d_index const *index, size_t n) {
  double e = NAN;
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                       NULL, 1, n, &e, NULL, NULL),
                  ==, PW85_SUCCESS);
  return e;
}

/* Every pair i < j and image n ∈ {−2, …, 2}², summed with no index:
 * more images than needed, as centres lie in [0, L) on a grid (an image
 * with |n_k| = 2 is at least L = 7 away along axis k, beyond the reach
 * 2·1.3 of any pair). Returns Σ U, and in *magnitude Σ |U|, in *pairs
 * the number of pairs with μ < 1. */
static double brute_force(Ellipses const *s, double *magnitude, size_t *pairs) {
  double e = 0.0, m = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < s->n; i++)
    for (size_t j = i + 1; j < s->n; j++)
      for (int n0 = -2; n0 <= 2; n0++)
        for (int n1 = -2; n1 <= 2; n1++) {
          double const r[2] = {
              s->c[2 * j] + n0 * s->box[0] - s->c[2 * i],
              s->c[2 * j + 1] + n1 * s->box[1] - s->c[2 * i + 1]};
          double ml[2], u[2];
          g_assert_cmpint(
              pw85_2d_contact_function(r, s->q + 3 * i, s->q + 3 * j, ml), ==,
              PW85_SUCCESS);
          overlap_u(ml[0], 1.0, u);
          count += ml[0] < 1.0;
          e += u[0];
          m += fabs(u[0]);
        }
  *magnitude = m;
  *pairs = count;
  return e;
}

static void test_brute_force(void) {
  Ellipses s = draw(90, 7.0, 2.0, 21);
  pw85_2d_index *index = indexed(&s);
  double magnitude;
  size_t pairs;
  double const expected = brute_force(&s, &magnitude, &pairs);
  g_assert_cmpuint(pairs, >, 40); /* many overlaps */
  double const e = total(index, s.n);
  /* The same correctly rounded terms summed in two orders: within
   * 2·pairs·u·Σ|U| (recursive summation, Higham, Accuracy and Stability,
   * eq. (4.4), for each order). */
  double const bound = 2.0 * (double)pairs * U_ROUND * magnitude;
  if (!(fabs(e - expected) <= bound))
    g_test_fail_printf("energy %.17g, brute force %.17g: %.3g > %.3g", e,
                       expected, fabs(e - expected), bound);
  pw85_2d_index_destroy(index);
  release(&s);
}

/* The energy with ellipse i moved to centre c and angle θ. */
static double moved(pw85_2d_index *index, Ellipses const *s, size_t i,
                    double const c[2], double theta) {
  double q[3];
  g_assert_cmpint(pw85_2d_ellipse(s->a + 2 * i, theta, q), ==, 0);
  g_assert_cmpint(pw85_2d_index_update(index, i, c, q), ==, 0);
  double const e = total(index, s->n);
  g_assert_cmpint(pw85_2d_index_update(index, i, s->c + 2 * i, s->q + 3 * i),
                  ==, 0);
  return e;
}

/* Forces and torques against central differences of the energy, along x,
 * y and θ of every ellipse. */
static void test_finite_differences(void) {
  Ellipses s = draw(60, 6.0, 2.0, 22);
  pw85_2d_index *index = indexed(&s);
  double e;
  double *f = g_new(double, 2 * s.n), *t = g_new(double, s.n);
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                       NULL, 2, s.n, &e, f, t),
                  ==, PW85_SUCCESS);
  g_assert_cmpfloat(e, >, 1.0);
  double const h = 1e-5;
  /* A central difference errs by h²/6·|U'''| (truncation) plus about
   * u·|E|/h (rounding of E): measured at most 1.7e-9 over these 180
   * components (forces and torques of order 1; 1.4e-7 with h = 1e-4,
   * truncation, and 2.0e-8 with h = 1e-6, rounding). 1e-7 leaves room
   * for other compilers and libms, not for a wrong formula (a wrong sign
   * or factor is an error of order 1). */
  double const tol = 1e-7;
  double worst = 0.0;
  for (size_t i = 0; i < s.n; i++) {
    double const *c0 = s.c + 2 * i;
    double d[3];
    for (int k = 0; k < 2; k++) {
      double cp[2] = {c0[0], c0[1]}, cm[2] = {c0[0], c0[1]};
      cp[k] += h;
      cm[k] -= h;
      d[k] = -(moved(index, &s, i, cp, s.theta[i]) -
               moved(index, &s, i, cm, s.theta[i])) /
             (2 * h);
    }
    d[2] = -(moved(index, &s, i, c0, s.theta[i] + h) -
             moved(index, &s, i, c0, s.theta[i] - h)) /
           (2 * h);
    double const got[3] = {f[2 * i], f[2 * i + 1], t[i]};
    for (int k = 0; k < 3; k++) {
      double const err = fabs(d[k] - got[k]) / (1.0 + fabs(d[k]));
      worst = fmax(worst, err);
      if (!(err <= tol))
        g_test_fail_printf(
            "ellipse %zu, %s: %.12g, central difference "
            "%.12g",
            i,
            k == 0   ? "F_x"
            : k == 1 ? "F_y"
                     : "T",
            got[k], d[k]);
    }
  }
  g_test_message("largest error against central differences: %.3g", worst);
  g_free(f);
  g_free(t);
  pw85_2d_index_destroy(index);
  release(&s);
}

/* Σ F = 0 and Σ (T_i + c_i × F_i) + Σ over pairs (n∘L) × F_j = 0: the
 * moments of the forces taken at the images' centres. */
static void test_balance(void) {
  Ellipses s = draw(400, 12.0, 3.0, 23);
  pw85_2d_index *index = indexed(&s);
  double e;
  double *f = g_new(double, 2 * s.n), *t = g_new(double, s.n);
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 2.0, NULL,
                                       NULL, 2, s.n, &e, f, t),
                  ==, PW85_SUCCESS);
  size_t count = 0;
  g_assert_cmpint(
      pw85_2d_index_pairs_within(index, 1.0, 1, 0, NULL, NULL, NULL, &count),
      ==, 0);
  g_assert_cmpuint(count, >, 100);
  size_t *ids = g_new(size_t, 2 * count);
  int *shifts = g_new(int, 2 * count);
  double *ml = g_new(double, 2 * count);
  g_assert_cmpint(
      pw85_2d_index_pairs_within(index, 1.0, 1, count, ids, shifts, ml, &count),
      ==, 0);
  int crossing = 0; /* pairs through a periodic image */
  double fx = 0, fy = 0, torque = 0, fscale = 0, tscale = 0;
  for (size_t k = 0; k < count; k++) {
    size_t const i = ids[2 * k], j = ids[2 * k + 1];
    double nl[2], r[2], geometry[PW85_2D_GEOM_SIZE], d[PW85_2D_DERIV_SIZE],
        u[2];
    for (int a = 0; a < 2; a++) {
      nl[a] = shifts[2 * k + a] * s.box[a];
      r[a] = s.c[2 * j + a] + nl[a] - s.c[2 * i + a];
    }
    crossing += shifts[2 * k] != 0 || shifts[2 * k + 1] != 0;
    g_assert_cmpint(
        pw85_2d_contact_derivatives(r, s.q + 3 * i, s.q + 3 * j, geometry, d),
        ==, 0);
    overlap_u(geometry[PW85_2D_GEOM_MU2], 2.0, u);
    double const fj[2] = {-u[1] * d[PW85_2D_DERIV_R12],
                          -u[1] * d[PW85_2D_DERIV_R12 + 1]};
    double const m = nl[0] * fj[1] - nl[1] * fj[0];
    torque += m;
    tscale += fabs(m);
  }
  g_assert_cmpint(crossing, >, 0);
  for (size_t i = 0; i < s.n; i++) {
    double const *c = s.c + 2 * i, *fi = f + 2 * i;
    double const m = c[0] * fi[1] - c[1] * fi[0];
    fx += fi[0];
    fy += fi[1];
    torque += m + t[i];
    fscale += fabs(fi[0]) + fabs(fi[1]);
    tscale += fabs(m) + fabs(t[i]);
  }
  /* Each pair's terms cancel in exact arithmetic; what remains is the
   * rounding of the sums (count + n terms each) and of each term (a few
   * u): (count + n)·8u times the sum of the magnitudes. */
  double const bf = 8.0 * (double)(count + s.n) * U_ROUND * fscale;
  double const bt = 8.0 * (double)(count + s.n) * U_ROUND * tscale;
  if (!(fabs(fx) <= bf && fabs(fy) <= bf))
    g_test_fail_printf("total force %.3g %.3g > %.3g", fx, fy, bf);
  if (!(fabs(torque) <= bt))
    g_test_fail_printf("total torque %.3g > %.3g", torque, bt);
  g_test_message(
      "total force %.3g %.3g (scale %.3g), torque %.3g (scale "
      "%.3g)",
      fx, fy, fscale, torque, tscale);
  g_free(ids);
  g_free(shifts);
  g_free(ml);
  g_free(f);
  g_free(t);
  pw85_2d_index_destroy(index);
  release(&s);
}

/* The same outputs, bit for bit, on 1, 2 and 8 threads (several blocks of
 * 256 pairs, the unit of the threads' schedule). */
static void test_threads(void) {
  size_t const n = g_getenv("PW85_TEST_SMALL") ? 2000 : 8000;
  Ellipses s = draw(n, sqrt((double)n) * 1.2, 1.5, 24);
  pw85_2d_index *index = indexed(&s);
  int const threads[3] = {1, 2, 8};
  double e[3], *f[3], *t[3];
  for (int k = 0; k < 3; k++) {
    f[k] = g_new(double, 2 * n);
    t[k] = g_new(double, n);
    g_assert_cmpint(
        pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL, NULL,
                             threads[k], n, e + k, f[k], t[k]),
        ==, PW85_SUCCESS);
  }
  size_t count = 0;
  g_assert_cmpint(
      pw85_2d_index_overlapping_pairs(index, 1, 0, NULL, NULL, NULL, &count),
      ==, 0);
  g_assert_cmpuint(count, >, 2048);
  for (int k = 1; k < 3; k++) {
    g_assert_true(memcmp(e, e + k, sizeof(double)) == 0);
    g_assert_true(memcmp(f[0], f[k], 2 * n * sizeof(double)) == 0);
    g_assert_true(memcmp(t[0], t[k], n * sizeof(double)) == 0);
  }
  for (int k = 0; k < 3; k++) {
    g_free(f[k]);
    g_free(t[k]);
  }
  pw85_2d_index_destroy(index);
  release(&s);
}

/* The user kind with the overlap energy's formula: the outputs of the
 * overlap kind, bit for bit; and a soft energy reaching beyond contact
 * (t = 1.5) against central differences (tolerance of
 * test_finite_differences()). */
static void test_user(void) {
  Ellipses s = draw(150, 9.0, 2.5, 25);
  pw85_2d_index *index = indexed(&s);
  double eps = 1.5, e1, e2;
  double *f1 = g_new(double, 2 * s.n), *t1 = g_new(double, s.n);
  double *f2 = g_new(double, 2 * s.n), *t2 = g_new(double, s.n);
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, eps, NULL,
                                       NULL, 2, s.n, &e1, f1, t1),
                  ==, 0);
  g_assert_cmpint(
      pw85_2d_index_energy(index, PW85_ENERGY_USER, 1.0, overlap_callback, &eps,
                           2, s.n, &e2, f2, t2),
      ==, 0);
  g_assert_cmpfloat(e1, >, 0.0);
  g_assert_true(memcmp(&e1, &e2, sizeof e1) == 0);
  g_assert_true(memcmp(f1, f2, 2 * s.n * sizeof(double)) == 0);
  g_assert_true(memcmp(t1, t2, s.n * sizeof(double)) == 0);
  double t = 1.5;
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_USER, t,
                                       soft_callback, &t, 1, s.n, &e1, f1, t1),
                  ==, 0);
  double const h = 1e-5, tol = 1e-7;
  for (size_t i = 0; i < 40; i++) {
    double const *c0 = s.c + 2 * i;
    double ep, em, q[3];
    g_assert_cmpint(pw85_2d_ellipse(s.a + 2 * i, s.theta[i] + h, q), ==, 0);
    g_assert_cmpint(pw85_2d_index_update(index, i, c0, q), ==, 0);
    g_assert_cmpint(
        pw85_2d_index_energy(index, PW85_ENERGY_USER, t, soft_callback, &t, 1,
                             s.n, &ep, NULL, NULL),
        ==, 0);
    g_assert_cmpint(pw85_2d_ellipse(s.a + 2 * i, s.theta[i] - h, q), ==, 0);
    g_assert_cmpint(pw85_2d_index_update(index, i, c0, q), ==, 0);
    g_assert_cmpint(
        pw85_2d_index_energy(index, PW85_ENERGY_USER, t, soft_callback, &t, 1,
                             s.n, &em, NULL, NULL),
        ==, 0);
    g_assert_cmpint(pw85_2d_index_update(index, i, c0, s.q + 3 * i), ==, 0);
    double const d = -(ep - em) / (2 * h);
    if (!(fabs(d - t1[i]) <= tol * (1.0 + fabs(d))))
      g_test_fail_printf(
          "soft torque on %zu: %.12g, central difference "
          "%.12g",
          i, t1[i], d);
  }
  g_free(f1);
  g_free(t1);
  g_free(f2);
  g_free(t2);
  pw85_2d_index_destroy(index);
  release(&s);
}

static int not_finite(double mu2, void *data, double out[2]) {
  (void)mu2;
  (void)data;
  out[0] = 0.0;
  out[1] = INFINITY;
  return 0;
}

/* A pair energy of 2^1023 on each pair: a sum beyond a double. */
static int huge(double mu2, void *data, double out[2]) {
  (void)mu2;
  (void)data;
  out[0] = 0x1p1023;
  out[1] = 0.0;
  return 0;
}

/* Every error status, with energy, forces and torques untouched. */
static void test_errors(void) {
  Ellipses s = draw(40, 4.0, 2.0, 26);
  pw85_2d_index *index = indexed(&s);
  double t = 1.0;
  struct {
    pw85_2d_index const *index;
    int kind;
    double param;
    pw85_pair_energy fn;
    int threads;
    size_t n;
    int energy; /* 0: NULL */
    int status;
  } const cases[] = {
      {NULL, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 40, 1, PW85_EFAULT},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 40, 0, PW85_EFAULT},
      {index, 2, 1.0, NULL, 1, 40, 1, PW85_EINVAL},
      {index, -1, 1.0, NULL, 1, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 0.0, NULL, 1, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, -2.0, NULL, 1, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, NAN, NULL, 1, 40, 1, PW85_EDOM},
      {index, PW85_ENERGY_OVERLAP, -INFINITY, NULL, 1, 40, 1, PW85_EDOM},
      {index, PW85_ENERGY_USER, 1.0, NULL, 1, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_USER, -1.0, soft_callback, 1, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 0, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, -3, 40, 1, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 39, 1, PW85_EINVAL},
      {index, PW85_ENERGY_USER, 1.0, stop_callback, 1, 40, 1, PW85_ECANCELLED},
      {index, PW85_ENERGY_USER, 1.0, not_finite, 1, 40, 1, PW85_EDOM},
      {index, PW85_ENERGY_USER, 1.5, huge, 1, 40, 1, PW85_ERANGE},
      /* 2·n doubles that no array can hold */
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, SIZE_MAX / 2 + 1, 1,
       PW85_ENOMEM},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    double e = 42.0, f[80], tq[40];
    for (int m = 0; m < 80; m++) f[m] = 42.0;
    for (int m = 0; m < 40; m++) tq[m] = 42.0;
    int const st = pw85_2d_index_energy(
        cases[k].index, cases[k].kind, cases[k].param, cases[k].fn, &t,
        cases[k].threads, cases[k].n, cases[k].energy ? &e : NULL, f, tq);
    if (st != cases[k].status)
      g_test_fail_printf("case %zu: status %d, expected %d", k, st,
                         cases[k].status);
    g_assert_cmpfloat(e, ==, 42.0);
    for (int m = 0; m < 80; m++) g_assert_cmpfloat(f[m], ==, 42.0);
    for (int m = 0; m < 40; m++) g_assert_cmpfloat(tq[m], ==, 42.0);
  }
  /* Without forces nor torques, n is only a bound on the ids: valid. */
  double e = 42.0;
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                       NULL, 1, SIZE_MAX, &e, NULL, NULL),
                  ==, PW85_SUCCESS);
  g_assert_cmpfloat(e, ==, total(index, 40));
  /* An empty index: 0, and rows of zeros. */
  pw85_2d_index *empty = NULL;
  double f[6] = {1, 1, 1, 1, 1, 1}, tq[3] = {1, 1, 1};
  g_assert_cmpint(pw85_2d_index_create(NULL, &empty), ==, 0);
  g_assert_cmpint(pw85_2d_index_energy(empty, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                       NULL, 1, 3, &e, f, tq),
                  ==, 0);
  g_assert_cmpfloat(e, ==, 0.0);
  for (int m = 0; m < 6; m++) g_assert_cmpfloat(f[m], ==, 0.0);
  for (int m = 0; m < 3; m++) g_assert_cmpfloat(tq[m], ==, 0.0);
  pw85_2d_index_destroy(empty);
  pw85_2d_index_destroy(index);
  release(&s);
}

/* Two unit circles, centres 1 apart along x in an open plane, worked by
 * hand: μ = |r|/2 = 1/2, U = (1 − μ)² = 1/4 exactly; μ² = |r|²/4, so
 * g = ∂μ²/∂r = r/2 = (1/2, 0), U′ = −(1 − μ)/μ = −1, and the force on
 * the second circle is −U′·g = (1/2, 0), on the first its opposite; a
 * circle has no torque (to rounding). */
static void test_circles(void) {
  pw85_2d_index *index = NULL;
  double const q[3] = {1, 0, 1}, c0[2] = {0, 0}, c1[2] = {1, 0};
  g_assert_cmpint(pw85_2d_index_create(NULL, &index), ==, 0);
  g_assert_cmpint(pw85_2d_index_insert(index, 0, c0, q), ==, 0);
  g_assert_cmpint(pw85_2d_index_insert(index, 1, c1, q), ==, 0);
  double e, f[4], t[2];
  g_assert_cmpint(pw85_2d_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                       NULL, 1, 2, &e, f, t),
                  ==, 0);
  g_assert_cmpfloat(e, ==, 0.25);
  g_assert_cmpfloat_with_epsilon(f[2], 0.5, 4 * U_ROUND);
  g_assert_cmpfloat(f[0], ==, -f[2]);
  g_assert_cmpfloat(f[1], ==, 0.0);
  g_assert_cmpfloat(f[3], ==, 0.0);
  g_assert_cmpfloat(fabs(t[0]), <=, 4 * U_ROUND);
  g_assert_cmpfloat(fabs(t[1]), <=, 4 * U_ROUND);
  pw85_2d_index_destroy(index);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/2d-energy/brute-force", test_brute_force);
  g_test_add_func("/pw85/2d-energy/finite-differences",
                  test_finite_differences);
  g_test_add_func("/pw85/2d-energy/balance", test_balance);
  g_test_add_func("/pw85/2d-energy/threads", test_threads);
  g_test_add_func("/pw85/2d-energy/user", test_user);
  g_test_add_func("/pw85/2d-energy/errors", test_errors);
  g_test_add_func("/pw85/2d-energy/circles", test_circles);
  return g_test_run();
}
