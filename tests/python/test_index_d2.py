# SPDX-License-Identifier: BSD-3-Clause
"""pypw85.d2.Index against a brute force over every pair and periodic image,
computed with pypw85.d2.overlap and pypw85.d2.contact_function (the C
library's 2D contact functions): the index's answers must be those values,
bit for bit, in an open plane and a periodic rectangle, after insert,
update and remove."""

import itertools

import numpy as np
import pytest

import pypw85
from pypw85 import d2

GRID = 2.0**-20  # centres on this grid: every r below is a double, exact


def ellipses(rng, n, big=0.9, small=0.3):
    """n forms of random angles and semi-axes in [small, big], (n, 3)."""
    a = rng.uniform(small, big, (n, 2))
    return np.array([d2.ellipse(a[k], rng.uniform(0, np.pi))
                     for k in range(n)])


def snap(x):
    return np.round(np.asarray(x, dtype=float) / GRID) * GRID


def images(ci, cj, qi, qj, box, reach_t):
    """The shifts s (tuples) of every image of j that can be within
    mu2 < reach_t of i (a superset: half-widths √Q_kk bound each ellipse)."""
    if box is None:
        return [(0, 0)]
    half = np.sqrt(reach_t) * 1.01 * (np.sqrt(qi[[0, 2]]) +
                                      np.sqrt(qj[[0, 2]]))
    d = ci - cj
    return list(itertools.product(*[
        range(int(np.floor((d[k] - half[k]) / box[k])),
              int(np.ceil((d[k] + half[k]) / box[k])) + 1) for k in (0, 1)]))


def reference(c, q, ids, box, t=None):
    """{(i, j, shift): overlap result <= 0, or (mu2, lambda) with mu2 < t}
    over every pair i < j (and i == j with a non-zero shift)."""
    out = {}
    L = np.zeros(2) if box is None else np.asarray(box)
    for a, b in itertools.combinations_with_replacement(range(len(ids)), 2):
        i, j = (a, b) if ids[a] <= ids[b] else (b, a)
        for s in images(c[i], c[j], q[i], q[j], box, t or 1.0):
            if i == j and not s > (0, 0):
                continue
            r = c[j] + np.array(s) * L - c[i]
            key = (int(ids[i]), int(ids[j]), s)
            if t is None:
                res = d2.overlap(r, q[i], q[j])
                if res <= 0:
                    out[key] = int(res)
            else:
                mu2, lam = d2.contact_function(r, q[i], q[j])
                if mu2 < t:
                    out[key] = (mu2, lam)
    return out


def as_dict(ids, shifts, values):
    return {(int(i), int(j), tuple(int(x) for x in s)):
            (int(v) if np.ndim(v) == 0 else tuple(float(x) for x in v))
            for (i, j), s, v in zip(ids, shifts, values)}


def check_all(index, c, q, ids, box):
    """Every query of index against the brute force."""
    for threads in (1, 2, 8):
        got = as_dict(*index.overlapping_pairs(threads=threads))
        assert got == reference(c, q, ids, box)
        got = as_dict(*index.pairs_within(1.7, threads=threads))
        assert got == reference(c, q, ids, box, t=1.7)
    rng = np.random.default_rng(17)
    L = np.zeros(2) if box is None else np.asarray(box)
    for _ in range(8):
        cc = snap(rng.uniform(0, 8, 2))
        qq = ellipses(rng, 1)[0]
        ref = {}
        for k in range(len(ids)):
            for s in images(cc, c[k], qq, q[k], box, 1.7):
                mu2, lam = d2.contact_function(c[k] + np.array(s) * L - cc,
                                               qq, q[k])
                if mu2 < 1.7:
                    ref[(int(ids[k]), s)] = (mu2, lam)
        j, s, ml = index.within(cc, qq, t=1.7)
        assert s.shape == (len(j), 2) and ml.shape == (len(j), 2)
        assert {(int(a), tuple(int(x) for x in b)): tuple(v)
                for a, b, v in zip(j, s, ml)} == ref
        res, found = index.overlap_any(cc, qq)
        best = min([d2.overlap(c[ids.tolist().index(a)] + np.array(b) * L
                               - cc, qq, q[ids.tolist().index(a)])
                    for a, b in ref] + [1])
        assert res == best and (found is None) == (best == 1)
        if found is not None:
            k = ids.tolist().index(found)
            assert min(d2.overlap(c[k] + np.array(b) * L - cc, qq, q[k])
                       for b in images(cc, c[k], qq, q[k], box, 1.0)) == res


@pytest.mark.parametrize("box", [None, (8.0, 7.0)])
def test_queries_after_changes(box):
    rng = np.random.default_rng(29)
    n = 90
    ids = np.arange(0, 3 * n, 3)
    c = snap(rng.uniform(-1, 9, (n, 2)))
    q = ellipses(rng, n)
    with d2.Index(box) as index:
        index.insert(ids, c, q)
        assert len(index) == n and list(index) == ids.tolist()
        check_all(index, c, q, ids, box)
        assert len(reference(c, q, ids, box)) > 10  # the test sees overlaps
        for k in range(0, n, 4):  # move and reshape a quarter
            c[k] = snap(rng.uniform(-1, 9, 2))
            q[k] = ellipses(rng, 1)[0]
            index.update(int(ids[k]), c[k], q[k])
        gone = np.arange(1, n, 5)
        for k in gone:
            index.remove(int(ids[k]))
        keep = np.setdiff1d(np.arange(n), gone)
        c, q, ids = c[keep], q[keep], ids[keep]
        check_all(index, c, q, ids, box)
        got_c, got_q = index.get(int(ids[0]))
        assert got_c.tolist() == c[0].tolist()
        assert got_q.tolist() == q[0].tolist()


def test_overlap_any_many_threads():
    rng = np.random.default_rng(3)
    c = snap(rng.uniform(0, 10, (80, 2)))
    q = ellipses(rng, 80)
    with d2.Index([10.0, 10.0]) as index:
        index.insert(np.arange(80), c, q)
        m = 700  # above 512: threads are started
        cc = snap(rng.uniform(0, 10, (m, 2)))
        qq = ellipses(rng, m, 0.5, 0.2)
        exclude = np.where(np.arange(m) % 4 == 0, np.arange(m) % 80, -1)
        ref = [index.overlap_any(cc[i], qq[i], None if exclude[i] < 0
                                 else int(exclude[i])) for i in range(m)]
        results0 = np.array([r for r, _ in ref])
        ids0 = np.array([-1 if j is None else j for _, j in ref])
        assert (results0 < 0).sum() > m // 10
        assert (results0 > 0).sum() > m // 10
        for threads in (1, 2, 8, 0):
            results, ids = index.overlap_any_many(cc, qq, exclude, threads)
            assert np.array_equal(results, results0)
            assert np.array_equal(ids, ids0)


def test_errors():
    circle = np.array([1.0, 0.0, 1.0])
    with pytest.raises(pypw85.Error) as e:
        d2.Index([1.0, -2.0])
    assert e.value.status == pypw85.EINVAL and "L_1" in str(e.value)
    with pytest.raises(pypw85.Error) as e:
        d2.Index([np.inf, 2.0])
    assert e.value.status == pypw85.EDOM
    with pytest.raises(ValueError):
        d2.Index([1.0, 2.0, 3.0])  # a 3D box
    with d2.Index([4.0, 4.0]) as index:
        index.insert(2, [0.0, 0.0], circle)
        with pytest.raises(pypw85.Error) as e:  # all or none
            index.insert([4, 2], [[1.0, 1.0], [2.0, 2.0]], circle)
        assert e.value.status == pypw85.EINVAL
        assert e.value.id == 2 and e.value.item == 1
        assert "already stored" in str(e.value) and len(index) == 1
        with pytest.raises(pypw85.Error) as e:  # Q00·Q11 − Q01² = 0
            index.insert(5, [1.0, 1.0], [1.0, 1.0, 1.0])
        assert e.value.status == pypw85.ENOTPOSDEF
        assert "ellipse 5" in str(e.value)
        with pytest.raises(pypw85.Error) as e:  # wider than the rectangle
            index.insert(5, [1.0, 1.0], [4.0, 0.0, 1.0])
        assert e.value.status == pypw85.EINVAL and "L_0" in str(e.value)
        with pytest.raises(pypw85.Error) as e:  # taller than the rectangle
            index.insert(5, [1.0, 1.0], [1.0, 0.0, 4.0])
        assert e.value.status == pypw85.EINVAL
        assert "2·√Q_11·(1 + 2⁻²⁰) = 4.0000038146972656 ≥ L_1 = 4" \
            in str(e.value)
        with pytest.raises(pypw85.Error) as e:
            index.insert(5, [np.nan, 1.0], circle)
        assert e.value.status == pypw85.EDOM
        with pytest.raises(ValueError):
            index.insert(5, [1.0, 1.0, 1.0], circle)  # a 3D centre
        with pytest.raises(ValueError):
            index.insert(5, [1.0, 1.0], np.ones(6))  # a 3D form
        with pytest.raises(TypeError):
            index.insert(5.0, [1.0, 1.0], circle)
        with pytest.raises(pypw85.Error) as e:
            index.update(9, [0.0, 0.0], circle)
        assert e.value.status == pypw85.EINVAL and "not stored" in str(e.value)
        with pytest.raises(pypw85.Error) as e:
            index.remove(9)
        assert e.value.status == pypw85.EINVAL
        with pytest.raises(pypw85.Error) as e:
            index.get(9)
        assert e.value.status == pypw85.EINVAL
        with pytest.raises(pypw85.Error) as e:
            index.within([0.0, 0.0], circle, t=0.0)
        assert e.value.status == pypw85.EINVAL
        with pytest.raises(pypw85.Error) as e:
            index.overlap_any([0.0, 0.0], [1.0, 2.0, 1.0])
        assert e.value.status == pypw85.ENOTPOSDEF
        with pytest.raises(pypw85.Error) as e:
            index.pairs_within(1.0, threads=0)
        assert e.value.status == pypw85.EINVAL
        bad = np.tile(circle, (3, 1))
        bad[1, 1] = 2.0
        with pytest.raises(pypw85.Error) as e:
            index.overlap_any_many(np.zeros((3, 2)), bad)
        assert e.value.status == pypw85.ENOTPOSDEF and e.value.index == 1
        assert e.value.statuses.tolist() == [0, pypw85.ENOTPOSDEF, 0]
        assert repr(index) == ("<pypw85.d2.Index: periodic rectangle "
                               "(4, 4), 1 ellipse>")
    assert repr(index) == "<pypw85.d2.Index (closed)>"
    with pytest.raises(ValueError):
        len(index)
