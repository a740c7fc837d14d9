# SPDX-License-Identifier: BSD-3-Clause
"""Benchmark (meson test --benchmark --suite lammps): pair style pw85 in
Debian's lmp relaxing 1000 ellipsoids 1 : 0.5 : 0.2 at phi = 0.5 (placed
and turned at random, seeded) to no overlapping pair, on 1 and 2 MPI
ranks, by the protocol of the tests (lammps_run.relax_lines).

Reports: the wall time of each relaxation, its steps, the time per step
and the speed-up of 2 ranks over 1 per step (at zero temperature fix
langevin adds no noise: both runs follow the same trajectory to rounding,
and take the same number of steps unless rounding tips a chunk); and
the time per call of pw85_contact_derivatives() inside the pair style
(LAMMPS's Pair time / the calls counted by compute pair pw85) against the
yardstick of the same run: a plain loop of pw85_contact_derivatives()
calls in the library (pypw85's batch call, one thread) on the pairs of
the relaxed configuration whose bounding spheres meet, and on those of
the initial one. Exit status 0 unless a run fails or overlaps remain; the
figures are reported, not judged (the machine may be shared).
"""

import os
import re
import shutil
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lammps_run as lr  # noqa: E402

import pypw85  # noqa: E402

SEMI = np.array([1.0, 0.5, 0.2])
N = 1000
PHI = 0.5


def script(data, dump):
    return ("units lj\natom_style ellipsoid\nread_data %s\n" % data + lr.LOAD +
            "pair_style pw85\npair_coeff 1 1 2.5\n"
            "compute ov all pw85/overlap\ncompute pc all pair pw85\n"
            "thermo_style custom step c_ov c_pc[1]\n"
            "thermo_modify norm no\n" + lr.relax_lines(SEMI, dump) +
            'print "CALLS $(c_pc[1])"\n')


def timings(out):
    """Sum over the runs of the output: loop time, steps, Pair time (the
    average over ranks)."""
    loop = steps = pair = 0.0
    for m in re.finditer(r"Loop time of (\S+) on \d+ procs for (\d+) steps", out):
        loop += float(m.group(1))
        steps += int(m.group(2))
    for m in re.finditer(r"^Pair\s+\|\s*\S+\s+\|\s*(\S+)", out, re.M):
        pair += float(m.group(1))
    return loop, int(steps), pair


def candidate_pairs(d):
    x, semi = d["x"], d["semi"]
    box = d["box"][:, 1] - d["box"][:, 0]
    q = pypw85.ellipsoid_quaternion(semi, d["quat"])
    rb = semi.max(axis=1)
    i, j = np.triu_indices(len(x), 1)
    r12 = x[j] - x[i]
    r12 -= box * np.round(r12 / box)
    near = np.einsum("ij,ij->i", r12, r12) < (rb[i] + rb[j]) ** 2
    return (np.ascontiguousarray(r12[near]), np.ascontiguousarray(q[i[near]]),
            np.ascontiguousarray(q[j[near]]))


def loop_time(r12, q1, q2, repeats=5):
    """Seconds per pair of the library's loop of
    pw85_contact_derivatives() (the batch call, one thread): the best of
    `repeats`."""
    best = float("inf")
    geom = np.empty((len(r12), pypw85.GEOM_SIZE))
    d = np.empty((len(r12), pypw85.DERIV_SIZE))
    for _ in range(repeats):
        t = time.perf_counter()
        pypw85.contact_derivatives(r12, q1, q2, geom, d, threads=1)
        best = min(best, time.perf_counter() - t)
    return best / len(r12)


def main():
    rng = np.random.default_rng(1000)
    side = (N * lr.ellipsoid_volume(SEMI) / PHI) ** (1.0 / 3.0)
    box = np.full(3, side)
    centres = rng.uniform(0.0, side, size=(N, 3))
    quats = lr.random_quaternions(rng, N)
    work = tempfile.mkdtemp(prefix="bench-lammps-", dir=os.getcwd())
    data = os.path.join(work, "data.lmp")
    lr.write_data(data, box, centres, np.tile(SEMI, (N, 1)), quats)
    results = {}
    for ranks in (1, 2):
        dump = os.path.join(work, "relaxed-%d.dump" % ranks)
        t = time.perf_counter()
        _, out, _ = lr.run(script(data, dump), ranks, cwd=work, timeout=3600)
        wall = time.perf_counter() - t
        loop, steps, pair = timings(out)
        calls = lr.printed(out, "CALLS")[0]
        final = lr.printed(out, "FINAL")[0]
        if final != 0:
            print("FAIL: %d overlapping pairs remain on %d rank(s)" % (final, ranks))
            sys.exit(1)
        results[ranks] = (wall, loop, steps, pair, calls)
        print("%d rank(s): relaxed in %.1f s wall (%.1f s in runs), %d steps, "
              "%.3f ms/step; Pair %.1f s (average over ranks), %d pw85 calls, "
              "%.3f us per call (x %d ranks)"
              % (ranks, wall, loop, steps, 1e3 * loop / steps, pair, calls,
                 1e6 * pair * ranks / calls, ranks))
    per_step = {r: v[1] / v[2] for r, v in results.items()}
    print("2 ranks over 1, per step: %.2fx (issue 31 asks >= 1.7x on 2 free cores)"
          % (per_step[1] / per_step[2]))
    print("2 ranks over 1, whole relaxation: %.2fx" % (results[1][0] / results[2][0]))
    d_final = lr.read_dump(os.path.join(work, "relaxed-1.dump"))
    d_initial = dict(d_final)
    d_initial["x"] = centres
    d_initial["quat"] = quats
    for name, d in (("relaxed", d_final), ("initial", d_initial)):
        r12, q1, q2 = candidate_pairs(d)
        per = loop_time(r12, q1, q2)
        print("yardstick: plain loop of pw85_contact_derivatives() on the %d pairs "
              "of the %s configuration whose bounding spheres meet: %.3f us per call"
              % (len(r12), name, 1e6 * per))
        if name == "relaxed":
            one = results[1][3] / results[1][4]
            print("pair style pw85 on 1 rank: %.3f us per call = %.2fx the plain loop "
                  "(the neighbor loop, forms, energy and tallies on top of pw85)"
                  % (1e6 * one, one / per))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
