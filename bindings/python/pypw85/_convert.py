# SPDX-License-Identifier: BSD-3-Clause
"""Argument conversion and validation, shared by pypw85 and pypw85.legacy.

Inputs become C-contiguous float64 arrays (or Python floats) that can be
handed to C as addresses; outputs are checked, never converted. A wrong
shape raises ValueError and a wrong type TypeError, both naming the
argument and what was expected; a NaN or infinite input raises
`Error` (`EDOM`).
"""

import numbers

import numpy as np

from ._constants import EDOM
from ._errors import Error


def unmasked(name, x):
    """Raise ValueError if x is a masked array with a masked entry: numpy's
    conversions (np.asarray) keep the values under the mask and drop the
    mask, so that the call would use values the caller has set aside."""
    if isinstance(x, np.ma.MaskedArray) and np.ma.getmaskarray(x).any():
        raise ValueError("%s: a masked array with %d masked entries (numpy "
                         "would pass the values under the mask); fill them "
                         "(x.filled(...)) or leave out the items they "
                         "belong to" % (name, np.ma.count_masked(x)))


def reals(name, x, expected):
    """np.asarray(x), if x holds real numbers (integers or floats), or
    raise naming x: ValueError where x is not an array (a ragged list; the
    message says it expected `expected`) or has masked entries
    (unmasked()); TypeError for other entries (a cast would drop the
    imaginary parts of complex numbers, read bools as 0 and 1, or fail on
    strings with a message that does not name x)."""
    unmasked(name, x)
    try:
        a = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise ValueError("%s: expected %s, got %s (%s)"
                         % (name, expected, type(x).__name__, exc)) from None
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected real numbers, got an array of dtype %s"
                        % (name, a.dtype))
    return a


def vector(name, x, n):
    """x as a C-contiguous float64 array of shape (n,), or raise."""
    if (type(x) is np.ndarray and x.dtype == np.float64 and x.shape == (n,)
            and x.flags.c_contiguous):
        return x
    a = reals(name, x, "an array of shape (%d,)" % n)
    if a.shape != (n,):
        raise ValueError("%s: expected shape (%d,), got %s"
                         % (name, n, a.shape))
    return np.ascontiguousarray(a, dtype=np.float64)


def output(name, out, n):
    """out, checked to be a writeable float64 array of shape (n,); or new."""
    if out is None:
        return np.empty(n, dtype=np.float64)
    expected = "a C-contiguous, writeable numpy.ndarray of dtype float64 " \
               "and shape (%d,)" % n
    if not isinstance(out, np.ndarray):
        raise TypeError("%s: expected %s, got %s"
                        % (name, expected, type(out).__name__))
    if out.dtype != np.float64:
        raise TypeError("%s: expected %s, got dtype %s"
                        % (name, expected, out.dtype))
    if out.shape != (n,):
        raise ValueError("%s: expected %s, got shape %s"
                         % (name, expected, out.shape))
    if not out.flags.c_contiguous:
        raise ValueError("%s: expected %s, got a non-contiguous array"
                         % (name, expected))
    if not out.flags.writeable:
        raise ValueError("%s: expected %s, got a read-only array"
                         % (name, expected))
    return out


def unaliased(out, *inputs):
    """The inputs, each copied if it shares memory with out."""
    return [np.array(x) if np.may_share_memory(out, x) else x for x in inputs]


def real(name, x):
    """x as a Python float, if x is a real scalar; else raise TypeError
    (ValueError for an integer beyond the range of a double). A bool is
    refused, as in the arrays (vector()): True is no length."""
    if isinstance(x, (bool, np.bool_)):
        raise TypeError("%s: expected a real number, got a bool (%r)"
                        % (name, x))
    if isinstance(x, numbers.Real) or (
            isinstance(x, np.ndarray) and x.ndim == 0 and
            x.dtype.kind in "iuf"):
        try:
            return float(x)
        except OverflowError:
            raise ValueError("%s: expected a real number in the range of a "
                             "double, got an integer of %d digits"
                             % (name, len(str(abs(int(x)))))) from None
    raise TypeError("%s: expected a real number, got %s"
                    % (name, type(x).__name__))


def real_array(name, x):
    """x as a C-contiguous float64 array, if its entries are real numbers
    (integers or floats); else raise as reals()."""
    return np.ascontiguousarray(reals(name, x, "an array"), dtype=np.float64)


def check_finite(where, **named):
    """Raise Error(EDOM) naming the first non-finite argument."""
    for name, value in named.items():
        if not np.isfinite(value).all():
            raise Error(EDOM, where, "%s = %r" % (name, value))
