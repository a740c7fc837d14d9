# SPDX-License-Identifier: BSD-3-Clause
"""`pack`: N ellipsoids in a periodic box with no overlapping pair
(``pw85_pack.h``, whose description is the contract: the method, the
certification, determinism); `pypw85.d2.pack`, N ellipses in a periodic
rectangle (``pw85_2d_pack.h``), through the same code (`_pack`)."""

from __future__ import annotations

import ctypes
import math
import typing

import numpy as np

if typing.TYPE_CHECKING:
    from typing import Callable, Optional, Sequence, Type
    from numpy.typing import ArrayLike

from ._constants import EDOM, EINVAL, ERANGE
from ._convert import real as _real, reals as _real_values
from ._errors import Error
from ._libpw85 import lib as _lib
from ._symbols import declare as _declare

__all__ = ["pack", "Packing"]


class _Progress(ctypes.Structure):
    _fields_ = [("phi", ctypes.c_double), ("phi_trial", ctypes.c_double),
                ("energy", ctypes.c_double), ("elapsed", ctypes.c_double),
                ("steps", ctypes.c_size_t), ("pairs", ctypes.c_size_t)]


_CALLBACK = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.POINTER(_Progress),
                             ctypes.c_void_p)


class _Options(ctypes.Structure):
    _fields_ = [("size", ctypes.c_size_t), ("target", ctypes.c_double),
                ("seed", ctypes.c_uint64), ("aspect", ctypes.c_double * 3),
                ("orientation", ctypes.c_int),
                ("axis", ctypes.c_double * 3), ("threads", ctypes.c_int),
                ("time_limit", ctypes.c_double),
                ("step_limit", ctypes.c_size_t),
                ("progress_every", ctypes.c_size_t),
                ("progress", _CALLBACK), ("progress_data", ctypes.c_void_p)]


_P = ctypes.c_void_p
_declare(_lib, {
    "pw85_pack_options_init": (None, [ctypes.POINTER(_Options)]),
    "pw85_pack": (ctypes.c_int, [ctypes.c_size_t, _P,
                                 ctypes.POINTER(_Options), _P, _P, _P, _P,
                                 ctypes.POINTER(ctypes.c_double),
                                 ctypes.POINTER(ctypes.c_int)]),
})

class _Shape(typing.NamedTuple):
    """What differs between the packer of ellipsoids and that of ellipses:
    the sizes (of a semi-axes row, a form, an orientation row: () for one
    angle), the C function, the volume of a shape over the product of its
    semi-axes, the words of the messages."""
    dim: int
    sym: int
    orientation: tuple
    function: str
    measure: float
    noun: str
    domain: str


_D3 = _Shape(3, 6, (4,), "pw85_pack", 4.0 / 3.0 * math.pi, "ellipsoid",
             "box")

_ORIENTATIONS = {"isotropic": 0, "aligned": 1}
_OUTCOMES = ("target", "limit", "jammed", "cancelled")
# The side rule of pw85_pack.h: 2·a_max·(1 + 2⁻⁹) < L_k at the target.
_SIDE_MARGIN = 1.0 + 2.0**-9


class Packing(typing.NamedTuple):
    """The result of `pack` (a named tuple).

    Parameters
    ----------
    box : ndarray, shape (3,)
        The sides of the periodic box.
    centres : ndarray, shape (n, 3)
        The centres, in [0, L_k).
    quaternions : ndarray, shape (n, 4)
        Unit quaternions (w, x, y, z): semi-axis j along R(p)·e_j.
    forms : ndarray, shape (n, 6)
        The quadratic forms: `ellipsoid_quaternion` of the semi-axes and
        quaternions, bit for bit.
    phi : float
        The packing fraction of the result.
    outcome : str
        ``"target"`` (reached), ``"limit"`` (time or step limit),
        ``"jammed"`` (the target is beyond jamming: the densest certified
        packing found) or ``"cancelled"`` (by the progress callback).

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
    quaternions: np.ndarray
    forms: np.ndarray
    phi: float
    outcome: str


def _positive(name, value, allow_zero=False):
    try:
        v = _real(name, value)
    except TypeError:
        raise TypeError("pack: %s must be a real number, got %r"
                        % (name, value)) from None
    except ValueError as e:
        raise ValueError("pack: %s" % e) from None
    if not math.isfinite(v):
        raise Error(EDOM, "pack", "%s = %r is not finite" % (name, v))
    if not (v >= 0 if allow_zero else v > 0):
        raise Error(EINVAL, "pack", "%s = %r is not %s" %
                    (name, v, "≥ 0" if allow_zero else "> 0"))
    return v


def _packer(sh, result, aspect, axis, module, doc):
    """The public function that packs the shapes of sh into a result (a
    NamedTuple class): its signature written once for both dimensions,
    with the defaults of aspect and axis of the dimension."""
    def pack(semi_axes: ArrayLike, target: float = 0.5, *, seed: int = 0,
             aspect: Sequence[float] = aspect,
             orientation: str = "isotropic",
             axis: Sequence[float] = axis, threads: int = 1,
             time_limit: Optional[float] = None,
             step_limit: Optional[int] = None,
             progress: Optional[Callable[[dict], object]] = None,
             progress_every: int = 100):
        return result(*_pack(sh, semi_axes, target, seed, aspect,
                             orientation, axis, threads, time_limit,
                             step_limit, progress, progress_every))
    pack.__annotations__["return"] = result.__name__
    pack.__module__ = module
    pack.__qualname__ = "pack"
    pack.__doc__ = doc
    return pack


pack = _packer(_D3, Packing, (1.0, 1.0, 1.0), (0.0, 0.0, 1.0), __name__,
               """Pack ellipsoids in a periodic box, no pair overlapping
(``pw85_pack``; its header describes the method and its sources).

Parameters
----------
semi_axes : array_like, shape (n, 3)
    The semi-axes of each ellipsoid (> 0): any mix of sizes and shapes
    (``np.tile(shape, (n, 1))`` for n of one shape).
target : float
    The packing fraction to reach, in (0, 1).
seed : int
    The seed of the random placement, 0 to 2⁶⁴ − 1. The same inputs and
    seed give the same packing, bit for bit, for any ``threads``.
aspect : 3 floats
    The box's sides are proportional to these (cube by default).
orientation : {"isotropic", "aligned"}
    Uniform random orientations, or the largest semi-axis of every
    ellipsoid along ``axis`` (fibres; they then turn about it only).
axis : 3 floats
    The direction of ``"aligned"`` (normalised; not zero).
threads : int
    OpenMP threads (≥ 1).
time_limit : float, optional
    Seconds of wall clock; then the outcome is ``"limit"``.
step_limit : int, optional
    Steps of the minimiser; then the outcome is ``"limit"``.
progress : callable, optional
    Called every ``progress_every`` steps with a dict: ``phi`` (the
    densest certified packing fraction so far), ``phi_trial`` (the one
    being relaxed), ``energy`` (overlap energy per ellipsoid),
    ``elapsed`` (seconds), ``steps``, ``pairs`` (overlapping pairs).
    A true return value stops the run (outcome ``"cancelled"``); an
    exception stops it and is raised again. Called from Python: about
    a microsecond per call, negligible at 100 steps.
progress_every : int
    Steps between calls of ``progress`` (≥ 1).

Returns
-------
Packing
    ``box``, ``centres``, ``quaternions``, ``forms``, ``phi`` and
    ``outcome`` (``"target"``, ``"limit"``, ``"jammed"`` or
    ``"cancelled"``). Whatever the outcome, no pair overlaps (checked
    by the all-pairs query before the library returns).

Raises
------
Error
    A status of the library, with a message naming the argument: `EDOM`
    for a value not finite, `EINVAL` for n = 0, a semi-axis not > 0, a
    target not in (0, 1), an aspect not > 0, an unknown orientation, a
    zero axis, threads < 1, a limit not > 0, or a box too small at the
    target for the largest ellipsoid (decided by the library, as
    ``pw85_pack.h`` states the rule); `ERANGE` for semi-axes spanning
    more than 2⁴⁰.
TypeError, ValueError
    An argument of the wrong type or shape (``threads``,
    ``step_limit`` and ``progress_every`` are ints), or a count beyond
    the C type that holds it (``threads`` above 2³¹ − 1, a limit above
    2⁶⁴ − 1).
    """)


def _pack(sh, semi_axes, target, seed, aspect, orientation, axis, threads,
          time_limit, step_limit, progress, progress_every):
    """`pack` (sh = _D3) and `pypw85.d2.pack`: the fields of the result."""
    d = sh.dim
    a = _real_values("pack: semi_axes", semi_axes,
                     "an array of shape (n, %d)" % d)
    if a.ndim != 2 or a.shape[1] != d:
        raise ValueError("pack: semi_axes must have shape (n, %d), got %s"
                         % (d, a.shape))
    a = np.ascontiguousarray(a, dtype=np.float64)
    n = a.shape[0]
    if n == 0:
        raise Error(EINVAL, "pack", "semi_axes holds no %s (n = 0)"
                    % sh.noun)
    if not np.all(np.isfinite(a)):
        k = int(np.argmin(np.isfinite(a).all(axis=1)))
        raise Error(EDOM, "pack", "semi_axes[%d] = %s is not finite"
                    % (k, a[k]))
    if not np.all(a > 0):
        k = int(np.argmin((a > 0).all(axis=1)))
        raise Error(EINVAL, "pack", "semi_axes[%d] = %s: a semi-axis is "
                    "not > 0" % (k, a[k]))
    amin, amax = float(a.min()), float(a.max())
    if amax / amin > 2.0**40:
        raise Error(ERANGE, "pack", "semi_axes span %.6g to %.6g, more than "
                    "2⁴⁰" % (amin, amax))
    target = _positive("target", target)
    if not target < 1:
        raise Error(EINVAL, "pack", "target = %r is not < 1" % target)
    if orientation not in _ORIENTATIONS:
        raise Error(EINVAL, "pack", "orientation = %r is not one of %s"
                    % (orientation, ", ".join(map(repr, _ORIENTATIONS))))
    asp = [_positive("aspect[%d]" % k, x) for k, x in
           enumerate(_reals("aspect", aspect, d))]
    ax = _reals("axis", axis, d)
    # Ellipses read the axis with "aligned" only (pw85_2d_pack.h).
    if d == 3 or orientation == "aligned":
        for k, x in enumerate(ax):
            if not math.isfinite(x):
                raise Error(EDOM, "pack", "axis[%d] = %r is not finite"
                            % (k, x))
        if not any(ax):
            raise Error(EINVAL, "pack", "axis = (%s) has no direction"
                        % ", ".join(["0"] * d))
    threads = _count("threads", threads, 1, 2**31 - 1)
    limit = 0.0 if time_limit is None else _positive("time_limit",
                                                     time_limit)
    steps = 0 if step_limit is None else _count("step_limit", step_limit,
                                                 1, 2**64 - 1)
    every = _count("progress_every", progress_every, 1, 2**64 - 1)

    opts = _Options()
    _lib.pw85_pack_options_init(ctypes.byref(opts))
    opts.target = target
    opts.seed = _count("seed", seed, 0, 2**64 - 1)
    opts.aspect[:d] = asp
    opts.orientation = _ORIENTATIONS[orientation]
    opts.axis[:d] = ax
    opts.threads = threads
    opts.time_limit = limit
    opts.step_limit = steps
    opts.progress_every = every
    raised = []
    if progress is not None:
        if not callable(progress):
            raise TypeError("pack: progress must be callable, got %s"
                            % type(progress).__name__)

        def call(p, data):
            try:
                x = p.contents
                stop = progress({"phi": x.phi, "phi_trial": x.phi_trial,
                                 "energy": x.energy, "elapsed": x.elapsed,
                                 "steps": x.steps, "pairs": x.pairs})
                return 1 if stop else 0
            except BaseException as exc:  # raised again below
                raised.append(exc)
                return 1
        opts.progress = _CALLBACK(call)
    box = np.empty(d)
    centres = np.empty((n, d))
    orientations = np.empty((n,) + sh.orientation)
    forms = np.empty((n, sh.sym))
    phi = ctypes.c_double()
    outcome = ctypes.c_int()
    code = getattr(_lib, sh.function)(
        n, a.ctypes.data, ctypes.byref(opts), box.ctypes.data,
        centres.ctypes.data, orientations.ctypes.data, forms.ctypes.data,
        ctypes.byref(phi), ctypes.byref(outcome))
    if raised:
        raise raised[0]
    if code == EINVAL:
        # Every other rule of PW85_EINVAL was checked above: the side rule
        # (decided by the library alone, whose arithmetic is the rule),
        # with the numbers.
        volume = sh.measure * float(np.sum(np.prod(a, axis=1)))
        s = (volume / (target * math.prod(asp))) ** (1.0 / d)
        k = int(np.argmin(np.asarray(asp)))
        raise Error(EINVAL, "pack", "the %s at target %.6g has side "
                    "L_%d = %.6g, not above 2·a_max·(1 + 2⁻⁹) = %.6g "
                    "(the largest semi-axis, %.6g, must fit: lower the "
                    "target or change the aspect)"
                    % (sh.domain, target, k, asp[k] * s,
                       2 * amax * _SIDE_MARGIN, amax))
    if code != 0:
        raise Error(code, "pack")
    return (box, centres, orientations, forms, phi.value,
            _OUTCOMES[outcome.value])


def _count(name, x, lo, hi):
    """x as an int in [lo, hi] (a C int or size_t: never wrapped), or
    raise naming it."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x,
                                                         (int, np.integer)):
        raise TypeError("pack: %s must be an int, got %r" % (name, x))
    x = int(x)
    if x < lo:
        raise Error(EINVAL, "pack", "%s = %d is not ≥ %d" % (name, x, lo))
    if x > hi:
        raise ValueError("pack: %s = %d is above %d" % (name, x, hi))
    return x


def _reals(name, x, d):
    """x as a list of d floats, or raise naming it."""
    try:
        if isinstance(x, (str, bytes, dict, set)):  # iterable, not numbers
            raise TypeError(name)
        v = [_real(name, y) for y in x]
    except TypeError:
        raise TypeError("pack: %s must be %d real numbers, got %r"
                        % (name, d, x)) from None
    except ValueError as e:
        raise ValueError("pack: %s" % e) from None
    if len(v) != d:
        raise ValueError("pack: %s must be %d real numbers, got %d"
                         % (name, d, len(v)))
    return v
