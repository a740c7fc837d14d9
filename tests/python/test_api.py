# SPDX-License-Identifier: BSD-3-Clause
"""pypw85, the new API (docs/python-api.rst): every function, every error."""

import math
import os
import pickle
import re
import threading

import numpy as np
import pytest

import pypw85
from conftest import TUTORIAL_LAMBDA, TUTORIAL_MU2, full, random_spd

EPS = np.finfo(np.float64).eps
R_OK = np.array([0.7, -0.7, 1.1])
Q1_OK = np.array([100.0, 0.0, 0.0, 100.0, 0.0, 0.01])
Q2_OK = np.array([25.0, 0.0, 0.0, 0.25, 0.0, 0.25])


def rel(actual, expected):
    return abs(actual - expected) / abs(expected)


def f_numpy(lambda_, r12, q1, q2):
    """f(λ) by NumPy (docs/theory.rst, eq. (3.11))."""
    q = (1 - lambda_) * full(q1) + lambda_ * full(q2)
    return lambda_ * (1 - lambda_) * r12 @ np.linalg.solve(q, r12)


# --- version, status codes (constants: test_constants.py) ------------

def test_version():
    assert re.fullmatch(r"\d+\.\d+\.\d+", pypw85.__version__)
    assert pypw85.__version__.split(".")[0] == str(pypw85._ABI_MAJOR)
    expected = os.environ.get("PW85_EXPECTED_VERSION")
    if expected:
        assert pypw85.__version__ == expected


def test_library_from_environment():
    if os.environ.get("PW85_LIBRARY"):
        assert pypw85._library_path == os.environ["PW85_LIBRARY"]


def test_public_names_documented():
    assert pypw85.__doc__
    for name in pypw85.__all__ + ["_cholesky_decomp", "_cholesky_solve",
                                  "_residual"]:
        obj = getattr(pypw85, name)
        if callable(obj):
            assert obj.__doc__, name
        if callable(obj) and name != "Error":
            for section in ("Parameters", "Returns", "Raises"):
                assert section in obj.__doc__, (name, section)


@pytest.mark.parametrize("status", range(6))
def test_error_carries_strerror(status):
    e = pypw85.Error(status, "where", "detail")
    assert isinstance(e, ValueError)
    assert e.status == status
    assert e.strerror and "unknown" not in e.strerror
    assert str(e).startswith("where: " + e.strerror)
    assert "detail" in str(e)
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.status, str(e2)) == (status, str(e))


def test_error_unknown_status():
    e = pypw85.Error(1000)
    assert e.status == 1000 and "1000" in str(e)


# --- the tutorial (docs/tutorial.rst) ---------------------------------------------

def test_tutorial_spheroids(tutorial):
    assert tutorial.q1 == pytest.approx([1e2, 0, 0, 1e2, 0, 1e-2],
                                        rel=1e-12, abs=0)
    assert tutorial.q2 == pytest.approx([25, 0, 0, 0.25, 0, 0.25],
                                        rel=1e-15, abs=0)


def test_tutorial_contact_function(tutorial):
    mu2, lambda_ = pypw85.contact_function(tutorial.r12, tutorial.q1,
                                           tutorial.q2)
    print("tutorial: mu2 = %r (rel. error %.2g), lambda = %r (rel. error "
          "%.2g)" % (mu2, rel(mu2, TUTORIAL_MU2), lambda_,
                     rel(lambda_, TUTORIAL_LAMBDA)))
    assert rel(mu2, TUTORIAL_MU2) <= 1e-15
    assert rel(lambda_, TUTORIAL_LAMBDA) <= 1e-12
    assert mu2 > 1  # The two spheroids do not overlap.


# --- _cholesky_decomp, _cholesky_solve ------------------------------------

def test_cholesky_decomp(rng):
    for _ in range(100):
        a = random_spd(rng)
        l = pypw85._cholesky_decomp(a)
        lower = np.zeros((3, 3))
        lower[[0, 1, 2, 1, 2, 2], [0, 0, 0, 1, 1, 2]] = l
        np.testing.assert_allclose(lower, np.linalg.cholesky(full(a)),
                                   rtol=1e-13, atol=1e-14 * np.abs(a).max())
        np.testing.assert_allclose(lower @ lower.T, full(a), rtol=0,
                                   atol=1e-14 * np.abs(a).max())


def test_cholesky_decomp_in_place():
    l = np.full(6, 42.0)
    assert pypw85._cholesky_decomp([4, 2, 0, 5, 0, 9], l) is l
    np.testing.assert_array_equal(l, [2, 1, 0, 2, 0, 3])
    # Output aliasing the input: the input is copied first.
    a = np.array([4.0, 2, 0, 5, 0, 9])
    assert pypw85._cholesky_decomp(a, a) is a
    np.testing.assert_array_equal(a, [2, 1, 0, 2, 0, 3])


def test_cholesky_decomp_not_positive_definite():
    l = np.zeros(6)
    with pytest.raises(pypw85.Error) as info:
        pypw85._cholesky_decomp([1, 2, 0, 1, 0, 1], l)
    assert info.value.status == pypw85.ENOTPOSDEF
    assert np.isnan(l).all()


def test_cholesky_solve(rng):
    for _ in range(100):
        a = random_spd(rng)
        b = rng.standard_normal(3)
        x = pypw85._cholesky_solve(pypw85._cholesky_decomp(a), b)
        np.testing.assert_allclose(full(a) @ x, b, rtol=0,
                                   atol=1e-12 * np.abs(b).max())


def test_cholesky_solve_in_place():
    l = np.array([2.0, 1, 0, 2, 0, 3])
    b = np.array([4.0, 7, 9])  # L·Lᵀ = [[4, 2, 0], [2, 5, 0], [0, 0, 9]]
    x = np.empty(3)
    assert pypw85._cholesky_solve(l, b, x) is x
    np.testing.assert_allclose(x, [0.375, 1.25, 1.0], rtol=1e-15)
    x_b = pypw85._cholesky_solve(l, b, b)  # x may alias b
    assert x_b is b
    np.testing.assert_array_equal(b, x)


def test_cholesky_solve_errors():
    with pytest.raises(pypw85.Error) as info:
        pypw85._cholesky_solve([1, 0, 0, 0, 0, 1], [1, 1, 1])
    assert info.value.status == pypw85.ENOTPOSDEF
    with pytest.raises(pypw85.Error) as info:
        pypw85._cholesky_solve([1, 0, 0, 1, 0, 1], [1, np.inf, 1])
    assert info.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as info:
        pypw85._cholesky_solve([1e-300, 0, 0, 1, 0, 1], [1e300, 1, 1])
    assert info.value.status == pypw85.ERANGE


# --- spheroid ---------------------------------------------------------------

def test_spheroid(rng):
    for _ in range(100):
        a, c = rng.uniform(0.01, 100, 2)
        n = rng.standard_normal(3)
        n /= np.linalg.norm(n)
        q = pypw85.spheroid(a, c, n)
        expected = a**2 * np.eye(3) + (c**2 - a**2) * np.outer(n, n)
        np.testing.assert_allclose(full(q), expected, rtol=0,
                                   atol=4 * EPS * max(a, c)**2)
        # Semi-axis c along n (to rounding times the condition number).
        cond = (max(a, c) / min(a, c))**2
        assert n @ np.linalg.solve(full(q), n) == pytest.approx(
            c**-2, rel=16 * EPS * cond)


def test_spheroid_in_place_and_array_likes():
    q = np.full(6, np.nan)
    assert pypw85.spheroid(2, 3, [0, 1, 0], q) is q
    np.testing.assert_array_equal(q, [4, 0, 0, 9, 0, 4])
    for n in ([0, 1, 0], (0, 1, 0), np.array([0, 1, 0]),
              np.array([0, 1, 0], dtype=np.float32),
              np.arange(6.0)[[0, 1, 0]] * 1.0,
              np.array([0.0, 9, 1, 9, 0, 9])[::2]):
        np.testing.assert_array_equal(pypw85.spheroid(2.0, 3, n), q)
    np.testing.assert_array_equal(
        pypw85.spheroid(np.float32(2), np.array(3), [0, 1, 0]), q)


def test_spheroid_aliasing():
    q = np.array([0.0, 1, 0, 7, 7, 7])
    pypw85.spheroid(2, 3, q[:3], q)  # n is a view of q
    np.testing.assert_array_equal(q, [4, 0, 0, 9, 0, 4])


@pytest.mark.parametrize("args", [(np.nan, 1, [0, 0, 1]),
                                  (1, np.inf, [0, 0, 1]),
                                  (1, 1, [0, -np.inf, 1])])
def test_spheroid_not_finite(args):
    q = np.full(6, 42.0)
    with pytest.raises(pypw85.Error) as info:
        pypw85.spheroid(*args, q=q)
    assert info.value.status == pypw85.EDOM
    assert (q == 42.0).all()


def test_spheroid_overflow():
    with pytest.raises(pypw85.Error) as info:
        pypw85.spheroid(1e200, 1, [0, 0, 1])
    assert info.value.status == pypw85.ERANGE


# --- f, f_neg, _residual ----------------------------------------------------

def test_f(rng):
    for _ in range(200):
        r12 = rng.standard_normal(3)
        q1, q2 = random_spd(rng), random_spd(rng)
        lambda_ = rng.uniform()
        value = pypw85.f(lambda_, r12, q1, q2)
        assert type(value) is float
        assert value == pytest.approx(f_numpy(lambda_, r12, q1, q2),
                                      rel=1e-12)
        assert pypw85.f_neg(lambda_, r12, q1, q2) == -value


def test_f_spheres():
    # Spheres of radii 1 and 2: f = λ(1−λ)|r|²/((1−λ) + 4λ).
    r = np.array([1.0, 2.0, 2.0])
    for lambda_ in np.linspace(0, 1, 11):
        expected = lambda_ * (1 - lambda_) * 9 / (1 + 3 * lambda_)
        assert pypw85.f(lambda_, r, [1, 0, 0, 1, 0, 1],
                        [4, 0, 0, 4, 0, 4]) == pytest.approx(expected,
                                                             rel=1e-15,
                                                             abs=0)


def test_f_array_likes(tutorial):
    expected = pypw85.f(0.25, tutorial.r12, tutorial.q1, tutorial.q2)
    assert pypw85.f(np.float32(0.25), list(tutorial.r12),
                    tuple(tutorial.q1), tutorial.q2.tolist()) == expected
    assert pypw85.f(np.array(0.25), tutorial.r12, tutorial.q1,
                    tutorial.q2) == expected
    assert pypw85.f(1, [0, 0, 0], [1, 0, 0, 1, 0, 1], [1, 0, 0, 1, 0, 1]) == 0


@pytest.mark.parametrize("function", [pypw85.f, pypw85.f_neg])
@pytest.mark.parametrize("position", range(16))
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_f_not_finite(function, position, bad):
    args = [0.5, R_OK.copy(), Q1_OK.copy(), Q2_OK.copy()]
    if position == 0:
        args[0] = bad
    else:
        flat = np.concatenate(args[1:])
        flat[position - 1] = bad
        args[1:] = flat[:3], flat[3:9], flat[9:]
    with pytest.raises(pypw85.Error) as info:
        function(*args)
    assert info.value.status == pypw85.EDOM
    assert function.__name__ in str(info.value)


@pytest.mark.parametrize("function", [pypw85.f, pypw85.f_neg])
def test_f_not_positive_definite(function):
    with pytest.raises(pypw85.Error) as info:
        function(0.5, R_OK, [-1, 0, 0, 1, 0, 1], [-1, 0, 0, 1, 0, 1])
    assert info.value.status == pypw85.ENOTPOSDEF


def test_residual(tutorial):
    mu2, lambda_ = pypw85.contact_function(tutorial.r12, tutorial.q1,
                                           tutorial.q2)
    out = np.empty(3)
    assert pypw85._residual(lambda_, tutorial.r12, tutorial.q1, tutorial.q2,
                            out) is out
    assert out[0] == pytest.approx(mu2, rel=1e-15)
    assert abs(out[1]) <= 1e-10 * mu2  # g(λ) = 0 at the maximiser
    h = 1e-6
    g = [pypw85._residual(lambda_ + s * h, tutorial.r12, tutorial.q1,
                          tutorial.q2)[1] for s in (-1, 1)]
    assert out[2] == pytest.approx((g[1] - g[0]) / (2 * h), rel=1e-6)


def test_residual_errors():
    with pytest.raises(ValueError, match="lambda_"):
        pypw85._residual(1.5, R_OK, Q1_OK, Q2_OK)
    with pytest.raises(pypw85.Error) as info:
        pypw85._residual(np.nan, R_OK, Q1_OK, Q2_OK)
    assert info.value.status == pypw85.EDOM


# --- contact_function --------------------------------------------------------

def test_contact_function_spheres(rng):
    for _ in range(100):
        a1, a2 = rng.uniform(0.1, 10, 2)
        r = rng.standard_normal(3)
        mu2, lambda_ = pypw85.contact_function(
            r, pypw85.spheroid(a1, a1, [0, 0, 1]),
            pypw85.spheroid(a2, a2, [0, 0, 1]))
        assert mu2 == pytest.approx(r @ r / (a1 + a2)**2, rel=1e-15)
        assert lambda_ == pytest.approx(a1 / (a1 + a2), rel=1e-12)


def test_contact_function_properties(rng):
    for _ in range(100):
        r = rng.standard_normal(3)
        q1, q2 = random_spd(rng), random_spd(rng)
        mu2, lambda_ = pypw85.contact_function(r, q1, q2)
        assert 0 <= lambda_ <= 1
        # μ² is the maximum of f over [0, 1].
        fs = [pypw85.f(x, r, q1, q2) for x in np.linspace(0, 1, 101)]
        assert mu2 >= max(fs) * (1 - 1e-14)
        assert mu2 == pytest.approx(pypw85.f(lambda_, r, q1, q2), rel=1e-14)
        # Exchanging the ellipsoids: λ → 1 − λ; scaling: same μ².
        mu2_s, lambda_s = pypw85.contact_function(-r, q2, q1)
        assert mu2_s == pytest.approx(mu2, rel=1e-14)
        assert lambda_s == pytest.approx(1 - lambda_, abs=1e-10)
        mu2_t, _ = pypw85.contact_function(r * 2.0**-40, q1 * 2.0**-80,
                                           q2 * 2.0**-80)
        assert mu2_t == pytest.approx(mu2, rel=1e-14)


def test_contact_function_coincident_centres():
    mu2, lambda_ = pypw85.contact_function([0, 0, 0], Q1_OK, Q2_OK)
    assert (mu2, lambda_) == (0.0, 0.5)


def test_contact_function_in_place(tutorial):
    expected = pypw85.contact_function(tutorial.r12, tutorial.q1,
                                       tutorial.q2)
    assert isinstance(expected, np.ndarray) and expected.shape == (2,)
    assert expected.dtype == np.float64
    out = np.full(2, np.nan)
    assert pypw85.contact_function(tutorial.r12, tutorial.q1, tutorial.q2,
                                   out) is out
    np.testing.assert_array_equal(out, expected)
    out = np.full(2, np.nan)
    assert pypw85.contact_function(tutorial.r12, tutorial.q1, tutorial.q2,
                                   out=out) is out
    np.testing.assert_array_equal(out, expected)


def test_contact_function_array_likes(tutorial):
    expected = pypw85.contact_function(tutorial.r12, tutorial.q1,
                                       tutorial.q2)
    big = np.zeros((6, 2))
    big[:, 1] = tutorial.q1  # a non-contiguous column
    for r12, q1, q2 in [
            (list(tutorial.r12), list(tutorial.q1), list(tutorial.q2)),
            (tuple(tutorial.r12), big[:, 1], tutorial.q2.astype(">f8")),
            (tutorial.r12, [100, 0, 0, 100, 0, tutorial.q1[5]],
             np.array([25, 0, 0, 0.25, 0, 0.25], dtype=np.longdouble))]:
        np.testing.assert_array_equal(
            pypw85.contact_function(r12, q1, q2), expected)
    mu2, _ = pypw85.contact_function(np.array([3, 4, 0]),
                                     np.array([1, 0, 0, 1, 0, 1]),
                                     np.array([1, 0, 0, 1, 0, 1],
                                              dtype=np.int8))
    assert mu2 == pytest.approx(25 / 4, rel=1e-15)


def test_contact_function_does_not_modify_inputs(tutorial):
    copies = [x.copy() for x in (tutorial.r12, tutorial.q1, tutorial.q2)]
    pypw85.contact_function(tutorial.r12, tutorial.q1, tutorial.q2)
    for x, y in zip(copies, (tutorial.r12, tutorial.q1, tutorial.q2)):
        np.testing.assert_array_equal(x, y)


@pytest.mark.parametrize("position", range(15))
@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_contact_function_not_finite(position, bad):
    flat = np.concatenate([R_OK, Q1_OK, Q2_OK])
    flat[position] = bad
    out = np.array([42.0, -7.0])
    with pytest.raises(pypw85.Error) as info:
        pypw85.contact_function(flat[:3], flat[3:9], flat[9:], out)
    assert info.value.status == pypw85.EDOM
    assert info.value.strerror in str(info.value)
    assert "contact_function" in str(info.value)
    np.testing.assert_array_equal(out, [42.0, -7.0])


@pytest.mark.parametrize("q", [[-1, 0, 0, 1, 0, 1], [1, 2, 0, 1, 0, 1],
                               [0, 0, 0, 0, 0, 0], [1, 0, 0, 1, 0, -1e-300]])
@pytest.mark.parametrize("which", [1, 2])
def test_contact_function_not_positive_definite(q, which):
    q1, q2 = (q, Q2_OK) if which == 1 else (Q1_OK, q)
    out = np.array([42.0, -7.0])
    with pytest.raises(pypw85.Error) as info:
        pypw85.contact_function(R_OK, q1, q2, out)
    assert info.value.status == pypw85.ENOTPOSDEF
    np.testing.assert_array_equal(out, [42.0, -7.0])


def test_contact_function_overflow():
    # μ² = |r|²/(1 + 1)² = 1e600/4 exceeds the largest double.
    out = np.zeros(2)
    with pytest.raises(pypw85.Error) as info:
        pypw85.contact_function([1e300, 0, 0], [1, 0, 0, 1, 0, 1],
                                [1, 0, 0, 1, 0, 1], out)
    assert info.value.status == pypw85.ERANGE
    assert out[0] == math.inf and out[1] == pytest.approx(0.5)


# --- overlap ---------------------------------------------------------------

def test_overlap(rng, tutorial):
    assert pypw85.overlap(tutorial.r12, tutorial.q1, tutorial.q2) == 1
    assert pypw85.overlap([0, 0, 0], Q1_OK, Q2_OK) == -1
    # Spheres of radii 1 and 2, 3 apart: tangent; closer or farther.
    s1, s2 = [1, 0, 0, 1, 0, 1], [4, 0, 0, 4, 0, 4]
    assert pypw85.overlap([3, 0, 0], s1, s2) == 0
    assert pypw85.overlap([2.9, 0, 0], s1, s2) == -1
    assert pypw85.overlap((0, 3.1, 0), s1, s2) == 1
    assert pypw85.overlap([1e300, 0, 0], s1, s2) == 1
    for _ in range(500):
        r = rng.standard_normal(3)
        q1, q2 = random_spd(rng, 0.5), random_spd(rng, 0.5)
        mu2, _ = pypw85.contact_function(r, q1, q2)
        expected = 0 if abs(mu2 - 1) <= 4 * EPS else (1 if mu2 > 1 else -1)
        assert pypw85.overlap(r, q1, q2) == expected


def test_overlap_errors():
    with pytest.raises(pypw85.Error) as info:
        pypw85.overlap([np.nan, 0, 0], Q1_OK, Q2_OK)
    assert info.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as info:
        pypw85.overlap(R_OK, Q1_OK, [1, 0, 0, -1, 0, 1])
    assert info.value.status == pypw85.ENOTPOSDEF
    assert "overlap" in str(info.value)


# --- wrong arguments (shapes, dtypes, outputs) ------------------------------

CALLS = {
    # name: (function, valid arguments, {argument: expected length})
    "_cholesky_decomp": (pypw85._cholesky_decomp, dict(a=Q1_OK), dict(a=6)),
    "_cholesky_solve": (pypw85._cholesky_solve,
                        dict(l=Q1_OK, b=R_OK), dict(l=6, b=3)),
    "spheroid": (pypw85.spheroid, dict(a=1.0, c=2.0, n=R_OK), dict(n=3)),
    "f": (pypw85.f, dict(lambda_=0.5, r12=R_OK, q1=Q1_OK, q2=Q2_OK),
          dict(r12=3, q1=6, q2=6)),
    "f_neg": (pypw85.f_neg, dict(lambda_=0.5, r12=R_OK, q1=Q1_OK, q2=Q2_OK),
              dict(r12=3, q1=6, q2=6)),
    "_residual": (pypw85._residual,
                  dict(lambda_=0.5, r12=R_OK, q1=Q1_OK, q2=Q2_OK),
                  dict(r12=3, q1=6, q2=6)),
    "contact_function": (pypw85.contact_function,
                         dict(r12=R_OK, q1=Q1_OK, q2=Q2_OK),
                         dict(r12=3, q1=6, q2=6)),
    "overlap": (pypw85.overlap, dict(r12=R_OK, q1=Q1_OK, q2=Q2_OK),
                dict(r12=3, q1=6, q2=6)),
}
OUTPUTS = {"_cholesky_decomp": ("l", 6), "_cholesky_solve": ("x", 3),
           "spheroid": ("q", 6), "_residual": ("out", 3),
           "contact_function": ("out", 2)}
# The functions that also take arrays of pairs.
BATCHES = {"contact_function", "overlap", "spheroid"}
ARRAY_ARGS = [(name, arg, n) for name, (_, _, lengths) in CALLS.items()
              for arg, n in lengths.items()]


@pytest.mark.parametrize("name,arg,n", ARRAY_ARGS)
@pytest.mark.parametrize("shape", [(), (1,), (2,), (5,), (7,), (1, 3),
                                   (3, 1), (2, 3), (0,)])
def test_wrong_shape(name, arg, n, shape):
    if shape == (n,):
        return
    function, args, _ = CALLS[name]
    args = dict(args, **{arg: np.ones(shape)})
    expected = r"^%s: expected shape \(%d,\), got " % (arg, n)
    if name in BATCHES and len(shape) > 1:
        # An array of pairs (test_batch.py), if its last axis fits.
        if shape[-1] == n:
            return
        expected = r"^%s: expected shape \(%d,\) or \(\.\.\., %d\), got " \
            % (arg, n, n)
    with pytest.raises(ValueError, match=expected) as info:
        function(**args)
    assert not isinstance(info.value, pypw85.Error)


@pytest.mark.parametrize("name,arg,n", ARRAY_ARGS)
@pytest.mark.parametrize("kind", ["complex", "str", "object", "bool", "none",
                                  "datetime"])
def test_wrong_dtype(name, arg, n, kind):
    function, args, _ = CALLS[name]
    value = {"complex": np.ones(n, dtype=complex),
             "str": ["1"] * n,
             "object": np.array([1.0] * (n - 1) + [None], dtype=object),
             "bool": np.ones(n, dtype=bool),
             "none": None,
             "datetime": np.array(["2019-01-01"] * n, dtype="M8[D]")}[kind]
    with pytest.raises(TypeError, match=r"^%s: expected real numbers" % arg):
        function(**dict(args, **{arg: value}))


@pytest.mark.parametrize("name,arg,n", ARRAY_ARGS)
def test_ragged_input(name, arg, n):
    function, args, _ = CALLS[name]
    with pytest.raises(ValueError, match=r"^%s: " % arg):
        function(**dict(args, **{arg: [[1.0], [1.0, 2.0]] + [1.0] * (n - 2)}))


@pytest.mark.parametrize("name,arg", [("f", "lambda_"), ("f_neg", "lambda_"),
                                      ("_residual", "lambda_"),
                                      ("spheroid", "a"), ("spheroid", "c")])
@pytest.mark.parametrize("value", ["0.5", 0.5j, np.complex128(0.5), None,
                                   [0.5], np.array([0.5]), np.ones((1, 1))])
def test_wrong_scalar(name, arg, value):
    function, args, _ = CALLS[name]
    if name == "spheroid" and np.ndim(value) > 0:
        return  # an array of spheroids (test_batch.py)
    with pytest.raises(TypeError, match=r"^%s: expected a real number" % arg):
        function(**dict(args, **{arg: value}))


def bad_outputs(n):
    read_only = np.zeros(n)
    read_only.flags.writeable = False
    return [
        (TypeError, "dtype float32", np.zeros(n, dtype=np.float32)),
        (TypeError, "dtype int64", np.zeros(n, dtype=np.int64)),
        (TypeError, "dtype >f8", np.zeros(n, dtype=">f8")),
        (TypeError, "got list", [0.0] * n),
        (ValueError, r"got shape \(%d,\)" % (n + 1), np.zeros(n + 1)),
        (ValueError, r"got shape \(1, %d\)" % n, np.zeros((1, n))),
        (ValueError, "non-contiguous", np.zeros(2 * n)[::2]),
        (ValueError, "read-only", read_only),
    ]


@pytest.mark.parametrize("name", sorted(OUTPUTS))
@pytest.mark.parametrize("case", range(8))
def test_wrong_output(name, case):
    function, args, _ = CALLS[name]
    arg, n = OUTPUTS[name]
    error, message, out = bad_outputs(n)[case]
    before = np.array(out, copy=True)
    with pytest.raises(error, match=r"^%s: expected a C-contiguous, writeable "
                       r"numpy.ndarray of dtype float64 and shape \(%d,\), "
                       r".*%s" % (arg, n, message)):
        function(**dict(args, **{arg: out}))
    np.testing.assert_array_equal(np.asarray(out), before)


# --- threads -----------------------------------------------------------------

def test_threads(rng):
    """Concurrent calls (ctypes releases the GIL) give the serial results."""
    cases = [(rng.standard_normal(3), random_spd(rng), random_spd(rng))
             for _ in range(2000)]
    serial = np.array([pypw85.contact_function(*c) for c in cases])
    results = [np.empty_like(serial) for _ in range(4)]

    def work(out):
        for i, c in enumerate(cases):
            pypw85.contact_function(*c, out=out[i])

    threads = [threading.Thread(target=work, args=(r,)) for r in results]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, serial)


def test_thread_safety_documented():
    assert "GIL" in pypw85.__doc__
