/* SPDX-License-Identifier: BSD-3-Clause */
/* Two ellipses (pw85_2d.h): their quadratic forms from semi-axes and
 * angles, the semi-axes and angle back, the contact function, the contact
 * point and normal, the force and torques of a pair energy, and the
 * overlap test along a line in one batch call (docs: "Ellipses"). Prints
 * the same lines as tutorial/ellipses.py. */
#include <math.h>
#include <pw85/pw85_2d.h>
#include <stdio.h>

static int fail(char const *call, int status) {
  fprintf(stderr, "%s: %s\n", call, pw85_strerror(status));
  return 1;
}

int main(void) {
  double const deg = acos(-1.) / 180.;
  /* E1: semi-axes 2 and 0.5, the long one at 30 degrees from x; E2:
   * semi-axes 1.2 and 0.6, at -45 degrees; centres c1 = 0, c2 = (3, 1.5). */
  double const a1[PW85_2D_DIM] = {2., 0.5}, a2[PW85_2D_DIM] = {1.2, 0.6};
  double const r12[PW85_2D_DIM] = {3., 1.5}; /* c2 − c1 */
  double q1[PW85_2D_SYM], q2[PW85_2D_SYM];
  int status = pw85_2d_ellipse(a1, 30. * deg, q1);
  if (status != PW85_SUCCESS) return fail("pw85_2d_ellipse", status);
  status = pw85_2d_ellipse(a2, -45. * deg, q2);
  if (status != PW85_SUCCESS) return fail("pw85_2d_ellipse", status);
  printf("q1 = (%.6f, %.6f, %.6f)\n", q1[0], q1[1], q1[2]);
  printf("q2 = (%.6f, %.6f, %.6f)\n", q2[0], q2[1], q2[2]);

  /* Back to the semi-axes (decreasing) and the angle of the first. */
  double a[PW85_2D_DIM], theta;
  status = pw85_2d_principal_axes(q2, a, &theta);
  if (status != PW85_SUCCESS) return fail("pw85_2d_principal_axes", status);
  printf("E2: semi-axes (%.6f, %.6f), angle %.6f degrees\n", a[0], a[1],
         theta / deg);

  /* μ², λ, the contact point relative to c1, the normal, and the
   * derivatives of μ². */
  double g[PW85_2D_GEOM_SIZE], d[PW85_2D_DERIV_SIZE];
  status = pw85_2d_contact_derivatives(r12, q1, q2, g, d);
  if (status != PW85_SUCCESS)
    return fail("pw85_2d_contact_derivatives", status);
  printf("mu^2 = %.6f, lambda = %.6f: %s\n", g[PW85_2D_GEOM_MU2],
         g[PW85_2D_GEOM_LAMBDA],
         g[PW85_2D_GEOM_MU2] < 1. ? "they overlap" : "they are disjoint");
  printf("x - c1 = (%.6f, %.6f)\n", g[PW85_2D_GEOM_POINT],
         g[PW85_2D_GEOM_POINT + 1]);
  printf("n = (%.6f, %.6f)\n", g[PW85_2D_GEOM_NORMAL],
         g[PW85_2D_GEOM_NORMAL + 1]);
  /* A pair energy U = (1 − μ²)² for μ² < 1 (U′ = −2(1 − μ²)), at
   * r12/2, where they overlap: the force on E2 is −U′·∂μ²/∂r12, the
   * torque on Ei is −U′·∂μ²/∂θi. */
  double const half[PW85_2D_DIM] = {r12[0] / 2., r12[1] / 2.};
  status = pw85_2d_contact_derivatives(half, q1, q2, g, d);
  if (status != PW85_SUCCESS)
    return fail("pw85_2d_contact_derivatives", status);
  double const du = -2. * (1. - g[PW85_2D_GEOM_MU2]);
  printf("at r12/2: mu^2 = %.6f, force on E2 = (%.6f, %.6f), torques "
         "%.6f, %.6f\n",
         g[PW85_2D_GEOM_MU2], -du * d[PW85_2D_DERIV_R12],
         -du * d[PW85_2D_DERIV_R12 + 1], -du * d[PW85_2D_DERIV_THETA1],
         -du * d[PW85_2D_DERIV_THETA2]);

  /* E2 moved along r12, c2 = t·r12 for t = 0.25, 0.5, ..., 1.5: one batch
   * call, q1 and q2 the same for every pair (stride 0). */
  enum { N = 6 };
  double r[2 * N];
  int result[N];
  for (int i = 0; i < N; i++) {
    r[2 * i] = 0.25 * (i + 1) * r12[0];
    r[2 * i + 1] = 0.25 * (i + 1) * r12[1];
  }
  status = pw85_2d_overlap_batch(N, r, PW85_2D_DIM, q1, 0, q2, 0, result,
                                 NULL, 1);
  if (status != PW85_SUCCESS) return fail("pw85_2d_overlap_batch", status);
  printf("overlap at t = 0.25, 0.5, ..., 1.5:");
  for (int i = 0; i < N; i++) printf(" %+d", result[i]);
  printf("\n");
  return 0;
}
