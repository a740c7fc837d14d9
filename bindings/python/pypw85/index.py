# SPDX-License-Identifier: BSD-3-Clause
"""A spatial index of ellipsoids in an open domain or a periodic box.

`Index` wraps ``pw85_index.h``: ellipsoids stored by id (small
non-negative integers, such as their positions in the caller's arrays),
centre and quadratic form; overlap and near-contact queries whose answers
are those of `pypw85.overlap` and `pypw85.contact_function` on every pair
and every periodic image (the C header documents the contract: the image
rule, the side rule of a periodic box, the order of the results).

Arrays in, arrays out: `Index.insert` takes ``(n,)`` ids, ``(n, 3)``
centres and ``(n, 6)`` forms in one call into the library; the queries
return NumPy arrays. The all-pairs queries and `Index.overlap_any_many`
run on ``threads`` OpenMP threads (`OPENMP` says whether this libpw85 has
them), with the GIL released, and give the same arrays for any number of
threads.
"""

import ctypes

import numpy as np

from ._batch import threads_count as _threads_count
from ._errors import Error
from ._libpw85 import lib as _lib
from ._symbols import declare as _declare

__all__ = ["Index", "OPENMP", "NO_ID"]

_P = ctypes.c_void_p
_SIZE = ctypes.c_size_t
_INT = ctypes.c_int
_DOUBLE = ctypes.c_double
_SIZE_P = ctypes.POINTER(_SIZE)
_INT_P = ctypes.POINTER(_INT)

#: The prototypes of pw85_index.h (the handle is a ``void *``).
LIBPW85_INDEX = {
    "pw85_index_create": (_INT, [_P, ctypes.POINTER(_P)]),
    "pw85_index_destroy": (None, [_P]),
    "pw85_index_openmp": (_INT, []),
    "pw85_index_count": (_INT, [_P, _SIZE_P]),
    "pw85_index_insert": (_INT, [_P, _SIZE, _P, _P]),
    "pw85_index_insert_many": (_INT, [_P, _SIZE, _P, _P, _P]),
    "pw85_index_update": (_INT, [_P, _SIZE, _P, _P]),
    "pw85_index_remove": (_INT, [_P, _SIZE]),
    "pw85_index_get": (_INT, [_P, _SIZE, _P, _P]),
    "pw85_index_overlap_any": (_INT, [_P, _P, _P, _SIZE, _INT_P, _SIZE_P]),
    "pw85_index_overlap_any_batch": (_INT, [_P, _SIZE, _P, _SIZE, _P, _SIZE,
                                            _P, _P, _P, _P, _INT]),
    "pw85_index_within": (_INT, [_P, _P, _P, _DOUBLE, _SIZE, _SIZE, _P, _P,
                                 _P, _SIZE_P]),
    "pw85_index_overlapping_pairs": (_INT, [_P, _INT, _SIZE, _P, _P, _P,
                                            _SIZE_P]),
    "pw85_index_pairs_within": (_INT, [_P, _DOUBLE, _INT, _SIZE, _P, _P, _P,
                                       _SIZE_P]),
}
_declare(_lib, LIBPW85_INDEX)

#: True when the all-pairs queries and `Index.overlap_any_many` can run on
#: several threads.
OPENMP = bool(_lib.pw85_index_openmp())
#: "No id": ``exclude=None`` in the queries, and the id `Index.overlap_any`
#: returns when nothing overlaps.
NO_ID = ctypes.c_size_t(-1).value


def _array(name, x, dtype, shape):
    """x as a C-contiguous array of dtype and shape (-1: any length)."""
    a = np.ascontiguousarray(x, dtype=dtype)
    if a.ndim != len(shape) or any(s != -1 and s != n
                                   for s, n in zip(shape, a.shape)):
        raise ValueError("%s: expected shape %s, got %s"
                         % (name, tuple("n" if s == -1 else s for s in shape),
                            a.shape))
    return a


def _ptr(a):
    return a.ctypes.data if a.size else None


def _check(status, where):
    if status != 0:
        raise Error(status, where)


def _id(name, value):
    v = int(value)
    if v < 0:
        raise ValueError("%s: an id is a non-negative integer, got %d"
                         % (name, v))
    return v


class Index:
    """A spatial index of ellipsoids (``pw85_index``).

    Parameters
    ----------
    box : array_like of 3 floats, optional
        The sides of a periodic orthorhombic box; None (default) for an
        open domain.

    An `Index` holds library memory: it is freed by `close` (or by the
    ``with`` statement, or when the object is collected). Modifying calls
    must not run concurrently with other calls on the same index; queries
    may.
    """

    def __init__(self, box=None):
        self._handle = None
        b = None if box is None else _array("box", box, np.float64, (3,))
        handle = _P()
        _check(_lib.pw85_index_create(None if b is None else _ptr(b),
                                      ctypes.byref(handle)), "Index")
        self._handle = handle
        self.box = None if b is None else b.copy()

    def close(self):
        """Free the library's memory; the index is unusable afterwards."""
        if self._handle is not None:
            _lib.pw85_index_destroy(self._handle)
            self._handle = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _h(self):
        if self._handle is None:
            raise ValueError("the index is closed")
        return self._handle

    def __len__(self):
        n = _SIZE()
        _check(_lib.pw85_index_count(self._h(), ctypes.byref(n)), "len")
        return n.value

    def insert(self, ids, centres, q):
        """Insert ellipsoids, all or none.

        ``ids`` of shape ``(n,)`` (or one int), ``centres`` ``(n, 3)`` (or
        ``(3,)``), ``q`` ``(n, 6)`` (or ``(6,)``). Raises `Error` (status
        `EINVAL` for an id in use, `ENOTPOSDEF`, `EDOM`, ...), the index
        then unchanged.
        """
        one = np.ndim(ids) == 0
        if (np.asarray(ids) < 0).any():
            raise ValueError("ids: non-negative integers expected")
        i = _array("ids", [ids] if one else ids, np.uintp, (-1,))
        c = _array("centres", [centres] if one else centres, np.float64,
                   (i.size, 3))
        f = _array("q", [q] if one else q, np.float64, (i.size, 6))
        _check(_lib.pw85_index_insert_many(self._h(), i.size, _ptr(i),
                                           _ptr(c), _ptr(f)), "insert")

    def update(self, id, centre, q):
        """Move or reshape the stored ellipsoid ``id``."""
        c = _array("centre", centre, np.float64, (3,))
        f = _array("q", q, np.float64, (6,))
        _check(_lib.pw85_index_update(self._h(), _id("id", id), _ptr(c),
                                      _ptr(f)), "update")

    def remove(self, id):
        """Remove the stored ellipsoid ``id``."""
        _check(_lib.pw85_index_remove(self._h(), _id("id", id)), "remove")

    def get(self, id):
        """(centre, q) of the stored ellipsoid ``id``, as inserted."""
        c = np.empty(3)
        f = np.empty(6)
        _check(_lib.pw85_index_get(self._h(), _id("id", id), _ptr(c),
                                   _ptr(f)), "get")
        return c, f

    def overlap_any(self, centre, q, exclude=None):
        """Does a candidate overlap a stored ellipsoid (skipping ``exclude``)?

        Returns ``(result, id)``: result -1 (some overlap; stops at the
        first), 0 (none overlaps, some is tangent to 4 ulps) or +1, and the
        id of an ellipsoid with that result (None for +1).
        """
        c = _array("centre", centre, np.float64, (3,))
        f = _array("q", q, np.float64, (6,))
        result = _INT()
        found = _SIZE()
        _check(_lib.pw85_index_overlap_any(
            self._h(), _ptr(c), _ptr(f),
            NO_ID if exclude is None else _id("exclude", exclude),
            ctypes.byref(result), ctypes.byref(found)), "overlap_any")
        return result.value, (None if found.value == NO_ID else found.value)

    def overlap_any_many(self, centres, q, exclude=None, threads=1):
        """`overlap_any` for n candidates in one call, each decided against
        the stored ellipsoids only (not against each other).

        ``centres`` ``(n, 3)``, ``q`` ``(n, 6)``; ``exclude`` None, or
        ``(n,)`` ids, -1 for none. ``threads``: 1, 0 (OpenMP's default) or
        up to that many (none started below 512 candidates); the results
        do not depend on it.

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
        c = _array("centres", centres, np.float64, (-1, 3))
        n = c.shape[0]
        f = _array("q", q, np.float64, (n, 6))
        ex = None
        if exclude is not None:
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
            ex = e.astype(np.int64).astype(np.uintp)
            ex[e == -1] = NO_ID
        results = np.empty(n, dtype=np.intc)
        found = np.empty(n, dtype=np.uintp)
        args = (self._h(), n, _ptr(c), 3, _ptr(f), 6,
                None if ex is None else _ptr(ex), _ptr(results), _ptr(found))
        code = _lib.pw85_index_overlap_any_batch(*args, None, threads)
        if code != 0:
            status = np.empty(n, dtype=np.intc)
            code = _lib.pw85_index_overlap_any_batch(*args, _ptr(status),
                                                     threads)
            i = int(np.flatnonzero(status)[0])
            error = Error(code, "overlap_any_many",
                          "candidate %d of %d (%d failed): centre = %r, "
                          "q = %r" % (i, n, np.count_nonzero(status),
                                      c[i].tolist(), f[i].tolist()))
            error.index = i
            error.statuses = status
            raise error
        # NO_ID (2⁶⁴ − 1) becomes -1.
        return results, found.astype(np.int64)

    def within(self, centre, q, t=1.0, exclude=None):
        """Every stored ellipsoid and image with μ² < t from a candidate.

        Returns ``(ids, shifts, mu2_lambda)`` of shapes ``(m,)``,
        ``(m, 3)``, ``(m, 2)``, sorted by id then shift; the image of
        ellipsoid j is at ``c_j + shift * box``.
        """
        c = _array("centre", centre, np.float64, (3,))
        f = _array("q", q, np.float64, (6,))
        ex = NO_ID if exclude is None else _id("exclude", exclude)

        def call(cap, ids, shifts, ml, count):
            return _lib.pw85_index_within(self._h(), _ptr(c), _ptr(f),
                                          float(t), ex, cap, ids, shifts, ml,
                                          count)
        return self._collect(call, 1, np.float64, "within", 16)

    def overlapping_pairs(self, threads=1):
        """Every overlapping (or tangent) pair, each once.

        Returns ``(ids, shifts, results)`` of shapes ``(m, 2)``,
        ``(m, 3)``, ``(m,)``: pairs (i, j), i < j, the image shift of j,
        and -1 (overlap) or 0 (tangent to 4 ulps); sorted by i, j, shift.
        """
        def call(cap, ids, shifts, res, count):
            return _lib.pw85_index_overlapping_pairs(
                self._h(), int(threads), cap, ids, shifts, res, count)
        return self._collect(call, 2, np.intc, "overlapping_pairs",
                             4 * len(self) + 16)

    def pairs_within(self, t, threads=1):
        """Every pair (and image) with μ² < t, each once.

        Returns ``(ids, shifts, mu2_lambda)`` of shapes ``(m, 2)``,
        ``(m, 3)``, ``(m, 2)``, sorted by i, j, shift.
        """
        def call(cap, ids, shifts, ml, count):
            return _lib.pw85_index_pairs_within(
                self._h(), float(t), int(threads), cap, ids, shifts, ml,
                count)
        return self._collect(call, 2, np.float64, "pairs_within",
                             8 * len(self) + 16)

    @staticmethod
    def _collect(call, ids_per_row, value_dtype, where, guess):
        """Call with room for `guess` results, then again if too few."""
        count = _SIZE()
        cap = guess
        while True:
            ids = np.empty((cap, ids_per_row), dtype=np.uintp)
            shifts = np.empty((cap, 3), dtype=np.intc)
            values = (np.empty(cap, dtype=np.intc) if value_dtype is np.intc
                      else np.empty((cap, 2), dtype=np.float64))
            _check(call(cap, _ptr(ids), _ptr(shifts), _ptr(values),
                        ctypes.byref(count)), where)
            if count.value <= cap:
                break
            cap = count.value
        m = count.value
        ids = ids[:m, 0] if ids_per_row == 1 else ids[:m]
        return ids.astype(np.int64), shifts[:m].copy(), values[:m].copy()
