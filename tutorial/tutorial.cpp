// SPDX-License-Identifier: BSD-3-Clause
// Do two spheroids overlap? The C tutorial (seed chapter 2.2), through the
// C++ API of pw85.hpp.
#include <array>
#include <cstdio>
#include <pw85/pw85.hpp>

int main() {
  std::array<double, pw85::dim> const x1{-0.5, 0.4, -0.7};
  std::array<double, pw85::dim> const n1{0., 0., 1.};
  double const a1 = 10.;
  double const c1 = 0.1;

  std::array<double, pw85::dim> const x2{0.2, -0.3, 0.4};
  std::array<double, pw85::dim> const n2{1., 0., 0.};
  double const a2 = 0.5;
  double const c2 = 5.;

  std::array<double, pw85::dim> r12{};
  for (std::size_t i = 0; i < pw85::dim; ++i) r12[i] = x2[i] - x1[i];

  std::array<double, pw85::sym> q1{}, q2{};
  pw85::spheroid(a1, c1, n1.data(), q1.data());
  pw85::spheroid(a2, c2, n2.data(), q2.data());

  std::array<double, 2> out{};
  int const status =
      pw85::contact_function(r12.data(), q1.data(), q2.data(), out.data());
  if (status != PW85_SUCCESS) {
    std::fprintf(stderr, "pw85::contact_function: %s\n",
                 pw85::strerror(status));
    return 1;
  }
  std::printf("mu^2 = %g\n", out[0]);
  std::printf("lambda = %g\n", out[1]);
  return 0;
}
