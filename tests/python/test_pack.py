# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.pack and Index.energy: packings checked by a brute force over
every pair and image (pypw85.overlap), determinism, outcomes, callbacks,
errors naming their argument; energies against central differences and
the C path."""

import itertools

import numpy as np
import pytest

import pypw85


def brute_overlaps(p, overlap=pypw85.overlap):
    """Overlapping or tangent (i, j, shift), by overlap (pypw85.overlap, or
    pypw85.d2.overlap for a packing of ellipses) on every pair i < j and
    image shift in {-1, 0, 1}^D (enough: centres in [0, L), box wider than
    twice the largest semi-axis), in one batch call."""
    n, dim = p.centres.shape
    i, j = np.triu_indices(n, 1)
    shifts = np.array(list(itertools.product((-1, 0, 1), repeat=dim)))
    r = (p.centres[j][:, None, :] + shifts[None, :, :] * p.box
         - p.centres[i][:, None, :])
    res = overlap(r, p.forms[i][:, None, :], p.forms[j][:, None, :])
    return np.argwhere(res <= 0)


def semi_axes(n, shape=(1.0, 0.5, 0.2), poly=False):
    s = 1.0 + 2.0 * (np.arange(n) % 5) / 4.0 if poly else np.ones(n)
    return s[:, None] * np.asarray(shape)[None, :]


@pytest.mark.parametrize("shape,target,orientation,poly", [
    ((1.0, 1.0, 1.0), 0.55, "isotropic", False),
    ((1.0, 0.5, 0.2), 0.50, "isotropic", True),
    ((1.0, 0.2, 0.2), 0.50, "aligned", False),
])
def test_pack_target(shape, target, orientation, poly):
    a = semi_axes(200, shape, poly)
    p = pypw85.pack(a, target, seed=5, orientation=orientation)
    assert p.outcome == "target"
    assert p.phi == pytest.approx(target, rel=1e-14)
    assert len(brute_overlaps(p)) == 0
    assert np.all((p.centres >= 0) & (p.centres < p.box))
    # the forms are ellipsoid_quaternion of the outputs, bit for bit
    q = np.array([pypw85.ellipsoid_quaternion(a[k], p.quaternions[k])
                  for k in range(len(a))])
    assert np.array_equal(q, p.forms)
    if orientation == "aligned":
        # the largest semi-axis (first) along z: column 0 of R(p)
        w, x, y, z = p.quaternions.T
        assert np.allclose(np.abs(2 * (x * z - w * y)), 1.0, atol=1e-9)


def test_pack_deterministic():
    a = semi_axes(150, (1.0, 0.6, 0.3), poly=True)
    p1 = pypw85.pack(a, 0.5, seed=11)
    p2 = pypw85.pack(a, 0.5, seed=11, threads=2)
    p3 = pypw85.pack(a, 0.5, seed=12)
    for x, y in zip(p1[:4], p2[:4]):
        assert np.array_equal(x, y)
    assert not np.array_equal(p1.centres, p3.centres)


def test_pack_progress_and_limits():
    a = semi_axes(150, (1.0, 1.0, 1.0))
    seen = []

    def progress(info):
        seen.append(info)
        return len(seen) == 2  # stop at the second call
    p = pypw85.pack(a, 0.6, progress=progress, progress_every=3)
    assert p.outcome == "cancelled" and len(seen) == 2
    assert seen[1]["steps"] == 6 and seen[0]["phi_trial"] == 0.6
    assert 0 < p.phi < 0.6 and len(brute_overlaps(p)) == 0
    p = pypw85.pack(a, 0.6, step_limit=10)
    assert p.outcome == "limit" and len(brute_overlaps(p)) == 0

    class Stop(Exception):
        pass

    def boom(info):
        raise Stop()
    with pytest.raises(Stop):
        pypw85.pack(a, 0.6, progress=boom)


@pytest.mark.parametrize("kwargs,kind,words", [
    ({"semi_axes": np.ones((0, 3))}, pypw85.Error, "n = 0"),
    ({"semi_axes": [[1, 1, -1]]}, pypw85.Error, "semi_axes[0]"),
    ({"semi_axes": [[1, 1, np.nan]]}, pypw85.Error, "not finite"),
    ({"semi_axes": [1, 1, 1]}, ValueError, "shape (n, 3)"),
    ({"target": 0.0}, pypw85.Error, "target"),
    ({"target": 1.0}, pypw85.Error, "target"),
    ({"orientation": "random"}, pypw85.Error, "orientation"),
    ({"aspect": (1, 0, 1)}, pypw85.Error, "aspect[1]"),
    ({"aspect": (1, 1, 1e-6)}, pypw85.Error, "L_2"),
    ({"axis": (0, 0, 0)}, pypw85.Error, "axis"),
    ({"threads": 0}, pypw85.Error, "threads"),
    ({"time_limit": -1.0}, pypw85.Error, "time_limit"),
])
def test_pack_errors(kwargs, kind, words):
    args = {"semi_axes": semi_axes(4), "target": 0.3}
    args.update(kwargs)
    with pytest.raises(kind) as info:
        pypw85.pack(args.pop("semi_axes"), **args)
    assert words in str(info.value)


@pytest.mark.parametrize("kwargs,kind,words", [
    # semi-axes spanning more than 2⁴⁰: the library's PW85_ERANGE, named
    ({"semi_axes": [[1.0, 1.0, 1.0], [2.0**-41, 1.0, 1.0]]}, pypw85.Error,
     "semi_axes"),
    # beyond a C int: ctypes wrapped 2³² + 1 to 1 thread, 2³¹ to −2³¹
    ({"threads": 2**32 + 1}, ValueError, "threads"),
    ({"threads": 2**31}, ValueError, "threads"),
    # beyond a size_t: wrapped around
    ({"step_limit": 2**64 + 1}, ValueError, "step_limit"),
    ({"progress_every": 2**64 + 1}, ValueError, "progress_every"),
    ({"step_limit": "ten"}, TypeError, "step_limit"),
    # the seed was masked to 64 bits (−1 packed as 2⁶⁴ − 1) or truncated
    ({"seed": -1}, pypw85.Error, "seed"),
    ({"seed": 2**64}, ValueError, "seed"),
    ({"seed": 1.5}, TypeError, "seed"),
    ({"progress_every": 2.5}, TypeError, "progress_every"),
])
def test_pack_errors_named(kwargs, kind, words):
    args = {"semi_axes": semi_axes(4), "target": 0.3}
    args.update(kwargs)
    with pytest.raises(kind) as info:
        pypw85.pack(args.pop("semi_axes"), **args)
    assert words in str(info.value)


def test_pack_side_rule_as_the_library():
    """The side rule 2·a_max·(1 + 2⁻⁹) < L_k decided as pw85_pack decides
    it: a target a few ulps below the boundary is packed (pypw85 decided it
    with its own arithmetic, x ** (1/3) for cbrt, and refused it), one a few
    ulps above is refused with the numbers."""
    a = np.array([[1.0, 0.37, 0.21]])
    volume = 4.0 / 3.0 * np.pi * 1.0 * 0.37 * 0.21
    boundary = volume / (2.0 * (1.0 + 2.0**-9)) ** 3
    for k in (1, 2, 3):
        t = boundary * (1.0 - k * 2.0**-52)
        p = pypw85.pack(a, t, step_limit=10)
        assert (2.0 * (1.0 + 2.0**-9) < p.box).all()
    with pytest.raises(pypw85.Error, match=r"L_0 = .*2·a_max") as info:
        pypw85.pack(a, boundary * (1.0 + 8 * 2.0**-52))
    assert info.value.status == pypw85.EINVAL


def overlapping_index(n=60, side=5.0, seed=2):
    rng = np.random.default_rng(seed)
    a = semi_axes(n, (1.0, 0.6, 0.3))
    p = rng.normal(size=(n, 4))
    p /= np.linalg.norm(p, axis=1)[:, None]
    q = np.array([pypw85.ellipsoid_quaternion(a[k], p[k]) for k in range(n)])
    c = np.round(rng.uniform(0, side, (n, 3)) * 2.0**20) / 2.0**20
    index = pypw85.Index(box=(side, side, side))
    index.insert(np.arange(n), c, q)
    return index, c, q


def test_energy_finite_differences():
    index, c, q = overlapping_index()
    e, f, t = index.energy()
    assert e > 0 and f.shape == (60, 3) and t.shape == (60, 3)
    h = 1e-5
    # (the error of a central difference here: 1.2e-9, test-energy.c)
    for k in range(0, 60, 7):
        for d in range(3):
            cp, cm = c[k].copy(), c[k].copy()
            cp[d] += h
            cm[d] -= h
            index.update(k, cp, q[k])
            ep = index.energy()[0]
            index.update(k, cm, q[k])
            em = index.energy()[0]
            index.update(k, c[k], q[k])
            assert f[k, d] == pytest.approx(-(ep - em) / (2 * h), abs=1e-7)
    assert np.abs(f.sum(axis=0)).max() < 1e-12 * np.abs(f).sum()


def test_energy_callback_and_threads():
    index, _, _ = overlapping_index(n=300, side=8.0)

    def overlap(mu2):
        mu = np.sqrt(mu2)
        return (1 - mu) ** 2, -(1 - mu) / mu
    e1, f1, t1 = index.energy(threads=1)
    e2, f2, t2 = index.energy(threads=2)
    e3, f3, t3 = index.energy(u=overlap, t=1.0)
    assert e1 == e2 and np.array_equal(f1, f2) and np.array_equal(t1, t2)
    # the same formula from Python: the same arrays (up to the rounding of
    # NumPy's sqrt and division, which are those of C)
    assert e3 == e1 and np.array_equal(f3, f1) and np.array_equal(t3, t1)

    class Stop(Exception):
        pass

    def boom(mu2):
        raise Stop()
    with pytest.raises(Stop):
        index.energy(u=boom, t=1.0)
    with pytest.raises(pypw85.Error, match="not finite"):
        index.energy(u=lambda mu2: (np.nan, 0.0), t=1.0)
    with pytest.raises(pypw85.Error, match="eps"):
        index.energy(eps=-1.0)
    with pytest.raises(pypw85.Error, match="t = "):
        index.energy(u=overlap, t=0.0)
    with pytest.raises(pypw85.Error, match="largest stored id"):
        index.energy(n=10)


def test_energy_callback_cannot_modify():
    """u may query the index, not modify or close it: closing it from u
    made the library read freed memory (valgrind), and returned ENOTPOSDEF
    or a result."""
    index, _, _ = overlapping_index(n=60, side=4.0)
    ids = list(index)
    centre, q = index.get(ids[0])
    e1, f1, t1 = index.energy(u=lambda mu2: (1.0 - mu2, -1.0), t=1.0)
    calls = {
        "close": lambda: index.close(),
        "insert": lambda: index.insert(max(ids) + 1, centre, q),
        "update": lambda: index.update(ids[0], centre, q),
        "remove": lambda: index.remove(ids[0]),
    }
    for name, call in calls.items():
        def u(mu2):
            call()
            return 1.0 - mu2, -1.0
        with pytest.raises(RuntimeError, match="^%s: the index is in use "
                           "by energy\\(\\)" % name):
            index.energy(u=u, t=1.0)
        # unchanged, and usable
        assert list(index) == ids
        e, f, t = index.energy(u=lambda mu2: (1.0 - mu2, -1.0), t=1.0)
        assert e == e1 and np.array_equal(f, f1) and np.array_equal(t, t1)

    # queries are allowed
    def query(mu2):
        assert len(index.overlapping_pairs()[0]) > 0
        return 1.0 - mu2, -1.0
    e, f, t = index.energy(u=query, t=1.0)
    assert e == e1 and np.array_equal(f, f1)
    index.close()
