// SPDX-License-Identifier: BSD-3-Clause
// Benchmark (meson test --benchmark): pw85_contact_function, pw85_overlap
// (and, on the first two workloads, pw85_f_neg, pw85_contact_geometry and
// pw85_contact_derivatives) against a faithful implementation of the
// seed's algorithm kept here as the yardstick, timed in the same run: every
// figure is a ratio, the yardstick's time over the function's (above 1:
// faster than the seed's algorithm), except "ov/cf", pw85_overlap's time
// over pw85_contact_function's on the same pairs (issue 26: ≤ 0.5 near
// contact). Times are the CPU time of the thread, measured in interleaved
// rounds (the yardstick, then each function, on the same pairs, round
// after round, about 50 ms each), each round's ratio taken, and the median
// printed with the spread of the rounds, so that load shared with other
// processes moves both sides of a ratio.
//
// Workloads (one row each):
// - reference: every record of MU2 in data/pw85_ref_data.h5 (419,904
//   calls);
// - general: data/pw85_general_pairs.h5;
// - hard/<class>: each class of data/pw85_hard_pairs.h5 (data/README.md);
// - near_contact: triaxial pairs (semi-axes 10^[−3, 0], aspect ratios to
//   1e3, random orientations) at |μ² − 1| log-uniform in 1e-12 … 1e-3, on
//   both sides, drawn here from a fixed seed (r scaled from a random
//   direction: μ² ∝ |r|²);
// - far: the same shapes at μ² in 0.01 … 0.5 and 2 … 100.
// Also the mean number of evaluations of f (formations of Q(λ)) per call
// of the contact function, from an instrumented build of the core, and
// the worst relative error of its μ² against the file's reference (none
// for the drawn classes).
//
// Usage: bench-contact REF_DATA.h5 GENERAL_PAIRS.h5 [HARD_PAIRS.h5]
//                      [--class NAME]... [--rounds N]
// --class runs only the workloads whose name starts with NAME (repeatable):
// e.g. from the build directory (one line),
//   tests/bench/bench-contact ../data/pw85_ref_data.h5
//     ../data/pw85_general_pairs.h5 ../data/pw85_hard_pairs.h5
//     --class near_contact
// or through meson (which passes the three files first; one line):
//   meson test -C build --benchmark contact-function -v
//     --test-args='--class hard/needles --class far'
// --rounds sets the number of rounds (default 5; 3 for the reference
// workload, whose calls take longest). The whole run takes about a minute
// on an idle core.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <hdf5.h>
#include <hdf5_hl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
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

hid_t open_or_exit(char const *path) {
  hid_t const f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    std::fprintf(stderr, "cannot open %s\n", path);
    std::exit(1);
  }
  return f;
}

// The pairs of a file with datasets /r12, /q1, /q2 and /MU2 (the general
// and the hard pairs).
std::vector<Case> listed_pairs(hid_t f) {
  auto const r = read(f, "/r12");
  auto const q1 = read(f, "/q1");
  auto const q2 = read(f, "/q2");
  auto const mu2 = read(f, "/MU2");
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

std::vector<Case> reference_workload(char const *path) {
  hid_t const f = open_or_exit(path);
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
  hid_t const f = open_or_exit(path);
  std::vector<Case> cases = listed_pairs(f);
  H5Fclose(f);
  return cases;
}

std::vector<Case> hard_pairs(char const *path, std::vector<std::string> *names,
                             std::vector<int> *klass) {
  hid_t const f = open_or_exit(path);
  std::vector<Case> cases = listed_pairs(f);
  klass->assign(cases.size(), 0);
  hsize_t dims[1] = {0};
  H5T_class_t type_class;
  std::size_t type_size = 0;
  if (H5LTread_dataset_int(f, "/class", klass->data()) < 0 ||
      H5LTget_attribute_info(f, "/", "class_names", dims, &type_class, &type_size) < 0) {
    std::fprintf(stderr, "%s: no classes\n", path);
    std::exit(1);
  }
  std::string all(type_size + 1, '\0');
  H5LTget_attribute_string(f, "/", "class_names", all.data());
  H5Fclose(f);
  all.resize(std::strlen(all.c_str()));
  names->clear();
  for (std::size_t at = 0;;) {
    std::size_t const comma = all.find(',', at);
    names->push_back(all.substr(at, comma - at));
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return cases;
}

// A random triaxial form: semi-axes 10^[−3, 0] (aspect ratios to 1e3), a
// random rotation (a unit quaternion from four normal deviates).
void random_triaxial(std::mt19937_64 &rng, double q[6]) {
  std::uniform_real_distribution<double> u(-3., 0.);
  std::normal_distribution<double> g;
  double a2[3];
  for (double &x : a2) x = std::pow(10., 2. * u(rng));
  double w = g(rng), x = g(rng), y = g(rng), z = g(rng);
  double const n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  double const m[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
                       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
                       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)};
  int k = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = i; j < 3; ++j, ++k)
      q[k] = m[3 * i] * a2[0] * m[3 * j] + m[3 * i + 1] * a2[1] * m[3 * j + 1] +
             m[3 * i + 2] * a2[2] * m[3 * j + 2];
}

// n pairs of random_triaxial() forms with μ² drawn by target(): r is a
// random direction scaled by √(target/μ²(direction)); a pair is kept if
// its μ² (as pw85_contact_function computes it) passes keep(). The
// references of these pairs are not known (mu2 = NaN): the library only
// selects the workload here.
template <class Target, class Keep>
std::vector<Case> drawn_pairs(std::size_t n, std::uint64_t seed, Target target,
                              Keep keep) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<Case> cases;
  while (cases.size() < n) {
    Case c;
    random_triaxial(rng, c.q1);
    random_triaxial(rng, c.q2);
    double u[3] = {g(rng), g(rng), g(rng)};
    double const norm = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    double out[2];
    for (double &x : u) x /= norm;
    if (pw85_contact_function(u, c.q1, c.q2, out) != PW85_SUCCESS) continue;
    double const s = std::sqrt(target(rng) / out[0]);
    for (int k = 0; k < 3; ++k) c.r[k] = s * u[k];
    if (pw85_contact_function(c.r, c.q1, c.q2, out) != PW85_SUCCESS || !keep(out[0]))
      continue;
    c.mu2 = NAN;
    cases.push_back(c);
  }
  return cases;
}

std::vector<Case> near_contact_pairs() {
  return drawn_pairs(
      2000, 2026,
      [](std::mt19937_64 &rng) {
        std::uniform_real_distribution<double> e(-12., -3.);
        double const d = std::pow(10., e(rng));
        return rng() % 2 ? 1. + d : 1. - d;
      },
      [](double mu2) {
        double const d = std::fabs(mu2 - 1.);
        return d >= 1e-12 && d <= 1e-3;
      });
}

std::vector<Case> far_pairs() {
  return drawn_pairs(
      2000, 2027,
      [](std::mt19937_64 &rng) {
        std::uniform_real_distribution<double> e(0.3, 2.);
        double const m = std::pow(10., e(rng));
        return rng() % 2 ? m : 1. / m;
      },
      [](double mu2) { return (mu2 >= .01 && mu2 <= .5) || (mu2 >= 2. && mu2 <= 100.); });
}

volatile double sink;

using Call = double (*)(Case const &);

double call_seed(Case const &c) {
  double out[2];
  seed::contact_function(c.r, c.q1, c.q2, out);
  return out[0];
}
double call_cf(Case const &c) {
  double out[2];
  pw85_contact_function(c.r, c.q1, c.q2, out);
  return out[0];
}
double call_overlap(Case const &c) {
  int result = 0;
  pw85_overlap(c.r, c.q1, c.q2, &result);
  return double(result);
}
double call_f(Case const &c) {
  double params[15];
  for (int a = 0; a < 3; ++a) params[a] = c.r[a];
  for (int a = 0; a < 6; ++a) {
    params[3 + a] = c.q1[a];
    params[9 + a] = c.q2[a];
  }
  return pw85_f_neg(0.5, params);
}
double call_geometry(Case const &c) {
  double g[PW85_GEOM_SIZE];
  pw85_contact_geometry(c.r, c.q1, c.q2, g);
  return g[PW85_GEOM_NORMAL];
}
double call_derivatives(Case const &c) {
  double g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  pw85_contact_derivatives(c.r, c.q1, c.q2, g, d);
  return d[PW85_DERIV_Q2];
}

// The CPU time of the calling thread, in seconds: on a shared machine the
// time that the thread waits for a core does not count (wall-clock times
// of the same rounds spread 3 to 10 times wider at a load of 10 on 2
// cores).
double thread_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Seconds (of the thread's CPU) of `passes` passes of call over the cases.
double time_passes(std::vector<Case> const &cases, int passes, Call call) {
  double acc = 0.;
  double const t0 = thread_seconds();
  for (int p = 0; p < passes; ++p)
    for (Case const &c : cases) acc += call(c);
  double const t1 = thread_seconds();
  sink = acc;
  return t1 - t0;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::size_t const m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// The functions of a row, timed in `rounds` interleaved rounds against the
// yardstick (calls[0]): per function, the ratio of each round, time of
// calls[0] over its time (ratio[0]: the yardstick's ns per call).
struct Timing {
  std::vector<std::vector<double>> ratio;  // [function][round]
};

Timing time_row(std::vector<Case> const &cases, std::vector<Call> const &calls,
                int rounds) {
  // Passes per measurement: about 50 ms of the yardstick.
  double const once = time_passes(cases, 1, calls[0]);
  int const passes = int(std::min(2000., std::max(1., std::ceil(0.05 / once))));
  Timing t;
  t.ratio.assign(calls.size(), {});
  for (int r = 0; r < rounds; ++r) {
    double const yard = time_passes(cases, passes, calls[0]);
    t.ratio[0].push_back(1e9 * yard / (double(passes) * double(cases.size())));
    for (std::size_t f = 1; f < calls.size(); ++f)
      t.ratio[f].push_back(yard / time_passes(cases, passes, calls[f]));
  }
  return t;
}

// The spread of a function's ratios over the rounds: (max − min)/median.
double spread(std::vector<double> const &v) {
  return (*std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end())) /
         median(v);
}

struct Accuracy {
  double evals;  // per call of the contact function (instrumented core)
  double err;    // worst relative error of μ² (NaN: no reference)
};

Accuracy accuracy(std::vector<Case> const &cases) {
  double err = 0.;
  bool known = false;
  unsigned long long const lib0 = pw85::detail::evaluation_count();
  for (Case const &c : cases) {
    double out[2] = {NAN, NAN};
    if (pw85::detail::check_input(c.r, c.q1, c.q2, out) == pw85::detail::Status::success)
      pw85::detail::contact_function(c.r, c.q1, c.q2, out);
    if (std::isfinite(c.mu2)) {
      known = true;
      double const e = std::fabs(out[0] - c.mu2) / c.mu2;
      err = std::max(err, std::isnan(e) ? HUGE_VAL : e);
    }
  }
  return {double(pw85::detail::evaluation_count() - lib0) / double(cases.size()),
          known ? err : NAN};
}

void table_header() {
  std::printf("\n%-28s %7s %8s %7s %7s %6s %7s %7s %10s\n", "workload", "N",
              "seed ns", "cf x", "ov x", "ov/cf", "spread", "cf f/c", "cf err");
}

// One row: the yardstick, pw85_contact_function, pw85_overlap.
void row(char const *name, std::vector<Case> const &cases, int rounds) {
  Timing const t = time_row(cases, {call_seed, call_cf, call_overlap}, rounds);
  std::vector<double> ov_cf;
  for (int r = 0; r < rounds; ++r) ov_cf.push_back(t.ratio[1][r] / t.ratio[2][r]);
  Accuracy const a = accuracy(cases);
  double const sp = std::max(spread(t.ratio[1]), spread(t.ratio[2]));
  std::printf("%-28s %7zu %8.0f %7.2f %7.2f %6.2f %6.0f%% %7.2f %10.2g\n", name,
              cases.size(), median(t.ratio[0]), median(t.ratio[1]), median(t.ratio[2]),
              median(ov_cf), 100. * sp, a.evals, a.err);
}

// The other functions on a workload: pw85_f_neg (one f),
// pw85_contact_geometry and pw85_contact_derivatives, each as a ratio to
// the yardstick and as a cost against the contact function.
void extra_row(char const *name, std::vector<Case> const &cases, int rounds) {
  Timing const t = time_row(
      cases, {call_seed, call_cf, call_f, call_geometry, call_derivatives}, rounds);
  auto cost = [&](std::size_t f) {
    std::vector<double> v;
    for (int r = 0; r < rounds; ++r) v.push_back(t.ratio[1][r] / t.ratio[f][r]);
    return median(v);
  };
  std::printf("%-28s %7.2f %7.2f %7.2f %7.2f %10.2f %6.0f%%\n", name, median(t.ratio[2]),
              median(t.ratio[3]), cost(3), median(t.ratio[4]), cost(4),
              std::max({spread(t.ratio[2]), spread(t.ratio[3]), spread(t.ratio[4])}) * 100.);
}

}  // namespace

int main(int argc, char **argv) {
  std::vector<char const *> files, only;
  int rounds = 5;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--class") == 0 && i + 1 < argc)
      only.push_back(argv[++i]);
    else if (std::strcmp(argv[i], "--rounds") == 0 && i + 1 < argc)
      rounds = std::max(1, std::atoi(argv[++i]));
    else
      files.push_back(argv[i]);
  }
  if (files.size() < 2 || files.size() > 3) {
    std::fprintf(stderr,
                 "usage: %s REF_DATA.h5 GENERAL_PAIRS.h5 [HARD_PAIRS.h5] "
                 "[--class NAME]... [--rounds N]\n",
                 argv[0]);
    return 2;
  }
  auto wanted = [&](std::string const &name) {
    if (only.empty()) return true;
    for (char const *o : only)
      if (name.compare(0, std::strlen(o), o) == 0) return true;
    return false;
  };
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  // The yardstick calls GSL on every input as the seed did: its error
  // handler (abort() by default) is this program's to set.
  gsl_set_error_handler_off();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::printf(
      "pw85 %s contact-function benchmark: ratios to the seed's algorithm in the "
      "same run\n(cf x, ov x: seed time / function time, median of %d interleaved "
      "rounds; ov/cf: overlap time / contact-function time; spread: (max − min)/"
      "median of the rounds' ratios, the noise; seed ns: the yardstick's ns per "
      "call; cf f/c: evaluations of f per call; cf err: worst relative error of "
      "mu2)\n",
      pw85_version(), rounds);
  auto const t_start = std::chrono::steady_clock::now();
  std::vector<Case> reference, general;
  if (wanted("reference")) reference = reference_workload(files[0]);
  if (wanted("general")) general = general_pairs(files[1]);
  table_header();
  if (!reference.empty()) row("reference", reference, std::min(rounds, 3));
  if (!general.empty()) row("general", general, rounds);
  if (files.size() == 3) {
    std::vector<std::string> names;
    std::vector<int> klass;
    std::vector<Case> const hard = hard_pairs(files[2], &names, &klass);
    for (std::size_t k = 0; k < names.size(); ++k) {
      std::string const name = "hard/" + names[k];
      if (!wanted(name)) continue;
      std::vector<Case> cases;
      for (std::size_t n = 0; n < hard.size(); ++n)
        if (klass[n] == int(k)) cases.push_back(hard[n]);
      row(name.c_str(), cases, rounds);
    }
  }
  if (wanted("near_contact")) row("near_contact", near_contact_pairs(), rounds);
  if (wanted("far")) row("far", far_pairs(), rounds);
  if (!reference.empty() || !general.empty()) {
    std::printf("\n%-28s %7s %7s %7s %7s %10s %7s\n", "workload", "f_neg x", "geom x",
                "geom/cf", "deriv x", "deriv/cf", "spread");
    if (!reference.empty()) extra_row("reference", reference, std::min(rounds, 3));
    if (!general.empty()) extra_row("general", general, rounds);
  }
  std::printf("\n(%.0f s)\n", std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - t_start).count());
  return 0;
}
