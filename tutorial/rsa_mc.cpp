// SPDX-License-Identifier: BSD-3-Clause
// Random sequential addition, then hard-particle Monte Carlo moves, with
// pw85::Index (pw85_index.hpp): triaxial ellipsoids (semi-axes 1, 0.5,
// 0.2, random orientations) dropped into a periodic cube until a target
// packing fraction, then each moved in turn by a small random step,
// accepted only if it overlaps no other one. The all-pairs query then
// checks the packing: no overlapping pair.
//
// Usage: rsa_mc [N [FRACTION [SWEEPS]]]  (default: 2000 ellipsoids at
// 0.2, 5 sweeps). Exit status 0 when the check passes.
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <pw85/pw85_index.hpp>
#include <random>
#include <vector>

namespace {

using Vec = std::array<double, pw85::dim>;
using Form = std::array<double, pw85::sym>;

int fail(char const *what, int status) {
  std::fprintf(stderr, "%s: %s\n", what, pw85::strerror(status));
  return 1;
}

}  // namespace

int main(int argc, char **argv) {
  std::size_t const n = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 2000;
  double const target = argc > 2 ? std::strtod(argv[2], nullptr) : 0.2;
  int const sweeps = argc > 3 ? std::atoi(argv[3]) : 5;
  Vec const axes{1., .5, .2};
  double const volume = 4. / 3. * 3.14159265358979323846 * 1. * .5 * .2;
  double const side = std::cbrt(static_cast<double>(n) * volume / target);
  double const box[pw85::dim] = {side, side, side};

  pw85::Index index;  // destroyed at the end of main, whatever happens
  int status = pw85::Index::periodic(box, index);
  if (status != PW85_SUCCESS) return fail("pw85::Index::periodic", status);

  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::normal_distribution<double> normal(0., 1.);
  auto random_form = [&](Form &q) {
    std::array<double, 4> p;  // a uniform random unit quaternion
    for (double &x : p) x = normal(rng);
    double const norm =
        std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3]);
    for (double &x : p) x /= norm;
    return pw85::ellipsoid_quaternion(axes.data(), p.data(), q.data());
  };

  // Random sequential addition: ellipsoid `placed` is kept if it overlaps
  // (or touches) none already there.
  std::vector<Vec> centres;
  std::vector<Form> forms;
  std::size_t attempts = 0;
  while (centres.size() < n && attempts < 100 * n) {
    Vec c;
    Form q;
    for (double &x : c) x = side * uniform(rng);
    if ((status = random_form(q)) != PW85_SUCCESS)
      return fail("pw85::ellipsoid_quaternion", status);
    ++attempts;
    int result;
    std::size_t other;
    status =
        index.overlap_any(c.data(), q.data(), pw85::index_no_id, result, other);
    if (status != PW85_SUCCESS) return fail("pw85::Index::overlap_any", status);
    if (result <= 0) continue;
    status = index.insert(centres.size(), c.data(), q.data());
    if (status != PW85_SUCCESS) return fail("pw85::Index::insert", status);
    centres.push_back(c);
    forms.push_back(q);
  }

  // Monte Carlo sweeps: a trial position for ellipsoid i, tested against
  // all the others (`exclude` = i, the one it would replace).
  std::size_t accepted = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (std::size_t i = 0; i < centres.size(); ++i) {
      Vec trial = centres[i];
      for (double &x : trial) x += 0.1 * (2. * uniform(rng) - 1.);
      int result;
      std::size_t other;
      status =
          index.overlap_any(trial.data(), forms[i].data(), i, result, other);
      if (status != PW85_SUCCESS)
        return fail("pw85::Index::overlap_any", status);
      if (result <= 0) continue;
      status = index.update(i, trial.data(), forms[i].data());
      if (status != PW85_SUCCESS) return fail("pw85::Index::update", status);
      centres[i] = trial;
      ++accepted;
    }
  }

  // The check, on 2 threads: no overlapping pair. And the near neighbours
  // (μ² < 1.2), pairs that a soft potential would see.
  std::vector<pw85::Index::OverlappingPair> overlaps;
  std::vector<pw85::Index::Pair> near;
  status = index.overlapping_pairs(2, overlaps);
  if (status == PW85_SUCCESS) status = index.pairs_within(1.2, 2, near);
  if (status != PW85_SUCCESS) return fail("pw85::Index pairs", status);
  std::printf(
      "%zu ellipsoids placed in %zu attempts, packing fraction %.4f; "
      "%zu of %zu moves accepted\n",
      centres.size(), attempts,
      static_cast<double>(centres.size()) * volume / (side * side * side),
      accepted, static_cast<std::size_t>(sweeps) * centres.size());
  std::printf("overlapping pairs: %zu; pairs with mu^2 < 1.2: %zu\n",
              overlaps.size(), near.size());
  return overlaps.empty() ? 0 : 1;
}
