# SPDX-License-Identifier: BSD-3-Clause
"""Two overlapping ellipsoids pushed apart until they touch.

Steepest descent on the pair energy u = (1 − μ)², with the forces and
torques of pypw85.contact_derivatives (docs: "Contact geometry, forces and
torques"); the same computation as tutorial/contact_descent.c, which prints
the same lines. Exits with status 1 if u fails to decrease at a step, if
the ellipsoids do not touch within MAX_STEPS, or if pypw85.overlap
disagrees with the final μ².
"""

import math
import sys

import numpy as np

import pypw85

# Stop when |μ² − 1| <= TOL; the mobilities ETA_X (a squared length) and
# ETA_R (dimensionless): see contact_descent.c.
TOL = 1e-12
MAX_STEPS = 50
ETA_X = 0.2
ETA_R = 0.2


def quat_mul(p, q):
    """The quaternion product p·q, quaternions (w, x, y, z)."""
    return np.array([p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
                     p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
                     p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
                     p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0]])


def turn(p, w):
    """The orientation p turned about the centre by the rotation vector w."""
    t = math.sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2])
    if t == 0.0:
        return p
    s = math.sin(0.5 * t) / t
    return quat_mul([math.cos(0.5 * t), s * w[0], s * w[1], s * w[2]], p)


# Semi-axes, orientations (unit quaternions) and centres.
a1 = [2.0, 1.0, 0.5]
a2 = [1.5, 1.0, 0.4]
p1 = np.array([0.8, 0.4, -0.4, 0.2])
p2 = np.array([0.5, -0.5, 0.5, 0.5])
c1 = np.array([0.0, 0.0, 0.0])
c2 = np.array([0.8, 0.4, 0.2])

u_prev = math.inf
for step in range(MAX_STEPS + 1):
    r12 = c2 - c1
    q1 = pypw85.ellipsoid_quaternion(a1, p1)
    q2 = pypw85.ellipsoid_quaternion(a2, p2)
    geometry, d = pypw85.contact_derivatives(r12, q1, q2)
    mu2 = geometry[pypw85.GEOM_MU2]
    mu = math.sqrt(mu2)
    u = (1.0 - mu) * (1.0 - mu)
    print("%2d  mu^2 = %.12f" % (step, mu2))
    if not u < u_prev:
        sys.exit("step %d: u = %g did not decrease" % (step, u))
    if abs(mu2 - 1.0) <= TOL:
        break
    u_prev = u

    # du/dμ² = −(1 − μ)/μ. Force on ellipsoid 2: −(du/dμ²)·∂μ²/∂r12, the
    # opposite on ellipsoid 1; torque on ellipsoid i: −(du/dμ²)·∂μ²/∂ωᵢ.
    du = -(1.0 - mu) / mu
    force2 = -du * d[pypw85.DERIV_R12:pypw85.DERIV_R12 + 3]
    c1 = c1 - ETA_X * force2
    c2 = c2 + ETA_X * force2
    p1 = turn(p1, ETA_R * (-du * d[pypw85.DERIV_ROT1:pypw85.DERIV_ROT1 + 3]))
    p2 = turn(p2, ETA_R * (-du * d[pypw85.DERIV_ROT2:pypw85.DERIV_ROT2 + 3]))
else:
    sys.exit("no contact after %d steps" % MAX_STEPS)

# The certified test must agree: tangent within 4 ulps of 1, else the sign
# of μ² − 1.
expected = (0 if abs(mu2 - 1.0) <= 4 * np.finfo(float).eps
            else -1 if mu2 < 1.0 else 1)
overlap = pypw85.overlap(r12, q1, q2)
if overlap != expected:
    sys.exit("pypw85.overlap: %d, expected %d" % (overlap, expected))
print("in contact after %d steps: |mu^2 - 1| <= %g" % (step, TOL))
