/* SPDX-License-Identifier: BSD-3-Clause */
/* Compiled as C (several standards, -Werror -pedantic): pw85.h stands alone,
 * twice included, and its prototypes accept const arrays. */
#include <pw85/pw85.h>
#include <pw85/pw85.h>
#include <pw85.h>

int main(void) {
  double const r[PW85_DIM] = {1., 0., 0.};
  double const q[PW85_SYM] = {1., 0., 0., 1., 0., 1.};
  double out[2];
  return pw85_contact_function(r, q, q, out) == PW85_SUCCESS ? 0 : 1;
}
