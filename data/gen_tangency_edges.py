#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes data/pw85_tangency_edges.txt: pairs of ellipsoids and of ellipses
whose exact mu^2 lies next to an edge of pw85_overlap's tangency band,
|mu^2 - 1| <= 4 DBL_EPSILON (pw85.h), on either side of it. Near the edges
the correctly rounded mu^2 is 1 +- 4 DBL_EPSILON itself while the exact
value may lie outside the band (up to half an ulp above 1 + 4 eps, a quarter
below 1 - 4 eps): a held-out near-tangent pair had mu^2 - 1 = 4.49 eps.

Every mu^2 - 1 is certified exactly (rationals) by the routes of the
committed data: gen_ref_data.contact() in 3D, gen_2d_data.contact_exact() in
2D; never computed by pw85. r12 is scaled at 120 digits onto 1 + k eps for a
few k, then each of its neighbours (every component -1, 0 or +1 ulp) is kept
whose mu^2 - 1 falls in one of the four windows:

    upper-beyond  4 eps < mu^2 - 1 < 4.5 eps    (rounds to 1 + 4 eps)
    upper-inside  3.5 eps < mu^2 - 1 <= 4 eps
    lower-inside  -4 eps <= mu^2 - 1 < -3.75 eps
    lower-beyond  -4.25 eps < mu^2 - 1 < -4 eps (rounds to 1 - 4 eps)

and, on the edge itself, discs and spheres whose exact mu^2 is 1 + 4 eps
(window upper-edge, pw85.h's answer 0): radii rho1 = j 2^25, rho2 = (S - j)
2^25 and r12 = m (2^25 + s i)(u + v i) (in the plane z = 0 in 3D), S = c m for a
Pythagorean triple (u, v, c), u^2 + v^2 = c^2, so that |r12|^2 =
S^2 (2^50 + 1) and mu^2 = |r12|^2 / (rho1 + rho2)^2 = 1 + 2^-50 exactly
(certified as the others). 1 - 4 eps is no such value: 2^50 - 1 = 7 mod 8
is not a sum of three squares times a square.

One pair per line: dimension, window, r12 (dim), q1, q2 (dim (dim + 1)/2
each), mu^2 - 1 rounded once to a double; C99 hexadecimal floats.

    /usr/bin/python3 data/gen_tangency_edges.py   # from the top of the tree
"""
import itertools
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np

sys.dont_write_bytecode = True
HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import gen_2d_data as g2  # noqa: E402
import gen_hard_set as g3  # noqa: E402
import gen_ref_data as gen  # noqa: E402
import mpmath  # noqa: E402

OUT = HERE / "pw85_tangency_edges.txt"
SEED = 2026_11_26
EPS = Fraction(1, 2**52)
BASES = 10      # base pairs per dimension
TARGETS = (4.25, 3.75, -4.125, -3.875)  # mu^2 = 1 + k eps before rounding
WINDOWS = (
    ("upper-beyond", 4 * EPS, Fraction(9, 2) * EPS, False, False),
    ("upper-inside", Fraction(7, 2) * EPS, 4 * EPS, False, True),
    ("lower-inside", -4 * EPS, Fraction(-15, 4) * EPS, True, False),
    ("lower-beyond", Fraction(-17, 4) * EPS, -4 * EPS, False, False),
)  # name, low, high, low end included, high end included


def window_of(m1):
    for name, lo, hi, lo_in, hi_in in WINDOWS:
        if (lo < m1 or (lo_in and m1 == lo)) and \
                (m1 < hi or (hi_in and m1 == hi)):
            return name
    return None


def exact_m1(dim, r, q1, q2, pair=None):
    """mu^2 - 1 as a Fraction: exact to the last bit needed to place it in a
    window (the certified double of mu^2 - 1 is exact here: near 1 the
    doubles are far finer than the windows)."""
    if dim == 3:
        return Fraction(gen.contact(pair, list(r)).mu2m1)
    return Fraction(g2.contact_exact(list(r), list(q1), list(q2)).mu2m1)


def scaled_r(dim, u, q1, q2, pair, k):
    target = 1 + mpmath.mpf(k) * mpmath.mpf(2) ** -52
    if dim == 3:
        return g3.scale_to(pair, u, target)
    with mpmath.workdps(120):
        t = mpmath.sqrt(target / g2.mu2_mp(list(u), q1, q2, 120))
        return [float(mpmath.mpf(float(x)) * t) for x in u]


def base_pair(dim, rng):
    if dim == 3:
        q1, q2 = (g3.random_form(rng, int(rng.integers(0, 3)),
                                 rng.uniform(0.0, 2.0),
                                 rng.uniform(-0.5, 0.5)) for _ in range(2))
        return q1, q2, gen.Pair(q1, q2), [float(x) for x in g3.unit(rng, 3)]
    q1, q2 = (g2.rand_form(rng, rng.uniform(0.0, 2.0),
                           rng.uniform(-0.5, 0.5)) for _ in range(2))
    return q1, q2, None, [float(x) for x in g2.unit(rng)]


def rows_for(dim, rng):
    rows, seen = [], set()
    for _ in range(BASES):
        q1, q2, pair, u = base_pair(dim, rng)
        for k in TARGETS:
            r0 = scaled_r(dim, u, q1, q2, pair, k)
            for steps in itertools.product((-1, 0, 1), repeat=dim):
                r = [gen._ulp_step(x, s) for x, s in zip(r0, steps)]
                key = (tuple(r), tuple(q1), tuple(q2))
                if key in seen:
                    continue
                seen.add(key)
                m1 = exact_m1(dim, r, q1, q2, pair)
                name = window_of(m1)
                if name is not None:
                    rows.append((dim, name, r, q1, q2, float(m1)))
    return rows


# (u, v, c): u^2 + v^2 = c^2
TRIPLES = ((1, 0, 1), (3, 4, 5), (4, 3, 5), (5, 12, 13), (8, 15, 17),
           (20, 21, 29))


def edge_rows(dim):
    """Discs or spheres whose exact mu^2 - 1 is 4 eps (window upper-edge)."""
    rows = []
    t = 2 ** 25
    for u, v, c in TRIPLES:
        for s in (1, -1):
            m = 2 if c == 1 else 1  # S = c m >= 2
            x, y = float(m * (t * u - s * v)), float(m * (t * v + s * u))
            S = c * m
            for j in sorted({1, S // 2, S - 1}):
                rho1, rho2 = float(j * t), float((S - j) * t)
                if dim == 2:
                    r, q1, q2 = [x, y], [rho1 ** 2, 0.0, rho1 ** 2], \
                        [rho2 ** 2, 0.0, rho2 ** 2]
                else:
                    r = [x, y, 0.0]
                    q1 = [rho1 ** 2, 0.0, 0.0, rho1 ** 2, 0.0, rho1 ** 2]
                    q2 = [rho2 ** 2, 0.0, 0.0, rho2 ** 2, 0.0, rho2 ** 2]
                pair = gen.Pair(q1, q2) if dim == 3 else None
                m1 = exact_m1(dim, r, q1, q2, pair)
                assert m1 == 4 * EPS, (r, q1, q2, m1)
                rows.append((dim, "upper-edge", r, q1, q2, float(m1)))
    return rows


def main():
    rng = np.random.default_rng(SEED)
    rows = rows_for(3, rng) + rows_for(2, rng) + edge_rows(3) + edge_rows(2)
    # An independent check of every mu^2 - 1: an 80-digit Newton iteration
    # (gen_ref_data.contact_mp: Newton on g with LU solves; gen_2d_data.
    # mu2_mp), a different algorithm from the certified exact routes.
    for dim, name, r, q1, q2, m1 in rows:
        if dim == 3:
            check = gen.contact_mp(list(r), list(q1), list(q2), dps=80)[2]
        else:
            with mpmath.workdps(80):
                check = float(g2.mu2_mp(list(r), list(q1), list(q2), 80) - 1)
        if check != m1:
            raise AssertionError("%dD %s: mu^2 - 1 = %r, 80 digits: %r"
                                 % (dim, name, m1, check))
    with open(OUT, "w") as out:
        out.write("# Generated by data/gen_tangency_edges.py: dim, window, "
                  "r12, q1, q2, mu2 - 1 (hex; exact, rounded once).\n")
        for dim, name, r, q1, q2, m1 in rows:
            out.write(" ".join([str(dim), name] +
                               [x.hex() for x in list(r) + list(q1) +
                                list(q2) + [m1]]) + "\n")
    counts = {}
    for dim, name, *_ in rows:
        counts[(dim, name)] = counts.get((dim, name), 0) + 1
    for key in sorted(counts):
        print("%dD %-13s %d" % (key[0], key[1], counts[key]))
    print("wrote %s (%d pairs)" % (OUT, len(rows)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
