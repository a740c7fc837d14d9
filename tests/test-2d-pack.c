/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85_2d_pack(): every packing of ellipses checked by a brute force over
 * every pair and image (pw85_2d_overlap() and pw85_2d_contact_function(),
 * no index); the forms are pw85_2d_ellipse() of the outputs, bit for bit;
 * a target near jamming reached, and the jammed outcome beyond it;
 * determinism on 1, 2 and 8 threads; the aligned rule; the outputs of
 * semi-axes scaled by 2^k are the outputs scaled; every bad input. */
#include <glib.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "energy-util.h"
#include "pw85_2d.h"
#include "pw85_2d_pack.h"
#include "testutil.h"

typedef struct {
  size_t n;
  double const *a;
  double *c, *theta, *q;
  double box[2], phi;
  int outcome, status;
} Ellipses;

static Ellipses pack(size_t n, double const *a, pw85_pack_options const *o) {
  Ellipses s = {n, a, NULL, NULL, NULL, {0, 0}, 0, -1, -1};
  s.c = g_new(double, 2 * n);
  s.theta = g_new(double, n);
  s.q = g_new(double, 3 * n);
  s.status =
      pw85_2d_pack(n, a, o, s.box, s.c, s.theta, s.q, &s.phi, &s.outcome);
  return s;
}

static void release(Ellipses *s) {
  g_free(s->c);
  g_free(s->theta);
  g_free(s->q);
}

/* The smallest μ² over every pair i < j and image n ∈ {−1, 0, 1}², from
 * pw85_2d_contact_function() on r = (c_j + n∘L) − c_i rounded to doubles
 * (images beyond ±1 cannot meet: centres in [0, L), sides above twice the
 * largest semi-axis, checked here with √Q_kk); *bad counts the pairs that
 * pw85_2d_overlap() on that r finds overlapping or tangent. The rounding
 * of r moves μ² by a few ulps: where the smallest μ² exceeds 1 by 2^-30,
 * the decisions on the rounded r are those on the exact image vectors. */
static double brute_force(Ellipses const *s, size_t *bad) {
  double least = INFINITY;
  *bad = 0;
  for (size_t i = 0; i < s->n; i++) {
    for (int k = 0; k < 2; k++) {
      g_assert_cmpfloat(s->c[2 * i + k], >=, 0.0);
      g_assert_cmpfloat(s->c[2 * i + k], <, s->box[k]);
      g_assert_cmpfloat(2.0 * sqrt(s->q[3 * i + 2 * k]), <, s->box[k]);
    }
    for (size_t j = i + 1; j < s->n; j++)
      for (int n0 = -1; n0 <= 1; n0++)
        for (int n1 = -1; n1 <= 1; n1++) {
          double const r[2] = {
              s->c[2 * j] + n0 * s->box[0] - s->c[2 * i],
              s->c[2 * j + 1] + n1 * s->box[1] - s->c[2 * i + 1]};
          double ml[2];
          int result = 2;
          g_assert_cmpint(
              pw85_2d_overlap(r, s->q + 3 * i, s->q + 3 * j, &result), ==,
              PW85_SUCCESS);
          g_assert_cmpint(
              pw85_2d_contact_function(r, s->q + 3 * i, s->q + 3 * j, ml), ==,
              PW85_SUCCESS);
          *bad += result <= 0;
          least = fmin(least, ml[0]);
        }
  }
  return least;
}

/* The packing fraction Σπ·a0·a1/(L0·L1), as pw85_2d_pack.h defines it. */
static double fraction(Ellipses const *s) {
  double v = 0.0;
  for (size_t i = 0; i < s->n; i++) v += s->a[2 * i] * s->a[2 * i + 1];
  return G_PI * v / (s->box[0] * s->box[1]);
}

static void check(Ellipses const *s) {
  g_assert_cmpint(s->status, ==, PW85_SUCCESS);
  size_t bad = 0;
  double const least = brute_force(s, &bad);
  g_assert_cmpuint(bad, ==, 0);
  g_assert_cmpfloat(least, >, 1.0 + 0x1p-30);
  g_assert_cmpfloat(fabs(s->phi - fraction(s)), <=, 1e-14 * s->phi);
  for (size_t i = 0; i < s->n; i++) {
    double q[3];
    g_assert_cmpfloat(fabs(s->theta[i]), <=, G_PI);
    g_assert_cmpint(pw85_2d_ellipse(s->a + 2 * i, s->theta[i], q), ==,
                    PW85_SUCCESS);
    g_assert_true(memcmp(q, s->q + 3 * i, sizeof q) == 0);
  }
}

/* n ellipses of semi-axes s·(1, 1/aspect); s = 1, or 1 to 2 in 5 sizes
 * (poly). */
static double *ellipses(size_t n, double aspect, int poly) {
  double *a = g_new(double, 2 * n);
  for (size_t i = 0; i < n; i++) {
    double const s = poly ? 1.0 + (double)(i % 5) / 4.0 : 1.0;
    a[2 * i] = s;
    a[2 * i + 1] = s / aspect;
  }
  return a;
}

static size_t small(size_t n) {
  return g_getenv("PW85_TEST_SMALL") ? n / 2 : n;
}

/* Targets reached, certified by the brute force: aspect 1.3 to 0.85
 * (random close packing of discs is near 0.84; the densest of ellipses of
 * aspect 1.3 near 0.90), polydisperse, needles of aspect 5, a 2 : 1
 * rectangle. */
static void test_targets(void) {
  struct {
    double aspect, target;
    int poly;
    double sides[2];
  } const cases[] = {
      {1.3, 0.85, 0, {1, 1}},
      {2.0, 0.75, 1, {1, 1}},
      {5.0, 0.60, 0, {1, 1}},
      {1.5, 0.70, 1, {2, 1}},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    size_t const n = small(200);
    double *a = ellipses(n, cases[k].aspect, cases[k].poly);
    pw85_pack_options o;
    pw85_pack_options_init(&o);
    o.target = cases[k].target;
    o.seed = 40 + k;
    o.aspect[0] = cases[k].sides[0];
    o.aspect[1] = cases[k].sides[1];
    Ellipses s = pack(n, a, &o);
    check(&s);
    g_assert_cmpint(s.outcome, ==, PW85_PACK_TARGET);
    g_assert_cmpfloat(fabs(s.phi - cases[k].target), <=, 1e-14);
    g_assert_cmpfloat(
        fabs(s.box[1] / s.box[0] - cases[k].sides[1] / cases[k].sides[0]), <=,
        1e-14);
    release(&s);
    g_free(a);
  }
}

/* Sizes 100 : 1 and 30 : 1 at φ = 0.3, far below jamming: the target is
 * reached (two unit discs and one of 0.01 came back PW85_PACK_JAMMED at
 * 0.26 for seed 3, as in 3D: test-pack.c, size-ratio). 8 + 72 at 100 : 1
 * also needs the stall window to grow with the sizes (0.275 and 0.251,
 * jammed, with 500 steps); 1.4 s, not run under valgrind. */
static void test_size_ratio(void) {
  struct {
    size_t big, small;
    double ratio;
    uint64_t seeds;
  } const cases[] = {{2, 1, 100., 3}, {6, 30, 30., 2}, {8, 72, 100., 2}};
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    if (k == 2 && g_getenv("PW85_TEST_SMALL")) continue;
    size_t const n = cases[k].big + cases[k].small;
    double *a = g_new(double, 2 * n);
    for (size_t i = 0; i < 2 * n; i++)
      a[i] = i < 2 * cases[k].big ? 1.0 : 1.0 / cases[k].ratio;
    for (uint64_t seed = 1; seed <= cases[k].seeds; seed++) {
      pw85_pack_options o;
      pw85_pack_options_init(&o);
      o.target = 0.3;
      o.seed = seed;
      Ellipses s = pack(n, a, &o);
      check(&s);
      if (s.outcome != PW85_PACK_TARGET)
        g_test_fail_printf("%zu + %zu discs at %g : 1, seed %d: outcome %d "
                           "at phi = %.4f", cases[k].big, cases[k].small,
                           cases[k].ratio, (int)seed, s.outcome, s.phi);
      release(&s);
    }
    g_free(a);
  }
}

/* A target beyond jamming (0.95 for aspect 1.3): PW85_PACK_JAMMED with a
 * certified packing above 0.85 and below the target (measured 0.891 for
 * 200 ellipses, seed 7, in 1.7 s; the record for this aspect, N = 10³,
 * is near 0.90). */
static void test_jammed(void) {
  size_t const n = small(200);
  double *a = ellipses(n, 1.3, 0);
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.95;
  o.seed = 7;
  Ellipses s = pack(n, a, &o);
  check(&s);
  g_assert_cmpint(s.outcome, ==, PW85_PACK_JAMMED);
  g_assert_cmpfloat(s.phi, >, 0.85);
  g_assert_cmpfloat(s.phi, <, 0.95);
  g_test_message("%zu ellipses of aspect 1.3 jammed at phi = %.4f", n, s.phi);
  release(&s);
  g_free(a);
}

static gboolean same(Ellipses const *s1, Ellipses const *s2) {
  size_t const n = s1->n;
  return s2->status == PW85_SUCCESS && s1->outcome == s2->outcome &&
         memcmp(s1->box, s2->box, sizeof s1->box) == 0 &&
         memcmp(&s1->phi, &s2->phi, sizeof s1->phi) == 0 &&
         memcmp(s1->c, s2->c, 2 * n * sizeof(double)) == 0 &&
         memcmp(s1->theta, s2->theta, n * sizeof(double)) == 0 &&
         memcmp(s1->q, s2->q, 3 * n * sizeof(double)) == 0;
}

/* The same outputs, bit for bit, on 1, 2, 8, 100 000 and INT_MAX threads
 * (the last two above the cap of pw85_index.h; they crashed in libgomp,
 * and gave PW85_ENOMEM) (a case that goes through stalls and bisection:
 * target beyond jamming, step limit), and
 * without angles; another seed, another packing. */
static void test_determinism(void) {
  size_t const n = small(120);
  double *a = ellipses(n, 2.0, 1);
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.95;
  o.seed = 11;
  /* Through a stall (declared at step 1001, the energy stuck near 3e-3
   * per ellipse since step 600), its certification grown to contact and
   * a bisection step (to φ = 0.931), then the limit. */
  o.step_limit = 1300;
  Ellipses s1 = pack(n, a, &o);
  check(&s1);
  int const threads[] = {2, 8, 100000, INT_MAX};
  for (size_t k = 0; k < G_N_ELEMENTS(threads); k++) {
    o.threads = threads[k];
    Ellipses s = pack(n, a, &o);
    if (!same(&s1, &s))
      g_test_fail_printf("%d threads: another packing", threads[k]);
    release(&s);
  }
  o.threads = 1;
  double box[2], *c = g_new(double, 2 * n), *q = g_new(double, 3 * n), phi;
  int outcome;
  g_assert_cmpint(pw85_2d_pack(n, a, &o, box, c, NULL, q, &phi, &outcome), ==,
                  PW85_SUCCESS);
  g_assert_true(memcmp(c, s1.c, 2 * n * sizeof(double)) == 0);
  g_assert_true(memcmp(q, s1.q, 3 * n * sizeof(double)) == 0);
  o.seed = 12;
  Ellipses s2 = pack(n, a, &o);
  check(&s2);
  g_assert_false(memcmp(s1.c, s2.c, 2 * n * sizeof(double)) == 0);
  g_free(c);
  g_free(q);
  release(&s1);
  release(&s2);
  g_free(a);
}

/* Bit for bit on 1 and 8 threads where 8 threads really work: the energy
 * runs on min(threads, pairs/256 + 1) threads, and test_determinism's
 * 120 ellipses have at most 358 overlapping pairs (2 threads). Here 1000
 * ellipses placed at φ = 0.95 start with thousands; 40 steps. */
static void test_determinism_threads(void) {
  size_t const n = 1000;
  double *a = ellipses(n, 1.3, 1);
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.95;
  o.seed = 5;
  o.step_limit = 40;
  Ellipses s1 = pack(n, a, &o);
  g_assert_cmpint(s1.status, ==, PW85_SUCCESS);
  size_t most;
  watch_pairs(&o, 8, &most);
  Ellipses s8 = pack(n, a, &o);
  g_assert_cmpuint(most, >=, 7 * 256);
  if (!same(&s1, &s8)) g_test_fail_printf("8 threads: another packing");
  release(&s1);
  release(&s8);
  g_free(a);
}

/* A step limit and a cancellation: certified, below the target. */
static void test_outcomes(void) {
  size_t const n = small(150);
  double *a = ellipses(n, 1.0, 0); /* discs */
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.84;
  o.step_limit = 20;
  Ellipses s = pack(n, a, &o);
  check(&s);
  g_assert_cmpint(s.outcome, ==, PW85_PACK_LIMIT);
  g_assert_cmpfloat(s.phi, <, 0.84);
  g_assert_cmpfloat(s.phi, >, 0.0);
  release(&s);
  int calls = 0;
  o.step_limit = 0;
  o.progress = cancel_at_third;
  o.progress_data = &calls;
  o.progress_every = 5;
  s = pack(n, a, &o);
  check(&s);
  g_assert_cmpint(calls, ==, 3);
  g_assert_cmpint(s.outcome, ==, PW85_PACK_CANCELLED);
  g_assert_cmpfloat(s.phi, <, 0.84);
  release(&s);
  g_free(a);
}

/* PW85_PACK_ALIGNED: the largest semi-axis along the axis (1, 2), the
 * first or the second semi-axis, and no turning: every angle is that of
 * the axis, or of the axis less π/2. */
static void test_aligned(void) {
  size_t const n = small(200);
  double *a = ellipses(n, 4.0, 1);
  for (size_t i = 0; i < n; i += 3) { /* the largest second, for some */
    double const t = a[2 * i];
    a[2 * i] = a[2 * i + 1];
    a[2 * i + 1] = t;
  }
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.7;
  o.orientation = PW85_PACK_ALIGNED;
  o.axis[0] = 1.0, o.axis[1] = 2.0, o.axis[2] = NAN; /* axis[2] unread */
  Ellipses s = pack(n, a, &o);
  check(&s);
  g_assert_cmpint(s.outcome, ==, PW85_PACK_TARGET);
  double const along = atan2(2.0, 1.0);
  for (size_t i = 0; i < n; i++) {
    double const expected = a[2 * i] > a[2 * i + 1] ? along : along - G_PI_2;
    g_assert_cmpfloat(s.theta[i], ==, expected);
  }
  release(&s);
  /* An axis in the third quadrant: the angles of ellipses whose largest
   * semi-axis is the second (atan2 − π/2 < −π) are kept in [−π, π] by
   * check(), and that semi-axis still lies along the axis. */
  o.axis[0] = -1.0, o.axis[1] = -2.0;
  o.target = 0.01; /* 3 far apart: no FIRE step, whose turn wraps θ */
  s = pack(3, a, &o);
  check(&s);
  for (size_t i = 0; i < 3; i++) {
    double const t = s.theta[i];
    double const d[2] = {a[2 * i] > a[2 * i + 1] ? cos(t) : -sin(t),
                         a[2 * i] > a[2 * i + 1] ? sin(t) : cos(t)};
    g_assert_cmpfloat(fabs(d[0] * -2.0 - d[1] * -1.0), <=, 1e-14);
    g_assert_cmpfloat(d[0] * -1.0 + d[1] * -2.0, >, 0.0);
  }
  release(&s);
  g_free(a);
}

/* Semi-axes times 2^k: box and centres times 2^k, forms times 2^2k,
 * angles, packing fraction and outcome the same, bit for bit (k = ±3 at
 * the scale of the packer; ±400, whose areas are beyond a double, packed
 * scaled and scaled back). */
static void test_scaled(void) {
  size_t const n = 40;
  double *a = ellipses(n, 1.7, 1);
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.6;
  o.seed = 5;
  Ellipses ref = pack(n, a, &o);
  check(&ref);
  int const exps[] = {-400, -3, 3, 400};
  for (size_t k = 0; k < G_N_ELEMENTS(exps); k++) {
    int const e = exps[k];
    double *b = g_new(double, 2 * n);
    for (size_t i = 0; i < 2 * n; i++) b[i] = ldexp(a[i], e);
    Ellipses s = pack(n, b, &o);
    gboolean ok = s.status == PW85_SUCCESS && s.outcome == ref.outcome &&
                  s.phi == ref.phi;
    for (int m = 0; ok && m < 2; m++) ok = s.box[m] == ldexp(ref.box[m], e);
    for (size_t i = 0; ok && i < 2 * n; i++) ok = s.c[i] == ldexp(ref.c[i], e);
    for (size_t i = 0; ok && i < 3 * n; i++)
      ok = s.q[i] == ldexp(ref.q[i], 2 * e);
    ok = ok && memcmp(s.theta, ref.theta, n * sizeof(double)) == 0;
    if (!ok)
      g_test_fail_printf(
          "semi-axes times 2^%d: not the packing scaled "
          "(status %d)",
          e, s.status);
    release(&s);
    g_free(b);
  }
  release(&ref);
  g_free(a);
}

/* Every bad input gets its status and nothing is written. */
static void test_errors(void) {
  double const a[4] = {1, 0.5, 1, 0.5};
  double box[2] = {7, 7}, c[4] = {7, 7, 7, 7}, th[2] = {7, 7},
         q[6] = {7, 7, 7, 7, 7, 7}, phi = 7;
  int outcome = 7;
  g_assert_cmpint(pw85_2d_pack(2, NULL, NULL, box, c, th, q, &phi, &outcome),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(2, a, NULL, NULL, c, th, q, &phi, &outcome), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(2, a, NULL, box, NULL, th, q, &phi, &outcome),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(2, a, NULL, box, c, th, NULL, &phi, &outcome),
                  ==, PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(2, a, NULL, box, c, th, q, NULL, &outcome), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(2, a, NULL, box, c, th, q, &phi, NULL), ==,
                  PW85_EFAULT);
  g_assert_cmpint(pw85_2d_pack(0, a, NULL, box, c, th, q, &phi, &outcome), ==,
                  PW85_EINVAL);
  double const values[] = {0.0, -1.0, NAN, INFINITY};
  int const statuses[] = {PW85_EINVAL, PW85_EINVAL, PW85_EDOM, PW85_EDOM};
  pw85_pack_options o;
  pw85_pack_options_init(&o);
  o.target = 0.1;
  for (int v = 0; v < 4; v++) {
    double bad[4] = {1, 0.5, 1, 0.5};
    bad[3] = values[v];
    g_assert_cmpint(pw85_2d_pack(2, bad, &o, box, c, th, q, &phi, &outcome), ==,
                    statuses[v]);
  }
  struct {
    int field;
    double value;
    int status;
  } const cases[] = {
      {0, 0.0, PW85_EINVAL},
      {0, 1.0, PW85_EINVAL},
      {0, NAN, PW85_EDOM},
      {1, 0.0, PW85_EINVAL},
      {1, -2.0, PW85_EINVAL},
      {1, INFINITY, PW85_EDOM},
      {2, 5.0, PW85_EINVAL},
      {3, 0.0, PW85_EINVAL},
      {3, NAN, PW85_EDOM},
      {4, 0.0, PW85_EINVAL},
      {5, -1.0, PW85_EINVAL},
      {6, 0.0, PW85_EINVAL},
      {7, 0.0, PW85_EINVAL},
      {8, 1e-3, PW85_EINVAL},
      /* the side rule: at 0.6, two ellipses of semi-axis 1 need sides
       * 2·(1 + 2^-9) = 2.004; the square's is √(2π·0.5/0.6) = 2.288, a
       * 4 : 1 rectangle's shorter one 1.144 */
      {9, 4.0, PW85_EINVAL},
  };
  for (size_t k = 0; k < G_N_ELEMENTS(cases); k++) {
    pw85_pack_options_init(&o);
    o.target = 0.1;
    double const v = cases[k].value;
    switch (cases[k].field) {
      case 0:
        o.target = v;
        break;
      case 1:
        o.aspect[1] = v;
        break;
      case 2:
        o.orientation = (int)v;
        break;
      case 3: /* the axis, read with ALIGNED: zero, or NaN */
        o.orientation = PW85_PACK_ALIGNED;
        o.axis[0] = o.axis[1] = v;
        break;
      case 4:
        o.threads = (int)v;
        break;
      case 5:
        o.time_limit = v;
        break;
      case 6:
        o.progress_every = (size_t)v;
        break;
      case 7:
        o.size = (size_t)v;
        break;
      case 8:
        o.aspect[0] = v;
        break; /* 1e-3 : 1 */
      case 9:
        o.target = 0.6, o.aspect[0] = v;
        break;
    }
    int const st = pw85_2d_pack(2, a, &o, box, c, th, q, &phi, &outcome);
    if (st != cases[k].status)
      g_test_fail_printf("case %zu: status %d, expected %d", k, st,
                         cases[k].status);
  }
  /* aspect[2] and axis[2] are not read; nor the axis when isotropic (the
   * default axis (0, 0, 1) has no direction in the plane). */
  pw85_pack_options_init(&o);
  o.target = 0.1;
  o.aspect[2] = NAN;
  o.axis[2] = -INFINITY;
  double box2[2], c2[4], q2[6], phi2;
  int outcome2;
  g_assert_cmpint(pw85_2d_pack(2, a, &o, box2, c2, NULL, q2, &phi2, &outcome2),
                  ==, PW85_SUCCESS);
  /* n whose 3·n forms (or 2·n semi-axes) no array can hold. */
  size_t const counts[] = {SIZE_MAX / 3 + 1, SIZE_MAX / 2 + 1, SIZE_MAX};
  for (size_t k = 0; k < G_N_ELEMENTS(counts); k++)
    g_assert_cmpint(
        pw85_2d_pack(counts[k], a, NULL, box, c, th, q, &phi, &outcome), ==,
        PW85_ENOMEM);
  for (int k = 0; k < 2; k++) {
    g_assert_cmpfloat(box[k], ==, 7);
    g_assert_cmpfloat(th[k], ==, 7);
  }
  for (int k = 0; k < 4; k++) g_assert_cmpfloat(c[k], ==, 7);
  for (int k = 0; k < 6; k++) g_assert_cmpfloat(q[k], ==, 7);
  g_assert_cmpfloat(phi, ==, 7);
  g_assert_cmpint(outcome, ==, 7);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/2d-pack/targets", test_targets);
  g_test_add_func("/pw85/2d-pack/jammed", test_jammed);
  g_test_add_func("/pw85/2d-pack/determinism", test_determinism);
  g_test_add_func("/pw85/2d-pack/determinism-threads",
                  test_determinism_threads);
  g_test_add_func("/pw85/2d-pack/outcomes", test_outcomes);
  g_test_add_func("/pw85/2d-pack/aligned", test_aligned);
  g_test_add_func("/pw85/2d-pack/scaled", test_scaled);
  g_test_add_func("/pw85/2d-pack/errors", test_errors);
  g_test_add_func("/pw85/2d-pack/size-ratio", test_size_ratio);
  return g_test_run();
}
