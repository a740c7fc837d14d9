#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Writes data/pw85_index_edges.txt: pairs of stored ellipsoids (and of
ellipses) whose exact image vector r = (c_j + n L) - c is not a double and
whose exact mu^2 lies next to an edge of the tangency band, |mu^2 - 1| <=
4 DBL_EPSILON (pw85.h), on either side of it. The indexes decide such pairs
on r carried as a double-double (pw85_index.h, "Images"): these rows check
that path where the decision is closest (tests/test-index-edges.c).

For each base pair (forms as in gen_tangency_edges.py) and each target
mu^2 = 1 + k eps, the image vector r* reaching it is computed at 120 digits,
then the centres are placed so that the exact r misses r* by about 2^-25
ulp of r* only: the query's centre c = n L - r* (1 + delta), |delta| in
[2^-25, 2^-24], n = 0 in an open domain and (1, ..., 1) in a periodic box,
rounded to doubles, and the stored centre c_j = r* + c - n L rounded to a
double (a small number, whose bits reach far below ulp(r*)). The rows keep
the exact r = c_j + n L - c (rationals), whose mu^2 - 1 is certified by the
routes of the committed data (gen_ref_data.contact() in 3D,
gen_2d_data.contact_exact() in 2D), never by pw85, and checked against an
independent 80-digit Newton iteration. Windows as gen_tangency_edges.py,
targets inside them and within 2^-20 eps of the edges.

One row per line: dimension, window, box (dim sides, or 0 ... for an open
domain), c (dim), c_j (dim), q of c, q_j (dim (dim + 1)/2 each), the
correctly rounded mu^2, mu^2 - 1 rounded once; C99 hexadecimal floats.

    /usr/bin/python3 data/gen_index_edges.py   # from the top of the tree
"""
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
import gen_tangency_edges as edges  # noqa: E402
import mpmath  # noqa: E402

OUT = HERE / "pw85_index_edges.txt"
SEED = 2026_11_27
BASES = 6       # base pairs per dimension and domain
E20 = 2.0 ** -20
TARGETS = (4.25, 4 + E20, 4 - E20, 3.75, -3.875, -4 + E20, -4 - E20,
           -4.125)  # mu^2 = 1 + k eps


def dyadic(x):
    """x (a double or a Fraction with a power-of-two denominator) exactly."""
    x = Fraction(x)
    d = x.denominator
    if d & (d - 1):
        raise ValueError("not dyadic")
    return x


def to_ints_exact(values):
    """gen_ref_data.to_ints() for dyadic rationals (values[i] == ints[i] *
    2**-s exactly)."""
    vals = [dyadic(v) for v in values]
    s = max(v.denominator.bit_length() - 1 for v in vals)
    return [v.numerator * ((1 << s) // v.denominator) for v in vals], s


def mpf_of(x):
    x = Fraction(x)
    return mpmath.mpf(x.numerator) / x.denominator


# The exact routes take r as doubles; the rows' r are dyadic rationals,
# which the same integer and rational arithmetic handles exactly.
gen.to_ints = to_ints_exact
g2.fr = dyadic


def exact(dim, r, q1, q2, pair):
    """(mu^2 correctly rounded, mu^2 - 1 as a Fraction) for the exact r."""
    if dim == 3:
        res = gen.contact(pair, list(r))
    else:
        res = g2.contact_exact(list(r), list(q1), list(q2))
    return res.mu2, Fraction(res.mu2m1)


def check_mp(dim, r, q1, q2):
    """mu^2 - 1 by an 80-digit Newton iteration with LU solves (3D:
    gen_ref_data.contact_mp's algorithm; 2D: gen_2d_data.solve_mp), r
    entering exactly."""
    with mpmath.workdps(80):
        rv = [mpf_of(x) for x in r]
        if dim == 3:
            saved = gen._mp_inputs

            def inputs(a, b, _r):
                q1m, q2m, _ = saved(a, b, [0.0] * 3)
                return q1m, q2m, mpmath.matrix(rv)
            gen._mp_inputs = inputs
            try:
                return gen.contact_mp(list(r), list(q1), list(q2), dps=80)[2]
            finally:
                gen._mp_inputs = saved
        mu2 = g2.solve_mp(rv, g2.mpf_list(q1), g2.mpf_list(q2))[0]
        return float(mu2 - 1)


def target_r(dim, u, q1, q2, pair, k):
    """r* = u t with mu^2(r*) = 1 + k eps, at 120 digits (mpf)."""
    with mpmath.workdps(120):
        if dim == 3:
            mu0 = g3.mu2_exact_mpf(gen.contact(pair, list(u)))
        else:
            mu0 = g2.mu2_mp(list(u), q1, q2, 120)
        t = mpmath.sqrt((1 + mpmath.mpf(k) * mpmath.mpf(2) ** -52) / mu0)
        return [mpmath.mpf(x) * t for x in u]


def place(rng, dim, rstar, box):
    """Centres c, c_j (doubles) and the exact r = c_j + n L - c."""
    with mpmath.workdps(120):
        c, cj, r = [], [], []
        for k in range(dim):
            delta = rng.choice((-1, 1)) * rng.uniform(1.0, 2.0) * 2.0 ** -25
            shift = 0 if box is None else box[k]
            ck = float(mpmath.mpf(shift) - rstar[k] * (1 + mpmath.mpf(delta)))
            cjk = float(rstar[k] + mpmath.mpf(ck) - mpmath.mpf(shift))
            c.append(ck)
            cj.append(cjk)
            r.append(Fraction(cjk) + Fraction(shift) - Fraction(ck))
        return c, cj, r


def box_for(rng, dim, rstar, q1, q2):
    """Sides L_k: 4 to 6 times the reach of the pair along axis k, so that
    only the image n = (1, ..., 1) comes near; not a power of two."""
    out = []
    for k in range(dim):
        d = k * (2 * dim - k + 1) // 2  # diagonal entry k
        reach = abs(float(rstar[k])) + np.sqrt(q1[d]) + np.sqrt(q2[d])
        out.append(float(4.0 * reach * rng.uniform(1.0, 1.5)))
    return out


def rows_for(dim, rng, periodic):
    rows = []
    for _ in range(BASES):
        q1, q2, pair, u = edges.base_pair(dim, rng)
        for k in TARGETS:
            rstar = target_r(dim, u, q1, q2, pair, k)
            box = box_for(rng, dim, rstar, q1, q2) if periodic else None
            c, cj, r = place(rng, dim, rstar, box)
            if all(Fraction(float(x)) == x for x in r):
                continue  # r is a double: not the path under test
            mu2, m1 = exact(dim, r, q1, q2, pair)
            name = edges.window_of(m1)
            if name is None:
                continue
            rows.append((dim, name, box, c, cj, q1, q2, mu2, float(m1), r))
    return rows


def main():
    rng = np.random.default_rng(SEED)
    rows = []
    for dim in (3, 2):
        for periodic in (False, True):
            rows += rows_for(dim, rng, periodic)
    for dim, name, box, c, cj, q1, q2, mu2, m1, r in rows:
        check = check_mp(dim, r, q1, q2)
        if check != m1:
            raise AssertionError(f"80-digit check: {check!r} != {m1!r}")
    names = sorted({row[1] for row in rows})
    with open(OUT, "w") as f:
        f.write("# Generated by data/gen_index_edges.py: dim, window, box "
                "(0 = open), c, c_j, q, q_j, mu2, mu2 - 1 (hex; exact r = "
                "c_j + n L - c, n = 1 in a box).\n")
        for dim, name, box, c, cj, q1, q2, mu2, m1, r in rows:
            sides = box if box is not None else [0.0] * dim
            vals = list(sides) + c + cj + list(q1) + list(q2) + [mu2, m1]
            f.write(f"{dim} {name} " + " ".join(float(v).hex() for v in vals)
                    + "\n")
    counts = {n: sum(1 for row in rows if row[1] == n) for n in names}
    print(f"wrote {OUT}: {len(rows)} rows {counts}")


if __name__ == "__main__":
    main()
