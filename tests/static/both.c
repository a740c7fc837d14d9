/* SPDX-License-Identifier: BSD-3-Clause */
/* Calls libpw85 and libpw85_legacy, to be linked with both archives: they
 * define nothing twice, and both answer. Exit status 0 if the two contact
 * functions agree to 1e-10 on a pair of moderate spheroids. */
#include <math.h>
#include <pw85_legacy.h>
#include <stdio.h>

int main(void) {
  double const n1[PW85_DIM] = {0., 0., 1.}, n2[PW85_DIM] = {1., 0., 0.};
  double const r12[PW85_DIM] = {1., 2., 3.};
  double q1[PW85_SYM], q2[PW85_SYM], exact[2], legacy[2];
  pw85_spheroid(1., 2., n1, q1);
  pw85_spheroid(2., 0.5, n2, q2);
  int const s1 = pw85_contact_function(r12, q1, q2, exact);
  int const s2 = pw85_legacy_contact_function1(r12, q1, q2, legacy);
  printf("pw85: %d, mu^2 = %.17g; pw85_legacy: %d, mu^2 = %.17g\n", s1,
         exact[0], s2, legacy[0]);
  return s1 == PW85_SUCCESS && s2 == PW85_SUCCESS &&
                 fabs(exact[0] - legacy[0]) <= 1e-10 * exact[0]
             ? 0
             : 1;
}
