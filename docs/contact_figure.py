# SPDX-License-Identifier: BSD-3-Clause
"""Draw the figure of docs/geometry.rst: two ellipsoids, the same scaled by
μ, their contact point and the common normal, computed by pypw85.

    contact_figure.py OUTPUT.svg

Run by docs/meson.build at build time (pypw85 from the source tree, libpw85
of the build, as the tests). Both ellipsoids have a principal axis along z
and their centres in the plane z = 0, so that s = Q(λ)⁻¹·r12, hence the
contact point and the normal, lie in that plane: the plane section is
exact, not a projection. The section of an ellipsoid of form Q by z = 0 is
the ellipse of the 2×2 block Qxy (Q is block-diagonal), drawn as
c + Lxy·(cos t, sin t), Qxy = Lxy·Lxyᵀ.
"""

import math
import sys

import numpy as np

import contact_plot
import pypw85


def about_z(degrees):
    """The unit quaternion of a rotation about z."""
    h = math.radians(degrees) / 2.0
    return [math.cos(h), 0.0, 0.0, math.sin(h)]


def section(c, q, scale=1.0, n=400):
    """Points of the section by z = 0 of the ellipsoid (c, q) scaled by
    `scale` about its centre."""
    lxy = np.linalg.cholesky(pypw85.unpack_sym(q)[:2, :2])
    t = np.linspace(0.0, 2.0 * math.pi, n)
    return c[:2, None] + scale * lxy @ np.vstack((np.cos(t), np.sin(t)))


def main(output):
    c1 = np.array([0.0, 0.0, 0.0])
    c2 = np.array([2.5, 1.0, 0.0])
    q1 = pypw85.ellipsoid_quaternion([1.6, 0.6, 0.8], about_z(25.0))
    q2 = pypw85.ellipsoid_quaternion([1.2, 0.45, 0.6], about_z(-55.0))
    geometry = pypw85.contact_geometry(c2 - c1, q1, q2)
    mu2 = geometry[pypw85.GEOM_MU2]
    mu = math.sqrt(mu2)
    x = c1 + geometry[pypw85.GEOM_POINT:pypw85.GEOM_POINT + 3]
    n = geometry[pypw85.GEOM_NORMAL:pypw85.GEOM_NORMAL + 3]
    if x[2] != 0.0 or n[2] != 0.0:
        sys.exit("contact_figure.py: the contact point or the normal is "
                 "out of the plane z = 0: %r, %r" % (x, n))

    fig, ax = contact_plot.figure(3.6)
    contact_plot.shapes(ax, ((c1, q1), (c2, q2)), section, mu)
    contact_plot.contact(ax, c1, c2, x[:2], n[:2], (-4, -17))
    contact_plot.finish(
        fig, ax, r"Plane $z = 0$:  $\mu^2 = %.4f$,  $\lambda = %.4f$"
        % (mu2, geometry[pypw85.GEOM_LAMBDA]), output)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
