/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_index_energy(): the energy summed over an assembly, the forces and
 * the torques, against central differences of the energy, a brute force
 * over every pair and image, the balance of forces and moments, and
 * itself on 1, 2 and 8 threads. */
#include <glib.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "pw85.h"
#include "pw85_index.h"
#include "energy-util.h"
#include "testutil.h"

#define U_ROUND 1.1102230246251565e-16 /* 2^-53 */

typedef struct {
  size_t n;
  double box[3];
  double *a;  /* semi-axes, 3n */
  double *p;  /* quaternions, 4n */
  double *c;  /* centres, 3n */
  double *q;  /* forms, 6n */
} Assembly;

/* n triaxial ellipsoids (semi-axes s·(1, 0.6, 0.3), s in [0.7, 1.3]) at
 * random centres on a grid of 2^-20 in a cube of side L (so that every
 * image vector is a double: the brute force below then decides what the
 * index decides), random orientations: many overlaps when L is small. */
static Assembly make_assembly(size_t n, double side, guint32 seed) {
  Assembly s = {n, {side, side, side}, NULL, NULL, NULL, NULL};
  s.a = g_new(double, 3 * n);
  s.p = g_new(double, 4 * n);
  s.c = g_new(double, 3 * n);
  s.q = g_new(double, 6 * n);
  GRand *rng = g_rand_new_with_seed(seed);
  for (size_t i = 0; i < n; i++) {
    double const f = g_rand_double_range(rng, 0.7, 1.3);
    s.a[3 * i] = f;
    s.a[3 * i + 1] = 0.6 * f;
    s.a[3 * i + 2] = 0.3 * f;
    random_unit_quaternion(rng, s.p + 4 * i);
    for (int k = 0; k < 3; k++)
      s.c[3 * i + k] = ldexp(floor(ldexp(g_rand_double(rng) * side, 20)), -20);
    g_assert_cmpint(pw85_ellipsoid_quaternion(s.a + 3 * i, s.p + 4 * i,
                                              s.q + 6 * i), ==, PW85_SUCCESS);
  }
  g_rand_free(rng);
  return s;
}

static void free_assembly(Assembly *s) {
  g_free(s->a);
  g_free(s->p);
  g_free(s->c);
  g_free(s->q);
}

static pw85_index *index_of(Assembly const *s) {
  pw85_index *index = NULL;
  g_assert_cmpint(pw85_index_create(s->box, &index), ==, PW85_SUCCESS);
  size_t *ids = g_new(size_t, s->n);
  for (size_t i = 0; i < s->n; i++) ids[i] = i;
  g_assert_cmpint(pw85_index_insert_many(index, s->n, ids, s->c, s->q), ==,
                  PW85_SUCCESS);
  g_free(ids);
  return index;
}

static double energy_of(pw85_index const *index, size_t n) {
  double e = NAN;
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 1, n, &e, NULL, NULL),
                  ==, PW85_SUCCESS);
  return e;
}

/* The energy from every pair i < j and image n in {-1, 0, 1}^3 (the box
 * is more than twice the reach of any pair), decided by
 * pw85_contact_function(): a brute force with no index. Returns the sum
 * and, in *abs_sum, the sum of the magnitudes of its terms. */
static double brute_energy(Assembly const *s, double *abs_sum, size_t *pairs) {
  double e = 0.0, mag = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < s->n; i++)
    for (size_t j = i + 1; j < s->n; j++)
      for (int n0 = -1; n0 <= 1; n0++)
        for (int n1 = -1; n1 <= 1; n1++)
          for (int n2 = -1; n2 <= 1; n2++) {
            int const n[3] = {n0, n1, n2};
            double r[3], out[2], u[2];
            for (int k = 0; k < 3; k++)
              r[k] = s->c[3 * j + k] + n[k] * s->box[k] - s->c[3 * i + k];
            g_assert_cmpint(pw85_contact_function(r, s->q + 6 * i,
                                                  s->q + 6 * j, out),
                            ==, PW85_SUCCESS);
            overlap_u(out[0], 1.0, u);
            if (out[0] < 1.0) count++;
            e += u[0];
            mag += fabs(u[0]);
          }
  *abs_sum = mag;
  *pairs = count;
  return e;
}

static void test_brute_force(void) {
  Assembly s = make_assembly(80, 6.0, 11);
  pw85_index *index = index_of(&s);
  double mag;
  size_t pairs;
  double const expected = brute_energy(&s, &mag, &pairs);
  g_assert_cmpuint(pairs, >, 40); /* the case is one of many overlaps */
  double const e = energy_of(index, s.n);
  /* Both are sums of the same correctly rounded terms in different
   * orders: within (pairs·u)·Σ|U| of each other (recursive summation,
   * Higham, Accuracy and Stability, eq. (4.4)), both ways. */
  double const bound = 2.0 * (double)pairs * U_ROUND * mag;
  if (!(fabs(e - expected) <= bound))
    g_test_fail_printf("energy %.17g, brute force %.17g, difference %.3g > %.3g",
                       e, expected, fabs(e - expected), bound);
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* Rotates quaternion p by the rotation vector w in the lab frame:
 * p' = exp(w/2)·p (Hamilton product). */
static void rotate_quaternion(double const w[3], double const p[4],
                              double out[4]) {
  double const t = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  double const sc = t > 0 ? sin(0.5 * t) / t : 0.5;
  double const r[4] = {cos(0.5 * t), sc * w[0], sc * w[1], sc * w[2]};
  out[0] = r[0] * p[0] - r[1] * p[1] - r[2] * p[2] - r[3] * p[3];
  out[1] = r[0] * p[1] + r[1] * p[0] + r[2] * p[3] - r[3] * p[2];
  out[2] = r[0] * p[2] - r[1] * p[3] + r[2] * p[0] + r[3] * p[1];
  out[3] = r[0] * p[3] + r[1] * p[2] - r[2] * p[1] + r[3] * p[0];
}

/* Forces and torques against central differences of the energy, for
 * every coordinate and rotation of every ellipsoid. */
static void test_finite_differences(void) {
  Assembly s = make_assembly(40, 5.0, 12);
  pw85_index *index = index_of(&s);
  double e;
  double *f = g_new(double, 3 * s.n), *t = g_new(double, 3 * s.n);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 2, s.n, &e, f, t),
                  ==, PW85_SUCCESS);
  g_assert_cmpfloat(e, >, 1.0);
  double const h = 1e-5;
  /* The error of a central difference: h²/6·|U'''| (truncation) plus
   * 2·δE/(2h) (δE the rounding of E, a few u·|E|): measured at most
   * 1.2e-9 over these 240 components, against forces and torques of
   * order 1; 1e-7 leaves room for other compilers, not for a wrong
   * formula (a missing factor or sign is an error of order 1). */
  double const tol = 1e-7;
  double worst = 0.0;
  for (size_t i = 0; i < s.n; i++) {
    for (int k = 0; k < 3; k++) {
      double c[3] = {s.c[3 * i], s.c[3 * i + 1], s.c[3 * i + 2]};
      double ep, em;
      c[k] += h;
      g_assert_cmpint(pw85_index_update(index, i, c, s.q + 6 * i), ==, 0);
      ep = energy_of(index, s.n);
      c[k] -= 2 * h;
      g_assert_cmpint(pw85_index_update(index, i, c, s.q + 6 * i), ==, 0);
      em = energy_of(index, s.n);
      g_assert_cmpint(pw85_index_update(index, i, s.c + 3 * i, s.q + 6 * i),
                      ==, 0);
      double const fd = -(ep - em) / (2 * h);
      double const err = fabs(fd - f[3 * i + k]) / (1.0 + fabs(fd));
      worst = fmax(worst, err);
      if (!(err <= tol))
        g_test_fail_printf("force on %zu, axis %d: %.12g, difference %.12g",
                           i, k, f[3 * i + k], fd);
      double w[3] = {0, 0, 0}, pq[4], qq[6];
      w[k] = h;
      rotate_quaternion(w, s.p + 4 * i, pq);
      g_assert_cmpint(pw85_ellipsoid_quaternion(s.a + 3 * i, pq, qq), ==, 0);
      g_assert_cmpint(pw85_index_update(index, i, s.c + 3 * i, qq), ==, 0);
      ep = energy_of(index, s.n);
      w[k] = -h;
      rotate_quaternion(w, s.p + 4 * i, pq);
      g_assert_cmpint(pw85_ellipsoid_quaternion(s.a + 3 * i, pq, qq), ==, 0);
      g_assert_cmpint(pw85_index_update(index, i, s.c + 3 * i, qq), ==, 0);
      em = energy_of(index, s.n);
      g_assert_cmpint(pw85_index_update(index, i, s.c + 3 * i, s.q + 6 * i),
                      ==, 0);
      double const td = -(ep - em) / (2 * h);
      double const terr = fabs(td - t[3 * i + k]) / (1.0 + fabs(td));
      worst = fmax(worst, terr);
      if (!(terr <= tol))
        g_test_fail_printf("torque on %zu, axis %d: %.12g, difference %.12g",
                           i, k, t[3 * i + k], td);
    }
  }
  g_test_message("largest error against central differences: %.3g", worst);
  g_free(f);
  g_free(t);
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* Σ forces = 0, and Σ torques + Σ moments of the forces about the origin,
 * each pair's forces applied at the centres of the images it joins, = 0:
 * to the rounding of the sums. */
static void test_balance(void) {
  Assembly s = make_assembly(300, 8.0, 13);
  pw85_index *index = index_of(&s);
  double e;
  double *f = g_new(double, 3 * s.n), *t = g_new(double, 3 * s.n);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 2.0, NULL,
                                    NULL, 2, s.n, &e, f, t),
                  ==, PW85_SUCCESS);
  size_t count = 0;
  g_assert_cmpint(pw85_index_pairs_within(index, 1.0, 1, 0, NULL, NULL, NULL,
                                          &count), ==, 0);
  g_assert_cmpuint(count, >, 100);
  size_t *ids = g_new(size_t, 2 * count);
  int *shifts = g_new(int, 3 * count);
  double *ml = g_new(double, 2 * count);
  g_assert_cmpint(pw85_index_pairs_within(index, 1.0, 1, count, ids, shifts,
                                          ml, &count), ==, 0);
  /* The moment of each pair's force on j about the image shift n∘L (the
   * part of the lever arm that Σ c_k × F_k misses), from
   * pw85_contact_derivatives() and the formula of pw85_index.h. */
  double total_f[3] = {0, 0, 0}, total_t[3] = {0, 0, 0}, scale_f = 0,
         scale_t = 0;
  for (size_t k = 0; k < count; k++) {
    size_t const i = ids[2 * k], j = ids[2 * k + 1];
    double r[3], nl[3], g[8], d[21], u[2];
    for (int a = 0; a < 3; a++) {
      nl[a] = shifts[3 * k + a] * s.box[a];
      r[a] = s.c[3 * j + a] + nl[a] - s.c[3 * i + a];
    }
    g_assert_cmpint(pw85_contact_derivatives(r, s.q + 6 * i, s.q + 6 * j, g,
                                             d), ==, 0);
    overlap_u(g[0], 2.0, u);
    double fj[3];
    for (int a = 0; a < 3; a++) fj[a] = -u[1] * d[PW85_DERIV_R12 + a];
    double const m[3] = {nl[1] * fj[2] - nl[2] * fj[1],
                         nl[2] * fj[0] - nl[0] * fj[2],
                         nl[0] * fj[1] - nl[1] * fj[0]};
    for (int a = 0; a < 3; a++) {
      total_t[a] += m[a];
      scale_t += fabs(m[a]);
    }
  }
  for (size_t i = 0; i < s.n; i++) {
    double const *c = s.c + 3 * i, *fi = f + 3 * i;
    double const m[3] = {c[1] * fi[2] - c[2] * fi[1],
                         c[2] * fi[0] - c[0] * fi[2],
                         c[0] * fi[1] - c[1] * fi[0]};
    for (int a = 0; a < 3; a++) {
      total_f[a] += fi[a];
      total_t[a] += m[a] + t[3 * i + a];
      scale_f += fabs(fi[a]);
      scale_t += fabs(m[a]) + fabs(t[3 * i + a]);
    }
  }
  /* Each pair's terms cancel exactly in exact arithmetic; what remains is
   * the rounding of the sums and of the derivatives (a few u·cond each,
   * pw85.h): bounded by (terms per sum)·u·(sum of magnitudes), with
   * count + n terms, times 8 for the rounding of each term. */
  double const bound_f = 8.0 * (double)(count + s.n) * U_ROUND * scale_f;
  double const bound_t = 8.0 * (double)(count + s.n) * U_ROUND * scale_t;
  for (int a = 0; a < 3; a++) {
    if (!(fabs(total_f[a]) <= bound_f))
      g_test_fail_printf("total force %d: %.3g > %.3g", a, total_f[a], bound_f);
    if (!(fabs(total_t[a]) <= bound_t))
      g_test_fail_printf("total torque %d: %.3g > %.3g", a, total_t[a],
                         bound_t);
  }
  g_test_message("total force %.3g %.3g %.3g (scale %.3g); torque %.3g %.3g "
                 "%.3g (scale %.3g)", total_f[0], total_f[1], total_f[2],
                 scale_f, total_t[0], total_t[1], total_t[2], scale_t);
  g_free(ids);
  g_free(shifts);
  g_free(ml);
  g_free(f);
  g_free(t);
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* The same outputs, bit for bit, on 1, 2 and 8 threads. */
static void test_threads(void) {
  size_t const n = g_getenv("PW85_TEST_SMALL") ? 1500 : 6000;
  Assembly s = make_assembly(n, cbrt((double)n) * 1.1, 14);
  pw85_index *index = index_of(&s);
  double e[3];
  double *f[3], *t[3];
  int const threads[3] = {1, 2, 8};
  for (int k = 0; k < 3; k++) {
    f[k] = g_new(double, 3 * n);
    t[k] = g_new(double, 3 * n);
    g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                      NULL, threads[k], n, e + k, f[k], t[k]),
                    ==, PW85_SUCCESS);
  }
  size_t count = 0;
  g_assert_cmpint(pw85_index_overlapping_pairs(index, 1, 0, NULL, NULL, NULL,
                                               &count), ==, 0);
  g_assert_cmpuint(count, >, 2048); /* several blocks of 256 pairs */
  for (int k = 1; k < 3; k++) {
    g_assert_true(memcmp(e, e + k, sizeof(double)) == 0);
    g_assert_true(memcmp(f[0], f[k], 3 * n * sizeof(double)) == 0);
    g_assert_true(memcmp(t[0], t[k], 3 * n * sizeof(double)) == 0);
  }
  for (int k = 0; k < 3; k++) {
    g_free(f[k]);
    g_free(t[k]);
  }
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* PW85_ENERGY_USER with the overlap energy's formula gives the outputs of
 * PW85_ENERGY_OVERLAP, bit for bit (centres on a grid: the same μ²). */
static void test_user_as_overlap(void) {
  Assembly s = make_assembly(200, 7.0, 15);
  pw85_index *index = index_of(&s);
  double eps = 1.5, e1, e2;
  double *f1 = g_new(double, 3 * s.n), *t1 = g_new(double, 3 * s.n);
  double *f2 = g_new(double, 3 * s.n), *t2 = g_new(double, 3 * s.n);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, eps, NULL,
                                    NULL, 2, s.n, &e1, f1, t1), ==, 0);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_USER, 1.0,
                                    overlap_callback, &eps, 2, s.n, &e2, f2,
                                    t2), ==, 0);
  g_assert_cmpfloat(e1, >, 0.0);
  g_assert_true(memcmp(&e1, &e2, sizeof e1) == 0);
  g_assert_true(memcmp(f1, f2, 3 * s.n * sizeof(double)) == 0);
  g_assert_true(memcmp(t1, t2, 3 * s.n * sizeof(double)) == 0);
  g_free(f1);
  g_free(t1);
  g_free(f2);
  g_free(t2);
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* A caller's energy reaching beyond contact (t = 1.5), against central
 * differences (the tolerance of test_finite_differences()). */
static void test_user_finite_differences(void) {
  Assembly s = make_assembly(30, 6.0, 16);
  pw85_index *index = index_of(&s);
  double t = 1.5, e;
  double *f = g_new(double, 3 * s.n), *tq = g_new(double, 3 * s.n);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_USER, t, soft_callback,
                                    &t, 1, s.n, &e, f, tq), ==, 0);
  g_assert_cmpfloat(e, >, 0.0);
  double const h = 1e-5, tol = 1e-7;
  for (size_t i = 0; i < s.n; i++)
    for (int k = 0; k < 3; k++) {
      double c[3] = {s.c[3 * i], s.c[3 * i + 1], s.c[3 * i + 2]}, ep, em;
      c[k] += h;
      g_assert_cmpint(pw85_index_update(index, i, c, s.q + 6 * i), ==, 0);
      g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_USER, t,
                                        soft_callback, &t, 1, s.n, &ep, NULL,
                                        NULL), ==, 0);
      c[k] -= 2 * h;
      g_assert_cmpint(pw85_index_update(index, i, c, s.q + 6 * i), ==, 0);
      g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_USER, t,
                                        soft_callback, &t, 1, s.n, &em, NULL,
                                        NULL), ==, 0);
      g_assert_cmpint(pw85_index_update(index, i, s.c + 3 * i, s.q + 6 * i),
                      ==, 0);
      double const fd = -(ep - em) / (2 * h);
      if (!(fabs(fd - f[3 * i + k]) <= tol * (1.0 + fabs(fd))))
        g_test_fail_printf("force on %zu, axis %d: %.12g, difference %.12g",
                           i, k, f[3 * i + k], fd);
    }
  g_free(f);
  g_free(tq);
  pw85_index_destroy(index);
  free_assembly(&s);
}

static int nan_callback(double mu2, void *data, double out[2]) {
  (void)mu2;
  (void)data;
  out[0] = NAN;
  out[1] = 0.0;
  return 0;
}

/* Every error status, and nothing written on error. */
static void test_errors(void) {
  Assembly s = make_assembly(50, 5.0, 17);
  pw85_index *index = index_of(&s);
  double e = 42.0, t = 1.0;
  double f[150], tq[150];
  for (int k = 0; k < 150; k++) f[k] = tq[k] = 42.0;
  struct {
    pw85_index const *index;
    int kind;
    double param;
    pw85_pair_energy fn;
    int threads;
    size_t n;
    double *energy;
    int status;
  } const cases[] = {
      {NULL, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 50, &e, PW85_EFAULT},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 50, NULL, PW85_EFAULT},
      {index, 2, 1.0, NULL, 1, 50, &e, PW85_EINVAL},
      {index, -1, 1.0, NULL, 1, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 0.0, NULL, 1, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, -1.0, NULL, 1, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, NAN, NULL, 1, 50, &e, PW85_EDOM},
      {index, PW85_ENERGY_OVERLAP, INFINITY, NULL, 1, 50, &e, PW85_EDOM},
      {index, PW85_ENERGY_USER, 1.0, NULL, 1, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_USER, 0.0, soft_callback, 1, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 0, 50, &e, PW85_EINVAL},
      {index, PW85_ENERGY_OVERLAP, 1.0, NULL, 1, 49, &e, PW85_EINVAL},
      {index, PW85_ENERGY_USER, 1.0, stop_callback, 1, 50, &e,
       PW85_ECANCELLED},
      {index, PW85_ENERGY_USER, 1.0, nan_callback, 1, 50, &e, PW85_EDOM},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    int const st = pw85_index_energy(cases[k].index, cases[k].kind,
                                     cases[k].param, cases[k].fn, &t,
                                     cases[k].threads, cases[k].n,
                                     cases[k].energy, f, tq);
    if (st != cases[k].status)
      g_test_fail_printf("case %zu: status %d, expected %d", k, st,
                         cases[k].status);
  }
  g_assert_cmpfloat(e, ==, 42.0);
  for (int k = 0; k < 150; k++) {
    g_assert_cmpfloat(f[k], ==, 42.0);
    g_assert_cmpfloat(tq[k], ==, 42.0);
  }
  g_assert_cmpstr(pw85_strerror(PW85_ECANCELLED), !=, "unknown pw85 status");
  /* An empty index: energy 0, rows of zeros. */
  pw85_index *empty = NULL;
  double const box[3] = {1, 1, 1};
  g_assert_cmpint(pw85_index_create(box, &empty), ==, 0);
  g_assert_cmpint(pw85_index_energy(empty, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 1, 3, &e, f, tq), ==, 0);
  g_assert_cmpfloat(e, ==, 0.0);
  for (int k = 0; k < 9; k++) g_assert_cmpfloat(f[k], ==, 0.0);
  pw85_index_destroy(empty);
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* Rows whose 3·n doubles do not fit a size_t: PW85_ENOMEM (no array of
 * that size can exist), nothing written; without forces nor torques such
 * an n is only a bound on the ids, and valid. (3·n wrapped around to a
 * few doubles: the rows of ids 0 and 1 were written past the end of a
 * buffer of 2, and the call succeeded.) */
static void test_rows_overflow(void) {
  Assembly s = make_assembly(20, 3.0, 5);
  pw85_index *index = index_of(&s);
  size_t const n = SIZE_MAX / 3 + 1; /* 3·n wraps to 2 */
  double e = 42.0, f[60], tq[60];
  for (int k = 0; k < 60; k++) f[k] = tq[k] = 42.0;
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 1, n, &e, f, NULL), ==, PW85_ENOMEM);
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 2, SIZE_MAX, &e, NULL, tq), ==,
                  PW85_ENOMEM);
  g_assert_cmpfloat(e, ==, 42.0);
  for (int k = 0; k < 60; k++) {
    g_assert_cmpfloat(f[k], ==, 42.0);
    g_assert_cmpfloat(tq[k], ==, 42.0);
  }
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 1.0, NULL,
                                    NULL, 1, SIZE_MAX, &e, NULL, NULL), ==,
                  PW85_SUCCESS);
  g_assert_cmpfloat(e, ==, energy_of(index, 20));
  pw85_index_destroy(index);
  free_assembly(&s);
}

/* A pair energy of 2^1023 on each of two overlapping pairs: the sum is
 * beyond the range of a double, PW85_ERANGE, nothing written (it was
 * +inf with PW85_SUCCESS); the same for a slope whose force overflows. */
static int huge_callback(double mu2, void *data, double out[2]) {
  (void)mu2;
  double const *slope = data;
  out[0] = *slope == 0.0 ? 0x1p1023 : 1.0;
  out[1] = *slope;
  return 0;
}

static void test_sum_overflow(void) {
  /* Three unit spheres on a line, centres 1 apart: pairs (0, 1), (1, 2)
   * and (0, 2) overlap (μ = 1/2, 1/2, 1). */
  double const box[3] = {10, 10, 10}, q[6] = {1, 0, 0, 1, 0, 1};
  double const c[9] = {1, 1, 1, 2, 1, 1, 3, 1, 1};
  pw85_index *index = NULL;
  g_assert_cmpint(pw85_index_create(box, &index), ==, PW85_SUCCESS);
  for (size_t i = 0; i < 3; i++)
    g_assert_cmpint(pw85_index_insert(index, i, c + 3 * i, q), ==,
                    PW85_SUCCESS);
  double const slopes[] = {0.0, -0x1.fp1023};
  for (size_t k = 0; k < G_N_ELEMENTS(slopes); k++) {
    double e = 42.0, f[9], tq[9];
    for (int m = 0; m < 9; m++) f[m] = tq[m] = 42.0;
    int const st = pw85_index_energy(index, PW85_ENERGY_USER, 1.5,
                                     huge_callback, (void *)&slopes[k], 1, 3,
                                     &e, f, tq);
    if (st != PW85_ERANGE)
      g_test_fail_printf("slope %g: status %d (energy %g, force %g), "
                         "expected PW85_ERANGE", slopes[k], st, e, f[0]);
    g_assert_cmpfloat(e, ==, 42.0);
    for (int m = 0; m < 9; m++) {
      g_assert_cmpfloat(f[m], ==, 42.0);
      g_assert_cmpfloat(tq[m], ==, 42.0);
    }
  }
  /* ε = 2^1023 with pairs of (1 − μ)² = 1/4: 2^1023·(1/4 + 1/4) is a
   * double, so the overlap energy succeeds. */
  double e = 0.0;
  g_assert_cmpint(pw85_index_energy(index, PW85_ENERGY_OVERLAP, 0x1p1023,
                                    NULL, NULL, 1, 3, &e, NULL, NULL), ==,
                  PW85_SUCCESS);
  g_assert_cmpfloat(e, ==, 0x1p1022);
  pw85_index_destroy(index);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/energy/brute-force", test_brute_force);
  g_test_add_func("/pw85/energy/finite-differences", test_finite_differences);
  g_test_add_func("/pw85/energy/balance", test_balance);
  g_test_add_func("/pw85/energy/threads", test_threads);
  g_test_add_func("/pw85/energy/user-as-overlap", test_user_as_overlap);
  g_test_add_func("/pw85/energy/user-finite-differences",
                  test_user_finite_differences);
  g_test_add_func("/pw85/energy/errors", test_errors);
  g_test_add_func("/pw85/energy/rows-overflow", test_rows_overflow);
  g_test_add_func("/pw85/energy/sum-overflow", test_sum_overflow);
  return g_test_run();
}
