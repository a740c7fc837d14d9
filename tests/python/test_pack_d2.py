# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.d2.pack and pypw85.d2.Index.energy: packings of ellipses checked
by a brute force over every pair and image (d2.overlap), the forms against
d2.ellipse, determinism, the aligned rule, errors naming their argument;
energies against central differences, the balance of forces, the C path
through a Python pair energy; docstrings of d2.Index in two dimensions."""

import inspect
import math

import numpy as np
import pytest

import pypw85
from pypw85 import d2
from test_pack import brute_overlaps as _brute_overlaps


def brute_overlaps(p):
    """test_pack.brute_overlaps with d2.overlap, images {-1, 0, 1}²."""
    return _brute_overlaps(p, d2.overlap)


def ellipses(n, aspect=1.3, poly=False):
    s = 1.0 + (np.arange(n) % 5) / 4.0 if poly else np.ones(n)
    return np.stack([s, s / aspect], axis=1)


@pytest.mark.parametrize("aspect,target,orientation,poly", [
    (1.3, 0.85, "isotropic", False),
    (2.0, 0.75, "isotropic", True),
    (4.0, 0.70, "aligned", False),
])
def test_pack_target(aspect, target, orientation, poly):
    a = ellipses(150, aspect, poly)
    p = d2.pack(a, target, seed=5, orientation=orientation, axis=(1.0, 2.0))
    assert p.outcome == "target"
    assert p.phi == pytest.approx(target, rel=1e-14)
    assert p.centres.shape == (150, 2) and p.angles.shape == (150,)
    assert len(brute_overlaps(p)) == 0
    assert np.all((p.centres >= 0) & (p.centres < p.box))
    q = np.array([d2.ellipse(a[k], p.angles[k]) for k in range(len(a))])
    assert np.array_equal(q, p.forms)
    if orientation == "aligned":
        assert np.all(p.angles == math.atan2(2.0, 1.0))


def test_pack_deterministic_and_progress():
    a = ellipses(600, 2.0, poly=True)
    p1 = d2.pack(a, 0.8, seed=11)
    pairs = []

    def count(info):
        pairs.append(info["pairs"])
        return 0
    p2 = d2.pack(a, 0.8, seed=11, threads=2, progress=count,
                 progress_every=1)
    # The energy runs on min(threads, pairs/256 + 1) threads: both
    # threads worked on some steps, else this would test one thread.
    assert max(pairs) >= 512
    p3 = d2.pack(a, 0.8, seed=12)
    for x, y in zip(p1[:4], p2[:4]):
        assert np.array_equal(x, y)
    assert not np.array_equal(p1.centres, p3.centres)
    seen = []

    def progress(info):
        seen.append(info)
        return len(seen) == 2
    p = d2.pack(a, 0.95, progress=progress, progress_every=3)
    assert p.outcome == "cancelled" and len(seen) == 2
    assert seen[0]["phi_trial"] == 0.95
    assert 0 < p.phi < 0.95 and len(brute_overlaps(p)) == 0


@pytest.mark.parametrize("kwargs,kind,words", [
    ({"semi_axes": np.ones((0, 2))}, pypw85.Error, "no ellipse"),
    ({"semi_axes": [[1, -1]]}, pypw85.Error, "semi_axes[0]"),
    ({"semi_axes": np.ones((3, 3))}, ValueError, "shape (n, 2)"),
    ({"target": 1.0}, pypw85.Error, "target"),
    ({"aspect": (1, 0)}, pypw85.Error, "aspect[1]"),
    ({"aspect": (1, 1, 1)}, ValueError, "aspect must be 2"),
    ({"axis": (0, 0), "orientation": "aligned"}, pypw85.Error, "axis"),
    ({"axis": (math.nan, 1), "orientation": "aligned"}, pypw85.Error,
     "axis[0]"),
    ({"orientation": "random"}, pypw85.Error, "orientation"),
    ({"threads": 0}, pypw85.Error, "threads"),
    ({"target": 0.9, "aspect": (1, 40)}, pypw85.Error, "rectangle"),
])
def test_pack_errors(kwargs, kind, words):
    args = {"semi_axes": ellipses(4), "target": 0.3}
    args.update(kwargs)
    with pytest.raises(kind) as info:
        d2.pack(args.pop("semi_axes"), **args)
    assert words in str(info.value)


def test_pack_isotropic_reads_no_axis():
    # As pw85_2d_pack: the axis is read with "aligned" only.
    a = ellipses(10)
    p = d2.pack(a, 0.1, seed=3)
    for axis in ((0.0, 0.0), (math.nan, 0.0)):
        q = d2.pack(a, 0.1, seed=3, axis=axis)
        for x, y in zip(p[:4], q[:4]):
            assert np.array_equal(x, y)


def overlapping_index(n=60, side=6.0, seed=2):
    rng = np.random.default_rng(seed)
    a = ellipses(n, 2.0, poly=True) * 0.7
    theta = rng.uniform(-np.pi, np.pi, n)
    q = np.array([d2.ellipse(a[k], theta[k]) for k in range(n)])
    c = np.round(rng.uniform(0, side, (n, 2)) * 2.0**20) / 2.0**20
    index = d2.Index(box=(side, side))
    index.insert(np.arange(n), c, q)
    return index, a, theta, c, q


def test_energy_finite_differences_and_balance():
    index, a, theta, c, q = overlapping_index()
    e, f, t = index.energy()
    assert e > 0 and f.shape == (60, 2) and t.shape == (60,)
    h = 1e-5
    # (the error of a central difference here: 1.7e-9, test-2d-energy.c)
    for k in range(0, 60, 7):
        for d in range(3):
            cp, cm, qp, qm = c[k].copy(), c[k].copy(), q[k], q[k]
            if d < 2:
                cp[d] += h
                cm[d] -= h
            else:
                qp = d2.ellipse(a[k], theta[k] + h)
                qm = d2.ellipse(a[k], theta[k] - h)
            index.update(k, cp, qp)
            ep = index.energy()[0]
            index.update(k, cm, qm)
            em = index.energy()[0]
            index.update(k, c[k], q[k])
            got = f[k, d] if d < 2 else t[k]
            assert got == pytest.approx(-(ep - em) / (2 * h), abs=1e-7)
    assert np.abs(f.sum(axis=0)).max() < 1e-12 * np.abs(f).sum()


def test_energy_callback_threads_errors():
    index, _, _, _, _ = overlapping_index(n=300, side=12.0)

    def overlap(mu2):
        mu = np.sqrt(mu2)
        return (1 - mu) ** 2, -(1 - mu) / mu
    e1, f1, t1 = index.energy(threads=1)
    e2, f2, t2 = index.energy(threads=2)
    e3, f3, t3 = index.energy(u=overlap, t=1.0)
    assert e1 > 0
    assert e1 == e2 and np.array_equal(f1, f2) and np.array_equal(t1, t2)
    assert e3 == e1 and np.array_equal(f3, f1) and np.array_equal(t3, t1)
    with pytest.raises(pypw85.Error, match="not finite"):
        index.energy(u=lambda mu2: (np.inf, 0.0), t=1.0)
    with pytest.raises(pypw85.Error, match="eps"):
        index.energy(eps=0.0)
    with pytest.raises(pypw85.Error, match="largest stored id"):
        index.energy(n=10)


def test_docstrings_in_two_dimensions():
    """d2.Index's methods say (n, 2) and ellipse; pypw85.Index's (n, 3)
    and ellipsoid: one implementation, a docstring per dimension."""
    for name, f in inspect.getmembers(d2.Index, inspect.isfunction):
        doc = f.__doc__ or ""
        assert "ellipsoid" not in doc, name
        assert "(n, 3)``" not in doc or "``q`` ``(n, 3)``" in doc, name
        assert "{" not in doc, name
    assert "``centres`` ``(n, 2)``" in d2.Index.insert.__doc__
    assert "``(n,)``" in d2.Index.energy.__doc__
    assert "``centres`` ``(n, 3)``" in pypw85.Index.insert.__doc__
    assert "ellipsoid" in pypw85.Index.energy.__doc__
    assert d2.Index.insert is not pypw85.Index.insert
