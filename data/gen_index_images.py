#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate data/pw85_index_images.txt: periodic pairs whose image vector
r = (c_j + n*L) - c_i is not a double (issue 25, item 4).

Each record is a periodic box L, a stored ellipsoid (c_j, q_j), a candidate
(c_i, q_i) and the image shift n through which they meet, with centres up to
2^29 L (the index's limit), placed near contact (mu^2 = 1 + delta, delta
from +-1e-3 to +-1e-15 and 0) or well inside or outside it, and the
reference: mu^2 of the exact configuration, correctly rounded to a double.

r is formed exactly here, as a dyadic rational (Fractions: every double is
one), never in floating point; mu^2 comes from the certified integer route
of gen_ref_data.py (imported, not copied: exact polynomial data of the pair,
a root enclosure of the numerator of f' about 1e-96 wide, mu^2 correctly
rounded), fed the exact integers of r instead of a double vector.  Every
record is cross-checked by an independent mpmath route at 60 digits
(bisection on f', LU solves): the reference must lie within half an ulp of
it.  Nothing of libpw85 is used.

Layout: one record per line, hexadecimal doubles (float.hex) and integers,
blank-separated:
    L0 L1 L2  ci0 ci1 ci2  qi0..qi5  cj0 cj1 cj2  qj0..qj5  n0 n1 n2  mu2
Lines starting with '#' are comments.

Usage (from the repository root):
    /usr/bin/python3 data/gen_index_images.py [--out FILE] [--count N]
"""

import argparse
import math
import os
import random
import sys
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_ref_data as ref  # noqa: E402

import mpmath  # noqa: E402

SEED = 2529
DELTAS = [1e-3, 1e-8, 1e-12, 1e-14, 1e-15, 0.0]


def rotation(rng):
    """A random rotation (rows) from a uniform unit quaternion."""
    w, x, y, z = (rng.gauss(0, 1) for _ in range(4))
    n = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / n, x / n, y / n, z / n
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]


def form(rng, axes):
    """Q = R diag(a^2) R^T as doubles (a positive definite form)."""
    r = rotation(rng)
    q = []
    for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)):
        q.append(sum(r[i][k] * r[j][k] * axes[k] ** 2 for k in range(3)))
    return q


def mu2_certified(qi, qj, r):
    """mu^2 of (r, qi, qj) correctly rounded, r exact (Fractions)."""
    pair = ref.Pair(qi, qj)
    sr = max(f.denominator.bit_length() - 1 for f in r)
    ri = [int(f * (1 << sr)) for f in r]
    a = tuple(ref.xtax(ak, ri) for ak in pair.A)
    stats, p = ref.RootStats(), ref.P_BITS
    while True:
        res = ref._contact_p(pair, a, sr, p, stats)
        if res is not None:
            return res.mu2
        p += 256


def mu2_mp(qi, qj, r, dps=60):
    """mu^2 by bisection on f' = (1-2l) s.r - l(1-l) s.(Q2-Q1)s, at dps
    digits (an independent check)."""
    with mpmath.workdps(dps):
        def full(q):
            q = [mpmath.mpf(x) for x in q]
            return mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                                  [q[2], q[4], q[5]]])
        q1, q2 = full(qi), full(qj)
        rv = mpmath.matrix([mpmath.mpf(f.numerator) / f.denominator for f in r])

        def parts(lam):
            s = mpmath.lu_solve((1 - lam) * q1 + lam * q2, rv)
            return s, (rv.T * s)[0]

        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        for _ in range(3 * dps + 20):
            lam = (lo + hi) / 2
            s, rs = parts(lam)
            d = (1 - 2 * lam) * rs - lam * (1 - lam) * (s.T * (q2 - q1) * s)[0]
            if d > 0:
                lo = lam
            else:
                hi = lam
        lam = (lo + hi) / 2
        return lam * (1 - lam) * parts(lam)[1]


def record(rng, k):
    """One record: the k-th of the recipe (see the module's docstring)."""
    box = [float(rng.uniform(4.0, 8.0)) for _ in range(3)]
    size = rng.uniform(0.3, 1.0)
    qi = form(rng, [size, size * rng.uniform(0.2, 1), size * rng.uniform(0.01, 1)])
    qj = form(rng, [1.0, rng.uniform(0.2, 1), rng.uniform(0.01, 1)])
    # Centres: magnitudes 2^0 to 2^29 times the box, either sign.
    ci = [rng.choice((-1, 1)) * box[d] * 2.0 ** rng.uniform(0, 28.9)
          for d in range(3)]
    ci = [math.copysign(min(abs(x), 2.0 ** 29 * box[d]), x)
          for d, x in enumerate(ci)]
    u = [rng.gauss(0, 1) for _ in range(3)]
    nu = math.sqrt(sum(x * x for x in u))
    u = [x / nu for x in u]
    # Scale the direction so that mu^2 is near 1 + delta (or far from 1).
    kind = k % (2 * len(DELTAS) + 2)
    if kind < 2 * len(DELTAS):
        target = 1.0 + DELTAS[kind // 2] * (1 if kind % 2 == 0 else -1)
    else:
        target = 0.3 if kind == 2 * len(DELTAS) else 2.5
    unit = float(mu2_mp(qi, qj, [Fraction(x) for x in u], dps=30))
    scale = math.sqrt(target / unit)
    # The stored centre: near the candidate's image, wrapped to a copy of
    # the box picked at random (its own magnitude up to 2^29 L too).
    # Near contact, the stored centre stays in the box (copy 0: its
    # resolution, ulp(L), lets two corrections along u bring mu^2 within an
    # ulp or so of 1 + delta); else in a random copy, up to 2^28 boxes away.
    near = kind < 2 * len(DELTAS)
    n, cj = [], []
    for d in range(3):
        x = ci[d] + scale * u[d]
        copy = 0 if near else rng.choice((0, 1, -1, rng.randint(-(1 << 28), 1 << 28)))
        w = math.floor(x / box[d]) - copy
        n.append(w)
        cj.append(float(Fraction(x) - w * Fraction(box[d])))

    def exact_r():
        return [Fraction(cj[d]) + n[d] * Fraction(box[d]) - Fraction(ci[d])
                for d in range(3)]
    for _ in range(2 if near else 0):
        r = exact_r()
        grow = math.sqrt(target / float(mu2_mp(qi, qj, r, dps=40))) - 1
        cj = [float(Fraction(cj[d]) + Fraction(grow) * r[d]) for d in range(3)]
    r = exact_r()
    for d in range(3):
        if abs(cj[d]) > 2.0 ** 29 * box[d]:
            raise AssertionError("centre beyond 2^29 L")
    mu2 = mu2_certified(qi, qj, r)
    check = mu2_mp(qi, qj, r)
    if abs(check - mpmath.mpf(mu2)) > mpmath.mpf(mu2) * 2.0 ** -52:
        raise AssertionError("mpmath and the certified route disagree")
    if abs(check / mpmath.mpf(mu2) - 1) > 2.0 ** -53 * (1 + 1e-6):
        raise AssertionError("mu2 not within half an ulp of mpmath's")
    fields = box + ci + qi + cj + qj
    return " ".join([x.hex() for x in fields] + [str(x) for x in n] + [mu2.hex()])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "pw85_index_images.txt"))
    parser.add_argument("--count", type=int, default=112)
    args = parser.parse_args()
    rng = random.Random(SEED)
    lines = ["# Periodic image vectors formed exactly: data/gen_index_images.py",
             "# L[3] c_i[3] q_i[6] c_j[3] q_j[6] n[3] mu2 (hex doubles)"]
    for k in range(args.count):
        lines.append(record(rng, k))
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
