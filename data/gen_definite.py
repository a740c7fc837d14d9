#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes data/pw85_definite_forms.txt: symmetric 3×3 forms (six doubles, upper
triangle row by row, as pw85.h stores them) with the exact verdict of
positive definiteness, decided here in rational arithmetic (Sylvester's
criterion on the exact values of the doubles, fractions.Fraction), never
by pw85. One form per line: `1` (positive definite) or `0`, then the six
entries as C99 hexadecimal floats.

The set aims at the edge of the rule: forms singular in exact arithmetic
and their neighbours a few ulps away on either side, the same scaled by
powers of two per axis (D·Q·D) so that their entries span the range of a
double and off-diagonal entries fall to subnormal numbers or far below
the diagonal, forms whose products overflow a double, and the fuzzer's
reproducer of issue 25. Seeded: the same file on every run.

    /usr/bin/python3 data/gen_definite.py   # from the top of the tree
"""
import math
import random
import sys
from fractions import Fraction as F
from pathlib import Path

OUT = Path(__file__).resolve().parent / "pw85_definite_forms.txt"


def positive_definite(q):
    """Sylvester's criterion, exactly: leading principal minors > 0."""
    a00, a01, a02, a11, a12, a22 = (F(x) for x in q)
    m2 = a00 * a11 - a01 * a01
    det = (a00 * (a11 * a22 - a12 * a12) - a01 * (a01 * a22 - a12 * a02)
           + a02 * (a01 * a12 - a11 * a02))
    return a00 > 0 and m2 > 0 and det > 0


def ulps(x, k):
    """x moved by k ulps (k may be negative)."""
    for _ in range(abs(k)):
        x = math.nextafter(x, math.inf if k > 0 else -math.inf)
    return x


def scaled(q, h):
    """D·Q·D for D = diag(2^h0, 2^h1, 2^h2), entry by entry in double
    (ldexp: exact unless the result leaves the normal range)."""
    pos = [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]
    return [math.ldexp(x, h[i] + h[j]) for x, (i, j) in zip(q, pos)]


def singular_bases(rng):
    """Forms singular in exact arithmetic, exactly representable: sums of
    two outer products of small integer vectors (rank 2), one outer
    product (rank 1), and forms with two equal rows below the first
    entry (as the reproducer of issue 25)."""
    out = []
    for _ in range(60):
        u = [rng.randint(-9, 9) for _ in range(3)]
        v = [rng.randint(-9, 9) for _ in range(3)]
        q = [u[i] * u[j] + v[i] * v[j]
             for i, j in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]]
        if q[0] > 0 and q[3] > 0 and q[5] > 0:
            out.append([float(x) for x in q])
    for _ in range(20):
        u = [rng.randint(1, 2**20) * rng.choice([-1, 1]) for _ in range(3)]
        out.append([float(u[i] * u[j]) for i, j in
                    [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]])
    for _ in range(20):
        a, b, c = rng.uniform(1, 2), rng.uniform(0.1, 0.5), rng.uniform(1, 2)
        out.append([a, b, b, c, c, c])  # det = −c·0 = 0: rows 1, 2 equal
    return out


def near(q, rng):
    """q with one entry moved by a few ulps (either way), or unchanged."""
    q = list(q)
    k = rng.randrange(6)
    q[k] = ulps(q[k], rng.choice([-3, -2, -1, 0, 1, 2, 3]))
    return q


def main():
    rng = random.Random(20261125)
    forms = []
    # The reproducer of issue 25 (fuzz-contact-raw): indefinite, off-diagonal
    # entries that a scaling by the diagonal takes below 2^−1074.
    forms.append([float.fromhex(x) for x in (
        "0x1.7e43c88p+996", "0x1.232323232005bp-220", "0x1.232322b323232p-220",
        "0x1.c6c6c6c6c6c6cp+711", "0x1.c6c6c6c6c6c6cp+711",
        "0x1.c6c6c6c6c6c6cp+711")])
    bases = singular_bases(rng)
    for base in bases:
        forms.append(base)
        for _ in range(6):
            forms.append(near(base, rng))
    # The same, scaled per axis by powers of two: moderate, then extreme
    # (entries from subnormal to near DBL_MAX; off-diagonal entries that
    # underflow once the diagonal is brought to one).
    for base in bases:
        for span in (40, 400, 1000):
            h = [rng.randint(-span // 2, span // 2) for _ in range(3)]
            for _ in range(3):
                q = scaled(near(base, rng), h)
                if all(math.isfinite(x) for x in q) and q[0] > 0 and \
                        q[3] > 0 and q[5] > 0:
                    forms.append(q)
    # The reproducer's family: a huge first axis, off-diagonal entries near
    # 2^-220 differing in their last bits, equal lower rows (indefinite),
    # and with the lower block made definite by one ulp.
    for _ in range(60):
        e0 = rng.randint(600, 1000)
        e1 = rng.randint(300, 800)
        d0 = math.ldexp(rng.uniform(1, 2), e0)
        d1 = math.ldexp(rng.uniform(1, 2), e1)
        o = math.ldexp(rng.uniform(1, 2), -rng.randint(100, 300))
        o2 = ulps(o, rng.choice([-5, -1, 0, 1, 5]))
        d2 = ulps(d1, rng.choice([0, 0, 1, 2]))
        forms.append([d0, o, o2, d1, d1, d2])
    # Random definite forms R·diag(e)·Rᵀ rounded to double, eigenvalues from
    # 1 down to 1e-20 (rounding makes the smallest ones indefinite or not),
    # times a power of two.
    for _ in range(600):
        w, x, y, z = (rng.gauss(0, 1) for _ in range(4))
        n = math.sqrt(w * w + x * x + y * y + z * z)
        w, x, y, z = w / n, x / n, y / n, z / n
        r = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
             [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
             [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
        ev = [1.0, 10.0 ** -rng.uniform(0, 20), 10.0 ** -rng.uniform(0, 20)]
        s = rng.randint(-1000, 990)
        q = []
        for i, j in [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)]:
            v = sum(F(r[i][m]) * F(r[j][m]) * F(ev[m]) for m in range(3))
            q.append(math.ldexp(float(v), s))
        if all(math.isfinite(t) for t in q) and q[0] > 0 and q[3] > 0 and q[5] > 0:
            forms.append(q)
    # 2×2 minors at the edge: Q00·Q11 = Q01² exactly, then one ulp either
    # way, with a dominant third axis.
    for _ in range(60):
        a = rng.randint(1, 2**26)
        b = rng.randint(1, 2**26)
        s = rng.randint(-500, 500)
        q0, q1, q3 = float(a * a), float(a * b), float(b * b)
        base = [math.ldexp(q0, s), math.ldexp(q1, s), 0.0, math.ldexp(q3, s),
                0.0, math.ldexp(1.0, s + 60)]
        forms.append(base)
        forms.append(near(base, rng))
    lines = []
    for q in forms:
        assert all(math.isfinite(x) for x in q)
        lines.append("%d %s" % (positive_definite(q),
                                " ".join(float.hex(x) for x in q)))
    OUT.write_text("# Generated by data/gen_definite.py: verdict (1: positive"
                   " definite, exact), then q[0..5].\n" + "\n".join(lines) + "\n")
    yes = sum(line.startswith("1") for line in lines)
    print(f"{OUT}: {len(lines)} forms, {yes} positive definite",
          file=sys.stderr)


if __name__ == "__main__":
    main()
