/* SPDX-License-Identifier: BSD-3-Clause */
/* Compiled as C (several standards, -Werror -pedantic): pw85.h and
 * pw85_index.h stand alone, twice included, and their prototypes accept
 * const arrays. */
#include <pw85/pw85_index.h>
#include <pw85/pw85_index.h>
#include <pw85/pw85.h>
#include <pw85/pw85.h>
#include <pw85.h>

int main(void) {
  double const r[PW85_DIM] = {1., 0., 0.};
  double const q[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double out[2];
  pw85_index *index = NULL;
  size_t count = 1;
  if (pw85_index_create(NULL, &index) != PW85_SUCCESS ||
      pw85_index_insert(index, 0, r, q) != PW85_SUCCESS ||
      pw85_index_pairs_within(index, 1., 1, 0, NULL, NULL, NULL, &count) !=
          PW85_SUCCESS || count != 0)
    return 1;
  pw85_index_destroy(index);
  return pw85_contact_function(r, q, q, out) == PW85_SUCCESS ? 0 : 1;
}
