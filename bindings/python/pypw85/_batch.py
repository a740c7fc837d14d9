# SPDX-License-Identifier: BSD-3-Clause
"""Arrays of pairs: one call of a batch function of pw85.h per call.

`contact_function`, `overlap`, `contact_geometry` and `contact_derivatives`
of pypw85 come here when an input has more than one dimension; `spheroid`,
`ellipsoid_rotation`, `ellipsoid_quaternion` and `principal_axes` when an
input has more axes than one item's (a, c: 0; n, a: 1; rot: 2). The leading
axes of r12 (..., 3), q1 (..., 6) and q2 (..., 6) (or of each input before
its item's axes) broadcast as NumPy's do; the outputs have the broadcast
shape followed by the shape of one result. An input whose leading axes
hold one item, or that is a broadcast view (stride 0 on every leading
axis, as ``np.broadcast_to`` makes), is passed once, with a stride of 0
(no copy); one of the broadcast shape is passed as is when C-contiguous
float64; any other is copied to the broadcast shape. Then one C call does
every pair, with the GIL released (ctypes releases it around a call); the
statuses are asked for only when that call reports a failure.
"""

from __future__ import annotations

import ctypes
import typing

import numpy as np

if typing.TYPE_CHECKING:  # annotations only: nothing imported at run time
    from typing import Optional

from ._constants import (DERIV_SIZE, DIM, EDOM, EINVAL, GEOM_SIZE, SUCCESS,
                         SYM, UNIT_TOL)
from ._convert import reals as _reals
from ._errors import Error
from ._libpw85 import lib

_SEQUENCES = (list, tuple)


def is_batch(*inputs):
    """True if an input has more than one dimension (an array of pairs).

    Decided without converting lists: a list or tuple whose first item is
    itself a sequence or an array."""
    for x in inputs:
        if isinstance(x, np.ndarray):
            if x.ndim > 1:
                return True
        elif isinstance(x, _SEQUENCES) and len(x) > 0 and \
                isinstance(x[0], _SEQUENCES + (np.ndarray,)):
            return True
    return False


def threads_count(threads):
    """threads as an int ≥ 0, or raise."""
    if isinstance(threads, (bool, np.bool_)) or \
            not isinstance(threads, (int, np.integer)):
        raise TypeError("threads: expected an int, got %s"
                        % type(threads).__name__)
    if threads < 0:
        raise ValueError("threads: expected 0 (OpenMP's default) or a "
                         "positive count, got %d" % threads)
    if threads > 2**31 - 1:
        raise ValueError("threads: expected at most 2³¹ − 1 (a C int), "
                         "got %d" % threads)
    return int(threads)


def _real_array(name, x, item):
    """x as a float64 array of shape (...,) + item, or raise."""
    a = _reals(name, x, "an array of shape (...%s)" % _dims(item))
    if a.ndim < len(item) or a.shape[a.ndim - len(item):] != item:
        raise ValueError("%s: expected shape %s or (...%s), got %s"
                         % (name, item, _dims(item), a.shape))
    return a  # converted to float64 by Items, after a broadcast view's
    # record is taken (converting first would copy every item)


def _dims(item):
    return "".join(", %d" % k for k in item)


class Items:
    """The inputs of a batch: broadcast shape, count, and for each input
    the array handed to C and its stride in doubles.

    inputs: (name, value, item shape) for each input of the C function, in
    its order; `noun` names an item in messages."""

    def __init__(self, where, inputs, noun="pair"):
        self.where = where
        self.noun = noun
        self.names = [name for name, _, _ in inputs]
        arrays = [_real_array(name, x, item) for name, x, item in inputs]
        leading = [a.shape[:a.ndim - len(item)]
                   for a, (_, _, item) in zip(arrays, inputs)]
        try:
            self.shape = np.broadcast_shapes(*leading)
        except ValueError:
            shapes = ["%s %s" % (name, a.shape)
                      for name, a in zip(self.names, arrays)]
            raise ValueError(
                "%s: the leading axes of %s and %s do not broadcast "
                "together" % (where, ", ".join(shapes[:-1]), shapes[-1])) \
                from None
        self.n = int(np.prod(self.shape, dtype=np.int64))
        self.inputs = []  # (array, stride)
        for a, (_, _, item) in zip(arrays, inputs):
            size = int(np.prod(item, dtype=np.int64))
            lead = a.ndim - len(item)
            if a.size > size and all(st == 0 or k == 1 for st, k in
                                     zip(a.strides[:lead], a.shape[:lead])):
                # A broadcast view (np.broadcast_to, stride 0 on every
                # leading axis): its one record, passed with stride 0.
                a = a[(0,) * lead]
            if a.size == size:  # one record for every item
                a = np.ascontiguousarray(a, dtype=np.float64).reshape(size)
                stride = 0
            else:
                if a.shape[:a.ndim - len(item)] != self.shape:
                    a = np.broadcast_to(a, self.shape + item)
                a = np.ascontiguousarray(a, dtype=np.float64).reshape(
                    self.n, size)
                stride = size
            self.inputs.append((a, stride))

    def arguments(self):
        """n, then (address, stride) of each input: the first arguments
        of a batch function."""
        args = [self.n]
        for a, stride in self.inputs:
            args += [a.ctypes.data, stride]
        return args

    def item(self, i):
        """The inputs of item i (flat index), for messages."""
        return [a if stride == 0 else a[i] for a, stride in self.inputs]

    def raise_first(self, code, status, cause=None):
        """Raise Error for the first failing item (status: n ints); cause:
        what is wrong with it, if known."""
        i = int(np.flatnonzero(status)[0])
        index = np.unravel_index(i, self.shape)
        index = tuple(int(k) for k in index)
        values = ", ".join("%s = %r" % (name, value) for name, value
                           in zip(self.names, self.item(i)))
        error = Error(code, self.where,
                      "%s %s of %s (%d of %d failed): %s%s"
                      % (self.noun, index, self.shape,
                         np.count_nonzero(status), self.n,
                         cause + ": " if cause else "", values))
        error.index = index
        error.statuses = status.reshape(self.shape)
        raise error


def pairs_of(where, r12, q1, q2):
    """The inputs of a batch of pairs."""
    return Items(where, [("r12", r12, (DIM,)), ("q1", q1, (SYM,)),
                         ("q2", q2, (SYM,))])


def output(name, out, shape, dtype=np.float64):
    """out, checked to be a C-contiguous writeable array of the exact shape
    and dtype; or a new one."""
    if out is None:
        return np.empty(shape, dtype=dtype)
    expected = "a C-contiguous, writeable numpy.ndarray of dtype %s and " \
               "shape %s" % (np.dtype(dtype).name, shape)
    if not isinstance(out, np.ndarray):
        raise TypeError("%s: expected %s, got %s"
                        % (name, expected, type(out).__name__))
    if out.dtype != dtype:
        raise TypeError("%s: expected %s, got dtype %s"
                        % (name, expected, out.dtype))
    if out.shape != shape:
        raise ValueError("%s: expected %s, got shape %s"
                         % (name, expected, out.shape))
    if not out.flags.c_contiguous or not out.flags.writeable:
        raise ValueError("%s: expected %s, got a non-contiguous or read-only "
                         "array" % (name, expected))
    return out


def _unaliased(pairs, *outputs):
    """Copy the inputs that share memory with an output."""
    pairs.inputs = [
        (np.array(a) if any(np.may_share_memory(a, o) for o in outputs)
         else a, stride) for a, stride in pairs.inputs]


def _call(pairs, c_function, outputs, threads):
    """One call of c_function on every pair; raise for the first failure.

    The per-pair statuses are not asked for (NULL) unless the call fails:
    then a second call, whose outputs and statuses are those the first
    would have given (every pair is computed alone, from its inputs only),
    fills them for the error. A batch that succeeds so writes no status
    array, which at 1e5 overlaps on 2 threads was 5% of the time."""
    threads = threads_count(threads)
    arguments = pairs.arguments() + [o.ctypes.data for o in outputs]
    code = c_function(*arguments, None, threads)
    if code != SUCCESS:
        status = np.empty(pairs.n, dtype=np.intc)
        code = c_function(*arguments, status.ctypes.data, threads)
        pairs.raise_first(code, status)


def contact_function(r12, q1, q2, out, threads):
    pairs = pairs_of("contact_function", r12, q1, q2)
    out = output("out", out, pairs.shape + (2,))
    _unaliased(pairs, out)
    _call(pairs, lib.pw85_contact_function_batch, [out], threads)
    return out


def overlap(r12, q1, q2, threads):
    pairs = pairs_of("overlap", r12, q1, q2)
    result = np.empty(pairs.shape, dtype=np.intc)
    _call(pairs, lib.pw85_overlap_batch, [result], threads)
    return result


def contact_geometry(r12, q1, q2, out, threads):
    pairs = pairs_of("contact_geometry", r12, q1, q2)
    out = output("out", out, pairs.shape + (GEOM_SIZE,))
    _unaliased(pairs, out)
    _call(pairs, lib.pw85_contact_geometry_batch, [out], threads)
    return out


def contact_derivatives(r12, q1, q2, geometry, d, threads):
    pairs = pairs_of("contact_derivatives", r12, q1, q2)
    geometry = output("geometry", geometry, pairs.shape + (GEOM_SIZE,))
    d = output("d", d, pairs.shape + (DERIV_SIZE,))
    if np.may_share_memory(geometry, d):
        raise ValueError("geometry and d: expected separate arrays")
    _unaliased(pairs, geometry, d)
    _call(pairs, lib.pw85_contact_derivatives_batch, [geometry, d], threads)
    return geometry, d


def is_batch_of(*inputs):
    """True if an input (value, item ndim) has more axes than one item.

    An input NumPy cannot convert (ragged lists) is not a batch: the
    single-item path names it in its error."""
    for x, k in inputs:
        try:
            if np.ndim(x) > k:
                return True
        except (TypeError, ValueError):
            pass
    return False


def spheroid(a, c, n, q, threads):
    items = Items("spheroid", [("a", a, ()), ("c", c, ()), ("n", n, (DIM,))],
                  "item")
    q = output("q", q, items.shape + (SYM,))
    _unaliased(items, q)
    bad, first = _spheroid_preconditions(items)
    if bad is None:
        _call(items, lib.pw85_spheroid_batch, [q], threads)
        return q
    # Items that break a rule (which pw85_spheroid_batch does not check):
    # every status, from a call into scratch memory, theirs EINVAL. If one
    # of them fails first, no item is computed; else the batch's outputs,
    # but theirs (q untouched there, as for EDOM).
    threads = threads_count(threads)
    scratch = np.empty_like(q)
    status = np.empty(items.n, dtype=np.intc)
    lib.pw85_spheroid_batch(*items.arguments(), scratch.ctypes.data,
                            status.ctypes.data, threads)
    status[bad] = EINVAL
    i = int(np.flatnonzero(status)[0])
    if status[i] != EINVAL:
        written = (status != EINVAL) & (status != EDOM)
        q.reshape(-1, SYM)[written] = scratch.reshape(-1, SYM)[written]
        items.raise_first(int(status[i]), status)
    items.raise_first(EINVAL, status, first)


def _spheroid_preconditions(items):
    """The items with a ≤ 0, c ≤ 0 or |‖n‖² − 1| > UNIT_TOL (what
    pw85_spheroid_checked() refuses and pw85_spheroid_batch() does not
    check), as a mask, with the rule the first breaks; (None, None) if
    none."""
    (a, sa), (c, sc), (n, sn) = items.inputs
    count = items.n
    a = np.broadcast_to(a if sa == 0 else a.reshape(count), (count,))
    c = np.broadcast_to(c if sc == 0 else c.reshape(count), (count,))
    n = np.broadcast_to(n, (count, DIM))
    with np.errstate(invalid="ignore", over="ignore"):
        nn = np.einsum("ij,ij->i", n, n)
        finite = np.isfinite(a) & np.isfinite(c) & np.isfinite(n).all(axis=1)
        bad = finite & ~((a > 0) & (c > 0) & (np.abs(nn - 1.0) <= UNIT_TOL))
    if not bad.any():
        return None, None
    i = int(np.flatnonzero(bad)[0])
    return bad, spheroid_rule(a[i], c[i], n[i])


def spheroid_rule(a, c, n):
    """The precondition of pw85_spheroid that (a, c, n) breaks, or None."""
    nn = float(np.dot(n, n))
    if not a > 0:
        return "a = %r is not > 0" % float(a)
    if not c > 0:
        return "c = %r is not > 0" % float(c)
    if not abs(nn - 1.0) <= UNIT_TOL:
        return ("n is not a unit vector: ‖n‖² = %r, |‖n‖² − 1| > "
                "UNIT_TOL = %g" % (nn, UNIT_TOL))
    return None


def ellipsoid_rotation(a, rot, q, threads):
    if np.shape(rot) == (DIM * DIM,):
        rot = np.reshape(rot, (DIM, DIM))
    items = Items("ellipsoid_rotation",
                  [("a", a, (DIM,)), ("rot", rot, (DIM, DIM))], "item")
    q = output("q", q, items.shape + (SYM,))
    _unaliased(items, q)
    _call(items, lib.pw85_ellipsoid_rotation_batch, [q], threads)
    return q


def ellipsoid_quaternion(a, p, q, threads):
    items = Items("ellipsoid_quaternion", [("a", a, (DIM,)), ("p", p, (4,))],
                  "item")
    q = output("q", q, items.shape + (SYM,))
    _unaliased(items, q)
    _call(items, lib.pw85_ellipsoid_quaternion_batch, [q], threads)
    return q


def principal_axes(q, threads):
    items = Items("principal_axes", [("q", q, (SYM,))], "item")
    a = np.empty(items.shape + (DIM,))
    rot = np.empty(items.shape + (DIM, DIM))
    _call(items, lib.pw85_principal_axes_batch, [a, rot], threads)
    return a, rot


def principal_axes_quaternion(q, threads):
    items = Items("principal_axes_quaternion", [("q", q, (SYM,))], "item")
    a = np.empty(items.shape + (DIM,))
    p = np.empty(items.shape + (4,))
    _call(items, lib.pw85_principal_axes_quaternion_batch, [a, p], threads)
    return a, p


#: The default n of batch_threads: 256 pairs for each of 2³¹ − 1 threads,
#: below the 2⁵⁶ pairs beyond which a batch runs on one thread.
LARGE_BATCH = 256 * (2**31 - 1)


def batch_threads(threads: int = 0, n: Optional[int] = None) -> int:
    """The number of threads a batch of n pairs runs on (pw85_batch_threads).

    Parameters
    ----------
    threads : int, optional
        The count asked for: 0 (the default) for OpenMP's default
        (``OMP_NUM_THREADS`` if set, else one per processor), or k ≥ 1.
    n : int, optional
        The number of pairs; None (the default) for a batch large enough
        to use every thread asked for.

    Returns
    -------
    int
        min(k, n // 256), at least 1; 1 when libpw85 was built without
        OpenMP, and for n ≥ 2⁵⁶ (pw85.h). ``batch_threads()`` is the
        count a large batch with the default ``threads=0`` would use.

    Raises
    ------
    ValueError, TypeError
        If threads or n is not a count.
    """
    threads = threads_count(threads)
    if n is None:
        n = LARGE_BATCH
    if isinstance(n, (bool, np.bool_)) or \
            not isinstance(n, (int, np.integer)) or not 0 <= n < 2**64:
        raise ValueError("n: expected a count ≥ 0, got %r" % (n,))
    return lib.pw85_batch_threads(threads, ctypes.c_size_t(int(n)))
