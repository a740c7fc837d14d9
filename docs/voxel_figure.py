# SPDX-License-Identifier: BSD-3-Clause
"""Draw the figure of docs/microstructures.rst: a slice of the voxel image
of a packing, computed by pypw85 (random sequential addition with
pypw85.Index, then pypw85.micro.voxel_image), with the exact sections of the
ellipsoids by the plane of the voxel centres drawn over it.

    voxel_figure.py OUTPUT.svg

Run by docs/meson.build at build time (pypw85 from the source tree, libpw85
of the build, as the tests). The section of ellipsoid (c, Q) by the plane
z = z0 is the level 1 of (m − c)ᵀQ⁻¹(m − c) over that plane, drawn as a
contour on a fine grid, for every periodic image.
"""

import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
import numpy as np  # noqa: E402

import pypw85  # noqa: E402
from pypw85 import micro  # noqa: E402


def packing(n, side, axes, seed):
    """Random sequential addition of n ellipsoids (fewer if they do not fit
    in 20000 attempts): centres and forms."""
    rng = np.random.default_rng(seed)
    index = pypw85.Index([side] * 3)
    centres, forms = [], []
    for _ in range(20000):
        if len(centres) == n:
            break
        c = rng.uniform(0, side, 3)
        p = rng.normal(size=4)
        q = pypw85.ellipsoid_quaternion(axes, p / np.linalg.norm(p))
        if index.overlap_any(c, q)[0] > 0:
            index.insert(len(centres), c, q)
            centres.append(c)
            forms.append(q)
    return np.array(centres), np.array(forms)


def main(output):
    side, m = 8.0, 40
    centres, forms = packing(110, side, [1.0, 0.55, 0.35], seed=28)
    box = np.array([side] * 3)
    image = micro.voxel_image(centres, forms, box, m)
    k0 = m // 2
    z0 = (k0 + 0.5) * side / m
    plt.rcParams.update({"svg.hashsalt": "pw85", "font.size": 10})
    fig, ax = plt.subplots(figsize=(5.6, 5.2))
    rng = np.random.default_rng(3)
    colours = np.vstack([[1.0, 1.0, 1.0, 1.0],
                         np.column_stack([rng.uniform(0.35, 0.85, (len(centres), 3)),
                                          np.ones(len(centres))])])
    # image[i, j, k0]: x along i (horizontal), y along j (vertical)
    ax.imshow(image[:, :, k0].T + 1, origin="lower", extent=(0, side, 0, side),
              cmap=ListedColormap(colours), vmin=0, vmax=len(centres),
              interpolation="nearest")
    t = np.linspace(0, side, 601)
    x, y = np.meshgrid(t, t, indexing="xy")
    for c, q in zip(centres, forms):
        b = np.linalg.inv(pypw85.unpack_sym(q))
        r = np.sqrt(np.array([q[0], q[3], q[5]]))  # half-widths
        for s in np.ndindex(3, 3, 3):
            cc = c + (np.array(s) - 1) * side
            # only the images whose bounding box meets the slice's square
            if abs(z0 - cc[2]) > r[2] or (cc[:2] + r[:2] < 0).any() or \
                    (cc[:2] - r[:2] > side).any():
                continue
            d = np.stack([x - cc[0], y - cc[1], np.full_like(x, z0 - cc[2])])
            v = np.einsum("i...,ij,j...->...", d, b, d)
            if v.min() < 1:
                ax.contour(x, y, v, levels=[1.0], colors="k", linewidths=0.7)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title("voxels k = %d of a %d³ image (z = %.2f); black: exact sections"
                 % (k0, m, z0), fontsize=9)
    fig.tight_layout()
    fig.savefig(output, format="svg")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: voxel_figure.py OUTPUT.svg")
    main(sys.argv[1])
