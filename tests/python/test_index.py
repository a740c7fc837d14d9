# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.Index against a brute force over pairs and periodic images that
calls pypw85.overlap and pypw85.contact_function itself."""

import itertools

import numpy as np
import pytest

import pypw85
import pypw85.d2  # noqa: F401 (pypw85.d2.Index, when run alone)
from pypw85.index import NO_ID, OPENMP


def random_forms(rng, n, axes=(1.0, 0.5, 0.2)):
    """n forms R·diag(a²)·Rᵀ of random rotations, (n, 6)."""
    q = np.empty((n, 6))
    a2 = np.square(axes)
    for k in range(n):
        r, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        m = (r * a2) @ r.T
        q[k] = m[np.triu_indices(3)]
    return q


def on_grid(x):
    """x rounded to the grid of 2^-24: the vectors between such centres and
    their images in a box of side 6 are doubles, so that the brute force's
    r (rounded in double) is the exact r the index decides (pw85_index.h,
    "Images"; the exact vectors themselves: test-index-exact)."""
    return np.round(np.asarray(x) * 2.0**24) / 2.0**24


def configuration(seed=3, n=120, side=6.0):
    rng = np.random.default_rng(seed)
    return (on_grid(rng.uniform(-0.5 * side, 1.5 * side, (n, 3))),
            random_forms(rng, n))


def brute_pairs(c, q, box, t=None):
    """{(i, j, shift): value}: overlap results <= 0, or mu2 < t."""
    out = {}
    n = len(c)
    for i in range(n):
        for j in range(i, n):
            reach = 1.01 * np.sqrt(t or 1.0) * (
                np.sqrt(q[i][[0, 3, 5]].sum()) + np.sqrt(q[j][[0, 3, 5]].sum()))
            d = c[i] - c[j]
            ranges = [range(int(np.floor((d[k] - reach) / box[k])),
                            int(np.ceil((d[k] + reach) / box[k])) + 1)
                      for k in range(3)]
            for s in itertools.product(*ranges):
                if i == j and not s > (0, 0, 0):
                    continue
                r = (c[j] + np.array(s) * box) - c[i]
                if t is None:
                    res = pypw85.overlap(r, q[i], q[j])
                    if res <= 0:
                        out[(i, j, s)] = res
                else:
                    mu2, lam = pypw85.contact_function(r, q[i], q[j])
                    if mu2 < t:
                        out[(i, j, s)] = (mu2, lam)
    return out


@pytest.fixture
def periodic():
    c, q = configuration()
    box = np.array([6.0, 6.6, 5.4])
    with pypw85.Index(box) as index:
        index.insert(np.arange(len(c)), c, q)
        yield index, c, q, box


def test_overlapping_pairs(periodic):
    index, c, q, box = periodic
    ids, shifts, results = index.overlapping_pairs()
    got = {(int(i), int(j), tuple(int(x) for x in s)): int(r)
           for (i, j), s, r in zip(ids, shifts, results)}
    assert got == brute_pairs(c, q, box)
    assert len(got) > 0
    keys = [(i, j, tuple(s)) for (i, j), s in zip(ids.tolist(), shifts.tolist())]
    assert keys == sorted(keys)


def test_pairs_within_and_threads(periodic):
    index, c, q, box = periodic
    ids, shifts, ml = index.pairs_within(2.0)
    got = {(int(i), int(j), tuple(int(x) for x in s)): tuple(v)
           for (i, j), s, v in zip(ids, shifts, ml)}
    assert got == brute_pairs(c, q, box, t=2.0)
    for threads in (2, 8):
        ids2, shifts2, ml2 = index.pairs_within(2.0, threads=threads)
        assert np.array_equal(ids, ids2) and np.array_equal(shifts, shifts2)
        assert np.array_equal(ml, ml2)  # bit for bit


def test_candidate_queries(periodic):
    index, c, q, box = periodic
    rng = np.random.default_rng(5)
    for k in range(10):
        cc = on_grid(rng.uniform(0, 6, 3))
        qq = random_forms(rng, 1)[0]
        ids, shifts, ml = index.within(cc, qq, t=1.5)
        ref = {}
        for j in range(len(c)):
            for s in itertools.product(range(-2, 3), repeat=3):
                r = (c[j] + np.array(s) * box) - cc
                mu2, lam = pypw85.contact_function(r, qq, q[j])
                if mu2 < 1.5:
                    ref[(j, s)] = (mu2, lam)
        got = {(int(j), tuple(int(x) for x in s)): tuple(v)
               for j, s, v in zip(ids, shifts, ml)}
        assert got == ref
        result, found = index.overlap_any(cc, qq)
        best = min([pypw85.overlap((c[j] + np.array(s) * box) - cc, qq, q[j])
                    for j, s in ref] + [1])
        assert result == best
        assert (found is None) == (best == 1)


def test_insert_update_remove():
    with pypw85.Index() as index:
        q = np.array([1.0, 0, 0, 1, 0, 1])
        index.insert(3, [0, 0, 0], q)
        index.insert([5, 7], [[1.5, 0, 0], [10, 0, 0]], [q, q])
        assert len(index) == 3
        ids, _, res = index.overlapping_pairs()
        assert ids.tolist() == [[3, 5]] and res.tolist() == [-1]
        index.update(5, [3.0, 0, 0], q)
        assert index.overlapping_pairs()[0].shape == (0, 2)
        assert index.overlap_any([2.9, 0, 0], q) == (-1, 5)
        assert index.overlap_any([2.9, 0, 0], q, exclude=5) == (1, None)
        c, qq = index.get(5)
        assert c.tolist() == [3.0, 0, 0] and qq.tolist() == q.tolist()
        index.remove(5)
        assert len(index) == 2
        with pytest.raises(pypw85.Error) as e:
            index.remove(5)
        assert e.value.status == pypw85.EINVAL
        with pytest.raises(pypw85.Error) as e:  # all or none
            index.insert([8, 3], [[0, 0, 0], [0, 0, 0]], [q, q])
        assert e.value.status == pypw85.EINVAL and len(index) == 2
        with pytest.raises(pypw85.Error) as e:
            index.insert(9, [0, 0, 0], [1.0, 2, 0, 1, 0, 1])
        assert e.value.status == pypw85.ENOTPOSDEF
        with pytest.raises(ValueError):
            index.insert([1, 2], [[0, 0, 0]], [q, q])
        with pytest.raises(pypw85.Error) as e:
            index.pairs_within(1.0, threads=0)
        assert e.value.status == pypw85.EINVAL
    with pytest.raises(pypw85.Error) as e:
        pypw85.Index([1.0, 0.0, 1.0])
    assert e.value.status == pypw85.EINVAL
    assert NO_ID == 2**64 - 1 and OPENMP in (True, False)


def test_overlap_any_many():
    """overlap_any_many against overlap_any, one candidate at a time (which
    test_candidate_queries checks against the brute force)."""
    c, q = configuration(seed=4, n=150, side=12.0)
    with pypw85.Index([12.0, 13.0, 11.0]) as index:
        index.insert(np.arange(len(c)), c, q)
        check_overlap_any_many(index, c, q)


def check_overlap_any_many(index, c, q):
    rng = np.random.default_rng(11)
    n = 1200  # >= 512: threads are started
    cc = rng.uniform(-3, 9, (n, 3))
    qq = random_forms(rng, n)
    exclude = np.full(n, -1)
    moved = np.arange(0, n, 3)  # Monte Carlo moves of stored ellipsoids
    exclude[moved] = moved % len(c)
    cc[moved] = c[moved % len(c)] + rng.uniform(-0.05, 0.05, (len(moved), 3))
    qq[moved] = q[moved % len(c)]
    ref = [index.overlap_any(cc[i], qq[i],
                             None if exclude[i] == -1 else exclude[i])
           for i in range(n)]
    ref_results = np.array([r for r, _ in ref])
    ref_ids = np.array([-1 if j is None else j for _, j in ref])
    assert (ref_results == 1).sum() > n // 10
    assert (ref_results == -1).sum() > n // 10
    for threads in (1, 2, 8, 0):
        results, ids = index.overlap_any_many(cc, qq, exclude, threads=threads)
        assert results.dtype == np.intc and ids.dtype == np.int64
        assert np.array_equal(results, ref_results)
        assert np.array_equal(ids, ref_ids)
    # without exclusions the moves overlap their own originals
    results, _ = index.overlap_any_many(cc[moved], qq[moved])
    assert (results == -1).all()
    # the first failing candidate is named, with every status
    bad = qq.copy()
    bad[7, 3] = -1.0
    bad[9, 0] = np.nan
    with pytest.raises(pypw85.Error) as e:
        index.overlap_any_many(cc, bad, threads=2)
    assert e.value.status == pypw85.ENOTPOSDEF and e.value.index == 7
    assert e.value.statuses[9] == pypw85.EDOM
    assert (np.delete(e.value.statuses, [7, 9]) == 0).all()
    with pytest.raises(ValueError):
        index.overlap_any_many(cc[:5], qq[:4])
    with pytest.raises(ValueError):
        index.overlap_any_many(cc[:5], qq[:5], exclude=[-2, 0, 0, 0, 0])
    with pytest.raises(ValueError):
        index.overlap_any_many(cc[:5], qq[:5], threads=-1)
    with pytest.raises(TypeError):
        index.overlap_any_many(cc[:5], qq[:5], exclude=np.zeros(5))
    # ids above MAX_ID: ValueError, as overlap_any's exclude (they were
    # taken for "no exclusion")
    for bad in (pypw85.index.MAX_ID + 1, 2**40, np.uint64(2**63)):
        ex = np.zeros(5, dtype=np.uint64 if bad == 2**63 else np.int64)
        ex[3] = bad
        with pytest.raises(ValueError, match="candidate 3 has %d$" % bad):
            index.overlap_any_many(cc[:5], qq[:5], exclude=ex)
        with pytest.raises(ValueError):
            index.overlap_any(cc[3], qq[3], exclude=int(bad))
    r, i = index.overlap_any_many(np.empty((0, 3)), np.empty((0, 6)))
    assert r.shape == (0,) and i.shape == (0,)


@pytest.mark.parametrize("dim", [3, 2])
def test_overlap_any_reach_of_images(dim):
    """A candidate reaching across more than 2^20 images of the box:
    PW85_ERANGE (pw85_index.h), with a message naming the reach, not the
    range of a double; a narrower one is decided."""
    make = pypw85.Index if dim == 3 else pypw85.d2.Index
    index = make(np.ones(dim))
    ball = [0.01, 0.0, 0.0, 0.01, 0.0, 0.01] if dim == 3 else [0.01, 0.0, 0.01]
    index.insert(0, np.zeros(dim), ball)
    needle = np.array(ball)
    needle[0] = 2.0**34
    centre = np.zeros(dim)
    centre[0] = 0.5
    assert index.overlap_any(centre, needle) == (-1, 0)
    needle[0] = 2.0**38
    with pytest.raises(pypw85.Error) as e:
        index.overlap_any(centre, needle)
    assert e.value.status == pypw85.ERANGE
    assert "2²⁰" in str(e.value) and "images" in str(e.value)
    with pytest.raises(pypw85.Error) as e:
        index.overlap_any_many(centre[None, :], needle[None, :])
    assert e.value.status == pypw85.ERANGE and "images" in str(e.value)
