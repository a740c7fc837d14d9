# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.micro for ellipses (issue 29): the 2D layout of pw85-pack --2d
read and written (HDF5 against h5py's raw read, XYZ against ASE and the
tool's own file, XDMF against the tool's), the pixel image against exact
decisions in rationals and against the tool's /image, the 3D files written
byte for byte as before the 2D layout, and every bad input refused."""

import math
import os
import shlex
import subprocess
import xml.etree.ElementTree as ET
from fractions import Fraction

import numpy as np
import pytest

import pypw85
from pypw85 import d2, micro


def ellipses(n=40, seed=11, box=(9.0, 7.5)):
    rng = np.random.default_rng(seed)
    box = np.array(box)
    a = np.column_stack([rng.uniform(0.5, 1.2, n), rng.uniform(0.2, 0.6, n)])
    theta = rng.uniform(-math.pi, math.pi, n)
    c = rng.uniform(0, 1, (n, 2)) * box
    return micro.Microstructure(box=box, centres=c, forms=d2.ellipse(a, theta),
                                axes=a, angles=theta, seed=2**64 - 5,
                                method="rsa")


def raw(path):
    h5py = pytest.importorskip("h5py")
    with h5py.File(path, "r") as f:
        return ({k: f[k][()] for k in f.keys()}, dict(f.attrs),
                {k: (f[k].shape, f[k].dtype) for k in f.keys()})


def same_bits(x, y):
    x, y = np.asarray(x), np.asarray(y)
    assert x.dtype == y.dtype and x.shape == y.shape
    assert x.tobytes() == y.tobytes()


# ---- the 2D layout, by Python alone ---------------------------------------


def test_hdf5_round_trip_2d(tmp_path):
    m = ellipses()
    assert m.dimension == 2 and m.quaternions is None
    m.image = micro.voxel_image(m.centres, m.forms, m.box, (45, 30))
    path = tmp_path / "e.h5"
    micro.write_hdf5(path, m)
    assert sorted(os.listdir(tmp_path)) == ["e.h5"]
    data, attrs, shapes = raw(path)
    assert shapes == {"box": ((2,), np.float64), "centres": ((40, 2), np.float64),
                      "forms": ((40, 3), np.float64), "axes": ((40, 2), np.float64),
                      "angles": ((40,), np.float64), "image": ((45, 30), np.int32)}
    assert attrs["dimension"] == 2 and attrs["dimension"].dtype == np.int32
    assert attrs["seed"] == 2**64 - 5 and attrs["seed"].dtype == np.uint64
    # the area fraction, in rationals from the doubles (π to 40 digits)
    pi = Fraction("3.141592653589793238462643383279502884197")
    exact = pi * sum(Fraction(x) * Fraction(y) for x, y in m.axes) / (
        Fraction(m.box[0]) * Fraction(m.box[1]))
    # 40 terms, each rounded twice, then the sum and a division: a few ulps
    assert abs(Fraction(attrs["packing_fraction"]) - exact) <= 1e-15 * exact
    assert attrs["image_fraction"] == np.mean(m.image >= 0)
    r = micro.read_hdf5(path)
    assert r.dimension == 2 and r.quaternions is None
    for name in ("box", "centres", "forms", "axes", "angles", "image"):
        same_bits(getattr(r, name), getattr(m, name))
    assert (r.seed, r.method, r.extra) == (m.seed, "rsa", {})
    # written again: the same file to the byte
    micro.write_hdf5(tmp_path / "again.h5", r)
    assert (tmp_path / "again.h5").read_bytes() == path.read_bytes()


def test_xyz_round_trip_2d(tmp_path):
    m = ellipses()
    path = tmp_path / "e.xyz"
    micro.write_xyz(path, m)
    lines = path.read_text().splitlines()
    header = dict(x.split("=", 1) for x in shlex.split(lines[1]))
    H = 2 * m.axes.max()
    assert [float(x) for x in header["Lattice"].split()] == [
        m.box[0], 0, 0, 0, m.box[1], 0, 0, 0, H]
    assert header["pbc"] == "T T F" and header["dimension"] == "2"
    assert header["Properties"].endswith(":orientation:R:4:angle:R:1")
    r = micro.read_xyz(path)
    assert r.dimension == 2 and r.quaternions is None
    for name in ("box", "centres", "axes", "angles"):
        same_bits(getattr(r, name), getattr(m, name))
    # the forms rebuilt by pw85_2d_ellipse, as m's were: the same bits
    same_bits(r.forms, m.forms)
    assert (r.seed, r.method, r.extra) == (m.seed, m.method, {})
    ase_io = pytest.importorskip("ase.io")
    atoms = ase_io.read(path, format="extxyz")
    np.testing.assert_array_equal(atoms.positions[:, :2], m.centres)
    assert (atoms.positions[:, 2] == 0).all()
    np.testing.assert_array_equal(atoms.cell.lengths(), [m.box[0], m.box[1], H])
    assert list(atoms.pbc) == [True, True, False]
    np.testing.assert_array_equal(atoms.arrays["angle"], m.angles)
    np.testing.assert_array_equal(atoms.arrays["aspherical_shape"],
                                  np.column_stack([m.axes, m.axes.min(axis=1)]))
    t = m.angles
    np.testing.assert_array_equal(
        atoms.arrays["orientation"],
        np.column_stack([0 * t, 0 * t, [math.sin(0.5 * x) for x in t],
                         [math.cos(0.5 * x) for x in t]]))
    assert atoms.info["dimension"] == 2


def test_xyz_without_ellipses(tmp_path):
    """No ellipse (a file stopped before the first): the cell's height is
    the box's larger side, as io.c, never 0."""
    m = micro.Microstructure(box=np.array([3.0, 5.0]), centres=np.empty((0, 2)),
                             forms=np.empty((0, 3)), axes=np.empty((0, 2)),
                             angles=np.empty(0))
    micro.write_xyz(tmp_path / "e.xyz", m)
    header = (tmp_path / "e.xyz").read_text().splitlines()[1]
    assert 'Lattice="3.0 0 0 0 5.0 0 0 0 5.0"' in header
    r = micro.read_xyz(tmp_path / "e.xyz")
    assert r.dimension == 2 and len(r) == 0 and r.forms.shape == (0, 3)
    micro.write_hdf5(tmp_path / "e.h5", m)
    data, attrs, _ = raw(tmp_path / "e.h5")
    assert data["angles"].shape == (0,) and attrs["packing_fraction"] == 0


def test_xdmf_2d(tmp_path):
    micro.write_xdmf(tmp_path / "e.xdmf", tmp_path / "e.h5", (40, 30), [8.0, 6.0])
    grid = ET.parse(tmp_path / "e.xdmf").getroot().find("./Domain/Grid")
    topology = grid.find("Topology")
    assert topology.get("TopologyType") == "2DCoRectMesh"
    assert topology.get("Dimensions") == "41 31"
    assert grid.find("Geometry").get("GeometryType") == "ORIGIN_DXDY"
    origin, spacing = grid.findall("Geometry/DataItem")
    assert origin.get("Dimensions") == "2" and origin.text.split() == ["0.0", "0.0"]
    assert [float(x) for x in spacing.text.split()] == [0.2, 0.2]
    item = grid.find("Attribute/DataItem")
    assert item.get("Dimensions") == "40 30" and item.text == "e.h5:/image"
    with pytest.raises(ValueError, match="dims"):
        micro.write_xdmf(tmp_path / "bad.xdmf", "e.h5", (40, 30), [8.0, 6.0, 1.0])
    assert sorted(os.listdir(tmp_path)) == ["e.xdmf"]


# ---- the pixel image --------------------------------------------------------


def exact_inside_2d(point, c, q):
    """dᵀ adj(Q) d ≤ det Q in rationals, d = point − c."""
    d0, d1 = point[0] - c[0], point[1] - c[1]
    q0, q1, q2 = (Fraction(x) for x in q)
    return q2 * d0 * d0 - 2 * q1 * d0 * d1 + q0 * d1 * d1 <= q0 * q2 - q1 * q1


def brute_pixels(c, q, box, dims, origin, periodic):
    """Every pixel against every ellipse (and image): doubles far from the
    boundary (dᵀQ⁻¹d farther than 1e-9 from 1; its rounding error is below
    1e-14 here), rationals near it."""
    img = np.full(dims, -1, dtype=np.int32)
    x = [origin[k] + (np.arange(dims[k]) + 0.5) * box[k] / dims[k] for k in range(2)]
    m = np.stack(np.meshgrid(*x, indexing="ij"), axis=-1)
    shifts = list(np.ndindex(3, 3)) if periodic else [(1, 1)]
    for e in range(len(c) - 1, -1, -1):  # the least position written last
        qinv = np.linalg.inv([[q[e][0], q[e][1]], [q[e][1], q[e][2]]])
        inside = np.zeros(dims, dtype=bool)
        for s in shifts:
            d = m - (c[e] + (np.array(s) - 1) * box)
            v = np.einsum("...i,ij,...j->...", d, qinv, d)
            inside |= v < 1 - 1e-9
            for idx in zip(*np.nonzero(np.abs(v - 1) <= 1e-9)):
                point = [Fraction(origin[k]) + (2 * int(idx[k]) + 1)
                         * Fraction(box[k]) / (2 * dims[k]) for k in range(2)]
                cf = [Fraction(c[e][k]) + (s[k] - 1) * Fraction(box[k]) for k in range(2)]
                if exact_inside_2d(point, cf, q[e]):
                    inside[idx] = True
        img[inside] = e
    return img


def test_pixels_brute_force():
    m = ellipses(n=30, seed=3, box=(6.0, 5.0))
    dims = (48, 37)
    img = micro.voxel_image(m.centres, m.forms, m.box, dims, threads=2)
    assert img.dtype == np.int32 and img.shape == dims
    np.testing.assert_array_equal(img, brute_pixels(m.centres, m.forms, m.box, dims,
                                                    np.zeros(2), True))
    assert 0.2 < micro.phase_fraction(img) < 0.9
    assert micro.phase_fraction(img) == np.mean(img >= 0)
    # open, with an origin
    origin = np.array([-3.0, 100.5])
    img = micro.voxel_image(m.centres + origin, m.forms, m.box, dims,
                            origin=origin, periodic=False)
    np.testing.assert_array_equal(img, brute_pixels(m.centres + origin, m.forms, m.box,
                                                    dims, origin, False))


def test_pixels_on_the_boundary():
    """Pixel centres on an ellipse to the last bit: c = p − v/√(vᵀQ⁻¹v),
    rounded, for a pixel centre p; the pixel's value against rationals."""
    rng = np.random.default_rng(17)
    sides = {True: 0, False: 0}
    for trial in range(150):
        a, t = rng.uniform([0.8, 0.3], [2.5, 1.2]), rng.uniform(-3, 3)
        q = d2.ellipse(a, t)
        idx = tuple(int(x) for x in rng.integers(0, 8, 2))
        p = np.array(idx) + 0.5
        v = rng.normal(size=2)
        v /= math.sqrt(v @ np.linalg.inv([[q[0], q[1]], [q[1], q[2]]]) @ v)
        c = p - v
        img = micro.voxel_image(c[None, :], q[None, :], [8.0, 8.0], 8)
        want = any(exact_inside_2d([Fraction(x) for x in p],
                                   [Fraction(c[k]) + (s[k] - 1) * 8 for k in range(2)], q)
                   for s in np.ndindex(3, 3))
        sides[want] += 1
        assert (img[idx] == 0) == want, (trial, idx, c, q)
    assert sides[True] > 20 and sides[False] > 20, sides


def test_pixels_errors():
    q = np.array([[0.25, 0.0, 0.25], [0.25, 0.5, 0.25]])
    c = np.array([[1.0, 1.0], [0.5, 0.5]])
    with pytest.raises(pypw85.Error, match=r"q\[1\] = \[0.25 0.5  0.25\] is not positive"):
        micro.voxel_image(c, q, [2.0, 2.0], 4)
    with pytest.raises(ValueError, match=r"q: expected shape \(2, 3\)"):
        micro.voxel_image(c, np.zeros((2, 6)), [2.0, 2.0], 4)
    with pytest.raises(ValueError, match=r"sides: expected shape \(2,\)"):
        micro.voxel_image(c, q, [2.0, 2.0, 2.0], 4)
    with pytest.raises(ValueError, match="dims: expected 2 integers"):
        micro.voxel_image(c, q, [2.0, 2.0], (4, 4, 4))
    with pytest.raises(pypw85.Error, match="ellipse 0"):
        micro.voxel_image([[2.0**31, 0]], q[:1], [2.0, 2.0], 4)
    with pytest.raises(ValueError, match="image"):
        micro.phase_fraction(np.zeros(4, dtype=np.int32))


# ---- the files of the tool ----------------------------------------------------


@pytest.fixture(scope="module")
def tool_files(tmp_path_factory):
    tool = os.environ.get("PW85_PACK")
    if not tool:
        pytest.skip("pw85-pack not built (no HDF5): PW85_PACK unset")
    pytest.importorskip("h5py")
    d = tmp_path_factory.mktemp("tool")
    subprocess.run([tool, "--2d", "--n", "150", "--axes", "1,0.4", "--fraction", "0.45",
                    "--method", "rsa", "--seed", "7", "--voxels", "96", "--quiet",
                    "--out", str(d / "t.h5"), "--xyz", str(d / "t.xyz")],
                   check=True)
    return d


def test_read_tool_hdf5(tool_files):
    path = tool_files / "t.h5"
    data, attrs, _ = raw(path)
    m = micro.read_hdf5(path)
    assert m.dimension == 2 and len(m) == 150 and m.quaternions is None
    for name in ("box", "centres", "forms", "axes", "angles", "image"):
        same_bits(getattr(m, name), data[name])
    assert (m.seed, m.method, m.pw85_version) == (7, "rsa", attrs["pw85_version"])
    assert set(m.extra) == {"attempts", "target_count"}
    # equal semi-axes: n·(π·a0·a1) / (L0·L1) formed as the tool forms it,
    # bit for bit (a naive sum of the 150 terms was 5 to 22 ulps off)
    assert m.packing_fraction == attrs["packing_fraction"]
    # the image: the same pixels as the tool's, and its fraction
    same_bits(micro.voxel_image(m.centres, m.forms, m.box, 96), data["image"])
    assert micro.phase_fraction(data["image"]) == attrs["image_fraction"]
    # Python writes it back in the tool's layout: the same datasets and
    # attributes, and the tool resumes from it
    micro.write_hdf5(tool_files / "py.h5", m)
    back, battrs, _ = raw(tool_files / "py.h5")
    assert set(back) == set(data)
    for name in data:
        same_bits(back[name], data[name])
    assert set(battrs) == set(attrs)
    for key in attrs:
        assert battrs[key] == attrs[key] and np.asarray(battrs[key]).dtype == \
            np.asarray(attrs[key]).dtype, key
    subprocess.run([os.environ["PW85_PACK"], "--2d", "--resume", str(tool_files / "py.h5"),
                    "--n", "160", "--quiet", "--out", str(tool_files / "resumed.h5")],
                   check=True)
    r = micro.read_hdf5(tool_files / "resumed.h5")
    assert r.dimension == 2 and len(r) >= 150
    same_bits(r.centres[:150], m.centres)


def test_read_tool_xyz(tool_files):
    data, attrs, _ = raw(tool_files / "t.h5")
    r = micro.read_xyz(tool_files / "t.xyz")
    assert r.dimension == 2
    for name in ("box", "centres", "forms", "axes", "angles"):
        same_bits(getattr(r, name), data[name])
    # Python's XYZ of the same ellipses: the tool's, number for number
    m = micro.read_hdf5(tool_files / "t.h5")
    micro.write_xyz(tool_files / "py.xyz", m)
    ours = (tool_files / "py.xyz").read_text().splitlines()
    theirs = (tool_files / "t.xyz").read_text().splitlines()
    assert len(ours) == len(theirs) == 152

    def fields(line):
        return dict(x.split("=", 1) for x in shlex.split(line))
    h0, h1 = fields(ours[1]), fields(theirs[1])
    assert [float(x) for x in h0["Lattice"].split()] == \
        [float(x) for x in h1["Lattice"].split()]
    for key in ("pbc", "Properties", "dimension", "seed", "method", "pw85_version"):
        assert h0[key] == h1[key], key
    for a, b in zip(ours[2:], theirs[2:]):
        a, b = a.split(), b.split()
        assert a[0] == b[0] and [float(x) for x in a[1:]] == [float(x) for x in b[1:]]


def test_xdmf_as_the_tool(tool_files):
    tool = ET.parse(next(tool_files.glob("t*.xdmf"))).getroot().find("./Domain/Grid")
    micro.write_xdmf(tool_files / "py.xdmf", tool_files / "t.h5", (96, 96),
                     micro.read_hdf5(tool_files / "t.h5").box)
    ours = ET.parse(tool_files / "py.xdmf").getroot().find("./Domain/Grid")
    for g in (tool, ours):
        assert g.find("Topology").get("TopologyType") == "2DCoRectMesh"
    assert ours.find("Topology").attrib == tool.find("Topology").attrib
    assert ours.find("Geometry").attrib == tool.find("Geometry").attrib
    for a, b in zip(ours.findall("Geometry/DataItem"), tool.findall("Geometry/DataItem")):
        assert a.attrib == b.attrib
        assert [float(x) for x in a.text.split()] == [float(x) for x in b.text.split()]
    a, b = ours.find("Attribute/DataItem"), tool.find("Attribute/DataItem")
    assert (a.attrib, a.text) == (b.attrib, b.text)


# ---- 3D: the files of before ----------------------------------------------


def ellipsoids(n=20, seed=4):
    rng = np.random.default_rng(seed)
    box = np.array([8.0, 9.0, 10.0])
    a = np.column_stack([rng.uniform(0.5, 1.0, n), rng.uniform(0.3, 0.5, n),
                         rng.uniform(0.2, 0.3, n)])
    p = rng.normal(size=(n, 4))
    p /= np.linalg.norm(p, axis=1)[:, None]
    q = np.array([pypw85.ellipsoid_quaternion(a[k], p[k]) for k in range(n)])
    return micro.Microstructure(box, rng.uniform(0, 1, (n, 3)) * box, q, a, p,
                                seed=9, method="fire", pw85_version="2.4.0",
                                extra={"attempts": np.uint64(3)})


def old_write_hdf5(path, m):
    """The 3D writer of pypw85.micro before the 2D layout (pw85 2.4.0), call
    for call: what write_hdf5 must still write to the byte."""
    h5py = pytest.importorskip("h5py")
    with h5py.File(path, "w") as f:
        f["box"] = np.asarray(m.box, dtype=np.float64)
        for name in ("centres", "forms", "axes", "quaternions"):
            f[name] = np.ascontiguousarray(getattr(m, name), dtype=np.float64)
        if m.image is not None:
            f["image"] = m.image
            f.attrs["image_fraction"] = np.mean(m.image >= 0)
        for key, value in m.extra.items():
            f.attrs[key] = value
        f.attrs["packing_fraction"] = np.float64(sum(
            4.0 / 3.0 * math.pi * x * y * z for x, y, z in m.axes) / np.prod(m.box))
        f.attrs["seed"] = np.uint64(m.seed)
        f.attrs["pw85_version"] = str(m.pw85_version)
        f.attrs["method"] = str(m.method)


def test_3d_files_as_before(tmp_path):
    m = ellipsoids()
    assert m.dimension == 3 and m.angles is None
    for image in (None, micro.voxel_image(m.centres, m.forms, m.box, (8, 9, 10))):
        m.image = image
        micro.write_hdf5(tmp_path / "new.h5", m)
        old_write_hdf5(tmp_path / "old.h5", m)
        assert (tmp_path / "new.h5").read_bytes() == (tmp_path / "old.h5").read_bytes()
        _, attrs, _ = raw(tmp_path / "new.h5")
        assert "dimension" not in attrs
    # the XYZ of 2.4.0 for one ellipsoid, written out by hand
    one = micro.Microstructure(np.array([4.0, 5.0, 6.0]), np.array([[1.5, 2.0, 0.25]]),
                               np.array([[1.0, 0, 0, 0.25, 0, 0.0625]]),
                               np.array([[1.0, 0.5, 0.25]]),
                               np.array([[1.0, 0.0, 0.0, 0.0]]), seed=3, method="rsa",
                               pw85_version="2.4.0")
    micro.write_xyz(tmp_path / "one.xyz", one)
    fraction = 4.0 / 3.0 * math.pi * 1.0 * 0.5 * 0.25 / 120.0
    assert (tmp_path / "one.xyz").read_text() == (
        '1\nLattice="4.0 0 0 0 5.0 0 0 0 6.0" pbc="T T T" '
        'Properties=species:S:1:pos:R:3:aspherical_shape:R:3:orientation:R:4 '
        'packing_fraction=%r seed=3 method="rsa" pw85_version="2.4.0"\n'
        'X 1.5 2.0 0.25 1.0 0.5 0.25 0.0 0.0 0.0 1.0\n' % fraction)
    micro.write_xdmf(tmp_path / "one.xdmf", "one.h5", (2, 3, 4), [4.0, 6.0, 8.0])
    text = (tmp_path / "one.xdmf").read_text()
    assert ('<Topology TopologyType="3DCoRectMesh" Dimensions="3 4 5"/>' in text
            and 'GeometryType="ORIGIN_DXDYDZ"' in text
            and 'Format="XML">0.0 0.0 0.0</DataItem>' in text
            and 'Format="XML">2.0 2.0 2.0</DataItem>' in text
            and '<DataItem Dimensions="2 3 4" NumberType="Int"' in text)


# ---- bad inputs ---------------------------------------------------------------


def test_bad_microstructures(tmp_path):
    def bad(match, **changes):
        m = ellipses(n=5)
        for k, v in changes.items():
            setattr(m, k, v)
        for write in (micro.write_hdf5, micro.write_xyz):
            with pytest.raises(ValueError, match=match):
                write(tmp_path / "bad", m)
    bad("quaternions: a Microstructure of ellipses", quaternions=np.zeros((5, 4)))
    bad(r"centres: expected shape \(5, 2\)", centres=np.zeros((5, 3)))
    bad(r"angles: expected shape \(5,\)", angles=np.zeros((5, 1)))
    bad("angles: None", angles=None)
    bad(r"box: expected shape \(3,\) \(ellipsoids\) or \(2,\)", box=np.ones(4))
    with pytest.raises(ValueError, match=r"forms: expected shape \(5, 3\)"):
        micro.write_hdf5(tmp_path / "bad", micro.Microstructure(
            np.ones(2), np.zeros((5, 2)), np.zeros((5, 6)), np.ones((5, 2)),
            angles=np.zeros(5)))
    m = ellipsoids(n=3)
    m.angles = np.zeros(3)
    with pytest.raises(ValueError, match="angles: a Microstructure of ellipsoids"):
        micro.write_hdf5(tmp_path / "bad", m)
    m = ellipses(n=3)
    m.image = np.zeros((2, 2, 2), dtype=np.int32)
    with pytest.raises(ValueError, match="image: expected 2 dimensions"):
        micro.write_hdf5(tmp_path / "bad", m)
    m = ellipses(n=3)
    m.extra = {"dimension": 3}
    with pytest.raises(ValueError, match="dimension"):
        micro.write_hdf5(tmp_path / "bad", m)
    assert os.listdir(tmp_path) == []


def test_bad_files(tmp_path):
    h5py = pytest.importorskip("h5py")
    micro.write_hdf5(tmp_path / "e.h5", ellipses(n=4))

    def altered(name, change):
        path = tmp_path / name
        path.write_bytes((tmp_path / "e.h5").read_bytes())
        with h5py.File(path, "a") as f:
            change(f)
        return path
    # a 2D file with quaternions
    p = altered("q.h5", lambda f: f.create_dataset("quaternions", data=np.zeros((4, 4))))
    with pytest.raises(ValueError, match="/quaternions in a file of the 2D layout"):
        micro.read_hdf5(p)
    # the 2D layout without its attribute: read as 3D, /box refused
    p = altered("nodim.h5", lambda f: f.attrs.__delitem__("dimension"))
    with pytest.raises(ValueError, match=r"/box has dtype float64 and shape \(2,\), "
                       r"not float64 \(3,\) \(the 3D layout"):
        micro.read_hdf5(p)
    # mixed: dimension 2 with a box of 3 sides, or of no dimension known
    def box3(f):
        del f["box"]
        f["box"] = np.ones(3)
    with pytest.raises(ValueError, match=r"/box .* not float64 \(2,\) \(the 2D layout"):
        micro.read_hdf5(altered("box3.h5", box3))
    for value in (np.int32(5), np.float64(2.0), "2"):
        p = altered("dim.h5", lambda f: f.attrs.__setitem__("dimension", value))
        with pytest.raises(ValueError, match="attribute dimension is"):
            micro.read_hdf5(p)
    p = altered("img.h5", lambda f: f.create_dataset("image", data=np.zeros((2, 2, 2),
                                                                         np.int32)))
    with pytest.raises(ValueError, match="/image is not int32 of 2 dimensions"):
        micro.read_hdf5(p)
    # XYZ: dimension=2 without the column angle, an ellipse off the plane
    micro.write_xyz(tmp_path / "e.xyz", ellipses(n=2))
    lines = (tmp_path / "e.xyz").read_text().splitlines()
    (tmp_path / "noangle.xyz").write_text("\n".join(
        [lines[0], lines[1].replace(":angle:R:1", "")]
        + [" ".join(x.split()[:-1]) for x in lines[2:]]) + "\n")
    with pytest.raises(ValueError, match=r"no angle column \(dimension=2\)"):
        micro.read_xyz(tmp_path / "noangle.xyz")
    row = lines[2].split()
    row[3] = "0.5"
    (tmp_path / "off.xyz").write_text("\n".join(lines[:2] + [" ".join(row)] + lines[3:]))
    with pytest.raises(ValueError, match="off the plane z = 0"):
        micro.read_xyz(tmp_path / "off.xyz")
    (tmp_path / "d4.xyz").write_text("\n".join(
        [lines[0], lines[1].replace("dimension=2", "dimension=4")] + lines[2:]))
    with pytest.raises(ValueError, match="dimension=4, not 2 or 3"):
        micro.read_xyz(tmp_path / "d4.xyz")
    # a header or a line that is not of write_xyz: the file and the cause
    # named (a KeyError or a bare conversion message escaped)
    for name, text, match in (
            ("nolat.xyz", [lines[0], lines[1].replace("Lattice=", "Cell=")],
             "no Lattice= in the header line"),
            ("noprop.xyz", [lines[0], lines[1].replace("Properties=", "P=")],
             "no Properties= in the header line"),
            ("badlat.xyz", [lines[0], lines[1].replace('Lattice="', 'Lattice="x ')],
             "Lattice is not 9 numbers of an orthorhombic box"),
            ("count.xyz", ["two", lines[1]], "the first line, 'two', is not a "
             "count of particles"),
            ("neg.xyz", ["-2", lines[1]], "the first line, '-2', is not a"),
            ("width.xyz", [lines[0], lines[1].replace("pos:R:3", "pos:R:x")],
             "column pos has no width"),
            ("word.xyz", [lines[0], lines[1], "X abc" + lines[2][
                lines[2].index(" ", 2):]], "column pos: could not convert")):
        (tmp_path / name).write_text("\n".join(text + lines[len(text):]) + "\n")
        with pytest.raises(ValueError, match=match):
            micro.read_xyz(tmp_path / name)
