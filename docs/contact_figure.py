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

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import pypw85  # noqa: E402


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

    plt.rcParams.update({"svg.hashsalt": "pw85", "font.size": 11})
    fig, ax = plt.subplots(figsize=(7.0, 3.6))
    colours = ("#3a6ea5", "#c0504d")
    for c, q, colour, name in ((c1, q1, colours[0], "1"),
                               (c2, q2, colours[1], "2")):
        xy = section(c, q)
        ax.fill(*xy, color=colour, alpha=0.25, lw=0)
        ax.plot(*xy, color=colour, lw=1.5, label=r"$E_%s$" % name)
        ax.plot(*section(c, q, mu), color=colour, lw=1.2, ls="--",
                label=r"$E_%s$ scaled by $\mu$" % name)
        ax.plot(c[0], c[1], "+", color=colour, ms=9, mew=1.5)
        ax.annotate(r"$c_%s$" % name, c[:2], xytext=(5, -13),
                    textcoords="offset points", color=colour)
    ax.plot([c1[0], c2[0]], [c1[1], c2[1]], color="0.5", lw=0.8, ls=":")
    ax.plot(x[0], x[1], "o", color="black", ms=5, zorder=3)
    ax.annotate(r"$x_0$", x[:2], xytext=(-4, -17), textcoords="offset points")
    ax.annotate("", xy=x[:2] + 0.9 * n[:2], xytext=x[:2],
                arrowprops=dict(arrowstyle="-|>", color="black", lw=1.3))
    ax.annotate(r"$n$", x[:2] + 0.9 * n[:2], xytext=(4, 0),
                textcoords="offset points")
    ax.set_title(r"Plane $z = 0$:  $\mu^2 = %.4f$,  $\lambda = %.4f$"
                 % (mu2, geometry[pypw85.GEOM_LAMBDA]))
    ax.set_aspect("equal")
    ax.legend(loc="center left", bbox_to_anchor=(1.02, 0.5), fontsize=9,
              frameon=False)
    ax.set_xlabel(r"$x$")
    ax.set_ylabel(r"$y$")
    fig.tight_layout()
    fig.savefig(output, metadata={"Date": None})


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
