/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85-pack's files (io.c): the HDF5 layout of docs/microstructures.rst,
 * its XDMF companion and the extended XYZ, in 3D or 2D (dim.h). Every writer writes a temporary
 * file beside the target and renames it: the target is whole or untouched.
 * Errors: −1 and one line in err (no trailing newline). */
#ifndef PW85_PACK_IO_H
#define PW85_PACK_IO_H

#include <stddef.h>
#include <stdint.h>

#include "dim.h"

/* The most ellipsoids a file may hold (--n's range): io_read_hdf5()
 * rejects larger datasets. */
#define IO_MAX_COUNT 100000000u

/* A configuration as written: count ellipsoids (or ellipses) in a periodic
 * box (its first dims->dim sides). */
struct micro {
  struct dim_ops const *dims;
  double box[3];
  size_t count;
  /* per ellipsoid: 3, 6, 3, 4 doubles (the orientation a quaternion); per
   * ellipse: 2, 3, 2, 1 (the angle) */
  double *centres, *forms, *axes, *orientations;
  double packing_fraction;
  uint64_t seed, attempts;
  size_t target;
  char method[32];
  char pw85_version[32];
  /* the image, or NULL: side^dim int32, and its phase fraction */
  int32_t const *image;
  size_t side;
  double image_fraction;
};

int io_check_writable(char const *path, char *err, size_t size);
/* 1 if the paths a and b name one file: the same string; two names of one
 * existing file (stat: device and inode); or, the file absent, the same
 * name in the same directory (stat of the directories). 0 otherwise. */
int io_same_file(char const *a, char const *b);
int io_write_hdf5(char const *path, struct micro const *m, char *err, size_t size);
/* Reads the layout (without /image), 3D or 2D by its attribute dimension
 * (none: 3D); validates types and shapes, and sizes (at most IO_MAX_COUNT
 * ellipsoids). */
int io_read_hdf5(char const *path, struct micro *m, char *err, size_t size);
void io_free(struct micro *m);
/* 1 if the file name of path (its last component) can be written in an
 * XML document (io_write_xdmf() escapes & < > " '): UTF-8, without control
 * characters, which XML 1.0 does not allow even as references. 0 if not. */
int io_xml_name(char const *path);
int io_write_xdmf(char const *path, char const *h5_path, struct micro const *m,
                  char *err, size_t size);
int io_write_xyz(char const *path, struct micro const *m, char *err, size_t size);

#endif
