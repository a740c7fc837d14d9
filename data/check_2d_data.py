#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Check data/pw85_2d_pairs.h5 and data/pw85_2d_geometry.h5 (issue 29)
against a fresh recomputation by the machinery of gen_2d_data.py.

* layout: datasets, shapes, dtypes, class names, counts and order;
* every pair: both forms positive definite in exact rational arithmetic,
  MU2, LAMBDA, MU2_MINUS_1, ONE_MINUS_LAMBDA and LAMBDA_WINDOW recomputed by
  the certified exact route (route A) and compared bit for bit; COND1, COND2
  recomputed; route B (mpmath) at d and 2d digits on a random sample;
* a random sample of records regenerated from the seed (inputs and every
  reference, with all the generator's checks);
* geometry: every row's inputs equal to its pair's, every reference
  recomputed (with the identities), finite differences on a random sample;
  every constructor case regenerated.

Usage:  /usr/bin/python3 data/check_2d_data.py [DATA_DIR] [--sample N]
            [--pairs FILE] [--geometry FILE] [--seed S]
Exit status 0 if everything matches, 1 on any mismatch, 77 (skipped) if
numpy, h5py or mpmath cannot be imported.
"""

import argparse
import os
import sys
import time

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

try:
    import h5py
    import mpmath
    import numpy as np
    del mpmath  # only its presence: gen_2d_data imports it where used
except ImportError as e:  # pragma: no cover
    print("skipped: %s" % e)
    sys.exit(77)

import gen_2d_data as gen  # noqa: E402


class Checker:
    def __init__(self):
        self.failures = 0

    def fail(self, msg):
        self.failures += 1
        if self.failures <= 30:
            print("MISMATCH: " + msg)

    def same(self, what, got, want):
        """Bit-for-bit equality (NaN equal to NaN)."""
        a = np.asarray(got, dtype=np.float64)
        b = np.asarray(want, dtype=np.float64)
        if a.shape != b.shape or a.tobytes() != b.tobytes():
            self.fail("%s: %r != %r" % (what, got, want))
            return False
        return True


def read(f, names):
    return {n: f[n][()] for n in names}


def check_pairs(ck, path, seed, sample, rng, strict_counts=True):
    spec = gen.PAIR_DATASETS
    with h5py.File(path, "r") as f:
        names = [n for n, _, _, _ in spec]
        for n, width, dtype, _ in spec:
            if n not in f:
                ck.fail("%s: no dataset %s" % (path, n))
                return None
        d = read(f, names)
        cn = [x.decode() for x in f["CLASS_NAMES"][()]]
        attr_seed = int(f.attrs["seed"])
    n = len(d["MU2"])
    for name, width, dtype, _ in spec:
        shape = (n, width) if width else (n,)
        if d[name].shape != shape or d[name].dtype != np.dtype(dtype):
            ck.fail("%s: shape %r dtype %s" % (name, d[name].shape,
                                                d[name].dtype))
    if tuple(cn) != gen.CLASS_NAMES:
        ck.fail("CLASS_NAMES %r" % cn)
    if attr_seed != seed:
        ck.fail("seed attribute %d, expected %d" % (attr_seed, seed))
    counts = [int(np.sum(d["CLASS"] == i)) for i in range(len(gen.CLASSES))]
    want = np.concatenate([np.full(c, i, dtype=np.int32)
                           for i, c in enumerate(counts)])
    if d["CLASS"].tobytes() != want.tobytes():
        ck.fail("classes not in order")
    if strict_counts and counts != [c for _, c in gen.CLASSES]:
        ck.fail("class counts %r" % counts)
    t0 = time.time()
    for i in range(n):
        r, q1, q2 = (list(map(float, d[k][i])) for k in ("R12", "Q1", "Q2"))
        if not (gen.positive_definite_exact(q1)
                and gen.positive_definite_exact(q2)):
            ck.fail("pair %d: form not positive definite" % i)
            continue
        res = gen.contact_exact(r, q1, q2)
        for key, v in (("MU2", res.mu2), ("LAMBDA", res.lam),
                       ("MU2_MINUS_1", res.mu2m1),
                       ("ONE_MINUS_LAMBDA", res.oml),
                       ("LAMBDA_WINDOW", res.window)):
            ck.same("pair %d %s" % (i, key), d[key][i], v)
        a, b = gen.ab_polys(r, q1, q2)
        ck.same("pair %d F" % i, d["F"][i],
                [float(gen.f_exact(a, b, gen.fr(x)))
                 for x in d["F_LAMBDA"][i]])
        if d["F_LAMBDA"][i][0] != d["LAMBDA"][i] or d["F_LAMBDA"][i][1] != 0.5:
            ck.fail("pair %d F_LAMBDA" % i)
        for key, q in (("COND1", q1), ("COND2", q2)):
            c = gen.cond_mp(q)
            if not c < gen.COND_MAX:
                ck.fail("pair %d: cond >= 1e16" % i)
            ck.same("pair %d %s" % (i, key), d[key][i], c)
    print("pairs: %d recomputed by the exact route (and F), forms positive "
          "definite, cond < 1e16 (%.0f s)" % (n, time.time() - t0))
    t0 = time.time()
    idx = sorted(rng.choice(n, size=min(sample, n), replace=False))
    for i in idx:
        r, q1, q2 = (list(map(float, d[k][i])) for k in ("R12", "Q1", "Q2"))
        extra = gen.extra_digits(d["LAMBDA_WINDOW"][i], d["LAMBDA"][i],
                                 d["ONE_MINUS_LAMBDA"][i])
        want = (d["MU2"][i], d["MU2_MINUS_1"][i], d["LAMBDA"][i],
                d["ONE_MINUS_LAMBDA"][i])
        for dps in (gen.DPS_B + extra, 2 * (gen.DPS_B + extra)):
            ck.same("pair %d route B at %d digits" % (i, dps),
                    gen.contact_mp(r, q1, q2, dps), want)
    print("pairs: %d random pairs by the mpmath route at d and 2d digits "
          "(%.0f s)" % (len(idx), time.time() - t0))
    t0 = time.time()
    starts = np.cumsum([0] + counts)
    idx = sorted(rng.choice(n, size=min(sample, n), replace=False))
    for i in idx:
        cls = int(np.searchsorted(starts, i, side="right") - 1)
        k = int(i - starts[cls])
        rec, _ = gen.pair_record((seed, cls, k))
        for name, _, _, _ in spec:
            ck.same("pair %d regenerated %s" % (i, name), d[name][i],
                    rec[name])
    print("pairs: %d random records regenerated from the seed (%.0f s)"
          % (len(idx), time.time() - t0))
    return d


def check_geometry(ck, path, pairs, sample, rng):
    with h5py.File(path, "r") as f:
        names = [n for n, _, _, _ in gen.GEOM_DATASETS]
        g = read(f, names)
        c = read(f["constructors"], [n for n, _, _, _ in gen.CTOR_DATASETS])
        cn = [x.decode() for x in f["CLASS_NAMES"][()]]
    if tuple(cn) != gen.CLASS_NAMES:
        ck.fail("geometry CLASS_NAMES %r" % cn)
    m = len(g["MU2"])
    for name, width, dtype, _ in gen.GEOM_DATASETS:
        shape = (m, width) if width else (m,)
        if g[name].shape != shape or g[name].dtype != np.dtype(dtype):
            ck.fail("geometry %s: shape %r dtype %s"
                    % (name, g[name].shape, g[name].dtype))
    t0 = time.time()
    fd_rows = set(rng.choice(m, size=min(sample, m), replace=False).tolist())
    worst = 0.0
    want_idx = []
    for i, (_, cnt) in enumerate(gen.CLASSES):
        rows = np.nonzero(pairs["CLASS"] == i)[0]
        want_idx += rows[:gen.GEOM_PER_CLASS].tolist()
    if g["PAIR_INDEX"].tolist() != want_idx:
        ck.fail("geometry PAIR_INDEX")
    for i in range(m):
        j = int(g["PAIR_INDEX"][i])
        rec = {k: pairs[k][j] for k in ("R12", "Q1", "Q2", "MU2", "LAMBDA",
                                        "ONE_MINUS_LAMBDA", "MU2_MINUS_1",
                                        "CLASS", "LAMBDA_WINDOW")}
        for k in ("R12", "Q1", "Q2", "CLASS", "MU2", "LAMBDA",
                  "ONE_MINUS_LAMBDA", "MU2_MINUS_1"):
            ck.same("geometry %d %s = pair %d's" % (i, k, j), g[k][i], rec[k])
        rec = {k: (list(map(float, v)) if np.ndim(v) else
                   (int(v) if k == "CLASS" else float(v)))
               for k, v in rec.items()}
        extra = gen.extra_digits(rec["LAMBDA_WINDOW"], rec["LAMBDA"],
                                 rec["ONE_MINUS_LAMBDA"])
        dps = gen.GEOM_DPS + extra
        got = gen.geometry(rec["R12"], rec["Q1"], rec["Q2"], dps)
        ref = gen.rounded(got)
        for k in gen.GEOM_REFS:
            ck.same("geometry %d %s" % (i, k), g[k][i], ref[k])
        ck.same("geometry %d COND_Q" % i, g["COND_Q"][i],
                gen.cond_of_mp(got["q_lambda"]))
        gen.identities(rec["R12"], rec["Q1"], rec["Q2"], got, dps)
        if i in fd_rows:
            err = gen.fd_check(rec["R12"], rec["Q1"], rec["Q2"], got, extra)
            worst = max(worst, max(err.values()))
            if not max(err.values()) <= gen.FD_RTOL:
                ck.fail("geometry %d: finite differences %r" % (i, err))
    print("geometry: %d rows recomputed with the identities, finite "
          "differences on %d (worst relative error %.1e) (%.0f s)"
          % (m, len(fd_rows), worst, time.time() - t0))
    t0 = time.time()
    tasks = [(kind, k) for kind, (_, cnt) in enumerate(gen.CTOR_KINDS)
             for k in range(cnt)]
    if len(tasks) != len(c["KIND"]):
        ck.fail("constructors: %d cases, expected %d"
                % (len(c["KIND"]), len(tasks)))
        return
    for i, t in enumerate(tasks):
        rec = gen.ctor_record(t)
        for name, _, _, _ in gen.CTOR_DATASETS:
            ck.same("constructor %d %s" % (i, name), c[name][i], rec[name])
    print("constructors: %d cases regenerated (%.0f s)"
          % (len(tasks), time.time() - t0))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("data_dir", nargs="?", default=HERE)
    ap.add_argument("--pairs", help="pairs file (default DATA_DIR/%s)"
                    % gen.PAIRS_FILE)
    ap.add_argument("--geometry", help="geometry file (default "
                    "DATA_DIR/%s; 'none' to skip)" % gen.GEOM_FILE)
    ap.add_argument("--seed", type=int, default=gen.SEED,
                    help="the generator's seed (for a held-out file)")
    ap.add_argument("--sample", type=int, default=100)
    args = ap.parse_args(argv)
    t0 = time.time()
    rng = np.random.default_rng(29)
    ck = Checker()
    pairs = check_pairs(ck, args.pairs or os.path.join(
        args.data_dir, gen.PAIRS_FILE), args.seed, args.sample, rng,
        strict_counts=args.pairs is None)
    gpath = args.geometry or os.path.join(args.data_dir, gen.GEOM_FILE)
    if pairs is not None and args.geometry != "none":
        check_geometry(ck, gpath, pairs, max(1, args.sample // 2), rng)
    print("%s: %d mismatches (%.0f s)" % (
        "FAILED" if ck.failures else "OK", ck.failures, time.time() - t0))
    return 1 if ck.failures else 0


if __name__ == "__main__":
    sys.exit(main())
