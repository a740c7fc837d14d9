# SPDX-License-Identifier: BSD-3-Clause
"""From a packing to the files of a microstructure, with pypw85 (the Python
twin of micro.c; docs: "Microstructures for FFT solvers and viewers").

Random sequential addition (rsa.py's `rsa_packing`), then the voxel image
(`pypw85.micro.voxel_image`: each voxel centre decided exactly), its phase
fraction, and the files that pw85-pack writes: HDF5 (read back), its XDMF
companion for ParaView, extended XYZ for OVITO.

    python3 micro.py [DIRECTORY]   (default: a temporary directory)

Exit status 0 when its checks pass.
"""

import math
import os
import sys
import tempfile

import numpy as np

import pypw85
from pypw85 import micro

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rsa import AXES, rsa_packing  # noqa: E402


def main(directory):
    # 1. A packing of 800 ellipsoids (1, 0.5, 0.2) at a fraction of 0.2.
    index, centres, forms, side, _ = rsa_packing(800, 0.2, seed=28)
    box = np.array([side] * 3)
    print("%d ellipsoids, packing fraction %.4f"
          % (len(centres), len(centres) * 4 / 3 * math.pi * AXES.prod() / side**3))

    # 2. Its voxel image: image[i, j, k] is the position of the ellipsoid
    #    containing voxel (i, j, k)'s centre, or -1.
    image = micro.voxel_image(centres, forms, box, 80, threads=2)
    print("image %s, phase fraction %.4f" % (image.shape, micro.phase_fraction(image)))

    # 3. The files: semi-axes and quaternions (w, x, y, z) from the forms.
    axes, quaternions = zip(*(pypw85.principal_axes_quaternion(q) for q in forms))
    m = micro.Microstructure(box=box, centres=np.asarray(centres),
                             forms=np.asarray(forms), axes=np.array(axes),
                             quaternions=np.array(quaternions), seed=28,
                             method="rsa", image=image)
    h5 = os.path.join(directory, "micro.h5")
    micro.write_hdf5(h5, m)
    micro.write_xdmf(os.path.join(directory, "micro.xdmf"), h5, image.shape, box)
    micro.write_xyz(os.path.join(directory, "micro.xyz"), m)
    print("written:", ", ".join(sorted(os.listdir(directory))))

    # Checks: the file holds what was written; the image holds ellipsoids
    # where the packing is (sampling error at 80³: 0.01 is loose).
    back = micro.read_hdf5(h5)
    ok = (np.array_equal(back.image, image) and np.array_equal(back.centres, m.centres)
          and abs(micro.phase_fraction(image) - m.packing_fraction) < 0.01)
    print("checks:", "passed" if ok else "FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) > 1:
        sys.exit(main(sys.argv[1]))
    with tempfile.TemporaryDirectory() as d:
        sys.exit(main(d))
