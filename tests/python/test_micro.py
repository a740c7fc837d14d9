# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.micro: the voxel image against exact decisions (Python
fractions), and the files of pw85-pack read and written (h5py, XDMF, ASE's
extended XYZ)."""

import math
import os
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest

import pypw85
from pypw85 import micro


def rotation(p):
    w, x, y, z = p
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def random_config(rng, n, box, scale=1.0):
    a = np.column_stack([rng.uniform(0.6, 1.6, n), rng.uniform(0.4, 1.0, n),
                         rng.uniform(0.3, 0.7, n)]) * scale
    p = rng.normal(size=(n, 4))
    p /= np.linalg.norm(p, axis=1)[:, None]
    q = np.array([(rotation(p[k]) @ np.diag(a[k] ** 2) @ rotation(p[k]).T)
                  [np.triu_indices(3)] for k in range(n)])
    c = rng.uniform(0, 1, (n, 3)) * box
    return c, q, a, p


def exact_inside(point, c, q):
    """dᵀ adj(Q) d ≤ det Q in rationals, d = point − c (exact values)."""
    d = [point[k] - c[k] for k in range(3)]
    Q = [[Fraction(q[0]), Fraction(q[1]), Fraction(q[2])],
         [Fraction(q[1]), Fraction(q[3]), Fraction(q[4])],
         [Fraction(q[2]), Fraction(q[4]), Fraction(q[5])]]
    A = [[Q[(l + 1) % 3][(k + 1) % 3] * Q[(l + 2) % 3][(k + 2) % 3]
          - Q[(l + 1) % 3][(k + 2) % 3] * Q[(l + 2) % 3][(k + 1) % 3]
          for l in range(3)] for k in range(3)]
    det = sum(Q[0][l] * A[l][0] for l in range(3))
    return sum(A[k][l] * d[k] * d[l] for k in range(3) for l in range(3)) <= det


def brute_image(c, q, box, dims, origin, periodic):
    """Every voxel against every ellipsoid (and image): doubles far from the
    surface (value of dᵀQ⁻¹d farther than 1e-9 from 1, its rounding error
    being below 1e-14 here), Fractions near it."""
    n = len(c)
    img = np.full(dims, -1, dtype=np.int32)
    grids = np.meshgrid(*[origin[k] + (np.arange(dims[k]) + 0.5) * box[k] / dims[k]
                          for k in range(3)], indexing="ij")
    m = np.stack(grids, axis=-1)
    shifts = list(np.ndindex(3, 3, 3)) if periodic else [(1, 1, 1)]
    for e in range(n - 1, -1, -1):  # lowest position written last
        qinv = np.linalg.inv(micro_unpack(q[e]))
        inside = np.zeros(dims, dtype=bool)
        for s in shifts:
            cc = c[e] + (np.array(s) - 1) * box
            d = m - cc
            v = np.einsum("...i,ij,...j->...", d, qinv, d)
            inside |= v < 1 - 1e-9
            for idx in zip(*np.nonzero(np.abs(v - 1) <= 1e-9)):
                point = [Fraction(origin[k]) + (2 * int(idx[k]) + 1)
                         * Fraction(box[k]) / (2 * dims[k]) for k in range(3)]
                cf = [Fraction(c[e][k]) + (s[k] - 1) * Fraction(box[k])
                      for k in range(3)]
                if exact_inside(point, cf, q[e]):
                    inside[idx] = True
        img[inside] = e
    return img


def micro_unpack(q):
    return np.array([[q[0], q[1], q[2]], [q[1], q[3], q[4]], [q[2], q[4], q[5]]])


def test_image_periodic_brute_force():
    rng = np.random.default_rng(2028)
    box = np.array([6.0, 6.5, 7.0])
    c, q, _, _ = random_config(rng, 25, box)
    dims = (20, 22, 24)
    img = micro.voxel_image(c, q, box, dims, threads=2)
    assert img.dtype == np.int32 and img.shape == dims
    np.testing.assert_array_equal(img, brute_image(c, q, box, dims, np.zeros(3), True))
    assert micro.phase_fraction(img) == np.mean(img >= 0)
    assert 0.1 < micro.phase_fraction(img) < 0.9
    for t in (1, 3, 0):
        np.testing.assert_array_equal(micro.voxel_image(c, q, box, dims, threads=t), img)


def test_image_open_brute_force():
    rng = np.random.default_rng(7)
    box, origin = np.array([5.0, 4.0, 4.5]), np.array([-2.5, 1.0, 100.25])
    c, q, _, _ = random_config(rng, 15, box)
    c += origin
    dims = (18, 15, 16)
    img = micro.voxel_image(c, q, box, dims, origin=origin, periodic=False)
    np.testing.assert_array_equal(img, brute_image(c, q, box, dims, origin, False))


def test_surface_points_exact():
    """Voxel centres on surfaces to the last bit: c = m − v/√(vᵀQ⁻¹v),
    rounded, for a voxel centre m; the voxel's value against Fractions."""
    rng = np.random.default_rng(99)
    box, dims = np.array([8.0, 8.0, 8.0]), (8, 8, 8)
    sides = {True: 0, False: 0}
    for trial in range(120):
        a = rng.uniform([0.8, 0.5, 0.3], [2.5, 1.5, 1.2])
        p = rng.normal(size=4)
        p /= np.linalg.norm(p)
        q = pypw85.ellipsoid_quaternion(a, p)
        idx = tuple(int(x) for x in rng.integers(0, 8, 3))
        m = np.array(idx) + 0.5
        v = rng.normal(size=3)
        v /= math.sqrt(v @ np.linalg.inv(micro_unpack(q)) @ v)
        c = m - v
        img = micro.voxel_image(c[None, :], q[None, :], box, dims)
        want = any(exact_inside([Fraction(x) for x in m],
                                [Fraction(c[k]) + (s[k] - 1) * 8 for k in range(3)], q)
                   for s in np.ndindex(3, 3, 3))
        sides[want] += 1
        assert (img[idx] == 0) == want, (trial, idx, c, q)
    assert sides[True] > 20 and sides[False] > 20, sides


def test_image_errors():
    box = np.array([2.0, 2.0, 2.0])
    c = np.array([[1.0, 1.0, 1.0], [0.5, 0.5, 0.5]])
    q = np.array([[0.25, 0, 0, 0.25, 0, 0.25], [0.25, 0.5, 0, 0.25, 0, 0.25]])
    with pytest.raises(pypw85.Error, match=r"q\[1\].*not positive definite") as e:
        micro.voxel_image(c, q, box, 4)
    assert e.value.status == pypw85.ENOTPOSDEF
    with pytest.raises(pypw85.Error, match="dims") as e:
        micro.voxel_image(c[:1], q[:1], box, (4, 0, 4))
    assert e.value.status == pypw85.EINVAL
    with pytest.raises(pypw85.Error, match="sides"):
        micro.voxel_image(c[:1], q[:1], [2.0, -1.0, 2.0], 4)
    with pytest.raises(pypw85.Error, match="not finite") as e:
        micro.voxel_image([[np.nan, 0, 0]], q[:1], box, 4)
    assert e.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error, match="ellipsoid 0"):
        micro.voxel_image([[0, 0, 2.0**31]], q[:1], box, 4)
    # 2²⁹·L = +∞: the reach |c − o| + √Q_kk must still be finite (an
    # infinite one passed the check, and the library's message named
    # nothing)
    with pytest.raises(pypw85.Error, match="ellipsoid 0") as e:
        micro.voxel_image([[1.7e308, 0, 0]], q[:1], [1e300] * 3, 4,
                          origin=[-1.7e308, 0, 0])
    assert e.value.status == pypw85.EINVAL
    # counts that are not integers were truncated (4.5 voxels drew 4)
    with pytest.raises(TypeError, match="dims"):
        micro.voxel_image(c[:1], q[:1], box, (4.5, 4, 4))
    with pytest.raises(TypeError, match="dims"):
        micro.voxel_image(c[:1], q[:1], box, 4.0)
    with pytest.raises(ValueError, match="centres"):
        micro.voxel_image([1.0, 2.0], q[:1], box, 4)
    with pytest.raises(ValueError, match="threads"):
        micro.voxel_image(c[:1], q[:1], box, 4, threads=-1)
    assert (micro.voxel_image(np.empty((0, 3)), np.empty((0, 6)), box, 3) == -1).all()


def test_phase_fraction_of_other_dtypes():
    """An image of another integer type is counted as its values say, or
    refused when they do not fit int32 (they were wrapped around: 2³² − 1,
    ≥ 0, counted as the matrix); a float or bool image is refused."""
    img = np.full((2, 2, 2), -1, dtype=np.int64)
    img[0, 0, 0] = 3
    assert micro.phase_fraction(img) == 0.125
    with pytest.raises(ValueError, match="image"):
        micro.phase_fraction(np.full((2, 2, 2), 2**32 - 1, dtype=np.int64))
    with pytest.raises(TypeError, match="image"):
        micro.phase_fraction(np.zeros((2, 2, 2)))
    with pytest.raises(TypeError, match="image"):
        micro.phase_fraction(np.ones((2, 2, 2), dtype=bool))


def configuration(n=50, seed=5):
    rng = np.random.default_rng(seed)
    box = np.array([10.0, 11.0, 12.0])
    c, q, a, p = random_config(rng, n, box, scale=0.5)
    return micro.Microstructure(box=box, centres=c, forms=q, axes=a,
                                quaternions=p, seed=2**64 - 3, method="rsa")


def test_hdf5_round_trip(tmp_path):
    h5py = pytest.importorskip("h5py")
    m = configuration()
    m.image = micro.voxel_image(m.centres, m.forms, m.box, (10, 11, 12))
    path = tmp_path / "m.h5"
    micro.write_hdf5(path, m)
    assert sorted(os.listdir(tmp_path)) == ["m.h5"]
    with h5py.File(path, "r") as f:
        assert f["quaternions"].shape == (50, 4) and f["image"].dtype == np.int32
        assert f.attrs["seed"] == 2**64 - 3 and f.attrs["seed"].dtype == np.uint64
        assert f.attrs["pw85_version"] == pypw85.__version__
        # different semi-axes: Σ of the doubles 4/3·π·a0·a1·a2, correctly
        # rounded (u = 2⁻⁵³ relative), over V rounded twice (2u), then
        # divided (u): within 4u of the exact quotient, to first order (a
        # bound; measured 0.21u on this configuration)
        exact = sum(Fraction(4 / 3 * math.pi * x * y * z) for x, y, z in m.axes) / (
            Fraction(m.box[0]) * Fraction(m.box[1]) * Fraction(m.box[2]))
        got = f.attrs["packing_fraction"]
        assert abs(Fraction(got) - exact) <= 4 * 2**-53 * exact
    r = micro.read_hdf5(path)
    for name in ("box", "centres", "forms", "axes", "quaternions", "image"):
        np.testing.assert_array_equal(getattr(r, name), getattr(m, name))
    assert (r.seed, r.method) == (m.seed, "rsa")
    # a failed write leaves the file as it was, and no temporary file
    before = path.read_bytes()
    bad = configuration()
    bad.forms = bad.forms[:, :5]
    with pytest.raises(ValueError, match="forms"):
        micro.write_hdf5(path, bad)
    bad = configuration()
    bad.image = np.zeros((2, 2), dtype=np.int32)
    with pytest.raises(ValueError, match="image"):
        micro.write_hdf5(path, bad)
    # values that a cast to int32 would change: refused, not truncated (a
    # voxel of 2⁴⁰ + 5 was stored as 5, of 0.7 as 0; a seed of -1 as 2⁶⁴ − 1)
    bad.image = np.full((2, 2, 2), 2**40 + 5)
    with pytest.raises(ValueError, match="^image: a voxel value 1099511627781 "
                       "is outside int32$"):
        micro.write_hdf5(path, bad)
    bad.image = np.full((2, 2, 2), 0.7)
    with pytest.raises(TypeError, match="^image: expected integer voxel "
                       "values"):
        micro.write_hdf5(path, bad)
    bad = configuration()
    for seed, error in ((-1, ValueError), (2**64, ValueError),
                        (1.0, TypeError), (True, TypeError)):
        bad.seed = seed
        with pytest.raises(error, match="^seed: expected an int"):
            micro.write_hdf5(path, bad)
    assert path.read_bytes() == before
    assert sorted(os.listdir(tmp_path)) == ["m.h5"]
    # another layout
    with h5py.File(tmp_path / "other.h5", "w") as f:
        f["box"] = [1.0, 2.0, 3.0]
    with pytest.raises(ValueError, match="no dataset /centres"):
        micro.read_hdf5(tmp_path / "other.h5")


def test_xdmf(tmp_path):
    micro.write_xdmf(tmp_path / "m.xdmf", tmp_path / "m.h5", (10, 11, 12),
                     [10.0, 11.0, 12.0])
    root = ET.parse(tmp_path / "m.xdmf").getroot()
    assert root.find("./Domain/Grid/Topology").get("Dimensions") == "11 12 13"
    spacing = root.findall("./Domain/Grid/Geometry/DataItem")[1].text.split()
    assert [float(x) for x in spacing] == [1.0, 1.0, 1.0]
    assert root.find("./Domain/Grid/Attribute/DataItem").text == "m.h5:/image"
    # names with XML's special characters give well-formed XML that names
    # the file as it is (they were pasted unescaped)
    for name in ("a&b.h5", "a<b>.h5", "run--1.h5", "q\"'.h5"):
        micro.write_xdmf(tmp_path / "odd.xdmf", tmp_path / name, (2, 2, 2),
                         [1.0, 1.0, 1.0])
        odd = ET.parse(tmp_path / "odd.xdmf").getroot()
        assert odd.find("./Domain/Grid/Attribute/DataItem").text == name + ":/image"
    (tmp_path / "odd.xdmf").unlink()
    # names XML 1.0 cannot hold are refused, nothing written (pw85-pack too)
    for name in ("a\x01b.h5", "tab\x0b.h5", b"\xff.h5", "cr\rb.h5", "t\tb.h5"):
        with pytest.raises(ValueError, match="XML"):
            micro.write_xdmf(tmp_path / "odd.xdmf", name, (2, 2, 2), [1.0, 1.0, 1.0])
    # dims: three integers from 1 (a zero count made a spacing of L/0),
    # refused before anything is written
    for dims in ((0, 11, 12), (10, 0, 12), (10, 11, -1), (10, 11), 0):
        with pytest.raises(ValueError, match="dims"):
            micro.write_xdmf(tmp_path / "bad.xdmf", tmp_path / "m.h5", dims,
                             [10.0, 11.0, 12.0])
    assert sorted(os.listdir(tmp_path)) == ["m.xdmf"]


def test_xyz_round_trip(tmp_path):
    m = configuration()
    micro.write_xyz(tmp_path / "m.xyz", m)
    r = micro.read_xyz(tmp_path / "m.xyz")
    for name in ("box", "centres", "axes", "quaternions"):
        np.testing.assert_array_equal(getattr(r, name), getattr(m, name))
    # the forms rebuilt by pw85_ellipsoid_quaternion: a few ulps of a²
    np.testing.assert_allclose(r.forms, m.forms, rtol=0, atol=1e-15)
    assert (r.seed, r.method) == (m.seed, m.method)
    ase_io = pytest.importorskip("ase.io")
    atoms = ase_io.read(tmp_path / "m.xyz", format="extxyz")
    np.testing.assert_array_equal(atoms.positions, m.centres)
    np.testing.assert_array_equal(atoms.cell.lengths(), m.box)
    np.testing.assert_array_equal(atoms.arrays["orientation"],
                                  m.quaternions[:, [1, 2, 3, 0]])
    np.testing.assert_array_equal(atoms.arrays["aspherical_shape"], m.axes)


def test_xyz_species_one_word(tmp_path):
    """The species is a column: a space or a quote in it, or an empty one,
    shifted every column of the line (read_xyz, OVITO, ASE misread the
    file); refused before anything is written."""
    m = configuration()
    for bad in ("A B", "", "C\n", 'say"', "it's", "\tX"):
        with pytest.raises(ValueError, match="is not one word"):
            micro.write_xyz(tmp_path / "s.xyz", m, species=bad)
    with pytest.raises(TypeError, match="is not a str"):
        micro.write_xyz(tmp_path / "s.xyz", m, species=3)
    assert not (tmp_path / "s.xyz").exists()
    micro.write_xyz(tmp_path / "s.xyz", m, species="Ellipsoid_1")
    r = micro.read_xyz(tmp_path / "s.xyz")
    np.testing.assert_array_equal(r.centres, m.centres)


def test_xyz_method_quoted(tmp_path):
    """The method (any text) quoted in the header: a space no longer cuts it
    nor starts a key of its own; a double quote or a line break, which no
    quoting of extended XYZ carries, is refused before anything is
    written."""
    m = configuration()
    m.method = "random sequential addition, seed=3"
    micro.write_xyz(tmp_path / "m.xyz", m)
    with open(tmp_path / "m.xyz") as f:
        f.readline()
        assert 'method="random sequential addition, seed=3"' in f.readline()
    r = micro.read_xyz(tmp_path / "m.xyz")
    assert (r.method, r.seed) == (m.method, m.seed)
    ase_io = pytest.importorskip("ase.io")
    atoms = ase_io.read(tmp_path / "m.xyz", format="extxyz")
    assert atoms.info["method"] == m.method
    for bad in ('say "rsa"', "rsa\nX 0 0 0"):
        m.method = bad
        with pytest.raises(ValueError, match="method"):
            micro.write_xyz(tmp_path / "bad.xyz", m)
    assert sorted(os.listdir(tmp_path)) == ["m.xyz"]
