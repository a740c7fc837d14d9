# SPDX-License-Identifier: BSD-3-Clause
"""The figure of packing.rst: a planar section through a packing made by
pypw85.pack, drawn at build time.

Each ellipsoid (or periodic image) that the plane z = z0 cuts is cut along
an ellipse: with e = z0 - c_z and q = (Q_xz, Q_yz), non-empty when
e² < Q_zz, of centre (c_x, c_y) + e·q/Q_zz and quadratic form
(1 - e²/Q_zz)·(Q_xy - q·qᵀ/Q_zz) (as plot_section.py).
"""

import itertools

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Ellipse

import pypw85

n, fraction = 1000, 0.55
p = pypw85.pack(np.tile([1.0, 0.5, 0.2], (n, 1)), fraction, seed=3,
                threads=2)
side = p.box[0]
z0 = 0.5 * side

fig, ax = plt.subplots(figsize=(5.5, 5.5))
for c, q in zip(p.centres, p.forms):
    for sx, sy, sz in itertools.product((-1, 0, 1), repeat=3):
        cc = c + side * np.array([sx, sy, sz])
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
                             angle=angle, facecolor="#dd8452",
                             edgecolor="#5a2a0c", linewidth=0.4))
ax.set_xlim(0, side)
ax.set_ylim(0, side)
ax.set_aspect("equal")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_title("Section z = %.2f of a periodic packing by pypw85.pack\n"
             "(%d ellipsoids 1 : 0.5 : 0.2, packing fraction %.2f, %s)"
             % (z0, n, p.phi, p.outcome), fontsize=9)
fig.tight_layout()
