# SPDX-License-Identifier: BSD-3-Clause
"""The drawing shared by plot_section.py (assemblies.rst) and
plot_packing.py (packing.rst): the section of a periodic assembly of
ellipsoids by the plane z = z0. A module of the docs' build, imported by
those two scripts from docs/ (Sphinx's plot directive puts its working
directory on sys.path).

Each ellipsoid (or periodic image) that the plane cuts is cut along an
ellipse: with e = z0 - c_z and q = (Q_xz, Q_yz), non-empty when
e² < Q_zz, of centre (c_x, c_y) + e·q/Q_zz and quadratic form
(1 - e²/Q_zz)·(Q_xy - q·qᵀ/Q_zz)."""

import itertools

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Ellipse


def section(centres, forms, side, z0, facecolor, edgecolor):
    """A 5.5-inch square figure of the section z = z0 of the ellipsoids
    (centres, forms as the six stored entries) in a cubic box of the given
    side, with every image that reaches the box; returns (fig, ax)."""
    fig, ax = plt.subplots(figsize=(5.5, 5.5))
    for c, q in zip(centres, forms):
        for shift in itertools.product((-1, 0, 1), repeat=3):
            cc = c + side * np.array(shift)
            e = z0 - cc[2]
            if e * e >= q[5]:
                continue
            qxz = np.array([q[2], q[4]])
            centre = cc[:2] + e * qxz / q[5]
            s = (1.0 - e * e / q[5]) * (np.array([[q[0], q[1]], [q[1], q[3]]])
                                       - np.outer(qxz, qxz) / q[5])
            w, v = np.linalg.eigh(s)
            angle = np.degrees(np.arctan2(v[1, 1], v[0, 1]))
            ax.add_patch(Ellipse(centre, 2 * np.sqrt(w[1]), 2 * np.sqrt(w[0]),
                                 angle=angle, facecolor=facecolor,
                                 edgecolor=edgecolor, linewidth=0.4))
    ax.set_xlim(0, side)
    ax.set_ylim(0, side)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    return fig, ax
