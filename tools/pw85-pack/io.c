/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85-pack's files (io.h): the HDF5 layout, its XDMF companion and the
 * extended XYZ of docs/microstructures.rst (3D, or 2D: dim.h), each written to a temporary
 * file of the same directory, flushed, then renamed over the target: whole
 * or not at all. */
#define _POSIX_C_SOURCE 200809L
#include "io.h"

#include <errno.h>
#include <hdf5.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The temporary name beside path: path.tmp-PID-XXXXXX, created (mkstemp);
 * its descriptor in *fd. NULL on failure (errno set). */
static char *temp_beside(char const *path, int *fd) {
  size_t const n = strlen(path) + 64;
  char *t = malloc(n);
  if (t == NULL) return NULL;
  snprintf(t, n, "%s.tmp-%ld-XXXXXX", path, (long)getpid());
  *fd = mkstemp(t);
  if (*fd < 0) {
    int const e = errno;
    free(t);
    errno = e;
    return NULL;
  }
  /* mkstemp() makes it 0600: the mode of a file created by open(). */
  mode_t const mask = umask(0);
  umask(mask);
  fchmod(*fd, 0666 & ~mask);
  return t;
}

static void set_error(char *err, size_t size, char const *what,
                      char const *path, char const *why) {
  snprintf(err, size, "%s %s: %s", what, path, why);
}

/* fsync then rename, or unlink on failure. */
static int commit(char *tmp, int fd, char const *path, char *err, size_t size) {
  int ok = fsync(fd) == 0;
  int e = errno;
  ok = close(fd) == 0 && ok;
  if (ok && rename(tmp, path) != 0) {
    e = errno;
    ok = 0;
  }
  if (!ok) {
    unlink(tmp);
    set_error(err, size, "cannot write", path, strerror(e));
  }
  free(tmp);
  return ok ? 0 : -1;
}

int io_check_writable(char const *path, char *err, size_t size) {
  int fd;
  char *tmp = temp_beside(path, &fd);
  if (tmp == NULL) {
    set_error(err, size, "cannot write", path, strerror(errno));
    return -1;
  }
  close(fd);
  unlink(tmp);
  free(tmp);
  return 0;
}

/* The directory part of path ("." without one, "/" for "/name") into dir. */
static void dir_of(char const *path, char *dir, size_t size) {
  char const *slash = strrchr(path, '/');
  if (slash == NULL)
    snprintf(dir, size, ".");
  else if (slash == path)
    snprintf(dir, size, "/");
  else
    snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

int io_same_file(char const *a, char const *b) {
  if (strcmp(a, b) == 0) return 1;
  struct stat sa, sb;
  /* two names of one existing file (a link, another spelling) */
  if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
    return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
  /* not there yet: one name in one directory, spelt two ways (./x, d/../x) */
  char const *sa_base = strrchr(a, '/'), *sb_base = strrchr(b, '/');
  if (strcmp(sa_base ? sa_base + 1 : a, sb_base ? sb_base + 1 : b) != 0) return 0;
  size_t const size = (strlen(a) > strlen(b) ? strlen(a) : strlen(b)) + 2;
  char *da = malloc(size), *db = malloc(size);
  int same = 0;
  if (da != NULL && db != NULL) {
    dir_of(a, da, size), dir_of(b, db, size);
    same = stat(da, &sa) == 0 && stat(db, &sb) == 0
               ? sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino
               : strcmp(da, db) == 0;
  } else {
    same = 1; /* out of memory: refuse rather than risk a file */
  }
  free(da), free(db);
  return same;
}

/* ---- HDF5 ---- */

/* The dataset of the orientations. */
static char const *orientation_name(struct dim_ops const *d) {
  return d->orient > 1 ? "quaternions" : "angles";
}

static herr_t write_dataset(hid_t file, char const *name, hid_t type, int rank,
                            hsize_t const *dims, void const *data) {
  hid_t const space = H5Screate_simple(rank, dims, NULL);
  if (space < 0) return -1;
  hid_t const set = H5Dcreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT,
                               H5P_DEFAULT);
  herr_t st = set < 0 ? -1 : 0;
  if (st == 0 && dims[0] > 0) st = H5Dwrite(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data);
  if (set >= 0) H5Dclose(set);
  H5Sclose(space);
  return st;
}

static herr_t write_attr(hid_t file, char const *name, hid_t type, void const *value) {
  hid_t const space = H5Screate(H5S_SCALAR);
  hid_t const attr = H5Acreate2(file, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  herr_t const st = attr < 0 ? -1 : H5Awrite(attr, type, value);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  return st;
}

static herr_t write_string_attr(hid_t file, char const *name, char const *value) {
  hid_t const type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  herr_t const st = write_attr(file, name, type, &value);
  H5Tclose(type);
  return st;
}

int io_write_hdf5(char const *path, struct micro const *m, char *err, size_t size) {
  int fd;
  char *tmp = temp_beside(path, &fd);
  if (tmp == NULL) {
    set_error(err, size, "cannot write", path, strerror(errno));
    return -1;
  }
  hid_t const file = H5Fcreate(tmp, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  herr_t st = file < 0 ? -1 : 0;
  struct dim_ops const *d = m->dims;
  hsize_t const dim[1] = {(hsize_t)d->dim};
  hsize_t const n = m->count;
  hsize_t dims[3];
  if (st == 0) st = write_dataset(file, "box", H5T_NATIVE_DOUBLE, 1, dim, m->box);
  dims[0] = n, dims[1] = (hsize_t)d->dim;
  if (st == 0) st = write_dataset(file, "centres", H5T_NATIVE_DOUBLE, 2, dims, m->centres);
  dims[1] = (hsize_t)d->sym;
  if (st == 0) st = write_dataset(file, "forms", H5T_NATIVE_DOUBLE, 2, dims, m->forms);
  dims[1] = (hsize_t)d->dim;
  if (st == 0) st = write_dataset(file, "axes", H5T_NATIVE_DOUBLE, 2, dims, m->axes);
  /* /quaternions float64[n][4], or /angles float64[n] */
  dims[1] = (hsize_t)d->orient;
  if (st == 0)
    st = write_dataset(file, orientation_name(d), H5T_NATIVE_DOUBLE, d->orient > 1 ? 2 : 1,
                       dims, m->orientations);
  if (st == 0 && m->image != NULL) {
    for (int k = 0; k < d->dim; k++) dims[k] = m->side;
    st = write_dataset(file, "image", H5T_NATIVE_INT32, d->dim, dims, m->image);
  }
  if (st == 0) st = write_attr(file, "packing_fraction", H5T_NATIVE_DOUBLE, &m->packing_fraction);
  if (st == 0) st = write_attr(file, "seed", H5T_NATIVE_UINT64, &m->seed);
  if (st == 0) st = write_string_attr(file, "pw85_version", m->pw85_version);
  if (st == 0) st = write_string_attr(file, "method", m->method);
  if (st == 0) st = write_attr(file, "attempts", H5T_NATIVE_UINT64, &m->attempts);
  uint64_t const target = m->target;
  if (st == 0) st = write_attr(file, "target_count", H5T_NATIVE_UINT64, &target);
  if (st == 0 && m->image != NULL)
    st = write_attr(file, "image_fraction", H5T_NATIVE_DOUBLE, &m->image_fraction);
  /* 2D only: the files of 3D packings are those of before --2d */
  int32_t const dimension = d->dim;
  if (st == 0 && dimension != 3)
    st = write_attr(file, "dimension", H5T_NATIVE_INT32, &dimension);
  if (file >= 0 && H5Fclose(file) < 0) st = -1;
  if (st < 0) {
    close(fd);
    unlink(tmp);
    free(tmp);
    set_error(err, size, "cannot write", path, "HDF5 error (disk full?)");
    return -1;
  }
  return commit(tmp, fd, path, err, size);
}

/* Reads dataset name: type double (or int32 for the image), rank `rank`,
 * the dims given where nonzero (dims[0] = 0: any; returned). */
static int read_dataset(hid_t file, char const *name, int rank, hsize_t *dims,
                        hid_t mem_type, void **data, char *why, size_t size) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) {
    snprintf(why, size, "no dataset /%s", name);
    return -1;
  }
  hid_t const set = H5Dopen2(file, name, H5P_DEFAULT);
  if (set < 0) {
    snprintf(why, size, "/%s is not a dataset", name);
    return -1;
  }
  hid_t const space = H5Dget_space(set), type = H5Dget_type(set);
  hsize_t got[4] = {0, 0, 0, 0};
  int const r = H5Sget_simple_extent_ndims(space);
  int ok = r == rank && H5Tget_class(type) == H5Tget_class(mem_type);
  if (ok) H5Sget_simple_extent_dims(space, got, NULL);
  for (int k = 0; ok && k < rank; k++)
    if (dims[k] != 0 && got[k] != dims[k]) ok = 0;
  /* The sizes are the file's, not ours: rows within --n's range, and a
   * count of bytes that fits a size_t (it wrapped around: a small buffer
   * that H5Dread() overran). */
  size_t const item = H5Tget_size(mem_type);
  size_t count = 1;
  if (!ok) {
    snprintf(why, size, "/%s has not the documented type and shape", name);
  } else if (rank == 2 && got[0] > IO_MAX_COUNT) {
    snprintf(why, size, "/%s has %llu rows, more than %llu", name,
             (unsigned long long)got[0], (unsigned long long)IO_MAX_COUNT);
    ok = 0;
  } else {
    for (int k = 0; ok && k < rank; k++) {
      if (got[k] != 0 && count > SIZE_MAX / item / got[k]) {
        snprintf(why, size, "/%s is too large", name);
        ok = 0;
      }
      count *= (size_t)got[k];
    }
  }
  if (ok) {
    for (int k = 0; k < rank; k++) dims[k] = got[k];
    *data = malloc((count ? count : 1) * item);
    if (*data == NULL) {
      snprintf(why, size, "out of memory for /%s", name);
      ok = 0;
    } else if (count > 0 &&
               H5Dread(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, *data) < 0) {
      snprintf(why, size, "/%s cannot be read (corrupted?)", name);
      free(*data);
      *data = NULL;
      ok = 0;
    }
  }
  H5Tclose(type);
  H5Sclose(space);
  H5Dclose(set);
  return ok ? 0 : -1;
}

/* The attribute `name` of file and its type (both to close), or -1 with
 * why set when there is none. */
static int open_attr(hid_t file, char const *name, hid_t *attr, hid_t *type,
                     char *why, size_t size) {
  if (H5Aexists(file, name) <= 0) {
    snprintf(why, size, "no attribute %s", name);
    return -1;
  }
  *attr = H5Aopen(file, name, H5P_DEFAULT);
  *type = H5Aget_type(*attr);
  return 0;
}

static int read_attr(hid_t file, char const *name, hid_t mem_type, void *value,
                     char *why, size_t size) {
  hid_t attr, type;
  if (open_attr(file, name, &attr, &type, why, size) != 0) return -1;
  int ok = H5Tget_class(type) == H5Tget_class(mem_type) &&
           H5Aread(attr, mem_type, value) >= 0;
  H5Tclose(type);
  H5Aclose(attr);
  if (!ok) snprintf(why, size, "attribute %s has not the documented type", name);
  return ok ? 0 : -1;
}

static int read_string_attr(hid_t file, char const *name, char *out, size_t out_size,
                            char *why, size_t size) {
  hid_t attr, type;
  if (open_attr(file, name, &attr, &type, why, size) != 0) return -1;
  int ok = H5Tget_class(type) == H5T_STRING;
  if (ok && H5Tis_variable_str(type) > 0) {
    char *s = NULL;
    hid_t const mem = H5Tcopy(H5T_C_S1);
    H5Tset_size(mem, H5T_VARIABLE);
    H5Tset_cset(mem, H5Tget_cset(type));
    ok = H5Aread(attr, mem, &s) >= 0 && s != NULL;
    if (ok) snprintf(out, out_size, "%s", s);
    if (s != NULL) H5free_memory(s);
    H5Tclose(mem);
  } else if (ok) {
    size_t const n = H5Tget_size(type);
    char *s = calloc(n + 1, 1);
    ok = s != NULL && H5Aread(attr, type, s) >= 0;
    if (ok) snprintf(out, out_size, "%s", s);
    free(s);
  }
  H5Tclose(type);
  H5Aclose(attr);
  if (!ok) snprintf(why, size, "attribute %s is not a string", name);
  return ok ? 0 : -1;
}

int io_read_hdf5(char const *path, struct micro *m, char *err, size_t size) {
  memset(m, 0, sizeof *m);
  char why[256] = "";
  if (access(path, R_OK) != 0) {
    set_error(err, size, "cannot read", path, strerror(errno));
    return -1;
  }
  if (H5Fis_hdf5(path) <= 0) {
    set_error(err, size, "cannot read", path, "not an HDF5 file (or a corrupted one)");
    return -1;
  }
  hid_t const file = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    set_error(err, size, "cannot read", path, "not an HDF5 file (or a corrupted one)");
    return -1;
  }
  /* The attribute dimension: 2, or absent (3D; 3 is read as such). */
  int32_t dimension = 3;
  int st = 0;
  if (H5Aexists(file, "dimension") > 0) {
    st = read_attr(file, "dimension", H5T_NATIVE_INT32, &dimension, why, sizeof why);
    if (st == 0 && dimension != 2 && dimension != 3) {
      snprintf(why, sizeof why, "attribute dimension is %d, not 2 or 3", (int)dimension);
      st = -1;
    }
  }
  struct dim_ops const *dm = dimension == 2 ? &dim_2d : &dim_3d;
  m->dims = dm;
  hsize_t const dim = (hsize_t)dm->dim;
  hsize_t d[3] = {dim, 0, 0};
  double *box = NULL;
  if (st == 0)
    st = read_dataset(file, "box", 1, d, H5T_NATIVE_DOUBLE, (void **)&box, why, sizeof why);
  if (st == 0) {
    memcpy(m->box, box, dim * sizeof *box);
    free(box);
    d[0] = 0, d[1] = dim;
    st = read_dataset(file, "centres", 2, d, H5T_NATIVE_DOUBLE, (void **)&m->centres, why,
                      sizeof why);
    m->count = (size_t)d[0];
  }
  hsize_t const n = m->count;
  if (st == 0) {
    d[0] = n, d[1] = (hsize_t)dm->sym;
    st = read_dataset(file, "forms", 2, d, H5T_NATIVE_DOUBLE, (void **)&m->forms, why, sizeof why);
  }
  if (st == 0) {
    d[0] = n, d[1] = dim;
    st = read_dataset(file, "axes", 2, d, H5T_NATIVE_DOUBLE, (void **)&m->axes, why, sizeof why);
  }
  if (st == 0) {
    d[0] = n, d[1] = (hsize_t)dm->orient;
    st = read_dataset(file, orientation_name(dm), dm->orient > 1 ? 2 : 1, d, H5T_NATIVE_DOUBLE,
                      (void **)&m->orientations, why, sizeof why);
  }
  if (st == 0)
    st = read_attr(file, "packing_fraction", H5T_NATIVE_DOUBLE, &m->packing_fraction, why,
                   sizeof why);
  if (st == 0) st = read_attr(file, "seed", H5T_NATIVE_UINT64, &m->seed, why, sizeof why);
  if (st == 0)
    st = read_string_attr(file, "method", m->method, sizeof m->method, why, sizeof why);
  if (st == 0)
    st = read_string_attr(file, "pw85_version", m->pw85_version, sizeof m->pw85_version,
                          why, sizeof why);
  if (st == 0) st = read_attr(file, "attempts", H5T_NATIVE_UINT64, &m->attempts, why, sizeof why);
  uint64_t target = 0;
  if (st == 0) st = read_attr(file, "target_count", H5T_NATIVE_UINT64, &target, why, sizeof why);
  m->target = (size_t)target;
  H5Fclose(file);
  if (st != 0) {
    io_free(m);
    set_error(err, size, "not a pw85-pack file", path, why);
    return -1;
  }
  return 0;
}

void io_free(struct micro *m) {
  free(m->centres), free(m->forms), free(m->axes), free(m->orientations);
  m->centres = m->forms = m->axes = m->orientations = NULL;
}

/* ---- text files ---- */

static char const *base_name(char const *path) {
  char const *s = strrchr(path, '/');
  return s ? s + 1 : path;
}

/* A text file opened for writing at a temporary name beside path
 * (temp_beside()): the stream, its name in *tmp and its descriptor in *fd,
 * for finish_beside(); NULL with err set on failure (nothing left). */
static FILE *open_beside(char const *path, char **tmp, int *fd, char *err, size_t size) {
  *tmp = temp_beside(path, fd);
  if (*tmp == NULL) {
    set_error(err, size, "cannot write", path, strerror(errno));
    return NULL;
  }
  FILE *f = fdopen(dup(*fd), "w");
  if (f == NULL) {
    int const e = errno;
    close(*fd), unlink(*tmp), free(*tmp);
    set_error(err, size, "cannot write", path, strerror(e));
  }
  return f;
}

/* Closes what open_beside() opened and renames it over path (commit()),
 * or removes it if a write failed. */
static int finish_beside(FILE *f, char *tmp, int fd, char const *path, char *err,
                         size_t size) {
  int const bad = ferror(f) | (fclose(f) != 0);
  if (bad) {
    close(fd), unlink(tmp), free(tmp);
    set_error(err, size, "cannot write", path, "write error (disk full?)");
    return -1;
  }
  return commit(tmp, fd, path, err, size);
}

/* Appends to buf (of size size) count numbers, ' '-separated: values[k]
 * printed with fmt, or, values NULL, the integer of ints[k]. */
static void join(char *buf, size_t size, int count, char const *fmt, double const *values,
                 size_t const *ints) {
  size_t used = 0;
  buf[0] = '\0';
  for (int k = 0; k < count && used < size; k++) {
    int const w = values ? snprintf(buf + used, size - used, fmt, k ? " " : "", values[k])
                         : snprintf(buf + used, size - used, "%s%zu", k ? " " : "", ints[k]);
    used += w > 0 ? (size_t)w : 0;
  }
}

int io_xml_name(char const *path) {
  unsigned char const *p = (unsigned char const *)base_name(path);
  while (*p) {
    unsigned const b = *p;
    int const more = b < 0x80 ? 0 : (b & 0xe0) == 0xc0 ? 1 : (b & 0xf0) == 0xe0 ? 2
                     : (b & 0xf8) == 0xf0                ? 3
                                                         : -1;
    if (b < 0x20 || more < 0) return 0;
    unsigned long c = more == 0 ? b : b & (0x3f >> more);
    for (int k = 1; k <= more; k++) {
      if ((p[k] & 0xc0) != 0x80) return 0;
      c = c << 6 | (p[k] & 0x3f);
    }
    /* the shortest form; no surrogate; XML 1.0's Char */
    static unsigned long const least[4] = {0, 0x80, 0x800, 0x10000};
    if (c < least[more] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff) || c == 0xfffe ||
        c == 0xffff)
      return 0;
    p += 1 + more;
  }
  return 1;
}

/* s into f with & < > " ' as XML's entities: text or an attribute value. */
static void put_xml(FILE *f, char const *s) {
  for (; *s; s++) {
    switch (*s) {
      case '&': fputs("&amp;", f); break;
      case '<': fputs("&lt;", f); break;
      case '>': fputs("&gt;", f); break;
      case '"': fputs("&quot;", f); break;
      case '\'': fputs("&apos;", f); break;
      default: fputc(*s, f);
    }
  }
}

int io_write_xdmf(char const *path, char const *h5_path, struct micro const *m,
                  char *err, size_t size) {
  int fd;
  char *tmp;
  FILE *f = open_beside(path, &tmp, &fd, err, size);
  if (f == NULL) return -1;
  int const dim = m->dims->dim;
  size_t points[3], cells[3];
  double spacing[3];
  double const origin[3] = {0, 0, 0};
  for (int k = 0; k < dim; k++) {
    cells[k] = m->side, points[k] = m->side + 1;
    spacing[k] = m->box[k] / (double)m->side;
  }
  char point_text[96], cell_text[96], spacing_text[96], origin_text[16];
  join(point_text, sizeof point_text, dim, NULL, NULL, points);
  join(cell_text, sizeof cell_text, dim, NULL, NULL, cells);
  join(spacing_text, sizeof spacing_text, dim, "%s%.17g", spacing, NULL);
  join(origin_text, sizeof origin_text, dim, "%s%g", origin, NULL);
  /* XDMF lists dimensions slowest first (z y x; 2D: y x): the image's first
   * index, along x, is ParaView's Z (3D) or Y (2D) (docs/microstructures.rst,
   * "ParaView"). 2D: a 2DCoRectMesh with ORIGIN_DXDY (XDMF 3, Topology and
   * Geometry). The name of the HDF5 file is escaped (put_xml()), and not in
   * the comment, where "--" is not allowed. */
  fprintf(f,
          "<?xml version=\"1.0\" ?>\n"
          "<!-- pw85-pack %s: the voxel image of the HDF5 file below (docs: "
          "\"Microstructures for FFT solvers and viewers\"). -->\n"
          "<Xdmf Version=\"3.0\">\n"
          "  <Domain>\n"
          "    <Grid Name=\"image\" GridType=\"Uniform\">\n"
          "      <Topology TopologyType=\"%dDCoRectMesh\" Dimensions=\"%s\"/>\n"
          "      <Geometry GeometryType=\"%s\">\n"
          "        <DataItem Name=\"Origin\" Dimensions=\"%d\" NumberType=\"Float\" "
          "Precision=\"8\" Format=\"XML\">%s</DataItem>\n"
          "        <DataItem Name=\"Spacing\" Dimensions=\"%d\" NumberType=\"Float\" "
          "Precision=\"8\" Format=\"XML\">%s</DataItem>\n"
          "      </Geometry>\n"
          "      <Attribute Name=\"phase\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
          "        <DataItem Dimensions=\"%s\" NumberType=\"Int\" Precision=\"4\" "
          "Format=\"HDF\">",
          m->pw85_version, dim, point_text, dim == 3 ? "ORIGIN_DXDYDZ" : "ORIGIN_DXDY", dim,
          origin_text, dim, spacing_text, cell_text);
  put_xml(f, base_name(h5_path));
  fputs(":/image</DataItem>\n"
        "      </Attribute>\n"
        "    </Grid>\n"
        "  </Domain>\n"
        "</Xdmf>\n",
        f);
  return finish_beside(f, tmp, fd, path, err, size);
}

int io_write_xyz(char const *path, struct micro const *m, char *err, size_t size) {
  int fd;
  char *tmp;
  FILE *f = open_beside(path, &tmp, &fd, err, size);
  if (f == NULL) return -1;
  int const dim = m->dims->dim;
  /* 2D: the plane z = 0 of a cell whose third vector (0, 0, H), H twice
   * the largest semi-axis, is not periodic; an ellipse drawn as the
   * ellipsoid of semi-axes (a0, a1, min(a0, a1)), turned by θ about z (the
   * quaternion (cos θ/2, 0, 0, sin θ/2)), whose section by z = 0 is the
   * ellipse; θ itself in the column angle (docs/microstructures.rst).
   * Without ellipses (a file stopped before the first), H is the box's
   * larger side, so that the cell is never singular. */
  double height = m->box[2];
  if (dim == 2) {
    height = 0;
    for (size_t i = 0; i < 2 * m->count; i++) height = fmax(height, 2 * m->axes[i]);
    if (!(height > 0)) height = fmax(m->box[0], m->box[1]);
  }
  fprintf(f, "%zu\n", m->count);
  fprintf(f,
          "Lattice=\"%.17g 0 0 0 %.17g 0 0 0 %.17g\" pbc=\"T T %s\" "
          "Properties=species:S:1:pos:R:3:aspherical_shape:R:3:orientation:R:4%s "
          "%spacking_fraction=%.17g seed=%llu method=%s pw85_version=%s\n",
          m->box[0], m->box[1], height, dim == 3 ? "T" : "F", dim == 3 ? "" : ":angle:R:1",
          dim == 3 ? "" : "dimension=2 ", m->packing_fraction, (unsigned long long)m->seed,
          m->method, m->pw85_version);
  for (size_t i = 0; i < m->count; i++) {
    double const *c = m->centres + dim * i, *a = m->axes + dim * i,
                 *p = m->orientations + m->dims->orient * i;
    double c3[3] = {c[0], c[1], 0}, a3[3] = {a[0], a[1], fmin(a[0], a[1])}, p4[4];
    if (dim == 3) {
      memcpy(c3, c, sizeof c3), memcpy(a3, a, sizeof a3), memcpy(p4, p, sizeof p4);
    } else {
      p4[0] = cos(0.5 * p[0]), p4[1] = 0, p4[2] = 0, p4[3] = sin(0.5 * p[0]);
    }
    /* OVITO's orientation: x, y, z, w */
    fprintf(f, "X %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", c3[0], c3[1],
            c3[2], a3[0], a3[1], a3[2], p4[1], p4[2], p4[3], p4[0]);
    if (dim == 2) fprintf(f, " %.17g", p[0]);
    fputc('\n', f);
  }
  return finish_beside(f, tmp, fd, path, err, size);
}
