# SPDX-License-Identifier: BSD-3-Clause
"""The figure of packing.rst: a planar section through a packing made by
pypw85.pack, drawn at build time (section_plot.py)."""

import numpy as np

import pypw85
from section_plot import section

n, fraction = 1000, 0.55
p = pypw85.pack(np.tile([1.0, 0.5, 0.2], (n, 1)), fraction, seed=3,
                threads=2)
side = p.box[0]
z0 = 0.5 * side

fig, ax = section(p.centres, p.forms, side, z0, "#dd8452", "#5a2a0c")
ax.set_title("Section z = %.2f of a periodic packing by pypw85.pack\n"
             "(%d ellipsoids 1 : 0.5 : 0.2, packing fraction %.2f, %s)"
             % (z0, n, p.phi, p.outcome), fontsize=9)
fig.tight_layout()
