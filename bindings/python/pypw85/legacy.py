# SPDX-License-Identifier: BSD-3-Clause
"""Python wrapper of the legacy API of pw85 (library libpw85_legacy).

Earlier implementations of the function f and of the contact function,
discarded for accuracy or robustness and kept for reference and for the
comparisons of the documentation (docs/implementation.rst and docs/python-api.rst). New code
should call `pypw85.f` and `pypw85.contact_function`.

Vectors, symmetric matrices, array-likes, preallocated outputs, exceptions
and thread safety are as in `pypw85` (see its documentation).

libpw85_legacy is found like libpw85, from the first place that works: the
environment variable ``PW85_LEGACY_LIBRARY``, the path recorded by
``meson install``, the dynamic loader's search for ``libpw85_legacy.so.2``.
Importing this module raises `ImportError`, listing the places tried, when
none works (for example when pw85 was configured with ``-Dlegacy=false``).
"""

from __future__ import annotations

import math as _math
import typing

import numpy as _np

if typing.TYPE_CHECKING:  # annotations only: nothing imported at run time
    from typing import Optional
    from numpy.typing import ArrayLike, NDArray

from ._constants import (DIM as _DIM, ENOTPOSDEF as _ENOTPOSDEF,
                         SUCCESS as _SUCCESS, SYM as _SYM)
from ._constants import ENOCONV as _ENOCONV
from ._convert import (
    check_finite as _check_finite, output as _output, real as _real,
    unaliased as _unaliased, vector as _vector,
)
from ._errors import Error as _Error
from ._loader import load_library as _load_library
from ._symbols import LIBPW85_LEGACY as _LIBPW85_LEGACY, declare as _declare

__all__ = [
    "ENOCONV", "contact_function1", "contact_function2", "f1", "f2",
]

#: Status of `contact_function1` when Newton's method does not converge
#: (PW85_ENOCONV of pw85.h; the same value as `pypw85.ENOCONV`).
ENOCONV = _ENOCONV

_lib, _library_path = _load_library(
    "pw85_legacy", "PW85_LEGACY_LIBRARY", "LIBPW85_LEGACY", _LIBPW85_LEGACY)
_declare(_lib, _LIBPW85_LEGACY)

_c_det_sym = _lib.pw85_legacy__det_sym
_c_xT_adjA_x = _lib.pw85_legacy__xT_adjA_x
_c_detQ_as_poly = _lib.pw85_legacy__detQ_as_poly
_c_rT_adjQ_r_as_poly = _lib.pw85_legacy__rT_adjQ_r_as_poly
_c_f1 = _lib.pw85_legacy_f1
_c_f2 = _lib.pw85_legacy_f2
_c_contact_function1 = _lib.pw85_legacy_contact_function1
_c_contact_function2 = _lib.pw85_legacy_contact_function2


def _det_sym(a):
    """Return the determinant of a symmetric 3×3 matrix A.

    Internal (exposed for testing); may change without notice.

    Parameters
    ----------
    a : array_like, shape (6,)
        The symmetric matrix A (upper triangle, row by row).

    Returns
    -------
    float
        det(A), by cofactor expansion (the cube of a's unit).

    Raises
    ------
    ValueError, TypeError
        If a has the wrong shape or type.
    Error
        `pypw85.EDOM` if an entry of a is not finite.
    """
    a = _vector("a", a, _SYM)
    _check_finite("_det_sym", a=a)
    return _c_det_sym(a.ctypes.data)


def _xT_adjA_x(x, a):
    """Return the product xᵀ·adj(A)·x.

    adj(A) is the adjugate of A, the transpose of its cofactor matrix
    (A·adj(A) = det(A)·I). Internal (exposed for testing); may change
    without notice.

    Parameters
    ----------
    x : array_like, shape (3,)
        The column vector x.
    a : array_like, shape (6,)
        The symmetric matrix A (upper triangle, row by row).

    Returns
    -------
    float
        xᵀ·adj(A)·x.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `pypw85.EDOM` if an input is not finite.
    """
    x = _vector("x", x, _DIM)
    a = _vector("a", a, _SYM)
    _check_finite("_xT_adjA_x", x=x, a=a)
    return _c_xT_adjA_x(x.ctypes.data, a.ctypes.data)


def _detQ_as_poly(q1, q2, q3=None, q4=None, b=None):
    """Compute the coefficients of λ ↦ det[(1−λ)·Q1 + λ·Q2].

    det[(1−λ)·Q1 + λ·Q2] = b0 + b1·λ + b2·λ² + b3·λ³ (docs/implementation.rst, "Implementation 2",
    eqs. (12d)-(12g)). Internal (exposed for testing); may change without
    notice.

    Parameters
    ----------
    q1, q2 : array_like, shape (6,)
        The symmetric matrices Q1 and Q2 (upper triangle, row by row).
    q3 : array_like, shape (6,), optional
        2·Q1 − Q2 (``q3[i] = 2*q1[i] - q2[i]``), computed if None. Not
        checked: a q3 that is not 2·Q1 − Q2 gives wrong coefficients.
    q4 : array_like, shape (6,), optional
        (Q1 + Q2)/2 (``q4[i] = 0.5*(q1[i] + q2[i])``), computed if None.
        Not checked either.
    b : numpy.ndarray, shape (4,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    b : numpy.ndarray, shape (4,)
        The coefficients in increasing order: ``b[i] = bi``.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `pypw85.EDOM` if an input is not finite (b untouched).
    """
    q1 = _vector("q1", q1, _SYM)
    q2 = _vector("q2", q2, _SYM)
    q3 = 2.0 * q1 - q2 if q3 is None else _vector("q3", q3, _SYM)
    q4 = 0.5 * (q1 + q2) if q4 is None else _vector("q4", q4, _SYM)
    b = _output("b", b, _DIM + 1)
    q1, q2, q3, q4 = _unaliased(b, q1, q2, q3, q4)
    _check_finite("_detQ_as_poly", q1=q1, q2=q2, q3=q3, q4=q4)
    _c_detQ_as_poly(q1.ctypes.data, q2.ctypes.data, q3.ctypes.data,
                    q4.ctypes.data, b.ctypes.data)
    return b


def _rT_adjQ_r_as_poly(r, q1, q2, q3=None, a=None):
    """Compute the coefficients of λ ↦ rᵀ·adj[(1−λ)·Q1 + λ·Q2]·r.

    rᵀ·adj[(1−λ)·Q1 + λ·Q2]·r = a0 + a1·λ + a2·λ² (docs/implementation.rst, "Implementation 2",
    eqs. (12a)-(12c)). Internal (exposed for testing); may change without
    notice.

    Parameters
    ----------
    r : array_like, shape (3,)
        The vector r.
    q1, q2 : array_like, shape (6,)
        The symmetric matrices Q1 and Q2 (upper triangle, row by row).
    q3 : array_like, shape (6,), optional
        2·Q1 − Q2 (``q3[i] = 2*q1[i] - q2[i]``), computed if None. Not
        checked: a q3 that is not 2·Q1 − Q2 gives wrong coefficients.
    a : numpy.ndarray, shape (3,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    a : numpy.ndarray, shape (3,)
        The coefficients in increasing order: ``a[i] = ai``.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `pypw85.EDOM` if an input is not finite (a untouched).
    """
    r = _vector("r", r, _DIM)
    q1 = _vector("q1", q1, _SYM)
    q2 = _vector("q2", q2, _SYM)
    q3 = 2.0 * q1 - q2 if q3 is None else _vector("q3", q3, _SYM)
    a = _output("a", a, _DIM)
    r, q1, q2, q3 = _unaliased(a, r, q1, q2, q3)
    _check_finite("_rT_adjQ_r_as_poly", r=r, q1=q1, q2=q2, q3=q3)
    _c_rT_adjQ_r_as_poly(r.ctypes.data, q1.ctypes.data, q2.ctypes.data,
                         q3.ctypes.data, a.ctypes.data)
    return a


def _f(where, c_function, size, lambda_, r12, q1, q2, out):
    """Call pw85_legacy_f1 or _f2 (out: None or `size` doubles)."""
    lambda_ = _real("lambda_", lambda_)
    r12 = _vector("r12", r12, _DIM)
    q1 = _vector("q1", q1, _SYM)
    q2 = _vector("q2", q2, _SYM)
    if out is None:
        out_p = None
    else:
        out = _output("out", out, size)
        r12, q1, q2 = _unaliased(out, r12, q1, q2)
        out_p = out.ctypes.data
    value = c_function(lambda_, r12.ctypes.data, q1.ctypes.data,
                       q2.ctypes.data, out_p)
    if _math.isnan(value):
        _check_finite(where, lambda_=lambda_, r12=r12, q1=q1, q2=q2)
        raise _Error(_ENOTPOSDEF, where, "Q(λ) = (1−λ)·Q1 + λ·Q2 with "
                    "λ = %r: q1 = %r, q2 = %r" % (lambda_, q1, q2))
    return value


def f1(lambda_: float, r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
       out: Optional[NDArray[_np.float64]] = None) -> float:
    """Return f(λ) = λ(1−λ)·r12ᵀ·Q⁻¹·r12, Q = (1−λ)·Q1 + λ·Q2, and f′, f″.

    Implementation #1 (docs/implementation.rst, "Implementation 1"): a Cholesky factorisation of Q,
    plain double arithmetic (|r12|² and the entries of Q1, Q2 between about
    1e-300 and 1e300).

    Parameters
    ----------
    lambda_ : float
        λ, normally in [0, 1].
    r12 : array_like, shape (3,)
        The centre-to-centre vector c2 − c1.
    q1, q2 : array_like, shape (6,)
        The quadratic forms of the two ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.
    out : numpy.ndarray, shape (3,), float64, optional
        If given, modified in place: ``out[0] = f(λ)``, ``out[1] = f′(λ)``,
        ``out[2] = f″(λ)`` (NaN on error).

    Returns
    -------
    float
        f(λ), dimensionless.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `pypw85.EDOM` if an input is not finite; `pypw85.ENOTPOSDEF` if Q
        is not positive definite.
    """
    return _f("f1", _c_f1, 3, lambda_, r12, q1, q2, out)


def f2(lambda_: float, r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
       out: Optional[NDArray[_np.float64]] = None) -> float:
    """Alternative implementation of `f1`: f(λ) as a rational fraction.

    Implementation #2 (docs/implementation.rst, "Implementation 2"): f(λ) = λ(1−λ)·a(λ)/b(λ), with
    a(λ) = r12ᵀ·adj[Q]·r12 and b(λ) = det Q. Less accurate than `f1`. See
    `f1` for lambda_, r12, q1, q2 and the exceptions.

    Parameters
    ----------
    out : numpy.ndarray, shape (1,), float64, optional
        If given, modified in place: ``out[0] = f(λ)`` (NaN on error).

    Returns
    -------
    float
        f(λ), dimensionless.
    """
    return _f("f2", _c_f2, 1, lambda_, r12, q1, q2, out)


def _contact(where, c_function, r12, q1, q2, out):
    r12 = _vector("r12", r12, _DIM)
    q1 = _vector("q1", q1, _SYM)
    q2 = _vector("q2", q2, _SYM)
    out = _output("out", out, 2)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    status = c_function(r12.ctypes.data, q1.ctypes.data, q2.ctypes.data,
                        out.ctypes.data)
    if status != _SUCCESS:
        raise _Error(status, where,
                    "r12 = %r, q1 = %r, q2 = %r" % (r12, q1, q2))
    return out


def contact_function1(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                       out: Optional[NDArray[_np.float64]] = None
                       ) -> NDArray[_np.float64]:
    """Return μ² and λ by Newton-Raphson iterations on f′(λ) = 0.

    Starts from λ = ½ with the f′ and f″ of `f1`. Not robust: prefer
    `pypw85.contact_function`. Arguments, result and exceptions as
    `pypw85.contact_function`, plus one more failure.

    Raises
    ------
    Error
        As `pypw85.contact_function`, and `ENOCONV` when Newton's method
        fails (a step leaves [0, 1], f″(λ) ≥ 0, or no convergence after 50
        steps): out then holds the largest f(λ) met, a lower bound of μ²,
        and its λ.
    """
    return _contact("contact_function1", _c_contact_function1, r12, q1, q2,
                    out)


def contact_function2(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                       out: Optional[NDArray[_np.float64]] = None
                       ) -> NDArray[_np.float64]:
    """Return μ² and λ by bisection on the numerator of f′ (a polynomial).

    f′(λ) = c(λ)/b(λ)², c of degree 6 (docs/implementation.rst, "Implementation 2", eqs. (4.13)-(4.15));
    μ² = f(λ) as a rational fraction. Always terminates, but inaccurate for
    very flat or slender ellipsoids: prefer `pypw85.contact_function`.
    Arguments, result and exceptions as `pypw85.contact_function`.
    """
    return _contact("contact_function2", _c_contact_function2, r12, q1, q2,
                    out)
