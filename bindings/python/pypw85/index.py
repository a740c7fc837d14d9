# SPDX-License-Identifier: BSD-3-Clause
"""A spatial index of ellipsoids in an open domain or a periodic box.

`Index` wraps ``pw85_index.h``: ellipsoids stored by id (small
non-negative integers, such as their positions in the caller's arrays),
centre and quadratic form; overlap and near-contact queries whose answers
are those of `pypw85.overlap` and `pypw85.contact_function` on every pair
and every periodic image (the C header documents the contract: the image
rule, the side rule of a periodic box, the order of the results).

Arrays in, arrays out: `Index.insert` takes ``(n,)`` ids, ``(n, 3)``
centres (or one ``(3,)`` centre for all) and ``(n, 6)`` forms (or one
``(6,)`` form for all) in one call into the library; the queries return
NumPy arrays. Ids are integers (Python ``int`` or a NumPy integer type):
a float or a bool raises `TypeError`. An `Index` is a container of its
ids: ``len(index)``, ``id in index``, ``for id in index`` (ascending).

Errors name their cause: an input the library rejects raises `Error`
whose message says which rule failed, for which id (and which item of a
batch), with the numbers (``insert: ... ellipsoid 12 (item 3 of 5):
2·√Q_00·(1 + 2⁻²⁰) = 3.1 ≥ L_0 = 3``); its attributes ``status``, ``id``
and ``item`` give them to programs. The all-pairs queries and
`Index.overlap_any_many` run on up to ``threads`` OpenMP threads, at most
1024 (`OPENMP` says whether this libpw85 has them), with the GIL
released, and give the same arrays for any number of threads.

`pypw85.d2.Index` is the same class for ellipses (``pw85_2d_index.h``),
but for the sizes: centres ``(n, 2)``, forms ``(n, 3)`` (Q00, Q01, Q11),
shifts ``(m, 2)``, forces of `Index.energy` ``(n, 2)`` and torques ``(n,)``
(one angle per ellipse).
"""

from __future__ import annotations

import ctypes
import math
import types
import typing

import numpy as np

from typing import Callable, Tuple

if typing.TYPE_CHECKING:  # annotations only: nothing imported at run time
    from typing import Iterator, Optional, Union
    from numpy.typing import ArrayLike, NDArray
    IdLike = Union[int, np.integer]  # an id: int or a NumPy integer

from ._batch import threads_count as _threads_count
from ._constants import EDOM, EINVAL, ENOTPOSDEF, ERANGE
from ._convert import real as _real
from ._convert import real_array as _real_array
from ._convert import unmasked as _unmasked
from ._errors import Error
from ._libpw85 import lib as _lib
from ._symbols import declare as _declare

__all__ = ["Index", "OPENMP", "NO_ID", "MAX_ID"]

_P = ctypes.c_void_p
_SIZE = ctypes.c_size_t
_INT = ctypes.c_int
_DOUBLE = ctypes.c_double
_SIZE_P = ctypes.POINTER(_SIZE)
_INT_P = ctypes.POINTER(_INT)


def _prototypes(prefix):
    """The prototypes of pw85_index.h (prefix pw85_index_) or of
    pw85_2d_index.h (pw85_2d_index_): the same but for the sizes of the
    records (the handle is a ``void *``)."""
    return {prefix + name: proto for name, proto in {
        "create": (_INT, [_P, ctypes.POINTER(_P)]),
        "destroy": (None, [_P]),
        "count": (_INT, [_P, _SIZE_P]),
        "insert": (_INT, [_P, _SIZE, _P, _P]),
        "insert_many": (_INT, [_P, _SIZE, _P, _P, _P]),
        "update": (_INT, [_P, _SIZE, _P, _P]),
        "remove": (_INT, [_P, _SIZE]),
        "get": (_INT, [_P, _SIZE, _P, _P]),
        "overlap_any": (_INT, [_P, _P, _P, _SIZE, _INT_P, _SIZE_P]),
        "overlap_any_batch": (_INT, [_P, _SIZE, _P, _SIZE, _P, _SIZE, _P,
                                     _P, _P, _P, _INT]),
        "within": (_INT, [_P, _P, _P, _DOUBLE, _SIZE, _SIZE, _P, _P, _P,
                          _SIZE_P]),
        "overlapping_pairs": (_INT, [_P, _INT, _SIZE, _P, _P, _P, _SIZE_P]),
        "pairs_within": (_INT, [_P, _DOUBLE, _INT, _SIZE, _P, _P, _P,
                                _SIZE_P]),
        # pw85_index_energy since 2.4.0, pw85_2d_index_energy since 2.5.0
        "energy": (_INT, [_P, _INT, _DOUBLE, _P, _P, _INT, _SIZE,
                          ctypes.POINTER(_DOUBLE), _P, _P]),
    }.items()}


LIBPW85_INDEX = _prototypes("pw85_index_")
LIBPW85_INDEX["pw85_index_openmp"] = (_INT, [])
#: pw85_pair_energy: int (*)(double mu2, void *data, double out[2]).
_PAIR_ENERGY = ctypes.CFUNCTYPE(_INT, _DOUBLE, _P, ctypes.POINTER(_DOUBLE))
_declare(_lib, LIBPW85_INDEX)

#: True when the all-pairs queries and `Index.overlap_any_many` can run on
#: several threads.
OPENMP = bool(_lib.pw85_index_openmp())
#: "No id": ``exclude=None`` in the queries, and the id `Index.overlap_any`
#: returns when nothing overlaps.
NO_ID = ctypes.c_size_t(-1).value
#: The largest id (PW85_INDEX_MAX_ID, 2³² − 2).
MAX_ID = 0xFFFFFFFE

# The rules of pw85_index.h, for the messages: sides at most 2⁹⁹², an
# ellipsoid narrower than the box, 2·√Q_kk·(1 + 2⁻²⁰) < L_k, and a centre
# within 2²⁹·L_k (periodic) or 2¹⁰²¹ (open).
_SIDE_MARGIN = 1.0 + 2.0**-20
_CENTRE_REACH = 2.0**29
_MAX_SIDE = 2.0**992
_MAX_CENTRE = 2.0**1021
# The queries enumerate every image within reach of a candidate, at most
# 2²⁰ along an axis (PW85_ERANGE beyond: pw85_index_overlap_any()).
_IMAGE_SPAN = 2.0**20



def _posdef_3d(f):
    """The rule of pw85.h, by the library's own factorisation probe."""
    probe = np.empty(6)
    _lib.pw85__cholesky_decomp(f.ctypes.data, probe.ctypes.data)
    return not math.isnan(probe[0])


class _Dimension(typing.NamedTuple):
    """What differs between the index of ellipsoids and that of ellipses:
    the sizes of a centre, a form and a torque, the C prefix, the positions
    of the diagonal in a stored form, the words of the messages."""
    dim: int
    sym: int
    rot: int
    prefix: str
    diagonal: Tuple[int, ...]
    posdef: Callable
    shape: str      # "ellipsoid", "ellipse"
    domain: str     # "box", "rectangle"
    name: str       # the class, for repr

    def fn(self, name):
        return getattr(_lib, self.prefix + name)


_D3 = _Dimension(3, 6, 3, "pw85_index_", (0, 3, 5), _posdef_3d, "ellipsoid",
                 "box", "pypw85.Index")


def _array(name, x, dtype, shape):
    """x as a C-contiguous array of dtype and shape (-1: any length);
    real numbers only for float64 (TypeError)."""
    if dtype is np.float64:
        a = _real_array(name, x)  # masked entries refused there
    else:
        _unmasked(name, x)
        a = np.ascontiguousarray(x, dtype=dtype)
    if a.ndim != len(shape) or any(s != -1 and s != n
                                   for s, n in zip(shape, a.shape)):
        raise ValueError("%s: expected shape %s, got %s"
                         % (name, tuple("n" if s == -1 else s for s in shape),
                            a.shape))
    return a


def _records(name, x, n, size):
    """x as a C-contiguous (n, size) float64 array: one record of shape
    (size,) is repeated over the n items (broadcast), else (n, size)."""
    a = _real_array(name, x)
    if a.shape == (size,):
        a = np.broadcast_to(a, (n, size))
    elif a.shape != (n, size):
        raise ValueError("%s: expected shape (%d,) or (%d, %d), got %s"
                         % (name, size, n, size, a.shape))
    return np.ascontiguousarray(a, dtype=np.float64)


def _ptr(a):
    return a.ctypes.data if a.size else None


def _id(name, value):
    """value as an id (int), or raise: TypeError for anything but an
    integer (a float or a bool included), ValueError out of [0, MAX_ID]."""
    if isinstance(value, (bool, np.bool_)) or \
            not isinstance(value, (int, np.integer)):
        raise TypeError("%s: an id is an integer, got %s %r"
                        % (name, type(value).__name__, value))
    v = int(value)
    if not 0 <= v <= MAX_ID:
        raise ValueError("%s: an id is an integer from 0 to MAX_ID = %d, "
                         "got %d" % (name, MAX_ID, v))
    return v


def _ids(name, values):
    """values (an integer or an array of integers) as (n,) uintp ids."""
    if np.ndim(values) == 0:
        return np.array([_id(name, values)], dtype=np.uintp)
    _unmasked(name, values)
    a = np.asarray(values)
    if a.dtype.kind not in "iu":
        raise TypeError("%s: ids are integers, got an array of dtype %s"
                        % (name, a.dtype))
    if a.ndim != 1:
        raise ValueError("%s: expected shape (n,), got %s" % (name, a.shape))
    if a.size and (a.min() < 0 or a.max() > MAX_ID):
        k = int(np.flatnonzero((a < 0) | (a > MAX_ID))[0])
        raise ValueError("%s: an id is an integer from 0 to MAX_ID = %d, "
                         "got %d (item %d)" % (name, MAX_ID, int(a[k]), k))
    return a.astype(np.uintp)


def _check(status, where):
    if status != 0:
        raise Error(status, where)


def _fmt(x):
    return "%.17g" % x


class _Index:
    """The index of either dimension; `Index` (3D) and `pypw85.d2.Index`
    (2D) set `_dim`, the calls and sizes of their C header. The docstrings
    of its methods are written once, with {shape}, {shapes}, {domain},
    {D}, {S} and {torques} for the words and sizes of each dimension: each
    subclass gets its own copy of every method, its docstring filled in
    (`__init_subclass__`)."""

    _dim = _D3

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        d = cls._dim
        words = {"{shape}": d.shape, "{shapes}": d.shape + "s",
                 "{domain}": d.domain, "{D}": str(d.dim), "{S}": str(d.sym),
                 "{torques}": "``(n, 3)``" if d.rot == 3 else "``(n,)``"}
        for name, f in vars(_Index).items():
            if not isinstance(f, types.FunctionType) or f.__doc__ is None \
                    or "{" not in f.__doc__ or name in vars(cls):
                continue
            g = types.FunctionType(f.__code__, f.__globals__, f.__name__,
                                   f.__defaults__, f.__closure__)
            g.__kwdefaults__ = f.__kwdefaults__
            g.__annotations__ = dict(f.__annotations__)
            g.__qualname__ = cls.__qualname__ + "." + name
            g.__module__ = cls.__module__
            doc = f.__doc__
            for key, word in words.items():
                doc = doc.replace(key, word)
            g.__doc__ = doc
            setattr(cls, name, g)

    def __init__(self, box: Optional[ArrayLike] = None) -> None:
        d = self._dim
        self._handle = None
        self._stored = set()
        # Set while energy() calls u: the library then reads the index, so
        # u must not modify nor free it (valgrind: u closing it made the
        # library read freed memory).
        self._in_energy = False
        b = None if box is None else _array("box", box, np.float64, (d.dim,))
        handle = _P()
        code = d.fn("create")(None if b is None else _ptr(b),
                              ctypes.byref(handle))
        if code != 0:
            k = int(np.flatnonzero(~(np.isfinite(b) & (b > 0)
                                     & (b <= _MAX_SIDE)))[0])
            rule = ("is not finite" if not math.isfinite(b[k])
                    else "is not > 0" if not b[k] > 0
                    else "is above 2⁹⁹² = %s" % _fmt(_MAX_SIDE))
            raise Error(code, "Index", "%s side L_%d = %s %s"
                        % (d.domain, k, _fmt(b[k]), rule))
        self._handle = handle
        #: The sides of the periodic box (a copy), or None.
        self.box = None if b is None else b.copy()

    def close(self) -> None:
        """Free the library's memory; the index is unusable afterwards."""
        self._modifiable("close")
        if self._handle is not None:
            self._dim.fn("destroy")(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    def __enter__(self) -> "_Index":
        return self

    def __exit__(self, *exc) -> None:
        self.close()

    def _h(self):
        if self._handle is None:
            raise ValueError("the index is closed")
        return self._handle

    def _modifiable(self, where):
        """Raise RuntimeError inside energy()'s u, which must not modify
        or close the index that the library is reading."""
        if getattr(self, "_in_energy", False):
            raise RuntimeError("%s: the index is in use by energy(), whose "
                               "function u may query it but not modify or "
                               "close it" % where)

    def __len__(self) -> int:
        n = _SIZE()
        _check(self._dim.fn("count")(self._h(), ctypes.byref(n)), "len")
        return n.value

    def __contains__(self, id: object) -> bool:
        """True if ``id`` (an integer) is stored; False for anything else."""
        self._h()
        if isinstance(id, (bool, np.bool_)) or \
                not isinstance(id, (int, np.integer)):
            return False
        return int(id) in self._stored

    def __iter__(self) -> Iterator[int]:
        """The stored ids, ascending (a snapshot: the index may change
        while the iterator runs)."""
        self._h()
        return iter(sorted(self._stored))

    def __repr__(self) -> str:
        if self._handle is None:
            return "<%s (closed)>" % self._dim.name
        d = self._dim
        domain = ("open domain" if self.box is None else
                  "periodic %s %s" % (d.domain, ", ".join(
                      _fmt(x) for x in self.box).join("()")))
        n = len(self)
        return "<%s: %s, %d %s%s>" % (d.name, domain, n, d.shape,
                                      "" if n == 1 else "s")

    # -- the causes of EINVAL and friends (pw85_index.h), for messages --

    def _placement(self, c, f):
        """The rule of the domain that (c, f) breaks, or None."""
        if self.box is None:
            for k, x in enumerate(c):
                if not abs(x) <= _MAX_CENTRE:
                    return ("|c_%d| = %s > 2¹⁰²¹ = %s (a centre must lie "
                            "within 2¹⁰²¹ of the origin)"
                            % (k, _fmt(abs(x)), _fmt(_MAX_CENTRE)))
            return None
        d = self._dim
        for k, (q, side) in enumerate(zip(f[list(d.diagonal)], self.box)):
            width = 2.0 * math.sqrt(q) * _SIDE_MARGIN if q > 0 else 0.0
            if not width < side:
                return ("2·√Q_%d%d·(1 + 2⁻²⁰) = %s ≥ L_%d = %s (an %s "
                        "must be narrower than the %s)"
                        % (k, k, _fmt(width), k, _fmt(side), d.shape,
                           d.domain))
        for k, (x, side) in enumerate(zip(c, self.box)):
            if not abs(x) <= _CENTRE_REACH * side:
                return ("|c_%d| = %s > 2²⁹·L_%d = %s (a centre must lie "
                        "within 2²⁹ box sides of the origin)"
                        % (k, _fmt(abs(x)), k, _fmt(_CENTRE_REACH * side)))
        return None

    def _cause(self, c, f, id=None, new=False, seen=(), code=None):
        """What makes (id, c, f) fail (the checks of pw85_index_insert()),
        or None; of several, one with status code if given."""
        causes = []
        for name, x in (("centre", c), ("q", f)):
            if not np.isfinite(x).all():
                causes.append((EDOM, "%s = %r is not finite"
                               % (name, x.tolist())))
        if id is not None:
            if new and (id in self._stored or id in seen):
                causes.append((EINVAL, "id %d is already %s" % (
                    id, "stored" if id in self._stored else
                    "used by an earlier item of this call")))
            if not new and id not in self._stored:
                causes.append((EINVAL, "id %d is not stored" % id))
        if not causes:
            if not self._dim.posdef(f):
                causes.append((ENOTPOSDEF, "q = %r is not positive definite"
                               % f.tolist()))
            rule = self._placement(c, f)
            if rule is not None:
                causes.append((EINVAL, rule))
        for status, text in causes:
            if status == code:
                return text
        return causes[0][1] if causes else None

    def _raise(self, code, where, c, f, id=None, new=False, seen=(),
               item=None, n=None):
        """Raise Error(code) naming the cause, the id and the item."""
        detail = self._cause(c, f, id, new, seen, code) or \
            "centre = %r, q = %r" % (c.tolist(), f.tolist())
        if id is not None:
            who = "%s %d" % (self._dim.shape, id)
            if item is not None:
                who += " (item %d of %d)" % (item, n)
            detail = who + ": " + detail
        error = Error(code, where, detail)
        error.id = id
        error.item = item
        raise error

    def insert(self, ids: Union[IdLike, ArrayLike], centres: ArrayLike,
               q: ArrayLike) -> None:
        """Insert {shapes}, all or none.

        ``ids`` of shape ``(n,)`` (or one int), ``centres`` ``(n, {D})`` (or
        one ``({D},)`` centre for all), ``q`` ``(n, {S})`` (or one ``({S},)``
        form for all). Raises `TypeError` for ids that are not integers,
        `ValueError` for a negative one or a bad shape, `Error` for an
        input the library rejects (`EINVAL`: an id in use, or repeated, a
        centre beyond 2¹⁰²¹ in an open domain, or in a periodic {domain} an
        {shape} not narrower than the {domain} or a centre beyond 2²⁹
        sides; `ENOTPOSDEF`; `EDOM`), naming the first
        failing item, its id and the rule; the index is then unchanged.
        """
        self._modifiable("insert")
        one = np.ndim(ids) == 0
        i = _ids("ids", ids)
        d = self._dim
        c = _records("centres", centres, i.size, d.dim)
        f = _records("q", q, i.size, d.sym)
        code = self._dim.fn("insert_many")(self._h(), i.size, _ptr(i),
                                           _ptr(c), _ptr(f))
        if code != 0:
            # The index is unchanged: find the first item that fails
            # (pw85_index_insert_many reports the first error met, in
            # order), and say why.
            seen = set()
            for k in range(i.size):
                ident = int(i[k])
                if self._cause(c[k], f[k], ident, True, seen):
                    self._raise(code, "insert", c[k], f[k], ident, True,
                                seen, None if one else k, i.size)
                seen.add(ident)
            raise Error(code, "insert")
        self._stored.update(i.tolist())

    def update(self, id: IdLike, centre: ArrayLike, q: ArrayLike) -> None:
        """Move or reshape the stored {shape} ``id``.

        Raises `Error` as `insert` (`EINVAL` also for an id not stored),
        naming the rule; the index is then unchanged.
        """
        self._modifiable("update")
        ident = _id("id", id)
        c, f = self._one(centre, q)
        code = self._dim.fn("update")(self._h(), ident, _ptr(c), _ptr(f))
        if code != 0:
            self._raise(code, "update", c, f, ident)

    def remove(self, id: IdLike) -> None:
        """Remove the stored {shape} ``id`` (`Error` `EINVAL` if it is
        not stored)."""
        self._modifiable("remove")
        ident = _id("id", id)
        code = self._dim.fn("remove")(self._h(), ident)
        if code != 0:
            raise Error(code, "remove", "id %d is not stored" % ident)
        self._stored.discard(ident)

    def _one(self, centre, q):
        """One centre and one form, as arrays of their sizes."""
        return (_array("centre", centre, np.float64, (self._dim.dim,)),
                _array("q", q, np.float64, (self._dim.sym,)))

    def get(self, id: IdLike) -> Tuple[NDArray[np.float64],
                                      NDArray[np.float64]]:
        """(centre, q) of the stored {shape} ``id``, as inserted (`Error`
        `EINVAL` if it is not stored)."""
        ident = _id("id", id)
        c = np.empty(self._dim.dim)
        f = np.empty(self._dim.sym)
        code = self._dim.fn("get")(self._h(), ident, _ptr(c), _ptr(f))
        if code != 0:
            raise Error(code, "get", "id %d is not stored" % ident)
        return c, f

    def _reach_rule(self, f):
        """The candidate's reach across the box's images, where it is so
        wide that the queries' enumeration of images refuses it
        (PW85_ERANGE), or None."""
        if self.box is None:
            return None
        d = self._dim
        for k, (q, side) in enumerate(zip(f[list(d.diagonal)], self.box)):
            half = math.sqrt(q) if q > 0 else 0.0
            if half > _IMAGE_SPAN / 2 * (1.0 - 2.0**-4) * side:
                return ("√Q_%d%d = %s against L_%d = %s: the candidate "
                        "reaches across about 2·√Q_%d%d/L_%d images of the "
                        "%s, and the queries, which enumerate every image, "
                        "refuse more than 2²⁰ along an axis"
                        % (k, k, _fmt(half), k, _fmt(side), k, k, k,
                           d.domain))
        return None

    def _candidate_error(self, code, where, c, f, item=None, n=None):
        reach = self._reach_rule(f) if code == ERANGE else None
        if code == EDOM or code == ENOTPOSDEF:
            detail = self._cause(c, f, code=code)
        elif reach is not None:
            detail = reach
        else:
            rule = self._placement(c, np.ones(self._dim.sym))  # centre rule
            detail = rule if code == EINVAL and rule else (
                "centre = %r, q = %r" % (c.tolist(), f.tolist()))
        if item is not None:
            detail = "candidate %d of %d: %s" % (item, n, detail)
        error = Error(code, where, detail)
        error.item = item
        return error

    def overlap_any(self, centre: ArrayLike, q: ArrayLike,
                    exclude: Optional[IdLike] = None
                    ) -> Tuple[int, Optional[int]]:
        """Does a candidate overlap a stored {shape} (skipping ``exclude``)?

        Returns ``(result, id)``: result -1 (some overlap; stops at the
        first), 0 (none overlaps, some is tangent to 4 ulps) or +1, and the
        id of an {shape} with that result (None for +1). The result is
        an int, not a bool: test ``result < 0`` for "overlaps".
        """
        c, f = self._one(centre, q)
        result = _INT()
        found = _SIZE()
        code = self._dim.fn("overlap_any")(
            self._h(), _ptr(c), _ptr(f),
            NO_ID if exclude is None else _id("exclude", exclude),
            ctypes.byref(result), ctypes.byref(found))
        if code != 0:
            raise self._candidate_error(code, "overlap_any", c, f)
        return result.value, (None if found.value == NO_ID else found.value)

    def overlap_any_many(self, centres: ArrayLike, q: ArrayLike,
                         exclude: Optional[ArrayLike] = None,
                         threads: int = 1
                         ) -> Tuple[NDArray[np.intc], NDArray[np.int64]]:
        """`overlap_any` for n candidates in one call, each decided against
        the stored {shapes} only (not against each other).

        ``centres`` ``(n, {D})``, ``q`` ``(n, {S})`` (or one ``({S},)`` form
        for all); ``exclude`` None, or ``(n,)`` ids, -1 for none. ``threads``:
        1, 0 (OpenMP's default) or up to that many (none started below 512
        candidates); the results do not depend on it.

        Returns ``(results, ids)``: ``(n,)`` ints (-1, 0, +1, as
        `overlap_any`) and ``(n,)`` int64 ids (-1 where the result is +1).
        Raises `Error` for the first failing candidate (its ``index`` and
        the ``statuses`` of all), ValueError for a bad shape or id.

        Random sequential addition can draw candidates in batches, decide
        them here, then keep them in order, calling `overlap_any` again
        for a free candidate that follows an insertion in the same batch:
        the serial loop's result (tutorial/rsa.py).
        """
        threads = _threads_count(threads)
        d = self._dim
        c = _array("centres", centres, np.float64, (-1, d.dim))
        n = c.shape[0]
        f = _records("q", q, n, d.sym)
        ex = None
        if exclude is not None:
            _unmasked("exclude", exclude)
            e = np.asarray(exclude)
            if not np.issubdtype(e.dtype, np.integer):
                raise TypeError("exclude: expected integer ids, got dtype %s"
                                % e.dtype)
            if e.shape != (n,):
                raise ValueError("exclude: expected shape (%d,), got %s"
                                 % (n, e.shape))
            if (e < -1).any():
                raise ValueError("exclude: ids are non-negative integers "
                                 "(-1 for none)")
            # As overlap_any's exclude (the library would take an id above
            # MAX_ID for one not stored, and skip nothing).
            above = np.flatnonzero(e > MAX_ID)
            if above.size:
                raise ValueError("exclude: an id is an integer from 0 to "
                                 "MAX_ID = %d, or -1 for none; candidate %d "
                                 "has %d" % (MAX_ID, above[0],
                                             int(e[above[0]])))
            ex = e.astype(np.int64).astype(np.uintp)
            ex[e == -1] = NO_ID
        results = np.empty(n, dtype=np.intc)
        found = np.empty(n, dtype=np.uintp)
        args = (self._h(), n, _ptr(c), d.dim, _ptr(f), d.sym,
                None if ex is None else _ptr(ex), _ptr(results), _ptr(found))
        code = self._dim.fn("overlap_any_batch")(*args, None, threads)
        if code != 0:
            status = np.empty(n, dtype=np.intc)
            code = self._dim.fn("overlap_any_batch")(*args, _ptr(status),
                                                     threads)
            i = int(np.flatnonzero(status)[0])
            error = self._candidate_error(code, "overlap_any_many", c[i],
                                          f[i], i, n)
            error.detail += " (%d of %d failed)" % (
                np.count_nonzero(status), n)
            error.index = i
            error.statuses = status
            raise error
        # NO_ID (2⁶⁴ − 1) becomes -1.
        return results, found.astype(np.int64)

    def within(self, centre: ArrayLike, q: ArrayLike, t: float = 1.0,
               exclude: Optional[IdLike] = None
               ) -> Tuple[NDArray[np.int64], NDArray[np.intc],
                          NDArray[np.float64]]:
        """Every stored {shape} and image with μ² < t from a candidate.

        Returns ``(ids, shifts, mu2_lambda)`` of shapes ``(m,)``,
        ``(m, {D})``, ``(m, 2)``, sorted by id then shift; the image of
        {shape} j is at ``c_j + shift * box``.
        """
        c, f = self._one(centre, q)
        ex = NO_ID if exclude is None else _id("exclude", exclude)
        t = _real("t", t)
        if not t > 0:
            raise Error(EDOM if math.isnan(t) else EINVAL, "within",
                        "t = %s is not > 0" % _fmt(t))

        def call(cap, ids, shifts, ml, count):
            return self._dim.fn("within")(self._h(), _ptr(c), _ptr(f),
                                          t, ex, cap, ids, shifts, ml,
                                          count)
        return self._collect(call, 1, np.float64, "within", 16,
                             lambda code: self._candidate_error(
                                 code, "within", c, f))

    def overlapping_pairs(self, threads: int = 1
                          ) -> Tuple[NDArray[np.int64], NDArray[np.intc],
                                     NDArray[np.intc]]:
        """Every overlapping (or tangent) pair, each once.

        ``threads`` ≥ 1. Returns ``(ids, shifts, results)`` of shapes
        ``(m, 2)``, ``(m, {D})``, ``(m,)``: pairs (i, j), i < j, the image
        shift of j, and -1 (overlap) or 0 (tangent to 4 ulps); sorted by
        i, j, shift.
        """
        threads = _pair_threads("overlapping_pairs", threads)

        def call(cap, ids, shifts, res, count):
            return self._dim.fn("overlapping_pairs")(
                self._h(), threads, cap, ids, shifts, res, count)
        return self._collect(call, 2, np.intc, "overlapping_pairs",
                             4 * len(self) + 16)

    def pairs_within(self, t: float, threads: int = 1
                     ) -> Tuple[NDArray[np.int64], NDArray[np.intc],
                                NDArray[np.float64]]:
        """Every pair (and image) with μ² < t, each once.

        ``threads`` ≥ 1. Returns ``(ids, shifts, mu2_lambda)`` of shapes
        ``(m, 2)``, ``(m, {D})``, ``(m, 2)``, sorted by i, j, shift.
        """
        threads = _pair_threads("pairs_within", threads)
        t = _real("t", t)
        if not t > 0:
            raise Error(EDOM if math.isnan(t) else EINVAL, "pairs_within",
                        "t = %s is not > 0" % _fmt(t))

        def call(cap, ids, shifts, ml, count):
            return self._dim.fn("pairs_within")(
                self._h(), t, threads, cap, ids, shifts, ml, count)
        return self._collect(call, 2, np.float64, "pairs_within",
                             8 * len(self) + 16)

    def energy(self, eps: float = 1.0, *,
               u: Optional[Callable[[float], Tuple[float, float]]] = None,
               t: Optional[float] = None,
               threads: int = 1, n: Optional[int] = None
               ) -> Tuple[float, NDArray[np.float64], NDArray[np.float64]]:
        """The energy summed over every pair (and image), the force and the
        torque on every {shape} (``pw85_index_energy``,
        ``pw85_2d_index_energy``).

        By default the overlap energy ``eps·(1 − μ)²`` of the pairs with
        μ < 1 (its minimisation removes overlaps). With ``u``, a function
        ``u(mu2) -> (U, dU/dmu2)`` of the pairs with μ² < ``t``: it is
        called from Python once per pair, in the order of the pairs (about
        a microsecond each: slow for many pairs, where the overlap energy
        is not); an exception it raises stops the call and is raised again.
        ``u`` may query the index, not modify or close it (`RuntimeError`).

        ``n``: the rows of the outputs (default: the largest stored id
        plus one). Returns ``(energy, forces, torques)``, forces of shape
        ``(n, {D})`` and torques {torques}, row k for the {shape} of id k
        (zeros for ids in no pair or not stored). Forces are −∂U/∂c,
        torques −∂U/∂ω about each centre (in 2D ω is the angle θ, and a
        torque one number); both sum to zero over the assembly, the
        torques with the moments of the forces about the images' centres.
        The same arrays, bit for bit, for any ``threads`` (≥ 1).
        """
        threads = _pair_threads("energy", threads)
        if n is None:
            n = max(self._stored) + 1 if self._stored else 0
        if isinstance(n, (bool, np.bool_)) or \
                not isinstance(n, (int, np.integer)) or n < 0:
            raise TypeError("energy: n must be a non-negative int, got %r"
                            % (n,))
        n = int(n)
        if self._stored and n <= max(self._stored):
            raise Error(EINVAL, "energy", "n = %d is not above the largest "
                        "stored id, %d" % (n, max(self._stored)))
        d = self._dim
        forces = np.zeros((n, d.dim), dtype=np.float64)
        torques = np.zeros((n, d.rot) if d.rot > 1 else (n,),
                           dtype=np.float64)
        e = _DOUBLE()
        raised = []
        if u is None:
            if t is not None:
                raise TypeError("energy: t is the threshold of a function "
                                "u; the overlap energy takes eps only")
            eps = _real("eps", eps)
            if not eps > 0 or math.isinf(eps):
                raise Error(EDOM if not math.isfinite(eps) else EINVAL,
                            "energy", "eps = %s is not finite and > 0"
                            % _fmt(eps))
            code = d.fn("energy")(self._h(), 0, eps, None, None, threads, n,
                                  ctypes.byref(e), _ptr(forces),
                                  _ptr(torques))
        else:
            if not callable(u):
                raise TypeError("energy: u must be callable, got %s"
                                % type(u).__name__)
            if t is None:
                raise TypeError("energy: u needs its threshold t on mu2")
            t = _real("t", t)
            if not t > 0 or math.isinf(t):
                raise Error(EDOM if not math.isfinite(t) else EINVAL,
                            "energy", "t = %s is not finite and > 0"
                            % _fmt(t))

            def call(mu2, data, out):
                try:
                    value, slope = u(mu2)
                    out[0] = float(value)
                    out[1] = float(slope)
                    return 0
                except BaseException as exc:  # raised again below
                    raised.append(exc)
                    return 1
            fn = _PAIR_ENERGY(call)
            handle = self._h()
            self._in_energy = True
            try:
                code = d.fn("energy")(handle, 1, t, fn, None, threads, n,
                                      ctypes.byref(e), _ptr(forces),
                                      _ptr(torques))
            finally:
                self._in_energy = False
        if raised:
            raise raised[0]
        if code == EDOM and u is not None:
            raise Error(code, "energy", "u returned a value that is not "
                        "finite")
        _check(code, "energy")
        return e.value, forces, torques

    def _collect(self, call, ids_per_row, value_dtype, where, guess,
                 error=None):
        """Call with room for `guess` results, then again if too few."""
        count = _SIZE()
        cap = guess
        while True:
            ids = np.empty((cap, ids_per_row), dtype=np.uintp)
            shifts = np.empty((cap, self._dim.dim), dtype=np.intc)
            values = (np.empty(cap, dtype=np.intc) if value_dtype is np.intc
                      else np.empty((cap, 2), dtype=np.float64))
            code = call(cap, _ptr(ids), _ptr(shifts), _ptr(values),
                        ctypes.byref(count))
            if code != 0:
                raise error(code) if error else Error(code, where)
            if count.value <= cap:
                break
            cap = count.value
        m = count.value
        ids = ids[:m, 0] if ids_per_row == 1 else ids[:m]
        return ids.astype(np.int64), shifts[:m].copy(), values[:m].copy()


class Index(_Index):
    """A spatial index of ellipsoids (``pw85_index``).

    Parameters
    ----------
    box : array_like of 3 floats, optional
        The sides of a periodic orthorhombic box (each > 0 and at most
        2⁹⁹²); None (default) for an open domain.

    An `Index` holds library memory: it is freed by `close` (or by the
    ``with`` statement, or when the object is collected). Modifying calls
    must not run concurrently with other calls on the same index; queries
    may.

    It is a container of the ids it stores: ``len(index)``,
    ``id in index``, ``iter(index)`` (the ids, ascending); ``repr`` shows
    the box and the count.

    Returns
    -------
    Index
        An empty index.

    Raises
    ------
    Error
        `EDOM` if a side is not finite, `EINVAL` if one is not > 0 or is
        above 2⁹⁹² (the message names the side).
    """


def _pair_threads(where, threads):
    """threads of the all-pairs queries: an int ≥ 1 (EINVAL otherwise)."""
    if isinstance(threads, (bool, np.bool_)) or \
            not isinstance(threads, (int, np.integer)):
        raise TypeError("threads: expected an int, got %s"
                        % type(threads).__name__)
    if threads < 1:
        raise Error(EINVAL, where, "threads = %d is not ≥ 1" % threads)
    if threads > 2**31 - 1:
        raise Error(EINVAL, where,
                    "threads = %d is above 2³¹ − 1 (a C int)" % threads)
    return int(threads)
