# SPDX-License-Identifier: BSD-3-Clause
"""Arrays of pairs (issue 17): broadcasting, results bit for bit those of
single calls for any thread count, errors naming the first failing pair,
outputs, conversions, n = 0."""

import ctypes
import pickle

import numpy as np
import pytest

import pypw85
from conftest import random_spd

FUNCTIONS = ["contact_function", "overlap", "contact_geometry",
             "contact_derivatives"]


def single(name, r12, q1, q2):
    """The results of one pair, as one flat float64 array."""
    result = getattr(pypw85, name)(r12, q1, q2)
    if name == "overlap":
        return np.array([result], dtype=np.float64)
    if name == "contact_derivatives":
        return np.concatenate(result)
    return result


def batch(name, r12, q1, q2, **kwargs):
    """The results of an array of pairs, flat per pair: shape S + (k,)."""
    result = getattr(pypw85, name)(r12, q1, q2, **kwargs)
    if name == "overlap":
        assert result.dtype == np.intc
        return result[..., None].astype(np.float64)
    if name == "contact_derivatives":
        return np.concatenate(result, axis=-1)
    return result


@pytest.fixture
def pairs(rng):
    """40 random pairs, some overlapping, some not."""
    n = 40
    r12 = rng.uniform(-3.0, 3.0, (n, 3))
    q1 = np.array([random_spd(rng) for _ in range(n)])
    q2 = np.array([random_spd(rng, 0.3) for _ in range(n)])
    return r12, q1, q2


@pytest.mark.parametrize("name", FUNCTIONS)
@pytest.mark.parametrize("threads", [1, 2, 8, 0])
def test_same_as_single_calls(name, threads, pairs):
    r12, q1, q2 = pairs
    result = batch(name, r12, q1, q2, threads=threads)
    expected = np.array([single(name, *p) for p in zip(r12, q1, q2)])
    assert result.shape == expected.shape
    assert np.array_equal(result, expected)  # bit for bit


@pytest.mark.parametrize("name", FUNCTIONS)
def test_many_threads_bit_identical(name, rng):
    """Enough pairs for several threads (256 per thread at least)."""
    n = 1500
    r12 = rng.uniform(-4.0, 4.0, (n, 3))
    q1 = np.array([random_spd(rng) for _ in range(n)])
    q2 = random_spd(rng, 0.2)
    one = batch(name, r12, q1, q2, threads=1)
    for threads in (2, 8, 0):
        assert np.array_equal(batch(name, r12, q1, q2, threads=threads), one)
    # Spot checks against single calls.
    for i in (0, 777, n - 1):
        assert np.array_equal(one[i], single(name, r12[i], q1[i], q2))


@pytest.mark.parametrize("name", FUNCTIONS)
def test_broadcasting(name, pairs):
    r12, q1, q2 = pairs
    a, b = r12[:4].reshape(4, 1, 3), q2[:5]  # (4, 1, 3) with (5, 6)
    result = batch(name, a, q1[0], b)
    assert result.shape[:2] == (4, 5)
    for i in range(4):
        for j in range(5):
            assert np.array_equal(result[i, j],
                                  single(name, a[i, 0], q1[0], b[j]))
    # Leading axes of length 1 against the broadcast shape; lists.
    result = batch(name, r12[:3].tolist(), q1[None, :3], q2[0][None])
    for i in range(3):
        assert np.array_equal(result[0, i], single(name, r12[i], q1[i], q2[0]))
    # Inputs to be copied: not contiguous; broadcast along one axis only.
    wide = np.repeat(r12[:6], 2, axis=0)[::2]
    assert not wide.flags.c_contiguous
    result = batch(name, wide.reshape(2, 3, 3), q1[:3], q2[:2, None])
    assert result.shape[:2] == (2, 3)
    for i in range(2):
        for j in range(3):
            assert np.array_equal(result[i, j],
                                  single(name, r12[3 * i + j], q1[j], q2[i]))


@pytest.mark.parametrize("name", FUNCTIONS)
def test_conversions(name, pairs):
    r12, q1, q2 = pairs
    expected = batch(name, r12, q1, q2)
    assert np.array_equal(batch(name, r12.astype(">f8"), q1, q2), expected)
    assert np.array_equal(batch(name, np.asfortranarray(r12), q1, q2),
                          expected)
    assert np.array_equal(batch(name, r12, q1.astype(np.float32), q2),
                          batch(name, r12, q1.astype(np.float32)
                                .astype(np.float64), q2))
    ints = np.array([[1, 2, 2]] * 3)
    assert np.array_equal(batch(name, ints, q1[0], q2[0])[1],
                          single(name, [1.0, 2.0, 2.0], q1[0], q2[0]))


@pytest.mark.parametrize("name", FUNCTIONS)
def test_empty(name, pairs):
    r12, q1, q2 = pairs
    result = getattr(pypw85, name)(r12[:0], q1[0], q2[:0], threads=0)
    shapes = {"contact_function": [(0, 2)], "overlap": [(0,)],
              "contact_geometry": [(0, pypw85.GEOM_SIZE)],
              "contact_derivatives": [(0, pypw85.GEOM_SIZE),
                                      (0, pypw85.DERIV_SIZE)]}[name]
    results = result if isinstance(result, tuple) else (result,)
    assert [x.shape for x in results] == shapes


def bad_pairs(pairs):
    """Copies of the pairs with failures at 7 (EDOM), 12 (ENOTPOSDEF), 30
    (ERANGE: entries spanning more than a double's range)."""
    r12, q1, q2 = (x.copy() for x in pairs)
    r12[7, 1] = np.inf
    q1[12] = [1.0, 2.0, 0.0, 1.0, 0.0, 1.0]
    q1[30] = [1e308, 0.0, 0.0, 1e308, 0.0, 1e308]
    q2[30] = [5e-324, 0.0, 0.0, 5e-324, 0.0, 5e-324]
    return r12, q1, q2


@pytest.mark.parametrize("name", FUNCTIONS)
@pytest.mark.parametrize("threads", [1, 2])
def test_first_failure(name, threads, pairs):
    r12, q1, q2 = bad_pairs(pairs)
    with pytest.raises(pypw85.Error) as info:
        getattr(pypw85, name)(r12.reshape(5, 8, 3), q1.reshape(5, 8, 6),
                              q2.reshape(5, 8, 6),
                              threads=threads)
    e = info.value
    assert e.status == pypw85.EDOM
    assert e.index == (0, 7)
    assert e.where == name
    message = str(e)
    assert message.startswith(name + ": ")
    assert "pair (0, 7) of (5, 8) (3 of 40 failed)" in message
    assert "r12 = array([" in message and "inf" in message
    statuses = np.zeros(40, dtype=np.intc)
    statuses[[7, 12, 30]] = [pypw85.EDOM, pypw85.ENOTPOSDEF, pypw85.ERANGE]
    assert np.array_equal(e.statuses, statuses.reshape(5, 8))
    e2 = pickle.loads(pickle.dumps(e))
    assert str(e2) == message and e2.index == (0, 7)
    # Without the first: the next one.
    r12[7, 1] = 0.5
    with pytest.raises(pypw85.Error) as info:
        getattr(pypw85, name)(r12, q1, q2, threads=threads)
    assert (info.value.status, info.value.index) == (pypw85.ENOTPOSDEF, (12,))


def test_failure_keeps_other_results(pairs):
    r12, q1, q2 = bad_pairs(pairs)
    out = np.full((40, 2), -1.0)
    with pytest.raises(pypw85.Error):
        pypw85.contact_function(r12, q1, q2, out)
    for i in range(40):
        if i in (7, 12, 30):
            assert np.array_equal(out[i], [-1.0, -1.0])  # untouched
        else:
            assert np.array_equal(out[i],
                                  pypw85.contact_function(r12[i], q1[i],
                                                          q2[i]))


def test_outputs(pairs):
    r12, q1, q2 = pairs
    out = np.empty((40, 2))
    assert pypw85.contact_function(r12, q1, q2, out) is out
    g, d = np.empty((40, 8)), np.empty((40, 21))
    result = pypw85.contact_derivatives(r12, q1, q2, g, d)
    assert result[0] is g and result[1] is d
    assert np.array_equal(g, pypw85.contact_geometry(r12, q1, q2))
    for bad, error in [(np.empty((40, 3)), ValueError),
                       (np.empty((2, 40)), ValueError),
                       (np.empty((40, 2), dtype=np.float32), TypeError),
                       (np.empty((40, 2))[::-1], ValueError),
                       ([[0.0, 0.0]] * 40, TypeError)]:
        with pytest.raises(error, match="^out: expected"):
            pypw85.contact_function(r12, q1, q2, bad)
    buffer = np.empty(40 * 29)
    with pytest.raises(ValueError, match="^geometry and d: expected separate"):
        pypw85.contact_derivatives(r12, q1, q2, buffer[:320].reshape(40, 8),
                                   buffer[100:940].reshape(40, 21))


def test_output_aliasing_an_input(pairs):
    """out may share memory with an input: the input is copied first."""
    r12, q1, q2 = pairs
    expected = pypw85.contact_function(r12, q1, q2)
    buffer = np.empty(40 * 6)
    q1_shared = buffer.reshape(40, 6)
    q1_shared[:] = q1
    out = buffer[:80].reshape(40, 2)
    assert pypw85.contact_function(r12, q1_shared, q2, out) is out
    assert np.array_equal(out, expected)


@pytest.mark.parametrize("name", FUNCTIONS)
def test_bad_arrays(name, pairs):
    r12, q1, q2 = pairs
    function = getattr(pypw85, name)
    with pytest.raises(ValueError, match=r"^r12: expected shape \(3,\) or "
                       r"\(\.\.\., 3\), got \(40, 2\)"):
        function(r12[:, :2], q1, q2)
    with pytest.raises(ValueError, match=r"^q2: expected shape \(6,\) or "
                       r"\(\.\.\., 6\), got \(40, 5\)"):
        function(r12, q1, q2[:, :5])
    with pytest.raises(ValueError, match=r"^%s: the leading axes of r12 "
                       r"\(40, 3\), q1 \(39, 6\) and q2 \(40, 6\) do not "
                       r"broadcast" % name):
        function(r12, q1[:39], q2)
    with pytest.raises(TypeError, match=r"^q1: expected real numbers"):
        function(r12, q1.astype(complex), q2)
    for threads, error in [(-1, ValueError), (2**31, ValueError),
                           (1.0, TypeError), (True, TypeError),
                           (None, TypeError)]:
        with pytest.raises(error, match="^threads: expected"):
            function(r12, q1, q2, threads=threads)
    # Each message names the bound that the count breaks.
    with pytest.raises(ValueError, match="positive count, got -1$"):
        function(r12, q1, q2, threads=-1)
    with pytest.raises(ValueError, match=r"at most 2³¹ − 1 \(a C int\), "
                       "got 2147483648$"):
        function(r12, q1, q2, threads=2**31)


def test_batch_threads():
    assert pypw85.batch_threads(1) == 1
    assert pypw85.batch_threads(8, 511) == 1
    assert pypw85.batch_threads(0) >= 1
    assert pypw85.batch_threads(2, 512) in (1, 2)  # 1 without OpenMP
    with pytest.raises(ValueError):
        pypw85.batch_threads(-1)
    with pytest.raises(ValueError):
        pypw85.batch_threads(1, -5)


def test_gil_released_by_ctypes():
    """ctypes releases the GIL around calls through a CDLL (not a PyDLL):
    a batch runs without it."""
    lib = pypw85._lib
    assert isinstance(lib, ctypes.CDLL) and not isinstance(lib, ctypes.PyDLL)


def test_scalar_calls_unchanged(pairs):
    r12, q1, q2 = pairs
    assert pypw85.contact_function(r12[0], q1[0], q2[0]).shape == (2,)
    assert type(pypw85.overlap(r12[0], q1[0], q2[0])) is int
    assert pypw85.contact_geometry(list(r12[0]), q1[0], q2[0]).shape == (8,)


# The constructors and principal_axes on arrays (pw85_*_batch of the
# ellipsoids): the same items bit for bit as single calls, broadcasting,
# the first failure named, scalar calls unchanged.

def random_rotation(rng):
    """A rotation matrix (3, 3) from a random unit quaternion."""
    p = rng.normal(size=4)
    w, x, y, z = p / np.linalg.norm(p)
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


@pytest.fixture
def ellipsoids(rng):
    """600 items (more than two chunks of 256) for each constructor."""
    n = 600
    axes = 10.0 ** rng.uniform(-2.0, 2.0, (n, 3))
    rot = np.array([random_rotation(rng) for _ in range(n)])
    p = rng.normal(size=(n, 4))
    p /= np.linalg.norm(p, axis=1)[:, None]
    unit = rng.normal(size=(n, 3))
    unit /= np.linalg.norm(unit, axis=1)[:, None]
    q = np.array([random_spd(rng) for _ in range(n)])
    return {"a": axes[:, 0], "c": axes[:, 1], "n": unit, "axes": axes,
            "rot": rot, "p": p, "q": q}


# name, its array arguments (keys of the fixture), and the items' results
# as one flat float64 array.
CONSTRUCTORS = {
    "spheroid": ("a", "c", "n"),
    "ellipsoid_rotation": ("axes", "rot"),
    "ellipsoid_quaternion": ("axes", "p"),
    "principal_axes": ("q",),
}


def flat(name, result, lead):
    if name == "principal_axes":
        a, rot = result
        return np.concatenate([a.reshape(lead + (3,)),
                               rot.reshape(lead + (9,))], axis=-1)
    return result


@pytest.mark.parametrize("name", CONSTRUCTORS)
@pytest.mark.parametrize("threads", [1, 2, 8, 0])
def test_constructors_same_as_single_calls(name, threads, ellipsoids):
    args = [ellipsoids[k] for k in CONSTRUCTORS[name]]
    function = getattr(pypw85, name)
    result = flat(name, function(*args, threads=threads), (600,))
    expected = np.array([flat(name, function(*item), ())
                         for item in zip(*args)])
    assert result.shape == expected.shape
    assert np.array_equal(result, expected)  # bit for bit
    # Leading axes (20, 30): the same numbers in that shape.
    shaped = [x.reshape((20, 30) + x.shape[1:]) for x in args]
    result2 = flat(name, function(*shaped, threads=threads), (20, 30))
    assert np.array_equal(result2.reshape(600, -1), expected)


def test_constructors_broadcasting(ellipsoids):
    e = ellipsoids
    # One axis of revolution for every spheroid, and one radius c.
    q = pypw85.spheroid(e["a"], 2.0, e["n"][3])
    assert q.shape == (600, 6)
    for i in (0, 299, 599):
        assert np.array_equal(q[i], pypw85.spheroid(e["a"][i], 2.0,
                                                    e["n"][3]))
    # One rotation (3, 3) or flat (9,), many semi-axes; and a grid.
    for rot in (e["rot"][5], e["rot"][5].reshape(9)):
        q = pypw85.ellipsoid_rotation(e["axes"], rot)
        assert q.shape == (600, 6)
        assert np.array_equal(q[17], pypw85.ellipsoid_rotation(e["axes"][17],
                                                               e["rot"][5]))
    q = pypw85.ellipsoid_quaternion(e["axes"][:4, None], e["p"][None, :3])
    assert q.shape == (4, 3, 6)
    assert np.array_equal(q[2, 1], pypw85.ellipsoid_quaternion(e["axes"][2],
                                                               e["p"][1]))
    a, rot = pypw85.principal_axes(e["q"][:12].reshape(3, 4, 6))
    assert a.shape == (3, 4, 3) and rot.shape == (3, 4, 3, 3)


@pytest.mark.parametrize("threads", [1, 2])
def test_constructors_first_failure(threads, ellipsoids):
    e = {k: v.copy() for k, v in ellipsoids.items()}
    e["axes"][300, 1] = -1.0        # EINVAL
    e["p"][450] *= 2.0              # EINVAL
    e["axes"][500, 0] = np.nan      # EDOM
    with pytest.raises(pypw85.Error) as info:
        pypw85.ellipsoid_quaternion(e["axes"].reshape(2, 300, 3),
                                    e["p"].reshape(2, 300, 4),
                                    threads=threads)
    err = info.value
    assert (err.status, err.index, err.where) == (
        pypw85.EINVAL, (1, 0), "ellipsoid_quaternion")
    assert "item (1, 0) of (2, 300) (3 of 600 failed): a = array([" \
        in str(err)
    expected = np.zeros(600, dtype=np.intc)
    expected[[300, 450, 500]] = [pypw85.EINVAL, pypw85.EINVAL, pypw85.EDOM]
    assert np.array_equal(err.statuses.reshape(600), expected)
    # A failing item's q untouched, the others computed.
    q = np.full((600, 6), -7.0)
    e["q"][10] = [1.0, 2.0, 0.0, 1.0, 0.0, 1.0]  # not positive definite
    with pytest.raises(pypw85.Error) as info:
        pypw85.ellipsoid_rotation(e["axes"], e["rot"], q, threads=threads)
    assert (info.value.status, info.value.index) == (pypw85.EINVAL, (300,))
    assert np.array_equal(q[300], np.full(6, -7.0))
    assert np.array_equal(q[299], pypw85.ellipsoid_rotation(e["axes"][299],
                                                            e["rot"][299]))
    with pytest.raises(pypw85.Error) as info:
        pypw85.principal_axes(e["q"], threads=threads)
    assert (info.value.status, info.value.index) == (pypw85.ENOTPOSDEF, (10,))
    c = np.ones(600)
    c[77] = np.inf
    with pytest.raises(pypw85.Error) as info:
        pypw85.spheroid(e["a"], c, e["n"], threads=threads)
    assert (info.value.status, info.value.index) == (pypw85.EDOM, (77,))


def test_constructors_bad_arrays(ellipsoids):
    e = ellipsoids
    with pytest.raises(ValueError, match=r"^rot: expected shape \(3, 3\) or "
                       r"\(\.\.\., 3, 3\), got \(600, 9\)"):
        pypw85.ellipsoid_rotation(e["axes"], e["rot"].reshape(600, 9))
    with pytest.raises(ValueError, match=r"^spheroid: the leading axes of "
                       r"a \(600,\), c \(599,\) and n \(600, 3\) do not "
                       r"broadcast"):
        pypw85.spheroid(e["a"], e["c"][:599], e["n"])
    with pytest.raises(ValueError, match="^threads: expected"):
        pypw85.principal_axes(e["q"], threads=-1)


def test_constructors_scalar_calls_unchanged(ellipsoids):
    e = ellipsoids
    assert pypw85.spheroid(1.0, 2.0, [0.0, 0.0, 1.0]).shape == (6,)
    assert pypw85.ellipsoid_rotation(e["axes"][0], e["rot"][0]).shape == (6,)
    assert pypw85.ellipsoid_quaternion(e["axes"][0], e["p"][0]).shape == (6,)
    a, rot = pypw85.principal_axes(e["q"][0])
    assert a.shape == (3,) and rot.shape == (3, 3)
    # An empty batch.
    assert pypw85.ellipsoid_quaternion(np.ones((0, 3)),
                                       e["p"][0]).shape == (0, 6)
