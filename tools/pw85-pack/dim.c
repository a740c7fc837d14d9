/* SPDX-License-Identifier: BSD-3-Clause */
/* The tables of dim.h: ellipsoids (3) and ellipses (2). */
#include "dim.h"

#include <math.h>
#include <pw85/pw85_2d_index.h>
#include <pw85/pw85_2d_pack.h>
#include <pw85/pw85_image.h>
#include <pw85/pw85_index.h>
#include <stdlib.h>

static double const pi = 3.14159265358979323846;

/* The same expression, rounding for rounding, as the tool wrote before
 * dim.h: the files of 3D packings stay the same to the bit. */
static double volume(double const *a) { return 4.0 / 3.0 * pi * a[0] * a[1] * a[2]; }
static double area(double const *a) { return pi * a[0] * a[1]; }

static int ellipse_form(double const *a, double const *theta, double *q) {
  return pw85_2d_ellipse(a, *theta, q);
}

/* The calls of pw85_index.h (prefix pw85_index_, type pw85_index) or
 * pw85_2d_index.h (pw85_2d_index_, pw85_2d_index) with the index as a
 * void pointer: the signatures of struct dim_ops. */
#define INDEX_CALLS(P, T)                                                                \
  static int P##create_v(double const *box, void **index) {                             \
    T *ix = NULL;                                                                        \
    int const status = P##create(box, &ix);                                              \
    *index = ix;                                                                         \
    return status;                                                                       \
  }                                                                                      \
  static void P##destroy_v(void *index) { P##destroy(index); }                           \
  static int P##insert_v(void *index, size_t id, double const *c, double const *q) {     \
    return P##insert(index, id, c, q);                                                   \
  }                                                                                      \
  static int P##overlap_any_v(void const *index, double const *c, double const *q,       \
                              size_t exclude, int *result, size_t *id) {                 \
    return P##overlap_any(index, c, q, exclude, result, id);                             \
  }                                                                                      \
  static int P##overlap_any_batch_v(void const *index, size_t n, double const *c,        \
                                    size_t cs, double const *q, size_t qs,               \
                                    size_t const *exclude, int *results, size_t *ids,    \
                                    int *status, int threads) {                          \
    return P##overlap_any_batch(index, n, c, cs, q, qs, exclude, results, ids, status,   \
                                threads);                                                \
  }                                                                                      \
  static int P##overlapping_pairs_v(void const *index, int threads, size_t capacity,     \
                                    size_t *ids, int *shifts, int *results,              \
                                    size_t *count) {                                     \
    return P##overlapping_pairs(index, threads, capacity, ids, shifts, results, count);  \
  }
INDEX_CALLS(pw85_index_, pw85_index)
INDEX_CALLS(pw85_2d_index_, pw85_2d_index)

static int image_3d(size_t n, double const *centres, double const *q, double const *box,
                    size_t m, int32_t *image, int threads, double *fraction) {
  size_t const dims[3] = {m, m, m};
  int status = pw85_image_voxels(n, centres, q, NULL, box, 1, dims, image, threads);
  if (status == PW85_SUCCESS) status = pw85_image_fraction(dims, image, NULL, fraction);
  return status;
}

/* The image of ellipses through pw85_image_voxels(): ellipse (c, Q) is
 * drawn as the ellipsoid of centre (c0, L0/2, c1) and form
 * [[Q00, 0, Q01], [0, max(Q00, Q11), 0], [Q01, 0, Q11]] in the periodic
 * box (L0, L0, L1) cut into m × 1 × m voxels: voxel (i, 0, j) is pixel
 * (i, j), at the same place in memory (first index along x). The one layer
 * of voxel centres is the plane u1 = L0/2 exactly (pw85_image.h:
 * (0 + ½)·L0/1), where (m − c)ᵀQ₃⁻¹(m − c) is the (m − c)ᵀQ⁻¹(m − c) of
 * the ellipse, the difference along u1 being exactly 0: the image decides
 * the ellipse itself, exactly. The extent along u1, √max(Q00, Q11) ≤
 * a_max < L0/2, keeps the images along u1 away from the plane. (The extra
 * axis in the middle: pw85_image_voxels() decides rows along the last
 * index by their ends, so rows of m pixels, not of 1; and shares the m
 * planes along the first among threads, at most dims[0] of them.) */
static int image_2d(size_t n, double const *centres, double const *q, double const *box,
                    size_t m, int32_t *image, int threads, double *fraction) {
  double *c3 = malloc((n ? n : 1) * 3 * sizeof *c3), *q3 = malloc((n ? n : 1) * 6 * sizeof *q3);
  int status = c3 && q3 ? PW85_SUCCESS : PW85_ENOMEM;
  double const sides[3] = {box[0], box[0], box[1]};
  for (size_t i = 0; i < n && status == PW85_SUCCESS; i++) {
    double const *qi = q + 3 * i;
    c3[3 * i] = centres[2 * i], c3[3 * i + 1] = 0.5 * box[0], c3[3 * i + 2] = centres[2 * i + 1];
    q3[6 * i] = qi[0], q3[6 * i + 1] = 0, q3[6 * i + 2] = qi[1];
    q3[6 * i + 3] = fmax(qi[0], qi[2]), q3[6 * i + 4] = 0, q3[6 * i + 5] = qi[2];
  }
  size_t const dims[3] = {m, 1, m};
  if (status == PW85_SUCCESS)
    status = pw85_image_voxels(n, c3, q3, NULL, sides, 1, dims, image, threads);
  if (status == PW85_SUCCESS) status = pw85_image_fraction(dims, image, NULL, fraction);
  free(c3), free(q3);
  return status;
}

struct dim_ops const dim_3d = {
    3, 6, 4, "ellipsoids", volume, pw85_ellipsoid_quaternion, pw85_pack,
    pw85_index_create_v, pw85_index_destroy_v, pw85_index_insert_v,
    pw85_index_overlap_any_v, pw85_index_overlap_any_batch_v,
    pw85_index_overlapping_pairs_v, image_3d};

struct dim_ops const dim_2d = {
    2, 3, 1, "ellipses", area, ellipse_form, pw85_2d_pack,
    pw85_2d_index_create_v, pw85_2d_index_destroy_v, pw85_2d_index_insert_v,
    pw85_2d_index_overlap_any_v, pw85_2d_index_overlap_any_batch_v,
    pw85_2d_index_overlapping_pairs_v, image_2d};

double dim_voxels(struct dim_ops const *d, size_t m) {
  double const side = (double)m;
  return d->dim == 3 ? side * side * side : side * side;
}
