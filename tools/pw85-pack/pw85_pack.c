/* SPDX-License-Identifier: BSD-3-Clause */
/* pw85-pack: pack identical ellipsoids in a periodic cube (or, with --2d,
 * ellipses in a periodic square) and write the microstructure (HDF5, its
 * XDMF companion, extended XYZ, a voxel image). What depends on the
 * dimension is in dim.h; the rest is written once.
 * `pw85-pack --help` says how; docs/microstructures.rst is the contract of
 * the files. Exit status: 0 the target reached and the files written; 3
 * stopped early (time limit, jammed or saturated), files written; 130
 * interrupted (SIGINT, SIGTERM), the last certified configuration written;
 * 2 a bad argument (one line naming it, nothing written); 1 any other
 * error (nothing written, or the files as they were). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fenv.h>
#include <float.h>
#include <hdf5.h>
#include <limits.h>
#include <math.h>
#include <pw85/pw85_image.h>
#include <pw85/pw85_index.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "io.h"
#include "pack.h"

/* The methods, by name: the first is the default. */
static struct {
  char const *name;
  pack_method run;
} const methods[] = {{"fire", pack_fire}, {"rsa", pack_rsa}};
enum { method_count = sizeof methods / sizeof methods[0] };

static char const usage[] =
    "Usage: pw85-pack --n N --fraction F --out FILE.h5 [--2d] [options]\n"
    "Pack N identical ellipsoids in a periodic cube of the volume that they fill to\n"
    "the packing fraction F (with --2d: N identical ellipses in a periodic square of\n"
    "the area that they fill to the area fraction F), every pair certified free of\n"
    "overlap by pw85, and write the configuration (HDF5; layout: docs,\n"
    "\"Microstructures for FFT solvers and viewers\"). Where fire stops short of F\n"
    "(time limit, jammed, Ctrl-C), the file holds the larger box of its densest\n"
    "certified configuration and its true packing fraction.\n"
    "\n"
    "  --n N             number of ellipsoids (1 to 100000000)\n"
    "  --axes A,B,C      semi-axes (1e-100 to 1e100, default 1,1,1; with --2d: A,B,\n"
    "                    default 1,1)\n"
    "  --fraction F      target packing fraction, 0 < F < 1 (sets the box)\n"
    "  --2d              ellipses instead (pw85_2d_pack(), the index of ellipses):\n"
    "                    the files in their 2D layout (docs), the XYZ in the plane\n"
    "                    z = 0\n"
    "  --seed S          seed of the random stream (0 to 2^64-1, default 1)\n"
    "  --threads T       threads (1 to 1024, default 1); same result for any T\n"
    "  --out FILE        the HDF5 file to write\n"
    "  --xyz FILE        also an extended XYZ file (OVITO, ASE)\n"
    "  --voxels M        also an M^3 voxel image in FILE (/image) and FILE's\n"
    "                    XDMF companion (ParaView), M from 1 to 4096; with --2d,\n"
    "                    an M^2 image, M from 1 to 65536\n"
    "  --time-limit S    stop packing after S seconds (> 0) and write what is there\n"
    "  --resume FILE     continue the packing in FILE (written by pw85-pack\n"
    "                    --method rsa): its box, axes, seed and method; --n may\n"
    "                    raise the count, and with it the fraction (--fraction,\n"
    "                    if given, must be the one of that box and count); --2d\n"
    "                    for a file of ellipses, only then\n"
    "  --method NAME     packing method: fire (default; pw85_pack(): overlaps\n"
    "                    relaxed by FIRE, dense, jamming) or rsa (random sequential\n"
    "                    addition: fast, saturates at lower fractions, resumable)\n"
    "  --quiet           no progress bar (there is none when stderr is not a terminal)\n"
    "  --help, --version\n"
    "\n"
    "Exit status: 0 done; 3 stopped early (time limit, jammed, saturated), files\n"
    "written; 130 interrupted (Ctrl-C), the last certified configuration written;\n"
    "2 a bad argument (two outputs that name one file among them); 1 another error.\n"
    "Files are written whole or not at all.\n";

static char const *prog = "pw85-pack";

static int bad_argument(char const *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s: ", prog);
  vfprintf(stderr, fmt, ap);
  fprintf(stderr, " (see --help)\n");
  va_end(ap);
  return 2;
}

static int error(char const *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  fprintf(stderr, "%s: ", prog);
  vfprintf(stderr, fmt, ap);
  fputc('\n', stderr);
  va_end(ap);
  return 1;
}

/* ---- arguments ---- */

static int parse_double(char const *s, double *x) {
  char *end;
  errno = 0;
  *x = strtod(s, &end);
  return end != s && *end == '\0' && errno == 0 && isfinite(*x);
}

/* A number that is below 1 as written but 1 once rounded to a double
 * (0.99999999999999999): read again rounding downwards, it is below 1. */
static int rounds_up_to_one(char const *s) {
  int const mode = fegetround();
  fesetround(FE_DOWNWARD);
  double const down = strtod(s, NULL);
  fesetround(mode);
  return down < 1.0;
}

/* The range of the semi-axes: their products (a volume, N of them over the
 * fraction) stay normal doubles, far from underflow (1e-150 made the
 * volume 0, and the fraction of the box 0/0). */
#define AXIS_MIN 1e-100
#define AXIS_MAX 1e100

/* Exactly `count` fields separated by commas, none empty, each a number
 * from AXIS_MIN to AXIS_MAX (strtok would skip empty fields: 1,,1,1 as
 * 1,1,1): 0; -1 if a field is not a number > 0; 1 if it is one outside
 * the range (1e-400 and 1e400 included, which strtod() rounds to 0 and
 * infinity), copied into bad. */
static int parse_axes(char const *s, double *axes, int count, char *bad, size_t bad_size) {
  char buf[256];
  char const *p = s;
  for (int k = 0; k < count; k++) {
    char const *comma = strchr(p, ',');
    size_t const len = comma != NULL ? (size_t)(comma - p) : strlen(p);
    if ((comma != NULL) != (k < count - 1) || len == 0 || len >= sizeof buf) return -1;
    memcpy(buf, p, len);
    buf[len] = '\0';
    char *end;
    errno = 0;
    axes[k] = strtod(buf, &end);
    int const underflow = errno == ERANGE && axes[k] == 0 && !signbit(axes[k]);
    if (end == buf || *end != '\0' || isnan(axes[k]) || !(axes[k] > 0 || underflow))
      return -1;
    if (!(axes[k] >= AXIS_MIN && axes[k] <= AXIS_MAX)) {
      snprintf(bad, bad_size, "%s", buf);
      return 1;
    }
    p = comma != NULL ? comma + 1 : p + len;
  }
  return 0;
}

static int parse_u64(char const *s, uint64_t *x) {
  char *end;
  if (*s == '-' || *s == '+' || *s == ' ' || *s == '\0') return 0;
  errno = 0;
  unsigned long long const v = strtoull(s, &end, 10);
  *x = v;
  return *end == '\0' && errno == 0;
}

struct options {
  size_t n;
  int have_n, have_axes, have_fraction, have_seed;
  double axes[3], fraction, time_limit;
  uint64_t seed;
  int threads, quiet;
  size_t voxels;
  char const *out, *xyz, *resume, *method, *fraction_text, *axes_text, *voxels_text;
  struct dim_ops const *dims; /* &dim_3d, or &dim_2d (--2d) */
};

static int parse(int argc, char **argv, struct options *o) {
  *o = (struct options){.axes = {1, 1, 1}, .seed = 1, .threads = 1, .method = NULL,
                        .dims = &dim_3d};
  for (int i = 1; i < argc; i++) {
    char const *a = argv[i];
    if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
      fputs(usage, stdout);
      exit(0);
    }
    if (strcmp(a, "--version") == 0) {
      printf("pw85-pack (pw85) %s\n", pw85_version());
      exit(0);
    }
    if (strcmp(a, "--quiet") == 0) {
      o->quiet = 1;
      continue;
    }
    if (strcmp(a, "--2d") == 0) {
      o->dims = &dim_2d;
      continue;
    }
    static char const *const with_value[] = {
        "--n", "--axes", "--fraction", "--seed", "--threads", "--out", "--xyz",
        "--voxels", "--time-limit", "--resume", "--method"};
    char const *name = NULL, *v = NULL;
    for (size_t k = 0; k < sizeof with_value / sizeof *with_value; k++) {
      size_t const len = strlen(with_value[k]);
      if (strncmp(a, with_value[k], len) == 0 && (a[len] == '\0' || a[len] == '=')) {
        name = with_value[k];
        if (a[len] == '=') {
          v = a + len + 1;
        } else if (i + 1 < argc) {
          v = argv[++i];
        } else {
          return bad_argument("%s: a value is needed", name);
        }
        break;
      }
    }
    if (name == NULL) return bad_argument("unknown option '%s'", a);
    uint64_t u;
    double x;
    if (strcmp(name, "--n") == 0) {
      if (!parse_u64(v, &u) || u < 1 || u > 100000000)
        return bad_argument("--n: expected an integer from 1 to 100000000, got '%s'", v);
      o->n = (size_t)u, o->have_n = 1;
    } else if (strcmp(name, "--axes") == 0) {
      o->axes_text = v, o->have_axes = 1; /* read below, once --2d is known */
    } else if (strcmp(name, "--fraction") == 0) {
      if (parse_double(v, &x) && x == 1 && rounds_up_to_one(v))
        return bad_argument("--fraction: '%s' is 1 in double precision: expected a number "
                            "between 0 and 1 (excluded)",
                            v);
      if (!parse_double(v, &x) || !(x > 0 && x < 1))
        return bad_argument("--fraction: expected a number between 0 and 1 (excluded), got '%s'",
                            v);
      o->fraction = x, o->have_fraction = 1, o->fraction_text = v;
    } else if (strcmp(name, "--seed") == 0) {
      if (!parse_u64(v, &u))
        return bad_argument("--seed: expected an integer from 0 to 2^64-1, got '%s'", v);
      o->seed = u, o->have_seed = 1;
    } else if (strcmp(name, "--threads") == 0) {
      if (!parse_u64(v, &u) || u < 1 || u > 1024)
        return bad_argument("--threads: expected an integer from 1 to 1024, got '%s'", v);
      o->threads = (int)u;
    } else if (strcmp(name, "--voxels") == 0) {
      o->voxels_text = v; /* read below, once --2d is known */
    } else if (strcmp(name, "--time-limit") == 0) {
      if (!parse_double(v, &x) || !(x > 0))
        return bad_argument("--time-limit: expected a number of seconds > 0, got '%s'", v);
      o->time_limit = x;
    } else if (*v == '\0') {
      return bad_argument("%s: expected a file name, got ''", name);
    } else if (strcmp(name, "--out") == 0) {
      o->out = v;
    } else if (strcmp(name, "--xyz") == 0) {
      o->xyz = v;
    } else if (strcmp(name, "--resume") == 0) {
      o->resume = v;
    } else if (strcmp(name, "--method") == 0) {
      int found = 0;
      for (int k = 0; k < method_count; k++) found |= strcmp(v, methods[k].name) == 0;
      if (!found) return bad_argument("--method: unknown method '%s' (known: fire, rsa)", v);
      o->method = v;
    }
  }
  int const dim = o->dims->dim;
  char bad[256];
  int const axes_status =
      o->axes_text ? parse_axes(o->axes_text, o->axes, dim, bad, sizeof bad) : 0;
  if (axes_status < 0)
    return bad_argument("--axes: expected %s numbers > 0 separated by commas%s, got '%s'",
                        dim == 3 ? "three" : "two", dim == 3 ? "" : " (--2d)", o->axes_text);
  if (axes_status > 0)
    return bad_argument("--axes: %s is outside the range of the semi-axes, 1e-100 to 1e100, "
                        "got '%s'",
                        bad, o->axes_text);
  if (o->voxels_text) {
    /* 4096³ and 65536² int32: 256 GiB and 16 GiB */
    uint64_t const most = dim == 3 ? 4096 : 65536;
    uint64_t u;
    if (!parse_u64(o->voxels_text, &u) || u < 1 || u > most)
      return bad_argument("--voxels: expected an integer from 1 to %llu%s, got '%s'",
                          (unsigned long long)most, dim == 3 ? "" : " (--2d)",
                          o->voxels_text);
    o->voxels = (size_t)u;
  }
  if (o->out == NULL) return bad_argument("--out: the HDF5 file to write is needed");
  if (o->resume && o->method && strcmp(o->method, "rsa") != 0)
    return bad_argument("--resume: only for --method rsa: %s cannot start from a "
                        "configuration",
                        o->method);
  if (o->resume == NULL) {
    if (!o->have_n) return bad_argument("--n: the number of %s is needed", o->dims->shapes);
    if (!o->have_fraction) return bad_argument("--fraction: the target packing fraction is needed");
  }
  return 0;
}

/* ---- progress and signals ---- */

static volatile sig_atomic_t interrupted = 0;
static void on_signal(int sig) { interrupted = sig; }

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

struct progress_state {
  double t0, last_draw, time_limit;
  double unit_volume, box_volume; /* areas in 2D */
  size_t start_count, target;
  int by_steps; /* the method reports phi and steps, not a growing count */
  int bar; /* stderr is a terminal and not --quiet */
  int drawn;
};

/* rsa: fraction from the count, rate in ellipsoids/s, time left at that
 * rate; fire: the certified fraction (pw85_pack_progress.phi), FIRE steps/s,
 * time left from the fraction gained so far (a rough guide: it bisects). */
static void draw_bar(struct progress_state *p, struct pack_state const *st) {
  double const t = now() - p->t0;
  double const target_phi = (double)p->target * p->unit_volume / p->box_volume;
  double const phi = p->by_steps ? st->phi : (double)st->count * p->unit_volume / p->box_volume;
  double const done = fmin(1, phi / target_phi);
  double const rate = t <= 0       ? 0
                      : p->by_steps ? (double)st->steps / t
                                    : (double)(st->count - p->start_count) / t;
  int const width = 30, fill = (int)(done * width);
  char bar[64];
  for (int k = 0; k < width; k++) bar[k] = k < fill ? '#' : '.';
  bar[width] = '\0';
  char left[32] = "?";
  if (p->by_steps && done > 0)
    snprintf(left, sizeof left, "%.0f s", t * (1 - done) / done);
  else if (!p->by_steps && rate > 0)
    snprintf(left, sizeof left, "%.0f s", (double)(p->target - st->count) / rate);
  fprintf(stderr, "\r[%s] %5.1f%% fraction %.4f of %.4f, %.0f%s/s, %s left   ", bar,
          100 * done, phi, target_phi, rate, p->by_steps ? " steps" : "", left);
  fflush(stderr);
  p->drawn = 1;
}

static int on_progress(void *context, struct pack_state const *st) {
  struct progress_state *p = context;
  double const t = now();
  if (p->bar && t - p->last_draw > 0.1) {
    draw_bar(p, st);
    p->last_draw = t;
  }
  if (interrupted) return 1;
  if (p->time_limit > 0 && t - p->t0 >= p->time_limit) return 1;
  return 0;
}

/* ---- main ---- */

static int alloc_state(struct pack_state *st, struct dim_ops const *d, size_t capacity) {
  st->capacity = capacity;
  st->centres = malloc(capacity * (size_t)d->dim * sizeof(double));
  st->forms = malloc(capacity * (size_t)d->sym * sizeof(double));
  st->axes = malloc(capacity * (size_t)d->dim * sizeof(double));
  st->orientations = malloc(capacity * (size_t)d->orient * sizeof(double));
  return st->centres && st->forms && st->axes && st->orientations;
}

static double available_memory(void) {
  long const pages = sysconf(_SC_AVPHYS_PAGES), size = sysconf(_SC_PAGESIZE);
  return pages > 0 && size > 0 ? (double)pages * (double)size : INFINITY;
}

/* The product of the first dim sides of a box: a volume or an area. */
static double box_measure(struct dim_ops const *d, double const *box) {
  double v = box[0] * box[1];
  return d->dim == 3 ? v * box[2] : v;
}

/* What main() allocates, freed by main() on every path. */
static struct pack_state st;
static char *xdmf;
static int32_t *image;

/* --resume: the configuration of the file into st and cf, checked; 0, or
 * the exit status of the error (reported). */
static int resume(struct options const *o, struct pack_config *cf, char *method,
                  size_t method_size) {
  struct dim_ops const *d = o->dims;
  size_t const dim = (size_t)d->dim, sym = (size_t)d->sym, orient = (size_t)d->orient;
  char err[1024];
  struct micro r;
  if (io_read_hdf5(o->resume, &r, err, sizeof err) != 0) return error("--resume: %s", err);
  if (r.dims != d) {
    io_free(&r);
    return r.dims == &dim_2d
               ? bad_argument("--resume: %s holds ellipses (a 2D packing): add --2d", o->resume)
               : bad_argument("--resume: %s holds ellipsoids (a 3D packing): --2d is for "
                              "ellipses",
                              o->resume);
  }
  /* One set of axes, the one of the file (identical ellipsoids). */
  double const *a = r.axes;
  int same = 1;
  for (size_t i = 1; i < r.count; i++) same &= memcmp(r.axes + dim * i, a, dim * sizeof *a) == 0;
  /* The target count of a file: from its count to --n's range. */
  if (r.target < r.count || r.target > IO_MAX_COUNT) {
    io_free(&r);
    return error("--resume: %s: target_count %llu is not from the count of its "
                 "%s (%zu) to %u: a corrupted file",
                 o->resume, (unsigned long long)r.target, d->shapes, r.count, IO_MAX_COUNT);
  }
  if (r.count == 0 || !same) {
    io_free(&r);
    return error("--resume: %s: not a packing of identical %s by pw85-pack", o->resume,
                 d->shapes);
  }
  /* /forms, which are certified, must be the shapes of /axes and
   * /quaternions (/angles), from which the new ones are made: within
   * 16·ε·max aₘ² of pw85_ellipsoid_quaternion()'s (pw85_2d_ellipse()'s)
   * entries (pw85-pack and pypw85 write those, to the bit; another
   * writer's rounding may differ by an ulp or two of the largest, an
   * edited /axes by far more). */
  char const *orientations = d->orient > 1 ? "quaternions" : "angles";
  for (size_t i = 0; i < r.count; i++) {
    double q[6];
    double const *ai = r.axes + dim * i, *fi = r.forms + sym * i;
    int const status = d->form(ai, r.orientations + orient * i, q);
    double big = 0;
    for (size_t k = 0; k < dim; k++) big = fmax(big, ai[k] * ai[k]);
    int match = status == PW85_SUCCESS;
    for (size_t k = 0; k < sym && match; k++) match = fabs(q[k] - fi[k]) <= 16 * DBL_EPSILON * big;
    if (!match) {
      io_free(&r);
      if (status != PW85_SUCCESS)
        return error("--resume: %s: /axes[%zu] and /%s[%zu]: %s", o->resume, i, orientations,
                     i, pw85_strerror(status));
      return error("--resume: %s: /forms[%zu] is not the form of /axes[%zu] and "
                   "/%s[%zu]: a corrupted file",
                   o->resume, i, i, orientations, i);
    }
  }
  if (o->have_axes && memcmp(o->axes, a, dim * sizeof *a) != 0) {
    io_free(&r);
    return bad_argument("--axes: differs from the axes of %s", o->resume);
  }
  if (o->have_seed && o->seed != r.seed) {
    io_free(&r);
    return bad_argument("--seed: differs from the seed of %s (%llu)", o->resume,
                        (unsigned long long)r.seed);
  }
  if (o->method && strcmp(o->method, r.method) != 0) {
    io_free(&r);
    return bad_argument("--method: differs from the method of %s (%s)", o->resume, r.method);
  }
  int known = 0;
  for (int k = 0; k < method_count; k++) known |= strcmp(r.method, methods[k].name) == 0;
  if (!known) {
    io_free(&r);
    return error("--resume: %s: packed by method '%s', unknown here", o->resume, r.method);
  }
  if (strcmp(r.method, "rsa") != 0) {
    io_free(&r);
    return bad_argument("--resume: only for --method rsa: %s was packed by %s, which "
                        "cannot start from a configuration",
                        o->resume, r.method);
  }
  snprintf(method, method_size, "%s", r.method);
  memcpy(cf->axes, a, dim * sizeof *a);
  memcpy(cf->box, r.box, dim * sizeof *a);
  cf->seed = r.seed;
  cf->target = o->have_n ? o->n : r.target;
  if (cf->target < r.count) {
    io_free(&r);
    return bad_argument("--n: %zu is fewer than the %zu %s of %s", o->n, r.count, d->shapes,
                        o->resume);
  }
  /* --fraction, as --axes and --seed: the file's box and the target count
   * set the target fraction; a differing one is refused, not ignored. The
   * same fraction within 16ε (the box of a fresh run, its side rounded,
   * gives back the fraction asked for within 7ε: measured, 200 000 random
   * counts, axes and fractions, 3D and 2D). */
  double const target_phi = (double)cf->target * d->measure(a) / box_measure(d, r.box);
  if (o->have_fraction && !(fabs(o->fraction - target_phi) <= 16 * DBL_EPSILON * target_phi)) {
    io_free(&r);
    return bad_argument("--fraction: %s differs from the target of %s (%zu %s in its box: "
                        "%.6g); with --resume, --n sets the target",
                        o->fraction_text, o->resume, cf->target, d->shapes, target_phi);
  }
  if (!alloc_state(&st, d, cf->target)) {
    io_free(&r);
    return error("out of memory");
  }
  memcpy(st.centres, r.centres, r.count * dim * sizeof(double));
  memcpy(st.forms, r.forms, r.count * sym * sizeof(double));
  memcpy(st.axes, r.axes, r.count * dim * sizeof(double));
  memcpy(st.orientations, r.orientations, r.count * orient * sizeof(double));
  st.count = r.count;
  st.attempts = r.attempts;
  io_free(&r);
  /* Certified again: the file may have been edited. */
  void *index = NULL;
  int status = d->index_create(cf->box, &index);
  if (status == PW85_SUCCESS) {
    size_t pairs = 0;
    for (size_t i = 0; i < st.count && status == PW85_SUCCESS; i++)
      status = d->index_insert(index, i, st.centres + dim * i, st.forms + sym * i);
    if (status == PW85_SUCCESS)
      status = d->index_overlapping_pairs(index, o->threads, 0, NULL, NULL, NULL, &pairs);
    d->index_destroy(index);
    if (status == PW85_SUCCESS && pairs > 0)
      return error("--resume: %s: %zu pairs of %s overlap", o->resume, pairs, d->shapes);
  }
  if (status != PW85_SUCCESS) return error("--resume: %s: %s", o->resume, pw85_strerror(status));
  return 0;
}

static int pack_main(int argc, char **argv) {
  struct options o;
  int const bad = parse(argc, argv, &o);
  if (bad) return bad;
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* errors are reported by us */
  struct dim_ops const *d = o.dims;

  if (o.voxels && !io_xml_name(o.out))
    return bad_argument("--out and --voxels: the name of --out goes into the XDMF "
                        "companion, which XML cannot hold: a control character, or not "
                        "UTF-8");
  if (o.voxels) {
    size_t const len = strlen(o.out);
    xdmf = malloc(len + 6);
    if (xdmf == NULL) return error("out of memory");
    strcpy(xdmf, o.out);
    char *dot = strrchr(xdmf, '.'), *slash = strrchr(xdmf, '/');
    if (dot != NULL && (slash == NULL || dot > slash)) *dot = '\0';
    strcat(xdmf, ".xdmf");
  }
  /* Two outputs (or an output and the file to resume, which only --out may
   * replace) that name one file: the second written would replace the
   * first. */
  if (o.xyz && io_same_file(o.out, o.xyz))
    return bad_argument("--out and --xyz name the same file (%s): give each its own", o.xyz);
  if (xdmf && io_same_file(o.out, xdmf))
    return bad_argument("--out and --voxels name the same file (%s, the XDMF companion of "
                        "--out): give --out another extension, such as .h5",
                        xdmf);
  if (xdmf && o.xyz && io_same_file(o.xyz, xdmf))
    return bad_argument("--xyz and --voxels name the same file (%s, the XDMF companion of "
                        "--out): give --xyz another name",
                        xdmf);
  if (o.resume && o.xyz && io_same_file(o.resume, o.xyz))
    return bad_argument("--xyz and --resume name the same file (%s): the XYZ would replace "
                        "the packing to resume",
                        o.xyz);
  if (o.resume && xdmf && io_same_file(o.resume, xdmf))
    return bad_argument("--voxels and --resume name the same file (%s, the XDMF companion "
                        "of --out): the XDMF would replace the packing to resume",
                        xdmf);

  /* The output directories can be written (before any work). */
  char err[1024];
  if (io_check_writable(o.out, err, sizeof err) != 0) return error("--out: %s", err);
  if (o.xyz && io_check_writable(o.xyz, err, sizeof err) != 0) return error("--xyz: %s", err);
  if (o.voxels) {
    if (io_check_writable(xdmf, err, sizeof err) != 0) return error("--voxels: %s", err);
    double const need = 4.0 * dim_voxels(d, o.voxels);
    double const have = available_memory();
    if (need > have)
      return bad_argument("--voxels %zu: the image needs %.1f GiB, more than the %.1f GiB of "
                          "memory available",
                          o.voxels, need / 1073741824.0, have / 1073741824.0);
  }

  struct pack_config cf = {.dims = d, .threads = o.threads, .seed = o.seed,
                           .time_limit = o.time_limit};
  char method[32];
  snprintf(method, sizeof method, "%s", o.method ? o.method : methods[0].name);
  if (o.resume) {
    int const status = resume(&o, &cf, method, sizeof method);
    if (status != 0) return status;
  } else {
    double const v = d->measure(o.axes);
    double const whole = (double)o.n * v / o.fraction; /* the box's volume (area) */
    if (!isfinite(whole))
      return bad_argument("--n, --axes and --fraction: %zu %s of semi-axes %s at %s need a "
                          "box whose %s is beyond the range of a double",
                          o.n, d->shapes,
                          o.axes_text ? o.axes_text : d->dim == 3 ? "1,1,1" : "1,1",
                          o.fraction_text, d->dim == 3 ? "volume" : "area");
    double const side = d->dim == 3 ? cbrt(whole) : sqrt(whole);
    double const box[3] = {side, side, side};
    /* The packing fraction of the box as the methods compute it (pack.h:
     * from the sides): rounding can take it to 1 or beyond near 1, where
     * pw85_pack() refuses it with a generic PW85_EINVAL. */
    double const filled = (double)o.n * v / box_measure(d, box);
    if (!(filled < 1.0))
      return bad_argument("--fraction: %s with %zu %s gives a box that they would "
                          "fill to %.17g once its side is rounded: ask for less",
                          o.fraction_text, o.n, d->shapes, filled);
    double widest = 0;
    for (int k = 0; k < d->dim; k++) widest = fmax(widest, o.axes[k]);
    /* the side rule of pw85_index.h; fire's (pw85_pack.h) is 2⁻⁹ */
    double const margin = strcmp(method, "fire") == 0 ? 0x1p-9 : 0x1p-19;
    if (!(2.0 * widest * (1.0 + margin) < side))
      return bad_argument("--n: %zu %s give a box of side %.6g, not wider than an "
                          "%s (%.6g): ask for more",
                          o.n, d->shapes, side, d->dim == 3 ? "ellipsoid" : "ellipse",
                          2 * widest);
    memcpy(cf.axes, o.axes, sizeof cf.axes);
    memcpy(cf.box, box, sizeof cf.box);
    cf.target = o.n;
    if (!alloc_state(&st, d, cf.target)) return error("out of memory");
  }
  pack_method run = methods[0].run;
  for (int k = 0; k < method_count; k++)
    if (strcmp(method, methods[k].name) == 0) run = methods[k].run;

  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);

  double const unit_volume = d->measure(cf.axes);
  double const box_volume = box_measure(d, cf.box);
  struct progress_state ps = {.t0 = now(), .time_limit = o.time_limit,
                              .unit_volume = unit_volume, .box_volume = box_volume,
                              .start_count = st.count, .target = cf.target,
                              .by_steps = run == pack_fire,
                              .bar = !o.quiet && isatty(STDERR_FILENO)};
  int const outcome = run(&cf, &st, on_progress, &ps);
  if (ps.bar) {
    draw_bar(&ps, &st);
    fputc('\n', stderr);
  }
  if (outcome < 0) return error("packing: %s", pw85_strerror(-outcome));

  /* Ctrl-C from here on: the files are being written; finish them. */
  struct micro m = {.dims = d, .count = st.count, .centres = st.centres, .forms = st.forms,
                    .axes = st.axes, .orientations = st.orientations, .seed = cf.seed,
                    .attempts = st.attempts, .target = cf.target};
  /* the box of the configuration (fire short of the target: larger) */
  memcpy(m.box, st.box, sizeof m.box);
  m.packing_fraction = (double)st.count * unit_volume / box_measure(d, st.box);
  snprintf(m.method, sizeof m.method, "%s", method);
  snprintf(m.pw85_version, sizeof m.pw85_version, "%s", pw85_version());
  if (o.voxels) {
    size_t const n = o.voxels;
    image = malloc((size_t)dim_voxels(d, n) * sizeof *image);
    if (image == NULL)
      return error("--voxels %zu: cannot allocate the image (%.1f GiB)", n,
                   4.0 * dim_voxels(d, n) / 1073741824.0);
    int const status = d->image(st.count, st.centres, st.forms, st.box, n, image, o.threads,
                                &m.image_fraction);
    if (status != PW85_SUCCESS) return error("--voxels: %s", pw85_strerror(status));
    m.image = image;
    m.side = n;
  }
  if (io_write_hdf5(o.out, &m, err, sizeof err) != 0) return error("--out: %s", err);
  if (xdmf && io_write_xdmf(xdmf, o.out, &m, err, sizeof err) != 0)
    return error("--voxels: %s", err);
  if (o.xyz && io_write_xyz(o.xyz, &m, err, sizeof err) != 0) return error("--xyz: %s", err);

  char const *how = outcome == PACK_DONE ? "done"
                    : interrupted        ? "interrupted"
                    : outcome == PACK_SATURATED
                        ? (run == pack_fire
                               ? "jammed (the target is beyond jamming for fire)"
                               : "saturated (10^6 candidates in a row rejected)")
                        : "time limit reached";
  fprintf(stderr, "%s: %s: %zu of %zu %s, packing fraction %.6f, written to %s\n", prog, how,
          st.count, cf.target, d->shapes, m.packing_fraction, o.out);
  if (interrupted) return 130;
  return outcome == PACK_DONE ? 0 : 3;
}

int main(int argc, char **argv) {
  int const status = pack_main(argc, argv);
  free(image), free(xdmf);
  free(st.centres), free(st.forms), free(st.axes), free(st.orientations);
  return status;
}
