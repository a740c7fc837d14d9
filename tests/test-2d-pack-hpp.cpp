// SPDX-License-Identifier: BSD-3-Clause
// pw85_2d_pack.hpp and the energy members of pw85::d2::Index
// (pw85_2d_index.hpp) against the C functions they wrap, on the same
// input: the same outputs, bit for bit; callables as pair energies and
// progress callbacks; statuses, with the outputs unchanged.
#include <glib.h>

#include <cstring>
#include <pw85/pw85_2d_index.hpp>
#include <pw85/pw85_2d_pack.hpp>
#include <stdexcept>
#include <vector>

namespace {

// n ellipses of aspect 1.5, in three sizes.
std::vector<double> ellipses(std::size_t n) {
  std::vector<double> a;
  for (std::size_t i = 0; i < n; ++i) {
    double const s = 1.0 + 0.25 * double(i % 3);
    a.insert(a.end(), {s, s / 1.5});
  }
  return a;
}

bool equal(std::vector<double> const &a, double const *b, std::size_t n) {
  return a.size() == n && std::memcmp(a.data(), b, n * sizeof(double)) == 0;
}

void test_pack() {
  std::size_t const n = 120;
  std::vector<double> const a = ellipses(n);
  pw85::PackOptions o;
  o.target = 0.75;
  o.seed = 4;
  pw85::d2::Packing p;
  g_assert_cmpint(pw85::d2::pack(a, o, p), ==, PW85_SUCCESS);
  std::vector<double> c(2 * n), angles(n), q(3 * n);
  double box[2], phi;
  int outcome;
  g_assert_cmpint(pw85_2d_pack(n, a.data(), &o, box, c.data(), angles.data(),
                               q.data(), &phi, &outcome), ==, PW85_SUCCESS);
  g_assert_true(std::memcmp(box, p.box.data(), sizeof box) == 0);
  g_assert_true(equal(p.centres, c.data(), 2 * n));
  g_assert_true(equal(p.angles, angles.data(), n));
  g_assert_true(equal(p.forms, q.data(), 3 * n));
  g_assert_cmpfloat(p.phi, ==, phi);
  g_assert_cmpint(p.outcome, ==, outcome);
  g_assert_cmpint(p.outcome, ==, PW85_PACK_TARGET);

  // A progress lambda that stops at its second call; one that throws.
  o.target = 0.95;  // beyond jamming: the callback is called
  o.progress_every = 2;
  int calls = 0;
  pw85::d2::Packing stopped;
  g_assert_cmpint(pw85::d2::pack(a, o,
                                 [&](pw85_pack_progress const &pr) {
                                   g_assert_cmpfloat(pr.phi_trial, ==, 0.95);
                                   return ++calls < 2;
                                 },
                                 stopped),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(calls, ==, 2);
  g_assert_cmpint(stopped.outcome, ==, PW85_PACK_CANCELLED);
  g_assert_cmpfloat(stopped.phi, <, 0.95);
  pw85::d2::Packing thrown;
  g_assert_cmpint(pw85::d2::pack(a, o,
                                 [](pw85_pack_progress const &) -> bool {
                                   throw std::runtime_error("stop");
                                 },
                                 thrown),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(thrown.outcome, ==, PW85_PACK_CANCELLED);

  // Errors leave the output unchanged.
  pw85::d2::Packing untouched = p;
  std::vector<double> odd(a.begin(), a.begin() + 3);
  g_assert_cmpint(pw85::d2::pack(odd, o, untouched), ==, PW85_EINVAL);
  o.target = -0.5;
  g_assert_cmpint(pw85::d2::pack(a, o, untouched), ==, PW85_EINVAL);
  g_assert_true(untouched.centres == p.centres);
  g_assert_true(untouched.angles == p.angles);
}

void test_energy() {
  std::size_t const n = 150;
  std::vector<double> const a = ellipses(n);
  double const box[2] = {12, 12};
  pw85::d2::Index index;
  g_assert_cmpint(pw85::d2::Index::periodic(box, index), ==, PW85_SUCCESS);
  GRand *rng = g_rand_new_with_seed(6);
  for (std::size_t i = 0; i < n; ++i) {
    double c[2], q[3];
    for (int k = 0; k < 2; ++k) c[k] = g_rand_double_range(rng, 0, 12);
    double const theta = g_rand_double_range(rng, -3.2, 3.2);
    g_assert_cmpint(pw85_2d_ellipse(&a[2 * i], theta, q), ==, 0);
    g_assert_cmpint(index.insert(i, c, q), ==, 0);
  }
  g_rand_free(rng);
  double e = 0, ec = 0;
  std::vector<double> f, t, fc(2 * n), tc(n);
  g_assert_cmpint(index.overlap_energy(2.0, 2, n, e, f, t), ==, 0);
  g_assert_cmpint(pw85_2d_index_energy(index.handle(), PW85_ENERGY_OVERLAP,
                                       2.0, nullptr, nullptr, 1, n, &ec,
                                       fc.data(), tc.data()), ==, 0);
  g_assert_cmpfloat(e, >, 0.0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(equal(f, fc.data(), 2 * n));
  g_assert_true(equal(t, tc.data(), n));

  // A lambda for U = (t − μ²)², and the C function of the same formula.
  double const tt = 1.3;
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
  g_assert_cmpint(pw85_2d_index_energy(index.handle(), PW85_ENERGY_USER, tt,
                                       &C::fn, &t0, 1, n, &ec, fc.data(),
                                       tc.data()), ==, 0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(equal(f, fc.data(), 2 * n));
  g_assert_true(equal(t, tc.data(), n));

  // A lambda that stops, one that throws: PW85_ECANCELLED, outputs kept.
  std::vector<double> const f0 = f, t0v = t;
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) {
                    return false;
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) -> bool {
                    throw std::runtime_error("stop");
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.overlap_energy(0.0, 1, n, e, f, t), ==, PW85_EINVAL);
  g_assert_cmpint(index.overlap_energy(1.0, 1, n - 1, e, f, t), ==,
                  PW85_EINVAL);
  g_assert_true(f == f0);
  g_assert_true(t == t0v);
  pw85::d2::Index none;
  g_assert_cmpint(none.overlap_energy(1.0, 1, n, e, f, t), ==, PW85_EFAULT);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/2d-pack-hpp/pack", test_pack);
  g_test_add_func("/pw85/2d-pack-hpp/energy", test_energy);
  return g_test_run();
}
