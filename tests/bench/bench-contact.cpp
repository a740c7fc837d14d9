// SPDX-License-Identifier: BSD-3-Clause
// Benchmark (meson test --benchmark): ns per call of pw85_f_neg,
// pw85_contact_function and pw85_overlap, against a faithful implementation
// of the seed's algorithm kept here as the yardstick, on the reference
// workload (every record of MU2 in data/pw85_ref_data.h5: 419,904 calls) and
// on the general pairs of data/pw85_general_pairs.h5. Ratios matter, not
// absolute times: the machines are shared. Also reports the mean number of
// evaluations of f (formations of Q(λ)) per call, from an instrumented build
// of the core, and the worst relative error of μ² of both algorithms.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

#include "checks.hpp"
#include "compiler.hpp"
#include "contact.hpp"
#include "pw85.h"

namespace {

// ---------------------------------------------------------------------------
// The seed's algorithm (pw85 1.0, documentation chapters 4.1 and 5): f by a
// Cholesky factorisation and two triangular solves in plain double; GSL's
// Brent minimiser, allocated per call, on −f from λ = ½ over [0, 1] to an
// absolute tolerance of 1e-6 in at most 25 iterations; then 3
// Newton–Raphson steps on g = μ2² − μ1², keeping the better estimate.
namespace seed {

thread_local unsigned long long evaluations = 0;

void cholesky(double const a[6], double l[6]) {
  l[0] = std::sqrt(a[0]);
  l[1] = a[1] / l[0];
  l[2] = a[2] / l[0];
  l[3] = std::sqrt(a[3] - l[1] * l[1]);
  l[4] = (a[4] - l[1] * l[2]) / l[3];
  l[5] = std::sqrt(a[5] - l[2] * l[2] - l[4] * l[4]);
}

void solve(double const l[6], double const b[3], double x[3]) {
  double const y0 = b[0] / l[0];
  double const y1 = (b[1] - l[1] * y0) / l[3];
  double const y2 = (b[2] - l[2] * y0 - l[4] * y1) / l[5];
  x[2] = y2 / l[5];
  x[1] = (y1 - l[4] * x[2]) / l[3];
  x[0] = (y0 - l[1] * x[1] - l[2] * x[2]) / l[0];
}

double f_neg(double lambda, void *params) {
  ++evaluations;
  auto const *p = static_cast<double const *>(params);
  double q[6], l[6], s[3];
  for (int i = 0; i < 6; ++i) q[i] = (1. - lambda) * p[3 + i] + lambda * p[9 + i];
  cholesky(q, l);
  solve(l, p, s);
  return -lambda * (1. - lambda) * (p[0] * s[0] + p[1] * s[1] + p[2] * s[2]);
}

// out = {f, g, g′}, docs/optimisation.rst, eqs. (5.4)–(5.5).
void residual(double lambda, double const *p, double out[3]) {
  ++evaluations;
  double q[6], q12[6], l[6], s[3], u[3], v[3];
  for (int i = 0; i < 6; ++i) {
    q[i] = (1. - lambda) * p[3 + i] + lambda * p[9 + i];
    q12[i] = p[9 + i] - p[3 + i];
  }
  cholesky(q, l);
  solve(l, p, s);
  u[0] = q12[0] * s[0] + q12[1] * s[1] + q12[2] * s[2];
  u[1] = q12[1] * s[0] + q12[3] * s[1] + q12[4] * s[2];
  u[2] = q12[2] * s[0] + q12[4] * s[1] + q12[5] * s[2];
  solve(l, u, v);
  double const rs = p[0] * s[0] + p[1] * s[1] + p[2] * s[2];
  double const su = s[0] * u[0] + s[1] * u[1] + s[2] * u[2];
  double const uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  double const w = lambda * (1. - lambda);
  out[0] = w * rs;
  out[1] = (2. * lambda - 1.) * rs + w * su;
  out[2] = 2. * rs + 2. * (1. - 2. * lambda) * su - 2. * w * uv;
}

int contact_function(double const r[3], double const q1[6], double const q2[6],
                     double out[2]) {
  double params[15];
  for (int i = 0; i < 3; ++i) params[i] = r[i];
  for (int i = 0; i < 6; ++i) {
    params[3 + i] = q1[i];
    params[9 + i] = q2[i];
  }
  gsl_function fun{&f_neg, params};
  gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
  gsl_min_fminimizer_set(s, &fun, 0.5, 0., 1.);
  for (int iter = 0; iter < PW85_MAX_ITER; ++iter) {
    gsl_min_fminimizer_iterate(s);
    if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(s),
                              gsl_min_fminimizer_x_upper(s), PW85_LAMBDA_ATOL,
                              0.) == GSL_SUCCESS)
      break;
  }
  double lambda_brent = gsl_min_fminimizer_x_minimum(s);
  double mu2_brent = -gsl_min_fminimizer_f_minimum(s);
  gsl_min_fminimizer_free(s);
  double lambda = lambda_brent;
  double res[3];
  for (int k = 0; k < PW85_NR_ITER; ++k) {
    residual(lambda, params, res);
    lambda -= res[1] / res[2];
  }
  residual(lambda, params, res);
  if (lambda >= 0. && lambda <= 1. && res[0] > mu2_brent) {
    out[0] = res[0];
    out[1] = lambda;
  } else {
    out[0] = mu2_brent;
    out[1] = lambda_brent;
  }
  return 0;
}

}  // namespace seed

// ---------------------------------------------------------------------------
struct Case {
  double r[3], q1[6], q2[6];
  double mu2;  // reference
};

std::vector<double> read(hid_t file, char const *name) {
  int rank = 0;
  if (H5LTget_dataset_ndims(file, name, &rank) < 0) {
    std::fprintf(stderr, "missing dataset %s\n", name);
    std::exit(1);
  }
  std::vector<hsize_t> dims(rank);
  H5LTget_dataset_info(file, name, dims.data(), nullptr, nullptr);
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  std::vector<double> v(n);
  H5LTread_dataset_double(file, name, v.data());
  return v;
}

std::vector<Case> reference_workload(char const *path) {
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    std::fprintf(stderr, "cannot open %s\n", path);
    std::exit(1);
  }
  auto const dirs = read(f, "/directions");
  auto const sph = read(f, "/spheroids");
  auto const dist = read(f, "/distances");
  auto const mu2 = read(f, "/MU2");
  H5Fclose(f);
  std::size_t const nd = dirs.size() / 3, ns = sph.size() / 6, nm = dist.size();
  std::vector<Case> cases;
  cases.reserve(ns * ns * nd * nm);
  std::size_t n = 0;
  for (std::size_t i = 0; i < ns; ++i)
    for (std::size_t j = 0; j < ns; ++j)
      for (std::size_t k = 0; k < nd; ++k)
        for (std::size_t m = 0; m < nm; ++m, ++n) {
          Case c;
          for (int a = 0; a < 3; ++a) c.r[a] = dist[m] * dirs[3 * k + a];
          for (int a = 0; a < 6; ++a) {
            c.q1[a] = sph[6 * i + a];
            c.q2[a] = sph[6 * j + a];
          }
          c.mu2 = mu2[n];
          cases.push_back(c);
        }
  return cases;
}

std::vector<Case> general_pairs(char const *path) {
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    std::fprintf(stderr, "cannot open %s\n", path);
    std::exit(1);
  }
  auto const r = read(f, "/r12");
  auto const q1 = read(f, "/q1");
  auto const q2 = read(f, "/q2");
  auto const mu2 = read(f, "/MU2");
  H5Fclose(f);
  std::vector<Case> cases(mu2.size());
  for (std::size_t n = 0; n < cases.size(); ++n) {
    for (int a = 0; a < 3; ++a) cases[n].r[a] = r[3 * n + a];
    for (int a = 0; a < 6; ++a) {
      cases[n].q1[a] = q1[6 * n + a];
      cases[n].q2[a] = q2[6 * n + a];
    }
    cases[n].mu2 = mu2[n];
  }
  return cases;
}

volatile double sink;

// Best of `reps` timed passes over the cases, in ns per call.
double time_ns(std::vector<Case> const &cases, int passes_per_rep, int reps,
               std::function<double(Case const &)> const &call) {
  double best = 1e300;
  for (int rep = 0; rep < reps; ++rep) {
    double acc = 0.;
    auto const t0 = std::chrono::steady_clock::now();
    for (int p = 0; p < passes_per_rep; ++p)
      for (Case const &c : cases) acc += call(c);
    auto const t1 = std::chrono::steady_clock::now();
    sink = acc;
    double const ns = std::chrono::duration<double, std::nano>(t1 - t0).count();
    best = std::min(best, ns / (double(cases.size()) * passes_per_rep));
  }
  return best;
}

void run(char const *title, std::vector<Case> const &cases, int passes,
         int reps) {
  std::printf("\n%s: %zu cases, best of %d passes\n", title, cases.size(),
              reps);
  double const t_seed = time_ns(cases, passes, reps, [](Case const &c) {
    double out[2];
    seed::contact_function(c.r, c.q1, c.q2, out);
    return out[0];
  });
  double const t_cf = time_ns(cases, passes, reps, [](Case const &c) {
    double out[2];
    pw85_contact_function(c.r, c.q1, c.q2, out);
    return out[0];
  });
  double const t_f = time_ns(cases, passes, reps, [](Case const &c) {
    double params[15];
    for (int a = 0; a < 3; ++a) params[a] = c.r[a];
    for (int a = 0; a < 6; ++a) {
      params[3 + a] = c.q1[a];
      params[9 + a] = c.q2[a];
    }
    return pw85_f_neg(0.5, params);
  });
  double const t_ov = time_ns(cases, passes, reps, [](Case const &c) {
    int result = 0;
    pw85_overlap(c.r, c.q1, c.q2, &result);
    return double(result);
  });
  double const t_geom = time_ns(cases, passes, reps, [](Case const &c) {
    double g[PW85_GEOM_SIZE];
    pw85_contact_geometry(c.r, c.q1, c.q2, g);
    return g[PW85_GEOM_NORMAL];
  });
  double const t_deriv = time_ns(cases, passes, reps, [](Case const &c) {
    double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
    pw85_contact_derivatives(c.r, c.q1, c.q2, g, d);
    return d[PW85_DERIV_Q2];
  });

  // Accuracy and evaluation counts (untimed).
  double err_seed = 0., err_cf = 0.;
  seed::evaluations = 0;
  unsigned long long const lib0 = pw85::detail::evaluation_count();
  for (Case const &c : cases) {
    double out[2];
    seed::contact_function(c.r, c.q1, c.q2, out);
    err_seed = std::max(err_seed, std::fabs(out[0] - c.mu2) / c.mu2);
    if (pw85::detail::check_input(c.r, c.q1, c.q2, out) ==
        pw85::detail::Status::success)
      pw85::detail::contact_function(c.r, c.q1, c.q2, out);
    err_cf = std::max(err_cf, std::fabs(out[0] - c.mu2) / c.mu2);
  }
  double const n = double(cases.size());
  double const ev_seed = double(seed::evaluations) / n;
  double const ev_cf =
      double(pw85::detail::evaluation_count() - lib0) / n;

  std::printf("  %-28s %9s %9s %12s %14s\n", "function", "ns/call",
              "speed-up", "f evals/call", "worst rel err");
  std::printf("  %-28s %9.1f %9s %12.2f %14.3g\n", "seed algorithm (yardstick)",
              t_seed, "1.00", ev_seed, err_seed);
  std::printf("  %-28s %9.1f %9.2f %12.2f %14.3g\n", "pw85_contact_function",
              t_cf, t_seed / t_cf, ev_cf, err_cf);
  std::printf("  %-28s %9.1f %9.2f\n", "pw85_overlap", t_ov, t_seed / t_ov);
  std::printf("  %-28s %9.1f %9.2f\n", "pw85_f_neg (one f)", t_f,
              t_seed / t_f);
  // The full output against the contact function alone (issue 15).
  std::printf("  %-28s %9.1f %9.2f %12s %14.2f\n", "pw85_contact_geometry",
              t_geom, t_seed / t_geom, "cost vs cf:", t_geom / t_cf);
  std::printf("  %-28s %9.1f %9.2f %12s %14.2f\n", "pw85_contact_derivatives",
              t_deriv, t_seed / t_deriv, "cost vs cf:", t_deriv / t_cf);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s REF_DATA.h5 GENERAL_PAIRS.h5\n", argv[0]);
    return 2;
  }
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  std::printf("pw85 %s benchmark (ratios are the result; times are noisy)\n",
              pw85_version());
  run("reference workload (108 x 108 spheroids x 12 directions x 3 "
      "distances)",
      reference_workload(argv[1]), 1, 3);
  run("general triaxial pairs (aspect ratios to 1e4, near-tangent to far)",
      general_pairs(argv[2]), 50, 3);
  return 0;
}
