#!/usr/bin/python3
"""Check the committed pw85 reference data against a fresh recomputation.

Usage:  /usr/bin/python3 data/check_ref_data.py [DATA_DIR] [--seed N]

DATA_DIR defaults to the folder of this script.  The small data sets
(radii, directions, spheroids, lambdas, distances) are recomputed and
compared exactly; a deterministic random sample of F, MU2/LAMBDA and of the
general pairs, and every finish pair (inputs regenerated from the seed), is
recomputed with the exact/certified routines of
gen_ref_data.py (same folder) and compared bit for bit, and a smaller sample
with the independent mpmath route.  Every hard pair (pw85_hard_pairs.h5) is
recomputed and certified with gen_hard_set.py, and a sample is regenerated
from the seed.  In pw85_geometry_pairs.h5, a sample of pairs and every
constructor case is regenerated with gen_geometry.py (which repeats its own
checks: cold start at higher precision, exact route, identities, finite
differences) and compared bit for bit.  Exit status: 0 if everything matches,
1 on any mismatch, 77 (meson's "skipped") if numpy/h5py/mpmath are missing.
"""

import argparse
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.dont_write_bytecode = True  # keep data/ free of __pycache__

try:
    import numpy as np
    import h5py  # noqa: F401
    import mpmath  # noqa: F401
except ImportError as exc:  # pragma: no cover
    print("SKIP: %s (run with /usr/bin/python3)" % exc)
    sys.exit(77)

import gen_ref_data as gen  # noqa: E402
import gen_hard_set as hard  # noqa: E402
import gen_f_cases as fcases  # noqa: E402
import gen_geometry as geom  # noqa: E402

N_F = 20000
N_MU = 3000
N_GENERAL = 2000
N_F_MP = 500
N_MU_MP = 100
N_GENERAL_MP = 50
N_FINISH_MP = 50
N_HARD_REGEN = 150
N_HARD_COND = 300
N_F_CASES_MP = 300
N_F_CASES_REGEN = 150
N_GEOMETRY_PAIRS = 100


class Checker:
    def __init__(self):
        self.failures = 0

    def check(self, ok, what):
        if not ok:
            self.failures += 1
            if self.failures <= 20:
                print("MISMATCH: " + what)
            elif self.failures == 21:
                print("(further mismatches are counted, not printed)")
        return ok


def same(a, b):
    """Bitwise equality of float64 arrays (also distinguishes 0.0/-0.0)."""
    a = np.ascontiguousarray(a, dtype=np.float64)
    b = np.ascontiguousarray(b, dtype=np.float64)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def main(argv=None):
    ap = argparse.ArgumentParser(description="check pw85 reference data")
    ap.add_argument("datadir", nargs="?", default=HERE)
    ap.add_argument("--seed", type=int, default=2019)
    args = ap.parse_args(argv)
    t0 = time.time()
    ck = Checker()
    rng = np.random.default_rng(args.seed)

    path = os.path.join(args.datadir, gen.REF_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        d = {k: f[k][...] for k in f}
    expected_shapes = {
        "radii": (3,), "directions": (12, 3), "spheroids": (108, 6),
        "lambdas": (11,), "distances": (3,), "F": (108, 108, 12, 11),
        "MU2": (108, 108, 12, 3), "LAMBDA": (108, 108, 12, 3)}
    for k, shp in expected_shapes.items():
        ck.check(k in d and d[k].shape == shp and d[k].dtype == np.float64,
                 "dataset %s: expected float64 %s" % (k, shp))
    if ck.failures:
        return 1
    radii = gen.make_radii()
    directions = gen.make_directions()
    ck.check(same(d["radii"], radii), "radii")
    ck.check(same(d["directions"], directions), "directions")
    ck.check(same(d["spheroids"], gen.make_spheroids(radii, directions)),
             "spheroids")
    ck.check(same(d["lambdas"], gen.make_lambdas()), "lambdas")
    ck.check(same(d["distances"], gen.make_distances()), "distances")
    print("  radii, directions, spheroids, lambdas, distances: recomputed, "
          "compared exactly")

    fails = gen.invariant_failures(d)
    for msg in fails:
        ck.check(False, msg)
    print("  exact invariants of the full F, MU2, LAMBDA arrays (evenness in "
          "r, identical spheroids, F(0)=F(1)=0, LAMBDA=1/2 for q1 == q2): "
          "%d failures" % len(fails))

    sph = [list(map(float, q)) for q in d["spheroids"]]
    dirs = [list(map(float, v)) for v in d["directions"]]
    lams = [float(x) for x in d["lambdas"]]
    dists = [float(x) for x in d["distances"]]
    F, MU2, LAM = d["F"], d["MU2"], d["LAMBDA"]

    bad = 0
    for t in range(N_F):
        i, j, k, l = (int(rng.integers(0, n)) for n in F.shape)
        v = gen.f_value_F(gen.Pair(sph[i], sph[j]), dirs[k], lams[l])
        bad += not ck.check(same(v, F[i, j, k, l]),
                            "F[%d,%d,%d,%d] = %r, recomputed %r"
                            % (i, j, k, l, F[i, j, k, l], v))
        if t < N_F_MP:
            w = gen.f_mp(lams[l], dirs[k], sph[i], sph[j], dps=80)
            bad += not ck.check(same(w, F[i, j, k, l]),
                                "F[%d,%d,%d,%d] = %r, mpmath %r"
                                % (i, j, k, l, F[i, j, k, l], w))
    print("  F: %d random entries recomputed exactly (%d of them also with "
          "mpmath at 80 digits): %d mismatches" % (N_F, N_F_MP, bad))

    bad = 0
    for t in range(N_MU):
        i, j, k, m = (int(rng.integers(0, n)) for n in MU2.shape)
        r = gen.r12_vector(dists[m], dirs[k])
        res = gen.contact(gen.Pair(sph[i], sph[j]), r)
        bad += not ck.check(
            same([res.mu2, res.lam], [MU2[i, j, k, m], LAM[i, j, k, m]]),
            "MU2/LAMBDA[%d,%d,%d,%d] = %r %r, recomputed %r %r"
            % (i, j, k, m, MU2[i, j, k, m], LAM[i, j, k, m], res.mu2,
               res.lam))
        if t < N_MU_MP:
            mu2, lam, _ = gen.contact_mp(r, sph[i], sph[j], dps=100)
            bad += not ck.check(
                same([mu2, lam], [MU2[i, j, k, m], LAM[i, j, k, m]]),
                "MU2/LAMBDA[%d,%d,%d,%d] = %r %r, mpmath %r %r"
                % (i, j, k, m, MU2[i, j, k, m], LAM[i, j, k, m], mu2, lam))
    print("  MU2/LAMBDA: %d random entries recomputed (certified, %d "
          "fractional bits; %d of them also with mpmath at 100 digits): "
          "%d mismatches" % (N_MU, gen.P_BITS, N_MU_MP, bad))

    path = os.path.join(args.datadir, gen.GENERAL_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        g = {k: f[k][...] for k in f}
    n = gen.GENERAL_N
    before = ck.failures
    for k, shp in (("r12", (n, 3)), ("q1", (n, 6)), ("q2", (n, 6)),
                   ("MU2", (n,)), ("LAMBDA", (n,)), ("MU2_MINUS_1", (n,)),
                   ("delta", (n,))):
        ck.check(k in g and g[k].shape == shp and g[k].dtype == np.float64,
                 "general pairs dataset %s: expected float64 %s" % (k, shp))
    if ck.failures > before:
        return 1
    bad = 0
    for t, c in enumerate(rng.permutation(n)[:N_GENERAL]):
        c = int(c)
        q1 = [float(x) for x in g["q1"][c]]
        q2 = [float(x) for x in g["q2"][c]]
        r = [float(x) for x in g["r12"][c]]
        ok = gen.positive_definite_exact(q1) and gen.positive_definite_exact(q2)
        bad += not ck.check(ok, "general pair %d: q not positive definite" % c)
        res = gen.contact(gen.Pair(q1, q2), r)
        stored = [g["MU2"][c], g["LAMBDA"][c], g["MU2_MINUS_1"][c]]
        bad += not ck.check(same([res.mu2, res.lam, res.mu2m1], stored),
                            "general pair %d: stored %r, recomputed %r"
                            % (c, stored, [res.mu2, res.lam, res.mu2m1]))
        if t < N_GENERAL_MP:
            mp = gen.contact_mp(r, q1, q2, dps=100)
            bad += not ck.check(same(list(mp), stored),
                                "general pair %d: stored %r, mpmath %r"
                                % (c, stored, list(mp)))
    print("  general pairs: %d random cases recomputed (%d also with "
          "mpmath): %d mismatches" % (N_GENERAL, N_GENERAL_MP, bad))

    path = os.path.join(args.datadir, gen.FINISH_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        g = {k: f[k][...] for k in f}
        candidates = [int(k) for k in f.attrs["candidates"]]
    n = len(gen.FINISH_CASES)
    before = ck.failures
    ck.check(candidates == list(gen.FINISH_CASES),
             "finish pairs: attribute candidates differs from FINISH_CASES")
    for k, shp in (("r12", (n, 3)), ("q1", (n, 6)), ("q2", (n, 6)),
                   ("MU2", (n,)), ("LAMBDA", (n,)), ("MU2_MINUS_1", (n,)),
                   ("delta", (n,))):
        ck.check(k in g and g[k].shape == shp and g[k].dtype == np.float64,
                 "finish pairs dataset %s: expected float64 %s" % (k, shp))
    if ck.failures > before:
        return 1
    # every case: the inputs regenerated from the seed, the references
    # recomputed; a sample also with mpmath
    bad = 0
    mp_cases = set(int(c) for c in rng.permutation(n)[:N_FINISH_MP])
    for c, k in enumerate(gen.FINISH_CASES):
        q1, q2, r, dl, _ = gen.finish_inputs(k)
        bad += not ck.check(
            same(list(r) + list(q1) + list(q2) + [dl],
                 np.concatenate([g["r12"][c], g["q1"][c], g["q2"][c],
                                 [g["delta"][c]]])),
            "finish pair %d: inputs differ from candidate %d" % (c, k))
        res = gen.contact(gen.Pair(q1, q2), r)
        stored = [g["MU2"][c], g["LAMBDA"][c], g["MU2_MINUS_1"][c]]
        bad += not ck.check(same([res.mu2, res.lam, res.mu2m1], stored),
                            "finish pair %d: stored %r, recomputed %r"
                            % (c, stored, [res.mu2, res.lam, res.mu2m1]))
        if c in mp_cases:
            mp = gen.contact_mp(r, q1, q2, dps=100)
            bad += not ck.check(same(list(mp), stored),
                                "finish pair %d: stored %r, mpmath %r"
                                % (c, stored, list(mp)))
    print("  finish pairs: all %d cases regenerated and recomputed (%d also "
          "with mpmath): %d mismatches" % (n, N_FINISH_MP, bad))
    check_hard(args.datadir, ck, rng)
    check_f_cases(args.datadir, ck, rng)
    check_geometry(args.datadir, ck, rng)
    print("%s (%.1f s)" % ("FAILED: %d mismatches" % ck.failures
                           if ck.failures else "all checks passed",
                           time.time() - t0))
    return 1 if ck.failures else 0


def check_hard(datadir, ck, rng):
    """pw85_hard_pairs.h5: shapes, classes, every reference recomputed and
    certified, the reproducers against issue 13's hex floats, a sample of
    records regenerated from the seed (inputs, references, cond, mpmath)."""
    path = os.path.join(datadir, hard.HARD_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        g = {k: f[k][...] for k in f}
        names = f.attrs["class_names"].decode().split(",")
        candidates = [int(k) for k in f.attrs["candidates"]]
    n = sum(c for _, c in hard.CLASSES)
    before = ck.failures
    ck.check(names == list(hard.CLASS_NAMES),
             "hard pairs: class_names %r" % names)
    for k, shp in (("r12", (n, 3)), ("q1", (n, 6)), ("q2", (n, 6)),
                   ("MU2", (n,)), ("LAMBDA", (n,)), ("MU2_MINUS_1", (n,)),
                   ("cond1", (n,)), ("cond2", (n,))):
        ck.check(k in g and g[k].shape == shp and g[k].dtype == np.float64,
                 "hard pairs dataset %s: expected float64 %s" % (k, shp))
    ck.check("class" in g and g["class"].shape == (n,)
             and g["class"].dtype == np.int32, "hard pairs dataset class")
    ck.check(len(candidates) == n, "hard pairs: attribute candidates")
    if ck.failures > before:
        return
    expected = np.repeat(np.arange(len(hard.CLASSES), dtype=np.int32),
                         [c for _, c in hard.CLASSES])
    ck.check(same(g["class"].astype(np.float64), expected.astype(np.float64)),
             "hard pairs: class counts differ from CLASSES")
    for i, (r, q1, q2) in enumerate(hard.REPRODUCERS):
        ck.check(same([float.fromhex(x) for x in r + q1 + q2],
                      np.concatenate([g["r12"][i], g["q1"][i],
                                      g["q2"][i]])),
                 "hard pair %d: not issue 13's reproducer %d" % (i, i))
    # every pair: exact positive definiteness, references recomputed and
    # certified (sign change of f' across lambda* +- 1e-50 min(...))
    bad = 0
    for c in range(n):
        r, q1, q2 = list(g["r12"][c]), list(g["q1"][c]), list(g["q2"][c])
        ok = gen.positive_definite_exact(q1) and \
            gen.positive_definite_exact(q2)
        pair = gen.Pair(q1, q2)
        res = gen.contact(pair, r)
        stored = [g["MU2"][c], g["LAMBDA"][c], g["MU2_MINUS_1"][c]]
        ok = ok and same([res.mu2, res.lam, res.mu2m1], stored)
        try:
            hard.certify(pair, r, res)
        except AssertionError:
            ok = False
        bad += not ck.check(ok, "hard pair %d: stored %r, recomputed %r"
                            % (c, stored, [res.mu2, res.lam, res.mu2m1]))
    print("  hard pairs: all %d references recomputed and certified: %d "
          "mismatches" % (n, bad))
    bad = 0
    for c in rng.permutation(n)[:N_HARD_COND]:
        conds = [hard.cond_mp(list(g["q1"][c])), hard.cond_mp(list(g["q2"][c]))]
        bad += not ck.check(same(conds, [g["cond1"][c], g["cond2"][c]]),
                            "hard pair %d: cond %r" % (c, conds))
    print("  hard pairs: cond1, cond2 of %d random pairs recomputed: %d "
          "mismatches" % (N_HARD_COND, bad))
    bad = 0
    for c in sorted(int(x) for x in rng.permutation(n)[:N_HARD_REGEN]):
        out = hard.candidate((int(g["class"][c]), candidates[c]))
        ok = isinstance(out, dict)
        if ok:
            mine = out["r"] + out["q1"] + out["q2"] + [
                out["mu2"], out["lam"], out["m1"], out["cond1"],
                out["cond2"]]
            ok = same(mine, np.concatenate([
                g["r12"][c], g["q1"][c], g["q2"][c],
                [g["MU2"][c], g["LAMBDA"][c], g["MU2_MINUS_1"][c],
                 g["cond1"][c], g["cond2"][c]]])) and \
                out["mp"] == (out["mu2"], out["lam"], out["m1"])
        bad += not ck.check(ok, "hard pair %d: regenerated from candidate "
                            "%d differs" % (c, candidates[c]))
    print("  hard pairs: %d random pairs regenerated from the seed (inputs, "
          "references, cond, mpmath route): %d mismatches"
          % (N_HARD_REGEN, bad))


def check_f_cases(datadir, ck, rng):
    """pw85_f_cases.h5: shapes, classes and decades, every F recomputed in
    exact rationals with positive definiteness, a sample of F and COND by
    mpmath, a sample of records regenerated from the seed."""
    path = os.path.join(datadir, fcases.F_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        g = {k: f[k][...] for k in f}
        names = f.attrs["class_names"].decode().split(",")
        candidates = [int(k) for k in f.attrs["candidates"]]
    nc = len(fcases.CLASS_NAMES)
    n = fcases.DECADES * nc * fcases.COUNT
    ck.check(names == list(fcases.CLASS_NAMES),
             "f cases: class_names %r" % names)
    for k, shp in (("r12", (n, 3)), ("q1", (n, 6)), ("q2", (n, 6)),
                   ("lambda", (n,)), ("F", (n,)), ("COND", (n,))):
        ck.check(g[k].shape == shp and g[k].dtype == np.float64,
                 "f cases dataset %s: expected float64 %s" % (k, shp))
    ck.check(g["class"].shape == (n,) and g["class"].dtype == np.int32,
             "f cases dataset class")
    ck.check(len(candidates) == n, "f cases: attribute candidates")
    cell = np.arange(n) // fcases.COUNT  # records ordered by decade, class
    ck.check(np.array_equal(g["class"], (cell % nc).astype(np.int32)),
             "f cases: classes not in the documented order")
    decades = np.array([fcases.decade(c) for c in g["COND"]])
    ck.check(np.array_equal(decades, cell // nc),
             "f cases: COND not in the decade of its record")

    def inputs(c):
        return (list(g["r12"][c]), list(g["q1"][c]), list(g["q2"][c]),
                float(g["lambda"][c]))
    bad = 0
    for c in range(n):
        r, q1, q2, lam = inputs(c)
        ok = (fcases.positive_definite(fcases.frac6(q1))
              and fcases.positive_definite(fcases.frac6(q2))
              and fcases.positive_definite(
                  fcases.q_lambda_exact(q1, q2, lam))
              and same([fcases.f_exact(r, q1, q2, lam)], [g["F"][c]]))
        bad += not ck.check(ok, "f case %d: F %r or positive definiteness"
                            % (c, g["F"][c]))
    print("  f cases: all %d F recomputed in exact rationals, forms and "
          "Q(lambda) positive definite: %d mismatches" % (n, bad))
    bad = 0
    for c in sorted(rng.choice(n, N_F_CASES_MP, replace=False)):
        r, q1, q2, lam = inputs(c)
        ok = same([fcases.f_mp(r, q1, q2, lam), fcases.cond_mp(q1, q2, lam)],
                  [g["F"][c], g["COND"][c]])
        bad += not ck.check(ok, "f case %d: mpmath F or COND differs" % c)
    print("  f cases: F and COND of %d random cases recomputed with mpmath: "
          "%d mismatches" % (N_F_CASES_MP, bad))
    bad = 0
    for c in sorted(rng.choice(n, N_F_CASES_REGEN, replace=False)):
        q1, q2, lam, r, _ = fcases.candidate(int(cell[c] // nc),
                                             int(cell[c] % nc), candidates[c])
        ok = same(r + q1 + q2 + [lam], list(g["r12"][c]) + list(g["q1"][c])
                  + list(g["q2"][c]) + [g["lambda"][c]])
        bad += not ck.check(ok, "f case %d: regenerated from candidate %d "
                            "differs" % (c, candidates[c]))
    print("  f cases: %d random cases regenerated from the seed: %d "
          "mismatches" % (N_F_CASES_REGEN, bad))


def check_geometry(datadir, ck, rng):
    """pw85_geometry_pairs.h5: shapes, a random sample of pairs and every
    constructor case regenerated from the seed (inputs and references, with
    the generator's own checks), compared bit for bit."""
    path = os.path.join(datadir, geom.GEOM_FILE)
    print("checking %s" % path)
    with h5py.File(path, "r") as f:
        g = {k: f[k][...] for k in f if isinstance(f[k], h5py.Dataset)}
        c = {k: v[...] for k, v in f["constructors"].items()}
    n = sum(m for _, m in geom.PAIR_BLOCKS)
    m = sum(m for _, m in geom.CTOR_KINDS)
    for group, spec, rows in ((g, geom.PAIR_DATASETS, n),
                              (c, geom.CTOR_DATASETS, m)):
        for name, width, _, _ in spec:
            shp = (rows, width) if width else (rows,)
            ck.check(name in group and group[name].shape == shp,
                     "geometry dataset %s: expected shape %s" % (name, shp))
    if ck.failures:
        return
    tasks = [(b, k) for b, (_, cnt) in enumerate(geom.PAIR_BLOCKS)
             for k in range(cnt)]
    bad = 0
    for i in sorted(rng.choice(n, N_GEOMETRY_PAIRS, replace=False)):
        try:
            rec, _ = geom.pair_record(tasks[i])
            ok = all(same(np.atleast_1d(rec[name]), np.atleast_1d(g[name][i]))
                     for name, _, _, _ in geom.PAIR_DATASETS)
        except AssertionError as exc:
            ok = False
            print("  pair %d: %s" % (i, exc))
        bad += not ck.check(ok, "geometry pair %d differs" % i)
    print("  geometry pairs: %d random records regenerated and recomputed "
          "(with finite differences): %d mismatches" % (N_GEOMETRY_PAIRS, bad))
    tasks = [(kind, k) for kind, (_, cnt) in enumerate(geom.CTOR_KINDS)
             for k in range(cnt)]
    bad = 0
    for i, task in enumerate(tasks):
        try:
            rec, _ = geom.ctor_record(task)
            ok = all(same(np.atleast_1d(rec[name]), np.atleast_1d(c[name][i]))
                     for name, _, _, _ in geom.CTOR_DATASETS)
        except AssertionError as exc:
            ok = False
            print("  constructor case %d: %s" % (i, exc))
        bad += not ck.check(ok, "geometry constructor case %d differs" % i)
    print("  constructors: all %d cases regenerated and recomputed: %d "
          "mismatches" % (m, bad))


if __name__ == "__main__":
    sys.exit(main())
