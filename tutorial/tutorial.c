/* SPDX-License-Identifier: BSD-3-Clause */
/* Do two spheroids overlap? The C tutorial (seed chapter 2.2). */
#include <pw85.h>
#include <stdio.h>

int main(void) {
  /* E1: oblate spheroid centred at x1, radii a1 (equatorial), c1 (polar),
   * axis n1. E2: prolate spheroid centred at x2. */
  double const x1[PW85_DIM] = {-0.5, 0.4, -0.7};
  double const n1[PW85_DIM] = {0., 0., 1.};
  double const a1 = 10.;
  double const c1 = 0.1;

  double const x2[PW85_DIM] = {0.2, -0.3, 0.4};
  double const n2[PW85_DIM] = {1., 0., 0.};
  double const a2 = 0.5;
  double const c2 = 5.;

  double r12[PW85_DIM];
  for (int i = 0; i < PW85_DIM; i++) r12[i] = x2[i] - x1[i];

  double q1[PW85_SYM], q2[PW85_SYM];
  pw85_spheroid(a1, c1, n1, q1);
  pw85_spheroid(a2, c2, n2, q2);

  double out[2];
  int const status = pw85_contact_function(r12, q1, q2, out);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_contact_function: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("mu^2 = %g\n", out[0]);
  printf("lambda = %g\n", out[1]);
  return 0;
}
