# SPDX-License-Identifier: BSD-3-Clause
"""data/pw85_geometry_pairs.h5 against a fresh high-precision recomputation
of a deterministic sample, independent of libpw85 (it does not call pypw85).

The references are recomputed here by a route of their own: mpmath matrices
and LU solves, λ* by mpmath.findroot (Anderson's bracketing method) on f′,
eigenvalues by the general mpmath.eig (the generator used mpmath.eigsy),
rotation matrices from p/‖p‖ by the usual formula (the generator used exact
rational arithmetic). Every value must equal the stored double bit for bit
(a value that vanishes to 1e-60 of its scale is the exact 0 stored). The
envelope-theorem derivatives are checked again by one central difference of
μ² per pair along a random direction of all 21 inputs. data/gen_geometry.py
is imported only to regenerate the sampled inputs from its seed.
"""

import os
import pathlib
import sys

import numpy as np
import pytest

h5py = pytest.importorskip("h5py", reason="h5py reads the data "
                           "(Debian: python3-h5py)")
mpmath = pytest.importorskip("mpmath", reason="mpmath recomputes the "
                             "references (Debian: python3-mpmath)")
mp = mpmath.mp

ROOT = pathlib.Path(os.environ.get("PW85_SOURCE_ROOT")
                    or pathlib.Path(__file__).resolve().parents[2])
N_PAIRS = 20      # 4 per block
N_CTORS = 20      # 4 per kind
DPS = 100
ZERO = mpmath.mpf("1e-60")
SYM = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))


@pytest.fixture(scope="module")
def data():
    path = os.environ.get("PW85_GEOMETRY_PAIRS")
    if not path:
        path = ROOT / "data" / "pw85_geometry_pairs.h5"
        if not path.exists():
            pytest.skip("no %s (set PW85_GEOMETRY_PAIRS)" % path)
    # set by meson: a missing file is then a failure
    with h5py.File(path, "r") as h:
        out = {k: h[k][...] for k in h if isinstance(h[k], h5py.Dataset)}
        out.update({"constructors/" + k: v[...]
                    for k, v in h["constructors"].items()})
        out["block_names"] = h.attrs["block_names"].decode().split(",")
        out["kind_names"] = (h["constructors"].attrs["kind_names"]
                             .decode().split(","))
    return out


def sample(index, n):
    """n records: n / (number of groups) from each group, seeded."""
    rng = np.random.default_rng(1515)
    groups = np.unique(index)
    return [int(i) for g in groups
            for i in rng.choice(np.flatnonzero(index == g),
                                n // len(groups), replace=False)]


def mat(q):
    q = [mpmath.mpf(float(t)) for t in q]
    return mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                          [q[2], q[4], q[5]]])


def vec(v):
    return mpmath.matrix([mpmath.mpf(float(t)) for t in v])


def rounded(values, scale):
    """Doubles nearest to values, with exact-0 noise (below ZERO·scale) 0."""
    return np.array([0.0 if abs(v) <= ZERO * scale else float(v)
                     for v in values])


def same(a, b):
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    return a.shape == b.shape and (np.isnan(a) == np.isnan(b)).all() and \
        (a[~np.isnan(a)] == b[~np.isnan(b)]).all()


def norm(v):
    return mpmath.sqrt(sum(t * t for t in v))


def contact(r, Q1, Q2):
    """λ*, μ² at the working precision: the root of f′ (decreasing, f′(0) >
    0 > f′(1)) by the Illinois method, bisecting when the bracket does not
    halve in three steps."""
    def fprime(lam):
        s = mpmath.lu_solve((1 - lam) * Q1 + lam * Q2, r)
        return ((1 - 2 * lam) * (r.T * s)[0]
                - lam * (1 - lam) * (s.T * (Q2 - Q1) * s)[0])
    lo, hi = mpmath.mpf(0), mpmath.mpf(1)
    flo, fhi = fprime(lo), fprime(hi)
    assert flo > 0 > fhi
    tol = mpmath.mpf(10) ** (-(DPS - 10))
    side, width, steps = 0, hi - lo, 0
    while hi - lo > tol * min(lo + (hi - lo) / 2, 1 - hi + (hi - lo) / 2):
        steps += 1
        assert steps < 5000
        x = (lo * fhi - hi * flo) / (fhi - flo)
        if steps % 3 == 0:
            if hi - lo > width / 2:
                x = (lo + hi) / 2
            width = hi - lo
        fx = fprime(x)
        if fx == 0:
            lo = hi = x
            break
        if fx > 0:
            lo, flo = x, fx
            if side == 1:
                fhi /= 2
            side = 1
        else:
            hi, fhi = x, fx
            if side == -1:
                flo /= 2
            side = -1
    lam = (lo + hi) / 2
    s = mpmath.lu_solve((1 - lam) * Q1 + lam * Q2, r)
    return lam, lam * (1 - lam) * (r.T * s)[0]


def test_layout(data):
    n, m = len(data["r12"]), len(data["constructors/a"])
    widths = {"r12": 3, "q1": 6, "q2": 6, "s": 3, "point": 3, "normal": 3,
              "d_r12": 3, "d_rot1": 3, "d_rot2": 3, "d_q1": 6, "d_q2": 6}
    for k in ("mu2", "mu2_minus_1", "lambda", "one_minus_lambda", "cond_q1",
              "cond_q2", "cond_q", "block"):
        widths[k] = 0
    cwidths = {"a": 3, "rot": 9, "q_rot": 6, "q_rot_scale": 6, "quat": 4,
               "q_quat": 6, "eig_a": 3, "eig_gap": 3, "eig_vectors": 9,
               "kind": 0}
    for prefix, w, count in (("", widths, n),
                             ("constructors/", cwidths, m)):
        for k, width in w.items():
            arr = data[prefix + k]
            assert arr.shape == ((count, width) if width else (count,)), k
            assert arr.dtype == (np.int32 if k in ("block", "kind")
                                 else np.float64), k
    assert n >= 300 and m >= 250
    assert set(np.unique(data["block"])) == set(range(len(data["block_names"])))
    assert set(np.unique(data["constructors/kind"])) == \
        set(range(len(data["kind_names"])))
    # everything finite but the directions of exactly repeated eigenvalues
    for k, v in data.items():
        if isinstance(v, np.ndarray) and k != "constructors/eig_vectors":
            assert np.isfinite(v).all(), k
    assert (data["one_minus_lambda"] > 0).all() and (data["lambda"] > 0).all()


@pytest.fixture(scope="module")
def gen_geometry():
    sys.path.insert(0, str(ROOT / "data"))
    sys.dont_write_bytecode = True
    import gen_geometry as g
    return g


def test_inputs_from_seed(data, gen_geometry):
    """The sampled inputs are those the generator draws from its seed."""
    g = gen_geometry
    counts = np.cumsum([0] + [n for _, n in g.PAIR_BLOCKS])
    for i in sample(data["block"], N_PAIRS):
        b = int(data["block"][i])
        k = i - counts[b]
        for attempt in range(100):
            rng = np.random.default_rng([g.SEED, b, k, attempt])
            cand = g.pair_candidate(b, rng)
            if cand is not None:
                break
        for name, v in zip(("r12", "q1", "q2"), cand):
            assert same(data[name][i], v), (i, name)
    counts = np.cumsum([0] + [n for _, n in g.CTOR_KINDS])
    kinds = data["constructors/kind"]
    for i in sample(kinds, N_CTORS):
        c = int(kinds[i])
        rec, _ = g.ctor_record((c, i - counts[c]))
        for name in ("a", "rot", "quat"):
            assert same(data["constructors/" + name][i], rec[name]), (i, name)


@pytest.mark.parametrize("j", range(N_PAIRS))
def test_pair(data, j):
    i = sample(data["block"], N_PAIRS)[j]
    with mpmath.workdps(DPS):
        r, Q1, Q2 = vec(data["r12"][i]), mat(data["q1"][i]), mat(data["q2"][i])
        lam, mu2 = contact(r, Q1, Q2)
        oml = 1 - lam
        Q = oml * Q1 + lam * Q2
        s = mpmath.lu_solve(Q, r)
        q1s, q2s = Q1 * s, Q2 * s
        ns = norm(s)
        lever = 2 * lam * oml * ns * (oml * norm(q1s) + lam * norm(q2s))
        ss = [s[a] * s[b] * (1 if a == b else 2) for a, b in SYM]
        c1, c2 = lam * oml**2, lam**2 * oml
        rot1 = mpmath.matrix([s[1] * q1s[2] - s[2] * q1s[1],
                              s[2] * q1s[0] - s[0] * q1s[2],
                              s[0] * q1s[1] - s[1] * q1s[0]]) * (2 * c1)
        rot2 = mpmath.matrix([s[1] * q2s[2] - s[2] * q2s[1],
                              s[2] * q2s[0] - s[0] * q2s[2],
                              s[0] * q2s[1] - s[1] * q2s[0]]) * (2 * c2)
        expect = {
            "mu2": [mu2], "mu2_minus_1": [mu2 - 1], "lambda": [lam],
            "one_minus_lambda": [oml], "s": list(s),
            "point": [oml * t for t in q1s], "normal": [t / ns for t in s],
            "d_r12": [2 * lam * oml * t for t in s],
            "d_rot1": list(rot1), "d_rot2": list(rot2),
            "d_q1": [-c1 * t for t in ss], "d_q2": [-c2 * t for t in ss],
        }
        for k, v in expect.items():
            scale = lever if k.startswith("d_rot") else norm(v)
            assert same(np.atleast_1d(data[k][i]), rounded(v, scale)), (i, k)
        for k, m in (("cond_q", Q), ("cond_q1", Q1), ("cond_q2", Q2)):
            ev = sorted(mpmath.re(t) for t in
                        mpmath.eig(m, left=False, right=False))
            assert float(ev[2] / ev[0]) == data[k][i], (i, k)

        # one central difference of mu^2 along a random direction of all
        # 21 inputs (r12, q1, q2 entries, rotation vectors of 1 and 2)
        rng = np.random.default_rng([15, i])
        u = [mpmath.mpf(float(t)) for t in rng.normal(size=21)]
        h = mpmath.mpf("1e-35")
        def moved(t):
            rt = r + t * norm(list(r)) * mpmath.matrix(u[0:3])
            qs = []
            for q, du, w in ((data["q1"][i], u[3:9], u[15:18]),
                             (data["q2"][i], u[9:15], u[18:21])):
                sc = max(abs(float(x)) for x in q)
                qm = mat(q)
                for (a, b), d in zip(SYM, du):
                    qm[a, b] += t * sc * d
                    if a != b:
                        qm[b, a] += t * sc * d
                K = mpmath.matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]],
                                   [-w[1], w[0], 0]]) * t
                R = mpmath.expm(K)
                qs.append(R * qm * R.T)
            return contact(rt, *qs)[1]

        # rescale the closed form to the steps taken: the r12 and q steps
        # are relative to |r12| and max |q|
        sr = norm(list(r))
        s1 = max(abs(float(x)) for x in data["q1"][i])
        s2 = max(abs(float(x)) for x in data["q2"][i])
        closed = (sr * sum(a * b for a, b in zip(u[0:3], data["d_r12"][i]))
                  + s1 * sum(a * b for a, b in zip(u[3:9], data["d_q1"][i]))
                  + s2 * sum(a * b for a, b in zip(u[9:15], data["d_q2"][i]))
                  + sum(a * b for a, b in zip(u[15:18], data["d_rot1"][i]))
                  + sum(a * b for a, b in zip(u[18:21], data["d_rot2"][i])))
        fd = (moved(h) - moved(-h)) / (2 * h)
        # the stored closed forms are doubles: agreement to rounding
        bound = 1e-14 * float(
            sr * norm(list(data["d_r12"][i])) + s1 * norm(list(data["d_q1"][i]))
            + s2 * norm(list(data["d_q2"][i])) + norm(list(data["d_rot1"][i]))
            + norm(list(data["d_rot2"][i])))
        assert abs(float(fd) - float(closed)) <= bound, (i, fd, closed)


def axis_form(a, R):
    a2 = [mpmath.mpf(float(t)) ** 2 for t in a]
    return [sum(R[i, m] * R[j, m] * a2[m] for m in range(3)) for i, j in SYM]


@pytest.mark.parametrize("j", range(N_CTORS))
def test_constructor(data, j):
    d = {k[13:]: v for k, v in data.items() if k.startswith("constructors/")}
    i = sample(d["kind"], N_CTORS)[j]
    a = d["a"][i]
    amax2 = float(max(a)) ** 2
    with mpmath.workdps(DPS):
        R = mpmath.matrix(3, 3)
        for t in range(9):
            R[t // 3, t % 3] = mpmath.mpf(float(d["rot"][i][t]))
        assert same(d["q_rot"][i], rounded(axis_form(a, R), amax2)), i
        a2 = [mpmath.mpf(float(t)) ** 2 for t in a]
        scale = [sum(abs(R[p, m] * R[q, m]) * a2[m] for m in range(3))
                 for p, q in SYM]
        assert same(d["q_rot_scale"][i], rounded(scale, 0)), i
        p = [mpmath.mpf(float(t)) for t in d["quat"][i]]
        n = mpmath.sqrt(sum(t * t for t in p))
        w, x, y, z = (t / n for t in p)
        P = mpmath.matrix([
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
        assert same(d["q_quat"][i], rounded(axis_form(a, P), amax2)), i
        # the eigen-decomposition of the stored q_quat, general solver
        Q = mat(d["q_quat"][i])
        ev, V = mpmath.eig(Q)
        order = sorted(range(3), key=lambda t: -mpmath.re(ev[t]))
        e = [mpmath.re(ev[t]) for t in order]
        assert same(d["eig_a"][i], [float(mpmath.sqrt(t)) for t in e]), i
        gap = [min(abs(e[t] - e[u]) for u in range(3) if u != t) / e[0]
               for t in range(3)]
        assert same(d["eig_gap"][i], rounded(gap, 1)), i
        cols = []
        for t, k in enumerate(order):
            c = [mpmath.re(V[r, k]) for r in range(3)]
            c = [v / norm(c) for v in c]
            big = max(range(3), key=lambda r: abs(c[r]))
            cols.append([-v for v in c] if c[big] < 0 else c)
        if gap[0] > ZERO and gap[1] > ZERO:
            u, v = cols[0], cols[1]
            cols[2] = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]]
        got = d["eig_vectors"][i].reshape(3, 3)
        for t in range(3):
            if gap[t] <= ZERO:
                assert np.isnan(got[:, t]).all(), (i, t)
            else:
                assert same(got[:, t], rounded(cols[t], 1)), (i, t)
