// SPDX-License-Identifier: BSD-3-Clause
// Compiled as C++ (-Werror -pedantic): pw85.h and pw85.hpp stand alone and
// together, in either order; pw85_index.hpp first, standing alone.
#include <pw85/pw85_pack.hpp>
#include <pw85/pw85_2d.h>
#include <pw85/pw85_2d_index.h>
#include <pw85/pw85_2d_index.hpp>
#include <pw85/pw85_2d_pack.h>
#include <pw85/pw85_2d_pack.hpp>
#include <pw85/pw85_image.hpp>
#include <pw85/pw85_index.hpp>
#include <pw85/pw85_index.h>
#include <pw85/pw85.hpp>
#include <pw85/pw85.h>
#include <pw85.h>

static_assert(noexcept(pw85_contact_function(nullptr, nullptr, nullptr,
                                             nullptr)),
              "the C ABI is noexcept for C++ callers");
static_assert(noexcept(pw85_2d_overlap(nullptr, nullptr, nullptr, nullptr)),
              "pw85_2d.h is noexcept for C++ callers");
static_assert(noexcept(pw85_index_destroy(nullptr)),
              "pw85_index.h is noexcept for C++ callers");
static_assert(noexcept(pw85_2d_index_destroy(nullptr)),
              "pw85_2d_index.h is noexcept for C++ callers");
static_assert(noexcept(pw85_2d_pack(0, nullptr, nullptr, nullptr, nullptr,
                                    nullptr, nullptr, nullptr, nullptr)),
              "pw85_2d_pack.h is noexcept for C++ callers");

int main() {
  double const r[pw85::dim] = {1., 0., 0.};
  double const q[pw85::sym] = {1., 0., 0., 1., 0., 1.};
  double out[2], g[pw85::geom::size], d[pw85::deriv::size];
  double const a[pw85::dim] = {1., 1., 1.};
  double const p[4] = {1., 0., 0., 0.};
  double q2[pw85::sym], axes[pw85::dim], rot[pw85::dim * pw85::dim];
  bool ok = pw85::contact_function(r, q, q, out) == PW85_SUCCESS;
  ok = ok && pw85::ellipsoid_quaternion(a, p, q2) == PW85_SUCCESS;
  ok = ok && pw85::principal_axes(q2, axes, rot) == PW85_SUCCESS;
  ok = ok && pw85::ellipsoid_rotation(axes, rot, q2) == PW85_SUCCESS;
  ok = ok && pw85::contact_geometry(r, q, q2, g) == PW85_SUCCESS;
  ok = ok && pw85::contact_derivatives(r, q, q2, g, d) == PW85_SUCCESS;
  int status[1], result[1];
  ok = ok && pw85::batch_threads(1, 1) == 1;
  ok = ok && pw85::contact_function_batch(1, r, pw85::dim, q, 0, q, 0, out,
                                          status, 1) == PW85_SUCCESS;
  ok = ok && pw85::overlap_batch(1, r, 0, q, 0, q, pw85::sym, result,
                                 nullptr, 0) == PW85_SUCCESS;
  ok = ok && pw85::contact_geometry_batch(1, r, 0, q, 0, q2, 0, g, status,
                                          2) == PW85_SUCCESS;
  ok = ok && pw85::contact_derivatives_batch(1, r, 0, q, 0, q2, 0, g, d,
                                             nullptr, 1) == PW85_SUCCESS;
  double const c = 2., nz[pw85::dim] = {0., 0., 1.};
  ok = ok && pw85::spheroid_batch(1, a, 0, &c, 0, nz, 0, q2, status, 1) ==
                 PW85_SUCCESS;
  ok = ok && pw85::ellipsoid_rotation_batch(1, axes, 0, rot, 0, q2, nullptr,
                                            1) == PW85_SUCCESS;
  ok = ok && pw85::ellipsoid_quaternion_batch(1, a, 0, p, 0, q2, nullptr,
                                              1) == PW85_SUCCESS;
  ok = ok && pw85::principal_axes_batch(1, q2, 0, axes, rot, nullptr, 1) ==
                 PW85_SUCCESS;
  pw85::Index index;
  std::size_t n = 1;
  std::vector<pw85::Index::Pair> pairs;
  ok = ok && pw85::Index::open(index) == PW85_SUCCESS;
  ok = ok && index.insert(0, r, q) == PW85_SUCCESS;
  ok = ok && index.pairs_within(1., 1, pairs) == PW85_SUCCESS && pairs.empty();
  ok = ok && index.count(n) == PW85_SUCCESS && n == 1;
  std::vector<std::int32_t> image;
  std::size_t voxels = 0;
  double fraction = 0.;
  ok = ok && pw85::image_voxels({0.5, 0.5, 0.5}, {0.25, 0., 0., 0.25, 0., 0.25},
                                {0., 0., 0.}, {1., 1., 1.}, true, {2, 2, 2},
                                image) == PW85_SUCCESS;
  ok = ok && pw85::image_fraction({2, 2, 2}, image, voxels, fraction) ==
                 PW85_SUCCESS && voxels == 8 && fraction == 1.;
  return ok ? 0 : 1;
}
