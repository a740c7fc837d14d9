/* SPDX-License-Identifier: BSD-3-Clause */
/* The index's image vectors, formed exactly (pw85_index.h, "Images"):
 * periodic pairs whose r = (c_j + n∘L) − c_i is not a double, with centres
 * up to 2²⁹·L, against references computed at high precision for the exact
 * configuration (data/pw85_index_images.txt, data/gen_index_images.py; no
 * value from this library). pw85_index_within() must report the reference
 * μ², bit for bit, through the shift n; pw85_index_overlap_any() and
 * pw85_index_overlapping_pairs() must decide as its sign of μ² − 1 where
 * |μ² − 1| > 4ε (the band where pw85_overlap() may answer 0). The file is
 * named by PW85_INDEX_IMAGES (tests/meson.build). */
#include <pw85/pw85_index.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

typedef struct {
  double box[3], ci[3], qi[6], cj[3], qj[6];
  int n[3];
  double mu2;
} Image;

/* The records of the file; *count of them. */
static Image *read_images(const char *path, size_t *count) {
  gchar *text = NULL;
  GError *error = NULL;
  if (!g_file_get_contents(path, &text, NULL, &error))
    g_error("%s: %s", path, error->message);
  gchar **lines = g_strsplit(text, "\n", -1);
  GArray *out = g_array_new(FALSE, FALSE, sizeof(Image));
  for (gchar **l = lines; *l != NULL; l++) {
    if (**l == '#' || **l == '\0') continue;
    Image im;
    double *fields[] = {im.box, im.ci, im.qi, im.cj, im.qj};
    int const sizes[] = {3, 3, 6, 3, 6};
    char *p = *l, *end = NULL;
    for (int f = 0; f < 5; f++)
      for (int k = 0; k < sizes[f]; k++, p = end) {
        fields[f][k] = strtod(p, &end);
        g_assert_true(end != p);
      }
    for (int k = 0; k < 3; k++, p = end) {
      im.n[k] = (int)strtol(p, &end, 10);
      g_assert_true(end != p);
    }
    im.mu2 = strtod(p, &end);
    g_assert_true(end != p);
    g_array_append_val(out, im);
  }
  g_strfreev(lines);
  g_free(text);
  *count = out->len;
  return (Image *)g_array_free(out, FALSE);
}

/* The decision that pw85_overlap() would make on the exact μ²: −1, +1, or
 * 2 inside the 4-ulp band (either answer, or 0, is then right). */
static int expected_decision(double mu2) {
  if (fabs(mu2 - 1.) <= 4. * DBL_EPSILON) return 2;
  return mu2 < 1. ? -1 : 1;
}

static void test_images(void) {
  const char *path = g_getenv("PW85_INDEX_IMAGES");
  g_assert_nonnull(path);
  size_t count = 0;
  Image *images = read_images(path, &count);
  g_assert_cmpuint(count, >=, 100);
  int inexact = 0, decided = 0;
  for (size_t k = 0; k < count; k++) {
    Image const *im = images + k;
    /* The double image vector, as a brute force would form it. */
    double r[3];
    for (int d = 0; d < 3; d++) r[d] = (im->cj[d] + im->n[d] * im->box[d]) - im->ci[d];
    double rounded[2];
    g_assert_cmpint(pw85_contact_function(r, im->qi, im->qj, rounded), ==, PW85_SUCCESS);
    inexact += rounded[0] != im->mu2;

    pw85_index *ix = NULL;
    g_assert_cmpint(pw85_index_create(im->box, &ix), ==, PW85_SUCCESS);
    g_assert_cmpint(pw85_index_insert(ix, 3, im->cj, im->qj), ==, PW85_SUCCESS);
    size_t ids[16], n = 0;
    int shifts[3 * 16];
    double ml[2 * 16];
    g_assert_cmpint(pw85_index_within(ix, im->ci, im->qi, 4., PW85_INDEX_NO_ID, 16, ids,
                                      shifts, ml, &n), ==, PW85_SUCCESS);
    gboolean found = FALSE;
    for (size_t a = 0; a < MIN(n, (size_t)16); a++) {
      if (memcmp(shifts + 3 * a, im->n, sizeof im->n) != 0) continue;
      found = TRUE;
      if (ml[2 * a] != im->mu2)
        test_mismatch("record %zu: within reports mu2 %a, exact configuration %a "
                      "(rounded r gives %a)", k, ml[2 * a], im->mu2, rounded[0]);
    }
    if (!found) test_mismatch("record %zu: within misses the image", k);

    int const want = expected_decision(im->mu2);
    int result = 9;
    size_t id = 0;
    g_assert_cmpint(pw85_index_overlap_any(ix, im->ci, im->qi, PW85_INDEX_NO_ID, &result,
                                           &id), ==, PW85_SUCCESS);
    /* The candidate as a stored ellipsoid: the pair (3, 5, −n) seen from 3,
     * or (3, 5, n) from the candidate's side when ids are swapped. */
    g_assert_cmpint(pw85_index_insert(ix, 5, im->ci, im->qi), ==, PW85_SUCCESS);
    size_t np = 0, pid[2 * 4];
    int psh[3 * 4], pres[4];
    g_assert_cmpint(pw85_index_overlapping_pairs(ix, 1, 4, pid, psh, pres, &np), ==,
                    PW85_SUCCESS);
    int const pair_result = np == 0 ? 1 : pres[0];
    if (want != 2) {
      decided++;
      if (result != want || pair_result != want)
        test_mismatch("record %zu: mu2 %a: overlap_any %d, overlapping_pairs %d, "
                      "expected %d", k, im->mu2, result, pair_result, want);
    }
    pw85_index_destroy(ix);
  }
  g_test_message("%zu records, %d where the rounded r gives another mu2, %d decided "
                 "outside the 4-ulp band", count, inexact, decided);
  /* The records exercise what they are for. */
  g_assert_cmpint(inexact, >, (int)count / 4);
  g_assert_cmpint(decided, >, (int)count / 2);
  g_free(images);
}

int main(int argc, char **argv) {
  g_test_init(&argc, &argv, NULL);
  install_failing_gsl_handler();
  g_test_add_func("/pw85/index/exact-images", test_images);
  return g_test_run();
}
