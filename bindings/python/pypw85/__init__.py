# SPDX-License-Identifier: BSD-3-Clause
"""Overlap test of two ellipsoids: the contact function of Perram and Wertheim.

pypw85 wraps the pw85 C library, which computes the contact function of
Perram and Wertheim (J. Comp. Phys. 58(3), 409-416, 1985,
doi:10.1016/0021-9991(85)90171-8) for two ellipsoids: the *square* μ² of the
common factor by which both ellipsoids must be scaled, their centres fixed,
to be externally tangent. μ² < 1: the ellipsoids overlap; μ² > 1: they do
not.

Representation of vectors and matrices
--------------------------------------
An ellipsoid of centre c is the set of points m such that
(m - c)ᵀ·Q⁻¹·(m - c) ≤ 1, where Q is a 3×3 symmetric positive definite
matrix (a squared length; Q = Σ aᵢ² vᵢ·vᵢᵀ for semi-axes aᵢ along unit
vectors vᵢ).

- A *vector* is an array of shape ``(3,)`` (`DIM`) of Cartesian
  coordinates.
- A *symmetric matrix* (quadratic form) A is an array of shape ``(6,)``
  (`SYM`) holding its upper triangle row by row::

      a[0]=A00  a[1]=A01  a[2]=A02  a[3]=A11  a[4]=A12  a[5]=A22

Inputs may be any array-like of real numbers of the right shape (lists,
integer arrays, ...); they are converted to contiguous ``float64`` arrays.
A masked array (``numpy.ma``) with masked entries raises `ValueError`:
NumPy's conversion would pass the values under the mask.
Outputs are returned as new ``float64`` arrays, or written in place into a
preallocated array passed by the caller, which must then be a C-contiguous,
writeable ``numpy.ndarray`` of dtype ``float64`` and of the exact shape
(anything else raises, nothing is converted silently).

Arrays of pairs
---------------
`contact_function`, `overlap`, `contact_geometry` and
`contact_derivatives` also take arrays of pairs: r12 of shape (..., 3),
q1 and q2 of shape (..., 6), whose leading axes broadcast as NumPy's do
(one ellipsoid against many: ``q1`` of shape (6,) with ``q2`` of shape
(N, 6)). The results have the broadcast shape followed by the shape of
one result: ``contact_function(r12, q1, q2)`` with r12 of shape (N, 3)
returns an array of shape (N, 2). One call of the library's batch
function computes every pair, each exactly as alone (bit for bit), with
the GIL released; ``threads=k`` spreads the pairs over up to k OpenMP
threads, at most 1024 (0: OpenMP's default, ``OMP_NUM_THREADS`` if set),
with the same results
for any count. If a pair fails, `Error` names the first one (its index in
the broadcast shape, its inputs); its ``index`` and ``statuses``
attributes give that index and every pair's status, and a preallocated
``out`` holds the results of the pairs that succeeded.

Ellipses
--------
The same functions for ellipses (two dimensions: vectors of shape (2,),
forms (Q00, Q01, Q11) of shape (3,)) are in the submodule `pypw85.d2`
(``from pypw85 import d2``).

Errors
------
Bad input never crashes: a wrong shape raises `ValueError`, a wrong dtype
or type `TypeError` (both name the argument and what was expected), and an
input the library rejects raises `Error` (a subclass of `ValueError`) whose
``status`` is one of the status codes below (`EDOM`: NaN or infinite input,
`ENOTPOSDEF`: a quadratic form is not positive definite, `ERANGE`: a result
overflows a double).

Finding the library
-------------------
Nothing to configure. On import, libpw85 is loaded (``dlopen``) from the
first of these places that works:

1. the environment variable ``PW85_LIBRARY`` (a full path), if set;
2. the absolute path where ``meson install`` put the library, recorded in
   ``pypw85/_paths.py`` when pw85 was configured;
3. the dynamic loader's usual search for ``libpw85.so.2``
   (``LD_LIBRARY_PATH``, ``/etc/ld.so.cache``, the default directories),
   then ``ctypes.util.find_library("pw85")``.

A library that loads but is not a libpw85 of ABI 2 is skipped. If a place
named by ``PW85_LIBRARY`` fails and a later one works, a `RuntimeWarning`
says so. If nothing works, `ImportError` lists every place tried and why
each failed. `pypw85.legacy` finds libpw85_legacy the same way
(``PW85_LEGACY_LIBRARY``).

Thread safety
-------------
ctypes releases the GIL around every call into the library, and every pw85
function is reentrant, so threads calling pypw85 run in parallel while they
are in the library. For a single pair, converting and checking the
arguments costs more than the computation, and runs under the GIL: pass
arrays of pairs instead (one conversion, one call, `threads` for
parallelism). Do not share a preallocated output array between threads.

The only run-time dependency is NumPy. Released under the BSD 3-Clause
licence.
"""

from __future__ import annotations

import ctypes
import math
import sys
import typing

import numpy as np

if typing.TYPE_CHECKING:  # annotations only: nothing imported at run time
    from typing import Optional, Tuple, Union
    from numpy.typing import ArrayLike, NDArray
    _F64 = NDArray[np.float64]

from . import _batch, _constants
from ._convert import (
    check_finite as _check_finite, output as _output, real as _real,
    reals as _reals, unaliased as _unaliased, vector as _vector,
)
from ._batch import batch_threads
from ._batch import spheroid_rule as _spheroid_rule
from ._errors import Error
from ._libpw85 import lib as _lib, version as _library_version
# Not used here: kept where the tests look for them (the path libpw85 was
# loaded from; the ABI this package expects).
from ._libpw85 import path as _library_path
from ._loader import ABI_MAJOR as _ABI_MAJOR
from .index import Index  # pw85_index.h: pypw85.index.Index
from ._pack import pack, Packing  # pw85_pack.h

__all__ = [
    "DIM", "SYM", "LAMBDA_ATOL", "MAX_ITER", "NR_ITER", "UNIT_TOL",
    "GEOM_MU2", "GEOM_LAMBDA", "GEOM_POINT", "GEOM_NORMAL", "GEOM_SIZE",
    "DERIV_R12", "DERIV_ROT1", "DERIV_ROT2", "DERIV_Q1", "DERIV_Q2",
    "DERIV_SIZE",
    "SUCCESS", "EFAULT", "EDOM", "ENOTPOSDEF", "ERANGE", "ENOMEM", "ENOCONV",
    "EINVAL", "ECANCELLED",
    "Error", "contact_function", "f", "f_neg", "overlap", "spheroid",
    "contact_geometry", "contact_derivatives", "ellipsoid_rotation",
    "ellipsoid_quaternion", "principal_axes", "principal_axes_quaternion",
    "pack_sym", "unpack_sym", "batch_threads", "Index",
    "pack", "Packing",
]


# The constants of pw85.h: the values are those of _constants (checked
# against the header by tests/python/test_constants.py), documented here,
# where users and Sphinx look for them.
#: The dimension of the physical space.
DIM = _constants.DIM
#: The number of independent entries of a symmetric DIM×DIM matrix.
SYM = _constants.SYM
#: The width of the bracket on λ at which Brent's certification of the
#: maximum stops (in `contact_function`).
LAMBDA_ATOL = _constants.LAMBDA_ATOL
#: The maximum number of iterations of Brent's method (in
#: `contact_function`).
MAX_ITER = _constants.MAX_ITER
#: The maximum number of plain Newton steps restarted from Brent's estimate
#: when Brent's bracket did not confirm the first Newton run (in
#: `contact_function`).
NR_ITER = _constants.NR_ITER
#: The tolerance on the orthonormality of a rotation matrix and on the unit
#: norm of a quaternion (the ellipsoid constructors).
UNIT_TOL = _constants.UNIT_TOL

# Offsets into the arrays that contact_geometry and contact_derivatives
# return (the layouts of pw85.h).
#: μ² in the output of `contact_geometry`.
GEOM_MU2 = _constants.GEOM_MU2
#: λ in the output of `contact_geometry`.
GEOM_LAMBDA = _constants.GEOM_LAMBDA
#: The first of 3 entries: the contact point minus c1.
GEOM_POINT = _constants.GEOM_POINT
#: The first of 3 entries: the unit normal, from ellipsoid 1 to 2.
GEOM_NORMAL = _constants.GEOM_NORMAL
#: The length of the output of `contact_geometry`.
GEOM_SIZE = _constants.GEOM_SIZE
#: The first of 3 entries: ∂μ²/∂r12.
DERIV_R12 = _constants.DERIV_R12
#: The first of 3 entries: ∂μ²/∂ω1 (a rotation of ellipsoid 1 about c1).
DERIV_ROT1 = _constants.DERIV_ROT1
#: The first of 3 entries: ∂μ²/∂ω2 (a rotation of ellipsoid 2 about c2).
DERIV_ROT2 = _constants.DERIV_ROT2
#: The first of 6 entries: ∂μ²/∂q1[k], the stored entries of Q1.
DERIV_Q1 = _constants.DERIV_Q1
#: The first of 6 entries: ∂μ²/∂q2[k].
DERIV_Q2 = _constants.DERIV_Q2
#: The length of the derivatives that `contact_derivatives` returns.
DERIV_SIZE = _constants.DERIV_SIZE

# The status codes (values never change once released).
#: Success.
SUCCESS = _constants.SUCCESS
#: A pointer argument is NULL (cannot happen through pypw85).
EFAULT = _constants.EFAULT
#: An input is NaN or infinite.
EDOM = _constants.EDOM
#: A quadratic form is not positive definite.
ENOTPOSDEF = _constants.ENOTPOSDEF
#: A result (or the dynamic range of the input) exceeds the range of a
#: double.
ERANGE = _constants.ERANGE
#: Out of memory: the index could not allocate, or the minimiser needs
#: more working memory than pw85 reserves (not expected).
ENOMEM = _constants.ENOMEM
#: An iterative method did not converge (the legacy contact functions).
ENOCONV = _constants.ENOCONV
#: A finite argument is outside its documented domain (a semi-axis not
#: > 0, a rotation not orthonormal, ...).
EINVAL = _constants.EINVAL
#: A function of the caller (a pair energy, a progress callback) asked to
#: stop, or raised.
ECANCELLED = _constants.ECANCELLED

#: The version of the libpw85 actually loaded ("MAJOR.MINOR.PATCH", from
#: its pw85_version()).
__version__ = _library_version

_c_cholesky_decomp = _lib.pw85__cholesky_decomp
_c_cholesky_solve = _lib.pw85__cholesky_solve
_c_spheroid = _lib.pw85_spheroid
_c_f_neg = _lib.pw85_f_neg
_c_residual = _lib.pw85__residual
_c_contact_function = _lib.pw85_contact_function
_c_overlap = _lib.pw85_overlap
_c_ellipsoid_rotation = _lib.pw85_ellipsoid_rotation
_c_ellipsoid_quaternion = _lib.pw85_ellipsoid_quaternion
_c_principal_axes = _lib.pw85_principal_axes
_c_principal_axes_quaternion = _lib.pw85_principal_axes_quaternion
_c_spheroid_checked = _lib.pw85_spheroid_checked
_c_contact_geometry = _lib.pw85_contact_geometry
_c_contact_derivatives = _lib.pw85_contact_derivatives


# ---------------------------------------------------------------------------
# The API of pw85 1.0, its contract checked.

def _cholesky_decomp(a, l=None):
    """Compute the Cholesky decomposition A = L·Lᵀ of a 3×3 matrix.

    Internal (exposed for testing); may change without notice.

    Parameters
    ----------
    a : array_like, shape (6,)
        The symmetric positive definite matrix A (upper triangle, row by
        row).
    l : numpy.ndarray, shape (6,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    l : numpy.ndarray, shape (6,)
        The lower-triangular factor L, column by column:
        ``l[0]=L00 l[1]=L10 l[2]=L20 l[3]=L11 l[4]=L21 l[5]=L22``.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if an entry of a is not finite (l untouched); `ENOTPOSDEF`
        if A is not positive definite to the resolution of the
        factorisation (l is then filled with NaN).
    """
    a = _vector("a", a, SYM)
    l = _output("l", l, SYM)
    (a,) = _unaliased(l, a)
    _check_finite("_cholesky_decomp", a=a)
    _c_cholesky_decomp(a.ctypes.data, l.ctypes.data)
    if math.isnan(l[0]):  # pw85.h: l is all NaN when A is not SPD.
        raise Error(ENOTPOSDEF, "_cholesky_decomp", "a = %r" % a)
    return l


def _cholesky_solve(l, b, x=None):
    """Solve the 3×3 linear system L·Lᵀ·x = b.

    Internal (exposed for testing); may change without notice.

    Parameters
    ----------
    l : array_like, shape (6,)
        The lower-triangular factor L, as returned by `_cholesky_decomp`.
    b : array_like, shape (3,)
        The right-hand side.
    x : numpy.ndarray, shape (3,), float64, optional
        Preallocated output, modified in place (it may be b itself). A new
        array if None.

    Returns
    -------
    x : numpy.ndarray, shape (3,)
        The solution.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if an input is not finite; `ENOTPOSDEF` if a diagonal entry
        of L is zero (L·Lᵀ singular); `ERANGE` if the solution overflows.
        x is untouched, except for `ERANGE`.
    """
    l = _vector("l", l, SYM)
    b = _vector("b", b, DIM)
    x = _output("x", x, DIM)
    (l,) = _unaliased(x, l)  # x may alias b (pw85.h), not l.
    _check_finite("_cholesky_solve", l=l, b=b)
    if l[0] == 0.0 or l[3] == 0.0 or l[5] == 0.0:
        raise Error(ENOTPOSDEF, "_cholesky_solve",
                    "L has a zero diagonal entry: l = %r" % l)
    _c_cholesky_solve(l.ctypes.data, b.ctypes.data, x.ctypes.data)
    if not np.isfinite(x).all():
        raise Error(ERANGE, "_cholesky_solve", "x = %r" % x)
    return x


def spheroid(a: ArrayLike, c: ArrayLike, n: ArrayLike,
             q: Optional[_F64] = None, *, threads: int = 1) -> _F64:
    """Return the quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ.

    On arrays (a or c of shape (...), n of shape (..., 3), leading axes
    broadcast together), one form per item, in one call of
    ``pw85_spheroid_batch``.

    Parameters
    ----------
    a : float or array_like, shape (...)
        The equatorial radius (a length, > 0).
    c : float or array_like, shape (...)
        The polar radius (a length, same unit as a, > 0).
    n : array_like, shape (3,) or (..., 3)
        The direction of the axis of revolution, a unit vector:
        abs(‖n‖² − 1) ≤ `UNIT_TOL` (not normalised here).
    q : numpy.ndarray, shape (6,) or (..., 6), float64, optional
        Preallocated output, modified in place. A new array if None.
    threads : int, optional
        Arrays only: as in `contact_function`.

    Returns
    -------
    q : numpy.ndarray, shape (6,) or (..., 6)
        The symmetric matrix Q (a squared length; upper triangle, row by
        row).

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if a, c or an entry of n is not finite; `EINVAL` if a ≤ 0,
        c ≤ 0 or n is not a unit vector (the message names the rule);
        `ERANGE` if a² or c² overflows or underflows (q untouched). On
        arrays, for the first failing item (`index`, and `statuses`, every
        item's; if it fails with `EDOM` or `ERANGE`, the items that do not
        fail are computed, and the items with `ERANGE`, as
        ``pw85_spheroid_batch`` writes them; if with `EINVAL`, none; an
        item with `EINVAL` is never computed).
    """
    if _batch.is_batch_of((a, 0), (c, 0), (n, 1)):
        return _batch.spheroid(a, c, n, q, threads)
    a = _real("a", a)
    c = _real("c", c)
    n = _vector("n", n, DIM)
    q = _output("q", q, SYM)
    (n,) = _unaliased(q, n)
    _check_finite("spheroid", a=a, c=c, n=n)
    status = _c_spheroid_checked(a, c, n.ctypes.data, q.ctypes.data)
    if status != SUCCESS:
        rule = _spheroid_rule(a, c, n) if status == EINVAL else None
        raise Error(status, "spheroid", "%sa = %r, c = %r, n = %r" % (
            rule + ": " if rule else "", a, c, n))
    return q


def _f_neg(where, lambda_, r12, q1, q2):
    """−f(λ) through pw85_f_neg, with errors raised (see f)."""
    lambda_ = _real("lambda_", lambda_)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    params = np.concatenate((r12, q1, q2))
    value = _c_f_neg(lambda_, params.ctypes.data)
    if not math.isfinite(value):
        _check_finite(where, lambda_=lambda_, r12=r12, q1=q1, q2=q2)
        if math.isnan(value):
            raise Error(ENOTPOSDEF, where, "Q(λ) = (1−λ)·Q1 + λ·Q2 with "
                        "λ = %r: q1 = %r, q2 = %r" % (lambda_, q1, q2))
        raise Error(ERANGE, where, "f(%r) overflows" % lambda_)
    return value


def f(lambda_: float, r12: ArrayLike, q1: ArrayLike, q2: ArrayLike) -> float:
    """Return f(λ) = λ(1−λ)·r12ᵀ·Q⁻¹·r12, with Q = (1−λ)·Q1 + λ·Q2.

    μ² is the maximum of f over [0, 1] (see `contact_function`). f is
    evaluated with compensated (double-double) arithmetic, as pw85_f_neg in
    pw85.h: accurate to about one ulp while the condition number of Q stays
    below ~1e10 (every value of the reference dataset is correctly rounded).
    There is no rescaling: intermediate values must stay within the range of
    a double (r12ᵀ·r12 and the entries of Q1, Q2 between about 1e-150 and
    1e150).

    Parameters
    ----------
    lambda_ : float
        λ, normally in [0, 1] (any λ for which Q is positive definite is
        accepted).
    r12 : array_like, shape (3,)
        The centre-to-centre vector c2 − c1 of the two ellipsoids.
    q1, q2 : array_like, shape (6,)
        The quadratic forms Q1, Q2 of the ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.

    Returns
    -------
    float
        f(λ), dimensionless, ≥ 0 for λ in [0, 1].

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if an input is not finite; `ENOTPOSDEF` if Q is not positive
        definite; `ERANGE` if f(λ) overflows.
    """
    return -_f_neg("f", lambda_, r12, q1, q2)


def f_neg(lambda_: float, r12: ArrayLike, q1: ArrayLike,
          q2: ArrayLike) -> float:
    """Return −f(λ), the function whose minimum over [0, 1] is −μ².

    The same as ``-f(lambda_, r12, q1, q2)``. The C function pw85_f_neg
    takes r12, q1 and q2 packed into one array of 15 doubles (the signature
    of a gsl_function); here they are passed separately, as to `f`.

    Parameters
    ----------
    lambda_, r12, q1, q2
        As for `f`.

    Returns
    -------
    float
        −f(λ), dimensionless, ≤ 0 for λ in [0, 1].

    Raises
    ------
    ValueError, TypeError, Error
        As `f`.
    """
    return _f_neg("f_neg", lambda_, r12, q1, q2)


def _residual(lambda_, r12, q1, q2, out=None):
    """Return f(λ), g(λ) = μ2²(λ) − μ1²(λ) and g′(λ).

    Internal (exposed for testing; g is the residual of the docs page
    "Optimisation",
    whose sign the Newton steps of `contact_function` follow); may change
    without notice.

    Parameters
    ----------
    lambda_ : float
        λ in [0, 1].
    r12, q1, q2 : array_like
        As for `f`.
    out : numpy.ndarray, shape (3,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    out : numpy.ndarray, shape (3,)
        ``out[0] = f(λ), out[1] = g(λ), out[2] = g′(λ)``.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type, or λ is not in [0, 1]
        (ValueError).
    Error
        `EDOM` if an input is not finite; `ENOTPOSDEF` if the result is not
        finite (Q(λ) not positive definite).
    """
    lambda_ = _real("lambda_", lambda_)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    out = _output("out", out, 3)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    _check_finite("_residual", lambda_=lambda_, r12=r12, q1=q1, q2=q2)
    if not 0.0 <= lambda_ <= 1.0:
        raise ValueError("lambda_: expected a value in [0, 1], got %r"
                         % lambda_)
    _c_residual(lambda_, r12.ctypes.data, q1.ctypes.data, q2.ctypes.data,
                out.ctypes.data)
    if not np.isfinite(out).all():
        raise Error(ENOTPOSDEF, "_residual", "out = %r" % out)
    return out


def contact_function(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                     out: Optional[_F64] = None, *,
                     threads: int = 1) -> _F64:
    """Return the contact function μ² of two ellipsoids and its maximiser λ.

    μ is the common factor by which both ellipsoids must be scaled, their
    centres fixed, to be externally tangent: μ² < 1 means they overlap,
    μ² > 1 that they are disjoint. μ² is correctly rounded (the exact
    value rounded to the nearest double) across the documented domain.
    For the yes-or-no question, `overlap` is faster::

        mu2, lambda_ = pypw85.contact_function(c2 - c1, q1, q2)

    μ² = max over λ in [0, 1] of λ(1−λ)·r12ᵀ·[(1−λ)·Q1 + λ·Q2]⁻¹·r12
    (Perram and Wertheim, 1985; the docs page "Theory"); λ, the maximiser,
    locates the contact point (`contact_geometry`).

    How it is computed (the docs page "Optimisation"): the inputs are
    rescaled by
    powers of two; λ starts from the sphere model's maximiser and is refined
    by safeguarded Newton steps on ω(λ) = λρ − (1−λ), where ρ = √(P2/P1),
    Pi = sᵀ·Qi·s and s = Q(λ)⁻¹·r12; ω has the sign of g = μ2² − μ1² and
    the same root. GSL's Brent minimiser then certifies the maximum on a
    narrow verified bracket, stopping at a width of `LAMBDA_ATOL` or after
    `MAX_ITER` iterations; if that bracket does not confirm the first Newton
    run, at most `NR_ITER` plain Newton steps restart from Brent's estimate.
    A compensated (double-double) finish makes μ² correctly rounded (on the
    reference dataset and on general pairs of aspect ratios to 1e4); μ² and
    λ stay accurate while the condition numbers of Q1 and Q2 are below
    ~1e16 (aspect ratios to 1e8; see pw85.h).

    Parameters
    ----------
    r12 : array_like, shape (3,) or (..., 3)
        The centre-to-centre vector c2 − c1 (any finite vector; r12 = 0
        gives μ² = 0, λ = ½).
    q1, q2 : array_like, shape (6,) or (..., 6)
        The quadratic forms of the two ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.
        μ² is invariant under r12 → t·r12, Q → t²·Q; any finite scale is
        accepted. Arrays of pairs broadcast (see "Arrays of pairs").
    out : numpy.ndarray, shape (2,) or S + (2,), float64, optional
        Preallocated output, modified in place (S: the broadcast shape of
        the pairs). A new array if None.
    threads : int, optional, keyword only
        For arrays of pairs: 1 (the default) computes them in the calling
        thread, k > 1 on up to k OpenMP threads, 0 on OpenMP's default
        count. The results are the same for any count.

    Returns
    -------
    out : numpy.ndarray, shape (2,) or S + (2,)
        ``out[..., 0] = μ²`` (dimensionless, ≥ 0) and ``out[..., 1] = λ``
        in [0, 1]; ``mu2, lambda_ = contact_function(r12, q1, q2)`` unpacks
        a single pair.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if an input is NaN or infinite; `ENOTPOSDEF` if q1 or q2 is
        not positive definite; `ERANGE` if μ² exceeds the largest double
        (out then holds +inf and λ) or the diagonals of q1 and q2 span
        more than the search carries (about 1e607, pw85.h); `ENOMEM` (not
        expected). Except for the
        first `ERANGE` case, out is untouched. For arrays of pairs, the
        first failing pair's status; the other pairs are computed.
    """
    if _batch.is_batch(r12, q1, q2):
        return _batch.contact_function(r12, q1, q2, out, threads)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    out = _output("out", out, 2)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    status = _c_contact_function(r12.ctypes.data, q1.ctypes.data,
                                 q2.ctypes.data, out.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "contact_function",
                    "r12 = %r, q1 = %r, q2 = %r" % (r12, q1, q2))
    return out


def overlap(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike, *,
            threads: int = 1) -> Union[int, NDArray[np.intc]]:
    """Do two ellipsoids overlap? A certified answer, faster than μ².

    Returns an int, −1, 0 or +1, not a bool: ``if overlap(...)`` is true
    for both −1 and +1. Write ``overlap(...) < 0`` for "they overlap"
    (``<= 0`` to count tangency as contact).

    Decides the sign of μ² − 1 (see `contact_function`) from bounds of μ²
    with rounding margins; only nearly tangent pairs fall back to the exact
    μ², so the answer never contradicts `contact_function`.

    Parameters
    ----------
    r12 : array_like, shape (3,) or (..., 3)
        The centre-to-centre vector c2 − c1.
    q1, q2 : array_like, shape (6,) or (..., 6)
        The quadratic forms of the two ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.
        Arrays of pairs broadcast (see "Arrays of pairs").
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    int, or numpy.ndarray of dtype numpy.intc and shape S
        −1 if they overlap (μ² < 1; also for coincident centres), +1 if
        they are disjoint (μ² > 1, including μ² beyond the range of a
        double), 0 if they are tangent to the resolution of double
        arithmetic (abs(μ² − 1) ≤ 4·ε, ε = 2⁻⁵² the machine epsilon).

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        As `contact_function`: `EDOM`, `ENOTPOSDEF`, `ERANGE` (diagonals of
        q1 and q2 spanning more than the search carries), `ENOMEM`.
    """
    if _batch.is_batch(r12, q1, q2):
        return _batch.overlap(r12, q1, q2, threads)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    result = ctypes.c_int(2)
    status = _c_overlap(r12.ctypes.data, q1.ctypes.data, q2.ctypes.data,
                        ctypes.byref(result))
    if status != SUCCESS:
        raise Error(status, "overlap",
                    "r12 = %r, q1 = %r, q2 = %r" % (r12, q1, q2))
    return result.value


# ---------------------------------------------------------------------------
# Ellipsoids in full (since 2.2.0): constructors, principal axes, contact
# geometry and derivatives. Layouts as in pw85.h.

def pack_sym(a: ArrayLike, rtol: float = 1e-12) -> _F64:
    """Return the 6-entry storage of a symmetric 3×3 matrix.

    Parameters
    ----------
    a : array_like, shape (3, 3)
        A symmetric matrix.
    rtol : float, optional
        The largest accepted asymmetry, max abs(a − aᵀ), relative to
        max abs(a).

    Returns
    -------
    numpy.ndarray, shape (6,)
        ``[a00, a01, a02, a11, a12, a22]``: the upper triangle, row by row.

    Raises
    ------
    ValueError, TypeError
        If a has the wrong shape or type, or is not symmetric to rtol.
    """
    m = _reals("a", a, "an array of shape (3, 3)")
    if m.shape != (DIM, DIM):
        raise ValueError("a: expected shape (3, 3), got %s" % (m.shape,))
    m = m.astype(np.float64)
    if np.abs(m - m.T).max() > rtol * np.abs(m).max():
        raise ValueError("a: not symmetric (max abs(a - a.T) = %g)"
                         % np.abs(m - m.T).max())
    return m[np.triu_indices(DIM)].copy()


def unpack_sym(q: ArrayLike) -> _F64:
    """Return the symmetric 3×3 matrix of a 6-entry storage (`pack_sym`).

    Parameters
    ----------
    q : array_like, shape (6,)
        ``[q00, q01, q02, q11, q12, q22]``.

    Returns
    -------
    numpy.ndarray, shape (3, 3)

    Raises
    ------
    ValueError, TypeError
        If q has the wrong shape or type.
    """
    q = _vector("q", q, SYM)
    return np.array([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                     [q[2], q[4], q[5]]])


def _rotation(name, rot):
    """rot as a C-contiguous float64 array of 9 entries, from (3, 3) or
    (9,)."""
    m = _reals(name, rot, "an array of shape (3, 3) or (9,)")
    if m.shape == (DIM, DIM):
        m = m.reshape(DIM * DIM)
    return _vector(name, m, DIM * DIM)


def ellipsoid_rotation(a: ArrayLike, rot: ArrayLike,
                       q: Optional[_F64] = None, *,
                       threads: int = 1) -> _F64:
    """Return Q = R·diag(a²)·Rᵀ, the ellipsoid of semi-axes a along the
    columns of R.

    Each entry is computed in double-double arithmetic and rounded once
    (see pw85.h for the error bound); R is used as given. On arrays (a of
    shape (..., 3), rot of shape (..., 3, 3), leading axes broadcast
    together), one form per item, in one call of
    ``pw85_ellipsoid_rotation_batch``.

    Parameters
    ----------
    a : array_like, shape (3,) or (..., 3)
        The semi-axes (lengths, each > 0).
    rot : array_like, shape (3, 3), (9,) or (..., 3, 3), or a SciPy Rotation
        The rotation R, column j the direction of a[j] (row by row when
        flat: ``rot[3*i + j] = R[i, j]``), orthonormal to `UNIT_TOL`; a
        reflection is accepted. A ``scipy.spatial.transform.Rotation``
        (one or many) stands for its ``as_matrix()``.
    q : numpy.ndarray, shape (6,) or (..., 6), float64, optional
        Preallocated output, modified in place. A new array if None.
    threads : int, optional
        Arrays only: as in `contact_function`.

    Returns
    -------
    q : numpy.ndarray, shape (6,) or (..., 6)

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` (NaN or infinite input), `EINVAL` (a semi-axis not > 0, R
        not orthonormal), `ERANGE` (a² out of the normal range). q is
        untouched (on arrays: that item's q; the error names the first
        failing item).
    """
    scipy_rot = _scipy_rotation(rot)
    if scipy_rot is not None:
        rot = scipy_rot.as_matrix()
    if _batch.is_batch_of((a, 1), (rot, 2)):
        return _batch.ellipsoid_rotation(a, rot, q, threads)
    a = _vector("a", a, DIM)
    rot = _rotation("rot", rot)
    q = _output("q", q, SYM)
    a, rot = _unaliased(q, a, rot)
    status = _c_ellipsoid_rotation(a.ctypes.data, rot.ctypes.data,
                                   q.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "ellipsoid_rotation", "a = %r, rot = %r"
                    % (a, rot.reshape(DIM, DIM)))
    return q


def ellipsoid_quaternion(a: ArrayLike, p: ArrayLike,
                         q: Optional[_F64] = None, *,
                         scalar_first: bool = True,
                         threads: int = 1) -> _F64:
    """Return the ellipsoid of semi-axes a turned by the unit quaternion p.

    Q = R(p)·diag(a²)·R(p)ᵀ, where R(p) maps the coordinate axes onto the
    principal directions (v ↦ p·v·p*, the convention of HOOMD-blue and
    LAMMPS); p is normalised, and computed with, in double-double. On
    arrays (a of shape (..., 3), p of shape (..., 4), leading axes
    broadcast together), one form per item, in one call of
    ``pw85_ellipsoid_quaternion_batch``.

    The order of the components: (w, x, y, z), scalar first, by default
    (HOOMD-blue, LAMMPS, pw85's C API). OVITO and SciPy
    (``Rotation.as_quat()``) write (x, y, z, w): pass
    ``scalar_first=False``, or the SciPy ``Rotation`` itself. A quaternion
    in the wrong order gives a wrong ellipsoid without any error.

    Parameters
    ----------
    a : array_like, shape (3,) or (..., 3)
        The semi-axes (lengths, each > 0).
    p : array_like, shape (4,) or (..., 4), or a SciPy Rotation
        The quaternion, (w, x, y, z) (``scalar_first=False``:
        (x, y, z, w)), of norm 1 to `UNIT_TOL` (on its square). A
        ``scipy.spatial.transform.Rotation`` (one or many) is taken as
        the rotation it is, whatever ``scalar_first`` says.
    q : numpy.ndarray, shape (6,) or (..., 6), float64, optional
        Preallocated output, modified in place. A new array if None.
    scalar_first : bool, optional, keyword only
        True (the default): p is (w, x, y, z); False: (x, y, z, w).
    threads : int, optional
        Arrays only: as in `contact_function`.

    Returns
    -------
    q : numpy.ndarray, shape (6,) or (..., 6)

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM`, `EINVAL` (a semi-axis not > 0, p not of unit norm),
        `ERANGE`. q is untouched (on arrays: that item's q; the error
        names the first failing item).
    """
    p = _scalar_first("p", p, scalar_first)
    if _batch.is_batch_of((a, 1), (p, 1)):
        return _batch.ellipsoid_quaternion(a, p, q, threads)
    a = _vector("a", a, DIM)
    p = _vector("p", p, 4)
    q = _output("q", q, SYM)
    a, p = _unaliased(q, a, p)
    status = _c_ellipsoid_quaternion(a.ctypes.data, p.ctypes.data,
                                     q.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "ellipsoid_quaternion", "a = %r, p = %r" % (a, p))
    return q


def principal_axes(q: ArrayLike, *,
                   threads: int = 1) -> Tuple[_F64, _F64]:
    """Return the semi-axes and principal directions of an ellipsoid.

    The inverse of `ellipsoid_rotation`: eigenvectors from GSL's symmetric
    eigensolver, semi-axes from their Rayleigh quotients in double-double
    (accurate to a few ulps even for the small axes of needles and discs
    with distinct semi-axes; see pw85.h). On an array of forms (shape
    (..., 6)), the axes of each, in one call of
    ``pw85_principal_axes_batch``.

    Parameters
    ----------
    q : array_like, shape (6,) or (..., 6)
        The quadratic form Q.
    threads : int, optional
        Arrays only: as in `contact_function`.

    Returns
    -------
    a : numpy.ndarray, shape (3,) or (..., 3)
        The semi-axes, in decreasing order.
    rot : numpy.ndarray, shape (3, 3) or (..., 3, 3)
        The rotation R (det +1): ``rot[:, j]`` is the direction of
        ``a[j]``; in columns 0 and 1, the entry of largest magnitude is
        positive.

    Raises
    ------
    ValueError, TypeError
        If q has the wrong shape or type.
    Error
        `EDOM`, `ENOTPOSDEF`, `ERANGE` (see pw85.h); on arrays, for the
        first failing item (`index`, `statuses`).
    """
    if _batch.is_batch_of((q, 1)):
        return _batch.principal_axes(q, threads)
    q = _vector("q", q, SYM)
    a = np.empty(DIM)
    rot = np.empty((DIM, DIM))
    status = _c_principal_axes(q.ctypes.data, a.ctypes.data, rot.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "principal_axes", "q = %r" % q)
    return a, rot


def principal_axes_quaternion(q: ArrayLike, *, scalar_first: bool = True,
                              threads: int = 1) -> Tuple[_F64, _F64]:
    """Return the semi-axes of an ellipsoid and its orientation as a unit
    quaternion: the inverse of `ellipsoid_quaternion`.

    `principal_axes`, then the quaternion of its rotation (Shepperd's
    method, in C: ``pw85_principal_axes_quaternion``), normalised; of the
    pair ±p, the one with w > 0. ``ellipsoid_quaternion(a, p)`` gives Q
    back, to the accuracy of the semi-axes and directions. On an array of
    forms (shape (..., 6)), one call of
    ``pw85_principal_axes_quaternion_batch``.

    Parameters
    ----------
    q : array_like, shape (6,) or (..., 6)
        The quadratic form Q.
    scalar_first : bool, optional, keyword only
        True (the default): p is returned as (w, x, y, z), the order of
        `ellipsoid_quaternion`, HOOMD-blue and LAMMPS; False: as
        (x, y, z, w), the order of OVITO and SciPy
        (``scipy.spatial.transform.Rotation.from_quat(p)``).
    threads : int, optional
        Arrays only: as in `contact_function`.

    Returns
    -------
    a : numpy.ndarray, shape (3,) or (..., 3)
        The semi-axes, in decreasing order.
    p : numpy.ndarray, shape (4,) or (..., 4)
        The unit quaternion: a[j] lies along R(p)·e_j.

    Raises
    ------
    ValueError, TypeError
        If q has the wrong shape or type (or scalar_first is not a bool).
    Error
        As `principal_axes`.
    """
    if not isinstance(scalar_first, (bool, np.bool_)):
        raise TypeError("scalar_first: expected a bool, got %s"
                        % type(scalar_first).__name__)
    if _batch.is_batch_of((q, 1)):
        a, p = _batch.principal_axes_quaternion(q, threads)
    else:
        q = _vector("q", q, SYM)
        a = np.empty(DIM)
        p = np.empty(4)
        status = _c_principal_axes_quaternion(q.ctypes.data, a.ctypes.data,
                                              p.ctypes.data)
        if status != SUCCESS:
            raise Error(status, "principal_axes_quaternion", "q = %r" % q)
    if not scalar_first:
        p = np.ascontiguousarray(np.roll(p, -1, axis=-1))
    return a, p


def _scipy_rotation(x):
    """x if it is a scipy.spatial.transform.Rotation, else None (SciPy is
    never imported here: a Rotation exists only if the caller imported
    it)."""
    module = sys.modules.get("scipy.spatial.transform")
    rotation = getattr(module, "Rotation", None)
    if rotation is not None and isinstance(x, rotation):
        return x
    return None


def _scalar_first(name, p, scalar_first):
    """The quaternion(s) p as (w, x, y, z): from a SciPy Rotation, or
    reordered from (x, y, z, w) when not scalar_first."""
    rot = _scipy_rotation(p)
    if rot is not None:
        return np.roll(rot.as_quat(), 1, axis=-1)  # (x, y, z, w) -> (w, ...)
    if not isinstance(scalar_first, (bool, np.bool_)):
        raise TypeError("scalar_first: expected a bool, got %s"
                        % type(scalar_first).__name__)
    if scalar_first:
        return p
    a = _reals(name, p, "an array of shape (4,) or (..., 4)")
    if a.ndim < 1 or a.shape[-1] != 4:
        raise ValueError("%s: expected shape (4,) or (..., 4), got %s"
                         % (name, a.shape))
    return np.roll(a, 1, axis=-1)


def contact_geometry(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                     out: Optional[_F64] = None, *,
                     threads: int = 1) -> _F64:
    """Return μ², λ, the contact point and the common normal.

    One search (that of `contact_function`: the same μ², bit for bit), λ
    polished, then ``x − c1 = (1 − λ)·Q1·s`` and ``n = s/‖s‖`` with
    s = Q(λ)⁻¹·r12 (the docs page "Theory", eqs. (3.8), (3.9a)). See the docs
    page
    "Contact geometry, forces and torques".

    Parameters
    ----------
    r12, q1, q2
        As for `contact_function` (arrays of pairs included).
    out : numpy.ndarray, shape (8,) or S + (8,), float64, optional
        Preallocated output, modified in place. A new array if None.
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    out : numpy.ndarray, shape (8,) or S + (8,)
        ``out[GEOM_MU2]`` = μ², ``out[GEOM_LAMBDA]`` = λ,
        ``out[GEOM_POINT:GEOM_POINT + 3]`` = x − c1 (the point where the
        ellipsoids scaled by μ touch), ``out[GEOM_NORMAL:GEOM_NORMAL + 3]``
        = the unit normal there, from ellipsoid 1 towards ellipsoid 2.
        r12 = 0 gives μ² = 0, λ = ½, zero point and normal.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        As `contact_function`; with `ERANGE` for an overflow, out holds
        every output (some infinite).
    """
    if _batch.is_batch(r12, q1, q2):
        return _batch.contact_geometry(r12, q1, q2, out, threads)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    out = _output("out", out, GEOM_SIZE)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    status = _c_contact_geometry(r12.ctypes.data, q1.ctypes.data,
                                 q2.ctypes.data, out.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "contact_geometry",
                    "r12 = %r, q1 = %r, q2 = %r" % (r12, q1, q2))
    return out


def contact_derivatives(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                        geometry: Optional[_F64] = None,
                        d: Optional[_F64] = None, *,
                        threads: int = 1) -> Tuple[_F64, _F64]:
    """Return the contact geometry and the first derivatives of μ².

    By the envelope theorem, with s = Q(λ)⁻¹·r12: ∂μ²/∂r12 = 2λ(1−λ)·s;
    ∂μ²/∂ω1 = 2λ(1−λ)²·s × (Q1·s) and ∂μ²/∂ω2 = 2λ²(1−λ)·s × (Q2·s) for
    a rotation ωᵢ (radians) of ellipsoid i about its centre; and the
    derivatives with respect to the six stored entries of q1 and q2,
    −λ(1−λ)²·(s0², 2s0s1, 2s0s2, s1², 2s1s2, s2²) and
    −λ²(1−λ)·(the same). For a pair energy U(μ²), the force on ellipsoid 2
    is −U′·∂μ²/∂r12 and the torque on ellipsoid i is −U′·∂μ²/∂ωᵢ.

    Parameters
    ----------
    r12, q1, q2
        As for `contact_function` (arrays of pairs included).
    geometry : numpy.ndarray, shape (8,) or S + (8,), float64, optional
        Preallocated output for the geometry (as `contact_geometry`).
    d : numpy.ndarray, shape (21,) or S + (21,), float64, optional
        Preallocated output for the derivatives.
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    geometry : numpy.ndarray, shape (8,) or S + (8,)
        As `contact_geometry`.
    d : numpy.ndarray, shape (21,) or S + (21,)
        ``d[DERIV_R12:DERIV_R12 + 3]``, ``d[DERIV_ROT1:DERIV_ROT1 + 3]``,
        ``d[DERIV_ROT2:DERIV_ROT2 + 3]``, ``d[DERIV_Q1:DERIV_Q1 + 6]``,
        ``d[DERIV_Q2:DERIV_Q2 + 6]``.

    Raises
    ------
    ValueError, TypeError, Error
        As `contact_geometry`.
    """
    if _batch.is_batch(r12, q1, q2):
        return _batch.contact_derivatives(r12, q1, q2, geometry, d, threads)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    geometry = _output("geometry", geometry, GEOM_SIZE)
    d = _output("d", d, DERIV_SIZE)
    if np.may_share_memory(geometry, d):
        raise ValueError("geometry and d: expected separate arrays")
    r12, q1, q2 = _unaliased(geometry, r12, q1, q2)
    r12, q1, q2 = _unaliased(d, r12, q1, q2)
    status = _c_contact_derivatives(r12.ctypes.data, q1.ctypes.data,
                                    q2.ctypes.data, geometry.ctypes.data,
                                    d.ctypes.data)
    if status != SUCCESS:
        raise Error(status, "contact_derivatives",
                    "r12 = %r, q1 = %r, q2 = %r" % (r12, q1, q2))
    return geometry, d
