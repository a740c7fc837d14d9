// SPDX-License-Identifier: BSD-3-Clause
// pw85.hpp: the C++ API forwards to the C ABI with the same results
// (pw85::d2: to pw85_2d.h).
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

// pw85::d2 forwards to pw85_2d.h: the same bits and statuses as the C
// functions, on a pair that is not symmetric (a wrapper that swapped q1
// and q2, or r12's sign, would differ), and values known in closed form.
void test_2d() {
  static_assert(pw85::d2::dim == PW85_2D_DIM && pw85::d2::sym == PW85_2D_SYM,
                "dimensions");
  static_assert(pw85::d2::geom::mu2 == PW85_2D_GEOM_MU2 &&
                    pw85::d2::geom::lambda == PW85_2D_GEOM_LAMBDA &&
                    pw85::d2::geom::point == PW85_2D_GEOM_POINT &&
                    pw85::d2::geom::normal == PW85_2D_GEOM_NORMAL &&
                    pw85::d2::geom::size == PW85_2D_GEOM_SIZE &&
                    pw85::d2::deriv::r12 == PW85_2D_DERIV_R12 &&
                    pw85::d2::deriv::theta1 == PW85_2D_DERIV_THETA1 &&
                    pw85::d2::deriv::theta2 == PW85_2D_DERIV_THETA2 &&
                    pw85::d2::deriv::q1 == PW85_2D_DERIV_Q1 &&
                    pw85::d2::deriv::q2 == PW85_2D_DERIV_Q2 &&
                    pw85::d2::deriv::size == PW85_2D_DERIV_SIZE,
                "pw85.hpp mirrors the layouts of pw85_2d.h");
  namespace d2 = pw85::d2;
  double const r[d2::dim] = {0.7, -1.1};
  double const qa[d2::sym] = {4., 0.5, 0.25};
  double const qb[d2::sym] = {1., -0.3, 2.};

  double params[8] = {r[0], r[1], qa[0], qa[1], qa[2], qb[0], qb[1], qb[2]};
  for (double lambda : {0., 0.3, 0.5, 1.})
    g_assert_cmpfloat(d2::f_neg(lambda, r, qa, qb), ==,
                      pw85_2d_f_neg(lambda, params));
  g_assert_cmpfloat(d2::f_neg(0.3, r, qa, qb), !=, d2::f_neg(0.3, r, qb, qa));
  g_assert_true(std::isnan(d2::f_neg(0.5, r, nullptr, qb)));

  double out[2], out_c[2];
  g_assert_cmpint(d2::contact_function(r, qa, qb, out), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_contact_function(r, qa, qb, out_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(out, sizeof out, out_c, sizeof out_c);
  int result = 0, result_c = 0;
  g_assert_cmpint(d2::overlap(r, qa, qb, &result), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_overlap(r, qa, qb, &result_c), ==, PW85_SUCCESS);
  g_assert_cmpint(result, ==, result_c);
  g_assert_cmpint(result, ==, out[0] < 1. ? -1 : 1);

  double g[d2::geom::size], g_c[d2::geom::size];
  double d[d2::deriv::size], d_c[d2::deriv::size];
  g_assert_cmpint(d2::contact_geometry(r, qa, qb, g), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_contact_geometry(r, qa, qb, g_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(g, sizeof g, g_c, sizeof g_c);
  g_assert_cmpint(d2::contact_derivatives(r, qa, qb, g, d), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_contact_derivatives(r, qa, qb, g_c, d_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(g, sizeof g, g_c, sizeof g_c);
  g_assert_cmpmem(d, sizeof d, d_c, sizeof d_c);
  g_assert_cmpfloat(g[d2::geom::mu2], ==, out[0]);

  // Two circles of radii 1 and 2, centres 6 apart: μ = 6/(1 + 2), so
  // μ² = 4 exactly, and λ = 1/3 (seed, "Theory": spheres).
  double const six[d2::dim] = {0., 6.}, c1[d2::sym] = {1., 0., 1.};
  double const c2[d2::sym] = {4., 0., 4.};
  g_assert_cmpint(d2::contact_function(six, c1, c2, out), ==, PW85_SUCCESS);
  g_assert_cmpfloat(out[0], ==, 4.);
  g_assert_cmpfloat_with_epsilon(out[1], 1. / 3., 4e-16);

  // Constructors: exact for θ = 0 (cos 0 = 1, sin 0 = 0) and back.
  double const semi[d2::dim] = {3., 0.5};
  double q[d2::sym], q_c[d2::sym], ax[d2::dim], ax_c[d2::dim], th, th_c;
  g_assert_cmpint(d2::ellipse(semi, 0., q), ==, PW85_SUCCESS);
  g_assert_cmpfloat(q[0], ==, 9.);
  g_assert_cmpfloat(q[1], ==, 0.);
  g_assert_cmpfloat(q[2], ==, 0.25);
  g_assert_cmpint(d2::ellipse(semi, 0.4, q), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_ellipse(semi, 0.4, q_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(q, sizeof q, q_c, sizeof q_c);
  g_assert_cmpint(d2::principal_axes(qb, ax, &th), ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_principal_axes(qb, ax_c, &th_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(ax, sizeof ax, ax_c, sizeof ax_c);
  g_assert_cmpfloat(th, ==, th_c);

  // Errors: the statuses of pw85_2d.h, outputs untouched.
  double const nan_r[d2::dim] = {NAN, 0.}, neg[d2::sym] = {1., 2., 1.};
  double const zero_axis[d2::dim] = {1., 0.};
  double keep[2] = {42., -7.};
  g_assert_cmpint(d2::contact_function(r, qa, nullptr, keep), ==,
                  PW85_EFAULT);
  g_assert_cmpint(d2::contact_function(nan_r, qa, qb, keep), ==, PW85_EDOM);
  g_assert_cmpint(d2::contact_function(r, neg, qb, keep), ==,
                  PW85_ENOTPOSDEF);
  g_assert_cmpfloat(keep[0], ==, 42.);
  g_assert_cmpfloat(keep[1], ==, -7.);
  result = 42;
  g_assert_cmpint(d2::overlap(r, qa, neg, &result), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(result, ==, 42);
  g_assert_cmpint(d2::contact_geometry(nan_r, qa, qb, g), ==, PW85_EDOM);
  g_assert_cmpint(d2::contact_derivatives(r, neg, qb, g, d), ==,
                  PW85_ENOTPOSDEF);
  g_assert_cmpint(d2::ellipse(zero_axis, 0., q), ==, PW85_EINVAL);
  g_assert_cmpint(d2::ellipse(semi, NAN, q), ==, PW85_EDOM);
  g_assert_cmpint(d2::principal_axes(neg, ax, &th), ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(d2::principal_axes(qb, ax, nullptr), ==, PW85_EFAULT);

  // The batches: pair i = (r, qa, qb[i]) against the single-pair calls;
  // a stride of 1 is refused (PW85_EINVAL).
  double const qbs[2 * d2::sym] = {qb[0], qb[1], qb[2], qa[0], qa[1], qa[2]};
  double ob[4], gb[2 * d2::geom::size], db[2 * d2::deriv::size];
  int rb[2], sb[2] = {-1, -1};
  g_assert_cmpint(d2::contact_function_batch(2, r, 0, qa, 0, qbs, d2::sym, ob,
                                             sb, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(sb[0], ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_contact_function(r, qa, qbs + 3, out_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(ob + 2, sizeof out_c, out_c, sizeof out_c);
  g_assert_cmpint(d2::contact_function(r, qa, qb, out_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(ob, sizeof out_c, out_c, sizeof out_c);
  g_assert_cmpint(d2::contact_function_batch(2, r, 1, qa, 0, qbs, d2::sym, ob,
                                             sb, 1),
                  ==, PW85_EINVAL);
  g_assert_cmpint(d2::overlap_batch(2, r, 0, qa, 0, qbs, d2::sym, rb, nullptr,
                                    1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(rb[0], ==, result_c);
  g_assert_cmpint(pw85_2d_overlap(r, qa, qa, &result_c), ==, PW85_SUCCESS);
  g_assert_cmpint(rb[1], ==, result_c);
  g_assert_cmpint(d2::contact_geometry_batch(2, r, 0, qa, 0, qbs, d2::sym,
                                             gb, nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_contact_derivatives(r, qa, qa, g_c, d_c), ==,
                  PW85_SUCCESS);
  g_assert_cmpmem(gb + d2::geom::size, sizeof g_c, g_c, sizeof g_c);
  g_assert_cmpint(d2::contact_derivatives_batch(2, r, 0, qa, 0, qbs, d2::sym,
                                                gb, db, nullptr, 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(db + d2::deriv::size, sizeof d_c, d_c, sizeof d_c);
  g_assert_cmpmem(gb + d2::geom::size, sizeof g_c, g_c, sizeof g_c);
  // A failing pair: its status, the first failing one returned.
  double const bad_qbs[2 * d2::sym] = {qb[0], qb[1], qb[2], 1., 2., 1.};
  g_assert_cmpint(d2::overlap_batch(2, r, 0, qa, 0, bad_qbs, d2::sym, rb, sb,
                                    1),
                  ==, PW85_ENOTPOSDEF);
  g_assert_cmpint(sb[0], ==, PW85_SUCCESS);
  g_assert_cmpint(sb[1], ==, PW85_ENOTPOSDEF);

  double const thetas[2] = {0.4, -1.2};
  double qq[2 * d2::sym], ab[2 * d2::dim], tb[2];
  g_assert_cmpint(d2::ellipse_batch(2, semi, 0, thetas, 1, qq, sb, 1), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_ellipse(semi, -1.2, q_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(qq + d2::sym, sizeof q_c, q_c, sizeof q_c);
  g_assert_cmpint(d2::principal_axes_batch(2, qq, d2::sym, ab, tb, sb, 1), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(pw85_2d_principal_axes(q_c, ax_c, &th_c), ==, PW85_SUCCESS);
  g_assert_cmpmem(ab + d2::dim, sizeof ax_c, ax_c, sizeof ax_c);
  g_assert_cmpfloat(tb[1], ==, th_c);
  g_assert_cmpint(d2::ellipse_batch(2, semi, 1, thetas, 1, qq, sb, 1), ==,
                  PW85_EINVAL);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/cpp/constants", test_constants);
  g_test_add_func("/pw85/cpp/wrappers", test_wrappers);
  g_test_add_func("/pw85/cpp/2d", test_2d);
  return g_test_run();
}
