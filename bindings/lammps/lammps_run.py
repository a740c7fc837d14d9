# SPDX-License-Identifier: BSD-3-Clause
"""Running Debian's lmp with pair style pw85 from Python: configurations,
data files, input scripts, dumps. Shared by test_lammps.py, the benchmark
(bench_lammps.py) and the tutorial (tutorial/lammps_relax.py).

The environment names the programs and files (bindings/lammps/meson.build
sets them for the tests): LMP (lmp), MPIRUN (mpirun), PW85_LAMMPS_PY (the
loader run by LAMMPS's PYTHON package), PW85_LAMMPS_PLUGIN (the shared
object it loads).
"""

import math
import os
import subprocess
import tempfile

import numpy as np

#: PW85_LAMMPS_LOAD=plugin: the lmp run is built with PLUGIN, and loads
#: the shared object by `plugin load`; otherwise (Debian's lmp) through
#: the PYTHON package and pw85_lammps.py.
PLUGIN = os.environ.get("PW85_LAMMPS_LOAD") == "plugin"

#: The lines that load pair style pw85 (docs/lammps.rst, "Loading");
#: ${pw85} is set by `-var pw85 PATH` (run()): the loader pw85_lammps.py,
#: or with PLUGIN the shared object.
LOAD = ("plugin load ${pw85}\n" if PLUGIN else
        "python pw85_lammps input 1 SELF format p file ${pw85}\n"
        "python pw85_lammps invoke\n")


def random_quaternions(rng, n):
    """n unit quaternions (w, x, y, z), uniform on the sphere S³."""
    p = rng.normal(size=(n, 4))
    return p / np.linalg.norm(p, axis=1)[:, None]


def write_data(path, box, centres, semi_axes, quats, types=None, density=1.0):
    """A LAMMPS data file for atom_style ellipsoid: the Ellipsoids section
    takes DIAMETERS (2·semi-axis, exact in binary) and (w, x, y, z)."""
    n = len(centres)
    types = np.ones(n, dtype=int) if types is None else types
    with open(path, "w") as f:
        f.write("pw85 ellipsoids\n\n%d atoms\n%d atom types\n%d ellipsoids\n\n"
                % (n, int(types.max()), n))
        for k, axis in enumerate("xyz"):
            f.write("%.17g %.17g %slo %shi\n" % (0.0, box[k], axis, axis))
        f.write("\nAtoms # ellipsoid\n\n")
        for i in range(n):
            f.write("%d %d 1 %.17g %.17g %.17g %.17g\n"
                    % (i + 1, types[i], density, *centres[i]))
        f.write("\nEllipsoids\n\n")
        for i in range(n):
            f.write("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n"
                    % (i + 1, *(2.0 * np.asarray(semi_axes[i])), *quats[i]))


#: Dump columns of read_dump(), after id.
DUMP_COLUMNS = ("x y z fx fy fz tqx tqy tqz c_pw85q[1] c_pw85q[2] c_pw85q[3] "
                "c_pw85q[4] c_pw85s[1] c_pw85s[2] c_pw85s[3] c_pw85pe type")

#: Input lines that define the dump of read_dump() (every 'every' steps).
def dump_lines(path, every=1):
    return (
        "compute pw85q all property/atom quatw quati quatj quatk\n"
        "compute pw85s all property/atom shapex shapey shapez\n"
        "compute pw85pe all pe/atom pair\n"
        "dump pw85d all custom %d %s id %s\n"
        "dump_modify pw85d sort id format float %%.17g\n"
        % (every, path, DUMP_COLUMNS))


def read_dump(path):
    """The last frame of a dump of dump_lines(): a dict of arrays sorted
    by id: x (n, 3), f, tq, quat (n, 4, (w, x, y, z)), semi (n, 3: the
    semi-axes, half the dumped diameters), pe (per-atom pair energy), and
    type, and box ((3, 2): lo, hi)."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = max(i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP"))
    frame = lines[start:]
    n = int(frame[3])
    box = np.array([[float(v) for v in frame[5 + k].split()[:2]] for k in range(3)])
    rows = np.array([[float(v) for v in l.split()] for l in frame[9:9 + n]])
    rows = rows[np.argsort(rows[:, 0])]
    return {"id": rows[:, 0].astype(int), "x": rows[:, 1:4], "f": rows[:, 4:7],
            "tq": rows[:, 7:10], "quat": rows[:, 10:14],
            "semi": 0.5 * rows[:, 14:17], "pe": rows[:, 17],
            "type": rows[:, 18].astype(int), "box": box}


def run(script, ranks=1, cwd=None, extra_env=None, check=True, timeout=600):
    """Runs lmp on `ranks` MPI ranks with the input `script` (a string:
    the loader of pair style pw85 is NOT added), in cwd (a new temporary
    directory if None). Returns (returncode, output, cwd)."""
    cwd = cwd or tempfile.mkdtemp(prefix="pw85-lammps-")
    with open(os.path.join(cwd, "in.lmp"), "w") as f:
        f.write(script)
    env = dict(os.environ)
    # Open MPI: ranks that wait yield the processor (the machine may have
    # fewer cores than ranks); no warning about a missing fast network.
    env.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    env.setdefault("OMPI_MCA_btl", "self,vader,tcp")
    env.update(extra_env or {})
    lmp = env.get("LMP", "lmp")
    mpirun = env.get("MPIRUN", "mpirun")
    cmd = [mpirun, "-np", str(ranks), "--oversubscribe"]
    if os.geteuid() == 0:
        cmd.append("--allow-run-as-root")
    # Every rank sees the variables that name the shared object.
    for name in ("PW85_LAMMPS_PLUGIN", "LD_LIBRARY_PATH", "LD_PRELOAD", "PYTHONPATH"):
        if name in env:
            cmd += ["-x", name]
    loader = (env.get("PW85_LAMMPS_PLUGIN", "pw85_lammps.so") if PLUGIN else
              env.get("PW85_LAMMPS_PY", "pw85_lammps.py"))
    cmd += [lmp, "-var", "pw85", loader,
            "-in", "in.lmp", "-log", "log.lammps", "-nocite"]
    proc = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, timeout=timeout)
    if check and proc.returncode != 0:
        raise RuntimeError("lmp failed (status %d) in %s:\n%s"
                           % (proc.returncode, cwd, proc.stdout[-4000:]))
    return proc.returncode, proc.stdout, cwd


def printed(output, key, count=1):
    """The values of the lines `key value...` (count values) that the
    script printed (with print "key $(...)"), as floats, or tuples of
    floats when count > 1."""
    rows = [[float(v) for v in l.split()[1:]] for l in output.splitlines()
            if l.startswith(key + " ") and len(l.split()) == count + 1]
    return [r[0] for r in rows] if count == 1 else [tuple(r) for r in rows]


def relax_lines(semi, dump, inflate=1.02, chunk=1000, max_chunks=30):
    """Input lines that relax overlaps (after pair style pw85, compute ov
    pw85/overlap and the thermo settings): damped rigid-body dynamics (fix
    nve/asphere + fix langevin at zero temperature on translations and
    rotations) on ellipsoids of type 1 inflated by `inflate`, run by
    chunks; after each chunk, the true semi-axes `semi` are put back for a
    `run 0` that counts their overlapping pairs, and the relaxation stops
    when there are none (prints "OV inflated true" after each chunk). An
    inflated pair that does not overlap leaves a gap between the true
    ones: the true ellipsoids separate before the damped approach to zero
    energy of the inflated ones ends. Then a dump of read_dump() format,
    and "FINAL count" (true shapes). minimize cannot do it: it moves
    centres, never orientations (docs/lammps.rst)."""
    inflated = "set type 1 shape %r %r %r\n" % tuple(2 * inflate * np.asarray(semi))
    true = "set type 1 shape %r %r %r\n" % tuple(2 * np.asarray(semi))
    return (inflated +
            "fix 1 all nve/asphere\n"
            "fix 2 all langevin 0.0 0.0 0.5 8080 angmom 3.0\n"
            "timestep 0.005\n"
            "thermo 0\n"
            "variable n loop %d\n"
            "label again\n"
            "run %d\n"
            "variable inflated equal $(c_ov)\n" % (max_chunks, chunk) +
            true +
            "run 0\n"
            'print "OV ${inflated} $(c_ov)"\n'
            'if "$(c_ov) == 0" then "jump SELF done"\n' +
            inflated +
            "next n\n"
            "jump SELF again\n"
            "label done\n"
            "unfix 1\nunfix 2\n" + dump_lines(dump) +
            "run 0\n"
            'print "FINAL $(c_ov)"\n')


def ellipsoid_volume(semi):
    return 4.0 / 3.0 * math.pi * semi[0] * semi[1] * semi[2]
