# SPDX-License-Identifier: BSD-3-Clause
"""Property tests of pypw85 with hypothesis (issue 14, item 5).

The contract and the relations of issue 14, item 1, on random valid
ellipsoids: semi-axes m·2^e with m in [1, 2) and e in [-10, 10] (condition
numbers of Q below 2^44 ≈ 1.8e13, inside the domain pw85.h promises),
rotations from random quaternions, centre-to-centre vectors of random
direction at any distance, half of them placed near tangency. Then inputs
the library must reject, each with its documented status.

Reproducible: every test runs with ``derandomize=True`` (the examples are a
function of the test's source, not of a clock or of a saved database) and
``database=None``, so CI runs the same examples on every machine.
"""

import math

import numpy as np
import pytest

hypothesis = pytest.importorskip("hypothesis")
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import pypw85  # noqa: E402

EPS = np.finfo(np.float64).eps
# pw85_overlap answers 0 (tangent) within |μ² − 1| ≤ 4·ε; outside it, its
# sign must be that of μ² − 1.
BAND = 4 * EPS

# Fixed and derandomized; 300 examples per property keep the file near 10 s.
PROPERTY = settings(derandomize=True, database=None, max_examples=300,
                    deadline=None, print_blob=False,
                    suppress_health_check=[HealthCheck.too_slow])
ERRORS = settings(PROPERTY, max_examples=150)

# Strategies ---------------------------------------------------------------

unit_float = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)


@st.composite
def rotations(draw):
    """A rotation matrix from a random quaternion (norm at least 0.1)."""
    q = np.array(draw(st.tuples(unit_float, unit_float, unit_float,
                                unit_float).filter(
        lambda v: math.fsum(x * x for x in v) >= 0.01)))
    w, x, y, z = q / np.linalg.norm(q)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


semi_axis = st.builds(math.ldexp, st.floats(1.0, 2.0, exclude_max=True),
                      st.integers(-10, 10))


def upper(m):
    """The upper triangle, row by row, of a 3×3 matrix."""
    return np.ascontiguousarray(m[np.triu_indices(3)])


def form(rot, squares):
    """Q = R·diag(squares)·Rᵀ, symmetric by construction."""
    m = rot @ np.diag(squares) @ rot.T
    return upper(0.5 * (m + m.T))


@st.composite
def ellipsoids(draw):
    """(Q as double[6], semi-axes) of a random ellipsoid."""
    axes = np.array(draw(st.tuples(semi_axis, semi_axis, semi_axis)))
    return form(draw(rotations()), axes * axes), axes


@st.composite
def directions(draw):
    v = np.array(draw(st.tuples(unit_float, unit_float, unit_float).filter(
        lambda v: math.fsum(x * x for x in v) >= 0.01)))
    return v / np.linalg.norm(v)


# Relative distances to tangency (μ² ≈ 1 + δ), from a few ulps to 1e-3.
tangency_offsets = st.sampled_from(
    [0.0, EPS, -EPS, 2 * EPS, -2 * EPS, 4 * EPS, -4 * EPS, 5 * EPS,
     -5 * EPS, 8 * EPS, -8 * EPS, 1e-14, -1e-14, 1e-12, -1e-12, 1e-9,
     -1e-9, 1e-6, -1e-6, 1e-3, -1e-3])


@st.composite
def pairs(draw):
    """(r12, q1, q2) of two valid ellipsoids: far, overlapping, coincident
    or nearly tangent."""
    q1, a1 = draw(ellipsoids())
    q2, a2 = draw(ellipsoids())
    u = draw(directions())
    kind = draw(st.sampled_from(["distance", "tangent", "tangent",
                                 "coincident"]))
    if kind == "coincident":
        return np.zeros(3), q1, q2
    size = math.sqrt(max(a1)) * math.sqrt(max(a2))
    if kind == "distance":
        # Any distance, from deep overlap to far apart.
        scale = math.ldexp(size, draw(st.integers(-12, 12)))
        return u * scale, q1, q2
    # μ² is homogeneous of degree 2 in r12: rescale u to μ² ≈ 1 + δ.
    mu2_u = pypw85.contact_function(u, q1, q2)[0]
    delta = draw(tangency_offsets)
    return u * math.sqrt((1.0 + delta) / mu2_u), q1, q2


# Properties ---------------------------------------------------------------

@PROPERTY
@given(pairs())
def test_contract(pair):
    """μ² finite and ≥ 0, λ in [0, 1]; coincident centres: μ² = 0, λ = ½."""
    r12, q1, q2 = pair
    mu2, lam = pypw85.contact_function(r12, q1, q2)
    assert math.isfinite(mu2) and mu2 >= 0.0, (mu2, lam)
    assert 0.0 <= lam <= 1.0, (mu2, lam)
    if not r12.any():
        assert (mu2, lam) == (0.0, 0.5)


@PROPERTY
@given(pairs())
def test_overlap_consistent_with_mu2(pair):
    """overlap() has the sign of μ² − 1 outside the 4-ulp band, and says
    'tangent' (0) only inside it."""
    r12, q1, q2 = pair
    mu2, _ = pypw85.contact_function(r12, q1, q2)
    answer = pypw85.overlap(r12, q1, q2)
    assert answer in (-1, 0, 1)
    if mu2 < 1.0 - BAND:
        assert answer == -1, (mu2, answer)
    elif mu2 > 1.0 + BAND:
        assert answer == 1, (mu2, answer)
    if answer == 0:
        assert abs(mu2 - 1.0) <= BAND, (mu2, answer)


@PROPERTY
@given(pairs())
def test_swap(pair):
    """(−r12, q2, q1): the same μ² bit for bit, λ → 1 − λ to a few ulps."""
    r12, q1, q2 = pair
    mu2, lam = pypw85.contact_function(r12, q1, q2)
    mu2_s, lam_s = pypw85.contact_function(-r12, q2, q1)
    assert mu2_s == mu2, (mu2, mu2_s)
    assert abs(lam_s - (1.0 - lam)) <= 4 * EPS, (lam, lam_s)


@PROPERTY
@given(pairs(), st.integers(-60, 60))
def test_scaling_by_powers_of_two(pair, k):
    """Every length times 2^k (r12·2^k, Q·4^k, both exact): μ² and λ
    bit-identical."""
    r12, q1, q2 = pair
    mu2, lam = pypw85.contact_function(r12, q1, q2)
    scaled = pypw85.contact_function(np.ldexp(r12, k), np.ldexp(q1, 2 * k),
                                     np.ldexp(q2, 2 * k))
    assert (scaled[0], scaled[1]) == (mu2, lam), (k, mu2, lam, scaled)


@PROPERTY
@given(pairs())
def test_lower_bound(pair):
    """μ² ≥ |r12|²/(√tr Q1 + √tr Q2)² (pw85.h), up to the few roundings of
    the bound's own evaluation here."""
    r12, q1, q2 = pair
    mu2, _ = pypw85.contact_function(r12, q1, q2)
    tr1 = q1[0] + q1[3] + q1[5]
    tr2 = q2[0] + q2[3] + q2[5]
    bound = float(r12 @ r12) / (math.sqrt(tr1) + math.sqrt(tr2)) ** 2
    assert mu2 >= bound * (1.0 - 8 * EPS), (mu2, bound)


# Inputs the library rejects -------------------------------------------------

def _assert_rejected(status, r12, q1, q2):
    """contact_function and overlap raise Error(status); out untouched."""
    out = np.array([-7.0, -7.0])
    with pytest.raises(pypw85.Error) as info:
        pypw85.contact_function(r12, q1, q2, out=out)
    assert info.value.status == status, (info.value, status)
    assert out.tolist() == [-7.0, -7.0]
    with pytest.raises(pypw85.Error) as info:
        pypw85.overlap(r12, q1, q2)
    assert info.value.status == status, (info.value, status)


@ERRORS
@given(pairs(), st.integers(0, 14),
       st.sampled_from([math.nan, math.inf, -math.inf]))
def test_not_finite_is_edom(pair, position, bad):
    """A NaN or an infinity anywhere among the 15 inputs: EDOM."""
    values = np.concatenate(pair)
    values[position] = bad
    _assert_rejected(pypw85.EDOM, values[:3], values[3:9], values[9:])


@ERRORS
@given(pairs(), rotations(), st.tuples(semi_axis, semi_axis, semi_axis),
       st.integers(0, 2), st.booleans(), st.booleans())
def test_indefinite_is_enotposdef(pair, rot, axes, negative, second,
                                  negative_definite):
    """A form with a negative eigenvalue (or negative definite) in place of
    q1 or q2: ENOTPOSDEF."""
    r12, q1, q2 = pair
    squares = np.array(axes) ** 2
    if negative_definite:
        squares = -squares
    else:
        squares[negative] = -squares[negative]
    bad = form(rot, squares)
    if second:
        _assert_rejected(pypw85.ENOTPOSDEF, r12, q1, bad)
    else:
        _assert_rejected(pypw85.ENOTPOSDEF, r12, bad, q2)
