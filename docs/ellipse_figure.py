# SPDX-License-Identifier: BSD-3-Clause
"""Draw the figure of docs/ellipses.rst: the two ellipses of
tutorial/ellipses.c, the same scaled by μ, their contact point, the common
normal and the angle θ1, computed by pypw85.d2.

    ellipse_figure.py OUTPUT.svg

Run by docs/meson.build at build time (pypw85 from the source tree, libpw85
of the build, as the tests). Each ellipse is drawn from its form alone,
through d2.principal_axes: c + R(θ)·diag(a0, a1)·(cos t, sin t).
"""

import math
import sys

from matplotlib.patches import Arc
import numpy as np

import contact_plot
from pypw85 import d2


def outline(c, q, scale=1.0, n=400):
    """Points of the ellipse (c, q) scaled by `scale` about its centre."""
    a, theta = d2.principal_axes(q)
    rot = np.array([[math.cos(theta), -math.sin(theta)],
                    [math.sin(theta), math.cos(theta)]])
    t = np.linspace(0.0, 2.0 * math.pi, n)
    return c[:, None] + scale * rot @ (a[:, None] * np.vstack((np.cos(t),
                                                               np.sin(t))))


def main(output):
    # The data of tutorial/ellipses.c.
    deg = math.pi / 180.0
    theta1 = 30.0 * deg
    c1 = np.array([0.0, 0.0])
    c2 = np.array([3.0, 1.5])
    q1 = d2.ellipse([2.0, 0.5], theta1)
    q2 = d2.ellipse([1.2, 0.6], -45.0 * deg)
    geometry = d2.contact_geometry(c2 - c1, q1, q2)
    mu2 = geometry[d2.GEOM_MU2]
    mu = math.sqrt(mu2)
    x = c1 + geometry[d2.GEOM_POINT:d2.GEOM_POINT + 2]
    n = geometry[d2.GEOM_NORMAL:d2.GEOM_NORMAL + 2]

    fig, ax = contact_plot.figure(3.8)
    contact_plot.shapes(ax, ((c1, q1), (c2, q2)), outline, mu)
    # θ1: from the x axis to the semi-axis a0 of E1.
    ax.plot([c1[0], c1[0] + 1.0], [c1[1], c1[1]], color="0.4", lw=0.8)
    ax.plot([c1[0], c1[0] + 2.0 * math.cos(theta1)],
            [c1[1], c1[1] + 2.0 * math.sin(theta1)],
            color=contact_plot.COLOURS[0], lw=0.8)
    ax.add_patch(Arc(c1, 1.6, 1.6, theta1=0.0, theta2=30.0, color="0.4",
                     lw=0.8))
    ax.annotate(r"$\theta_1$", c1 + 0.85 * np.array([math.cos(theta1 / 2),
                                                      math.sin(theta1 / 2)]),
                xytext=(2, -4), textcoords="offset points", color="0.3")
    contact_plot.contact(ax, c1, c2, x, n, (-20, 2))
    contact_plot.finish(fig, ax, r"$\mu^2 = %.4f$,  $\lambda = %.4f$"
                        % (mu2, geometry[d2.GEOM_LAMBDA]), output)


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
