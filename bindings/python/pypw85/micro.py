# SPDX-License-Identifier: BSD-3-Clause
"""Microstructures: the voxel image of a set of ellipsoids, and the files
that pw85-pack writes (HDF5, its XDMF companion, extended XYZ).

`voxel_image` wraps ``pw85_image.h``: voxel ``(i, j, k)`` of an
``(n0, n1, n2)`` image of the box ``[origin, origin + sides]`` stands for
the point ``origin + ((i + ½)·L0/n0, (j + ½)·L1/n1, (k + ½)·L2/n2)``; its
value is the position of the ellipsoid that contains that point (the least,
when several do), or −1 for the matrix, decided exactly (no tolerance: a
point on a surface to the last bit is inside). `phase_fraction` is the
fraction of voxels that hold an ellipsoid.

`Microstructure` is one configuration; `read_hdf5` / `write_hdf5` read and
write the HDF5 layout of the documentation ("Microstructures for FFT
solvers and viewers", with h5py: ``/box``, ``/centres``, ``/forms``,
``/axes``, ``/quaternions`` (w, x, y, z), optional ``/image``, root
attributes ``packing_fraction``, ``seed``, ``pw85_version``, ``method``),
`write_xdmf` its companion for ParaView, and `read_xyz` / `write_xyz` the
extended XYZ that OVITO and ASE read (orientation in OVITO's order x, y, z,
w). Every writer writes a temporary file beside the target, then renames
it: a file is written whole or not at all.
"""

from __future__ import annotations

import ctypes
import dataclasses
import math
import operator
import os
import re
import shlex
import tempfile
import typing

import numpy as np

from ._batch import threads_count as _threads_count
from ._constants import EDOM, EINVAL, ENOTPOSDEF
from ._errors import Error
from ._libpw85 import lib as _lib, version as _library_version
from ._symbols import declare as _declare

if typing.TYPE_CHECKING:  # annotations only
    from typing import Optional, Sequence
    from numpy.typing import ArrayLike, NDArray

__all__ = ["voxel_image", "phase_fraction", "Microstructure", "read_hdf5",
           "write_hdf5", "write_xdmf", "read_xyz", "write_xyz", "MAX_DIM"]

_P = ctypes.c_void_p
_SIZE = ctypes.c_size_t
_INT = ctypes.c_int

#: The prototypes of pw85_image.h (since 2.4.0).
LIBPW85_IMAGE = {
    "pw85_image_voxels": (_INT, [_SIZE, _P, _P, _P, _P, _INT, _P, _P, _INT]),
    "pw85_image_fraction": (_INT, [_P, _P, _P, _P]),
}
_declare(_lib, LIBPW85_IMAGE)

#: The largest number of voxels along an axis (PW85_IMAGE_MAX_DIM, 2²⁰).
MAX_DIM = 1 << 20
# |c_k − o_k| + √Q_kk ≤ 2²⁹·L_k (pw85_image.h).
_REACH = 2.0**29


def _vec3(name, x):
    a = np.ascontiguousarray(x, dtype=np.float64)
    if a.shape != (3,):
        raise ValueError("%s: expected shape (3,), got %s" % (name, a.shape))
    return a


def voxel_image(centres: ArrayLike, q: ArrayLike, sides: ArrayLike,
                dims, *, origin: Optional[ArrayLike] = None,
                periodic: bool = True, threads: int = 1) -> NDArray:
    """The voxel image of n ellipsoids (pw85_image_voxels).

    Parameters
    ----------
    centres : array_like, shape (n, 3)
        The centres.
    q : array_like, shape (n, 6)
        The quadratic forms (upper triangle, row by row), positive
        definite.
    sides : array_like, shape (3,)
        The sides L of the box (> 0).
    dims : int or sequence of 3 ints
        The voxels along each axis (1 to `MAX_DIM`); an int for a cube.
    origin : array_like, shape (3,), optional
        The corner of the box (default 0).
    periodic : bool
        True: the box is periodic (every image of every ellipsoid counts);
        False: an open domain (only the ellipsoids, clipped to the box).
    threads : int
        1 (the calling thread), 0 (OpenMP's default) or more; the image is
        the same for any number.

    Returns
    -------
    numpy.ndarray of int32, shape dims
        ``image[i, j, k]``: the position of the ellipsoid containing the
        voxel's point (the least if several), or −1.

    Raises
    ------
    Error
        EDOM (a value not finite), ENOTPOSDEF (a form, named), EINVAL (a
        rule of pw85_image.h, named).
    """
    where = "voxel_image"
    c = np.ascontiguousarray(centres, dtype=np.float64)
    if c.ndim != 2 or c.shape[1] != 3:
        raise ValueError("centres: expected shape (n, 3), got %s" % (c.shape,))
    n = c.shape[0]
    qa = np.ascontiguousarray(q, dtype=np.float64)
    if qa.shape != (n, 6):
        raise ValueError("q: expected shape (%d, 6), got %s" % (n, qa.shape))
    L = _vec3("sides", sides)
    o = None if origin is None else _vec3("origin", origin)
    if isinstance(dims, (int, np.integer)):
        dims = (dims,) * 3
    try:
        d = tuple(dims)
    except TypeError:
        raise TypeError("dims: expected an int or 3 ints, got %r"
                        % (dims,)) from None
    if len(d) != 3:
        raise ValueError("dims: expected 3 integers, got %r" % (dims,))
    if not all(isinstance(x, (int, np.integer))
               and not isinstance(x, (bool, np.bool_)) for x in d):
        raise TypeError("dims: expected integers, got %r" % (dims,))
    d = tuple(int(x) for x in d)
    t = _threads_count(threads)
    for name, x in (("centres", c), ("q", qa), ("sides", L), ("origin", o)):
        if x is not None and not np.isfinite(x).all():
            raise Error(EDOM, where, "%s has a value that is not finite" % name)
    if not (L > 0).all():
        raise Error(EINVAL, where, "sides = %s: each must be > 0" % (L,))
    if not all(1 <= x <= MAX_DIM for x in d):
        raise Error(EINVAL, where, "dims = %s: each must be from 1 to %d"
                    % (d, MAX_DIM))
    if n > 2**31 - 1:
        raise Error(EINVAL, where, "%d ellipsoids: at most 2³¹ − 1" % n)
    oo = np.zeros(3) if o is None else o
    if n:
        diag = qa[:, [0, 3, 5]]
        with np.errstate(invalid="ignore", over="ignore"):
            reach = np.abs(c - oo) + np.sqrt(diag)
            # (2²⁹·L may be +∞: the reach must be finite too)
            ok = np.isfinite(reach) & (reach <= _REACH * L)
        bad = np.nonzero(~ok.all(axis=1))[0]
        if bad.size and (diag[bad[0]] > 0).all():
            p = int(bad[0])
            raise Error(EINVAL, where,
                        "ellipsoid %d: |c_k − o_k| + √Q_kk ≤ 2²⁹·L_k fails "
                        "(centre %s, √Q_kk %s)" % (p, c[p], np.sqrt(diag[p])))
    image = np.empty(d, dtype=np.int32)
    dims_c = (_SIZE * 3)(*d)
    status = _lib.pw85_image_voxels(
        n, c.ctypes.data if n else None, qa.ctypes.data if n else None,
        None if o is None else o.ctypes.data, L.ctypes.data,
        1 if periodic else 0, ctypes.addressof(dims_c), image.ctypes.data, t)
    if status == ENOTPOSDEF:
        # The library's rule is exact: name the first form it rejects.
        one = (_SIZE * 3)(1, 1, 1)
        probe = np.empty((1, 1, 1), dtype=np.int32)
        for p in range(n):
            if _lib.pw85_image_voxels(
                    1, c[p].ctypes.data, qa[p].ctypes.data, None,
                    L.ctypes.data, 1, ctypes.addressof(one),
                    probe.ctypes.data, 1) == ENOTPOSDEF:
                raise Error(status, where, "q[%d] = %s is not positive "
                            "definite" % (p, qa[p]))
    if status != 0:
        raise Error(status, where)
    return image


def phase_fraction(image: ArrayLike) -> float:
    """The fraction of voxels of image that hold an ellipsoid (value ≥ 0),
    correctly rounded (pw85_image_fraction)."""
    a = np.asarray(image)
    if a.dtype.kind not in "iu":
        raise TypeError("image: expected integers (int32), got dtype %s"
                        % a.dtype)
    if a.dtype != np.int32 and a.size and (
            int(a.min()) < -2**31 or int(a.max()) > 2**31 - 1):
        raise ValueError("image: values from %d to %d do not fit int32"
                         % (int(a.min()), int(a.max())))
    a = np.ascontiguousarray(a, dtype=np.int32)
    if a.ndim != 3 or a.size == 0:
        raise ValueError("image: expected a non-empty 3-d array, got shape %s"
                         % (a.shape,))
    dims_c = (_SIZE * 3)(*a.shape)
    fraction = ctypes.c_double()
    status = _lib.pw85_image_fraction(ctypes.addressof(dims_c), a.ctypes.data,
                                      None, ctypes.addressof(fraction))
    if status != 0:
        raise Error(status, "phase_fraction")
    return fraction.value


# ---------------------------------------------------------------------------
# Files.


@dataclasses.dataclass
class Microstructure:
    """A configuration of ellipsoids in a periodic box, as pw85-pack writes
    it (all arrays float64 but image, int32)."""

    #: The sides of the periodic box, shape (3,).
    box: NDArray
    #: The centres, shape (n, 3).
    centres: NDArray
    #: The quadratic forms (the q of pw85.h), shape (n, 6).
    forms: NDArray
    #: The semi-axes, shape (n, 3).
    axes: NDArray
    #: The unit quaternions (w, x, y, z), shape (n, 4).
    quaternions: NDArray
    #: The seed of the packing (uint64).
    seed: int = 0
    #: The packing method ("rsa", ...).
    method: str = ""
    #: The version of pw85 that wrote it.
    pw85_version: str = _library_version
    #: The voxel image, shape (m0, m1, m2), or None.
    image: Optional[NDArray] = None
    #: Other root attributes of the file (pw85-pack's "attempts", ...).
    extra: dict = dataclasses.field(default_factory=dict)

    def __len__(self):
        return self.centres.shape[0]

    @property
    def packing_fraction(self) -> float:
        """Σ 4π/3·a0·a1·a2 / V."""
        a = np.asarray(self.axes, dtype=np.float64)
        return float(sum(4.0 / 3.0 * math.pi * x * y * z for x, y, z in a)
                     / np.prod(self.box))


def _replace(path, write, mode="wb"):
    """write(file) into a temporary file beside path, then rename it."""
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=os.path.basename(path) + ".tmp-",
                               dir=directory)
    try:
        os.close(fd)
        write(tmp)
        mask = os.umask(0)
        os.umask(mask)
        os.chmod(tmp, 0o666 & ~mask)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise


def _h5py():
    try:
        import h5py
    except ImportError as e:  # pragma: no cover
        raise ImportError("pypw85.micro: reading and writing HDF5 needs h5py "
                          "(Debian: python3-h5py)") from e
    return h5py


_LAYOUT = (("centres", 3), ("forms", 6), ("axes", 3), ("quaternions", 4))


def write_hdf5(path, m: Microstructure) -> None:
    """Write m in the HDF5 layout of the documentation, whole or not at all."""
    h5py = _h5py()
    n = len(m)
    arrays = {}
    for name, width in _LAYOUT:
        a = np.ascontiguousarray(getattr(m, name), dtype=np.float64)
        if a.shape != (n, width):
            raise ValueError("%s: expected shape (%d, %d), got %s"
                             % (name, n, width, a.shape))
        arrays[name] = a
    box = _vec3("box", m.box)

    def write(tmp):
        with h5py.File(tmp, "w") as f:
            f["box"] = box
            for name, a in arrays.items():
                f[name] = a
            if m.image is not None:
                img = np.ascontiguousarray(m.image, dtype=np.int32)
                if img.ndim != 3:
                    raise ValueError("image: expected 3 dimensions")
                f["image"] = img
                f.attrs["image_fraction"] = phase_fraction(img)
            for key, value in m.extra.items():
                f.attrs[key] = value
            f.attrs["packing_fraction"] = np.float64(m.packing_fraction)
            f.attrs["seed"] = np.uint64(m.seed)
            f.attrs["pw85_version"] = str(m.pw85_version)
            f.attrs["method"] = str(m.method)
    _replace(path, write)


def read_hdf5(path, *, image: bool = True) -> Microstructure:
    """Read a file of the HDF5 layout; ValueError naming what is missing or
    of another type or shape."""
    h5py = _h5py()
    with h5py.File(path, "r") as f:
        def dataset(name, shape):
            if name not in f or not isinstance(f[name], h5py.Dataset):
                raise ValueError("%s: no dataset /%s" % (path, name))
            d = f[name]
            if d.dtype != np.float64 or len(d.shape) != len(shape) or any(
                    s is not None and s != t for s, t in zip(shape, d.shape)):
                raise ValueError("%s: /%s has dtype %s and shape %s, not float64 %s"
                                 % (path, name, d.dtype, d.shape, shape))
            return d[()]
        box = dataset("box", (3,))
        centres = dataset("centres", (None, 3))
        n = centres.shape[0]
        arrays = {name: dataset(name, (n, width)) for name, width in _LAYOUT[1:]}
        for key in ("packing_fraction", "seed", "pw85_version", "method"):
            if key not in f.attrs:
                raise ValueError("%s: no attribute %s" % (path, key))
        img = None
        if image and "image" in f:
            img = f["image"][()]
            if img.dtype != np.int32 or img.ndim != 3:
                raise ValueError("%s: /image is not int32 of 3 dimensions" % path)
        def text(v):
            return v.decode() if isinstance(v, bytes) else str(v)
        extra = {k: v for k, v in f.attrs.items()
                 if k not in ("packing_fraction", "seed", "pw85_version",
                              "method", "image_fraction")}
        return Microstructure(box=box, centres=centres, image=img,
                              seed=int(f.attrs["seed"]),
                              method=text(f.attrs["method"]),
                              pw85_version=text(f.attrs["pw85_version"]),
                              extra=extra, **arrays)


def write_xdmf(path, h5_path, dims: Sequence[int], box: ArrayLike,
               origin: ArrayLike = (0.0, 0.0, 0.0)) -> None:
    """The XDMF companion of an HDF5 file's /image, for ParaView (XDMF lists
    axes slowest first: the image's first index, along x, is ParaView's Z;
    see the documentation)."""
    try:
        d = [operator.index(x) for x in dims]
    except TypeError:
        raise ValueError("dims: expected 3 integers from 1, got %r"
                         % (dims,)) from None
    if len(d) != 3 or min(d) < 1:
        raise ValueError("dims: expected 3 integers from 1, got %r"
                         % (dims,))
    b = _vec3("box", box)
    o = _vec3("origin", origin)
    h = [b[k] / d[k] for k in range(3)]
    name = os.path.basename(os.fspath(h5_path))
    text = (
        '<?xml version="1.0" ?>\n'
        '<Xdmf Version="3.0">\n'
        '  <Domain>\n'
        '    <Grid Name="image" GridType="Uniform">\n'
        '      <Topology TopologyType="3DCoRectMesh" Dimensions="%d %d %d"/>\n'
        '      <Geometry GeometryType="ORIGIN_DXDYDZ">\n'
        '        <DataItem Name="Origin" Dimensions="3" NumberType="Float" '
        'Precision="8" Format="XML">%r %r %r</DataItem>\n'
        '        <DataItem Name="Spacing" Dimensions="3" NumberType="Float" '
        'Precision="8" Format="XML">%r %r %r</DataItem>\n'
        '      </Geometry>\n'
        '      <Attribute Name="phase" AttributeType="Scalar" Center="Cell">\n'
        '        <DataItem Dimensions="%d %d %d" NumberType="Int" Precision="4" '
        'Format="HDF">%s:/image</DataItem>\n'
        '      </Attribute>\n'
        '    </Grid>\n'
        '  </Domain>\n'
        '</Xdmf>\n' % (d[0] + 1, d[1] + 1, d[2] + 1, float(o[0]), float(o[1]),
                       float(o[2]), h[0], h[1], h[2], d[0], d[1], d[2], name))

    def write(tmp):
        with open(tmp, "w") as f:
            f.write(text)
    _replace(path, write)


_PROPERTIES = ("species:S:1:pos:R:3:aspherical_shape:R:3:orientation:R:4")


def _xyz_text(name, value):
    """value, quoted, for an extended XYZ header (a space would end it); a
    double quote or a line break, which no quoting of the format carries,
    or a backslash (ASE's readers take it as an escape): ValueError."""
    text = str(value)
    if any(ch in text for ch in '"\\\n\r'):
        raise ValueError("%s: %r holds a double quote, a backslash or a line "
                         "break, which an extended XYZ header cannot carry"
                         % (name, text))
    return '"%s"' % text


def write_xyz(path, m: Microstructure, species: str = "X") -> None:
    """Extended XYZ as OVITO reads ellipsoids (and ASE reads atoms):
    Lattice, pbc, Properties=species:S:1:pos:R:3:aspherical_shape:R:3:
    orientation:R:4 (x, y, z, w); every value to 17 significant digits."""
    n = len(m)
    box = _vec3("box", m.box)
    c = np.asarray(m.centres, dtype=np.float64)
    a = np.asarray(m.axes, dtype=np.float64)
    p = np.asarray(m.quaternions, dtype=np.float64)
    lines = ["%d" % n,
             'Lattice="%r 0 0 0 %r 0 0 0 %r" pbc="T T T" Properties=%s '
             'packing_fraction=%r seed=%d method=%s pw85_version=%s'
             % (float(box[0]), float(box[1]), float(box[2]), _PROPERTIES,
                m.packing_fraction, m.seed,
                _xyz_text("method", m.method or "none"),
                _xyz_text("pw85_version", m.pw85_version))]
    for k in range(n):
        values = list(c[k]) + list(a[k]) + [p[k][1], p[k][2], p[k][3], p[k][0]]
        lines.append(species + " " + " ".join(repr(float(v)) for v in values))

    def write(tmp):
        with open(tmp, "w") as f:
            f.write("\n".join(lines) + "\n")
    _replace(path, write)


def read_xyz(path) -> Microstructure:
    """Read an extended XYZ file with the columns of `write_xyz` (any order
    of the Properties, orthorhombic Lattice); the forms are computed from
    the axes and quaternions (pw85_ellipsoid_quaternion)."""
    from . import ellipsoid_quaternion
    with open(path) as f:
        n = int(f.readline())
        header = f.readline()
        fields = dict(re.findall(r'(\w+)=("[^"]*"|\S+)', header))
        fields = {k: v.strip('"') for k, v in fields.items()}
        lattice = [float(x) for x in fields["Lattice"].split()]
        if len(lattice) != 9 or any(lattice[i] != 0 for i in (1, 2, 3, 5, 6, 7)):
            raise ValueError("%s: Lattice is not orthorhombic: %s" % (path, lattice))
        spec = fields["Properties"].split(":")
        columns, at = {}, 0
        for name, _kind, width in zip(spec[0::3], spec[1::3], spec[2::3]):
            columns[name] = (at, at + int(width))
            at += int(width)
        for name in ("pos", "aspherical_shape", "orientation"):
            if name not in columns:
                raise ValueError("%s: no %s column" % (path, name))
        rows = [shlex.split(f.readline()) for _ in range(n)]
    if any(len(r) != at for r in rows):
        raise ValueError("%s: a line has not %d columns" % (path, at))

    def block(name):
        lo, hi = columns[name]
        return np.array([[float(x) for x in r[lo:hi]] for r in rows],
                        dtype=np.float64).reshape(n, hi - lo)
    c, a, o = block("pos"), block("aspherical_shape"), block("orientation")
    p = o[:, [3, 0, 1, 2]]
    forms = np.array([ellipsoid_quaternion(a[k], p[k]) for k in range(n)]
                     ).reshape(n, 6)
    extra = {k: v for k, v in fields.items()
             if k not in ("Lattice", "pbc", "Properties", "seed", "method",
                          "pw85_version", "packing_fraction")}
    return Microstructure(box=np.array(lattice[0::4]), centres=c, forms=forms,
                          axes=a, quaternions=p, seed=int(fields.get("seed", 0)),
                          method=fields.get("method", ""),
                          pw85_version=fields.get("pw85_version", ""),
                          extra=extra)
