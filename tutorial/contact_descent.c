/* SPDX-License-Identifier: BSD-3-Clause */
/* Two overlapping ellipsoids pushed apart until they touch: steepest descent
 * on the pair energy u = (1 − μ)², with the forces and torques that
 * pw85_contact_derivatives() gives (docs: "Contact geometry, forces and
 * torques"). Prints μ² at every step; exits with status 1 if u fails to
 * decrease at a step, if the ellipsoids do not touch within MAX_STEPS, or
 * if pw85_overlap() disagrees with the final μ². */
#include <float.h>
#include <math.h>
#include <pw85.h>
#include <stdio.h>

/* Stop when |μ² − 1| ≤ TOL. The gap (or overlap) left is then about
 * TOL/2 of the size of the ellipsoids, and TOL is 4500 ulps of 1, far
 * above the rounding of μ² (correctly rounded, to half an ulp): the test
 * is never decided by rounding noise. */
#define TOL 1e-12
#define MAX_STEPS 50
/* Mobilities: a step moves each centre by ETA_X·force (a squared length,
 * here for semi-axes of order 1) and turns each ellipsoid by the rotation
 * vector ETA_R·torque (radians): small enough for the first-order model of
 * μ² to hold at every step, so that u decreases; large enough to gain
 * about a decade per step. */
#define ETA_X 0.2
#define ETA_R 0.2

/* out = p·q, quaternions (w, x, y, z). */
static void quat_mul(double const p[4], double const q[4], double out[4]) {
  out[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
  out[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
  out[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1];
  out[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0];
}

/* Turns the orientation p about the centre by the rotation vector w. */
static void turn(double p[4], double const w[3]) {
  double const t = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  if (t == 0.) return;
  double const s = sin(0.5 * t) / t;
  double const dp[4] = {cos(0.5 * t), s * w[0], s * w[1], s * w[2]};
  double const old[4] = {p[0], p[1], p[2], p[3]};
  quat_mul(dp, old, p);
}

int main(void) {
  /* Semi-axes, orientations (unit quaternions) and centres. */
  double const a1[PW85_DIM] = {2., 1., 0.5};
  double const a2[PW85_DIM] = {1.5, 1., 0.4};
  double p1[4] = {0.8, 0.4, -0.4, 0.2};
  double p2[4] = {0.5, -0.5, 0.5, 0.5};
  double c1[PW85_DIM] = {0., 0., 0.};
  double c2[PW85_DIM] = {0.8, 0.4, 0.2};

  double q1[PW85_SYM], q2[PW85_SYM], r12[PW85_DIM];
  double geom[PW85_GEOM_SIZE], d[PW85_DERIV_SIZE];
  double u_prev = INFINITY, mu2 = 0.;
  int step;
  for (step = 0; step <= MAX_STEPS; step++) {
    for (int i = 0; i < PW85_DIM; i++) r12[i] = c2[i] - c1[i];
    int err = pw85_ellipsoid_quaternion(a1, p1, q1);
    if (err == PW85_SUCCESS) err = pw85_ellipsoid_quaternion(a2, p2, q2);
    if (err == PW85_SUCCESS)
      err = pw85_contact_derivatives(r12, q1, q2, geom, d);
    if (err != PW85_SUCCESS) {
      fprintf(stderr, "step %d: %s\n", step, pw85_strerror(err));
      return 1;
    }
    mu2 = geom[PW85_GEOM_MU2];
    double const mu = sqrt(mu2);
    double const u = (1. - mu) * (1. - mu);
    printf("%2d  mu^2 = %.12f\n", step, mu2);
    if (!(u < u_prev)) {
      fprintf(stderr, "step %d: u = %g did not decrease\n", step, u);
      return 1;
    }
    if (fabs(mu2 - 1.) <= TOL) break;
    u_prev = u;

    /* du/dμ² = −(1 − μ)/μ. Force on ellipsoid 2: −(du/dμ²)·∂μ²/∂r12,
     * the opposite on ellipsoid 1; torque on ellipsoid i:
     * −(du/dμ²)·∂μ²/∂ωᵢ. */
    double const du = -(1. - mu) / mu;
    double w1[PW85_DIM], w2[PW85_DIM];
    for (int i = 0; i < PW85_DIM; i++) {
      double const force2 = -du * d[PW85_DERIV_R12 + i];
      c1[i] -= ETA_X * force2;
      c2[i] += ETA_X * force2;
      w1[i] = ETA_R * (-du * d[PW85_DERIV_ROT1 + i]);
      w2[i] = ETA_R * (-du * d[PW85_DERIV_ROT2 + i]);
    }
    turn(p1, w1);
    turn(p2, w2);
  }
  if (step > MAX_STEPS) {
    fprintf(stderr, "no contact after %d steps\n", MAX_STEPS);
    return 1;
  }

  /* The certified test must agree: tangent within 4 ulps of 1, else the
   * sign of μ² − 1. */
  int overlap, expected = mu2 < 1. ? -1 : 1;
  if (fabs(mu2 - 1.) <= 4. * DBL_EPSILON) expected = 0;
  if (pw85_overlap(r12, q1, q2, &overlap) != PW85_SUCCESS) return 1;
  if (overlap != expected) {
    fprintf(stderr, "pw85_overlap: %d, expected %d\n", overlap, expected);
    return 1;
  }
  printf("in contact after %d steps: |mu^2 - 1| <= %g\n", step, TOL);
  return 0;
}
