# SPDX-License-Identifier: BSD-3-Clause
"""Microstructures: the voxel image of a set of ellipsoids (or ellipses),
and the files that pw85-pack writes (HDF5, its XDMF companion, extended
XYZ), in 3D or in 2D (``pw85-pack --2d``).

`voxel_image` wraps ``pw85_image.h``: voxel ``(i, j, k)`` of an
``(n0, n1, n2)`` image of the box ``[origin, origin + sides]`` stands for
the point ``origin + ((i + ½)·L0/n0, (j + ½)·L1/n1, (k + ½)·L2/n2)``; its
value is the position of the ellipsoid that contains that point (the least,
when several do), or −1 for the matrix, decided exactly (no tolerance: a
point on a surface to the last bit is inside). `phase_fraction` is the
fraction of voxels that hold an ellipsoid. Given ellipses (centres of
shape (n, 2), forms of pw85_2d.h of shape (n, 3), two sides), it draws the
pixel image of ``pw85-pack --2d`` (each ellipse as one layer of
ellipsoid, exactly; see `voxel_image`).

`Microstructure` is one configuration; `read_hdf5` / `write_hdf5` read and
write the HDF5 layout of the documentation ("Microstructures for FFT
solvers and viewers", with h5py: ``/box``, ``/centres``, ``/forms``,
``/axes``, ``/quaternions`` (w, x, y, z), optional ``/image``, root
attributes ``packing_fraction``, ``seed``, ``pw85_version``, ``method``),
`write_xdmf` its companion for ParaView, and `read_xyz` / `write_xyz` the
extended XYZ that OVITO and ASE read (orientation in OVITO's order x, y, z,
w).

Ellipses: a `Microstructure` whose box has two sides is one of ellipses
(its `~Microstructure.dimension` is 2): centres (n, 2), forms (n, 3) (the
q of pw85_2d.h), axes (n, 2) and `~Microstructure.angles` (n,) (the θ of
`pypw85.d2.ellipse`) instead of quaternions. The files are those of
``pw85-pack --2d`` (the documentation's "Ellipses (--2d)"): in HDF5,
``/box`` [2], ``/centres`` [n][2], ``/forms`` [n][3], ``/axes`` [n][2],
``/angles`` [n], an optional ``/image`` int32 [m0][m1], and the root
attribute ``dimension`` = 2 (int32; absent from 3D files, which are
written as before to the byte); the XDMF companion a ``2DCoRectMesh``; the
XYZ in the plane z = 0 of a cell of height twice the largest semi-axis
(the box's larger side without ellipses), with pbc "T T F", a column
``angle`` and ``dimension=2`` in the header.

Every writer writes a temporary file beside the target, then renames
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
from xml.sax.saxutils import escape as xml_escape

import numpy as np

from ._batch import threads_count as _threads_count
from ._constants import EDOM, EINVAL, ENOTPOSDEF
from ._convert import real_array as _real_array, unmasked as _unmasked
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


def _vec(name, x, dim=3):
    a = _real_array(name, x)
    if a.shape != (dim,):
        raise ValueError("%s: expected shape (%d,), got %s" % (name, dim, a.shape))
    return a


def _embed(c, q, sides, origin):
    """Ellipses (c, q of pw85_2d.h) in the periodic rectangle sides as the
    ellipsoids that pw85-pack --2d gives pw85_image_voxels()
    (tools/pw85-pack/dim.c, image_2d; docs/microstructures.rst, "Ellipses
    (--2d)"): centre (c0, L0/2, c1), form [[Q00, 0, Q01], [0, max(Q00,
    Q11), 0], [Q01, 0, Q11]], box (L0, L0, L1), origin (o0, 0, o1). One
    layer of voxels along the added axis has its centres on the plane
    u1 = L0/2 exactly, where the difference along u1 is exactly 0 and the
    ellipsoid's quadratic form is the ellipse's: each pixel is the exact
    decision for the ellipse (an image along u1 that reaches the plane cuts
    it in a smaller ellipse of the same centre, inside the first)."""
    n = c.shape[0]
    c3 = np.empty((n, 3))
    c3[:, 0], c3[:, 1], c3[:, 2] = c[:, 0], 0.5 * sides[0], c[:, 1]
    q3 = np.zeros((n, 6))
    q3[:, 0], q3[:, 2], q3[:, 5] = q[:, 0], q[:, 1], q[:, 2]
    q3[:, 3] = np.fmax(q[:, 0], q[:, 2])
    o3 = None if origin is None else np.array([origin[0], 0.0, origin[1]])
    return c3, q3, np.array([sides[0], sides[0], sides[1]]), o3


def voxel_image(centres: ArrayLike, q: ArrayLike, sides: ArrayLike,
                dims, *, origin: Optional[ArrayLike] = None,
                periodic: bool = True, threads: int = 1) -> NDArray:
    """The voxel image of n ellipsoids (pw85_image_voxels), or the pixel
    image of n ellipses.

    Ellipses (centres of shape (n, 2)): the image of ``pw85-pack --2d
    --voxels``, pixel ``(i, j)`` the point ``origin + ((i + ½)·L0/n0,
    (j + ½)·L1/n1)``, each ellipse decided exactly through
    pw85_image_voxels on one layer of voxels (the ellipse as an ellipsoid
    of centre (c0, L0/2, c1) and form [[Q00, 0, Q01], [0, max(Q00, Q11),
    0], [Q01, 0, Q11]] in the box (L0, L0, L1) cut into n0 × 1 × n1
    voxels; docs/microstructures.rst, "Ellipses (--2d)").

    Parameters
    ----------
    centres : array_like, shape (n, 3), or (n, 2) for ellipses
        The centres.
    q : array_like, shape (n, 6), or (n, 3) for ellipses
        The quadratic forms (upper triangle, row by row: the q of pw85.h
        or pw85_2d.h), positive definite.
    sides : array_like, shape (3,), or (2,) for ellipses
        The sides L of the box (> 0).
    dims : int or sequence of 3 ints (2 for ellipses)
        The voxels along each axis (1 to `MAX_DIM`); an int for a cube
        (a square).
    origin : array_like, shape (3,) or (2,), optional
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
        ``image[i, j, k]`` (``image[i, j]`` for ellipses): the position of
        the ellipsoid containing the voxel's point (the least if
        several), or −1.

    Raises
    ------
    Error
        EDOM (a value not finite), ENOTPOSDEF (a form, named), EINVAL (a
        rule of pw85_image.h, named).
    """
    where = "voxel_image"
    if not isinstance(periodic, (bool, np.bool_)):
        raise TypeError("periodic: expected a bool, got %s"
                        % type(periodic).__name__)
    c = _real_array("centres", centres)
    if c.ndim != 2 or c.shape[1] not in (2, 3):
        raise ValueError("centres: expected shape (n, 3), or (n, 2) for "
                         "ellipses, got %s" % (c.shape,))
    n, dim = c.shape
    sym = dim * (dim + 1) // 2
    qa = _real_array("q", q)
    if qa.shape != (n, sym):
        raise ValueError("q: expected shape (%d, %d), got %s" % (n, sym, qa.shape))
    L = _vec("sides", sides, dim)
    o = None if origin is None else _vec("origin", origin, dim)
    if isinstance(dims, (int, np.integer)):
        dims = (dims,) * dim
    try:
        d = tuple(dims)
    except TypeError:
        raise TypeError("dims: expected an int or %d ints, got %r"
                        % (dim, dims)) from None
    if len(d) != dim:
        raise ValueError("dims: expected %d integers, got %r" % (dim, dims))
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
    noun = "ellipsoid" if dim == 3 else "ellipse"
    if n > 2**31 - 1:
        raise Error(EINVAL, where, "%d %ss: at most 2³¹ − 1" % (n, noun))
    user_q = qa
    if dim == 2:
        c, qa, L, o = _embed(c, qa, L, o)
        d3 = (d[0], 1, d[1])
    else:
        d3 = d
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
                        "%s %d: |c_k − o_k| + √Q_kk ≤ 2²⁹·L_k fails "
                        "(centre %s, √Q_kk %s%s)"
                        % (noun, p, c[p], np.sqrt(diag[p]),
                           "" if dim == 3 else ", the ellipse as an ellipsoid"))
    image = np.empty(d3, dtype=np.int32)
    dims_c = (_SIZE * 3)(*d3)
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
                            "definite" % (p, user_q[p]))
    if status != 0:
        raise Error(status, where)
    return image.reshape(d)


def phase_fraction(image: ArrayLike) -> float:
    """The fraction of voxels of image (3 dimensions, or 2: pixels) that
    hold an ellipsoid (value ≥ 0), correctly rounded
    (pw85_image_fraction)."""
    a = _image_int32(image)
    if a.ndim not in (2, 3) or a.size == 0:
        raise ValueError("image: expected a non-empty 3-d (or 2-d) array, "
                         "got shape %s" % (a.shape,))
    # 2-d: the m0 × 1 × m1 image of the same voxels
    dims_c = (_SIZE * 3)(*(a.shape if a.ndim == 3 else (a.shape[0], 1, a.shape[1])))
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
    """A configuration of ellipsoids in a periodic box, or of ellipses in a
    periodic rectangle (a box of two sides), as pw85-pack (``--2d``) writes
    it (all arrays float64 but image, int32)."""

    #: The sides of the periodic box, shape (3,), or (2,) for ellipses.
    box: NDArray
    #: The centres, shape (n, 3) (ellipses: (n, 2)).
    centres: NDArray
    #: The quadratic forms, shape (n, 6), the q of pw85.h (ellipses: (n, 3),
    #: the q of pw85_2d.h).
    forms: NDArray
    #: The semi-axes, shape (n, 3) (ellipses: (n, 2)).
    axes: NDArray
    #: The unit quaternions (w, x, y, z), shape (n, 4); None for ellipses.
    quaternions: Optional[NDArray] = None
    #: The seed of the packing (uint64).
    seed: int = 0
    #: The packing method ("rsa", ...).
    method: str = ""
    #: The version of pw85 that wrote it.
    pw85_version: str = _library_version
    #: The voxel image, shape (m0, m1, m2) (ellipses: (m0, m1)), or None.
    image: Optional[NDArray] = None
    #: Other root attributes of the file (pw85-pack's "attempts", ...).
    extra: dict = dataclasses.field(default_factory=dict)
    #: Ellipses only: the angles θ of `pypw85.d2.ellipse` (radians, a0
    #: along (cos θ, sin θ)), shape (n,); None for ellipsoids.
    angles: Optional[NDArray] = None

    def __len__(self):
        return self.centres.shape[0]

    @property
    def dimension(self) -> int:
        """3 (ellipsoids) or 2 (ellipses): the number of sides of box."""
        return _layout(self.box).dim

    @property
    def packing_fraction(self) -> float:
        """Σ 4π/3·a0·a1·a2 / V; for ellipses the area fraction
        Σ π·a0·a1 / (L0·L1).

        Where every particle has the same semi-axes, n·v/V formed as
        pw85-pack forms it (the same value, bit for bit: a file of the tool
        read and written back keeps its attribute); else the sum correctly
        rounded (math.fsum), then divided by V.
        """
        layout = _layout(self.box)
        a = np.asarray(self.axes, dtype=np.float64)
        box = [float(x) for x in self.box]
        measure = box[0] * box[1]
        if len(box) == 3:
            measure *= box[2]
        if a.shape[0] > 0 and (a == a[0]).all():
            return float(a.shape[0]) * layout.measure(a[0]) / measure
        return math.fsum(layout.measure(row) for row in a) / measure


class _Layout(typing.NamedTuple):
    """What the files of one dimension hold (tools/pw85-pack/dim.h)."""
    dim: int
    sym: int             # doubles per form
    orientation: str     # the field and dataset of the orientations
    orient_shape: tuple  # the shape of one orientation
    other: str           # the orientation field of the other dimension
    measure: typing.Callable


# The same expression, rounding for rounding, as before the 2D layout.
_LAYOUTS = {
    3: _Layout(3, 6, "quaternions", (4,), "angles",
               lambda a: 4.0 / 3.0 * math.pi * a[0] * a[1] * a[2]),
    2: _Layout(2, 3, "angles", (), "quaternions",
               lambda a: math.pi * a[0] * a[1]),
}


def _layout(box):
    shape = np.shape(box)
    if len(shape) != 1 or shape[0] not in _LAYOUTS:
        raise ValueError("box: expected shape (3,) (ellipsoids) or (2,) "
                         "(ellipses), got %s" % (shape,))
    return _LAYOUTS[shape[0]]


def _checked(m, names=("centres", "forms", "axes")):
    """m's layout, box and arrays (names and the orientations, float64,
    contiguous), their shapes checked against the box's dimension: a
    ValueError naming the first that differs, or an orientation of the
    other dimension."""
    layout = _layout(m.box)
    box = _vec("box", m.box, layout.dim)
    n = len(m)
    if getattr(m, layout.other) is not None:
        raise ValueError("%s: a Microstructure of %s (box of %d sides) has %s "
                         "instead; set %s to None"
                         % (layout.other, "ellipses" if layout.dim == 2 else
                            "ellipsoids", layout.dim, layout.orientation,
                            layout.other))
    width = {"centres": (layout.dim,), "forms": (layout.sym,),
             "axes": (layout.dim,), layout.orientation: layout.orient_shape}
    arrays = {}
    for name in names + (layout.orientation,):
        value = getattr(m, name)
        if value is None:
            raise ValueError("%s: None, but a box of %d sides needs it"
                             % (name, layout.dim))
        a = np.ascontiguousarray(value, dtype=np.float64)
        if a.shape != (n,) + width[name]:
            raise ValueError("%s: expected shape %s, got %s"
                             % (name, (n,) + width[name], a.shape))
        arrays[name] = a
    return layout, box, arrays


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


# The attributes that read_hdf5 does not put in extra.
_OWN_ATTRS = ("packing_fraction", "seed", "pw85_version", "method",
              "image_fraction", "dimension")


def _image_int32(image):
    """The image as int32, or raise: TypeError for values that are not
    integers, ValueError for one outside int32 (a cast would wrap it) or a
    masked voxel."""
    _unmasked("image", image)
    a = np.asarray(image)
    if a.dtype.kind not in "iu":
        raise TypeError("image: expected integer voxel values (int32), got "
                        "dtype %s" % a.dtype)
    if a.size and a.dtype != np.int32 and a.dtype.itemsize >= 4 and \
            not (a.min() >= -2**31 and a.max() <= 2**31 - 1):
        bad = a.max() if a.max() > 2**31 - 1 else a.min()
        raise ValueError("image: a voxel value %d is outside int32" % bad)
    return np.ascontiguousarray(a, dtype=np.int32)


def _seed_uint64(seed):
    """The seed as numpy.uint64, or raise (TypeError, ValueError)."""
    if isinstance(seed, (bool, np.bool_)) or \
            not isinstance(seed, (int, np.integer)):
        raise TypeError("seed: expected an int, got %s" % type(seed).__name__)
    if not 0 <= int(seed) <= 2**64 - 1:
        raise ValueError("seed: expected an int from 0 to 2⁶⁴ − 1, got %d"
                         % int(seed))
    return np.uint64(int(seed))


def write_hdf5(path, m: Microstructure) -> None:
    """Write m in the HDF5 layout of the documentation (3D, or 2D for
    ellipses: /angles instead of /quaternions, and the root attribute
    ``dimension`` = 2 (int32), written in 2D only), whole or not at all."""
    h5py = _h5py()
    layout, box, arrays = _checked(m)
    if "dimension" in m.extra and m.extra["dimension"] != layout.dim:
        raise ValueError("extra: dimension = %r, but the box has %d sides"
                         % (m.extra["dimension"], layout.dim))
    img = None if m.image is None else _image_int32(m.image)
    seed = _seed_uint64(m.seed)

    def write(tmp):
        with h5py.File(tmp, "w") as f:
            f["box"] = box
            for name, a in arrays.items():
                f[name] = a
            if img is not None:
                if img.ndim != layout.dim:
                    raise ValueError("image: expected %d dimensions, got %d"
                                     % (layout.dim, img.ndim))
                f["image"] = img
                f.attrs["image_fraction"] = phase_fraction(img)
            for key, value in m.extra.items():
                f.attrs[key] = value
            f.attrs["packing_fraction"] = np.float64(m.packing_fraction)
            f.attrs["seed"] = seed
            f.attrs["pw85_version"] = str(m.pw85_version)
            f.attrs["method"] = str(m.method)
            if layout.dim != 3:  # 3D files: as before the 2D layout
                f.attrs["dimension"] = np.int32(layout.dim)
    _replace(path, write)


def read_hdf5(path, *, image: bool = True) -> Microstructure:
    """Read a file of the HDF5 layout, 3D or 2D (by its root attribute
    ``dimension``: 2, or absent for 3D); ValueError naming what is
    missing, of another type or shape, or of the other dimension."""
    h5py = _h5py()
    with h5py.File(path, "r") as f:
        dim = 3
        if "dimension" in f.attrs:
            v = f.attrs["dimension"]
            if (np.ndim(v) != 0 or np.asarray(v).dtype.kind not in "iu"
                    or int(v) not in _LAYOUTS):
                raise ValueError("%s: attribute dimension is %r, not 2 or 3"
                                 % (path, v))
            dim = int(v)
        layout = _LAYOUTS[dim]
        which = "the 2D layout (attribute dimension = 2)" if dim == 2 else \
            "the 3D layout (no attribute dimension)"

        def dataset(name, shape):
            if name not in f or not isinstance(f[name], h5py.Dataset):
                raise ValueError("%s: no dataset /%s (%s)" % (path, name, which))
            d = f[name]
            if d.dtype != np.float64 or len(d.shape) != len(shape) or any(
                    s is not None and s != t for s, t in zip(shape, d.shape)):
                raise ValueError("%s: /%s has dtype %s and shape %s, not float64 "
                                 "%s (%s)" % (path, name, d.dtype, d.shape,
                                              shape, which))
            return d[()]
        box = dataset("box", (dim,))
        if layout.other in f:
            raise ValueError("%s: /%s in a file of %s" % (path, layout.other, which))
        centres = dataset("centres", (None, dim))
        n = centres.shape[0]
        shapes = (("forms", (n, layout.sym)), ("axes", (n, dim)),
                  (layout.orientation, (n,) + layout.orient_shape))
        arrays = {name: dataset(name, shape) for name, shape in shapes}
        for key in ("packing_fraction", "seed", "pw85_version", "method"):
            if key not in f.attrs:
                raise ValueError("%s: no attribute %s" % (path, key))
        img = None
        if image and "image" in f:
            img = f["image"][()]
            if img.dtype != np.int32 or img.ndim != dim:
                raise ValueError("%s: /image is not int32 of %d dimensions"
                                 % (path, dim))
        def text(v):
            return v.decode() if isinstance(v, bytes) else str(v)
        extra = {k: v for k, v in f.attrs.items() if k not in _OWN_ATTRS}
        return Microstructure(box=box, centres=centres, image=img,
                              seed=int(f.attrs["seed"]),
                              method=text(f.attrs["method"]),
                              pw85_version=text(f.attrs["pw85_version"]),
                              extra=extra, **arrays)


# The characters of a file name refused in XML text: those outside XML
# 1.0's Char production (surrogates included: os.fsdecode() gives them for
# bytes that are not UTF-8), and tab, newline and carriage return, which a
# parser normalises (pw85-pack refuses the same).
_XML_BAD = re.compile("[^\u0020-\ud7ff\ue000-\ufffd\U00010000-\U0010ffff]")


def write_xdmf(path, h5_path, dims: Sequence[int], box: ArrayLike,
               origin: Optional[ArrayLike] = None) -> None:
    """The XDMF companion of an HDF5 file's /image, for ParaView (XDMF lists
    axes slowest first: the image's first index, along x, is ParaView's Z,
    or Y for a 2D image; see the documentation). dims, box and origin
    (default 0) have 3 entries, or 2 for the image of ellipses (a
    2DCoRectMesh with an ORIGIN_DXDY geometry, as pw85-pack --2d)."""
    try:
        d = [operator.index(x) for x in dims]
    except TypeError:
        raise ValueError("dims: expected 3 (or 2) integers from 1, got %r"
                         % (dims,)) from None
    if len(d) not in (2, 3) or min(d) < 1:
        raise ValueError("dims: expected 3 (or 2) integers from 1, got %r"
                         % (dims,))
    dim = len(d)
    if np.shape(box) != (dim,):
        raise ValueError("dims: %d integers for a box of shape %s"
                         % (dim, np.shape(box)))
    b = _vec("box", box, dim)
    o = _vec("origin", np.zeros(dim) if origin is None else origin, dim)
    h = [float(b[k] / d[k]) for k in range(dim)]

    def join(fmt, values):
        return " ".join(fmt % v for v in values)
    # the file name as XML text (a name may hold & < >); a character XML
    # 1.0 cannot hold (a control character, an undecodable byte) refused
    base = os.path.basename(os.fsdecode(h5_path))
    if _XML_BAD.search(base):
        raise ValueError("h5_path: %r holds a character that XML cannot "
                         "hold" % (base,))
    name = xml_escape(base)
    text = (
        '<?xml version="1.0" ?>\n'
        '<Xdmf Version="3.0">\n'
        '  <Domain>\n'
        '    <Grid Name="image" GridType="Uniform">\n'
        '      <Topology TopologyType="%dDCoRectMesh" Dimensions="%s"/>\n'
        '      <Geometry GeometryType="%s">\n'
        '        <DataItem Name="Origin" Dimensions="%d" NumberType="Float" '
        'Precision="8" Format="XML">%s</DataItem>\n'
        '        <DataItem Name="Spacing" Dimensions="%d" NumberType="Float" '
        'Precision="8" Format="XML">%s</DataItem>\n'
        '      </Geometry>\n'
        '      <Attribute Name="phase" AttributeType="Scalar" Center="Cell">\n'
        '        <DataItem Dimensions="%s" NumberType="Int" Precision="4" '
        'Format="HDF">%s:/image</DataItem>\n'
        '      </Attribute>\n'
        '    </Grid>\n'
        '  </Domain>\n'
        '</Xdmf>\n' % (dim, join("%d", [x + 1 for x in d]),
                       "ORIGIN_DXDYDZ" if dim == 3 else "ORIGIN_DXDY",
                       dim, join("%r", [float(x) for x in o]),
                       dim, join("%r", h), join("%d", d), name))

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
    orientation:R:4 (x, y, z, w); every value to 17 significant digits.

    Ellipses (as pw85-pack --2d): the plane z = 0 of a cell whose third
    vector (0, 0, H), H twice the largest semi-axis (the box's larger side
    without ellipses), is not periodic (pbc "T T F"); each ellipse as the
    ellipsoid of semi-axes (a0, a1, min(a0, a1)) turned by θ about z
    (orientation (0, 0, sin θ/2, cos θ/2)), θ itself in a last column
    ``angle``, and ``dimension=2`` in the header. ``species``, the first
    column of every line, is one word: a non-empty str without white
    space or quotes (ValueError, TypeError, before anything is written)."""
    if not isinstance(species, str):
        raise TypeError("species = %r is not a str" % (species,))
    if not species or re.search(r'[\s"\']', species):
        raise ValueError("species = %r is not one word (no white space or "
                         "quotes: it is a column of extended XYZ)"
                         % (species,))
    layout, box, arrays = _checked(m, ("centres", "axes"))
    n = len(m)
    c, a = arrays["centres"], arrays["axes"]
    if layout.dim == 3:
        p = arrays["quaternions"]
        height, pbc, columns, dimension = float(box[2]), "T", "", ""
    else:
        theta = arrays["angles"]
        # fmax, as io.c: the largest of 2·a, 0 without ellipses
        height = float(np.fmax.reduce(2 * a.ravel(), initial=0.0))
        if not height > 0:
            height = float(np.fmax(box[0], box[1]))
        pbc, columns, dimension = "F", ":angle:R:1", "dimension=2 "
    lines = ["%d" % n,
             'Lattice="%r 0 0 0 %r 0 0 0 %r" pbc="T T %s" Properties=%s%s '
             '%spacking_fraction=%r seed=%d method=%s pw85_version=%s'
             % (float(box[0]), float(box[1]), height, pbc, _PROPERTIES,
                columns, dimension, m.packing_fraction, m.seed,
                _xyz_text("method", m.method or "none"),
                _xyz_text("pw85_version", m.pw85_version))]
    for k in range(n):
        if layout.dim == 3:
            values = (list(c[k]) + list(a[k])
                      + [p[k][1], p[k][2], p[k][3], p[k][0]])
        else:
            t = float(theta[k])
            values = [c[k][0], c[k][1], 0.0, a[k][0], a[k][1],
                      min(a[k][0], a[k][1]), 0.0, 0.0, math.sin(0.5 * t),
                      math.cos(0.5 * t), t]
        lines.append(species + " " + " ".join(repr(float(v)) for v in values))

    def write(tmp):
        with open(tmp, "w") as f:
            f.write("\n".join(lines) + "\n")
    _replace(path, write)


def read_xyz(path) -> Microstructure:
    """Read an extended XYZ file with the columns of `write_xyz` (any order
    of the Properties, orthorhombic Lattice); the forms are computed from
    the axes and quaternions (pw85_ellipsoid_quaternion), or, in a file of
    ellipses (``dimension=2`` in the header: the plane z = 0, a column
    ``angle``), from the first two axes and the angles
    (pw85_2d_ellipse)."""
    from . import ellipsoid_quaternion
    with open(path) as f:
        first = f.readline()
        try:
            n = int(first)
        except ValueError:
            n = -1
        if n < 0:
            raise ValueError("%s: the first line, %r, is not a count of "
                             "particles" % (path, first.strip()))
        header = f.readline()
        fields = dict(re.findall(r'(\w+)=("[^"]*"|\S+)', header))
        fields = {k: v.strip('"') for k, v in fields.items()}
        text = fields.get("dimension", "3")  # absent: 3D
        if text not in ("2", "3"):
            raise ValueError("%s: dimension=%s, not 2 or 3" % (path, text))
        dim = int(text)
        for key in ("Lattice", "Properties"):
            if key not in fields:
                raise ValueError("%s: no %s= in the header line (a file of "
                                 "write_xyz has it)" % (path, key))
        try:
            lattice = [float(x) for x in fields["Lattice"].split()]
        except ValueError:
            lattice = []
        if len(lattice) != 9 or any(lattice[i] != 0 for i in (1, 2, 3, 5, 6, 7)):
            raise ValueError("%s: Lattice is not 9 numbers of an orthorhombic "
                             "box: %r" % (path, fields["Lattice"]))
        spec = fields["Properties"].split(":")
        columns, at = {}, 0
        for name, _kind, width in zip(spec[0::3], spec[1::3], spec[2::3]):
            if not width.isdigit():
                raise ValueError("%s: Properties=%s: column %s has no width"
                                 % (path, fields["Properties"], name))
            columns[name] = (at, at + int(width))
            at += int(width)
        needed = (("pos", "aspherical_shape", "orientation") if dim == 3
                  else ("pos", "aspherical_shape", "angle"))
        for name in needed:
            if name not in columns:
                raise ValueError("%s: no %s column%s" % (
                    path, name, " (dimension=2)" if dim == 2 else ""))
        rows = [shlex.split(f.readline()) for _ in range(n)]
    if any(len(r) != at for r in rows):
        raise ValueError("%s: a line has not %d columns" % (path, at))

    def block(name):
        lo, hi = columns[name]
        try:
            return np.array([[float(x) for x in r[lo:hi]] for r in rows],
                            dtype=np.float64).reshape(n, hi - lo)
        except ValueError as e:
            raise ValueError("%s: column %s: %s" % (path, name, e)) from None
    extra = {k: v for k, v in fields.items()
             if k not in ("Lattice", "pbc", "Properties", "seed", "method",
                          "pw85_version", "packing_fraction", "dimension")}
    common = dict(seed=int(fields.get("seed", 0)),
                  method=fields.get("method", ""),
                  pw85_version=fields.get("pw85_version", ""), extra=extra)
    c, a = block("pos"), block("aspherical_shape")
    if dim == 2:
        from . import d2
        if c.shape[1] != 3 or a.shape[1] != 3 or columns["angle"][1] - \
                columns["angle"][0] != 1:
            raise ValueError("%s: pos, aspherical_shape of 3 and angle of 1 "
                             "column expected (dimension=2)" % path)
        if (c[:, 2] != 0).any():
            raise ValueError("%s: an ellipse off the plane z = 0 (dimension=2)"
                             % path)
        theta = block("angle")[:, 0]
        a2 = np.ascontiguousarray(a[:, :2])
        forms = d2.ellipse(a2, theta) if n else np.empty((0, 3))
        return Microstructure(box=np.array([lattice[0], lattice[4]]),
                              centres=np.ascontiguousarray(c[:, :2]),
                              forms=forms, axes=a2, angles=theta, **common)
    o = block("orientation")
    p = o[:, [3, 0, 1, 2]]
    forms = np.array([ellipsoid_quaternion(a[k], p[k]) for k in range(n)]
                     ).reshape(n, 6)
    return Microstructure(box=np.array(lattice[0::4]), centres=c, forms=forms,
                          axes=a, quaternions=p, **common)
