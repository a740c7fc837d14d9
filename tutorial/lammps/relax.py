# SPDX-License-Identifier: BSD-3-Clause
"""Tutorial (docs/lammps.rst): a random packing of ellipsoids relaxed by
LAMMPS with pair style pw85, checked by pw85's all-pairs query.

1. Place N ellipsoids of semi-axes 1, 0.5, 0.2 at random in a periodic
   cube at packing fraction 0.5 (they overlap), and count the overlapping
   pairs with pypw85.Index.
2. Write them as a LAMMPS data file (data.lmp) and run in.relax in lmp.
3. Read the relaxed configuration back (relaxed.dump) and ask
   pypw85.Index again: no pair may overlap.

    python3 relax.py [N]

The environment names the programs: LMP (default lmp), MPIRUN (mpirun;
RANKS ranks, default 1) and PW85_LAMMPS_PY, the loader pw85_lammps.py.
Exit status 1 if a pair still overlaps.
"""

import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

import pypw85

SEMI = np.array([1.0, 0.5, 0.2])


def overlapping(box, centres, quats):
    """(overlapping, tangent) pairs of the periodic packing, by the index."""
    q = pypw85.ellipsoid_quaternion(np.tile(SEMI, (len(centres), 1)), quats)
    with pypw85.Index(box) as index:
        index.insert(np.arange(len(centres)), np.mod(centres, box), q)
        _, _, results = index.overlapping_pairs()
    return int(np.sum(results < 0)), int(np.sum(results == 0))


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    rng = np.random.default_rng(31)
    volume = 4.0 / 3.0 * np.pi * np.prod(SEMI)
    side = (n * volume / 0.5) ** (1.0 / 3.0)
    box = np.full(3, side)
    centres = rng.uniform(0.0, side, size=(n, 3))
    quats = rng.normal(size=(n, 4))
    quats /= np.linalg.norm(quats, axis=1)[:, None]
    print("%d ellipsoids at phi = 0.5 in a cube of side %.4f: %d overlapping pairs"
          % (n, side, overlapping(box, centres, quats)[0]))

    work = tempfile.mkdtemp(prefix="pw85-lammps-tutorial-")
    here = os.path.dirname(os.path.abspath(__file__))
    shutil.copy(os.path.join(here, "in.relax"), work)
    with open(os.path.join(work, "data.lmp"), "w") as f:
        f.write("random packing, pw85 tutorial\n\n%d atoms\n1 atom types\n"
                "%d ellipsoids\n\n" % (n, n))
        for axis in "xyz":
            f.write("0 %.17g %slo %shi\n" % (side, axis, axis))
        f.write("\nAtoms # ellipsoid\n\n")        # id type flag density x y z
        for i, c in enumerate(centres):
            f.write("%d 1 1 1.0 %.17g %.17g %.17g\n" % (i + 1, *c))
        f.write("\nEllipsoids\n\n")               # id diameters, (w, x, y, z)
        for i, p in enumerate(quats):
            f.write("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n"
                    % (i + 1, *(2 * SEMI), *p))

    cmd = [os.environ.get("MPIRUN", "mpirun"), "-np", os.environ.get("RANKS", "1")]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    if "PW85_LAMMPS_PLUGIN" in os.environ:
        cmd += ["-x", "PW85_LAMMPS_PLUGIN"]
    cmd += [os.environ.get("LMP", "lmp"), "-in", "in.relax", "-log", "log.lammps",
            "-var", "pw85", os.environ.get("PW85_LAMMPS_PY", "pw85_lammps.py")]
    proc = subprocess.run(cmd, cwd=work, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True)
    for line in proc.stdout.splitlines():
        if line.startswith("overlapping pairs after relaxation"):
            print("LAMMPS, compute pw85/overlap:", line)
    if proc.returncode != 0:
        print(proc.stdout[-3000:])
        sys.exit(1)

    with open(os.path.join(work, "relaxed.dump")) as f:
        lines = f.read().splitlines()
    lo_hi = np.array([[float(v) for v in lines[5 + k].split()] for k in range(3)])
    rows = np.array([[float(v) for v in l.split()] for l in lines[9:9 + n]])
    relaxed_box = lo_hi[:, 1] - lo_hi[:, 0]
    over, tangent = overlapping(relaxed_box, rows[:, 1:4] - lo_hi[:, 0], rows[:, 4:8])
    print("after relaxation, pypw85.Index: %d overlapping pairs, %d tangent" % (over, tangent))
    shutil.rmtree(work)
    sys.exit(0 if over == 0 and tangent == 0 else 1)


if __name__ == "__main__":
    main()
