# SPDX-License-Identifier: BSD-3-Clause
"""A general triaxial ellipsoid from a quaternion: its quadratic form, its
principal axes recovered, and its contact with a second ellipsoid (docs:
"Tutorials"). Prints the same lines as tutorial/triaxial.c."""

import math

import pypw85


def print_vector(name, v):
    print("%s = (%.6f, %.6f, %.6f)" % (name, v[0], v[1], v[2]))


# E1: semi-axes 3, 2, 1, turned by 40 degrees about the axis (1, 2, 2)/3:
# p = (cos 20°, sin 20°·(1, 2, 2)/3).
half = math.acos(-1.0) / 9.0  # 20 degrees
a1 = [3.0, 2.0, 1.0]
p1 = [math.cos(half), math.sin(half) / 3.0, 2.0 * math.sin(half) / 3.0,
      2.0 * math.sin(half) / 3.0]
# E2: semi-axes 1.5, 0.5, 0.5, turned by 90 degrees about z.
a2 = [1.5, 0.5, 0.5]
p2 = [math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)]
r12 = [2.0, 1.5, 1.0]  # c2 − c1

q1 = pypw85.ellipsoid_quaternion(a1, p1)
q2 = pypw85.ellipsoid_quaternion(a2, p2)
print("q1 = (%s)" % ", ".join("%.6f" % x for x in q1))

# Back to semi-axes (decreasing) and directions (columns of rot).
a, rot = pypw85.principal_axes(q1)
print_vector("semi-axes", a)
print_vector("longest axis along", rot[:, 0])

# μ², λ, the contact point relative to c1 and the normal.
geometry = pypw85.contact_geometry(r12, q1, q2)
print("mu^2 = %.6f, lambda = %.6f" % (geometry[pypw85.GEOM_MU2],
                                      geometry[pypw85.GEOM_LAMBDA]))
print_vector("x - c1", geometry[pypw85.GEOM_POINT:pypw85.GEOM_POINT + 3])
print_vector("n", geometry[pypw85.GEOM_NORMAL:pypw85.GEOM_NORMAL + 3])
