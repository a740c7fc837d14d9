# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.d2, the ellipses of pw85_2d.h.

Against the mpmath references of data/pw85_2d_pairs.h5 and
data/pw85_2d_geometry.h5 (data/gen_2d_data.py, independent of the
library), with the tolerances that pw85_2d.h promises and
tests/test-2d-ref-data.c holds the C functions to: every output through
the batch path and, on a seeded sample, through the single-pair path,
which must give the same bits. Then the conventions of pypw85: shapes,
broadcasting, preallocated outputs, threads, and every error path. The
constants against the header, parsed.
"""

import os

import numpy as np
import pytest

import pypw85
from pypw85 import d2

from conftest import SOURCE_ROOT
from test_constants import header_numbers

h5py = pytest.importorskip("h5py", reason="h5py reads the reference data "
                           "(Debian: python3-h5py)")

U = 2.0 ** -53
HEADER = SOURCE_ROOT / "include" / "pw85" / "pw85_2d.h"


def data_file(variable, name):
    path = os.environ.get(variable)
    if path:  # set by meson: a missing file is a failure
        return path
    path = SOURCE_ROOT / "data" / name
    if not path.exists():
        pytest.skip("no %s (set %s)" % (path, variable))
    return path


@pytest.fixture(scope="module")
def pairs():
    with h5py.File(data_file("PW85_2D_PAIRS", "pw85_2d_pairs.h5"), "r") as h:
        return {k: h[k][...] for k in h}


@pytest.fixture(scope="module")
def geometry():
    with h5py.File(data_file("PW85_2D_GEOMETRY", "pw85_2d_geometry.h5"),
                   "r") as h:
        out = {k: h[k][...] for k in h if isinstance(h[k], h5py.Dataset)}
        out.update({"constructors/" + k: v[...]
                    for k, v in h["constructors"].items()})
    return out


def sample(n, k, seed):
    return np.random.default_rng(seed).choice(n, k, replace=False)


# ---------------------------------------------------------------------------
# Constants.

def test_constants_match_header():
    """Every numeric PW85_2D_* macro of pw85_2d.h is d2.<NAME>, same value
    and type, and d2 has no other numeric constant."""
    numbers = {name[3:]: value for name, value in
               header_numbers(HEADER).items() if name.startswith("2D_")}
    assert {"DIM", "SYM", "GEOM_SIZE", "DERIV_SIZE"} <= set(numbers)
    for name, value in numbers.items():
        assert getattr(d2, name) == value and \
            type(getattr(d2, name)) is type(value), name
    mine = {name for name in d2.__all__ if name.isupper()}
    assert mine == set(numbers)


# ---------------------------------------------------------------------------
# The reference pairs.

def test_contact_function_ref(pairs):
    """μ² bit-equal to MU2 on all 3000 pairs (correct rounding, pw85_2d.h);
    λ within LAMBDA_WINDOW + one ulp of λ* (where f is within an ulp of
    μ²; test-2d-ref-data measures at most 0.17 window)."""
    out = d2.contact_function(pairs["R12"], pairs["Q1"], pairs["Q2"])
    assert out.shape == (len(pairs["MU2"]), 2)
    bad = np.flatnonzero(out[:, 0] != pairs["MU2"])
    assert bad.size == 0, (bad[:5], out[bad[:5], 0], pairs["MU2"][bad[:5]])
    star = pairs["LAMBDA"]
    tol = pairs["LAMBDA_WINDOW"] + np.spacing(star)
    err = np.abs(out[:, 1] - star)
    assert (err <= tol).all(), np.flatnonzero(err > tol)[:5]
    # The swapped call: the same μ², bit for bit.
    sw = d2.contact_function(-pairs["R12"], pairs["Q2"], pairs["Q1"],
                             threads=2)
    assert (sw[:, 0] == out[:, 0]).all()


def test_single_pair_path_same_bits(pairs):
    """The single-pair path (pw85_2d_contact_function, ...) gives the
    batch's bits, and the reference's μ²."""
    for i in sample(len(pairs["MU2"]), 60, 2901):
        r, q1, q2 = pairs["R12"][i], pairs["Q1"][i], pairs["Q2"][i]
        one = d2.contact_function(r, q1, q2)
        assert one.shape == (2,)
        assert one[0] == pairs["MU2"][i], i
        many = d2.contact_function(r[None], q1, q2)
        assert many.shape == (1, 2) and (many[0] == one).all(), i
        assert d2.overlap(r, q1, q2) == d2.overlap(r[None], q1, q2)[0]
        g = d2.contact_geometry(r, q1, q2)
        assert (g == d2.contact_geometry(r[None], q1, q2)[0]).all()
        assert g[d2.GEOM_MU2] == one[0]
        gd, d = d2.contact_derivatives(r, q1, q2)
        gb, db = d2.contact_derivatives(r[None], q1, q2)
        assert (gd == g).all() and (gb[0] == g).all() and (db[0] == d).all()


def test_overlap_ref(pairs):
    """The verdict is the sign of μ² − 1 (MU2_MINUS_1), 0 allowed in the
    4-ulp band only."""
    result = d2.overlap(pairs["R12"], pairs["Q1"], pairs["Q2"])
    assert result.dtype == np.intc
    sign = np.sign(pairs["MU2_MINUS_1"]).astype(int)
    band = np.abs(pairs["MU2_MINUS_1"]) <= 4 * np.finfo(float).eps
    ok = (result == sign) | (band & (result == 0))
    assert ok.all(), np.flatnonzero(~ok)[:5]
    assert (sign == 1).any() and (sign == -1).any()


def test_f_ref(pairs):
    """f at the four λ of F_LAMBDA, bit-equal to F where the inputs meet
    pw85_2d_f_neg's range (no rescaling: entries and |r12|² in [1e-150,
    1e150]), on a seeded sample of 300 pairs."""
    checked = 0
    for i in sample(len(pairs["MU2"]), 300, 29):
        r, q1, q2 = pairs["R12"][i], pairs["Q1"][i], pairs["Q2"][i]
        entries = np.abs(np.concatenate((q1, q2)))
        entries = entries[entries != 0]
        r2 = float(r @ r)
        if not ((entries >= 1e-150) & (entries <= 1e150)).all() or \
                not 1e-150 <= r2 <= 1e150:
            continue
        for lam, ref in zip(pairs["F_LAMBDA"][i], pairs["F"][i]):
            assert d2.f(lam, r, q1, q2) == ref, (i, lam)
            assert d2.f_neg(lam, r, q1, q2) == -ref, (i, lam)
        checked += 1
    assert checked > 200


def dist(x, y):
    """‖x − y‖ along the last axis, scaled against overflow."""
    diff = np.abs(np.asarray(x) - np.asarray(y)).reshape(len(x), -1)
    m = diff.max(axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        s = np.sqrt(((diff / np.where(m == 0, 1, m)[:, None]) ** 2)
                    .sum(axis=1))
    return m * s


def test_geometry_ref(geometry):
    """contact_derivatives on the 400 pairs of pw85_2d_geometry.h5: μ²
    bit-equal; each block (point, normal, ∂μ²/∂r12, ∂μ²/∂θᵢ, ∂μ²/∂qᵢ)
    within 8·u·(cond(Q(λ*)) + 1/min(λ*, 1 − λ*)) of its norm (torques: of
    |∂μ²/∂r12|·|x − cᵢ| where larger), the bound test-2d-ref-data holds
    the C function to (pw85_2d.h measures at most 1.1 of the unit)."""
    g, d = d2.contact_derivatives(geometry["R12"], geometry["Q1"],
                                  geometry["Q2"], threads=2)
    n = len(geometry["MU2"])
    assert g.shape == (n, d2.GEOM_SIZE) and d.shape == (n, d2.DERIV_SIZE)
    assert (g[:, d2.GEOM_MU2] == geometry["MU2"]).all()
    star, oml = geometry["LAMBDA"], geometry["ONE_MINUS_LAMBDA"]
    scale = U * (np.maximum(1.0, geometry["COND_Q"])
                 + 1.0 / np.minimum(star, oml))
    zero = np.zeros((n, 2))
    grad = dist(geometry["D_R12"], zero)
    arm1 = dist(geometry["POINT"], zero)
    arm2 = dist(geometry["POINT"], geometry["R12"])
    p, nn = d2.GEOM_POINT, d2.GEOM_NORMAL
    blocks = [
        ("point", g[:, p:p + 2], geometry["POINT"], None),
        ("normal", g[:, nn:nn + 2], geometry["NORMAL"], None),
        ("d_r12", d[:, d2.DERIV_R12:d2.DERIV_R12 + 2], geometry["D_R12"],
         None),
        ("d_theta1", d[:, d2.DERIV_THETA1], geometry["D_THETA1"],
         grad * arm1),
        ("d_theta2", d[:, d2.DERIV_THETA2], geometry["D_THETA2"],
         grad * arm2),
        ("d_q1", d[:, d2.DERIV_Q1:d2.DERIV_Q1 + 3], geometry["D_Q1"], None),
        ("d_q2", d[:, d2.DERIV_Q2:d2.DERIV_Q2 + 3], geometry["D_Q2"], None),
    ]
    for name, got, ref, floor in blocks:
        got = got.reshape(n, -1)
        ref = ref.reshape(n, -1)
        size = dist(ref, np.zeros_like(ref))
        if floor is not None:
            size = np.maximum(size, floor)
        err = dist(got, ref)
        with np.errstate(invalid="ignore", divide="ignore"):
            rel = np.where(err == 0, 0.0, err / size)
        bad = np.flatnonzero(~(rel <= 8 * scale))
        assert bad.size == 0, (name, bad[:5], (rel / scale)[bad[:5]])
    # contact_geometry: the same bits as the geometry of the derivatives.
    assert (d2.contact_geometry(geometry["R12"], geometry["Q1"],
                                geometry["Q2"]) == g).all()


def test_constructors_ref(geometry):
    """ellipse(A, THETA) within the bound of pw85_2d.h,
    2u·(|Q_k| + Σₘ |R_im·R_jm|·aₘ²), of Q exact for the θ given;
    principal_axes(Q): each semi-axis within u·(1 + u·(a0/aⱼ)²) relative
    of EIG_A, θ within 2 ulps of EIG_THETA modulo π (none for circles)."""
    a = geometry["constructors/A"]
    theta = geometry["constructors/THETA"]
    ref = geometry["constructors/Q"]
    q = d2.ellipse(a, theta)
    c, s = np.cos(theta), np.sin(theta)
    a0, a1 = a[:, 0] ** 2, a[:, 1] ** 2
    mag = np.stack([c * c * a0 + s * s * a1, np.abs(c * s) * (a0 + a1),
                    s * s * a0 + c * c * a1], axis=1)
    bound = 2 * U * (np.abs(ref) + mag)
    assert (np.abs(q - ref) <= bound).all()
    for i in sample(len(theta), 20, 3):
        assert (d2.ellipse(a[i], theta[i]) == q[i]).all()

    axes, t = d2.principal_axes(ref)
    ea = geometry["constructors/EIG_A"]
    ratio = ea[:, :1] / ea
    assert (np.abs(axes - ea) <= U * (1 + U * ratio ** 2) * ea).all()
    et = geometry["constructors/EIG_THETA"]
    has = ~np.isnan(et)
    diff = np.abs(t - et)[has]
    diff = np.where(diff > 1.0, np.abs(diff - np.pi), diff)
    assert (diff <= 2 * np.spacing(np.abs(et[has]))).all()
    for i in sample(len(theta), 20, 4):
        one_a, one_t = d2.principal_axes(ref[i])
        assert (one_a == axes[i]).all() and one_t == t[i]
        assert isinstance(one_t, float)


# ---------------------------------------------------------------------------
# Closed forms and conventions.

def test_circles_closed_form():
    """Circles of radii 1 and 2, centres 6 apart: μ² = (6/3)² = 4 exactly,
    λ = 1/3, contact point at distance 1 from c1 on the line of centres,
    normal along r12; turning a circle changes nothing (∂μ²/∂θ = 0)."""
    r = [0.0, 6.0]
    g, d = d2.contact_derivatives(r, [1.0, 0.0, 1.0], [4.0, 0.0, 4.0])
    assert g[d2.GEOM_MU2] == 4.0
    assert abs(g[d2.GEOM_LAMBDA] - 1 / 3) <= 2 * U
    assert np.allclose(g[d2.GEOM_POINT:d2.GEOM_POINT + 2], [0.0, 2.0],
                       rtol=0, atol=4 * U * 2)
    assert np.allclose(g[d2.GEOM_NORMAL:d2.GEOM_NORMAL + 2], [0.0, 1.0],
                       rtol=0, atol=4 * U)
    assert d[d2.DERIV_THETA1] == 0.0 and d[d2.DERIV_THETA2] == 0.0
    # μ² = |r|²/9 ⇒ ∂μ²/∂r12 = 2r/9.
    assert np.allclose(d[d2.DERIV_R12:d2.DERIV_R12 + 2], [0.0, 12 / 9],
                       rtol=4 * U, atol=0)


def test_ellipse_exact_angles():
    """θ = 0: Q = diag(a0², a1²) exactly; principal_axes gives a and 0."""
    assert list(d2.ellipse([3.0, 0.5], 0.0)) == [9.0, 0.0, 0.25]
    a, t = d2.principal_axes([0.25, 0.0, 9.0])  # a[0] along y
    assert list(a) == [3.0, 0.5]
    assert abs(t - np.pi / 2) <= np.spacing(np.pi / 2)


def test_broadcasting_and_threads(rng):
    """One ellipse against many; leading axes broadcast; results as the
    pairs computed one by one; the same bits on 1 and 2 threads."""
    n = 600
    a = rng.uniform(0.1, 2.0, (n, 2))
    theta = rng.uniform(-np.pi, np.pi, n)
    q = d2.ellipse(a, theta, threads=2)
    assert q.shape == (n, 3)
    assert (q == d2.ellipse(a, theta)).all()
    q0 = d2.ellipse([1.0, 0.3], 0.7)
    r = rng.normal(size=(n, 2)) * 2
    out1 = d2.contact_function(r, q0, q)
    out2 = d2.contact_function(r, q0, q, threads=2)
    assert (out1 == out2).all()
    for i in (0, 17, n - 1):
        assert (d2.contact_function(r[i], q0, q[i]) == out1[i]).all()
    grid = d2.contact_function(r.reshape(20, 30, 2), q0,
                               q.reshape(20, 30, 3))
    assert grid.shape == (20, 30, 2)
    assert (grid.reshape(n, 2) == out1).all()
    # (3, 1) against (1, 4): a 3×4 grid.
    cross = d2.overlap(r[:3, None, :], q0, q[None, :4, :])
    assert cross.shape == (3, 4)
    assert cross[2, 3] == d2.overlap(r[2], q0, q[3])
    # The same angle for every item (stride 0).
    same = d2.ellipse(a[:5], 0.25)
    assert (same[3] == d2.ellipse(a[3], 0.25)).all()
    axes, t = d2.principal_axes(q.reshape(30, 20, 3))
    assert axes.shape == (30, 20, 2) and t.shape == (30, 20)


def test_preallocated_outputs():
    q1, q2 = [2.0, 0.1, 1.0], [1.0, -0.2, 3.0]
    out = np.full(2, 7.0)
    assert d2.contact_function([1.0, 2.0], q1, q2, out) is out
    assert out[0] == d2.contact_function([1.0, 2.0], q1, q2)[0]
    g, d = np.empty(d2.GEOM_SIZE), np.empty(d2.DERIV_SIZE)
    assert d2.contact_derivatives([1.0, 2.0], q1, q2, g, d)[1] is d
    with pytest.raises(ValueError, match="out"):
        d2.contact_function([1.0, 2.0], q1, q2, np.empty(3))
    with pytest.raises(TypeError, match="out"):
        d2.contact_function([1.0, 2.0], q1, q2, np.empty(2, np.float32))
    with pytest.raises(ValueError, match="separate"):
        d2.contact_derivatives([1.0, 2.0], q1, q2, d[:d2.GEOM_SIZE], d)
    batch = np.empty((2, 2))
    assert d2.contact_function([[1.0, 2.0], [0.0, 1.0]], q1, q2,
                               batch) is batch
    with pytest.raises(ValueError, match="out"):
        d2.contact_function([[1.0, 2.0], [0.0, 1.0]], q1, q2,
                            np.empty((3, 2)))
    q = np.empty(3)
    assert d2.ellipse([1.0, 2.0], 0.5, q) is q
    # ERANGE with μ² overflowing: out written, {+inf, λ} (pw85_2d.h).
    with pytest.raises(pypw85.Error):
        d2.contact_function([1e300, 0.0], [1e-300, 0.0, 1e-300],
                            [1e-300, 0.0, 1e-300], out)
    assert out[0] == np.inf and 0.0 <= out[1] <= 1.0


# ---------------------------------------------------------------------------
# Errors: each status of pw85_2d.h, and the binding's own checks.

GOOD_R, GOOD_Q1, GOOD_Q2 = [0.7, -1.1], [4.0, 0.5, 0.25], [1.0, -0.3, 2.0]
NOT_SPD = [1.0, 2.0, 1.0]


@pytest.mark.parametrize("call", ["contact_function", "overlap",
                                  "contact_geometry", "contact_derivatives"])
def test_pair_errors(call):
    fn = getattr(d2, call)
    with pytest.raises(pypw85.Error) as e:
        fn([np.nan, 0.0], GOOD_Q1, GOOD_Q2)
    assert e.value.status == pypw85.EDOM and e.value.where == "d2." + call
    with pytest.raises(pypw85.Error) as e:
        fn(GOOD_R, GOOD_Q1, [1.0, np.inf, 1.0])
    assert e.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as e:
        fn(GOOD_R, NOT_SPD, GOOD_Q2)
    assert e.value.status == pypw85.ENOTPOSDEF
    assert "PW85_ENOTPOSDEF" in str(e.value)
    # μ² beyond DBL_MAX: ERANGE (the overlap test answers +1, disjoint).
    huge_r, tiny_q = [1e300, 0.0], [1e-300, 0.0, 1e-300]
    if call == "overlap":
        assert fn(huge_r, tiny_q, tiny_q) == 1
    else:
        with pytest.raises(pypw85.Error) as e:
            fn(huge_r, tiny_q, tiny_q)
        assert e.value.status == pypw85.ERANGE
    # A 3D vector or form is a shape error, before the library is called.
    with pytest.raises(ValueError, match="r12"):
        fn([1.0, 2.0, 3.0], GOOD_Q1, GOOD_Q2)
    with pytest.raises(ValueError, match="q2"):
        fn(GOOD_R, GOOD_Q1, [1.0, 0.0, 0.0, 1.0, 0.0, 1.0])
    with pytest.raises(TypeError, match="q1"):
        fn(GOOD_R, ["a", "b", "c"], GOOD_Q2)


def test_batch_error_names_first_pair():
    r = np.array([GOOD_R, GOOD_R, [0.0, np.nan], GOOD_R])
    q1 = np.array([GOOD_Q1, NOT_SPD, GOOD_Q1, GOOD_Q1])
    out = np.full((4, 2), -1.0)
    with pytest.raises(pypw85.Error) as e:
        d2.contact_function(r, q1, GOOD_Q2, out)
    assert e.value.status == pypw85.ENOTPOSDEF
    assert e.value.index == (1,)
    assert list(e.value.statuses) == [0, pypw85.ENOTPOSDEF, pypw85.EDOM, 0]
    assert (out[0] == d2.contact_function(GOOD_R, GOOD_Q1, GOOD_Q2)).all()
    assert (out[3] == out[0]).all()
    with pytest.raises(ValueError, match="broadcast"):
        d2.overlap(np.zeros((3, 2)), GOOD_Q1, np.ones((4, 3)))
    with pytest.raises(ValueError, match="threads"):
        d2.overlap(np.zeros((3, 2)), GOOD_Q1, GOOD_Q2, threads=-1)
    with pytest.raises(pypw85.Error) as e:
        d2.principal_axes([GOOD_Q1, NOT_SPD])
    assert e.value.index == (1,) and e.value.status == pypw85.ENOTPOSDEF


def test_f_errors():
    with pytest.raises(pypw85.Error) as e:
        d2.f(0.5, [np.nan, 0.0], GOOD_Q1, GOOD_Q2)
    assert e.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as e:
        d2.f_neg(0.5, GOOD_R, NOT_SPD, GOOD_Q2)
    assert e.value.status == pypw85.ENOTPOSDEF
    with pytest.raises(TypeError, match="lambda_"):
        d2.f("0.5", GOOD_R, GOOD_Q1, GOOD_Q2)


def test_constructor_errors():
    for a, theta, status in [([0.0, 1.0], 0.0, pypw85.EINVAL),
                             ([1.0, -2.0], 0.0, pypw85.EINVAL),
                             ([1.0, 2.0], np.nan, pypw85.EDOM),
                             ([np.inf, 2.0], 0.0, pypw85.EDOM),
                             ([1e200, 2.0], 0.0, pypw85.ERANGE)]:
        q = np.full(3, 5.0)
        with pytest.raises(pypw85.Error) as e:
            d2.ellipse(a, theta, q)
        assert e.value.status == status, (a, theta)
        assert (q == 5.0).all()  # untouched
    with pytest.raises(pypw85.Error) as e:
        d2.ellipse([[1.0, 1.0], [1.0, 0.0]], [0.0, 1.0])
    assert e.value.status == pypw85.EINVAL and e.value.index == (1,)
    with pytest.raises(pypw85.Error) as e:
        d2.principal_axes([1.0, 0.0, np.nan])
    assert e.value.status == pypw85.EDOM
    with pytest.raises(pypw85.Error) as e:
        d2.principal_axes(NOT_SPD)
    assert e.value.status == pypw85.ENOTPOSDEF
    with pytest.raises(ValueError, match="a"):
        d2.ellipse([1.0, 2.0, 3.0], 0.0)
    with pytest.raises(TypeError, match="theta"):
        d2.ellipse([1.0, 2.0], "0")


# ---------------------------------------------------------------------------
# tutorial/expected-ellipses.txt, the output that the tests ellipses-c and
# ellipses-py compare the tutorials' with, recomputed here in mpmath (40
# digits), from the tutorial's data and the definitions only: Q = R·diag(a²)
# ·Rᵀ; μ² = max f by a root of f′ in [0, 1]; x − c1 = (1 − λ)·Q1·s and
# n = s/‖s‖ (docs: "Theory"); the derivatives of μ² by central
# differences of μ² itself; the verdicts from t²·μ² − 1.

def test_tutorial_expected_output():
    mpmath = pytest.importorskip("mpmath", reason="mpmath recomputes the "
                                 "expected output (Debian: python3-mpmath)")
    mp = mpmath.mp
    mp.dps = 40

    def form(a, theta):
        c, s = mpmath.cos(theta), mpmath.sin(theta)
        r = mpmath.matrix([[c, -s], [s, c]])
        return r * mpmath.diag([a[0] ** 2, a[1] ** 2]) * r.T

    def contact(r, q1, q2):
        def s_of(lam):
            return mpmath.lu_solve((1 - lam) * q1 + lam * q2, r)

        def fprime(lam):  # (1 − λ)²·sᵀQ1s − λ²·sᵀQ2s
            s = s_of(lam)
            return ((1 - lam) ** 2 * (s.T * q1 * s)[0]
                    - lam ** 2 * (s.T * q2 * s)[0])
        lam = mpmath.findroot(fprime, (mpmath.mpf(0), mpmath.mpf(1)),
                              solver="anderson")
        s = s_of(lam)
        return lam * (1 - lam) * (r.T * s)[0], lam, s

    deg = mpmath.pi / 180
    a1, t1 = [mpmath.mpf(2), mpmath.mpf("0.5")], 30 * deg
    a2, t2 = [mpmath.mpf("1.2"), mpmath.mpf("0.6")], -45 * deg
    q1, q2 = form(a1, t1), form(a2, t2)
    r12 = mpmath.matrix([3, mpmath.mpf("1.5")])
    mu2, lam, s = contact(r12, q1, q2)
    x = (1 - lam) * q1 * s
    n = s / mpmath.norm(s)

    half = r12 / 2
    mu2h = contact(half, q1, q2)[0]
    h = mpmath.mpf("1e-15")

    def d_mu2(shift):
        plus, minus = shift(h), shift(-h)
        return (contact(*plus)[0] - contact(*minus)[0]) / (2 * h)
    e0, e1 = mpmath.matrix([1, 0]), mpmath.matrix([0, 1])
    d_r = [d_mu2(lambda e: (half + e * v, q1, q2)) for v in (e0, e1)]
    d_t1 = d_mu2(lambda e: (half, form(a1, t1 + e), q2))
    d_t2 = d_mu2(lambda e: (half, q1, form(a2, t2 + e)))
    du = -2 * (1 - mu2h)
    verdicts = ["%+d" % (1 if (k / mpmath.mpf(4)) ** 2 * mu2 > 1 else -1)
                for k in range(1, 7)]

    def f6(v):
        return "%.6f" % float(v)
    expected = [
        "q1 = (%s, %s, %s)" % (f6(q1[0, 0]), f6(q1[0, 1]), f6(q1[1, 1])),
        "q2 = (%s, %s, %s)" % (f6(q2[0, 0]), f6(q2[0, 1]), f6(q2[1, 1])),
        "E2: semi-axes (%s, %s), angle %s degrees" % (f6(a2[0]), f6(a2[1]),
                                                      f6(t2 / deg)),
        "mu^2 = %s, lambda = %s: %s" % (
            f6(mu2), f6(lam),
            "they are disjoint" if mu2 > 1 else "they overlap"),
        "x - c1 = (%s, %s)" % (f6(x[0]), f6(x[1])),
        "n = (%s, %s)" % (f6(n[0]), f6(n[1])),
        "at r12/2: mu^2 = %s, force on E2 = (%s, %s), torques %s, %s" % (
            f6(mu2h), f6(-du * d_r[0]), f6(-du * d_r[1]), f6(-du * d_t1),
            f6(-du * d_t2)),
        "overlap at t = 0.25, 0.5, ..., 1.5: " + " ".join(verdicts),
    ]
    path = SOURCE_ROOT / "tutorial" / "expected-ellipses.txt"
    assert path.read_text().splitlines() == expected
