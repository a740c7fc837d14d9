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
Outputs are returned as new ``float64`` arrays, or written in place into a
preallocated array passed by the caller, which must then be a C-contiguous,
writeable ``numpy.ndarray`` of dtype ``float64`` and of the exact shape
(anything else raises, nothing is converted silently).

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
function is reentrant, so threads calling pypw85 run in parallel. Do not
share a preallocated output array between threads.

The only run-time dependency is NumPy. Released under the BSD 3-Clause
licence.
"""

import ctypes
import ctypes.util
import numbers
import os
import sys
import warnings

import numpy as np

try:
    from . import _paths
except ImportError:  # Not installed by meson (e.g. run from the sources).
    _paths = None

__all__ = [
    "DIM", "SYM", "LAMBDA_ATOL", "MAX_ITER", "NR_ITER",
    "SUCCESS", "EFAULT", "EDOM", "ENOTPOSDEF", "ERANGE", "ENOMEM", "ENOCONV",
    "Error", "contact_function", "f", "f_neg", "overlap", "spheroid",
]

#: The dimension of the physical space.
DIM = 3
#: The number of independent entries of a symmetric DIM×DIM matrix.
SYM = 6
#: The absolute tolerance on λ at which Brent's method stops (in
#: `contact_function`).
LAMBDA_ATOL = 1e-6
#: The maximum number of iterations of Brent's method (in
#: `contact_function`).
MAX_ITER = 25
#: The maximum number of Newton-Raphson steps that refine Brent's λ (in
#: `contact_function`).
NR_ITER = 3

# The status codes of pw85.h (values never change once released).
#: Success.
SUCCESS = 0
#: A pointer argument is NULL (cannot happen through pypw85).
EFAULT = 1
#: An input is NaN or infinite.
EDOM = 2
#: A quadratic form is not positive definite.
ENOTPOSDEF = 3
#: A result (or the dynamic range of the input) exceeds the range of a
#: double.
ERANGE = 4
#: The minimiser needs more working memory than pw85 reserves (not
#: expected).
ENOMEM = 5
#: An iterative method did not converge (the legacy contact functions).
ENOCONV = 6

_STATUS_NAMES = {
    SUCCESS: "PW85_SUCCESS",
    EFAULT: "PW85_EFAULT",
    EDOM: "PW85_EDOM",
    ENOTPOSDEF: "PW85_ENOTPOSDEF",
    ERANGE: "PW85_ERANGE",
    ENOMEM: "PW85_ENOMEM",
    ENOCONV: "PW85_ENOCONV",
}

# Messages for codes that the pw85_strerror() of an older libpw85.so.2 may
# not name (PW85_ENOCONV appeared in 2.1.0).
_FALLBACK_MESSAGES = {6: "an iterative method did not converge"}

# The ABI this module is written for: the soname's major version
# (libpw85.so.2). Change it only together with the library's soversion.
_ABI_MAJOR = 2

# Arrays cross into C as the address of a validated, C-contiguous float64
# buffer (`double *` in pw85.h). c_void_p keeps each call cheap: ctypes
# converts the int address without calling back into Python.
_DOUBLE_P = ctypes.c_void_p


def _soname(name, major):
    """The file name the dynamic loader looks for (e.g. libpw85.so.2)."""
    if sys.platform == "darwin":
        return "lib%s.%d.dylib" % (name, major)
    if sys.platform in ("win32", "cygwin"):
        return "%s%s-%d.dll" % ("cyg" if sys.platform == "cygwin" else "lib",
                                name, major)
    return "lib%s.so.%d" % (name, major)


def _load_library(name, env_var, installed, symbols, check=None):
    """dlopen lib<name> from the first place that works (see the module doc).

    Returns (the ctypes.CDLL, the path or name it was loaded from). Raises
    ImportError listing every place tried and why each one failed.
    """
    soname = _soname(name, _ABI_MAJOR)
    candidates = []  # (where, path or None, reason if None)
    env_path = os.environ.get(env_var)
    if env_path:
        candidates.append(("$%s = %%r" % env_var, env_path, None))
    else:
        candidates.append(("$%s" % env_var, None, "not set"))
    if _paths is None:
        candidates.append(("installed path", None,
                           "none recorded (pypw85/_paths.py is absent: this "
                           "copy of pypw85 was not installed by meson)"))
    elif installed is None:
        candidates.append(("installed path", None,
                           "none recorded (lib%s was not built with this "
                           "pypw85)" % name))
    else:
        candidates.append(("installed path %r (recorded in pypw85/_paths.py)",
                           installed, None))
    candidates.append(("system search for %r (LD_LIBRARY_PATH, "
                       "/etc/ld.so.cache, default directories)", soname, None))

    tried = []

    def attempt(where, path, reason):
        if path is None:
            tried.append("%s: %s" % (where, reason))
            return None
        try:
            lib = ctypes.CDLL(path)
            missing = [s for s in symbols if not hasattr(lib, s)]
            if missing:
                raise OSError("not lib%s: no symbol %s"
                              % (name, ", ".join(missing)))
            if check is not None:
                check(lib)
        except OSError as exc:
            tried.append("%s: %s" % (where % path, exc))
            return None
        if env_path and path != env_path:
            warnings.warn("pypw85: could not load $%s; loaded %r instead (%s)"
                          % (env_var, path, tried[0]), RuntimeWarning,
                          stacklevel=4)
        return lib

    for where, path, reason in candidates:
        lib = attempt(where, path, reason)
        if lib is not None:
            return lib, path
    # Last resort, looked up only when needed (it may run ldconfig or gcc).
    found = ctypes.util.find_library(name)
    if found is None:
        tried.append("ctypes.util.find_library(%r): not found" % name)
    elif found != soname:
        lib = attempt("ctypes.util.find_library(%r) = %%r" % name, found,
                      None)
        if lib is not None:
            return lib, found
    raise ImportError(
        "pypw85: cannot load lib%s (ABI %d, %s). Places tried, in order:\n"
        "%s\nSet %s to the full path of %s, or reinstall pw85 with "
        "meson (which records where it puts the library)."
        % (name, _ABI_MAJOR, soname,
           "\n".join("  %d. %s" % (k + 1, t) for k, t in enumerate(tried)),
           env_var, soname), name="pypw85")


def _check_libpw85(lib):
    """Reject a library whose pw85_version() is not of our ABI."""
    lib.pw85_version.argtypes = []
    lib.pw85_version.restype = ctypes.c_char_p
    version = lib.pw85_version().decode("ascii", "replace")
    if version.split(".")[0] != str(_ABI_MAJOR):
        raise OSError("pw85_version() is %s, not %d.x" % (version, _ABI_MAJOR))


_SYMBOLS = {
    # name: (restype, argtypes), as declared in pw85.h.
    "pw85_strerror": (ctypes.c_char_p, [ctypes.c_int]),
    "pw85_version": (ctypes.c_char_p, []),
    "pw85__cholesky_decomp": (None, [_DOUBLE_P, _DOUBLE_P]),
    "pw85__cholesky_solve": (None, [_DOUBLE_P, _DOUBLE_P, _DOUBLE_P]),
    "pw85_spheroid": (None, [ctypes.c_double, ctypes.c_double, _DOUBLE_P,
                             _DOUBLE_P]),
    "pw85_f_neg": (ctypes.c_double, [ctypes.c_double, _DOUBLE_P]),
    "pw85__residual": (None, [ctypes.c_double, _DOUBLE_P, _DOUBLE_P,
                              _DOUBLE_P, _DOUBLE_P]),
    "pw85_contact_function": (ctypes.c_int, [_DOUBLE_P, _DOUBLE_P,
                                             _DOUBLE_P, _DOUBLE_P]),
    "pw85_overlap": (ctypes.c_int, [_DOUBLE_P, _DOUBLE_P, _DOUBLE_P,
                                    ctypes.POINTER(ctypes.c_int)]),
}


def _declare(lib, table):
    """Set restype and argtypes of every function of table on lib."""
    for symbol, (restype, argtypes) in table.items():
        function = getattr(lib, symbol)
        function.restype = restype
        function.argtypes = argtypes


_lib, _library_path = _load_library(
    "pw85", "PW85_LIBRARY", getattr(_paths, "LIBPW85", None), _SYMBOLS,
    _check_libpw85)
_declare(_lib, _SYMBOLS)

_strerror = _lib.pw85_strerror
_c_cholesky_decomp = _lib.pw85__cholesky_decomp
_c_cholesky_solve = _lib.pw85__cholesky_solve
_c_spheroid = _lib.pw85_spheroid
_c_f_neg = _lib.pw85_f_neg
_c_residual = _lib.pw85__residual
_c_contact_function = _lib.pw85_contact_function
_c_overlap = _lib.pw85_overlap

#: The version of the libpw85 actually loaded ("MAJOR.MINOR.PATCH", from
#: its pw85_version()).
__version__ = _lib.pw85_version().decode("ascii")


class Error(ValueError):
    """An input rejected by pw85, or a result it cannot represent.

    Parameters
    ----------
    status : int
        A pw85 status code (`EDOM`, `ENOTPOSDEF`, `ERANGE`, ...).
    where : str, optional
        The function that failed.
    detail : str, optional
        What exactly was wrong.

    Attributes
    ----------
    status : int
        The status code.
    strerror : str
        The library's message for it (``pw85_strerror(status)``).
    """

    def __init__(self, status, where=None, detail=None):
        super().__init__(status, where, detail)
        self.status = status
        self.strerror = _strerror(status).decode("utf-8", "replace")
        if status in _FALLBACK_MESSAGES and \
                self.strerror.startswith("unknown"):
            self.strerror = _FALLBACK_MESSAGES[status]
        self.where = where
        self.detail = detail

    def __str__(self):
        text = "%s (%s)" % (self.strerror,
                            _STATUS_NAMES.get(self.status,
                                              "status %d" % self.status))
        if self.detail:
            text += ": " + self.detail
        if self.where:
            text = self.where + ": " + text
        return text


# ---------------------------------------------------------------------------
# Argument checking, shared with pypw85.legacy.

def _vector(name, x, n):
    """x as a C-contiguous float64 array of shape (n,), or raise."""
    if (type(x) is np.ndarray and x.dtype == np.float64 and x.shape == (n,)
            and x.flags.c_contiguous):
        return x
    try:
        a = np.asarray(x)
    except (TypeError, ValueError) as exc:
        raise ValueError("%s: expected an array of shape (%d,), got %s (%s)"
                         % (name, n, type(x).__name__, exc)) from None
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected real numbers (float64), got an array "
                        "of dtype %s" % (name, a.dtype))
    if a.shape != (n,):
        raise ValueError("%s: expected shape (%d,), got %s"
                         % (name, n, a.shape))
    return np.ascontiguousarray(a, dtype=np.float64)


def _output(name, out, n):
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


def _unaliased(out, *inputs):
    """The inputs, each copied if it shares memory with out."""
    return [np.array(x) if np.may_share_memory(out, x) else x for x in inputs]


def _real(name, x):
    """x as a Python float, if x is a real scalar; else raise TypeError."""
    if isinstance(x, numbers.Real):
        return float(x)
    if isinstance(x, np.ndarray) and x.ndim == 0 and x.dtype.kind in "iuf":
        return float(x)
    raise TypeError("%s: expected a real number, got %s"
                    % (name, type(x).__name__))


def _check_finite(where, **named):
    """Raise Error(EDOM) naming the first non-finite argument."""
    for name, value in named.items():
        if not np.isfinite(value).all():
            raise Error(EDOM, where, "%s = %r" % (name, value))


# ---------------------------------------------------------------------------
# The new API (seed, chapter 8.1).

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
    if l[0] != l[0]:
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


def spheroid(a, c, n, q=None):
    """Return the quadratic form of a spheroid: Q = a²·I + (c² − a²)·n·nᵀ.

    Parameters
    ----------
    a : float
        The equatorial radius (a length).
    c : float
        The polar radius (a length, same unit as a).
    n : array_like, shape (3,)
        The direction of the axis of revolution, a unit vector (not
        normalised here: a non-unit n gives the formula's Q, which is not a
        spheroid).
    q : numpy.ndarray, shape (6,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    q : numpy.ndarray, shape (6,)
        The symmetric matrix Q (a squared length; upper triangle, row by
        row).

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if a, c or an entry of n is not finite (q untouched);
        `ERANGE` if an entry of Q overflows (q then holds it).
    """
    a = _real("a", a)
    c = _real("c", c)
    n = _vector("n", n, DIM)
    q = _output("q", q, SYM)
    (n,) = _unaliased(q, n)
    _check_finite("spheroid", a=a, c=c, n=n)
    _c_spheroid(a, c, n.ctypes.data, q.ctypes.data)
    if not np.isfinite(q).all():
        raise Error(ERANGE, "spheroid", "q = %r" % q)
    return q


def _f_neg(where, lambda_, r12, q1, q2):
    """−f(λ) through pw85_f_neg, with errors raised (see f)."""
    lambda_ = _real("lambda_", lambda_)
    r12 = _vector("r12", r12, DIM)
    q1 = _vector("q1", q1, SYM)
    q2 = _vector("q2", q2, SYM)
    params = np.concatenate((r12, q1, q2))
    value = _c_f_neg(lambda_, params.ctypes.data)
    if value - value != 0.0:  # NaN or infinite.
        _check_finite(where, lambda_=lambda_, r12=r12, q1=q1, q2=q2)
        if value != value:
            raise Error(ENOTPOSDEF, where, "Q(λ) = (1−λ)·Q1 + λ·Q2 with "
                        "λ = %r: q1 = %r, q2 = %r" % (lambda_, q1, q2))
        raise Error(ERANGE, where, "f(%r) overflows" % lambda_)
    return value


def f(lambda_, r12, q1, q2):
    """Return f(λ) = λ(1−λ)·r12ᵀ·Q⁻¹·r12, with Q = (1−λ)·Q1 + λ·Q2.

    μ² is the maximum of f over [0, 1] (see `contact_function`). f is
    evaluated through a Cholesky factorisation of Q (seed, chapter 4.1), in
    plain double arithmetic: |r12|² and the entries of Q1, Q2 must stay
    between about 1e-300 and 1e300.

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


def f_neg(lambda_, r12, q1, q2):
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

    Internal (exposed for testing; the residual of the Newton-Raphson
    refinement, seed chapter 5); may change without notice.

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


def contact_function(r12, q1, q2, out=None):
    """Return the contact function μ² of two ellipsoids and its maximiser λ.

    μ² = max over λ in [0, 1] of λ(1−λ)·r12ᵀ·[(1−λ)·Q1 + λ·Q2]⁻¹·r12
    (seed, chapter 3). μ is the common factor by which both ellipsoids must
    be scaled, their centres fixed, to be externally tangent: μ² < 1 means
    they overlap, μ² > 1 that they are disjoint. λ is found by Brent's
    method to `LAMBDA_ATOL`, then refined by Newton-Raphson steps.

    Parameters
    ----------
    r12 : array_like, shape (3,)
        The centre-to-centre vector c2 − c1 (any finite vector; r12 = 0
        gives μ² = 0, λ = ½).
    q1, q2 : array_like, shape (6,)
        The quadratic forms of the two ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.
        μ² is invariant under r12 → t·r12, Q → t²·Q; any finite scale is
        accepted.
    out : numpy.ndarray, shape (2,), float64, optional
        Preallocated output, modified in place. A new array if None.

    Returns
    -------
    out : numpy.ndarray, shape (2,)
        ``out[0] = μ²`` (dimensionless, ≥ 0) and ``out[1] = λ`` in [0, 1];
        ``mu2, lambda_ = contact_function(r12, q1, q2)`` unpacks it.

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        `EDOM` if an input is NaN or infinite; `ENOTPOSDEF` if q1 or q2 is
        not positive definite; `ERANGE` if μ² exceeds the largest double
        (out then holds +inf and λ) or the entries of q1 and q2 span more
        than the range of a double; `ENOMEM` (not expected). Except for the
        first `ERANGE` case, out is untouched.
    """
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


def overlap(r12, q1, q2):
    """Do two ellipsoids overlap? A certified answer, faster than μ².

    Decides the sign of μ² − 1 (see `contact_function`) from bounds of μ²
    with rounding margins; only nearly tangent pairs fall back to the exact
    μ², so the answer never contradicts `contact_function`.

    Parameters
    ----------
    r12 : array_like, shape (3,)
        The centre-to-centre vector c2 − c1.
    q1, q2 : array_like, shape (6,)
        The quadratic forms of the two ellipsoids, symmetric positive
        definite (upper triangle, row by row), in the square of r12's unit.

    Returns
    -------
    int
        −1 if they overlap (μ² < 1; also for coincident centres), +1 if
        they are disjoint (μ² > 1, including μ² beyond the range of a
        double), 0 if they are tangent to the resolution of double
        arithmetic (|μ² − 1| ≤ 4 ulps of 1).

    Raises
    ------
    ValueError, TypeError
        If an argument has the wrong shape or type.
    Error
        As `contact_function`: `EDOM`, `ENOTPOSDEF`, `ERANGE` (entries of
        q1 and q2 spanning more than the range of a double), `ENOMEM`.
    """
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
