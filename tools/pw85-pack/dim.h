/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85-pack: what depends on the dimension, in one table per dimension:
 * 3, ellipsoids (pw85.h, pw85_index.h, pw85_pack.h, pw85_image.h), the
 * default; 2, ellipses (pw85_2d.h, pw85_2d_index.h, pw85_2d_pack.h;
 * --2d). The command, the methods and the files are written once, for a
 * struct dim_ops; arrays hold `dim`, `sym` or `orient` doubles per shape,
 * row by row. */
#ifndef PW85_PACK_DIM_H
#define PW85_PACK_DIM_H

#include <pw85/pw85_pack.h>
#include <stddef.h>
#include <stdint.h>

struct dim_ops {
  int dim;    /* 3 or 2: doubles per centre and per set of semi-axes */
  int sym;    /* doubles per form: 6 (pw85.h) or 3 (pw85_2d.h) */
  int orient; /* doubles per orientation: 4, a unit quaternion (w, x, y,
               * z), or 1, the angle θ of pw85_2d_ellipse() (radians) */
  char const *shapes; /* "ellipsoids" or "ellipses", for messages */
  /* The volume 4π/3·a0·a1·a2 or the area π·a0·a1 of semi-axes a. */
  double (*measure)(double const *a);
  /* The form of semi-axes a and an orientation (a pw85 status):
   * pw85_ellipsoid_quaternion() or pw85_2d_ellipse(). */
  int (*form)(double const *a, double const *orientation, double *q);
  /* pw85_pack() or pw85_2d_pack() (the same signature). */
  int (*pack)(size_t n, double const *semi_axes, pw85_pack_options const *options,
              double *box, double *centres, double *orientations, double *q, double *phi,
              int *outcome);
  /* The index of pw85_index.h or pw85_2d_index.h, the same calls with the
   * index as a void pointer. */
  int (*index_create)(double const *box, void **index);
  void (*index_destroy)(void *index);
  int (*index_insert)(void *index, size_t id, double const *centre, double const *q);
  int (*index_overlap_any)(void const *index, double const *centre, double const *q,
                           size_t exclude, int *result, size_t *id);
  int (*index_overlap_any_batch)(void const *index, size_t n, double const *centres,
                                 size_t centre_stride, double const *q, size_t q_stride,
                                 size_t const *exclude, int *results, size_t *ids,
                                 int *status, int threads);
  int (*index_overlapping_pairs)(void const *index, int threads, size_t capacity,
                                 size_t *ids, int *shifts, int *results, size_t *count);
  /* The periodic voxel image of pw85_image.h, m voxels along each side of
   * box: m³ (3D) or m² (2D) int32 values, voxel (i, j[, k]) the point
   * ((i + ½)·L0/m, (j + ½)·L1/m[, (k + ½)·L2/m]), first index along x;
   * and its phase fraction (pw85_image_fraction()); a pw85 status. */
  int (*image)(size_t n, double const *centres, double const *q, double const *box,
               size_t m, int32_t *image, int threads, double *fraction);
};

extern struct dim_ops const dim_3d, dim_2d;

/* The count of voxels of an image of side m: m^dim (as a double: a size
 * that may not fit). */
double dim_voxels(struct dim_ops const *d, size_t m);

#endif
