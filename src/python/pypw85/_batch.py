# SPDX-License-Identifier: BSD-3-Clause
"""Arrays of pairs: one call of a batch function of pw85.h per call.

`contact_function`, `overlap`, `contact_geometry` and `contact_derivatives`
of pypw85 come here when an input has more than one dimension. The leading
axes of r12 (..., 3), q1 (..., 6) and q2 (..., 6) broadcast as NumPy's do;
the outputs have the broadcast shape followed by the shape of one result.
An input whose leading axes hold one pair is passed once, with a stride of
0 (no copy); one of the broadcast shape is passed as is when C-contiguous
float64; any other is copied to the broadcast shape. Then one C call does
every pair, with the GIL released (ctypes releases it around a call); the
statuses are asked for only when that call reports a failure.
"""

import ctypes

import numpy as np

from ._constants import DERIV_SIZE, DIM, GEOM_SIZE, SUCCESS, SYM
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
    if not 0 <= threads <= 2**31 - 1:
        raise ValueError("threads: expected 0 (OpenMP's default) or a "
                         "positive count, got %d" % threads)
    return int(threads)


def _real_array(name, x, size):
    """x as a float64 array of shape (..., size), or raise."""
    try:
        a = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise ValueError("%s: expected an array of shape (..., %d), got %s "
                         "(%s)" % (name, size, type(x).__name__, exc)) \
            from None
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected real numbers (float64), got an array "
                        "of dtype %s" % (name, a.dtype))
    if a.ndim == 0 or a.shape[-1] != size:
        raise ValueError("%s: expected shape (%d,) or (..., %d), got %s"
                         % (name, size, size, a.shape))
    return a.astype(np.float64, copy=False)


class Pairs:
    """The inputs of a batch: broadcast shape, count, and for each input
    the array handed to C and its stride in doubles."""

    def __init__(self, where, r12, q1, q2):
        self.where = where
        arrays = [_real_array("r12", r12, DIM), _real_array("q1", q1, SYM),
                  _real_array("q2", q2, SYM)]
        try:
            self.shape = np.broadcast_shapes(*(a.shape[:-1] for a in arrays))
        except ValueError:
            raise ValueError(
                "%s: the leading axes of r12 %s, q1 %s and q2 %s do not "
                "broadcast together" % ((where,) + tuple(
                    a.shape for a in arrays))) from None
        self.n = int(np.prod(self.shape, dtype=np.int64))
        self.inputs = []  # (array, stride)
        for a in arrays:
            size = a.shape[-1]
            if a.size == size:  # one record for every pair
                a = np.ascontiguousarray(a).reshape(size)
                stride = 0
            else:
                if a.shape[:-1] != self.shape:
                    a = np.broadcast_to(a, self.shape + (size,))
                a = np.ascontiguousarray(a).reshape(self.n, size)
                stride = size
            self.inputs.append((a, stride))

    def arguments(self):
        """n, then (address, stride) of r12, q1, q2: the first arguments
        of a batch function."""
        args = [self.n]
        for a, stride in self.inputs:
            args += [a.ctypes.data, stride]
        return args

    def pair(self, i):
        """The inputs of pair i (flat index), for messages."""
        return [a if stride == 0 else a[i] for a, stride in self.inputs]

    def raise_first(self, code, status):
        """Raise Error for the first failing pair (status: n ints)."""
        i = int(np.flatnonzero(status)[0])
        index = np.unravel_index(i, self.shape)
        index = tuple(int(k) for k in index)
        r12, q1, q2 = self.pair(i)
        error = Error(code, self.where,
                      "pair %s of %s (%d of %d failed): r12 = %r, q1 = %r, "
                      "q2 = %r" % (index, self.shape,
                                   np.count_nonzero(status), self.n, r12, q1,
                                   q2))
        error.index = index
        error.statuses = status.reshape(self.shape)
        raise error


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
    pairs = Pairs("contact_function", r12, q1, q2)
    out = output("out", out, pairs.shape + (2,))
    _unaliased(pairs, out)
    _call(pairs, lib.pw85_contact_function_batch, [out], threads)
    return out


def overlap(r12, q1, q2, threads):
    pairs = Pairs("overlap", r12, q1, q2)
    result = np.empty(pairs.shape, dtype=np.intc)
    _call(pairs, lib.pw85_overlap_batch, [result], threads)
    return result


def contact_geometry(r12, q1, q2, out, threads):
    pairs = Pairs("contact_geometry", r12, q1, q2)
    out = output("out", out, pairs.shape + (GEOM_SIZE,))
    _unaliased(pairs, out)
    _call(pairs, lib.pw85_contact_geometry_batch, [out], threads)
    return out


def contact_derivatives(r12, q1, q2, geometry, d, threads):
    pairs = Pairs("contact_derivatives", r12, q1, q2)
    geometry = output("geometry", geometry, pairs.shape + (GEOM_SIZE,))
    d = output("d", d, pairs.shape + (DERIV_SIZE,))
    if np.may_share_memory(geometry, d):
        raise ValueError("geometry and d: expected separate arrays")
    _unaliased(pairs, geometry, d)
    _call(pairs, lib.pw85_contact_derivatives_batch, [geometry, d], threads)
    return geometry, d


def batch_threads(threads=0, n=2**62):
    """The number of threads a batch of n pairs runs on (pw85_batch_threads).

    Parameters
    ----------
    threads : int, optional
        The count asked for: 0 (the default) for OpenMP's default
        (``OMP_NUM_THREADS`` if set, else one per processor), or k ≥ 1.
    n : int, optional
        The number of pairs (default: a large batch).

    Returns
    -------
    int
        min(k, n // 256), at least 1; 1 when libpw85 was built without
        OpenMP.

    Raises
    ------
    ValueError, TypeError
        If threads or n is not a count.
    """
    threads = threads_count(threads)
    if not isinstance(n, (int, np.integer)) or n < 0:
        raise ValueError("n: expected a count ≥ 0, got %r" % (n,))
    return lib.pw85_batch_threads(threads, ctypes.c_size_t(int(n)))
