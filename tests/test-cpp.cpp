// SPDX-License-Identifier: BSD-3-Clause
// pw85.hpp: the C++ API forwards to the C ABI with the same results.
#include <glib.h>

#include <cmath>
#include <cstring>
#include <pw85/pw85.hpp>
#include <string>

namespace {

double const r12[pw85::dim] = {0.7, -0.7, 1.1};
double const q1[pw85::sym] = {100., 0., 0., 100., 0., 0.01};
double const q2[pw85::sym] = {25., 0.5, -0.25, 0.25, 0., 0.75};

void test_constants() {
  static_assert(pw85::dim == 3 && pw85::sym == 6, "dimensions");
  static_assert(pw85::lambda_atol == PW85_LAMBDA_ATOL, "lambda_atol");
  static_assert(pw85::max_iter == PW85_MAX_ITER, "max_iter");
  static_assert(pw85::nr_iter == PW85_NR_ITER, "nr_iter");
  g_assert_true(pw85::metadata::name == "pw85");
  g_assert_true(pw85::metadata::version == PW85_VERSION);
  g_assert_true(pw85::metadata::license == "BSD-3-Clause");
  g_assert_true(pw85::metadata::description.find("Perram") !=
                std::string_view::npos);
  g_assert_cmpstr(pw85::library_version(), ==, PW85_VERSION);
  g_assert_cmpstr(pw85::strerror(PW85_EDOM), ==, pw85_strerror(PW85_EDOM));
}

void test_wrappers() {
  double const a[pw85::sym] = {4., 2., -2., 10., 5., 21.};
  double l[pw85::sym], l_c[pw85::sym];
  pw85::_cholesky_decomp(a, l);
  pw85__cholesky_decomp(a, l_c);
  g_assert_cmpmem(l, sizeof l, l_c, sizeof l_c);

  double const b[pw85::dim] = {2., 37., 71.};
  double x[pw85::dim], x_c[pw85::dim];
  pw85::_cholesky_solve(l, b, x);
  pw85__cholesky_solve(l, b, x_c);
  g_assert_cmpmem(x, sizeof x, x_c, sizeof x_c);

  double const n[pw85::dim] = {0.6, 0.8, 0.};
  double q[pw85::sym], q_c[pw85::sym];
  g_assert_cmpint(pw85::spheroid(2., 3., n, q), ==, PW85_SUCCESS);
  pw85_spheroid(2., 3., n, q_c);
  g_assert_cmpmem(q, sizeof q, q_c, sizeof q_c);
  // Since 2.3.0: the preconditions of pw85_spheroid() checked; on error q
  // is all NaN (never the singular or mirrored form pw85_spheroid() gives).
  double const n_long[pw85::dim] = {0.6, 0.8, 0.1};
  struct {
    double a, c;
    double const *n;
    int status;
  } const bad[] = {{0., 3., n, PW85_EINVAL},      {-2., 3., n, PW85_EINVAL},
                   {2., 0., n, PW85_EINVAL},      {2., 3., n_long, PW85_EINVAL},
                   {NAN, 3., n, PW85_EDOM},       {2., 3., nullptr, PW85_EFAULT},
                   {1e200, 3., n, PW85_ERANGE}};
  for (auto const &b : bad) {
    g_assert_cmpint(pw85::spheroid(b.a, b.c, b.n, q), ==, b.status);
    for (double x : q) g_assert_true(std::isnan(x));
  }
  double pq[4], axes_q[pw85::dim], axes_q_c[pw85::dim], p_c[4];
  g_assert_cmpint(pw85::principal_axes_quaternion(q_c, axes_q, pq), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(pw85_principal_axes_quaternion(q_c, axes_q_c, p_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(axes_q, sizeof axes_q, axes_q_c, sizeof axes_q_c);
  g_assert_cmpmem(pq, sizeof pq, p_c, sizeof p_c);

  double params[15];
  std::memcpy(params, r12, sizeof r12);
  std::memcpy(params + 3, q1, sizeof q1);
  std::memcpy(params + 9, q2, sizeof q2);
  for (double lambda : {0., 0.25, 0.5, 0.9, 1.})
    g_assert_cmpfloat(pw85::f_neg(lambda, r12, q1, q2), ==,
                      pw85_f_neg(lambda, params));
  g_assert_true(std::isnan(pw85::f_neg(0.5, nullptr, q1, q2)));

  double res[3], res_c[3];
  pw85::_residual(0.3, r12, q1, q2, res);
  pw85__residual(0.3, r12, q1, q2, res_c);
  g_assert_cmpmem(res, sizeof res, res_c, sizeof res_c);

  double out[2], out_c[2];
  g_assert_cmpint(pw85::contact_function(r12, q1, q2, out), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_contact_function(r12, q1, q2, out_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(out, sizeof out, out_c, sizeof out_c);
  g_assert_cmpint(pw85::contact_function(r12, q1, nullptr, out), ==,
                  PW85_EFAULT);

  int result = 0, result_c = 0;
  g_assert_cmpint(pw85::overlap(r12, q1, q2, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_overlap(r12, q1, q2, &result_c), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, result_c);
  g_assert_cmpint(result, ==, out[0] < 1. ? -1 : 1);

  // Since 2.2.0: the same results as the C functions, same layouts.
  static_assert(pw85::geom::normal == PW85_GEOM_NORMAL &&
                    pw85::geom::size == PW85_GEOM_SIZE &&
                    pw85::deriv::rot2 == PW85_DERIV_ROT2 &&
                    pw85::deriv::q2 == PW85_DERIV_Q2 &&
                    pw85::deriv::size == PW85_DERIV_SIZE &&
                    pw85::unit_tol == PW85_UNIT_TOL,
                "pw85.hpp mirrors the layouts of pw85.h");
  double const semi[pw85::dim] = {3., 2., 0.5};
  double const p[4] = {0.5, 0.5, -0.5, 0.5};
  double const rot[9] = {0., 0., 1., 1., 0., 0., 0., 1., 0.};
  double qa[pw85::sym], qa_c[pw85::sym];
  g_assert_cmpint(pw85::ellipsoid_quaternion(semi, p, qa), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_ellipsoid_quaternion(semi, p, qa_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(qa, sizeof qa, qa_c, sizeof qa_c);
  g_assert_cmpint(pw85::ellipsoid_rotation(semi, rot, qa), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_ellipsoid_rotation(semi, rot, qa_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(qa, sizeof qa, qa_c, sizeof qa_c);
  double axes[3], axes_c[3], dirs[9], dirs_c[9];
  g_assert_cmpint(pw85::principal_axes(q1, axes, dirs), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_principal_axes(q1, axes_c, dirs_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(axes, sizeof axes, axes_c, sizeof axes_c);
  g_assert_cmpmem(dirs, sizeof dirs, dirs_c, sizeof dirs_c);
  double g[pw85::geom::size], g_c[pw85::geom::size];
  double d[pw85::deriv::size], d_c[pw85::deriv::size];
  g_assert_cmpint(pw85::contact_geometry(r12, q1, q2, g), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_contact_geometry(r12, q1, q2, g_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(g, sizeof g, g_c, sizeof g_c);
  g_assert_cmpint(pw85::contact_derivatives(r12, q1, q2, g, d), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(pw85_contact_derivatives(r12, q1, q2, g_c, d_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(d, sizeof d, d_c, sizeof d_c);
  g_assert_cmpfloat(g[pw85::geom::mu2], ==, out[0]);

  // The batches: one pair broadcast to two (strides 0), as the C calls.
  double gb[2 * pw85::geom::size], db[2 * pw85::deriv::size], ob[4];
  int rb[2], sb[2] = {-1, -1};
  g_assert_cmpint(pw85::batch_threads(0, 1), ==, pw85_batch_threads(0, 1));
  g_assert_cmpint(pw85::contact_function_batch(2, r12, 0, q1, 0, q2, 0, ob,
                                               sb, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(ob + 2, 2 * sizeof(double), out, 2 * sizeof(double));
  g_assert_cmpint(sb[1], ==, PW85_SUCCESS);
  g_assert_cmpint(pw85::overlap_batch(2, r12, 0, q1, 0, q2, 0, rb, nullptr,
                                      1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(rb[1], ==, result_c);
  g_assert_cmpint(pw85::contact_geometry_batch(2, r12, 0, q1, 0, q2, 0, gb,
                                               nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(gb + pw85::geom::size, sizeof g_c, g_c, sizeof g_c);
  g_assert_cmpint(pw85::contact_derivatives_batch(2, r12, 0, q1, 0, q2, 0, gb,
                                                  db, nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(db + pw85::deriv::size, sizeof d_c, d_c, sizeof d_c);

  // The constructors' batches: one item broadcast to two, as the C calls.
  double const semi2[pw85::dim] = {3., 2., 0.5}, quat[4] = {0.5, 0.5, 0.5, 0.5};
  double const radii[2] = {1., 4.}, axis[pw85::dim] = {0.6, 0., 0.8};
  double qb[2 * pw85::sym], qc[pw85::sym], ab[2 * pw85::dim], rotb[18];
  double ac[pw85::dim], rotc[9];
  g_assert_cmpint(pw85::spheroid_batch(2, radii, 1, radii + 1, 0, axis, 0, qb,
                                       sb, 1),
                  ==, PW85_SUCCESS);
  pw85_spheroid(4., 4., axis, qc);
  g_assert_cmpmem(qb + pw85::sym, sizeof qc, qc, sizeof qc);
  g_assert_cmpint(pw85::ellipsoid_quaternion_batch(2, semi2, 0, quat, 0, qb,
                                                   nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_ellipsoid_quaternion(semi2, quat, qc), ==, PW85_SUCCESS);
  g_assert_cmpmem(qb + pw85::sym, sizeof qc, qc, sizeof qc);
  g_assert_cmpint(pw85::principal_axes_batch(2, qc, 0, ab, rotb, nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_principal_axes(qc, ac, rotc), ==, PW85_SUCCESS);
  g_assert_cmpmem(ab + pw85::dim, sizeof ac, ac, sizeof ac);
  g_assert_cmpmem(rotb + 9, sizeof rotc, rotc, sizeof rotc);
  g_assert_cmpint(pw85::ellipsoid_rotation_batch(2, ac, 0, rotc, 0, qb, sb, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_ellipsoid_rotation(ac, rotc, qc), ==, PW85_SUCCESS);
  g_assert_cmpmem(qb + pw85::sym, sizeof qc, qc, sizeof qc);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/cpp/constants", test_constants);
  g_test_add_func("/pw85/cpp/wrappers", test_wrappers);
  return g_test_run();
}
