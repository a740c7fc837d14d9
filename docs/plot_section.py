# SPDX-License-Identifier: BSD-3-Clause
"""The figure of assemblies.rst: a planar section through a random
sequential addition packing (tutorial/rsa.py), drawn at build time.

Each ellipsoid (or periodic image) that the plane z = z0 cuts is cut along
an ellipse: with e = z0 - c_z and q = (Q_xz, Q_yz), non-empty when
e² < Q_zz, of centre (c_x, c_y) + e·q/Q_zz and quadratic form
(1 - e²/Q_zz)·(Q_xy - q·qᵀ/Q_zz).
"""

import itertools
import pathlib
import sys

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Ellipse

# Run by Sphinx's plot directive from docs/ (conf.py: plot_working_directory).
sys.path.insert(0, str(pathlib.Path.cwd().resolve().parent / "tutorial"))
from rsa import rsa_packing  # noqa: E402

index, centres, forms, side, _ = rsa_packing(1500, 0.25, seed=4)
index.close()
z0 = 0.5 * side

fig, ax = plt.subplots(figsize=(5.5, 5.5))
for c, q in zip(centres, forms):
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
                             angle=angle, facecolor="#4c72b0",
                             edgecolor="#1b2a4a", linewidth=0.4))
ax.set_xlim(0, side)
ax.set_ylim(0, side)
ax.set_aspect("equal")
ax.set_xlabel("x")
ax.set_ylabel("y")
ax.set_title("Section z = %.2f of a periodic RSA packing\n"
             "(1500 ellipsoids 1 : 0.5 : 0.2, packing fraction 0.25)" % z0,
             fontsize=9)
fig.tight_layout()
