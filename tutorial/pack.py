# SPDX-License-Identifier: BSD-3-Clause
"""Packing ellipsoids (docs/packing.rst) with pypw85.pack: triaxial
ellipsoids 1 : 0.5 : 0.2 (half of them twice as large) to a packing
fraction, checked by the all-pairs query and the overlap energy.

    python3 tutorial/pack.py [N [FRACTION]]

Exit status 0 when the checks pass.
"""

import sys

import numpy as np

import pypw85


def packed(n=1000, fraction=0.5, seed=1):
    """A packing of n ellipsoids, the two sizes alternating."""
    sizes = np.where(np.arange(n) % 2 == 0, 1.0, 2.0)
    semi_axes = sizes[:, None] * np.array([1.0, 0.5, 0.2])
    return pypw85.pack(semi_axes, fraction, seed=seed, threads=2,
                       time_limit=60.0,
                       progress=lambda p: print(
                           "  step %5d: %6d overlapping pairs"
                           % (p["steps"], p["pairs"])))


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    fraction = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5
    p = packed(n, fraction)
    print("%d ellipsoids in a box of side %.3f: packing fraction %.4f (%s)"
          % (n, p.box[0], p.phi, p.outcome))
    # The check: every pair and image, decided as pypw85.overlap does.
    index = pypw85.Index(box=p.box)
    index.insert(np.arange(n), p.centres, p.forms)
    pairs = index.overlapping_pairs(threads=2)
    energy, forces, torques = index.energy()
    print("overlapping pairs: %d, overlap energy: %g"
          % (len(pairs[0]), energy))
    ok = len(pairs[0]) == 0 and energy == 0.0 and p.outcome == "target"
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
