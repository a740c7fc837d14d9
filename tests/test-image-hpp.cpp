// SPDX-License-Identifier: BSD-3-Clause
// pw85_image.hpp against the C functions of pw85_image.h it wraps: the same
// image, bit for bit; its statuses, and its outputs unchanged on error
// (also when the image cannot be allocated: PW85_ENOMEM, where the
// noexcept wrapper let std::bad_alloc reach std::terminate()).
#include <glib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <pw85/pw85_image.hpp>
#include <vector>

#if defined(__has_include)
#if __has_include(<valgrind/valgrind.h>)
#include <valgrind/valgrind.h>
#define PW85_HAVE_VALGRIND_H 1
#endif
#endif

namespace {

// Whether the test runs under valgrind (its client request; false where
// valgrind's header is not installed, and valgrind with it).
bool under_valgrind() {
#if defined(PW85_HAVE_VALGRIND_H)
  return RUNNING_ON_VALGRIND != 0;
#else
  return false;
#endif
}

// Three overlapping ellipsoids in a periodic box of side 2.
std::vector<double> const centres = {0.5, 0.5, 0.5, 1.0, 1.2, 0.9,
                                     1.9, 0.1, 1.5};
std::vector<double> const forms = {0.25, 0.05, 0.0,  0.16, 0.0,  0.09,
                                   0.36, 0.0,  0.1,  0.25, -0.02, 0.16,
                                   0.04, 0.0,  0.0,  0.04, 0.0,  0.49};

void test_same_as_c() {
  std::array<double, 3> const origin = {0.0, 0.0, 0.0}, sides = {2, 2, 2};
  std::array<std::size_t, 3> const dims = {9, 10, 11};
  std::vector<std::int32_t> image;
  g_assert_cmpint(pw85::image_voxels(centres, forms, origin, sides, true,
                                     dims, image, 2),
                  ==, PW85_SUCCESS);
  std::vector<std::int32_t> ref(9 * 10 * 11, 5);
  g_assert_cmpint(pw85_image_voxels(3, centres.data(), forms.data(),
                                    origin.data(), sides.data(), 1,
                                    dims.data(), ref.data(), 1),
                  ==, PW85_SUCCESS);
  g_assert_cmpmem(image.data(), image.size() * sizeof(std::int32_t),
                  ref.data(), ref.size() * sizeof(std::int32_t));
  std::size_t count = 0, ref_count = 1;
  double fraction = -1.0, ref_fraction = -2.0;
  g_assert_cmpint(pw85::image_fraction(dims, image, count, fraction), ==,
                  PW85_SUCCESS);
  g_assert_cmpint(pw85_image_fraction(dims.data(), ref.data(), &ref_count,
                                      &ref_fraction),
                  ==, PW85_SUCCESS);
  g_assert_cmpuint(count, ==, ref_count);
  g_assert_cmpfloat(fraction, ==, ref_fraction);
  g_assert_cmpuint(count, >, 0);
}

// Statuses, and the image unchanged on error.
void test_errors() {
  std::array<double, 3> const origin = {0.0, 0.0, 0.0}, sides = {2, 2, 2};
  std::vector<std::int32_t> image(4, 7);
  std::vector<double> const odd(centres.begin(), centres.end() - 1);
  std::array<std::size_t, 3> const dims = {2, 2, 1};
  g_assert_cmpint(pw85::image_voxels(odd, forms, origin, sides, true, dims,
                                     image),
                  ==, PW85_EINVAL);
  std::array<std::size_t, 3> const zero = {2, 0, 1};
  g_assert_cmpint(pw85::image_voxels(centres, forms, origin, sides, true,
                                     zero, image),
                  ==, PW85_EINVAL);
  std::array<double, 3> const flat = {2, 0, 2};
  g_assert_cmpint(pw85::image_voxels(centres, forms, origin, flat, true, dims,
                                     image),
                  ==, PW85_EINVAL);
  // 2⁵⁰ voxels, 4 PiB: its bytes fit a size_t, memory does not. (Not
  // under AddressSanitizer, whose operator new stops the process when it
  // cannot allocate, whatever allocator_may_return_null says; nor under
  // valgrind, whose operator new cannot throw and aborts.)
#if defined(__SANITIZE_ADDRESS__)
  g_test_message("AddressSanitizer: the allocation that fails is not tried");
#else
  if (under_valgrind()) {
    g_test_message("valgrind: the allocation that fails is not tried");
  } else {
    std::size_t const big = PW85_IMAGE_MAX_DIM;
    std::array<std::size_t, 3> const huge = {big, big, 1024};
    g_assert_cmpint(pw85::image_voxels(centres, forms, origin, sides, true,
                                       huge, image),
                    ==, PW85_ENOMEM);
  }
#endif
  g_assert_cmpuint(image.size(), ==, 4);
  for (std::int32_t v : image) g_assert_cmpint(v, ==, 7);
}

}  // namespace

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, nullptr);
  g_test_add_func("/pw85/image-hpp/same-as-c", test_same_as_c);
  g_test_add_func("/pw85/image-hpp/errors", test_errors);
  return g_test_run();
}
