/* SPDX-License-Identifier: BSD-3-Clause */
/* Compiled as C (several standards, -Werror -pedantic): pw85.h and
 * pw85_index.h (and pw85_image.h, pw85_2d.h, pw85_2d_index.h,
 * pw85_2d_pack.h) stand alone, twice included, and their prototypes
 * accept const arrays. */
#include <pw85/pw85_2d.h>
#include <pw85/pw85_2d.h>
#include <pw85/pw85_2d_index.h>
#include <pw85/pw85_2d_index.h>
#include <pw85/pw85_2d_pack.h>
#include <pw85/pw85_2d_pack.h>
#include <pw85/pw85_image.h>
#include <pw85/pw85_image.h>
#include <pw85/pw85_index.h>
#include <pw85/pw85_index.h>
#include <pw85/pw85_pack.h>
#include <pw85/pw85_pack.h>
#include <pw85/pw85.h>
#include <pw85/pw85.h>
#include <pw85.h>

int main(void) {
  double const r[PW85_DIM] = {1., 0., 0.};
  double const q[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double out[2], g[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  double const a[PW85_DIM] = {1., 1., 1.};
  double const rot[PW85_DIM * PW85_DIM] = {1., 0., 0., 0., 1., 0., 0., 0., 1.};
  double const p[4] = {1., 0., 0., 0.};
  double q2[PW85_SYM], axes[PW85_DIM], dirs[PW85_DIM * PW85_DIM];
  int ok = pw85_contact_function(r, q, q, out) == PW85_SUCCESS;
  ok = ok && pw85_ellipsoid_rotation(a, rot, q2) == PW85_SUCCESS;
  ok = ok && pw85_ellipsoid_quaternion(a, p, q2) == PW85_SUCCESS;
  ok = ok && pw85_principal_axes(q, axes, dirs) == PW85_SUCCESS;
  ok = ok && pw85_contact_geometry(r, q, q, g) == PW85_SUCCESS;
  ok = ok && pw85_contact_derivatives(r, q, q, g, d) == PW85_SUCCESS;
  int status[1], result[1];
  ok = ok && pw85_batch_threads(1, 1) == 1;
  ok = ok && pw85_contact_function_batch(1, r, PW85_DIM, q, 0, q, 0, out,
                                         status, 1) == PW85_SUCCESS;
  ok = ok && pw85_overlap_batch(1, r, 0, q, PW85_SYM, q, PW85_SYM, result,
                                NULL, 0) == PW85_SUCCESS;
  ok = ok && pw85_contact_geometry_batch(1, r, 0, q, 0, q, 0, g, status,
                                         2) == PW85_SUCCESS;
  ok = ok && pw85_contact_derivatives_batch(1, r, 0, q, 0, q, 0, g, d, NULL,
                                            1) == PW85_SUCCESS;
  double const c = 2., nz[PW85_DIM] = {0., 0., 1.};
  ok = ok && pw85_spheroid_batch(1, a, 0, &c, 0, nz, 0, q2, status, 1) ==
                 PW85_SUCCESS;
  ok = ok && pw85_ellipsoid_rotation_batch(1, a, 0, rot, 0, q2, NULL, 1) ==
                 PW85_SUCCESS;
  ok = ok && pw85_ellipsoid_quaternion_batch(1, a, 0, p, 0, q2, NULL, 1) ==
                 PW85_SUCCESS;
  ok = ok && pw85_principal_axes_batch(1, q, 0, axes, dirs, NULL, 1) ==
                 PW85_SUCCESS;
  pw85_index *index = NULL;
  size_t count = 1;
  ok = ok && pw85_index_create(NULL, &index) == PW85_SUCCESS;
  ok = ok && pw85_index_insert(index, 0, r, q) == PW85_SUCCESS;
  ok = ok && pw85_index_pairs_within(index, 1., 1, 0, NULL, NULL, NULL,
                                     &count) == PW85_SUCCESS && count == 0;
  pw85_index_destroy(index);
  size_t const dims[PW85_DIM] = {2, 2, 2};
  int32_t image[8];
  ok = ok && pw85_image_voxels(1, r, q, NULL, a, 1, dims, image, 1) == PW85_SUCCESS;
  ok = ok && pw85_image_fraction(dims, image, &count, NULL) == PW85_SUCCESS &&
       count == 8;
  double const r2[PW85_2D_DIM] = {1., 0.}, q2d[PW85_2D_SYM] = {1., 0., 1.};
  double const a2[PW85_2D_DIM] = {2., 1.};
  double const params2[PW85_2D_DIM + 2 * PW85_2D_SYM] = {1., 0., 1., 0., 1., 1., 0., 1.};
  double e2[PW85_2D_SYM], theta = 1.;
  ok = ok && pw85_2d_contact_function(r2, q2d, q2d, out) == PW85_SUCCESS;
  ok = ok && pw85_2d_overlap(r2, q2d, q2d, result) == PW85_SUCCESS;
  ok = ok && pw85_2d_f_neg(0.5, params2) < 0.;
  ok = ok && pw85_2d_ellipse(a2, 0., e2) == PW85_SUCCESS;
  ok = ok && pw85_2d_principal_axes(q2d, axes, &theta) == PW85_SUCCESS;
  double g2[PW85_2D_GEOM_SIZE], d2[PW85_2D_DERIV_SIZE];
  ok = ok && pw85_2d_contact_geometry(r2, q2d, q2d, g2) == PW85_SUCCESS;
  ok = ok && pw85_2d_contact_derivatives(r2, q2d, q2d, g2, d2) == PW85_SUCCESS;
  ok = ok && pw85_2d_contact_function_batch(1, r2, 0, q2d, 0, q2d, 0, out,
                                            NULL, 1) == PW85_SUCCESS;
  ok = ok && pw85_2d_overlap_batch(1, r2, 0, q2d, 0, q2d, 0, result, NULL,
                                   1) == PW85_SUCCESS;
  ok = ok && pw85_2d_contact_geometry_batch(1, r2, 0, q2d, 0, q2d, 0, g2,
                                            NULL, 1) == PW85_SUCCESS;
  ok = ok && pw85_2d_contact_derivatives_batch(1, r2, 0, q2d, 0, q2d, 0, g2,
                                               d2, NULL, 1) == PW85_SUCCESS;
  ok = ok && pw85_2d_ellipse_batch(1, a2, 0, &theta, 0, e2, NULL, 1) ==
                 PW85_SUCCESS;
  ok = ok && pw85_2d_principal_axes_batch(1, q2d, 0, axes, &theta, NULL, 1) ==
                 PW85_SUCCESS;
  double const box2[PW85_2D_DIM] = {4., 4.};
  pw85_2d_index *index2 = NULL;
  ok = ok && pw85_2d_index_create(box2, &index2) == PW85_SUCCESS;
  ok = ok && pw85_2d_index_insert(index2, 0, r2, q2d) == PW85_SUCCESS;
  ok = ok && pw85_2d_index_within(index2, r2, q2d, 1., PW85_INDEX_NO_ID, 0,
                                  NULL, NULL, NULL, &count) == PW85_SUCCESS &&
       count == 1;
  double energy2 = -1.;
  ok = ok && pw85_2d_index_energy(index2, PW85_ENERGY_OVERLAP, 1., NULL, NULL,
                                  1, 1, &energy2, NULL, NULL) ==
                 PW85_SUCCESS && energy2 == 0.;
  pw85_2d_index_destroy(index2);
  double const one[PW85_2D_DIM] = {1., .5};
  double side2[PW85_2D_DIM], c2[PW85_2D_DIM], f2[PW85_2D_SYM], phi2;
  int outcome2;
  pw85_pack_options options2;
  pw85_pack_options_init(&options2);
  options2.target = .1;
  ok = ok && pw85_2d_pack(1, one, &options2, side2, c2, NULL, f2, &phi2,
                          &outcome2) == PW85_SUCCESS &&
       outcome2 == PW85_PACK_TARGET;
  return ok ? 0 : 1;
}
