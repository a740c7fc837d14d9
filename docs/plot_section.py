# SPDX-License-Identifier: BSD-3-Clause
"""The figure of assemblies.rst: a planar section through a random
sequential addition packing (tutorial/rsa.py), drawn at build time
(section_plot.py)."""

import pathlib
import sys

from section_plot import section

# Run by Sphinx's plot directive from docs/ (conf.py: plot_working_directory).
sys.path.insert(0, str(pathlib.Path.cwd().resolve().parent / "tutorial"))
from rsa import rsa_packing  # noqa: E402

index, centres, forms, side, _ = rsa_packing(1500, 0.25, seed=4)
index.close()
z0 = 0.5 * side

fig, ax = section(centres, forms, side, z0, "#4c72b0", "#1b2a4a")
ax.set_title("Section z = %.2f of a periodic RSA packing\n"
             "(1500 ellipsoids 1 : 0.5 : 0.2, packing fraction 0.25)" % z0,
             fontsize=9)
fig.tight_layout()
