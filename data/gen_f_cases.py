#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate data/pw85_f_cases.h5, the accuracy cases of f (issue 13, item 1).

Seeded cases (r12, q1, q2, lambda) in named classes, spread so that
cond(Q(lambda)), Q(lambda) = (1 - lambda) Q1 + lambda Q2 of the stored
doubles, covers 1e0 to just below 1e16 evenly in log scale: for each decade
1eK (K = 0 ... 15) and each class, the first COUNT candidates whose
cond(Q(lambda)) lies in [1eK, 1e(K+1)) are kept.  The classes mix random
rotations, shared and unshared principal directions, bad diagonal scaling
D.Q.D, lambda within 1e-12 ... 1e-3 of 0 or 1 and generic lambda; in every
class r12 is random, along or across the thin direction of Q(lambda), and
scaled by a power of ten.  The recipes are in data/README.md.

For every stored case:

* q1, q2 and Q(lambda) (exact rational value from the stored doubles) are
  positive definite in exact rational arithmetic (leading minors,
  Fractions);
* COND = lambda_max/lambda_min of Q(lambda) from mpmath.eigsy at 80 digits;
* F = f(lambda) = lambda (1 - lambda) r12^T Q(lambda)^-1 r12 rounded to the
  nearest double, from an mpmath LU solve at 100 digits;
* second method, on every case: f = lambda (1 - lambda) r^T adj(Q) r /
  det(Q) in exact rational arithmetic (Fractions), rounded once (Python's
  Fraction -> float is correctly rounded).  The generator raises if it
  differs from F in any case.

Usage (from the repository root):
    /usr/bin/python3 data/gen_f_cases.py [--outdir DIR] [--jobs N]
"""

import argparse
import math
import multiprocessing
import os
import sys
import time
from fractions import Fraction

import numpy as np

sys.dont_write_bytecode = True  # keep data/ free of __pycache__
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_ref_data as gen  # noqa: E402  (write_h5, sha256)

F_FILE = "pw85_f_cases.h5"
SEED = 1313
DECADES = 16          # cond(Q(lambda)) in [1e0, 1e16)
COUNT = 50            # cases per (decade, class)
COND_DPS = 80
F_DPS = 100
MAX_CANDIDATES = 5000  # per (decade, class): raise beyond

CLASS_NAMES = (
    "shared_rotation",      # one rotation, generic lambda
    "shared_rotation_end",  # one rotation, lambda near 0 or 1
    "unshared_thin_axis",   # thin axis (nearly) shared, others not
    "unshared_end",         # independent rotations, lambda near an end
    "diag_scaled",          # D.Q0.D, generic lambda
    "diag_scaled_end",      # D.Q0.D, lambda near 0 or 1
)


# Inputs ----------------------------------------------------------------------


def rotation(rng):
    q = rng.normal(size=4)
    return gen.rotation_from_quaternion(q / np.linalg.norm(q))


def axis_rotation(axis, angle):
    """Rodrigues: rotation by angle about the unit vector axis."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]],
                  [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


def form(rot, eig):
    """R diag(eig) R^T in doubles, upper triangle (storage of pw85.h)."""
    m = rot @ np.diag(eig) @ rot.T
    return [float(m[0, 0]), float(m[0, 1]), float(m[0, 2]), float(m[1, 1]),
            float(m[1, 2]), float(m[2, 2])]


def scaled(d, q0):
    """D Q0 D for D = diag(d), in doubles (one rounding per entry)."""
    idx = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))
    return [float(d[i] * q0[k] * d[j]) for k, (i, j) in enumerate(idx)]


def pattern(rng, t):
    """Eigenvalues [1, 10^-U(0, t), 10^-t]: cond 10^t."""
    return np.array([1.0, 10.0**-rng.uniform(0, t), 10.0**-t])


def jitter(rng, e, w=0.3):
    return e * gen.pow10(rng.uniform(-w, w, 3))


def near_end(rng):
    """(lambda, delta, end): lambda within delta = 10^U(-12, -3) of end."""
    delta = 10.0**rng.uniform(-12, -3)
    end = int(rng.integers(0, 2))
    return (delta if end == 0 else 1.0 - delta), delta, end


def make_forms(rng, cls, t):
    """(q1, q2, lambda) of class cls aiming at cond(Q(lambda)) ~ 10^t."""
    s = 10.0**rng.uniform(-3, 3)
    if cls in (0, 1):  # shared rotation
        rot = rotation(rng)
        e = pattern(rng, t)
        e1, e2 = s * jitter(rng, e), s * jitter(rng, e)
        if cls == 0:
            lam = float(rng.uniform(0, 1))
        else:  # the form at the far end weighs 10^U(-2, 2) as much
            lam, delta, end = near_end(rng)
            w = 10.0**rng.uniform(-2, 2) / delta
            if end == 0:
                e2 = e2 * w
            else:
                e1 = e1 * w
        return form(rot, e1), form(rot, e2), lam
    if cls == 2:  # thin axis shared up to a tilt, the other axes not
        r1 = rotation(rng)
        phi = rng.uniform(0, 2 * math.pi)
        rz = axis_rotation(np.array([0.0, 0.0, 1.0]), phi)
        u = rng.normal(size=3)
        u /= np.linalg.norm(u)
        theta = 10.0**(-t / 2 + rng.uniform(-1.5, 0))
        r2 = axis_rotation(u, theta) @ r1 @ rz
        e = pattern(rng, t)
        e1 = s * jitter(rng, e)
        e2 = s * 10.0**rng.uniform(-1, 1) * jitter(rng, e)
        return form(r1, e1), form(r2, e2), float(rng.uniform(0.02, 0.98))
    if cls == 3:  # independent rotations; the ill form dominates
        lam, delta, end = near_end(rng)
        ill = form(rotation(rng), s * pattern(rng, t))
        sw = s * 10.0**(-t + rng.uniform(-1, 0)) / delta
        well = form(rotation(rng), sw * pattern(rng, rng.uniform(0, 1)))
        return (ill, well, lam) if end == 0 else (well, ill, lam)
    # classes 4, 5: D Q0 D
    spread = max(t - rng.uniform(0, 1), 0.0) / 2
    o = rng.uniform(-3, 3)
    d = gen.pow10([o, o + spread, o + rng.uniform(0, spread)])
    d = d[rng.permutation(3)]
    q01 = form(rotation(rng), pattern(rng, rng.uniform(0, 1)))
    q02 = form(rotation(rng), pattern(rng, rng.uniform(0, 1)))
    d2 = d * gen.pow10(rng.uniform(-0.2, 0.2, 3))
    q1, q2 = scaled(d, q01), scaled(d2, q02)
    if cls == 4:
        return q1, q2, float(rng.uniform(0, 1))
    lam, delta, end = near_end(rng)
    w = 10.0**rng.uniform(-2, 2) / delta
    if end == 0:
        q2 = [x * w for x in q2]
    else:
        q1 = [x * w for x in q1]
    return q1, q2, lam


def full(q):
    return np.array([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                     [q[2], q[4], q[5]]])


def make_r12(rng, q1, q2, lam):
    """r12 random, along or across the thin direction of Q(lambda) (from a
    double eigendecomposition: only a recipe), times 10^k, k in [-20, 20]."""
    mode = int(rng.integers(0, 3))
    u = rng.normal(size=3)
    if mode:
        m = (1 - lam) * full(q1) + lam * full(q2)
        v = np.linalg.eigh(m / np.abs(m).max())[1][:, 0]
        if mode == 1:
            u = v + 1e-3 * u
        else:
            u = u - (u @ v) * v
    u /= np.linalg.norm(u)
    k = int(rng.integers(-20, 21))
    return [float(x * 10.0**k) for x in u], mode


# References ------------------------------------------------------------------


def frac6(q):
    return [Fraction(float(x)) for x in q]


def q_lambda_exact(q1, q2, lam):
    lf = Fraction(lam)
    return [(1 - lf) * a + lf * b for a, b in zip(frac6(q1), frac6(q2))]


def positive_definite(m):
    """Leading minors of the symmetric m[6] (Fractions), exact."""
    return (m[0] > 0 and m[0] * m[3] - m[1] * m[1] > 0
            and gen.det6(m) > 0)


def f_exact(r, q1, q2, lam):
    """lambda (1 - lambda) r^T adj(Q) r / det(Q), exact, rounded once."""
    m = q_lambda_exact(q1, q2, lam)
    lf = Fraction(lam)
    rf = [Fraction(float(x)) for x in r]
    return float(lf * (1 - lf) * gen.xtax(gen.adj6(m), rf) / gen.det6(m))


def mp_q_lambda(q1, q2, lam):
    import mpmath
    lf = mpmath.mpf(lam)

    def fm(q):
        q = [mpmath.mpf(float(x)) for x in q]
        return mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                              [q[2], q[4], q[5]]])
    return (1 - lf) * fm(q1) + lf * fm(q2), lf


def cond_mp(q1, q2, lam):
    import mpmath
    with mpmath.workdps(COND_DPS):
        m, _ = mp_q_lambda(q1, q2, lam)
        ev = mpmath.eigsy(m, eigvals_only=True)
        ev = sorted(ev[i] for i in range(3))
        if ev[0] <= 0:
            raise AssertionError("exact minors positive, eigenvalue <= 0")
        return float(ev[2] / ev[0])


def f_mp(r, q1, q2, lam):
    """f by an LU solve at F_DPS digits, rounded to the nearest double."""
    import mpmath
    with mpmath.workdps(F_DPS):
        m, lf = mp_q_lambda(q1, q2, lam)
        rv = mpmath.matrix([mpmath.mpf(float(x)) for x in r])
        s = mpmath.lu_solve(m, rv)
        return float(lf * (1 - lf) * (rv.T * s)[0])


def decade(cond):
    return int(math.floor(math.log10(cond)))


def candidate(K, cls, k):
    """The inputs (q1, q2, lambda, r12, r12 mode) of candidate k of decade K
    and class cls."""
    rng = np.random.default_rng([SEED, K, cls, k])
    t = K + rng.uniform(0, 1)
    q1, q2, lam = make_forms(rng, cls, t)
    r, mode = make_r12(rng, q1, q2, lam)
    return q1, q2, lam, r, mode


def make_cell(task):
    """The first COUNT accepted cases of decade K and class cls."""
    K, cls = task
    out, rejected = [], {"indefinite": 0, "decade": 0}
    k = 0
    while len(out) < COUNT:
        if k >= MAX_CANDIDATES:
            raise AssertionError("decade %d class %d: too few" % (K, cls))
        q1, q2, lam, r, mode = candidate(K, cls, k)
        k += 1
        if not (0 < lam < 1 and positive_definite(frac6(q1))
                and positive_definite(frac6(q2))
                and positive_definite(q_lambda_exact(q1, q2, lam))):
            rejected["indefinite"] += 1
            continue
        cond = cond_mp(q1, q2, lam)
        if decade(cond) != K:
            rejected["decade"] += 1
            continue
        F = f_mp(r, q1, q2, lam)
        fx = f_exact(r, q1, q2, lam)
        if not (F == fx and F > 0 and abs(F) >= sys.float_info.min
                and math.isfinite(F)):
            raise AssertionError("decade %d class %d candidate %d: mpmath "
                                 "%r, exact %r" % (K, cls, k - 1, F, fx))
        out.append(dict(r12=r, q1=q1, q2=q2, lam=lam, F=F, cond=cond,
                        cls=cls, k=k - 1, mode=mode))
    return K, cls, out, rejected


def generate(outdir, jobs, log):
    import h5py  # noqa: F401
    import mpmath
    t0 = time.time()
    tasks = [(K, c) for K in range(DECADES) for c in range(len(CLASS_NAMES))]
    if jobs > 1:
        with multiprocessing.Pool(jobs) as pool:
            cells = list(pool.imap(make_cell, tasks, chunksize=1))
    else:
        cells = [make_cell(t) for t in tasks]
    records = [x for _, _, out, _ in cells for x in out]
    rej = {"indefinite": 0, "decade": 0}
    for _, _, _, r in cells:
        for key in rej:
            rej[key] += r[key]
    n = len(records)
    log("%d cases, %d candidates rejected (not positive definite: %d, cond "
        "outside the decade: %d); F of all %d identical by mpmath LU at %d "
        "digits and by exact rationals" % (n, sum(rej.values()),
                                           rej["indefinite"], rej["decade"],
                                           n, F_DPS))
    for i, nm in enumerate(CLASS_NAMES):
        cs = [x for x in records if x["cls"] == i]
        d = [min(x["lam"], 1 - x["lam"]) for x in cs]
        log("  class %d %-20s %4d cases, cond %.2g ... %.2g, "
            "min(lambda, 1 - lambda) %.2g ... %.2g" % (
                i, nm, len(cs), min(x["cond"] for x in cs),
                max(x["cond"] for x in cs), min(d), max(d)))
    modes = [sum(x["mode"] == m for x in records) for m in range(3)]
    log("  r12 random / along / across the thin direction: %d / %d / %d; "
        "|r12| %.2g ... %.2g; F %.2g ... %.2g" % (
            modes[0], modes[1], modes[2],
            min(np.linalg.norm(x["r12"]) for x in records),
            max(np.linalg.norm(x["r12"]) for x in records),
            min(x["F"] for x in records), max(x["F"] for x in records)))
    data = {
        "r12": np.array([x["r12"] for x in records], dtype=np.float64),
        "q1": np.array([x["q1"] for x in records], dtype=np.float64),
        "q2": np.array([x["q2"] for x in records], dtype=np.float64),
        "lambda": np.array([x["lam"] for x in records], dtype=np.float64),
        "F": np.array([x["F"] for x in records], dtype=np.float64),
        "COND": np.array([x["cond"] for x in records], dtype=np.float64),
        "class": np.array([x["cls"] for x in records], dtype=np.int32),
    }
    recipe = (
        "pw85 accuracy cases of f (issue 13, item 1), generated by "
        "data/gen_f_cases.py with numpy %s and mpmath %s. Case k of decade K "
        "and class c drawn from np.random.default_rng([%d, K, c, k]); for "
        "each (K, c) the first %d candidates with cond(Q(lambda)) in [1eK, "
        "1e(K+1)) are kept, records ordered by K, then c. q1, q2, Q(lambda) "
        "positive definite in exact rational arithmetic; COND = cond2("
        "Q(lambda)) from mpmath eigsy at %d digits; F = lambda (1 - lambda) "
        "r12^T Q(lambda)^-1 r12 correctly rounded (mpmath LU at %d digits, "
        "identical to exact rational arithmetic on every case). Classes "
        "(dataset class, attribute class_names, comma-separated; attribute "
        "candidates: the k of each record; data/README.md gives the "
        "recipes)." % (np.__version__, mpmath.__version__, SEED, COUNT,
                       COND_DPS, F_DPS))
    path = os.path.join(outdir, F_FILE)
    gen.write_h5(path, data, {k: None for k in data},
                 {"description": np.bytes_(recipe), "seed": SEED,
                  "class_names": np.bytes_(",".join(CLASS_NAMES)),
                  "candidates": np.array([x["k"] for x in records],
                                         dtype=np.int64)})
    log("wrote %s: %d cases (%.0f s)" % (path, n, time.time() - t0))
    return data


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--outdir", default=here)
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args(argv)
    t0 = time.time()

    def log(msg):
        print(msg, flush=True)

    os.makedirs(args.outdir, exist_ok=True)
    generate(args.outdir, max(args.jobs, 1), log)
    p = os.path.join(args.outdir, F_FILE)
    log("%s  %s  (%d bytes)" % (gen.sha256(p), F_FILE, os.path.getsize(p)))
    log("total run time: %.1f s" % (time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
