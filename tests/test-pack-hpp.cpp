// SPDX-License-Identifier: BSD-3-Clause
// pw85_pack.hpp and the energy members of pw85_index.hpp against the C
// functions they wrap, on the same input: the same outputs, bit for bit;
// callables as pair energies and progress callbacks; statuses.
#include <glib.h>

#include <cmath>
#include <cstring>
#include <pw85/pw85.hpp>
#include <pw85/pw85_pack.hpp>
#include <stdexcept>
#include <vector>

namespace {

std::vector<double> semi_axes(std::size_t n) {
  std::vector<double> a;
  for (std::size_t i = 0; i < n; ++i) {
    double const s = 1.0 + 0.5 * double(i % 3);
    a.insert(a.end(), {s, 0.6 * s, 0.3 * s});
  }
  return a;
}

bool same(std::vector<double> const &a, double const *b, std::size_t n) {
  return a.size() == n && std::memcmp(a.data(), b, n * sizeof(double)) == 0;
}

void test_pack() {
  std::size_t const n = 150;
  std::vector<double> const a = semi_axes(n);
  pw85::PackOptions o;
  o.target = 0.5;
  o.seed = 3;
  pw85::Packing p;
  g_assert_cmpint(pw85::pack(a, o, p), ==, PW85_SUCCESS);
  std::vector<double> c(3 * n), qt(4 * n), q(6 * n);
  double box[3], phi;
  int outcome;
  g_assert_cmpint(pw85_pack(n, a.data(), &o, box, c.data(), qt.data(),
                            q.data(), &phi, &outcome), ==, PW85_SUCCESS);
  g_assert_true(std::memcmp(box, p.box.data(), sizeof box) == 0);
  g_assert_true(same(p.centres, c.data(), 3 * n));
  g_assert_true(same(p.quaternions, qt.data(), 4 * n));
  g_assert_true(same(p.forms, q.data(), 6 * n));
  g_assert_cmpfloat(p.phi, ==, phi);
  g_assert_cmpint(p.outcome, ==, outcome);
  g_assert_cmpint(p.outcome, ==, PW85_PACK_TARGET);

  // A progress lambda that stops at its second call; one that throws.
  int calls = 0;
  o.progress_every = 2;
  pw85::Packing stopped;
  g_assert_cmpint(pw85::pack(a, o,
                             [&](pw85_pack_progress const &pr) {
                               g_assert_cmpfloat(pr.phi_trial, ==, 0.5);
                               return ++calls < 2;
                             },
                             stopped),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(calls, ==, 2);
  g_assert_cmpint(stopped.outcome, ==, PW85_PACK_CANCELLED);
  g_assert_cmpfloat(stopped.phi, <, 0.5);
  pw85::Packing thrown;
  g_assert_cmpint(pw85::pack(a, o,
                             [](pw85_pack_progress const &) -> bool {
                               throw std::runtime_error("stop");
                             },
                             thrown),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(thrown.outcome, ==, PW85_PACK_CANCELLED);

  // Errors leave the output unchanged.
  pw85::Packing untouched = p;
  std::vector<double> odd(a.begin(), a.begin() + 4);
  g_assert_cmpint(pw85::pack(odd, o, untouched), ==, PW85_EINVAL);
  o.target = 1.5;
  g_assert_cmpint(pw85::pack(a, o, untouched), ==, PW85_EINVAL);
  g_assert_true(untouched.centres == p.centres);
}

void test_energy() {
  std::size_t const n = 120;
  std::vector<double> const a = semi_axes(n);
  double const box[3] = {9, 9, 9};
  pw85::Index index;
  g_assert_cmpint(pw85::Index::periodic(box, index), ==, PW85_SUCCESS);
  GRand *rng = g_rand_new_with_seed(5);
  for (std::size_t i = 0; i < n; ++i) {
    double c[3], p[4], q[6], norm = 0;
    for (int k = 0; k < 3; ++k) c[k] = g_rand_double_range(rng, 0, 9);
    for (int k = 0; k < 4; ++k) {
      p[k] = g_rand_double_range(rng, -1, 1);
      norm += p[k] * p[k];
    }
    for (int k = 0; k < 4; ++k) p[k] /= std::sqrt(norm);
    g_assert_cmpint(pw85_ellipsoid_quaternion(&a[3 * i], p, q), ==, 0);
    g_assert_cmpint(index.insert(i, c, q), ==, 0);
  }
  g_rand_free(rng);
  double e = 0, ec = 0;
  std::vector<double> f, t, fc(3 * n), tc(3 * n);
  g_assert_cmpint(index.overlap_energy(2.0, 2, n, e, f, t), ==, 0);
  g_assert_cmpint(pw85_index_energy(index.handle(), PW85_ENERGY_OVERLAP, 2.0,
                                    nullptr, nullptr, 1, n, &ec, fc.data(),
                                    tc.data()), ==, 0);
  g_assert_cmpfloat(e, >, 0.0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(same(f, fc.data(), 3 * n));
  g_assert_true(same(t, tc.data(), 3 * n));

  // A lambda for U = (t − μ²)², through the C function with the same
  // formula.
  double const tt = 1.4;
  auto u = [tt](double mu2, double &U, double &dU) {
    U = (tt - mu2) * (tt - mu2);
    dU = -2.0 * (tt - mu2);
    return true;
  };
  struct C {
    static int fn(double mu2, void *d, double out[2]) {
      double const t0 = *static_cast<double *>(d);
      out[0] = (t0 - mu2) * (t0 - mu2);
      out[1] = -2.0 * (t0 - mu2);
      return 0;
    }
  };
  double t0 = tt;
  g_assert_cmpint(index.energy(tt, u, 2, n, e, f, t), ==, 0);
  g_assert_cmpint(pw85_index_energy(index.handle(), PW85_ENERGY_USER, tt,
                                    &C::fn, &t0, 1, n, &ec, fc.data(),
                                    tc.data()), ==, 0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(same(f, fc.data(), 3 * n));
  g_assert_true(same(t, tc.data(), 3 * n));

  // A lambda that stops, one that throws: PW85_ECANCELLED, outputs kept.
  std::vector<double> const f0 = f;
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) {
                    return false;
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) -> bool {
                    throw std::runtime_error("stop");
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.overlap_energy(-1.0, 1, n, e, f, t), ==, PW85_EINVAL);
  g_assert_true(f == f0);
  pw85::Index none;
  g_assert_cmpint(none.overlap_energy(1.0, 1, n, e, f, t), ==, PW85_EFAULT);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/pack-hpp/pack", test_pack);
  g_test_add_func("/pw85/pack-hpp/energy", test_energy);
  return g_test_run();
}
