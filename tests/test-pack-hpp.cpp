// SPDX-License-Identifier: BSD-3-Clause
// pw85_pack.hpp and pw85_2d_pack.hpp, and the energy members of
// pw85::Index and pw85::d2::Index, against the C functions they wrap, on
// the same input: the same outputs, bit for bit; callables as pair
// energies and progress callbacks; statuses, with the outputs unchanged.
// Each check is written once for both dimensions (a template on Dim3 or
// Dim2 below).
#include <glib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <pw85/pw85.hpp>
#include <pw85/pw85_2d_index.hpp>
#include <pw85/pw85_2d_pack.hpp>
#include <pw85/pw85_pack.hpp>
#include <stdexcept>
#include <vector>

namespace {

// What differs: sizes, the C functions, the C++ names, a random form.
struct Dim3 {
  static constexpr std::size_t dim = 3, orient = 4, sym = 6, rot = 3;
  using Index = pw85::Index;
  using Packing = pw85::Packing;
  static std::vector<double> const &orientations(Packing const &p) {
    return p.quaternions;
  }
  static int pack(std::vector<double> const &a, pw85::PackOptions const &o,
                  Packing &p) {
    return pw85::pack(a, o, p);
  }
  template <typename F>
  static int pack(std::vector<double> const &a, pw85::PackOptions const &o,
                  F &&f, Packing &p) {
    return pw85::pack(a, o, f, p);
  }
  static constexpr auto c_pack = pw85_pack;
  static constexpr auto c_energy = pw85_index_energy;
  // semi-axes s·(1, 0.6, 0.3), s in 1, 1.5, 2
  static std::vector<double> semi_axes(std::size_t n) {
    std::vector<double> a;
    for (std::size_t i = 0; i < n; ++i) {
      double const s = 1.0 + 0.5 * double(i % 3);
      a.insert(a.end(), {s, 0.6 * s, 0.3 * s});
    }
    return a;
  }
  static void form(GRand *rng, double const *a, double *q) {
    double p[4], norm = 0;
    for (int k = 0; k < 4; ++k) {
      p[k] = g_rand_double_range(rng, -1, 1);
      norm += p[k] * p[k];
    }
    for (int k = 0; k < 4; ++k) p[k] /= std::sqrt(norm);
    g_assert_cmpint(pw85_ellipsoid_quaternion(a, p, q), ==, 0);
  }
};

struct Dim2 {
  static constexpr std::size_t dim = 2, orient = 1, sym = 3, rot = 1;
  using Index = pw85::d2::Index;
  using Packing = pw85::d2::Packing;
  static std::vector<double> const &orientations(Packing const &p) {
    return p.angles;
  }
  static int pack(std::vector<double> const &a, pw85::PackOptions const &o,
                  Packing &p) {
    return pw85::d2::pack(a, o, p);
  }
  template <typename F>
  static int pack(std::vector<double> const &a, pw85::PackOptions const &o,
                  F &&f, Packing &p) {
    return pw85::d2::pack(a, o, f, p);
  }
  static constexpr auto c_pack = pw85_2d_pack;
  static constexpr auto c_energy = pw85_2d_index_energy;
  // semi-axes s·(1, 1/1.5), s in 1, 1.25, 1.5
  static std::vector<double> semi_axes(std::size_t n) {
    std::vector<double> a;
    for (std::size_t i = 0; i < n; ++i) {
      double const s = 1.0 + 0.25 * double(i % 3);
      a.insert(a.end(), {s, s / 1.5});
    }
    return a;
  }
  static void form(GRand *rng, double const *a, double *q) {
    g_assert_cmpint(pw85_2d_ellipse(a, g_rand_double_range(rng, -3.2, 3.2),
                                    q), ==, 0);
  }
};

bool same(std::vector<double> const &a, double const *b, std::size_t n) {
  return a.size() == n && std::memcmp(a.data(), b, n * sizeof(double)) == 0;
}

// pack() against the C function; a target the packer reaches, then one
// beyond jamming for the callbacks.
// A plain function as the pair energy: U = (1.4 − μ²)², as the lambda u of
// the energy test; and as a progress callback that stops at once. (A
// function named as the callable did not compile: its address is no
// object pointer.)
bool plain_energy(double mu2, double &U, double &dU) {
  U = (1.4 - mu2) * (1.4 - mu2);
  dU = -2.0 * (1.4 - mu2);
  return true;
}

bool plain_stop(pw85_pack_progress const &) { return false; }

template <class T>
void check_pack(std::size_t n, double target, double beyond) {
  std::vector<double> const a = T::semi_axes(n);
  pw85::PackOptions o;
  o.target = target;
  o.seed = 3;
  typename T::Packing p;
  g_assert_cmpint(T::pack(a, o, p), ==, PW85_SUCCESS);
  std::vector<double> c(T::dim * n), r(T::orient * n), q(T::sym * n);
  double box[T::dim], phi;
  int outcome;
  g_assert_cmpint(T::c_pack(n, a.data(), &o, box, c.data(), r.data(),
                            q.data(), &phi, &outcome), ==, PW85_SUCCESS);
  g_assert_true(std::memcmp(box, p.box.data(), sizeof box) == 0);
  g_assert_true(same(p.centres, c.data(), T::dim * n));
  g_assert_true(same(T::orientations(p), r.data(), T::orient * n));
  g_assert_true(same(p.forms, q.data(), T::sym * n));
  g_assert_cmpfloat(p.phi, ==, phi);
  g_assert_cmpint(p.outcome, ==, outcome);
  g_assert_cmpint(p.outcome, ==, PW85_PACK_TARGET);

  // A progress lambda that stops at its second call; one that throws.
  o.target = beyond;
  o.progress_every = 2;
  int calls = 0;
  typename T::Packing stopped;
  g_assert_cmpint(T::pack(a, o,
                          [&](pw85_pack_progress const &pr) {
                            g_assert_cmpfloat(pr.phi_trial, ==, beyond);
                            return ++calls < 2;
                          },
                          stopped),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(calls, ==, 2);
  g_assert_cmpint(stopped.outcome, ==, PW85_PACK_CANCELLED);
  g_assert_cmpfloat(stopped.phi, <, beyond);
  typename T::Packing thrown;
  g_assert_cmpint(T::pack(a, o,
                          [](pw85_pack_progress const &) -> bool {
                            throw std::runtime_error("stop");
                          },
                          thrown),
                  ==, PW85_SUCCESS);
  g_assert_cmpint(thrown.outcome, ==, PW85_PACK_CANCELLED);
  typename T::Packing plain;
  g_assert_cmpint(T::pack(a, o, plain_stop, plain), ==, PW85_SUCCESS);
  g_assert_cmpint(plain.outcome, ==, PW85_PACK_CANCELLED);

  // Errors leave the output unchanged.
  typename T::Packing untouched = p;
  std::vector<double> odd(a.begin(), a.begin() + T::dim + 1);
  g_assert_cmpint(T::pack(odd, o, untouched), ==, PW85_EINVAL);
  o.target = 1.5;
  g_assert_cmpint(T::pack(a, o, untouched), ==, PW85_EINVAL);
  g_assert_true(untouched.centres == p.centres);
  g_assert_true(T::orientations(untouched) == T::orientations(p));
}

// The energy members against the C function, n shapes at random in a
// periodic box of the given side.
template <class T>
void check_energy(std::size_t n, double side) {
  std::vector<double> const a = T::semi_axes(n);
  double const box[3] = {side, side, side};
  typename T::Index index;
  g_assert_cmpint(T::Index::periodic(box, index), ==, PW85_SUCCESS);
  GRand *rng = g_rand_new_with_seed(5);
  for (std::size_t i = 0; i < n; ++i) {
    double c[T::dim], q[T::sym];
    for (std::size_t k = 0; k < T::dim; ++k)
      c[k] = g_rand_double_range(rng, 0, side);
    T::form(rng, &a[T::dim * i], q);
    g_assert_cmpint(index.insert(i, c, q), ==, 0);
  }
  g_rand_free(rng);
  double e = 0, ec = 0;
  std::vector<double> f, t, fc(T::dim * n), tc(T::rot * n);
  g_assert_cmpint(index.overlap_energy(2.0, 2, n, e, f, t), ==, 0);
  g_assert_cmpint(T::c_energy(index.handle(), PW85_ENERGY_OVERLAP, 2.0,
                              nullptr, nullptr, 1, n, &ec, fc.data(),
                              tc.data()), ==, 0);
  g_assert_cmpfloat(e, >, 0.0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(same(f, fc.data(), T::dim * n));
  g_assert_true(same(t, tc.data(), T::rot * n));

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
  g_assert_cmpint(T::c_energy(index.handle(), PW85_ENERGY_USER, tt, &C::fn,
                              &t0, 1, n, &ec, fc.data(), tc.data()), ==, 0);
  g_assert_true(std::memcmp(&e, &ec, sizeof e) == 0);
  g_assert_true(same(f, fc.data(), T::dim * n));
  g_assert_true(same(t, tc.data(), T::rot * n));
  double ep = 0;
  std::vector<double> fp, tp;
  g_assert_cmpint(index.energy(tt, plain_energy, 2, n, ep, fp, tp), ==, 0);
  g_assert_true(std::memcmp(&e, &ep, sizeof e) == 0);
  g_assert_true(fp == f && tp == t);

  // A lambda that stops, one that throws: PW85_ECANCELLED, outputs kept;
  // an ε not > 0, rows not above the ids: PW85_EINVAL.
  std::vector<double> const f0 = f, tq0 = t;
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) {
                    return false;
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.energy(tt, [](double, double &, double &) -> bool {
                    throw std::runtime_error("stop");
                  }, 1, n, e, f, t), ==, PW85_ECANCELLED);
  g_assert_cmpint(index.overlap_energy(-1.0, 1, n, e, f, t), ==, PW85_EINVAL);
  g_assert_cmpint(index.overlap_energy(1.0, 1, n - 1, e, f, t), ==,
                  PW85_EINVAL);
  g_assert_true(f == f0);
  g_assert_true(t == tq0);
  typename T::Index none;
  g_assert_cmpint(none.overlap_energy(1.0, 1, n, e, f, t), ==, PW85_EFAULT);
  // rows no vector can hold: still PW85_EFAULT (it was PW85_ENOMEM, the
  // vectors allocated first)
  g_assert_cmpint(none.overlap_energy(1.0, 1, SIZE_MAX / 2, e, f, t), ==,
                  PW85_EFAULT);
}

void test_pack() { check_pack<Dim3>(150, 0.5, 0.7); }
void test_energy() { check_energy<Dim3>(120, 9.0); }
void test_pack_2d() { check_pack<Dim2>(120, 0.75, 0.95); }
void test_energy_2d() { check_energy<Dim2>(150, 12.0); }

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/pack-hpp/pack", test_pack);
  g_test_add_func("/pw85/pack-hpp/energy", test_energy);
  g_test_add_func("/pw85/pack-hpp/pack-2d", test_pack_2d);
  g_test_add_func("/pw85/pack-hpp/energy-2d", test_energy_2d);
  return g_test_run();
}
