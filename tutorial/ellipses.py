# SPDX-License-Identifier: BSD-3-Clause
"""Two ellipses (pypw85.d2): their quadratic forms from semi-axes and
angles, the semi-axes and angle back, the contact function, the contact
point and normal, the force and torques of a pair energy, and the overlap
test along a line on an array of pairs (docs: "Ellipses"). Prints the same
lines as tutorial/ellipses.c."""

import math

import numpy as np

from pypw85 import d2

deg = math.acos(-1.0) / 180.0
# E1: semi-axes 2 and 0.5, the long one at 30 degrees from x; E2: semi-axes
# 1.2 and 0.6, at -45 degrees; centres c1 = 0, c2 = (3, 1.5).
q1 = d2.ellipse([2.0, 0.5], 30.0 * deg)
q2 = d2.ellipse([1.2, 0.6], -45.0 * deg)
r12 = np.array([3.0, 1.5])  # c2 − c1
print("q1 = (%.6f, %.6f, %.6f)" % tuple(q1))
print("q2 = (%.6f, %.6f, %.6f)" % tuple(q2))

# Back to the semi-axes (decreasing) and the angle of the first.
a, theta = d2.principal_axes(q2)
print("E2: semi-axes (%.6f, %.6f), angle %.6f degrees"
      % (a[0], a[1], theta / deg))

# μ², λ, the contact point relative to c1, the normal, and the derivatives
# of μ².
g, d = d2.contact_derivatives(r12, q1, q2)
mu2 = g[d2.GEOM_MU2]
print("mu^2 = %.6f, lambda = %.6f: %s"
      % (mu2, g[d2.GEOM_LAMBDA],
         "they overlap" if mu2 < 1.0 else "they are disjoint"))
print("x - c1 = (%.6f, %.6f)" % tuple(g[d2.GEOM_POINT:d2.GEOM_POINT + 2]))
print("n = (%.6f, %.6f)" % tuple(g[d2.GEOM_NORMAL:d2.GEOM_NORMAL + 2]))
# A pair energy U = (1 − μ²)² for μ² < 1 (U′ = −2(1 − μ²)), at r12/2,
# where they overlap: the force on E2 is −U′·∂μ²/∂r12, the torque on Ei is
# −U′·∂μ²/∂θi.
g, d = d2.contact_derivatives(r12 / 2.0, q1, q2)
du = -2.0 * (1.0 - g[d2.GEOM_MU2])
force = -du * d[d2.DERIV_R12:d2.DERIV_R12 + 2]
print("at r12/2: mu^2 = %.6f, force on E2 = (%.6f, %.6f), torques "
      "%.6f, %.6f" % (g[d2.GEOM_MU2], force[0], force[1],
                      -du * d[d2.DERIV_THETA1], -du * d[d2.DERIV_THETA2]))

# E2 moved along r12, c2 = t·r12 for t = 0.25, 0.5, ..., 1.5: one call on
# an array of pairs (q1 and q2 broadcast to every pair).
t = 0.25 * np.arange(1, 7)
result = d2.overlap(t[:, None] * r12, q1, q2)
print("overlap at t = 0.25, 0.5, ..., 1.5: %s"
      % " ".join("%+d" % x for x in result))
