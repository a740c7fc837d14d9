# SPDX-License-Identifier: BSD-3-Clause
"""pw85-pack (issue 28, item 2) as a user runs it: the files it writes read
back by h5py, an XML parser and ASE's extended-XYZ reader with the
documented values; the same files for 1 and 2 threads; Ctrl-C (SIGINT)
leaving a valid file (rsa: that --resume completes into the uninterrupted
result; fire, the default: the larger box of its certified configuration,
and --resume refused); the progress bar seen in a tmux capture and absent
without a terminal; every bad argument: one line naming it, a non-zero
exit status, nothing written. Both methods: fire (pw85_pack(), the
default) and rsa.

Usage: test_pack.py PW85-PACK VERSION  (run by meson, /usr/bin/python3)
Exit status 77 (a skip) when h5py or ASE is missing.
"""

import math
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest
import xml.etree.ElementTree as ET
from fractions import Fraction

try:
    import h5py
    import numpy as np
    import ase.io
except ImportError as e:  # pragma: no cover
    print("SKIP:", e)
    sys.exit(77)

TOOL = None
VERSION = None
VOLUME = 4.0 / 3.0 * math.pi * 1.0 * 0.5 * 0.2  # axes 1, 0.5, 0.2


def run(args, cwd, **kw):
    return subprocess.run([TOOL] + args, cwd=cwd, capture_output=True,
                          text=True, timeout=300, **kw)


def exact_form(p, a):
    """q = R·diag(a²)·Rᵀ (upper triangle, row by row), R the rotation of the
    quaternion p/|p|, in rationals."""
    w, x, y, z = (Fraction(v) for v in p)
    s = w * w + x * x + y * y + z * z
    R = [[1 - 2 * (y * y + z * z) / s, 2 * (x * y - w * z) / s, 2 * (x * z + w * y) / s],
         [2 * (x * y + w * z) / s, 1 - 2 * (x * x + z * z) / s, 2 * (y * z - w * x) / s],
         [2 * (x * z - w * y) / s, 2 * (y * z + w * x) / s, 1 - 2 * (x * x + y * y) / s]]
    d = [Fraction(v) ** 2 for v in a]
    return [sum(R[i][m] * d[m] * R[j][m] for m in range(3))
            for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))]


def exact_inside(point, c, q):
    """(m − c)ᵀ Q⁻¹ (m − c) ≤ 1 in rationals: dᵀ adj(Q) d ≤ det Q."""
    d = [point[k] - Fraction(c[k]) for k in range(3)]
    Q = [[Fraction(q[0]), Fraction(q[1]), Fraction(q[2])],
         [Fraction(q[1]), Fraction(q[3]), Fraction(q[4])],
         [Fraction(q[2]), Fraction(q[4]), Fraction(q[5])]]
    A = [[Q[(l + 1) % 3][(k + 1) % 3] * Q[(l + 2) % 3][(k + 2) % 3]
          - Q[(l + 1) % 3][(k + 2) % 3] * Q[(l + 2) % 3][(k + 1) % 3]
          for l in range(3)] for k in range(3)]
    det = sum(Q[0][l] * A[l][0] for l in range(3))
    lhs = sum(A[k][l] * d[k] * d[l] for k in range(3) for l in range(3))
    return lhs <= det


class ToolCase(unittest.TestCase):
    """What the tests of ellipsoids and of ellipses (test_pack_2d.py) share:
    a directory of their own, and the checks written once for both."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="pw85-pack-test-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)

    def interrupt(self, argv, after):
        """pw85-pack ARGV sent SIGINT after `after` seconds: exit status 130,
        "interrupted"; returns its stderr."""
        proc = subprocess.Popen([TOOL] + argv, cwd=self.dir, stderr=subprocess.PIPE,
                                text=True)
        time.sleep(after)
        proc.send_signal(signal.SIGINT)
        err = proc.communicate(timeout=120)[1]
        self.assertEqual(proc.returncode, 130, err)
        self.assertIn("interrupted", err)
        return err

    def check_threads(self, args, names):
        """The datasets `names` and the attribute attempts the same, bit for
        bit, for 1 and 2 threads."""
        outs = []
        for t in ("1", "2"):
            r = run(args + ["--threads", t, "--out", "t%s.h5" % t], self.dir)
            self.assertEqual(r.returncode, 0, r.stderr)
            with h5py.File(os.path.join(self.dir, "t%s.h5" % t), "r") as f:
                outs.append(([f[k][()] for k in names], f.attrs["attempts"]))
        for k, name in enumerate(names):
            np.testing.assert_array_equal(outs[0][0][k], outs[1][0][k], name)
        self.assertEqual(outs[0][1], outs[1][1])

    def check_progress_bar(self, args, tail):
        """The bar of pw85-pack ARGS seen in a tmux capture, ending in tail."""
        tmux = shutil.which("tmux")
        if tmux is None:
            self.skipTest("tmux not installed")
        # A socket of its own per test: a server being killed by the
        # previous test on the same socket made new-session fail ("server
        # exited unexpectedly", once in a CI run).
        session = "pw85-pack-%d-%s" % (os.getpid(), self.id().rsplit(".", 1)[-1])
        env = dict(os.environ, TMUX="")
        command = "%s %s --out bar.h5; sleep 30" % (TOOL, args)
        subprocess.run([tmux, "-L", session, "new-session", "-d", "-s", session,
                        "-x", "160", "-y", "8", "-c", self.dir, command],
                       check=True, env=env)
        try:
            # Up to 30 s for the bar (the pane stays as long after the run):
            # under ASan on a slow machine the first one comes late.
            screen = ""
            for _ in range(600):
                time.sleep(0.05)
                screen = subprocess.run(
                    [tmux, "-L", session, "capture-pane", "-p", "-t", session],
                    capture_output=True, text=True, env=env).stdout
                if "left" in screen and "fraction" in screen:
                    break
            self.assertRegex(screen, r"\[[#.]{30}\] +[0-9.]+% fraction [0-9.]+ " + tail)
        finally:
            subprocess.run([tmux, "-L", session, "kill-server"], env=env)


class Pack(ToolCase):

    def test_files_fire(self):
        self.check_files([], "fire", 200, 0.5)

    def test_files_rsa(self):
        self.check_files(["--method", "rsa"], "rsa", 400, 0.2)

    def check_files(self, method, method_name, n, phi):
        m = 24
        r = run(["--n", str(n), "--axes", "1,0.5,0.2", "--fraction", str(phi),
                 "--seed", "7", "--out", "pack.h5", "--xyz", "pack.xyz",
                 "--voxels", str(m)] + method, self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        # no progress bar when stderr is not a terminal: one final line
        self.assertNotIn("\r", r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
        self.assertEqual(sorted(os.listdir(self.dir)),
                         ["pack.h5", "pack.xdmf", "pack.xyz"])
        side = (n * VOLUME / phi) ** (1 / 3)
        with h5py.File(os.path.join(self.dir, "pack.h5"), "r") as f:
            self.assertEqual(set(f.keys()), {"box", "centres", "forms", "axes",
                                             "quaternions", "image"})
            box = f["box"][()]
            self.assertEqual(f["box"].dtype, np.float64)
            np.testing.assert_allclose(box, [side] * 3, rtol=1e-15)
            for name, width in (("centres", 3), ("forms", 6), ("axes", 3),
                                ("quaternions", 4)):
                self.assertEqual(f[name].shape, (n, width), name)
                self.assertEqual(f[name].dtype, np.float64, name)
            c, q, a, p = (f[k][()] for k in ("centres", "forms", "axes",
                                              "quaternions"))
            img = f["image"][()]
            self.assertEqual(img.shape, (m, m, m))
            self.assertEqual(img.dtype, np.int32)
            attrs = dict(f.attrs)
            self.assertEqual(f.attrs["seed"].dtype, np.uint64)
        self.assertEqual(attrs["seed"], 7)
        self.assertEqual(attrs["method"], method_name)
        self.assertEqual(attrs["pw85_version"], VERSION)
        # Σ 4π/3·a0·a1·a2 / V, from the file's own axes and box
        expected = math.fsum(4 / 3 * math.pi * x * y * z for x, y, z in a) / box.prod()
        self.assertAlmostEqual(attrs["packing_fraction"], expected, delta=1e-15)
        self.assertAlmostEqual(attrs["packing_fraction"], phi, delta=1e-12)
        np.testing.assert_array_equal(a, np.tile([1.0, 0.5, 0.2], (n, 1)))
        self.assertTrue(((c >= 0) & (c < side)).all())
        # unit quaternions (w, x, y, z); the forms are R·diag(a²)·Rᵀ, R of
        # the quaternion normalised, in rationals: the library's constructor
        # within one ulp of the largest a² (1; measured: 0.25 ulp, fire, 200
        # ellipsoids; a float64 reference in NumPy is itself 6 ulps off)
        np.testing.assert_allclose(np.linalg.norm(p, axis=1), 1, atol=1e-15)
        for k in range(n):
            Q = exact_form(p[k], a[k])
            worst = max(abs(Fraction(q[k][i]) - Q[i]) for i in range(6))
            self.assertLessEqual(worst, Fraction(1, 2**52), k)
        # the image: phase fraction, and voxels against an exact decision
        self.assertEqual(attrs["image_fraction"], float(np.mean(img >= 0)))
        rng = np.random.default_rng(28)
        h = [Fraction(box[k]) / m for k in range(3)]
        for ijk in rng.integers(0, m, size=(40, 3)):
            point = [(int(ijk[k]) + Fraction(1, 2)) * h[k] for k in range(3)]
            want = -1
            for e in range(n):
                if want >= 0:
                    break
                # images within one box (the ellipsoids are far smaller)
                for shift in np.ndindex(3, 3, 3):
                    cc = [c[e][k] + (shift[k] - 1) * box[k] for k in range(3)]
                    if max(abs(float(point[k]) - cc[k]) for k in range(3)) > 1.01:
                        continue
                    if exact_inside(point, [Fraction(c[e][k]) + (shift[k] - 1)
                                            * Fraction(box[k])
                                            for k in range(3)], q[e]):
                        want = e
                        break
            self.assertEqual(img[tuple(ijk)], want, tuple(ijk))
        # XDMF: an XML document that points at the image
        root = ET.parse(os.path.join(self.dir, "pack.xdmf")).getroot()
        self.assertEqual(root.tag, "Xdmf")
        topo = root.find("./Domain/Grid/Topology")
        self.assertEqual(topo.get("TopologyType"), "3DCoRectMesh")
        self.assertEqual(topo.get("Dimensions").split(), [str(m + 1)] * 3)
        items = root.findall("./Domain/Grid/Geometry/DataItem")
        self.assertEqual([float(v) for v in items[1].text.split()],
                         [box[k] / m for k in range(3)])
        data = root.find("./Domain/Grid/Attribute/DataItem")
        self.assertEqual(data.text.strip(), "pack.h5:/image")
        self.assertEqual(data.get("Dimensions").split(), [str(m)] * 3)
        # extended XYZ, read by ASE: the same values, to the last bit
        atoms = ase.io.read(os.path.join(self.dir, "pack.xyz"), format="extxyz")
        self.assertEqual(len(atoms), n)
        np.testing.assert_array_equal(atoms.cell.lengths(), box)
        self.assertTrue(all(atoms.pbc))
        np.testing.assert_array_equal(atoms.positions, c)
        np.testing.assert_array_equal(atoms.arrays["aspherical_shape"], a)
        # OVITO's order x, y, z, w
        np.testing.assert_array_equal(atoms.arrays["orientation"],
                                      p[:, [1, 2, 3, 0]])

    def test_threads_fire(self):
        self.check_threads(["--n", "200", "--fraction", "0.5", "--axes", "1,0.5,0.2"],
                           ["centres", "forms"])

    def test_threads_rsa(self):
        self.check_threads(["--n", "3000", "--fraction", "0.2", "--method", "rsa",
                            "--axes", "1,0.5,0.2"], ["centres", "forms"])

    def check_short_of_target(self, n, phi):
        """A fire file short of its target: the box of the configuration
        (larger than the one of the target), the true packing fraction,
        below the target; returns it."""
        side = (n * VOLUME / phi) ** (1 / 3)
        with h5py.File(os.path.join(self.dir, "short.h5"), "r") as f:
            box, a = f["box"][()], f["axes"][()]
            self.assertEqual(f["centres"].shape, (n, 3))
            self.assertEqual(f["forms"].shape, (n, 6))
            self.assertEqual(f.attrs["method"], "fire")
            self.assertEqual(f.attrs["target_count"], n)
            got = f.attrs["packing_fraction"]
            self.assertTrue((f["centres"][()] < box).all())
        self.assertTrue((box > side).all(), (box, side))
        expected = math.fsum(4 / 3 * math.pi * x * y * z for x, y, z in a) / box.prod()
        self.assertAlmostEqual(got, expected, delta=1e-15)
        self.assertLess(got, phi)
        return got

    def test_interrupt_fire(self):
        # 200 at 0.8 is beyond jamming (16 s to find it, measured): cut at 1 s
        self.interrupt(["--n", "200", "--axes", "1,0.5,0.2", "--fraction", "0.8",
                        "--out", "short.h5"], 1)
        # (how far it got depends on the machine's speed: only that a
        # certified configuration is there)
        self.assertGreater(self.check_short_of_target(200, 0.8), 0.0)
        self.assertEqual(os.listdir(self.dir), ["short.h5"])
        # the packer cannot start from a configuration
        for extra in ([], ["--method", "fire"]):
            r = run(["--resume", "short.h5", "--out", "y.h5"] + extra, self.dir)
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
            self.assertIn("--resume: only for --method rsa", r.stderr)
        self.assertEqual(os.listdir(self.dir), ["short.h5"])

    def test_interrupt_and_resume_rsa(self):
        args = ["--n", "12000", "--axes", "1,0.5,0.2", "--fraction", "0.25",
                "--seed", "3", "--method", "rsa"]
        full = run(args + ["--out", "full.h5"], self.dir)
        self.assertEqual(full.returncode, 0, full.stderr)
        self.interrupt(args + ["--out", "cut.h5"], 0.3)
        with h5py.File(os.path.join(self.dir, "cut.h5"), "r") as f:
            count = f["centres"].shape[0]
            self.assertEqual(f["forms"].shape, (count, 6))
            self.assertLess(count, 12000)
            self.assertEqual(f.attrs["target_count"], 12000)
        # no temporary file left
        self.assertEqual(sorted(os.listdir(self.dir)), ["cut.h5", "full.h5"])
        res = run(["--resume", "cut.h5", "--out", "resumed.h5"], self.dir)
        self.assertEqual(res.returncode, 0, res.stderr)
        with h5py.File(os.path.join(self.dir, "full.h5"), "r") as f, \
                h5py.File(os.path.join(self.dir, "resumed.h5"), "r") as g:
            for name in ("box", "centres", "forms", "axes", "quaternions"):
                np.testing.assert_array_equal(f[name][()], g[name][()], name)
            self.assertEqual(f.attrs["attempts"], g.attrs["attempts"])

    def test_help_and_version(self):
        r = run(["--help"], self.dir)
        self.assertEqual(r.returncode, 0)
        for option in ("--n", "--axes", "--fraction", "--seed", "--threads",
                       "--out", "--xyz", "--voxels", "--time-limit",
                       "--resume", "--method"):
            self.assertIn(option, r.stdout)
        r = run(["--version"], self.dir)
        self.assertEqual(r.returncode, 0)
        self.assertEqual(r.stdout, "pw85-pack (pw85) %s\n" % VERSION)
        self.assertEqual(os.listdir(self.dir), [])

    def test_time_limit_fire(self):
        r = run(["--n", "200", "--axes", "1,0.5,0.2", "--fraction", "0.8",
                 "--time-limit", "0.5", "--out", "short.h5"], self.dir)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("time limit reached", r.stderr)
        self.check_short_of_target(200, 0.8)

    def test_time_limit_rsa(self):
        r = run(["--n", "200000", "--axes", "1,0.5,0.2", "--fraction", "0.25",
                 "--time-limit", "0.3", "--out", "t.h5", "--method", "rsa"], self.dir)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("time limit reached", r.stderr)
        with h5py.File(os.path.join(self.dir, "t.h5"), "r") as f:
            count = f["centres"].shape[0]
            self.assertTrue(0 < count < 200000, count)
            self.assertEqual(f["quaternions"].shape, (count, 4))
            side = (200000 * VOLUME / 0.25) ** (1 / 3)
            self.assertAlmostEqual(f.attrs["packing_fraction"],
                                   count * VOLUME / side**3, delta=1e-15)

    def test_progress_bar_in_tmux_fire(self):
        # beyond jamming (0.8): it runs long enough to be seen
        self.check_progress_bar("--n 200 --fraction 0.8 --axes 1,0.5,0.2",
                                r"of 0\.8000, [0-9]+ steps/s, ")

    def test_progress_bar_in_tmux_rsa(self):
        self.check_progress_bar("--n 30000 --fraction 0.28 --method rsa --axes 1,0.5,0.2",
                                r"of 0\.2800, [0-9]+/s, ")

    def test_bad_arguments(self):
        base = {"--n": "100", "--fraction": "0.2", "--out": "x.h5"}
        cases = [
            ({"--n": "0"}, "--n"), ({"--n": "abc"}, "--n"), ({"--n": "-3"}, "--n"),
            ({"--n": "1e3"}, "--n"), ({"--n": "100000001"}, "--n"),
            ({"--n": "1", "--fraction": "0.6"}, "--n: 1 ellipsoids give a box"),
            ({"--fraction": "0"}, "--fraction"), ({"--fraction": "1"}, "--fraction"),
            ({"--fraction": "nan"}, "--fraction"), ({"--fraction": "x"}, "--fraction"),
            ({"--axes": "1,2"}, "--axes"), ({"--axes": "1,2,0"}, "--axes"),
            ({"--axes": "1,2,3,4"}, "--axes"), ({"--axes": "1,-1,1"}, "--axes"),
            ({"--axes": "a,b,c"}, "--axes"),
            # empty fields (strtok skipped them: 1,,1,1 read as 1,1,1)
            ({"--axes": "1,,1,1"}, "--axes"), ({"--axes": "1,1,1,"}, "--axes"),
            ({"--axes": ",1,1,1"}, "--axes"), ({"--axes": "1,1,,"}, "--axes"),
            # numbers > 0 outside the range of the semi-axes: 1e-150 was
            # blamed on --fraction ("would fill to -nan"), 1e150 was "not
            # numbers > 0"
            ({"--axes": "1e-150,1e-150,1e-150"}, "--axes: 1e-150 is outside the range of "
             "the semi-axes, 1e-100 to 1e100, got '1e-150,1e-150,1e-150'"),
            ({"--axes": "1,1,1e150"}, "--axes: 1e150 is outside the range"),
            ({"--axes": "1e-320,1,1"}, "--axes: 1e-320 is outside the range"),
            ({"--axes": "1,1e-400,1"}, "--axes: 1e-400 is outside the range"),
            ({"--axes": "1,1,1e400"}, "--axes: 1e400 is outside the range"),
            ({"--axes": "-1e-400,1,1"}, "--axes: expected three numbers > 0"),
            # in range, but N of them at F need a box beyond a double
            ({"--axes": "1e100,1e100,1e100", "--n": "100000000", "--fraction": "0.5"},
             "--n, --axes and --fraction: 100000000 ellipsoids of semi-axes "
             "1e100,1e100,1e100 at 0.5 need a box whose volume is beyond the range of a "
             "double"),
            ({"--n": "100000000", "--fraction": "1e-300"},
             "100000000 ellipsoids of semi-axes 1,1,1 at 1e-300 need a box whose volume"),
            # a fraction whose box, rounded, 3 spheres fill to 1 or more: the
            # packer refused it with a generic "outside its documented domain"
            ({"--n": "3", "--fraction": "0.9999999999999999"},
             "--fraction: 0.9999999999999999 with 3 ellipsoids"),
            ({"--fraction": "0.99999999999999999"},
             "--fraction: '0.99999999999999999' is 1 in double precision"),
            ({"--seed": "-1"}, "--seed"), ({"--seed": "18446744073709551616"}, "--seed"),
            ({"--threads": "0"}, "--threads"), ({"--threads": "1025"}, "--threads"),
            ({"--voxels": "0"}, "--voxels"), ({"--voxels": "4097"}, "--voxels"),
            ({"--voxels": "4096"}, "the image needs 256.0 GiB"),
            ({"--time-limit": "0"}, "--time-limit"), ({"--time-limit": "-1"}, "--time-limit"),
            ({"--method": "annealing"}, "--method: unknown method 'annealing' (known: fire, rsa)"),
            ({"--resume": "x.h5", "--method": "fire"}, "--resume: only for --method rsa"),
            ({"--out": ""}, "--out"), ({"--xyz": ""}, "--xyz"),
            ({"--bogus": "1"}, "unknown option '--bogus'"),
        ]
        for change, message in cases:
            args = dict(base)
            args.update(change)
            argv = [x for kv in args.items() for x in kv]
            with self.subTest(change=change):
                r = run(argv, self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(os.listdir(self.dir), [])
        # the ends of the range of the semi-axes are packed
        for axes in ("1e-100,1e-100,1e-100", "1e100,1e100,1e100"):
            with self.subTest(axes=axes):
                r = run(["--n", "10", "--fraction", "0.3", "--axes", axes, "--out", "e.h5"],
                        self.dir)
                self.assertEqual(r.returncode, 0, r.stderr)
                with h5py.File(os.path.join(self.dir, "e.h5"), "r") as f:
                    self.assertAlmostEqual(f.attrs["packing_fraction"], 0.3, delta=1e-15)
                os.remove(os.path.join(self.dir, "e.h5"))
        for argv, message in [(["--fraction", "0.2", "--out", "x.h5"], "--n"),
                              (["--n", "10", "--out", "x.h5"], "--fraction"),
                              (["--n", "10", "--fraction", "0.2"], "--out"),
                              (["--n"], "--n: a value is needed")]:
            with self.subTest(argv=argv):
                r = run(argv, self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(os.listdir(self.dir), [])

    def test_colliding_outputs(self):
        """Two outputs naming one file, however spelt: refused (one line
        naming both options, exit status 2, nothing written). They were
        written one over the other with exit status 0: --out x.xdmf
        --voxels M left an HDF5 file replaced by its own XDMF."""
        ok = ["--n", "50", "--fraction", "0.2", "--method", "rsa"]
        os.mkdir(os.path.join(self.dir, "sub"))
        os.symlink(".", os.path.join(self.dir, "here"))
        with open(os.path.join(self.dir, "real.h5"), "w") as f:
            f.write("untouched\n")
        os.symlink("real.h5", os.path.join(self.dir, "link.h5"))
        before = sorted(os.listdir(self.dir))
        absolute = os.path.join(os.path.realpath(self.dir), "a.h5")
        cases = [
            (["--out", "col.xdmf", "--voxels", "8"], "--out and --voxels"),
            (["--2d", "--out", "col.xdmf", "--voxels", "8"], "--out and --voxels"),
            (["--out", "sub/col.xdmf", "--voxels", "8"], "--out and --voxels"),
            (["--out", "a.h5", "--xyz", "a.h5"], "--out and --xyz"),
            (["--out", "a.h5", "--xyz", "./a.h5"], "--out and --xyz"),
            (["--out", "a.h5", "--xyz", "sub/../a.h5"], "--out and --xyz"),
            (["--out", "a.h5", "--xyz", "here/a.h5"], "--out and --xyz"),
            (["--out", "a.h5", "--xyz", absolute], "--out and --xyz"),
            (["--out", "real.h5", "--xyz", "link.h5"], "--out and --xyz"),
            (["--out", "a.h5", "--xyz", "a.xdmf", "--voxels", "8"], "--xyz and --voxels"),
            (["--out", "a.h5", "--xyz", "here/a.xdmf", "--voxels", "8"],
             "--xyz and --voxels"),
            (["--out", "sub/a", "--xyz", "sub/a.xdmf", "--voxels", "8"],
             "--xyz and --voxels"),
        ]
        for argv, message in cases:
            with self.subTest(argv=argv):
                r = run(ok + argv, self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(sorted(os.listdir(self.dir)), before)
                self.assertEqual(os.listdir(os.path.join(self.dir, "sub")), [])
        with open(os.path.join(self.dir, "real.h5")) as f:
            self.assertEqual(f.read(), "untouched\n")
        # the file to resume: --out may replace it, not --xyz or the XDMF
        r = run(ok + ["--out", "p.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.dir, "p.h5"), "rb") as f:
            packed = f.read()
        shutil.copy(os.path.join(self.dir, "p.h5"), os.path.join(self.dir, "q.xdmf"))
        for argv, message in [
                (["--resume", "p.h5", "--out", "y.h5", "--xyz", "p.h5"], "--xyz and --resume"),
                (["--resume", "p.h5", "--out", "y.h5", "--xyz", "here/p.h5"],
                 "--xyz and --resume"),
                (["--resume", "p.h5", "--out", "p.h5", "--xyz", "./p.h5"], "--out and --xyz"),
                (["--resume", "q.xdmf", "--out", "q.h5", "--voxels", "4"],
                 "--voxels and --resume"),
                (["--resume", "p.h5", "--out", "p.h5", "--voxels", "4", "--xyz", "p.xdmf"],
                 "--xyz and --voxels")]:
            with self.subTest(resume=argv):
                r = run(argv + ["--n", "60"], self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                for name in ("p.h5", "q.xdmf"):
                    with open(os.path.join(self.dir, name), "rb") as f:
                        self.assertEqual(f.read(), packed, name)
        os.remove(os.path.join(self.dir, "q.xdmf"))
        # distinct names are accepted, and so is resuming in place
        r = run(["--resume", "p.h5", "--n", "60", "--out", "p.h5", "--xyz", "p.xyz",
                 "--voxels", "4"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        with h5py.File(os.path.join(self.dir, "p.h5"), "r") as f:
            self.assertEqual(f["centres"].shape, (60, 3))
        ET.parse(os.path.join(self.dir, "p.xdmf"))
        self.assertEqual(ase.io.read(os.path.join(self.dir, "p.xyz"),
                                     format="extxyz").positions.shape, (60, 3))

    def test_resume_fraction(self):
        """--fraction under --resume: the target of the file's box and the
        target count, or refused (exit status 2, one line, nothing written)
        as a differing --seed is; it was ignored, with exit status 0."""
        ok = ["--method", "rsa", "--seed", "4"]
        r = run(ok + ["--n", "100", "--fraction", "0.2", "--out", "p.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        for argv, message in [
                (["--fraction", "0.3"], "--fraction: 0.3 differs from the target of p.h5 "
                 "(100 ellipsoids in its box: 0.2); with --resume, --n sets the target"),
                (["--fraction", "0.2000001"], "--fraction: 0.2000001 differs"),
                (["--n", "150", "--fraction", "0.2"],
                 "--fraction: 0.2 differs from the target of p.h5 (150 ellipsoids in its "
                 "box: 0.3)")]:
            with self.subTest(argv=argv):
                r = run(["--resume", "p.h5", "--out", "y.h5"] + argv, self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(os.listdir(self.dir), ["p.h5"])
        # the fraction of the file, or of its box with the count of --n
        for argv, count in [(["--fraction", "0.2"], 100),
                            (["--n", "150", "--fraction", "0.3"], 150)]:
            with self.subTest(argv=argv):
                r = run(["--resume", "p.h5", "--out", "y.h5"] + argv, self.dir)
                self.assertEqual(r.returncode, 0, r.stderr)
                with h5py.File(os.path.join(self.dir, "y.h5"), "r") as f:
                    self.assertEqual(f["centres"].shape, (count, 3))
                    self.assertAlmostEqual(f.attrs["packing_fraction"], count / 500,
                                           delta=1e-15)

    def test_xdmf_names(self):
        """The XDMF companion well-formed XML (xml.etree) for any name of
        --out that XML can hold, and naming it: "--" went into its comment,
        & and < into its text, unescaped. Names that XML cannot hold (control
        characters, not UTF-8) refused with --voxels (one line, exit status
        2, nothing written)."""
        ok = ["--n", "20", "--fraction", "0.2", "--method", "rsa", "--voxels", "4"]
        for dim in ([], ["--2d"]):
            for stem in ("run--1", "a&b", "a<b>c", "q\"u'o", "a]]>b", "x&amp;y",
                         "\u00e9--\u00fc", "-->"):
                with self.subTest(stem=stem, dim=dim):
                    try:
                        r = run(ok + dim + ["--out", stem + ".h5"], self.dir)
                        self.assertEqual(r.returncode, 0, r.stderr)
                        self.assertEqual(sorted(os.listdir(self.dir)),
                                         sorted([stem + ".h5", stem + ".xdmf"]))
                        path = os.path.join(self.dir, stem + ".xdmf")
                        root = ET.parse(path).getroot()
                        data = root.find("./Domain/Grid/Attribute/DataItem")
                        self.assertEqual(data.get("Format"), "HDF")
                        self.assertEqual(data.text, stem + ".h5:/image")
                    finally:
                        for name in os.listdir(self.dir):
                            os.remove(os.path.join(self.dir, name))
        # "\udcff": the byte 0xff (os.fsencode); 0xc0 0xaf: "/" overlong
        for name in ("a\nb.h5", "tab\tb.h5", "cr\rb.h5", "a\udcffb.h5", "a\udcc0\udcafb.h5"):
            with self.subTest(name=name):
                try:
                    r = run(ok + ["--out", name], self.dir, errors="backslashreplace")
                    self.assertEqual(r.returncode, 2, r.stderr)
                    self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                    self.assertIn("--out and --voxels: the name of --out goes into the XDMF "
                                  "companion, which XML cannot hold", r.stderr)
                    self.assertEqual(os.listdir(self.dir), [])
                finally:
                    for name in os.listdir(self.dir):
                        os.remove(os.path.join(self.dir, name))
        # without --voxels, no XML: the name is the file system's business
        r = run(ok[:-2] + ["--out", "a\nb.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(os.listdir(self.dir), ["a\nb.h5"])

    def test_bad_files(self):
        ok = ["--n", "100", "--fraction", "0.2", "--method", "rsa"]
        # an output that cannot be written
        r = run(ok + ["--out", "/nonexistent-dir/x.h5"], self.dir)
        self.assertEqual(r.returncode, 1)
        self.assertIn("cannot write /nonexistent-dir/x.h5", r.stderr)
        self.assertEqual(len(r.stderr.splitlines()), 1)
        # a good file, untouched by every failed run below
        r = run(ok + ["--out", "good.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(os.path.join(self.dir, "good.h5"), "rb") as f:
            good = f.read()
        with open(os.path.join(self.dir, "text.h5"), "w") as f:
            f.write("not HDF5\n")
        with open(os.path.join(self.dir, "cut.h5"), "wb") as f:
            f.write(good[:len(good) // 2])
        with h5py.File(os.path.join(self.dir, "other.h5"), "w") as f:
            f["box"] = [1.0, 2.0]
        with h5py.File(os.path.join(self.dir, "nobox.h5"), "w") as f:
            f["positions"] = np.zeros((3, 3))
        def good_copy(name):
            """A copy of good.h5 named name, open for editing."""
            path = os.path.join(self.dir, name)
            shutil.copy(os.path.join(self.dir, "good.h5"), path)
            return h5py.File(path, "r+")

        # /axes edited, /forms not: the new ellipsoids would not be those
        # of the file (--resume used /axes without checking it)
        with good_copy("axes.h5") as f:
            f["axes"][...] = 2 * f["axes"][()]
        with good_copy("overlap.h5") as f:
            f["centres"][1] = f["centres"][0]
            f["forms"][1] = f["forms"][0]
        # sizes from a corrupted file: a count of rows whose bytes wrap
        # around a size_t, a target count beyond --n's range, or below the
        # count of the file (they were allocated as such: the tool wrote
        # past its buffers, or blamed --n, which was not given)
        with good_copy("huge.h5") as f:
            del f["centres"]
            f.create_dataset("centres", shape=(2**61 + 1, 3), dtype="f8",
                             chunks=(1, 3))
        for name, value in (("bigtarget.h5", 2**61 + 1),
                            ("smalltarget.h5", 5)):
            with good_copy(name) as f:
                f.attrs["target_count"] = np.uint64(value)
        # the attributes: one missing, a number and a string of the wrong
        # type (both readers of tools/pw85-pack/io.c)
        with good_copy("noseed.h5") as f:
            del f.attrs["seed"]
        with good_copy("textseed.h5") as f:
            f.attrs["seed"] = "five"
        with good_copy("intmethod.h5") as f:
            f.attrs["method"] = np.int32(1)
        for name, message in [("huge.h5", "/centres has 2305843009213693953 rows"),
                              ("bigtarget.h5", "target_count 2305843009213693953"),
                              ("smalltarget.h5", "target_count 5"),
                              ("missing.h5", "cannot read"),
                              ("text.h5", "not an HDF5 file"),
                              ("cut.h5", "not an HDF5 file"),
                              ("other.h5", "/box has not the documented type and shape"),
                              ("nobox.h5", "no dataset /box"),
                              ("noseed.h5", "no attribute seed"),
                              ("textseed.h5",
                               "attribute seed has not the documented type"),
                              ("intmethod.h5", "attribute method is not a string"),
                              ("overlap.h5", "pairs of ellipsoids overlap"),
                              ("axes.h5", "/forms[0] is not the form of /axes[0] "
                               "and /quaternions[0]")]:
            with self.subTest(resume=name):
                r = run(["--resume", name, "--out", "good.h5"], self.dir)
                self.assertEqual(r.returncode, 1, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                with open(os.path.join(self.dir, "good.h5"), "rb") as f:
                    self.assertEqual(f.read(), good)
        r = run(["--resume", "good.h5", "--seed", "5", "--out", "y.h5"], self.dir)
        self.assertEqual(r.returncode, 2)
        self.assertIn("--seed: differs", r.stderr)
        r = run(["--resume", "good.h5", "--n", "50", "--out", "y.h5"], self.dir)
        self.assertEqual(r.returncode, 2)
        self.assertIn("--n: 50 is fewer", r.stderr)
        self.assertFalse([x for x in os.listdir(self.dir) if x.startswith("y.h5")])


if __name__ == "__main__":
    TOOL, VERSION = os.path.abspath(sys.argv[1]), sys.argv[2]
    unittest.main(argv=sys.argv[:1], verbosity=2)
