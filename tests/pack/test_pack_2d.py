# SPDX-License-Identifier: BSD-3-Clause
"""pw85-pack --2d (issue 29, item 2: "it packs ellipses too") as a user runs
it, for both methods: the 2D layout read back by h5py with the documented
values; every pair of ellipses and every periodic image proved disjoint by
an exact computation independent of the library; every pixel of the image
against an independent decision, and its area fraction against the
packing's within a bound from the pixel size; the XDMF parsed; the
extended XYZ read by ASE; the same file for 1 and 2 threads; Ctrl-C, the
time limit and --resume as in 3D; bad inputs (a wrong number of axes, a
file of the other dimension): one line, exit status 2, nothing written.

Usage: test_pack_2d.py PW85-PACK VERSION  (run by meson, /usr/bin/python3)
Exit status 77 (a skip) when h5py, ASE or mpmath is missing.
"""

# The modules of test_pack.py (which exits 77, a skip, without h5py, NumPy
# or ASE), and what the tests of ellipsoids and ellipses share.
import test_pack as common
from test_pack import (ET, Fraction, ToolCase, ase, h5py, math, np, os, run, shutil, sys,
                       unittest)

try:
    import mpmath
except ImportError as e:  # pragma: no cover
    print("SKIP:", e)
    sys.exit(77)

AXES = (1.0, 0.5)
AREA = math.pi * AXES[0] * AXES[1]


def read(path):
    with h5py.File(path, "r") as f:
        return ({k: f[k][()] for k in f.keys()}, dict(f.attrs),
                {k: (f[k].shape, f[k].dtype) for k in f.keys()})


def form_error(q, a, theta):
    """The largest |q − Q| over the entries, Q = R(θ)·diag(a²)·R(θ)ᵀ
    (docs/ellipses.rst, "The angle") of the double θ and a, in mpmath at 40
    digits."""
    worst = mpmath.mpf(0)
    for k in range(len(theta)):
        t = mpmath.mpf(float(theta[k]))
        c, s = mpmath.cos(t), mpmath.sin(t)
        a0, a1 = mpmath.mpf(float(a[k][0])) ** 2, mpmath.mpf(float(a[k][1])) ** 2
        exact = (c * c * a0 + s * s * a1, c * s * (a0 - a1), s * s * a0 + c * c * a1)
        for i in range(3):
            worst = max(worst, abs(mpmath.mpf(float(q[k][i])) - exact[i]))
    return float(worst)


def f_float(lam, r, q1, q2):
    """The contact function f(λ) = λ(1 − λ) rᵀ Q(λ)⁻¹ r, Q(λ) = (1 − λ)Q1 +
    λQ2 (docs/ellipses.rst), for arrays of pairs (last axis) and of λ."""
    m0 = (1 - lam) * q1[0] + lam * q2[0]
    m1 = (1 - lam) * q1[1] + lam * q2[1]
    m2 = (1 - lam) * q1[2] + lam * q2[2]
    det = m0 * m2 - m1 * m1
    quad = (m2 * r[0] ** 2 - 2 * m1 * r[0] * r[1] + m0 * r[1] ** 2) / det
    return lam * (1 - lam) * quad


def f_exact(lam, r, q1, q2):
    """f(λ) in rationals, from the doubles given: the value at this λ."""
    lam = Fraction(lam)
    r = [Fraction(x) for x in r]
    m = [(1 - lam) * Fraction(x) + lam * Fraction(y) for x, y in zip(q1, q2)]
    det = m[0] * m[2] - m[1] * m[1]
    quad = m[2] * r[0] ** 2 - 2 * m[1] * r[0] * r[1] + m[0] * r[1] ** 2
    return lam * (1 - lam) * quad / det


def exact_r(cj, ci, shift, box):
    """r = c_j + shift∘L − c_i, exactly (rationals)."""
    return [Fraction(cj[k]) + shift[k] * Fraction(box[k]) - Fraction(ci[k])
            for k in range(2)]


def certify_disjoint(test, c, q, a, box):
    """Every pair (i, j) and every image n ∈ {−1, 0, 1}² (the others are
    farther than the side, wider than every ellipse) proved disjoint: either
    |r| > a_max,i + a_max,j (bounding circles), or f(λ) > 1 at some λ,
    computed exactly: μ² = max f ≥ f(λ) > 1 (the overlap test of the
    library says disjoint iff μ² > 1). λ: the maximiser in float64 (a grid,
    then golden sections); no value of the library is used. Returns the
    count of pairs that needed the certificate, and the least f found."""
    n = len(c)
    reach = a.max(axis=1)
    test.assertTrue((2 * reach.max() < box).all())
    i, j = np.triu_indices(n, 1)
    checked, least = 0, math.inf
    for sx in (-1, 0, 1):
        for sy in (-1, 0, 1):
            r = c[j] + np.array([sx, sy]) * box - c[i]
            near = np.hypot(r[:, 0], r[:, 1]) <= (reach[i] + reach[j]) * (1 + 1e-12)
            # the pairs (i, i) are not in the list: an ellipse meets none of
            # its images, as 2·a_max < L (asserted above)
            ii, jj, rr = i[near], j[near], r[near].T
            if len(ii) == 0:
                continue
            q1, q2 = q[ii].T, q[jj].T
            grid = np.linspace(0, 1, 129)[1:-1, None]
            best = grid[np.argmax(f_float(grid, rr, q1, q2), axis=0), 0]
            lo, hi = np.maximum(best - 1 / 128, 1e-9), np.minimum(best + 1 / 128, 1 - 1e-9)
            g = (math.sqrt(5) - 1) / 2
            for _ in range(60):
                x1, x2 = hi - g * (hi - lo), lo + g * (hi - lo)
                up = f_float(x1, rr, q1, q2) < f_float(x2, rr, q1, q2)
                lo, hi = np.where(up, x1, lo), np.where(up, hi, x2)
            lam = (lo + hi) / 2
            for k in range(len(ii)):
                e, f = int(ii[k]), int(jj[k])
                value = f_exact(float(lam[k]), exact_r(c[f], c[e], (sx, sy), box),
                                q[e], q[f])
                test.assertGreater(value, 1, (e, f, sx, sy))
                least = min(least, float(value))
                checked += 1
    return checked, least


def exact_inside(point, c, q):
    """(m − c)ᵀ Q⁻¹ (m − c) ≤ 1 in rationals: dᵀ adj(Q) d ≤ det Q."""
    d = [point[k] - c[k] for k in range(2)]
    q0, q1, q2 = (Fraction(x) for x in q)
    return q2 * d[0] ** 2 - 2 * q1 * d[0] * d[1] + q0 * d[1] ** 2 <= q0 * q2 - q1 * q1


def image_of(test, c, q, box, m):
    """The image as pw85-pack documents it, decided here: pixel (i, j) is the
    point ((i + ½)L0/m, (j + ½)L1/m); its value the ellipse containing it
    (any periodic image), −1 for none. Float64 where the quadratic form is
    farther than 1e-9 from 1 (its rounding error is below 1e-13 here),
    rationals otherwise."""
    h = box / m
    centres = (np.arange(m) + 0.5)
    want = np.full((m, m), -1, dtype=np.int64)
    q0, q1, q2 = q[:, 0], q[:, 1], q[:, 2]
    det = q0 * q2 - q1 * q1
    exact_count = 0
    for e in range(len(c)):
        for sx in (-1, 0, 1):
            for sy in (-1, 0, 1):
                ce = c[e] + np.array([sx, sy]) * box
                reach = math.sqrt(max(q0[e], q2[e]))
                i0 = max(0, int(math.floor((ce[0] - reach) / h[0])) - 1)
                i1 = min(m, int(math.ceil((ce[0] + reach) / h[0])) + 1)
                j0 = max(0, int(math.floor((ce[1] - reach) / h[1])) - 1)
                j1 = min(m, int(math.ceil((ce[1] + reach) / h[1])) + 1)
                if i0 >= i1 or j0 >= j1:
                    continue
                x = centres[i0:i1, None] * h[0] - ce[0]
                y = centres[None, j0:j1] * h[1] - ce[1]
                v = (q2[e] * x * x - 2 * q1[e] * x * y + q0[e] * y * y) / det[e]
                inside = v <= 1
                for di, dj in zip(*np.nonzero(np.abs(v - 1) <= 1e-9)):
                    exact_count += 1
                    point = [(i0 + di + Fraction(1, 2)) * Fraction(box[0]) / m,
                             (j0 + dj + Fraction(1, 2)) * Fraction(box[1]) / m]
                    cc = [Fraction(c[e][0]) + sx * Fraction(box[0]),
                          Fraction(c[e][1]) + sy * Fraction(box[1])]
                    inside[di, dj] = exact_inside(point, cc, q[e])
                block = want[i0:i1, j0:j1]
                test.assertFalse(((block >= 0) & inside).any(), "pixels in two ellipses")
                block[inside] = e
    return want, exact_count


def perimeter_bound(a0, a1):
    """An upper bound of the perimeter of an ellipse: that of its bounding
    rectangle, 4(a0 + a1), the perimeter of a convex set being at most
    that of any convex set containing it."""
    return 4 * (a0 + a1)


class Pack2D(ToolCase):
    def path(self, name):
        return os.path.join(self.dir, name)

    def test_files_fire(self):
        self.check_files([], "fire", 300, 0.6, 200)

    def test_files_rsa(self):
        self.check_files(["--method", "rsa"], "rsa", 1000, 0.35, 256)

    def check_files(self, method, method_name, n, phi, m):
        r = run(["--2d", "--n", str(n), "--axes", "1,0.5", "--fraction", str(phi),
                 "--seed", "7", "--out", "pack.h5", "--xyz", "pack.xyz",
                 "--voxels", str(m)] + method, self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertNotIn("\r", r.stderr)
        self.assertEqual(r.stderr.splitlines(),
                         ["pw85-pack: done: %d of %d ellipses, packing fraction %.6f, "
                          "written to pack.h5" % (n, n, phi)])
        self.assertEqual(sorted(os.listdir(self.dir)), ["pack.h5", "pack.xdmf", "pack.xyz"])
        data, attrs, shapes = read(self.path("pack.h5"))
        # the 2D layout (docs/microstructures.rst)
        self.assertEqual(shapes, {"box": ((2,), np.float64),
                                  "centres": ((n, 2), np.float64),
                                  "forms": ((n, 3), np.float64),
                                  "axes": ((n, 2), np.float64),
                                  "angles": ((n,), np.float64),
                                  "image": ((m, m), np.int32)})
        self.assertEqual(set(attrs), {"packing_fraction", "seed", "pw85_version", "method",
                                      "attempts", "target_count", "image_fraction",
                                      "dimension"})
        self.assertEqual(attrs["dimension"], 2)
        self.assertEqual(attrs["dimension"].dtype, np.int32)
        self.assertEqual(attrs["seed"], 7)
        self.assertEqual(attrs["method"], method_name)
        self.assertEqual(attrs["pw85_version"], common.VERSION)
        self.assertEqual(attrs["target_count"], n)
        box, c, q, a, theta = (data[k] for k in ("box", "centres", "forms", "axes", "angles"))
        side = math.sqrt(n * AREA / phi)
        np.testing.assert_allclose(box, [side, side], rtol=1e-15)
        np.testing.assert_array_equal(a, np.tile(AXES, (n, 1)))
        self.assertTrue(((c >= 0) & (c < box)).all())
        self.assertTrue(((theta >= -math.pi) & (theta <= math.pi)).all())
        # Σπ·a0·a1 / (L0·L1), from the file's own axes and box
        expected = math.fsum(math.pi * x * y for x, y in a) / box.prod()
        self.assertAlmostEqual(attrs["packing_fraction"], expected, delta=1e-15)
        self.assertAlmostEqual(attrs["packing_fraction"], phi, delta=1e-12)
        # the forms are those of the axes and angles, pw85_2d_ellipse()'s:
        # within one ulp of the largest a² (1) of the exact entries, as the
        # 3D test asks of quaternions (measured: 1.64e-16, 0.74 ulp, rsa,
        # 2000 ellipses; not each entry correctly rounded: up to 1.9 ulps of
        # the entry)
        mpmath.mp.dps = 40
        self.assertLessEqual(form_error(q, a, theta), 2.0**-52)
        # no pair overlaps, proved exactly
        checked, least = certify_disjoint(self, c, q, a, box)
        self.assertGreater(checked, n // 2)  # the certificate ran on many pairs
        # the image: every pixel against an independent decision
        img = data["image"]
        want, exact_count = image_of(self, c, q, box, m)
        np.testing.assert_array_equal(img, want)
        fraction = float(np.mean(img >= 0))
        self.assertEqual(attrs["image_fraction"], fraction)
        # Area fraction against the packing's. A pixel whose centre is in an
        # ellipse E lies in E grown by h/√2 (h the pixel side); one whose
        # centre is not lies outside E shrunk by h/√2; so the pixels of E
        # cover its area within the band of width h/√2 either side of its
        # boundary: |count·h² − |E|| ≤ P·h/√2 + πh²/2 (Steiner), P ≤ 4(a0 +
        # a1). Summed over the (disjoint) ellipses: a bound that holds for
        # any placement (0.27 and 0.24 here; measured errors, cancelling
        # between ellipses: 5.6e-4 rsa, 9.5e-4 fire; every pixel is checked
        # above, this checks the fraction the file reports against φ).
        h = float(box[0]) / m
        bound = n * (perimeter_bound(*AXES) * h / math.sqrt(2)
                     + math.pi * h * h / 2) / float(box.prod())
        self.assertLessEqual(abs(fraction - attrs["packing_fraction"]), bound)
        # XDMF: a 2DCoRectMesh over the image
        root = ET.parse(self.path("pack.xdmf")).getroot()
        self.assertEqual(root.tag, "Xdmf")
        topo = root.find("./Domain/Grid/Topology")
        self.assertEqual(topo.get("TopologyType"), "2DCoRectMesh")
        self.assertEqual(topo.get("Dimensions").split(), [str(m + 1)] * 2)
        geometry = root.find("./Domain/Grid/Geometry")
        self.assertEqual(geometry.get("GeometryType"), "ORIGIN_DXDY")
        items = geometry.findall("DataItem")
        self.assertEqual([float(v) for v in items[0].text.split()], [0.0, 0.0])
        self.assertEqual([float(v) for v in items[1].text.split()],
                         [box[k] / m for k in range(2)])
        data_item = root.find("./Domain/Grid/Attribute/DataItem")
        self.assertEqual(data_item.text.strip(), "pack.h5:/image")
        self.assertEqual(data_item.get("Dimensions").split(), [str(m)] * 2)
        # extended XYZ, read by ASE: the plane z = 0, the documented columns
        atoms = ase.io.read(self.path("pack.xyz"), format="extxyz")
        self.assertEqual(len(atoms), n)
        self.assertEqual(list(atoms.pbc), [True, True, False])
        np.testing.assert_array_equal(atoms.cell.lengths(), list(box) + [2 * max(AXES)])
        self.assertEqual(atoms.info["dimension"], 2)
        np.testing.assert_array_equal(atoms.positions[:, :2], c)
        np.testing.assert_array_equal(atoms.positions[:, 2], 0)
        np.testing.assert_array_equal(atoms.arrays["angle"], theta)
        np.testing.assert_array_equal(atoms.arrays["aspherical_shape"],
                                      np.tile(AXES + (min(AXES),), (n, 1)))
        # OVITO's order x, y, z, w: a turn by θ about z, (0, 0, sin θ/2, cos θ/2),
        # each within 2⁻⁵³ (an ulp below 1) of the exact value (mpmath; the C
        # library's sin and cos; measured: 0.503·2⁻⁵³ at most)
        p = atoms.arrays["orientation"]
        np.testing.assert_array_equal(p[:, :2], 0)
        worst = 0
        for k in range(n):
            half = mpmath.mpf(float(theta[k])) / 2
            worst = max(worst, abs(mpmath.mpf(float(p[k, 2])) - mpmath.sin(half)),
                        abs(mpmath.mpf(float(p[k, 3])) - mpmath.cos(half)))
        self.assertLessEqual(worst, 2.0**-53)

    def test_image_on_boundaries(self):
        """Pixel centres exactly on ellipses (and on a periodic image of
        one): inside, as the exact decision says. Two ellipses of axes
        (1, 0.5) at angle 0 (their forms (1, 0, 0.25) exact) placed by hand
        in a file that --resume completes at once (its target is its count)
        and images at 16² in a square of side 8: the pixel centres
        ((i + ½)/2, (j + ½)/2) at (±1, 0) and (0, ±0.5) from a centre are
        on its boundary."""
        centres = np.array([[4.25, 4.25], [0.25, 1.75]])
        with h5py.File(self.path("hand.h5"), "w") as f:
            f["box"] = np.array([8.0, 8.0])
            f["centres"] = centres
            f["forms"] = np.tile([1.0, 0.0, 0.25], (2, 1))
            f["axes"] = np.tile([1.0, 0.5], (2, 1))
            f["angles"] = np.zeros(2)
            f.attrs["packing_fraction"] = 2 * AREA / 64
            f.attrs["seed"] = np.uint64(1)
            f.attrs["pw85_version"] = common.VERSION
            f.attrs["method"] = "rsa"
            f.attrs["attempts"] = np.uint64(2)
            f.attrs["target_count"] = np.uint64(2)
            f.attrs["dimension"] = np.int32(2)
        r = run(["--2d", "--resume", "hand.h5", "--out", "img.h5", "--voxels", "16"],
                self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        data, attrs, shapes = read(self.path("img.h5"))
        img = data["image"]
        on = {(10, 8): 0, (6, 8): 0, (8, 9): 0, (8, 7): 0,  # e0 at (4.25, 4.25)
              (2, 3): 1, (14, 3): 1, (0, 4): 1, (0, 2): 1}  # e1, (14, 3) via x − 8
        for pixel, e in on.items():
            self.assertEqual(img[pixel], e, pixel)
        want, exact_count = image_of(self, data["centres"], data["forms"], data["box"], 16)
        self.assertGreaterEqual(exact_count, 8)  # the rationals decided these
        np.testing.assert_array_equal(img, want)
        # just outside: the next pixel along each axis
        for pixel in ((11, 8), (5, 8), (8, 10), (8, 6), (3, 3), (13, 3)):
            self.assertEqual(img[pixel], -1, pixel)

    def test_threads_fire(self):
        self.check_threads(["--2d", "--n", "300", "--fraction", "0.65", "--axes", "1,0.5"],
                           ["box", "centres", "forms", "axes", "angles"])

    def test_threads_rsa(self):
        self.check_threads(["--2d", "--n", "20000", "--fraction", "0.4", "--method", "rsa",
                            "--axes", "1,0.5"], ["box", "centres", "forms", "axes", "angles"])

    def test_interrupt_and_resume_rsa(self):
        args = ["--2d", "--n", "100000", "--axes", "1,0.5", "--fraction", "0.45",
                "--seed", "3", "--method", "rsa"]
        full = run(args + ["--out", "full.h5"], self.dir)
        self.assertEqual(full.returncode, 0, full.stderr)
        self.interrupt(args + ["--out", "cut.h5"], 0.3)
        data, attrs, shapes = read(self.path("cut.h5"))
        count = shapes["centres"][0][0]
        self.assertLess(count, 100000)
        self.assertEqual(shapes["angles"][0], (count,))
        self.assertEqual(attrs["target_count"], 100000)
        self.assertEqual(sorted(os.listdir(self.dir)), ["cut.h5", "full.h5"])
        # a file of ellipses resumes with --2d only
        r = run(["--resume", "cut.h5", "--out", "x.h5"], self.dir)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(r.stderr.splitlines(),
                         ["pw85-pack: --resume: cut.h5 holds ellipses (a 2D packing): "
                          "add --2d (see --help)"])
        self.assertEqual(sorted(os.listdir(self.dir)), ["cut.h5", "full.h5"])
        res = run(["--2d", "--resume", "cut.h5", "--out", "resumed.h5"], self.dir)
        self.assertEqual(res.returncode, 0, res.stderr)
        f, g = read(self.path("full.h5")), read(self.path("resumed.h5"))
        for name in ("box", "centres", "forms", "axes", "angles"):
            np.testing.assert_array_equal(f[0][name], g[0][name], name)
        self.assertEqual(f[1], g[1])

    def test_interrupt_fire(self):
        # 2000 ellipses at 0.95, beyond jamming (0.82 certified after 3 s in
        # a release build, measured): cut at 1 s
        self.interrupt(["--2d", "--n", "2000", "--axes", "1,0.5", "--fraction", "0.95",
                        "--out", "short.h5"], 1)
        self.check_short_of_target(2000, 0.95)
        self.assertEqual(os.listdir(self.dir), ["short.h5"])

    def test_time_limit(self):
        r = run(["--2d", "--n", "2000", "--axes", "1,0.5", "--fraction", "0.95",
                 "--time-limit", "0.5", "--out", "short.h5"], self.dir)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("time limit reached", r.stderr)
        self.check_short_of_target(2000, 0.95)
        r = run(["--2d", "--n", "1000000", "--axes", "1,0.5", "--fraction", "0.4",
                 "--time-limit", "0.3", "--method", "rsa", "--out", "t.h5"], self.dir)
        self.assertEqual(r.returncode, 3, r.stderr)
        self.assertIn("time limit reached", r.stderr)
        data, attrs, shapes = read(self.path("t.h5"))
        count = shapes["centres"][0][0]
        self.assertTrue(0 < count < 1000000, count)
        side = math.sqrt(1000000 * AREA / 0.4)
        self.assertAlmostEqual(attrs["packing_fraction"], count * AREA / side**2, delta=1e-15)

    def test_xyz_without_ellipses(self):
        # A time limit before the first ellipse (rsa checks it first): the
        # file holds none, and the XYZ cell is still not singular, its
        # height the box's larger side (twice the largest semi-axis else).
        r = run(["--2d", "--n", "100000", "--axes", "1,0.5", "--fraction", "0.5",
                 "--method", "rsa", "--time-limit", "1e-9", "--out", "e.h5",
                 "--xyz", "e.xyz"], self.dir)
        self.assertEqual(r.returncode, 3, r.stderr)
        with open(self.path("e.xyz")) as f:
            count = int(f.readline())
            header = f.readline()
        cell = [float(x) for x in header.split('Lattice="')[1].split('"')[0].split()]
        expected = max(cell[0], cell[4]) if count == 0 else 2.0
        self.assertEqual(cell[8], expected, (count, cell))

    def check_short_of_target(self, n, phi):
        """A fire file short of its target: the larger square of its
        certified configuration and its true (lower) packing fraction."""
        side = math.sqrt(n * AREA / phi)
        data, attrs, shapes = read(self.path("short.h5"))
        self.assertEqual(shapes["centres"][0], (n, 2))
        self.assertEqual(attrs["method"], "fire")
        self.assertEqual(attrs["dimension"], 2)
        box = data["box"]
        self.assertTrue((box > side).all(), (box, side))
        self.assertTrue((data["centres"] < box).all())
        expected = math.fsum(math.pi * x * y for x, y in data["axes"]) / box.prod()
        self.assertAlmostEqual(attrs["packing_fraction"], expected, delta=1e-15)
        self.assertLess(attrs["packing_fraction"], phi)
        # How far the packer got depends on the machine's speed (after the
        # 0.5 s limit: 0.088 under ASan on CI's machine, 0.75-0.78 in a
        # debugoptimized build on a loaded 2-core machine): only that a
        # certified configuration is there (even a limit of 1e-9 s leaves
        # one, φ = 3e-4, the random start scaled apart).
        self.assertGreater(attrs["packing_fraction"], 0.0)

    def test_help(self):
        r = run(["--help"], self.dir)
        self.assertEqual(r.returncode, 0)
        self.assertIn("--2d", r.stdout)
        self.assertIn("--axes A,B,C      semi-axes (1e-100 to 1e100, default 1,1,1; with "
                      "--2d: A,B,", r.stdout)

    def test_progress_bar_in_tmux(self):
        self.check_progress_bar("--2d --n 2000 --fraction 0.95 --axes 1,0.5",
                                r"of 0\.9500, [0-9]+ steps/s, ")

    def test_bad_arguments(self):
        base = ["--2d", "--n", "100", "--fraction", "0.3", "--axes", "1,0.5",
                "--out", "x.h5"]
        cases = [
            (["--axes", "1,0.5,0.2"], "--axes: expected two numbers > 0 separated by "
             "commas (--2d), got '1,0.5,0.2'"),
            (["--axes", "1"], "--axes: expected two numbers > 0"),
            (["--axes", "1,"], "--axes: expected two numbers > 0"),
            (["--axes", "1,0"], "--axes: expected two numbers > 0"),
            (["--axes", "1e-150,1e-150"], "--axes: 1e-150 is outside the range of the "
             "semi-axes, 1e-100 to 1e100, got '1e-150,1e-150'"),
            (["--axes", "1e150,1"], "--axes: 1e150 is outside the range"),
            (["--axes", "1e100,1e100", "--fraction", "1e-200"],
             "--n, --axes and --fraction: 100 ellipses of semi-axes 1e100,1e100 at 1e-200 "
             "need a box whose area is beyond the range of a double"),
            (["--voxels", "65537"], "--voxels: expected an integer from 1 to 65536 (--2d)"),
            (["--voxels", "0"], "--voxels: expected an integer from 1 to 65536 (--2d)"),
            (["--n", "1", "--fraction", "0.5"], "--n: 1 ellipses give a box of side"),
            (["--n", "3", "--fraction", "0.9999999999999999", "--axes", "1,1"],
             "--fraction: 0.9999999999999999 with 3 ellipses gives a box"),
            (["--resume", "x.h5", "--method", "fire"], "--resume: only for --method rsa"),
        ]
        for extra, message in cases:
            with self.subTest(extra=extra):
                r = run(base + extra, self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(os.listdir(self.dir), [])
        # two axes without --2d: the 3D message, unchanged
        r = run(base[1:], self.dir)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("--axes: expected three numbers > 0 separated by commas, got '1,0.5'",
                      r.stderr)
        self.assertEqual(os.listdir(self.dir), [])

    def test_resume_fraction(self):
        # as in 3D: a --fraction other than the target of the file's box and
        # count refused (it was ignored: exit status 0 at 0.4), the same
        # accepted
        r = run(["--2d", "--n", "300", "--axes", "1,0.4", "--fraction", "0.4", "--seed", "2",
                 "--method", "rsa", "--out", "p2.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)
        r = run(["--2d", "--resume", "p2.h5", "--fraction", "0.5", "--out", "o.h5"], self.dir)
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertEqual(r.stderr, "pw85-pack: --fraction: 0.5 differs from the target of "
                         "p2.h5 (300 ellipses in its box: 0.4); with --resume, --n sets the "
                         "target (see --help)\n")
        self.assertEqual(os.listdir(self.dir), ["p2.h5"])
        r = run(["--2d", "--resume", "p2.h5", "--fraction", "0.4", "--out", "o.h5"], self.dir)
        self.assertEqual(r.returncode, 0, r.stderr)

    def test_resume_other_dimension(self):
        # --2d anywhere on the line (here after --axes A,B)
        for args, name in ((["--axes", "1,0.5", "--2d"], "flat.h5"),
                           (["--axes", "1,0.5,0.2"], "solid.h5")):
            r = run(["--n", "200", "--fraction", "0.2", "--method", "rsa",
                     "--out", name] + args, self.dir)
            self.assertEqual(r.returncode, 0, r.stderr)
        for args, message in (
                (["--resume", "flat.h5"],
                 "--resume: flat.h5 holds ellipses (a 2D packing): add --2d"),
                (["--2d", "--resume", "solid.h5"],
                 "--resume: solid.h5 holds ellipsoids (a 3D packing): --2d is for ellipses")):
            with self.subTest(args=args):
                r = run(args + ["--out", "y.h5"], self.dir)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(sorted(os.listdir(self.dir)), ["flat.h5", "solid.h5"])
        # corrupted 2D files: a dimension that is neither, an edited angle
        # (the form no longer that of /axes and /angles), overlapping
        # ellipses: exit status 1 (as in 3D), nothing written
        for name, edit, message in (
                ("dim5.h5", lambda f: f.attrs.__setitem__("dimension", np.int32(5)),
                 "attribute dimension is 5, not 2 or 3"),
                ("angle.h5", lambda f: f["angles"].__setitem__(0, f["angles"][0] + 0.5),
                 "/forms[0] is not the form of /axes[0] and /angles[0]"),
                ("overlap.h5", lambda f: (f["centres"].__setitem__(1, f["centres"][0]),
                                          f["forms"].__setitem__(1, f["forms"][0]),
                                          f["angles"].__setitem__(1, f["angles"][0])),
                 "pairs of ellipses overlap"),
                ("shape.h5", lambda f: (f.__delitem__("angles"),
                                        f.__setitem__("angles", np.zeros((200, 1)))),
                 "/angles has not the documented type and shape")):
            with self.subTest(resume=name):
                shutil.copy(self.path("flat.h5"), self.path(name))
                with h5py.File(self.path(name), "r+") as f:
                    edit(f)
                r = run(["--2d", "--resume", name, "--out", "y.h5"], self.dir)
                self.assertEqual(r.returncode, 1, r.stderr)
                self.assertEqual(len(r.stderr.splitlines()), 1, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertNotIn("y.h5", os.listdir(self.dir))


if __name__ == "__main__":
    common.TOOL, common.VERSION = os.path.abspath(sys.argv[1]), sys.argv[2]
    unittest.main(argv=sys.argv[:1], verbosity=2)
