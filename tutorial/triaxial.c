/* SPDX-License-Identifier: BSD-3-Clause */
/* A general triaxial ellipsoid from a quaternion: its quadratic form, its
 * principal axes recovered, and its contact with a second ellipsoid
 * (docs: "Tutorials"). Prints the same lines as tutorial/triaxial.py. */
#include <math.h>
#include <pw85.h>
#include <stdio.h>

static void print_vector(char const *name, double const v[PW85_DIM]) {
  printf("%s = (%.6f, %.6f, %.6f)\n", name, v[0], v[1], v[2]);
}

int main(void) {
  /* E1: semi-axes 3, 2, 1, turned by 40 degrees about the axis
   * (1, 2, 2)/3: p = (cos 20°, sin 20°·(1, 2, 2)/3). */
  double const half = acos(-1.) / 9.; /* 20 degrees */
  double const a1[PW85_DIM] = {3., 2., 1.};
  double const p1[4] = {cos(half), sin(half) / 3., 2. * sin(half) / 3.,
                        2. * sin(half) / 3.};
  /* E2: semi-axes 1.5, 0.5, 0.5, turned by 90 degrees about z. */
  double const a2[PW85_DIM] = {1.5, 0.5, 0.5};
  double const p2[4] = {sqrt(0.5), 0., 0., sqrt(0.5)};
  double const r12[PW85_DIM] = {2., 1.5, 1.}; /* c2 − c1 */

  double q1[PW85_SYM], q2[PW85_SYM];
  int status = pw85_ellipsoid_quaternion(a1, p1, q1);
  if (status == PW85_SUCCESS) status = pw85_ellipsoid_quaternion(a2, p2, q2);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_ellipsoid_quaternion: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("q1 = (%.6f, %.6f, %.6f, %.6f, %.6f, %.6f)\n", q1[0], q1[1], q1[2],
         q1[3], q1[4], q1[5]);

  /* Back to semi-axes (decreasing) and directions (columns of rot). */
  double a[PW85_DIM], rot[PW85_DIM * PW85_DIM];
  status = pw85_principal_axes(q1, a, rot);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_principal_axes: %s\n", pw85_strerror(status));
    return 1;
  }
  double const v0[PW85_DIM] = {rot[0], rot[3], rot[6]};
  print_vector("semi-axes", a);
  print_vector("longest axis along", v0);

  /* μ², λ, the contact point relative to c1 and the normal. */
  double geom[PW85_GEOM_SIZE];
  status = pw85_contact_geometry(r12, q1, q2, geom);
  if (status != PW85_SUCCESS) {
    fprintf(stderr, "pw85_contact_geometry: %s\n", pw85_strerror(status));
    return 1;
  }
  printf("mu^2 = %.6f, lambda = %.6f\n", geom[PW85_GEOM_MU2],
         geom[PW85_GEOM_LAMBDA]);
  print_vector("x - c1", geom + PW85_GEOM_POINT);
  print_vector("n", geom + PW85_GEOM_NORMAL);
  return 0;
}
