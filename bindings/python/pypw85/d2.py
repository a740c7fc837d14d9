# SPDX-License-Identifier: BSD-3-Clause
"""Ellipses: the contact function of Perram and Wertheim in two dimensions.

The functions of pypw85 for ellipses (the C header pw85_2d.h), with the
conventions of the three-dimensional ones: arrays of pairs that broadcast,
one batch call into the library per call with the GIL released,
``threads``, preallocated outputs, and `pypw85.Error` for an input the
library rejects (with ``index`` and ``statuses`` for arrays of pairs).

An ellipse of centre c is the set of points m such that
(m − c)ᵀ·Q⁻¹·(m − c) ≤ 1, with Q a 2×2 symmetric positive definite matrix
(a squared length).

- A *vector* is an array of shape ``(2,)`` (`DIM`).
- A *quadratic form* Q is an array of shape ``(3,)`` (`SYM`)::

      q[0]=Q00  q[1]=Q01  q[2]=Q11

- An *angle* θ (radians, counter-clockwise from the x axis) orients an
  ellipse: `ellipse` turns the semi-axis ``a[0]`` onto (cos θ, sin θ).

μ², λ, the overlap test, the contact point, the normal and the derivatives
are those of the 3D functions with 2 × 2 forms (the same library code,
compiled for two dimensions), with one difference: a rotation in the plane
has one angle, so the torques are the scalars ∂μ²/∂θ1 and ∂μ²/∂θ2 (see
`contact_derivatives`). The docs page "Ellipses" draws the conventions.

Example: an ellipse of semi-axes 2 and 0.5 turned by 0.3 radians, a unit
circle, centres (3, 1) apart::

    from pypw85 import d2
    q1 = d2.ellipse([2.0, 0.5], 0.3)
    q2 = d2.ellipse([1.0, 1.0], 0.0)
    mu2, lambda_ = d2.contact_function([3.0, 1.0], q1, q2)
"""

from __future__ import annotations

import ctypes
import fractions
import math
import typing

import numpy as np

if typing.TYPE_CHECKING:  # annotations only: nothing imported at run time
    from typing import Optional, Tuple, Union
    from numpy.typing import ArrayLike, NDArray
    _F64 = NDArray[np.float64]

from . import _batch
from ._constants import ENOTPOSDEF, ERANGE, SUCCESS
from ._convert import (check_finite as _check_finite, output as _output,
                       real as _real, unaliased as _unaliased,
                       vector as _vector)
from ._errors import Error
from ._libpw85 import lib as _lib, version as _library_version
from ._symbols import LIBPW85_2D, declare as _declare
from .index import (_Dimension, _Index, _prototypes as _index_prototypes)
from ._pack import _Options, _Shape, _packer

__all__ = [
    "DIM", "SYM", "GEOM_MU2", "GEOM_LAMBDA", "GEOM_POINT", "GEOM_NORMAL",
    "GEOM_SIZE", "DERIV_R12", "DERIV_THETA1", "DERIV_THETA2", "DERIV_Q1",
    "DERIV_Q2", "DERIV_SIZE",
    "f", "f_neg", "contact_function", "overlap", "contact_geometry",
    "contact_derivatives", "ellipse", "principal_axes", "Index", "pack",
    "Packing",
]

# The macros of pw85_2d.h (tests/python/test_d2.py parses the header and
# fails if a value differs or a macro has no counterpart here).
#: The number of coordinates of a vector (PW85_2D_DIM).
DIM = 2
#: The number of stored entries of a symmetric 2×2 form (PW85_2D_SYM).
SYM = 3
#: μ² in the output of `contact_geometry`.
GEOM_MU2 = 0
#: λ in the output of `contact_geometry`.
GEOM_LAMBDA = 1
#: The first of 2 entries: the contact point minus c1.
GEOM_POINT = 2
#: The first of 2 entries: the unit normal, from ellipse 1 towards 2.
GEOM_NORMAL = 4
#: The length of the output of `contact_geometry`.
GEOM_SIZE = 6
#: The first of 2 entries: ∂μ²/∂r12.
DERIV_R12 = 0
#: ∂μ²/∂θ1, θ1 the angle (radians, counter-clockwise) turning ellipse 1
#: about its centre.
DERIV_THETA1 = 2
#: ∂μ²/∂θ2, the same for ellipse 2.
DERIV_THETA2 = 3
#: The first of 3 entries: ∂μ²/∂q1[k], the stored entries of Q1.
DERIV_Q1 = 4
#: The first of 3 entries: ∂μ²/∂q2[k].
DERIV_Q2 = 7
#: The length of the derivatives that `contact_derivatives` returns.
DERIV_SIZE = 10

try:
    _declare(_lib, LIBPW85_2D)
    _declare(_lib, _index_prototypes("pw85_2d_index_"))
    _declare(_lib, {"pw85_2d_pack": (
        ctypes.c_int, [ctypes.c_size_t, ctypes.c_void_p,
                       ctypes.POINTER(_Options)] + [ctypes.c_void_p] * 4
        + [ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_int)])})
except AttributeError as exc:  # a libpw85 older than 2.5.0
    raise ImportError("pypw85.d2: the libpw85 loaded (%s) has no ellipse "
                      "functions (pw85_2d.h, since 2.5.0): %s"
                      % (_library_version, exc)) from None

_WHERE = "d2."


def _pair(r12, q1, q2):
    return (_vector("r12", r12, DIM), _vector("q1", q1, SYM),
            _vector("q2", q2, SYM))


def _pairs(where, r12, q1, q2):
    """The inputs of a batch of pairs of ellipses."""
    return _batch.Items(_WHERE + where, [("r12", r12, (DIM,)),
                                         ("q1", q1, (SYM,)),
                                         ("q2", q2, (SYM,))])


def _pair_error(status, where, r12, q1, q2):
    return Error(status, _WHERE + where, "r12 = %r, q1 = %r, q2 = %r"
                 % (r12, q1, q2))


def _f_neg(where, lambda_, r12, q1, q2):
    """−f(λ) through pw85_2d_f_neg, with errors raised (see f)."""
    lambda_ = _real("lambda_", lambda_)
    r12, q1, q2 = _pair(r12, q1, q2)
    params = np.concatenate((r12, q1, q2))
    value = _lib.pw85_2d_f_neg(lambda_, params.ctypes.data)
    if not math.isfinite(value):
        _check_finite(_WHERE + where, lambda_=lambda_, r12=r12, q1=q1, q2=q2)
        if math.isnan(value):
            raise Error(ENOTPOSDEF, _WHERE + where,
                        "Q(λ) = (1−λ)·Q1 + λ·Q2 with λ = %r: q1 = %r, "
                        "q2 = %r" % (lambda_, q1, q2))
        raise Error(ERANGE, _WHERE + where, "f(%r) overflows" % lambda_)
    return value


def f(lambda_: float, r12: ArrayLike, q1: ArrayLike, q2: ArrayLike) -> float:
    """Return f(λ) = λ(1−λ)·r12ᵀ·Q(λ)⁻¹·r12, Q(λ) = (1−λ)·Q1 + λ·Q2.

    μ² is the maximum of f over [0, 1] (see `contact_function`). Evaluated
    as pw85_2d_f_neg in pw85_2d.h: compensated arithmetic, correctly
    rounded on the reference pairs (cond to 1e15); no rescaling, so the
    entries of Q1, Q2 and |r12|² must stay between about 1e-150 and
    1e150.

    Parameters
    ----------
    lambda_ : float
        λ, normally in [0, 1].
    r12 : array_like, shape (2,)
        The centre-to-centre vector c2 − c1.
    q1, q2 : array_like, shape (3,)
        The quadratic forms (Q00, Q01, Q11), in the square of r12's unit.

    Returns
    -------
    float
        f(λ), dimensionless.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `~pypw85.EDOM` if an input is not finite; `~pypw85.ENOTPOSDEF` if
        q1, q2 or Q(λ) is not positive definite; `~pypw85.ERANGE` if f(λ)
        overflows.
    """
    return -_f_neg("f", lambda_, r12, q1, q2)


def f_neg(lambda_: float, r12: ArrayLike, q1: ArrayLike,
          q2: ArrayLike) -> float:
    """Return −f(λ): the same as ``-f(lambda_, r12, q1, q2)``.

    The C function pw85_2d_f_neg takes r12, q1 and q2 packed into one
    array of 8 doubles (the signature of a gsl_function); here they are
    passed separately.

    Parameters
    ----------
    lambda_, r12, q1, q2
        As for `f`.

    Returns
    -------
    float
        −f(λ).

    Raises
    ------
    ValueError, TypeError, Error
        As `f`.
    """
    return _f_neg("f_neg", lambda_, r12, q1, q2)


def contact_function(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                     out: Optional[_F64] = None, *,
                     threads: int = 1) -> _F64:
    """Return the contact function μ² of two ellipses and its maximiser λ.

    μ² < 1: the ellipses overlap; μ² > 1: they are disjoint. μ² is
    correctly rounded for cond(Q1), cond(Q2) < 1e16 (pw85_2d.h), and
    swapping the ellipses gives the same μ² bit for bit. For the
    yes-or-no question, `overlap` is faster::

        mu2, lambda_ = pypw85.d2.contact_function(c2 - c1, q1, q2)

    Parameters
    ----------
    r12 : array_like, shape (2,) or (..., 2)
        The centre-to-centre vector c2 − c1 (r12 = 0 gives μ² = 0,
        λ = ½).
    q1, q2 : array_like, shape (3,) or (..., 3)
        The quadratic forms (Q00, Q01, Q11), positive definite, in the
        square of r12's unit. The leading axes of r12, q1 and q2
        broadcast together (see pypw85, "Arrays of pairs").
    out : numpy.ndarray, shape (2,) or S + (2,), float64, optional
        Preallocated output, modified in place (S: the broadcast shape).
    threads : int, optional, keyword only
        For arrays of pairs: 1 (the default), k > 1 OpenMP threads, or 0
        for OpenMP's default; the same results for any count.

    Returns
    -------
    out : numpy.ndarray, shape (2,) or S + (2,)
        ``out[..., 0] = μ²``, ``out[..., 1] = λ``.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `~pypw85.EDOM` (NaN or infinite input), `~pypw85.ENOTPOSDEF` (q1
        or q2 not positive definite), `~pypw85.ERANGE` (μ² beyond the
        largest double: out holds +inf and λ; or forms beyond the range
        of a double), `~pypw85.ENOMEM` (not expected). For arrays of
        pairs, the first failing pair (``index``, ``statuses``); the
        other pairs are computed.
    """
    if _batch.is_batch(r12, q1, q2):
        pairs = _pairs("contact_function", r12, q1, q2)
        out = _batch.output("out", out, pairs.shape + (2,))
        _batch._unaliased(pairs, out)
        _batch._call(pairs, _lib.pw85_2d_contact_function_batch, [out],
                     threads)
        return out
    r12, q1, q2 = _pair(r12, q1, q2)
    out = _output("out", out, 2)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    status = _lib.pw85_2d_contact_function(r12.ctypes.data, q1.ctypes.data,
                                           q2.ctypes.data, out.ctypes.data)
    if status != SUCCESS:
        raise _pair_error(status, "contact_function", r12, q1, q2)
    return out


def overlap(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike, *,
            threads: int = 1) -> Union[int, NDArray[np.intc]]:
    """Do two ellipses overlap? A certified answer, faster than μ².

    Returns an int, −1, 0 or +1, not a bool: write ``overlap(...) < 0``
    for "they overlap".

    Parameters
    ----------
    r12 : array_like, shape (2,) or (..., 2)
        The centre-to-centre vector c2 − c1.
    q1, q2 : array_like, shape (3,) or (..., 3)
        The quadratic forms; arrays of pairs broadcast.
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    int, or numpy.ndarray of dtype numpy.intc and shape S
        −1 if they overlap (μ² < 1; also for coincident centres), +1 if
        they are disjoint, 0 if tangent to the resolution of double
        arithmetic (abs(μ² − 1) ≤ 4·ε).

    Raises
    ------
    ValueError, TypeError, Error
        As `contact_function`.
    """
    if _batch.is_batch(r12, q1, q2):
        pairs = _pairs("overlap", r12, q1, q2)
        result = np.empty(pairs.shape, dtype=np.intc)
        _batch._call(pairs, _lib.pw85_2d_overlap_batch, [result], threads)
        return result
    r12, q1, q2 = _pair(r12, q1, q2)
    result = ctypes.c_int(2)
    status = _lib.pw85_2d_overlap(r12.ctypes.data, q1.ctypes.data,
                                  q2.ctypes.data, ctypes.byref(result))
    if status != SUCCESS:
        raise _pair_error(status, "overlap", r12, q1, q2)
    return result.value


def contact_geometry(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                     out: Optional[_F64] = None, *,
                     threads: int = 1) -> _F64:
    """Return μ², λ, the contact point and the common normal.

    One search (that of `contact_function`: the same μ², bit for bit),
    then with s = Q(λ)⁻¹·r12: ``x − c1 = (1 − λ)·Q1·s``, the point where
    the ellipses scaled by μ touch, and ``n = s/‖s‖``, the normal there
    from ellipse 1 towards ellipse 2 (n·r12 > 0).

    Parameters
    ----------
    r12, q1, q2
        As for `contact_function` (arrays of pairs included).
    out : numpy.ndarray, shape (6,) or S + (6,), float64, optional
        Preallocated output, modified in place.
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    out : numpy.ndarray, shape (6,) or S + (6,)
        ``out[GEOM_MU2]`` = μ², ``out[GEOM_LAMBDA]`` = λ,
        ``out[GEOM_POINT:GEOM_POINT + 2]`` = x − c1,
        ``out[GEOM_NORMAL:GEOM_NORMAL + 2]`` = n. r12 = 0 gives μ² = 0,
        λ = ½, zero point and normal.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        As `contact_function`; with `~pypw85.ERANGE` for an overflow, out
        holds every output (some infinite).
    """
    if _batch.is_batch(r12, q1, q2):
        pairs = _pairs("contact_geometry", r12, q1, q2)
        out = _batch.output("out", out, pairs.shape + (GEOM_SIZE,))
        _batch._unaliased(pairs, out)
        _batch._call(pairs, _lib.pw85_2d_contact_geometry_batch, [out],
                     threads)
        return out
    r12, q1, q2 = _pair(r12, q1, q2)
    out = _output("out", out, GEOM_SIZE)
    r12, q1, q2 = _unaliased(out, r12, q1, q2)
    status = _lib.pw85_2d_contact_geometry(r12.ctypes.data, q1.ctypes.data,
                                           q2.ctypes.data, out.ctypes.data)
    if status != SUCCESS:
        raise _pair_error(status, "contact_geometry", r12, q1, q2)
    return out


def contact_derivatives(r12: ArrayLike, q1: ArrayLike, q2: ArrayLike,
                        geometry: Optional[_F64] = None,
                        d: Optional[_F64] = None, *,
                        threads: int = 1) -> Tuple[_F64, _F64]:
    """Return the contact geometry and the first derivatives of μ².

    By the envelope theorem, with s = Q(λ)⁻¹·r12: ∂μ²/∂r12 = 2λ(1−λ)·s;
    ∂μ²/∂θ1 = 2λ(1−λ)²·s × (Q1·s) and ∂μ²/∂θ2 = 2λ²(1−λ)·s × (Q2·s)
    (a × b = a0·b1 − a1·b0) for ellipse i turned by θᵢ about its centre;
    ∂μ²/∂q1 = −λ(1−λ)²·(s0², 2·s0·s1, s1²) and ∂μ²/∂q2 =
    −λ²(1−λ)·(the same), with respect to the stored entries. For a pair
    energy U(μ²), the force on ellipse 2 is −U′·∂μ²/∂r12 and the torque
    on ellipse i is −U′·∂μ²/∂θᵢ.

    Parameters
    ----------
    r12, q1, q2
        As for `contact_function` (arrays of pairs included).
    geometry : numpy.ndarray, shape (6,) or S + (6,), float64, optional
        Preallocated output for the geometry (as `contact_geometry`).
    d : numpy.ndarray, shape (10,) or S + (10,), float64, optional
        Preallocated output for the derivatives.
    threads : int, optional, keyword only
        As for `contact_function`.

    Returns
    -------
    geometry : numpy.ndarray, shape (6,) or S + (6,)
        As `contact_geometry`.
    d : numpy.ndarray, shape (10,) or S + (10,)
        ``d[DERIV_R12:DERIV_R12 + 2]``, ``d[DERIV_THETA1]``,
        ``d[DERIV_THETA2]``, ``d[DERIV_Q1:DERIV_Q1 + 3]``,
        ``d[DERIV_Q2:DERIV_Q2 + 3]``.

    Raises
    ------
    ValueError, TypeError, Error
        As `contact_geometry`.
    """
    if _batch.is_batch(r12, q1, q2):
        pairs = _pairs("contact_derivatives", r12, q1, q2)
        geometry = _batch.output("geometry", geometry,
                                 pairs.shape + (GEOM_SIZE,))
        d = _batch.output("d", d, pairs.shape + (DERIV_SIZE,))
        if np.may_share_memory(geometry, d):
            raise ValueError("geometry and d: expected separate arrays")
        _batch._unaliased(pairs, geometry, d)
        _batch._call(pairs, _lib.pw85_2d_contact_derivatives_batch,
                     [geometry, d], threads)
        return geometry, d
    r12, q1, q2 = _pair(r12, q1, q2)
    geometry = _output("geometry", geometry, GEOM_SIZE)
    d = _output("d", d, DERIV_SIZE)
    if np.may_share_memory(geometry, d):
        raise ValueError("geometry and d: expected separate arrays")
    r12, q1, q2 = _unaliased(geometry, r12, q1, q2)
    r12, q1, q2 = _unaliased(d, r12, q1, q2)
    status = _lib.pw85_2d_contact_derivatives(
        r12.ctypes.data, q1.ctypes.data, q2.ctypes.data,
        geometry.ctypes.data, d.ctypes.data)
    if status != SUCCESS:
        raise _pair_error(status, "contact_derivatives", r12, q1, q2)
    return geometry, d


def ellipse(a: ArrayLike, theta: ArrayLike, q: Optional[_F64] = None, *,
            threads: int = 1) -> _F64:
    """Return the quadratic form of an ellipse from its semi-axes and angle.

    Q = R(θ)·diag(a0², a1²)·R(θ)ᵀ, R(θ) = [[cos θ, −sin θ], [sin θ,
    cos θ]]: a[0] lies along (cos θ, sin θ), a[1] along (−sin θ, cos θ).
    Each entry is computed in double-double arithmetic from cos θ and
    sin θ and rounded once (pw85_2d.h gives the bound). On arrays (a of
    shape (..., 2), theta of shape (...), leading axes broadcast
    together), one form per item, in one call of
    ``pw85_2d_ellipse_batch``.

    Parameters
    ----------
    a : array_like, shape (2,) or (..., 2)
        The semi-axes (lengths, each > 0).
    theta : float or array_like, shape (...)
        The angle from the x axis to the axis of a[0] (radians,
        counter-clockwise; any finite value).
    q : numpy.ndarray, shape (3,) or (..., 3), float64, optional
        Preallocated output, modified in place.
    threads : int, optional, keyword only
        Arrays only: as in `contact_function`.

    Returns
    -------
    q : numpy.ndarray, shape (3,) or (..., 3)
        (Q00, Q01, Q11), a squared length.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `~pypw85.EDOM` (NaN or infinite input), `~pypw85.EINVAL` (a
        semi-axis not > 0), `~pypw85.ERANGE` (aₘ² overflows or
        underflows). q untouched (on arrays: that item's q; the error
        names the first failing item).
    """
    if _batch.is_batch_of((a, 1), (theta, 0)):
        items = _batch.Items(_WHERE + "ellipse",
                             [("a", a, (DIM,)), ("theta", theta, ())],
                             "item")
        q = _batch.output("q", q, items.shape + (SYM,))
        _batch._unaliased(items, q)
        _batch._call(items, _lib.pw85_2d_ellipse_batch, [q], threads)
        return q
    a = _vector("a", a, DIM)
    theta = _real("theta", theta)
    q = _output("q", q, SYM)
    (a,) = _unaliased(q, a)
    status = _lib.pw85_2d_ellipse(a.ctypes.data, theta, q.ctypes.data)
    if status != SUCCESS:
        raise Error(status, _WHERE + "ellipse", "a = %r, theta = %r"
                    % (a, theta))
    return q


def principal_axes(q: ArrayLike, *,
                   threads: int = 1) -> Tuple[_F64, Union[float, _F64]]:
    """Return the semi-axes and the angle of an ellipse: the inverse of
    `ellipse`.

    θ = ½·atan2(2·Q01, Q00 − Q11), the direction of the larger semi-axis;
    each semi-axis from the Rayleigh quotient of its direction in
    double-double arithmetic (accurate for the small axis of a needle;
    pw85_2d.h). On an array of forms (shape (..., 3)), one call of
    ``pw85_2d_principal_axes_batch``.

    Parameters
    ----------
    q : array_like, shape (3,) or (..., 3)
        The quadratic form (Q00, Q01, Q11).
    threads : int, optional, keyword only
        Arrays only: as in `contact_function`.

    Returns
    -------
    a : numpy.ndarray, shape (2,) or (..., 2)
        The semi-axes, a[0] ≥ a[1] > 0.
    theta : float, or numpy.ndarray of shape (...)
        The angle from the x axis to the axis of a[0], in (−π/2, π/2]
        (0 for a circle).

    Raises
    ------
    ValueError, TypeError
        If q has the wrong shape or type.
    Error
        `~pypw85.EDOM`, `~pypw85.ENOTPOSDEF`, `~pypw85.ERANGE` (see
        pw85_2d.h); on arrays, for the first failing item.
    """
    if _batch.is_batch_of((q, 1)):
        items = _batch.Items(_WHERE + "principal_axes", [("q", q, (SYM,))],
                             "item")
        a = np.empty(items.shape + (DIM,))
        theta = np.empty(items.shape)
        _batch._call(items, _lib.pw85_2d_principal_axes_batch, [a, theta],
                     threads)
        return a, theta
    q = _vector("q", q, SYM)
    a = np.empty(DIM)
    theta = ctypes.c_double(0.0)
    status = _lib.pw85_2d_principal_axes(q.ctypes.data, a.ctypes.data,
                                         ctypes.byref(theta))
    if status != SUCCESS:
        raise Error(status, _WHERE + "principal_axes", "q = %r" % q)
    return a, theta.value


def _posdef(q):
    """The rule of pw85_2d.h: Q00 > 0 and Q00·Q11 − Q01² > 0 on the exact
    values of the three doubles (for the messages of `Index`)."""
    q00, q01, q11 = (fractions.Fraction(float(x)) for x in q)
    return q00 > 0 and q00 * q11 - q01 * q01 > 0


class Index(_Index):
    """A spatial index of ellipses (``pw85_2d_index``), in an open plane or
    a periodic rectangle: `pypw85.index.Index` for ellipses.

    Ids, containers, errors, threads and the order of the results are
    those of `pypw85.index.Index`; centres are of shape ``(n, 2)``, forms
    ``(n, 3)`` (Q00, Q01, Q11), image shifts ``(m, 2)`` (the image of
    ellipse j is at ``c_j + shift * box``); `Index.energy` returns forces
    ``(n, 2)`` and torques ``(n,)``, ∂/∂θ (``pw85_2d_index_energy``).

    Parameters
    ----------
    box : array_like of 2 floats, optional
        The sides of a periodic rectangle (each > 0 and at most 2⁹⁹²); None
        (default) for an open plane.

    Raises
    ------
    Error
        `EDOM` if a side is not finite, `EINVAL` if one is not > 0 or is
        above 2⁹⁹².
    """

    _dim = _Dimension(2, 3, 1, "pw85_2d_index_", (0, 2), _posdef,
                      "ellipse", "rectangle", "pypw85.d2.Index")


_D2 = _Shape(2, 3, (), "pw85_2d_pack", math.pi, "ellipse", "rectangle")


class Packing(typing.NamedTuple):
    """The result of `pack` (a named tuple): `pypw85.Packing` for ellipses.

    Parameters
    ----------
    box : ndarray, shape (2,)
        The sides of the periodic rectangle.
    centres : ndarray, shape (n, 2)
        The centres, in [0, L_k).
    angles : ndarray, shape (n,)
        The angles θ (radians, in [−π, π]): semi-axis 0 along
        (cos θ, sin θ).
    forms : ndarray, shape (n, 3)
        The quadratic forms (Q00, Q01, Q11): `ellipse` of the semi-axes
        and angles, bit for bit.
    phi : float
        The packing fraction of the result, Σπ·a0·a1 / (L0·L1).
    outcome : str
        ``"target"``, ``"limit"``, ``"jammed"`` or ``"cancelled"``, as
        `pypw85.pack`.

    Returns
    -------
    Packing
        (As a named tuple.) No pair of a packing overlaps.

    Raises
    ------
    TypeError
        With the wrong number of fields.
    """
    box: np.ndarray
    centres: np.ndarray
    angles: np.ndarray
    forms: np.ndarray
    phi: float
    outcome: str


pack = _packer(_D2, Packing, (1.0, 1.0), (1.0, 0.0), __name__,
               """Pack ellipses in a periodic rectangle, no pair overlapping
(``pw85_2d_pack``): `pypw85.pack` for ellipses, the same code.

Parameters
----------
semi_axes : array_like, shape (n, 2)
    The semi-axes of each ellipse (> 0): any mix of sizes and shapes.
target : float
    The packing fraction Σπ·a0·a1 / (L0·L1) to reach, in (0, 1).
seed : int
    The seed of the random placement, 0 to 2⁶⁴ − 1. The same inputs
    and seed give the same packing, bit for bit, for any ``threads``.
aspect : 2 floats
    The rectangle's sides are proportional to these (a square by
    default).
orientation : {"isotropic", "aligned"}
    Uniform random angles, or the largest semi-axis of every ellipse
    along ``axis`` (the ellipses then never turn).
axis : 2 floats
    The direction of ``"aligned"`` in the plane (finite, not zero);
    not read with ``"isotropic"``, as pw85_2d_pack.
threads, time_limit, step_limit, progress, progress_every
    As `pypw85.pack` (``energy`` of the progress dict is per ellipse).

Returns
-------
Packing
    ``box``, ``centres``, ``angles``, ``forms``, ``phi`` and
    ``outcome``. Whatever the outcome, no pair overlaps (checked by the
    all-pairs query of the index of ellipses before the library
    returns).

Raises
------
Error, TypeError, ValueError
    As `pypw85.pack`, with the side rule of the rectangle.
    """)
