# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.legacy (docs/python-api.rst) over libpw85_legacy.

Skipped, with the reason, when libpw85_legacy is not built; a failure when
meson says it is (PW85_EXPECT_LEGACY=1) but it does not load.
"""

import re

import numpy as np
import pytest

import pypw85
from conftest import (SOURCE_ROOT, TUTORIAL_LAMBDA, TUTORIAL_MU2, full,
                      legacy_or_skip, random_spd)

legacy = legacy_or_skip()

R_OK = np.array([0.7, -0.7, 1.1])
Q1_OK = np.array([100.0, 0.0, 0.0, 100.0, 0.0, 0.01])
Q2_OK = np.array([25.0, 0.0, 0.0, 0.25, 0.0, 0.25])


def adj(a):
    """The adjugate of a symmetric matrix: det(A)·A⁻¹."""
    m = full(a)
    return np.linalg.det(m) * np.linalg.inv(m)


def q_of(lambda_, q1, q2):
    return (1 - lambda_) * np.asarray(q1) + lambda_ * np.asarray(q2)


def test_enoconv_matches_header():
    text = (SOURCE_ROOT / "include" / "pw85" / "pw85.h").read_text()
    assert legacy.ENOCONV == pypw85.ENOCONV == int(
        re.search(r"#define PW85_ENOCONV (\d+)", text).group(1))
    message = str(pypw85.Error(legacy.ENOCONV))
    assert "converge" in message and "PW85_ENOCONV" in message


def test_library_from_environment():
    import os
    if os.environ.get("PW85_LEGACY_LIBRARY"):
        assert legacy._library_path == os.environ["PW85_LEGACY_LIBRARY"]


def test_documented():
    assert legacy.__doc__
    for name in ["_det_sym", "_xT_adjA_x", "_detQ_as_poly",
                 "_rT_adjQ_r_as_poly", "f1", "f2", "contact_function1",
                 "contact_function2"]:
        assert getattr(legacy, name).__doc__, name


# --- _det_sym, _xT_adjA_x ----------------------------------------------------

def test_det_sym(rng):
    assert legacy._det_sym([1, 0, 0, 2, 0, 3]) == 6.0
    assert legacy._det_sym(np.array([2, 1, 0, 2, 0, 1])) == 3.0
    for _ in range(100):
        a = random_spd(rng)
        value = legacy._det_sym(a)
        assert type(value) is float
        assert value == pytest.approx(np.linalg.det(full(a)), rel=1e-12)


def test_xT_adjA_x(rng):
    assert legacy._xT_adjA_x([1, 1, 1], [1, 0, 0, 2, 0, 3]) == 11.0
    for _ in range(100):
        a, x = random_spd(rng), rng.standard_normal(3)
        assert legacy._xT_adjA_x(x, a) == pytest.approx(
            x @ adj(a) @ x, rel=1e-12,
            abs=1e-12 * (x @ x) * np.abs(a).max()**2)


# --- the polynomials of implementation #2 -----------------------------------

def test_detQ_as_poly(rng):
    for _ in range(50):
        q1, q2 = random_spd(rng), random_spd(rng)
        b = legacy._detQ_as_poly(q1, q2)
        assert b.shape == (4,) and b.dtype == np.float64
        scale = max(abs(np.linalg.det(full(q_of(x, q1, q2))))
                    for x in (0, 1, -1, 0.5))
        for x in (0.0, 0.25, 0.5, 1.0, 2.0):
            assert np.polyval(b[::-1], x) == pytest.approx(
                np.linalg.det(full(q_of(x, q1, q2))), abs=1e-12 * scale)
        # q3 and q4 given: the same coefficients.
        out = np.full(4, np.nan)
        assert legacy._detQ_as_poly(q1, q2, 2 * q1 - q2, 0.5 * (q1 + q2),
                                    out) is out
        np.testing.assert_array_equal(out, b)
        np.testing.assert_array_equal(
            legacy._detQ_as_poly(q1, q2, q3=2 * q1 - q2), b)


def test_rT_adjQ_r_as_poly(rng):
    for _ in range(50):
        q1, q2, r = random_spd(rng), random_spd(rng), rng.standard_normal(3)
        a = legacy._rT_adjQ_r_as_poly(r, q1, q2)
        assert a.shape == (3,) and a.dtype == np.float64
        scale = max(abs(r @ adj(q_of(x, q1, q2)) @ r) for x in (0, 1, -1))
        for x in (0.0, 0.25, 0.5, 1.0, 2.0):
            assert np.polyval(a[::-1], x) == pytest.approx(
                r @ adj(q_of(x, q1, q2)) @ r, abs=1e-12 * scale)
        out = np.full(3, np.nan)
        assert legacy._rT_adjQ_r_as_poly(r, q1, q2, 2 * q1 - q2, out) is out
        np.testing.assert_array_equal(out, a)


# --- f1, f2 ------------------------------------------------------------------

def test_f1(rng):
    for _ in range(100):
        r12, q1, q2 = rng.standard_normal(3), random_spd(rng), random_spd(rng)
        lambda_ = rng.uniform(0.01, 0.99)
        out = np.full(3, np.nan)
        value = legacy.f1(lambda_, r12, q1, q2, out)
        assert type(value) is float and value == out[0]
        assert value == pytest.approx(pypw85.f(lambda_, r12, q1, q2),
                                      rel=1e-12)
        assert legacy.f1(lambda_, r12, q1, q2) == value
        # f′ and f″ against central differences of pypw85.f.
        h = 1e-4
        fm, f0, fp = (pypw85.f(lambda_ + s * h, r12, q1, q2)
                      for s in (-1, 0, 1))
        scale = max(abs(f0), abs(out[1]), abs(out[2]), 1e-3)
        assert out[1] == pytest.approx((fp - fm) / (2 * h), abs=1e-6 * scale)
        assert out[2] == pytest.approx((fp - 2 * f0 + fm) / h**2,
                                       abs=1e-4 * scale)


def test_f2(rng):
    for _ in range(100):
        r12, q1, q2 = rng.standard_normal(3), random_spd(rng), random_spd(rng)
        lambda_ = rng.uniform()
        out = np.full(1, np.nan)
        value = legacy.f2(lambda_, r12, q1, q2, out)
        assert type(value) is float and value == out[0]
        assert value == pytest.approx(pypw85.f(lambda_, r12, q1, q2),
                                      rel=1e-10)
        assert legacy.f2(lambda_, r12, q1, q2) == value


@pytest.mark.parametrize("function,size", [("f1", 3), ("f2", 1)])
def test_f_errors(function, size):
    function = getattr(legacy, function)
    out = np.zeros(size)
    with pytest.raises(pypw85.Error) as info:
        function(0.5, [0, np.nan, 0], Q1_OK, Q2_OK, out)
    assert info.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as info:
        function(np.inf, R_OK, Q1_OK, Q2_OK)
    assert info.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as info:
        function(0.5, R_OK, [-1, 0, 0, 1, 0, 1], [-1, 0, 0, 1, 0, 1], out)
    assert info.value.status == pypw85.ENOTPOSDEF
    assert np.isnan(out).all()
    with pytest.raises(ValueError, match=r"^out: .*got shape \(%d,\)"
                       % (size + 1)):
        function(0.5, R_OK, Q1_OK, Q2_OK, np.zeros(size + 1))
    with pytest.raises(TypeError, match=r"^out: .*dtype float32"):
        function(0.5, R_OK, Q1_OK, Q2_OK, np.zeros(size, dtype=np.float32))
    with pytest.raises(ValueError, match=r"^r12: expected shape \(3,\)"):
        function(0.5, R_OK[:2], Q1_OK, Q2_OK)
    with pytest.raises(TypeError, match=r"^lambda_: expected a real number"):
        function("0.5", R_OK, Q1_OK, Q2_OK)


# --- contact_function1, contact_function2 ------------------------------------

def test_contact_function1_does_not_converge(tutorial):
    """Newton's method from λ = ½ fails on the tutorial's flat spheroids
    (seed: "not robust"): ENOCONV, out holds a lower bound of μ²."""
    out = np.full(2, np.nan)
    with pytest.raises(pypw85.Error) as info:
        legacy.contact_function1(tutorial.r12, tutorial.q1, tutorial.q2, out)
    assert info.value.status == legacy.ENOCONV
    assert "did not converge" in str(info.value)
    assert 0 <= out[1] <= 1
    assert out[0] <= TUTORIAL_MU2 * (1 + 1e-15)
    assert out[0] == pytest.approx(
        pypw85.f(out[1], tutorial.r12, tutorial.q1, tutorial.q2), rel=1e-12)


def test_contact_function2_tutorial(tutorial):
    name, function = "contact_function2", legacy.contact_function2
    out = np.full(2, np.nan)
    assert function(tutorial.r12, tutorial.q1, tutorial.q2, out) is out
    mu2, lambda_ = out
    print("%s, tutorial: mu2 = %r (rel. error %.2g), lambda = %r"
          % (name, mu2, abs(mu2 - TUTORIAL_MU2) / TUTORIAL_MU2, lambda_))
    assert mu2 == pytest.approx(TUTORIAL_MU2, rel=1e-10)
    assert lambda_ == pytest.approx(TUTORIAL_LAMBDA, rel=1e-6)
    np.testing.assert_array_equal(
        function(list(tutorial.r12), tuple(tutorial.q1), tutorial.q2), out)


@pytest.mark.parametrize("name", ["contact_function1", "contact_function2"])
def test_contact_spheres(name, rng):
    function = getattr(legacy, name)
    for _ in range(50):
        # Radii close enough for Newton's method (contact_function1).
        a1, a2 = rng.uniform(0.8, 1.25, 2)
        r = rng.standard_normal(3)
        mu2, lambda_ = function(r, [a1**2, 0, 0, a1**2, 0, a1**2],
                                [a2**2, 0, 0, a2**2, 0, a2**2])
        assert mu2 == pytest.approx(r @ r / (a1 + a2)**2, rel=1e-10)
        assert lambda_ == pytest.approx(a1 / (a1 + a2), rel=1e-6)


@pytest.mark.parametrize("name", ["contact_function1", "contact_function2"])
def test_contact_errors(name):
    function = getattr(legacy, name)
    out = np.array([42.0, -7.0])
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(pypw85.Error) as info:
            function([0, 0, bad], Q1_OK, Q2_OK, out)
        assert info.value.status == pypw85.EDOM
        assert name in str(info.value)
    with pytest.raises(pypw85.Error) as info:
        function(R_OK, Q1_OK, [1, 2, 0, 1, 0, 1], out)
    assert info.value.status == pypw85.ENOTPOSDEF
    np.testing.assert_array_equal(out, [42.0, -7.0])
    with pytest.raises(ValueError, match=r"^out: .*got shape \(3,\)"):
        function(R_OK, Q1_OK, Q2_OK, np.zeros(3))
    with pytest.raises(ValueError, match=r"^q2: expected shape \(6,\)"):
        function(R_OK, Q1_OK, np.zeros((2, 3)))
    with pytest.raises(TypeError, match=r"^q1: expected real numbers"):
        function(R_OK, Q1_OK.astype(complex), Q2_OK)


# --- errors of the internal functions ----------------------------------------

@pytest.mark.parametrize("call", [
    lambda: legacy._det_sym([1, 0, 0, 1, 0, np.nan]),
    lambda: legacy._xT_adjA_x([np.inf, 0, 0], [1, 0, 0, 1, 0, 1]),
    lambda: legacy._detQ_as_poly(Q1_OK, [np.nan] * 6),
    lambda: legacy._detQ_as_poly(Q1_OK, Q2_OK, q4=[np.inf] * 6),
    lambda: legacy._rT_adjQ_r_as_poly([0, 0, np.nan], Q1_OK, Q2_OK),
])
def test_internal_not_finite(call):
    with pytest.raises(pypw85.Error) as info:
        call()
    assert info.value.status == pypw85.EDOM


@pytest.mark.parametrize("call,error,message", [
    (lambda: legacy._det_sym([1, 0, 0, 1, 0]), ValueError,
     r"^a: expected shape \(6,\)"),
    (lambda: legacy._xT_adjA_x([1, 0], Q1_OK), ValueError,
     r"^x: expected shape \(3,\)"),
    (lambda: legacy._xT_adjA_x(R_OK, ["a"] * 6), TypeError,
     r"^a: expected real numbers"),
    (lambda: legacy._detQ_as_poly(Q1_OK, Q2_OK, q3=np.zeros(5)), ValueError,
     r"^q3: expected shape \(6,\)"),
    (lambda: legacy._detQ_as_poly(Q1_OK, Q2_OK, b=np.zeros(3)), ValueError,
     r"^b: .*got shape \(3,\)"),
    (lambda: legacy._detQ_as_poly(Q1_OK, Q2_OK, b=np.zeros(8)[::2]),
     ValueError, r"^b: .*non-contiguous"),
    (lambda: legacy._rT_adjQ_r_as_poly(R_OK, Q1_OK, Q2_OK,
                                       a=np.zeros(3, dtype=int)),
     TypeError, r"^a: .*dtype int64"),
])
def test_internal_wrong_arguments(call, error, message):
    with pytest.raises(error, match=message):
        call()
