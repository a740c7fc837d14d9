#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate data/pw85_2d_index_images.txt: periodic pairs of ellipses whose
image vector r = (c_j + n*L) - c_i is not a double (issue 29, the index of
pw85_2d_index.h).

Each record is a periodic rectangle L, a stored ellipse (c_j, q_j), a
candidate (c_i, q_i), the image shift n through which they meet, and the
reference: mu^2 of the exact configuration, correctly rounded to a double.
The candidate's centre lies near the origin, with bits far below ulp(L);
in half the records the stored one lies up to 2^28 L away (the index
allows 2^29 L), through an image shift up to 2^26, with mu^2 anywhere
from 0.2 to 4; in the others within 8 L, placed near contact (mu^2 =
1 + delta, delta = +-1e-3, +-1e-8, +-1e-12).

r is formed exactly, as a dyadic rational (every double is one), never in
floating point.  mu^2 comes from route A of gen_2d_data.py (imported, not
copied: the exact numerator of f', a certified root enclosure, mu^2
correctly rounded), fed the exact rationals of r instead of doubles.  Every
record is cross-checked by an independent mpmath route at 60 digits
(golden-section search of f on [0, 1] with the closed-form 2x2 solve): the
reference must lie within half an ulp of it.  Nothing of libpw85 is used.

Layout: one record per line, hexadecimal doubles (float.hex) and integers,
blank-separated:
    L0 L1  ci0 ci1  qi0 qi1 qi2  cj0 cj1  qj0 qj1 qj2  n0 n1  mu2
Lines starting with '#' are comments.

Usage (from the repository root):
    /usr/bin/python3 data/gen_2d_index_images.py [--out FILE] [--count N]
"""

import argparse
import math
import os
import random
import sys
from fractions import Fraction

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gen_2d_data as g2  # noqa: E402

import mpmath  # noqa: E402

SEED = 2929
DELTAS = [1e-3, -1e-3, 1e-8, -1e-8, 1e-12, -1e-12]


def exact(x):
    """A double, or an exact rational already, as a Fraction."""
    return x if isinstance(x, Fraction) else Fraction(float(x))


# Route A takes its inputs through gen_2d_data.fr(), which rounds to a
# double: here r is an exact rational, kept as it is.
g2.fr = exact


def form(rng, big):
    """q = (Q00, Q01, Q11) of semi-axes in [0.15, big] and a random angle,
    rounded to doubles (the ellipse is the stored q, exactly)."""
    a = [rng.uniform(0.15, big), rng.uniform(0.15, big)]
    t = rng.uniform(-math.pi, math.pi)
    c, s = math.cos(t), math.sin(t)
    return [a[0] ** 2 * c * c + a[1] ** 2 * s * s,
            (a[0] ** 2 - a[1] ** 2) * c * s,
            a[0] ** 2 * s * s + a[1] ** 2 * c * c]


def to_mp(x):
    x = exact(x)
    return mpmath.mpf(x.numerator) / x.denominator


def mu2_check(r, qi, qj):
    """mu^2 by golden-section search of f on [0, 1] at 60 digits (f is
    concave: seed ch. 3), independent of route A."""
    with mpmath.workdps(60):
        rr = [to_mp(x) for x in r]
        q1 = [to_mp(x) for x in qi]
        q2 = [to_mp(x) for x in qj]

        def f(lam):
            q = [(1 - lam) * u + lam * v for u, v in zip(q1, q2)]
            det = q[0] * q[2] - q[1] * q[1]
            s0 = (q[2] * rr[0] - q[1] * rr[1]) / det
            s1 = (q[0] * rr[1] - q[1] * rr[0]) / det
            return lam * (1 - lam) * (rr[0] * s0 + rr[1] * s1)

        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        g = (mpmath.sqrt(5) - 1) / 2
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        fa, fb = f(a), f(b)
        for _ in range(300):
            if fa < fb:
                lo, a, fa = a, b, fb
                b = lo + g * (hi - lo)
                fb = f(b)
            else:
                hi, b, fb = b, a, fa
                a = hi - g * (hi - lo)
                fa = f(a)
        return max(fa, fb)


def record(rng, near):
    """One record, or None when r happens to be a double."""
    L = [rng.uniform(2.5, 9.0), rng.uniform(2.5, 9.0)]
    qi, qj = form(rng, 1.0), form(rng, 1.0)
    # c_i near the origin, its bits far below ulp(L) (r then needs more
    # than 53 bits); c_j far away through a large n (generic records).
    ci = [rng.uniform(-1.0, 1.0) * 2.0 ** -rng.randint(0, 12) for k in range(2)]
    t = rng.uniform(-math.pi, math.pi)
    u = [math.cos(t), math.sin(t)]
    with mpmath.workdps(40):
        m_u = g2.mu2_mp(u, qi, qj)  # mu^2 of r = u (degree 2 in r)
        target = 1 + rng.choice(DELTAS) if near else rng.uniform(0.2, 4.0)
        s = float(mpmath.sqrt(target / m_u))
    r_aim = [s * u[0], s * u[1]]
    n = [rng.randint(-2 ** 26, 2 ** 26) if not near else rng.randint(-8, 8)
         for _ in range(2)]
    # c_j = c_i + r_aim - n L, rounded; the exact r follows from it.
    cj = [float(exact(ci[k]) + exact(r_aim[k]) - n[k] * exact(L[k]))
          for k in range(2)]
    if any(abs(cj[k]) > 2 ** 29 * L[k] for k in range(2)):
        return None
    r = [exact(cj[k]) + n[k] * exact(L[k]) - exact(ci[k]) for k in range(2)]
    if all(Fraction(float(x)) == x for x in r):
        return None  # a double: not what the file is for
    ref = g2.contact_exact(r, qi, qj)
    check = mu2_check(r, qi, qj)
    ulp = math.ulp(ref.mu2)
    if not abs(to_mp(ref.mu2) - check) <= ulp / 2 + abs(check) * 1e-40:
        raise AssertionError("route A %r, check %s" % (ref.mu2, check))
    return L, ci, qi, cj, qj, n, ref.mu2


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "pw85_2d_index_images.txt"))
    parser.add_argument("--count", type=int, default=240)
    args = parser.parse_args()
    rng = random.Random(SEED)
    lines = [
        "# SPDX-License-Identifier: BSD-3-Clause",
        "# Periodic pairs of ellipses whose image vector is not a double, and",
        "# mu^2 of the exact configuration (data/gen_2d_index_images.py).",
        "# L0 L1  ci0 ci1  qi0 qi1 qi2  cj0 cj1  qj0 qj1 qj2  n0 n1  mu2",
    ]
    made = 0
    while made < args.count:
        rec = record(rng, near=made % 2 == 1)
        if rec is None:
            continue
        L, ci, qi, cj, qj, n, mu2 = rec
        fields = [float(x).hex() for x in L + ci + qi + cj + qj]
        fields += [str(k) for k in n] + [float(mu2).hex()]
        lines.append(" ".join(fields))
        made += 1
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote %d records to %s" % (made, args.out))


if __name__ == "__main__":
    main()
