// SPDX-License-Identifier: BSD-3-Clause
// Compiled as C++ (-Werror -pedantic): pw85.h and pw85.hpp stand alone and
// together, in either order.
#include <pw85/pw85_index.h>
#include <pw85/pw85.hpp>
#include <pw85/pw85.h>
#include <pw85.h>

static_assert(noexcept(pw85_contact_function(nullptr, nullptr, nullptr,
                                             nullptr)),
              "the C ABI is noexcept for C++ callers");
static_assert(noexcept(pw85_index_destroy(nullptr)),
              "pw85_index.h is noexcept for C++ callers");

int main() {
  double const r[pw85::dim] = {1., 0., 0.};
  double const q[pw85::sym] = {1., 0., 0., 1., 0., 1.};
  double out[2];
  return pw85::contact_function(r, q, q, out) == PW85_SUCCESS ? 0 : 1;
}
