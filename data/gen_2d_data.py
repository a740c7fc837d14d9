#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate the reference data of the contact function of two ellipses
(issue 29): data/pw85_2d_pairs.h5 and data/pw85_2d_geometry.h5.

An ellipse {m : (m - c)^T Q^-1 (m - c) <= 1} is stored as q[3] = (Q00, Q01,
Q11), and a pair as (r12 = c2 - c1, q1, q2).  f(lambda) = lambda (1 - lambda)
r12^T Q(lambda)^-1 r12 with Q(lambda) = (1 - lambda) Q1 + lambda Q2; mu^2 is
the maximum of f over [0, 1] and lambda* the maximiser (seed pw85-1.0
documentation, chapter "Theory", eqs. (10)-(12)).  In two dimensions
Q(lambda)^-1 = adj Q(lambda) / det Q(lambda), so f = lambda (1 - lambda)
a(lambda) / b(lambda) with a = r^T adj(Q(lambda)) r of degree 1 and b =
det Q(lambda) of degree 2: f is a rational function of lambda.

This script is independent of the library and of the 3D generators (no
import): every reference is computed from the doubles exactly as stored.

Route A (the references; exact rational arithmetic):
  c(lambda) = (1 - 2 lambda) a b + lambda (1 - lambda) (a' b - a b'), the
  numerator of f' = c / b^2, has exact rational coefficients (degree <= 4).
  c(0) > 0 > c(1), and one Descartes sign variation of (1 + t)^4 c(1/(1 + t))
  proves c has a single root in (0, 1).  The root is located on the half of
  [0, 1] where it lies (the sign of c(1/2)); on the upper half the pair is
  swapped, f(lambda; q1, q2) = f(1 - lambda; q2, q1), so that 1 - lambda* is
  found with full relative precision.  An mpmath root of c (safeguarded
  Newton, DPS digits) is widened to x (1 -+ 10^-(DPS - 15)) as exact
  fractions, and the exact signs of c there enclose lambda* (or 1 - lambda*).
  f is concave on [0, 1] (seed ch. 3: a minimum of functions affine in
  lambda), so f(x) <= mu^2 <= f(x) + |f'(x)| (hi - lo) with f(x), f'(x)
  exact rationals.  MU2, MU2_MINUS_1, LAMBDA and ONE_MINUS_LAMBDA are stored
  only if both ends of their enclosures round to the same double (Fraction
  -> float is correctly rounded); otherwise DPS is doubled and the root
  certified again.

Route B (the check; mpmath only): safeguarded Newton on f' = (1 - 2 lambda)
  r.s - lambda (1 - lambda) s.u, s = Q(lambda)^-1 r (closed-form 2x2
  inverse), u = (Q2 - Q1) s, at DPS_B and again at 2 DPS_B digits: the rounded
  doubles must equal route A's (otherwise the generator raises).

Geometry (second file; seed eqs. (8), (9a), (12) and the envelope theorem,
d mu^2 = partial f at fixed lambda*): contact point, normal, the derivatives
of mu^2 with respect to r12, the turning angles and the stored entries,
checked against central finite differences of mu^2 (the maximum solved again
at every perturbed input) on every pair; constructors (semi-axes and angle
-> q, and back to the principal axes of the stored q).

The layout and the recipes are in data/README.md, section "Ellipses (2D)".

Usage (from the repository root):
    /usr/bin/python3 data/gen_2d_data.py [--outdir DIR] [--jobs N]
                                         [--count K] [--only pairs|geometry]
"""

import argparse
import hashlib
import math
import multiprocessing
import os
import sys
import time
from fractions import Fraction

import numpy as np

PAIRS_FILE = "pw85_2d_pairs.h5"
GEOM_FILE = "pw85_2d_geometry.h5"
SEED = 2901        # record k of class i: default_rng([seed, i, k, attempt])
CTOR_SEED = 2903   # constructor k of kind i: default_rng([CTOR_SEED, i, k])
DPS = 60           # digits of the route-A root (doubled until certified)
DPS_B = 60         # digits of route B (and again at 2 DPS_B)
COND_DPS = 80      # digits of the eigenvalues of cond1, cond2
COND_MAX = 1e16    # the documented domain: cond(Qi) < 1e16
GEOM_PER_CLASS = 40    # geometry: the first records of each class
GEOM_DPS = 100         # digits of the geometry references
GEOM_DPS_CHECK = 200   # the same doubles again from a cold start
FD_H = "1e-30"         # relative step of the finite differences
FD_RTOL = 1e-15        # required agreement of FD and closed forms
ZERO_TOL = "1e-60"     # below this relative to its scale: an exact 0
CTOR_DPS = 100         # digits of the constructor references
CTOR_DPS_CHECK = 200   # and of their check

# (name, count), in file order.
CLASSES = (
    ("generic", 300),
    ("needles", 300),
    ("near_tangent", 300),
    ("near_tangent_ill", 300),
    ("lambda_near_0", 300),
    ("lambda_near_1", 300),
    ("cond", 300),
    ("extreme_scales", 300),
    ("tiny_r12", 300),
    ("flat_maxima", 300),
)
CLASS_NAMES = tuple(n for n, _ in CLASSES)
CTOR_KINDS = (
    ("random", 150),
    ("special_angles", 48),
    ("large_angles", 30),
    ("circles", 16),
    ("near_circles", 20),
)


# Route A: exact rational arithmetic ---------------------------------------


def fr(x):
    """The double x as an exact fraction."""
    return Fraction(float(x))


def pmul(p, q):
    out = [Fraction(0)] * (len(p) + len(q) - 1)
    for i, a in enumerate(p):
        for j, b in enumerate(q):
            out[i + j] += a * b
    return out


def padd(p, q):
    n = max(len(p), len(q))
    return [(p[i] if i < len(p) else 0) + (q[i] if i < len(q) else 0)
            for i in range(n)]


def pder(p):
    return [i * p[i] for i in range(1, len(p))] or [Fraction(0)]


def peval(p, x):
    v = Fraction(0)
    for c in reversed(p):
        v = v * x + c
    return v


def ab_polys(r, q1, q2):
    """a(l) = r^T adj(Q(l)) r (degree 1) and b(l) = det Q(l) (degree 2),
    coefficients in increasing degree, exact."""
    r0, r1 = fr(r[0]), fr(r[1])
    p = [fr(q1[0]), fr(q2[0]) - fr(q1[0])]
    o = [fr(q1[1]), fr(q2[1]) - fr(q1[1])]
    t = [fr(q1[2]), fr(q2[2]) - fr(q1[2])]
    a = [t[i] * r0 * r0 - 2 * o[i] * r0 * r1 + p[i] * r1 * r1
         for i in range(2)]
    b = padd(pmul(p, t), [-x for x in pmul(o, o)])
    return a, b


def c_poly(a, b):
    """c = (1 - 2l) a b + l (1 - l) (a' b - a b'): f' = c / b^2."""
    ab = pmul(a, b)
    t1 = pmul([Fraction(1), Fraction(-2)], ab)
    d = padd(pmul(pder(a), b), [-x for x in pmul(a, pder(b))])
    t2 = pmul([Fraction(0), Fraction(1), Fraction(-1)], d)
    c = padd(t1, t2)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return c


def descartes_01(c):
    """Sign variations of (1 + t)^n c(1/(1 + t)): the number of roots of c in
    (0, 1), up to an even number."""
    n = len(c) - 1
    acc = [Fraction(0)] * (n + 1)
    for i, ci in enumerate(c):
        # ci (1 + t)^(n - i)
        m = n - i
        for k in range(m + 1):
            acc[k] += ci * math.comb(m, k)
    signs = [x > 0 for x in acc if x != 0]
    return sum(1 for u, v in zip(signs, signs[1:]) if u != v)


def f_exact(a, b, x):
    return x * (1 - x) * peval(a, x) / peval(b, x)


def fprime_exact(a, b, c, x):
    bx = peval(b, x)
    return peval(c, x) / (bx * bx)


def window_exact(a, b, c, x, mu2):
    """sqrt(2 ulp(mu2) / |f''(x)|), f'' = c'(x) / b(x)^2 (exact at a root x
    of c; f'' is the same in lambda and in 1 - lambda): the half-width of
    the interval of lambda on which f is within one ulp of mu^2."""
    bx = peval(b, x)
    f2 = abs(peval(pder(c), x)) / (bx * bx)
    if f2 == 0:
        return math.inf
    return math.sqrt(float(2 * Fraction(math.ulp(mu2)) / f2))


def mpf_to_fraction(x):
    man, exp = x.man_exp  # exact (no conversion at the current precision)
    return Fraction(man) * (Fraction(2) ** exp)


def root_mp(c, dps):
    """The root of c in (0, 1/2) (c(0) > 0 > c(1/2)) at dps digits:
    safeguarded Newton, geometric bisection while the bracket spans decades."""
    import mpmath
    with mpmath.workdps(dps):
        cm = [mpmath.mpf(x.numerator) / x.denominator for x in c]
        dm = [i * cm[i] for i in range(1, len(cm))]

        def ev(p, x):
            v = mpmath.mpf(0)
            for t in reversed(p):
                v = v * x + t
            return v

        lo, hi = mpmath.mpf(0), mpmath.mpf(0.5)
        x = mpmath.mpf(0.25)
        tol = mpmath.mpf(10) ** (-(dps - 6))
        for _ in range(5000):
            v = ev(cm, x)
            if v > 0:
                lo = x
            elif v < 0:
                hi = x
            else:
                return x
            d = ev(dm, x)
            xn = x - v / d if d != 0 else lo - 1
            if not lo < xn < hi:
                if lo == 0:
                    xn = hi / 64
                elif hi > 4 * lo:
                    xn = mpmath.sqrt(lo * hi)
                else:
                    xn = (lo + hi) / 2
            if abs(xn - x) <= tol * xn:
                return xn
            x = xn
        raise AssertionError("root_mp did not converge")


class Contact:
    """The certified references of route A."""
    __slots__ = ("mu2", "mu2m1", "lam", "oml", "swapped", "dps", "root",
                 "window")


def contact_exact(r, q1, q2, dps=DPS):
    """MU2, MU2_MINUS_1, LAMBDA, ONE_MINUS_LAMBDA correctly rounded, with
    the certificate described in the module docstring."""
    if all(x == 0 for x in r):
        raise ValueError("r12 = 0")
    a, b = ab_polys(r, q1, q2)
    c = c_poly(a, b)
    if not (peval(c, Fraction(0)) > 0 > peval(c, Fraction(1))):
        raise AssertionError("c(0) > 0 > c(1) fails")
    if descartes_01(c) != 1:
        raise AssertionError("Descartes: not one root of c in (0, 1)")
    out = Contact()
    half = Fraction(1, 2)
    ch = peval(c, half)
    if ch == 0:  # lambda* = 1/2 exactly
        mu2 = f_exact(a, b, half)
        out.mu2, out.mu2m1 = float(mu2), float(mu2 - 1)
        out.lam = out.oml = 0.5
        out.swapped, out.dps, out.root = False, 0, half
        out.window = window_exact(a, b, c, half, out.mu2)
        return out
    swapped = ch > 0  # the root in (1/2, 1): solve for t = 1 - lambda
    if swapped:
        a, b = ab_polys(r, q2, q1)
        c = c_poly(a, b)
    while dps <= 960:
        x = mpf_to_fraction(root_mp(c, dps))
        eps = Fraction(1, 10 ** (dps - 15))
        lo, hi = x * (1 - eps), x * (1 + eps)
        if not (peval(c, lo) > 0 > peval(c, hi)):
            dps *= 2
            continue
        fx = f_exact(a, b, x)
        up = fx + abs(fprime_exact(a, b, c, x)) * (hi - lo)
        ends = {"mu2": (fx, up), "mu2m1": (fx - 1, up - 1),
                "v": (lo, hi), "1-v": (1 - hi, 1 - lo)}
        rounded = {k: (float(u), float(v)) for k, (u, v) in ends.items()}
        if all(u == v for u, v in rounded.values()):
            out.mu2 = rounded["mu2"][0]
            out.mu2m1 = rounded["mu2m1"][0]
            v, w = rounded["v"][0], rounded["1-v"][0]
            out.lam, out.oml = (w, v) if swapped else (v, w)
            out.swapped, out.dps, out.root = swapped, dps, x
            out.window = window_exact(a, b, c, x, out.mu2)
            return out
        dps *= 2
    raise AssertionError("contact_exact: not certified at 960 digits")


def extra_digits(window, lam, oml):
    """The digits that the root of f' loses to flatness: 2 log10(w) + 16,
    w = window / min(lambda*, 1 - lambda*) (0 when w < 1e-8)."""
    w = window / min(lam, oml)
    return max(0, math.ceil(2 * math.log10(w) + 16))


def positive_definite_exact(q):
    m = [fr(x) for x in q]
    return m[0] > 0 and m[0] * m[2] - m[1] * m[1] > 0


# Route B: mpmath ------------------------------------------------------------


def mpf_list(x):
    import mpmath
    return [mpmath.mpf(float(t)) for t in x]


def solve2(q, v):
    """Q^-1 v = adj(Q) v / det Q for the 2x2 symmetric q[3]."""
    det = q[0] * q[2] - q[1] * q[1]
    return [(q[2] * v[0] - q[1] * v[1]) / det,
            (q[0] * v[1] - q[1] * v[0]) / det]


def mv2(q, v):
    return [q[0] * v[0] + q[1] * v[1], q[1] * v[0] + q[2] * v[1]]


def dot2(u, v):
    return u[0] * v[0] + u[1] * v[1]


def f_derivs(r, qa, qb, x):
    """f', f'' at x of f(x) = x(1 - x) r^T ((1 - x) qa + x qb)^-1 r, and
    s, f.  f' = (1 - x)^2 s^T qa s - x^2 s^T qb s (= (1 - 2x) r.s - x(1 - x)
    s.u with u = (qb - qa) s, as r = Q(x) s; the seed's residual g = -f',
    chapter "Optimization"), which does not cancel where one form dominates
    Q(x); f'' = -2 r.s - 2(1 - 2x) s.u + 2x(1 - x) u.Q(x)^-1 u."""
    y = 1 - x
    q = [y * u + x * v for u, v in zip(qa, qb)]
    s = solve2(q, r)
    u = mv2([v - w for v, w in zip(qb, qa)], s)
    rs, su, uv = dot2(r, s), dot2(s, u), dot2(u, solve2(q, u))
    d1 = y * y * dot2(s, mv2(qa, s)) - x * x * dot2(s, mv2(qb, s))
    d2 = -2 * rs - 2 * (1 - 2 * x) * su + 2 * x * y * uv
    return d1, d2, s, x * y * rs


def solve_mp(r, q1, q2, t0=None):
    """(mu2, lambda, 1 - lambda, f''(lambda*)) at the working precision, the
    inputs mpf.  The root of f' is found on the half of [0, 1] where it lies,
    as a distance t from the nearer end (the pair swapped for the upper half),
    by safeguarded Newton; t0 a warm start (for finite differences)."""
    import mpmath
    d1, _, _, fh = f_derivs(r, q1, q2, mpmath.mpf(0.5))
    if d1 == 0:
        _, d2, _, fh = f_derivs(r, q1, q2, mpmath.mpf(0.5))
        return fh, mpmath.mpf(0.5), mpmath.mpf(0.5), d2
    swapped = d1 > 0
    qa, qb = (q2, q1) if swapped else (q1, q2)
    lo, hi = mpmath.mpf(0), mpmath.mpf(0.5)
    x = mpmath.mpf(0.25) if t0 is None else mpmath.mpf(t0)
    tol = mpmath.mpf(10) ** (-(mpmath.mp.dps - 8))
    for _ in range(5000):
        d1, d2, _, fx = f_derivs(r, qa, qb, x)
        if d1 > 0:
            lo = x
        elif d1 < 0:
            hi = x
        else:
            break
        xn = x - d1 / d2 if d2 < 0 else lo - 1
        if not lo < xn < hi:
            if lo == 0:
                xn = hi / 64
            elif hi > 4 * lo:
                xn = mpmath.sqrt(lo * hi)
            else:
                xn = (lo + hi) / 2
        if abs(xn - x) <= tol * xn:
            x = xn
            break
        x = xn
    else:
        raise AssertionError("solve_mp did not converge")
    _, d2, _, fx = f_derivs(r, qa, qb, x)
    if swapped:
        return fx, 1 - x, x, d2
    return fx, x, 1 - x, d2


def contact_mp(r, q1, q2, dps):
    """Route B, rounded: (mu2, mu2 - 1, lambda, 1 - lambda)."""
    import mpmath
    with mpmath.workdps(dps):
        mu2, lam, oml, _ = solve_mp(mpf_list(r), mpf_list(q1), mpf_list(q2))
        return float(mu2), float(mu2 - 1), float(lam), float(oml)


def f_mp(r, q1, q2, lam, dps):
    """f(lam) by the closed-form 2x2 solve at dps digits, rounded."""
    import mpmath
    with mpmath.workdps(dps):
        x = mpmath.mpf(lam)
        q = [(1 - x) * u + x * v for u, v in zip(mpf_list(q1), mpf_list(q2))]
        rr = mpf_list(r)
        return float(x * (1 - x) * dot2(rr, solve2(q, rr)))


def mu2_mp(r, q1, q2, dps=50):
    import mpmath
    with mpmath.workdps(dps):
        return solve_mp(mpf_list(r), mpf_list(q1), mpf_list(q2))[0]


def cond_mp(q, dps=COND_DPS):
    """cond2 = e_max / e_min of the exact stored q (a float); inf when not
    positive definite."""
    import mpmath
    if not positive_definite_exact(q):
        return math.inf
    with mpmath.workdps(dps):
        a, b, c = mpf_list(q)
        det = a * c - b * b          # exact at dps >= 35 (106-bit products)
        emax = (a + c) / 2 + mpmath.sqrt(((a - c) / 2) ** 2 + b * b)
        return float(emax / (det / emax))


# Inputs ---------------------------------------------------------------------


def unit(rng, n=2):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def turn(u, angle):
    """The unit vector u turned by angle (doubles; a recipe only)."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([c * u[0] - s * u[1], s * u[0] + c * u[1]])


def form_exact(axes, direction):
    """Q = a0^2 v v^T + a1^2 w w^T, v = direction (c, s), w = (-s, c):
    (a0^2 c^2 + a1^2 s^2, (a0^2 - a1^2) c s, a0^2 s^2 + a1^2 c^2), exact from
    the doubles, rounded once (seed eq. (2))."""
    a0, a1 = fr(axes[0]), fr(axes[1])
    c, s = fr(direction[0]), fr(direction[1])
    return [float(a0 * a0 * c * c + a1 * a1 * s * s),
            float((a0 * a0 - a1 * a1) * c * s),
            float(a0 * a0 * s * s + a1 * a1 * c * c)]


def axes_of(rng, log_ar, centre):
    """Semi-axes 10^(centre +- log_ar/2), in random order."""
    e = [centre + log_ar / 2, centre - log_ar / 2]
    if rng.uniform() < 0.5:
        e = e[::-1]
    return [float(10.0 ** x) for x in e]


def rand_form(rng, log_ar, centre, direction=None):
    d = unit(rng) if direction is None else direction
    return form_exact(axes_of(rng, log_ar, centre), d)


def scale_form(q, d):
    """D Q D, d = diag(D) doubles, exact, rounded once."""
    f = [fr(x) for x in q]
    d0, d1 = fr(d[0]), fr(d[1])
    return [float(f[0] * d0 * d0), float(f[1] * d0 * d1),
            float(f[2] * d1 * d1)]


def scaled(u, q1, q2, target):
    """r12 = u sqrt(target / mu0^2) at 60 digits, rounded (mu0^2 for r = u):
    mu^2 of the stored r12 is near, not at, the target."""
    import mpmath
    with mpmath.workdps(60):
        t = mpmath.sqrt(mpmath.mpf(target) / mu2_mp(u, q1, q2, 60))
        return [float(mpmath.mpf(float(x)) * t) for x in u]


def generic_target(rng):
    return 10.0 ** rng.uniform(-2.0, 2.0)


def near_tangent(rng, q1, q2, u):
    """r12 for mu^2 = 1 + delta, delta = +-10^U(-15, -3), then among r12 and
    its 8 neighbours (+-1 ulp per component) the one with mu^2 - 1 nearest
    delta (first in order on ties)."""
    import mpmath
    delta = (1 if rng.uniform() < 0.5 else -1) * 10.0 ** rng.uniform(-15, -3)
    with mpmath.workdps(60):
        r = scaled(u, q1, q2, 1 + mpmath.mpf(delta))
    best = None
    for s0 in (-1, 0, 1):
        for s1 in (-1, 0, 1):
            rr = [math.nextafter(x, math.copysign(math.inf, s)) if s else x
                  for x, s in zip(r, (s0, s1))]
            with mpmath.workdps(50):
                d = abs(mu2_mp(rr, q1, q2, 50) - 1 - mpmath.mpf(delta))
            if best is None or d < best[0]:
                best = (d, rr)
    return best[1], delta


def ill_form(rng):
    """A form of cond 10^U(12, 15) before rounding: by rotation (aspect ratio
    10^U(6, 7.5), random direction) or by scaling (D Q D, Q of aspect ratio
    10^U(0, 1), D = diag(10^o, 10^(o + S)) in random order, S = U(6, 7.5),
    o = U(-3, 3): badly scaled stored entries)."""
    if rng.uniform() < 0.5:
        return rand_form(rng, rng.uniform(6.0, 7.5), rng.uniform(-1, 1))
    q = rand_form(rng, rng.uniform(0.0, 1.0), 0.0)
    o, s = rng.uniform(-3, 3), rng.uniform(6.0, 7.5) / 2
    d = [10.0 ** o, 10.0 ** (o + s)]
    if rng.uniform() < 0.5:
        d = d[::-1]
    return scale_form(q, d)


def needle_pair(rng):
    """One needle of aspect ratio 10^U(3, 6) and an ellipse of aspect ratio
    10^U(0, 6); r12 random (mode 0), end-on at 10^U(-12, -2) rad from the
    needle's axis (mode 1), or two needles 10^U(-10, -2) rad from parallel,
    side by side within +-0.1 rad of the perpendicular (mode 2)."""
    mode = int(rng.integers(0, 3))
    v = unit(rng)
    L = rng.uniform(3.0, 6.0)
    a = [10.0 ** (rng.uniform(-1, 1) + L / 2)]
    a.append(a[0] / 10.0 ** L)
    q1 = form_exact(a, v)
    if mode == 2:
        L2 = rng.uniform(3.0, 6.0)
        b = [10.0 ** (rng.uniform(-1, 1) + L2 / 2)]
        b.append(b[0] / 10.0 ** L2)
        sign = 1 if rng.uniform() < 0.5 else -1
        q2 = form_exact(b, turn(v, sign * 10.0 ** rng.uniform(-10, -2)))
        u = turn(v, math.pi / 2 + rng.uniform(-0.1, 0.1))
    else:
        q2 = rand_form(rng, rng.uniform(0.0, 6.0), rng.uniform(-1, 1))
        if mode == 1:
            sign = 1 if rng.uniform() < 0.5 else -1
            u = turn(v, sign * 10.0 ** rng.uniform(-12, -2))
        else:
            u = unit(rng)
    if rng.uniform() < 0.5:
        q1, q2 = q2, q1
    return q1, q2, u


def end_pair(rng, small_first):
    """A small and a large ellipse (lambda* near the small one's end): sizes
    10^U(3, 22) apart with aspect ratios 10^U(0, 2) (mode 0), or a needle of
    aspect ratio 10^U(3, 6) seen side-on (r12 within 0.1 rad of the
    perpendicular to its axis) beside an ellipse 10^U(0, 8) larger than its
    short axis (mode 1)."""
    if rng.uniform() < 0.5:
        c = rng.uniform(-2, 2)
        large = rand_form(rng, rng.uniform(0, 2), c)
        small = rand_form(rng, rng.uniform(0, 2), c - rng.uniform(3, 22))
        u = unit(rng)
    else:
        v = unit(rng)
        L = rng.uniform(3.0, 6.0)
        a = [10.0 ** (rng.uniform(-1, 1) + L / 2)]
        a.append(a[0] / 10.0 ** L)
        small = form_exact(a, v)
        large = rand_form(rng, rng.uniform(0, 2),
                          math.log10(a[1]) + rng.uniform(0, 8))
        u = turn(v, math.pi / 2 + rng.uniform(-0.1, 0.1))
    q1, q2 = (small, large) if small_first else (large, small)
    return q1, q2, u


def make_candidate(cls, rng):
    """(r12, q1, q2, spec) of a candidate of class cls; spec holds the
    acceptance bounds."""
    name = CLASS_NAMES[cls]
    spec = {}
    if name == "generic":
        q1 = rand_form(rng, rng.uniform(0, 1), rng.uniform(-1, 1))
        q2 = rand_form(rng, rng.uniform(0, 1), rng.uniform(-1, 1))
        return scaled(unit(rng), q1, q2, generic_target(rng)), q1, q2, spec
    if name == "needles":
        q1, q2, u = needle_pair(rng)
        return scaled(u, q1, q2, generic_target(rng)), q1, q2, spec
    if name == "near_tangent":
        q1 = rand_form(rng, rng.uniform(0, 3), rng.uniform(-1, 1))
        q2 = rand_form(rng, rng.uniform(0, 3), rng.uniform(-1, 1))
        r, delta = near_tangent(rng, q1, q2, unit(rng))
        spec["delta"] = delta
        return r, q1, q2, spec
    if name == "near_tangent_ill":
        q1 = ill_form(rng)
        q2 = (ill_form(rng) if rng.uniform() < 0.5 else
              rand_form(rng, rng.uniform(0, 2), rng.uniform(-1, 1)))
        if rng.uniform() < 0.5:
            q1, q2 = q2, q1
        if not (positive_definite_exact(q1) and positive_definite_exact(q2)):
            return None
        r, delta = near_tangent(rng, q1, q2, unit(rng))
        spec["delta"] = delta
        spec["cond_max"] = (1e12, COND_MAX)
        return r, q1, q2, spec
    if name in ("lambda_near_0", "lambda_near_1"):
        q1, q2, u = end_pair(rng, name == "lambda_near_0")
        spec["end"] = (0 if name == "lambda_near_0" else 1, 1e-22, 1e-3)
        return scaled(u, q1, q2, generic_target(rng)), q1, q2, spec
    if name == "cond":
        q1 = ill_form(rng)
        q2 = (ill_form(rng) if rng.uniform() < 0.5 else
              rand_form(rng, rng.uniform(0, 2), rng.uniform(-1, 1)))
        if rng.uniform() < 0.5:
            q1, q2 = q2, q1
        if not (positive_definite_exact(q1) and positive_definite_exact(q2)):
            return None
        spec["cond_max"] = (1e12, COND_MAX)
        return scaled(unit(rng), q1, q2, generic_target(rng)), q1, q2, spec
    if name == "extreme_scales":
        mode = int(rng.integers(0, 3))
        q1 = rand_form(rng, rng.uniform(0, 2), rng.uniform(-1, 1))
        q2 = rand_form(rng, rng.uniform(0, 2), rng.uniform(-1, 1))
        u = unit(rng)
        if mode == 2:
            # sizes 10^U(20, 100) apart (one form scaled by its square)
            k = 10.0 ** rng.uniform(20, 100)
            if rng.uniform() < 0.5:
                k = 1 / k
            q2 = scale_form(q2, [k, k])
            return scaled(u, q1, q2, generic_target(rng)), q1, q2, spec
        # the whole configuration scaled by a length 2^+-500 (mode 0) or
        # 10^+-150 (mode 1): D Q D and D r, exact, rounded once
        sign = 1 if rng.uniform() < 0.5 else -1
        k = 2.0 ** (500 * sign) if mode == 0 else 10.0 ** (150 * sign)
        r = scaled(u, q1, q2, generic_target(rng))
        q1, q2 = scale_form(q1, [k, k]), scale_form(q2, [k, k])
        r = [float(fr(x) * fr(k)) for x in r]
        return r, q1, q2, spec
    if name == "tiny_r12":
        q1 = rand_form(rng, rng.uniform(0, 3), rng.uniform(-2, 2))
        q2 = rand_form(rng, rng.uniform(0, 3), rng.uniform(-2, 2))
        target = 10.0 ** (-2 * rng.uniform(8, 150))
        return scaled(unit(rng), q1, q2, target), q1, q2, spec
    if name == "flat_maxima":
        # two needles of semi-axes (A, A / 10^L), L = U(2, 7.5), crossed at
        # right angles, r12 at 45 degrees from both: then det Q(lambda) =
        # A^2 lambda (1 - lambda) + O(eta), eta = 10^-2L, and a(lambda) is
        # constant, so f = |r12|^2 / (A^2 + O(eta / lambda (1 - lambda))):
        # f''(1/2) ~ -32 eta mu^2, f is flat to a few ulps over a lambda
        # window ~ 1e-8 10^L.  The second needle's axes, the crossing angle
        # and the direction of r12 are moved by eta 10^U(-1, 1) (random
        # signs), which moves lambda* about the middle without tilting f
        # into a slope that would push lambda* to an end.
        v = unit(rng)
        L = rng.uniform(2, 7.5)
        eta = 10.0 ** (-2 * L)

        def jit():
            return (1 if rng.uniform() < 0.5 else -1) * eta * \
                10.0 ** rng.uniform(-1, 1)
        big = 10.0 ** rng.uniform(-1, 1)
        a = [big, big / 10.0 ** L]
        b = [big * (1 + jit()), a[1] * (1 + 10.0 ** L * jit())]
        q1 = form_exact(a, v)
        q2 = form_exact(b, turn(v, math.pi / 2 + jit()))
        k = int(rng.integers(0, 4))
        u = turn(v, math.pi / 4 + k * math.pi / 2 + jit())
        if rng.uniform() < 0.5:
            q1, q2 = q2, q1
        spec["window"] = 1e-7
        return scaled(u, q1, q2, generic_target(rng)), q1, q2, spec
    raise ValueError(name)


def finite_normal(vals):
    """No input overflows, and none is subnormal (a nonzero below 2^-1022)."""
    return all(math.isfinite(x) and (x == 0 or abs(x) >= 2.0 ** -1022)
               for x in vals)


def pair_record(task):
    """Record k of class cls: inputs, certified references, checks.  Returns
    (record, stats)."""
    seed, cls, k = task
    t0 = time.time()
    rejected = {}
    for attempt in range(1000):
        rng = np.random.default_rng([seed, cls, k, attempt])
        cand = make_candidate(cls, rng)
        why = None
        if cand is None:
            why = "not positive definite"
        else:
            r, q1, q2, spec = cand
            r, q1, q2 = ([float(x) for x in v] for v in (r, q1, q2))
            if not finite_normal(r + q1 + q2) or all(x == 0 for x in r):
                why = "subnormal, infinite or zero input"
            elif not (positive_definite_exact(q1)
                      and positive_definite_exact(q2)):
                why = "not positive definite"
            else:
                c1, c2 = cond_mp(q1), cond_mp(q2)
                if not max(c1, c2) < COND_MAX:
                    why = "cond >= 1e16"
                elif "cond_max" in spec and not (
                        spec["cond_max"][0] <= max(c1, c2)
                        < spec["cond_max"][1]):
                    why = "cond outside the class range"
        if why is None:
            res = contact_exact(r, q1, q2)
            if "delta" in spec:
                d = spec["delta"]
                if not (res.mu2m1 * d > 0
                        and 0.5e-15 <= abs(res.mu2m1) <= 2e-3):
                    why = "mu2 - 1 off the target side or range"
            if "end" in spec:
                end, lo, hi = spec["end"]
                dist = res.lam if end == 0 else res.oml
                if not lo <= dist <= hi:
                    why = "lambda* not near the end"
            if "window" in spec and not res.window >= spec["window"]:
                why = "maximum not flat"
        if why is None:
            break
        rejected[why] = rejected.get(why, 0) + 1
    else:
        raise AssertionError("no candidate for class %d record %d" % (cls, k))
    ref = (res.mu2, res.mu2m1, res.lam, res.oml)
    # route B at dps_b and 2 dps_b digits: the same doubles.  The root of f'
    # is ill-conditioned where f is flat on the scale of min(lambda*,
    # 1 - lambda*) (w = LAMBDA_WINDOW / min(...) > 1e-8, up to 1e34 for
    # lambda* ~ 1e-90): f' at relative error 10^-dps moves lambda* by about
    # 10^-dps w^2 / 2^-53 relative, so dps_b = DPS_B + 2 log10(w) + 16.
    dps_b = DPS_B + extra_digits(res.window, res.lam, res.oml)
    for dps in (dps_b, 2 * dps_b):
        got = contact_mp(r, q1, q2, dps)
        if got != ref:
            raise AssertionError(
                "route B at %d digits differs (class %s, record %d): %r %r"
                % (dps, CLASS_NAMES[cls], k, got, ref))
    # f at LAMBDA, 1/2 and two random lambdas, exact, rounded once
    frng = np.random.default_rng([seed, cls, k])
    f_lams = [res.lam, 0.5] + [float(x) for x in frng.uniform(0, 1, 2)]
    a, b = ab_polys(r, q1, q2)
    f_vals = [float(f_exact(a, b, fr(x))) for x in f_lams]
    if not f_vals[0] <= res.mu2:
        raise AssertionError("f(LAMBDA) > MU2")
    if f_vals != [f_mp(r, q1, q2, x, dps_b) for x in f_lams]:
        raise AssertionError("F: mpmath differs (class %s, record %d)"
                             % (CLASS_NAMES[cls], k))
    rec = dict(R12=r, Q1=q1, Q2=q2, MU2=res.mu2, LAMBDA=res.lam,
               F_LAMBDA=f_lams, F=f_vals,
               ONE_MINUS_LAMBDA=res.oml, MU2_MINUS_1=res.mu2m1,
               CLASS=cls, COND1=c1, COND2=c2,
               LAMBDA_WINDOW=res.window, CANDIDATE=attempt)
    stats = dict(rejected=rejected, dps=res.dps, dps_b=dps_b,
                 seconds=time.time() - t0)
    return rec, stats


# Geometry -------------------------------------------------------------------


def geometry(r12, q1, q2, dps):
    """Every geometry reference of a pair at dps digits (mpmath numbers)."""
    import mpmath
    with mpmath.workdps(dps):
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        mu2, lam, oml, d2 = solve_mp(r, Q1, Q2)
        q = [oml * u + lam * v for u, v in zip(Q1, Q2)]
        s = solve2(q, r)
        q1s, q2s = mv2(Q1, s), mv2(Q2, s)
        c1 = lam * oml * oml   # -d mu2 / d Q1 = c1 s s^T
        c2 = lam * lam * oml   # -d mu2 / d Q2 = c2 s s^T
        ns = mpmath.sqrt(dot2(s, s))
        point = [oml * t for t in q1s]                    # eq. (9a)
        cross = lambda u, v: u[0] * v[1] - u[1] * v[0]    # noqa: E731
        g = {
            "MU2": mu2, "MU2_MINUS_1": mu2 - 1, "LAMBDA": lam,
            "ONE_MINUS_LAMBDA": oml, "S": s, "POINT": point,
            "NORMAL": [t / ns for t in s],                # eq. (8)
            "D_R12": [2 * lam * oml * t for t in s],
            "D_THETA1": 2 * c1 * cross(s, q1s),
            "D_THETA2": 2 * c2 * cross(s, q2s),
            "D_Q1": [-c1 * s[0] * s[0], -2 * c1 * s[0] * s[1],
                     -c1 * s[1] * s[1]],
            "D_Q2": [-c2 * s[0] * s[0], -2 * c2 * s[0] * s[1],
                     -c2 * s[1] * s[1]],
            "q_lambda": q, "f2": d2,
        }
        # exact zeros (s x Q1 s for a circle) come out as rounding noise
        tol = mpmath.mpf(ZERO_TOL)
        dr = mpmath.sqrt(dot2(g["D_R12"], g["D_R12"]))
        x2 = [u - v for u, v in zip(point, r)]
        lever = {"D_THETA1": dr * mpmath.sqrt(dot2(point, point)),
                 "D_THETA2": dr * mpmath.sqrt(dot2(x2, x2))}
        for k in ("D_THETA1", "D_THETA2"):
            if abs(g[k]) <= tol * lever[k]:
                g[k] = mpmath.mpf(0)
        for k in ("S", "POINT", "NORMAL", "D_R12", "D_Q1", "D_Q2"):
            v = g[k]
            sc = mpmath.sqrt(sum(t * t for t in v))
            g[k] = [t if abs(t) > tol * sc else mpmath.mpf(0) for t in v]
        return g


GEOM_REFS = ("MU2", "MU2_MINUS_1", "LAMBDA", "ONE_MINUS_LAMBDA", "S", "POINT",
             "NORMAL", "D_R12", "D_THETA1", "D_THETA2", "D_Q1", "D_Q2")


def rounded(g):
    out = {}
    for k in GEOM_REFS:
        v = g[k]
        out[k] = ([float(t) for t in v] if isinstance(v, list) else float(v))
    return out


def rot_form(q, th):
    """R(th) Q R(th)^T, R(th) = [[cos, -sin], [sin, cos]] (not rounded)."""
    import mpmath
    c, s = mpmath.cos(th), mpmath.sin(th)
    a, b, d = q
    return [c * c * a - 2 * c * s * b + s * s * d,
            c * s * (a - d) + (c * c - s * s) * b,
            s * s * a + 2 * c * s * b + c * c * d]


def identities(r12, q1, q2, g, dps):
    """The largest relative residual of the identities of the seed at dps:
    x on both ellipses scaled by mu (eq. (13)), the normal along
    Q1^-1 (x - c1) and -Q2^-1 (x - c2) (eq. (8)), n.r12 > 0, and the lever
    arms d_theta1 = d_r12 x (x - c1), d_theta2 = (x - c2) x d_r12."""
    import mpmath
    with mpmath.workdps(dps):
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        x1 = g["POINT"]
        x2 = [a - b for a, b in zip(x1, r)]
        mu2, n = g["MU2"], g["NORMAL"]
        e = [abs(dot2(x1, solve2(Q1, x1)) / mu2 - 1),
             abs(dot2(x2, solve2(Q2, x2)) / mu2 - 1)]
        for v in (solve2(Q1, x1), [-t for t in solve2(Q2, x2)]):
            nv = mpmath.sqrt(dot2(v, v))
            e.append(mpmath.sqrt(sum((a / nv - b) ** 2
                                     for a, b in zip(v, n))))
        e.append(abs(dot2(n, n) - 1))
        gr = g["D_R12"]
        ngr = mpmath.sqrt(dot2(gr, gr))
        cr = lambda u, v: u[0] * v[1] - u[1] * v[0]  # noqa: E731
        scale = ngr * (mpmath.sqrt(dot2(x1, x1)) + mpmath.sqrt(dot2(x2, x2)))
        e.append(abs(g["D_THETA1"] - cr(gr, x1)) / scale)
        e.append(abs(g["D_THETA2"] - cr(x2, gr)) / scale)
        if not dot2(n, r) > 0:
            raise AssertionError("n . r12 <= 0")
        worst = max(e)
        if not worst < mpmath.mpf("1e-50"):
            raise AssertionError("identity residual %s" % mpmath.nstr(worst))
        return float(worst)


def fd_check(r12, q1, q2, g, extra=0):
    """Central differences of mu^2 (the maximum solved again at every
    perturbed input) against the closed forms: each component of r12 (step
    1e-30 |r12|), each stored entry of q1 and q2 (step 1e-30 max |q|) and the
    turning angles (Q -> R(th) Q R(th)^T, step 1e-30 rad).  The working
    precision grows with 1/min(lambda*, 1 - lambda*), as the derivatives with
    respect to the far form are that much smaller than mu^2.  Returns the
    relative error of each vector (relative to its natural scale where the
    closed form is 0)."""
    import mpmath
    end = min(g["LAMBDA"], g["ONE_MINUS_LAMBDA"])
    dps = 110 + extra + int(max(0, -float(mpmath.log10(end))))
    errors = {}
    with mpmath.workdps(dps):
        h = mpmath.mpf(FD_H)
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        t0 = end

        def mu2(rr, a, b):
            return solve_mp(rr, a, b, t0)[0]

        def diff(plus, minus, step):
            return (mu2(*plus) - mu2(*minus)) / (2 * step)

        fd = {"D_R12": [], "D_Q1": [], "D_Q2": [], "D_THETA1": [],
              "D_THETA2": []}
        hr = h * mpmath.sqrt(dot2(r, r))
        for i in range(2):
            rp, rm = list(r), list(r)
            rp[i] += hr
            rm[i] -= hr
            fd["D_R12"].append(diff((rp, Q1, Q2), (rm, Q1, Q2), hr))
        for name, which in (("D_Q1", 0), ("D_Q2", 1)):
            qq = (Q1, Q2)[which]
            hq = h * max(abs(t) for t in qq)
            for k in range(3):
                qp, qm = list(qq), list(qq)
                qp[k] += hq
                qm[k] -= hq
                if which == 0:
                    fd[name].append(diff((r, qp, Q2), (r, qm, Q2), hq))
                else:
                    fd[name].append(diff((r, Q1, qp), (r, Q1, qm), hq))
        for name, which in (("D_THETA1", 0), ("D_THETA2", 1)):
            qq = (Q1, Q2)[which]
            qp, qm = rot_form(qq, h), rot_form(qq, -h)
            if which == 0:
                fd[name].append(diff((r, qp, Q2), (r, qm, Q2), h))
            else:
                fd[name].append(diff((r, Q1, qp), (r, Q1, qm), h))
        lam, oml = mpmath.mpf(g["LAMBDA"]), mpmath.mpf(g["ONE_MINUS_LAMBDA"])
        s2 = dot2(g["S"], g["S"])
        gr = g["D_R12"]
        x1 = g["POINT"]
        x2 = [a - b for a, b in zip(x1, r)]
        ngr = mpmath.sqrt(dot2(gr, gr))
        natural = {"D_R12": ngr, "D_THETA1": ngr * mpmath.sqrt(dot2(x1, x1)),
                   "D_THETA2": ngr * mpmath.sqrt(dot2(x2, x2)),
                   "D_Q1": lam * oml * oml * s2, "D_Q2": lam * lam * oml * s2}
        for k, nat in natural.items():
            v = g[k] if isinstance(g[k], list) else [g[k]]
            closed = [mpmath.mpf(t) for t in v]
            den = mpmath.sqrt(sum(t * t for t in closed))
            if den <= mpmath.mpf("1e-30") * nat:
                den = nat
            num = mpmath.sqrt(sum((a - b) ** 2 for a, b in zip(fd[k], closed)))
            errors[k] = float(num / den)
    return errors


def geometry_record(task):
    """The geometry of pair record rec (an output of pair_record)."""
    index, rec = task
    t0 = time.time()
    r, q1, q2 = rec["R12"], rec["Q1"], rec["Q2"]
    extra = extra_digits(rec["LAMBDA_WINDOW"], rec["LAMBDA"],
                         rec["ONE_MINUS_LAMBDA"])
    dps = GEOM_DPS + extra
    g = geometry(r, q1, q2, dps)
    ref = rounded(g)
    ref2 = rounded(geometry(r, q1, q2, GEOM_DPS_CHECK + 2 * extra))
    if ref != ref2:
        raise AssertionError("geometry differs at %d digits (pair %d)"
                             % (GEOM_DPS_CHECK + 2 * extra, index))
    for k in ("MU2", "MU2_MINUS_1", "LAMBDA", "ONE_MINUS_LAMBDA"):
        if ref[k] != rec[k]:
            raise AssertionError("geometry %s differs from the pairs file "
                                 "(pair %d)" % (k, index))
    id_err = identities(r, q1, q2, g, dps)
    fd_err = fd_check(r, q1, q2, g, extra)
    if not max(fd_err.values()) <= FD_RTOL:
        raise AssertionError("finite differences (pair %d): %r"
                             % (index, fd_err))
    out = dict(PAIR_INDEX=index, CLASS=rec["CLASS"], R12=r, Q1=q1, Q2=q2,
               COND_Q=cond_of_mp(g["q_lambda"]))
    out.update(ref)
    return out, dict(id_err=id_err, fd_err=fd_err, dps=dps,
                     seconds=time.time() - t0)


def cond_of_mp(q):
    """cond2 of a form given as mpf numbers (not rounded first)."""
    import mpmath
    with mpmath.workdps(COND_DPS):
        a, b, c = q
        det = a * c - b * b
        emax = (a + c) / 2 + mpmath.sqrt(((a - c) / 2) ** 2 + b * b)
        return float(emax / (det / emax))


# Constructors ---------------------------------------------------------------


def ctor_candidate(kind, k, rng):
    """(a[2], theta) of constructor case k of the kind."""
    name = CTOR_KINDS[kind][0]
    a = axes_of(rng, rng.uniform(0, 8), rng.uniform(-3, 3))
    if name == "random":
        th = rng.uniform(-math.pi, math.pi)
    elif name == "special_angles":
        # 0, the doubles nearest j pi / 4 (j = -8 .. 8, but 0) and pi / 6 ...
        specials = [0.0] + [j * math.pi / 4 for j in range(-8, 9) if j] + \
            [j * math.pi / 6 for j in (-5, -4, -2, -1, 1, 2, 4, 5)]
        th = specials[k % len(specials)]
    elif name == "large_angles":
        sign = 1 if rng.uniform() < 0.5 else -1
        th = sign * 10.0 ** rng.uniform(1, 16)
    elif name == "circles":
        a = [a[0], a[0]]
        th = rng.uniform(-math.pi, math.pi) if k % 2 else 0.0
    else:  # near circles: a1 = a0 (1 +- 10^U(-15, -6))
        e = 10.0 ** rng.uniform(-15, -6)
        a = [a[0], a[0] * (1 + e if rng.uniform() < 0.5 else 1 - e)]
        th = rng.uniform(-math.pi, math.pi)
    return [float(x) for x in a], float(th)


def ctor_form(a, th, dps):
    """q of semi-axes a along angle th (a[0] along (cos th, sin th), a[1]
    along (-sin th, cos th)), at dps digits, rounded.  Exactly 0 when
    a[0] = a[1] or th = 0 (then q is exact in rational arithmetic)."""
    import mpmath
    a0, a1 = fr(a[0]), fr(a[1])
    if a0 == a1:
        return [float(a0 * a0), 0.0, float(a0 * a0)]
    if th == 0:
        return [float(a0 * a0), 0.0, float(a1 * a1)]
    with mpmath.workdps(dps):
        c, s = mpmath.cos(mpmath.mpf(th)), mpmath.sin(mpmath.mpf(th))
        A0, A1 = mpmath.mpf(a[0]) ** 2, mpmath.mpf(a[1]) ** 2
        return [float(A0 * c * c + A1 * s * s), float((A0 - A1) * c * s),
                float(A0 * s * s + A1 * c * c)]


def principal(q, dps):
    """Semi-axes (decreasing) and the angle in (-pi/2, pi/2] of the major
    axis of the exact stored q, and the relative gap (e0 - e1) / e0; the
    angle is NaN when e0 = e1 exactly (a circle: any angle)."""
    import mpmath
    with mpmath.workdps(dps):
        a, b, c = mpf_list(q)
        if b == 0 and a == c:
            return [float(mpmath.sqrt(a))] * 2, math.nan, 0.0
        h = mpmath.sqrt(((a - c) / 2) ** 2 + b * b)
        e0 = (a + c) / 2 + h
        e1 = (a * c - b * b) / e0
        th = mpmath.atan2(2 * b, a - c) / 2   # atan2 in (-pi, pi]
        return ([float(mpmath.sqrt(e0)), float(mpmath.sqrt(e1))],
                float(th), float((e0 - e1) / e0))


def ctor_record(task):
    kind, k = task
    rng = np.random.default_rng([CTOR_SEED, kind, k])
    a, th = ctor_candidate(kind, k, rng)
    q = ctor_form(a, th, CTOR_DPS)
    if q != ctor_form(a, th, CTOR_DPS_CHECK):
        raise AssertionError("constructor differs at %d digits (%d, %d)"
                             % (CTOR_DPS_CHECK, kind, k))
    if not positive_definite_exact(q):
        raise AssertionError("constructed q not positive definite")
    ea, eth, gap = principal(q, CTOR_DPS)
    ea2, eth2, gap2 = principal(q, CTOR_DPS_CHECK)
    if (ea, gap) != (ea2, gap2) or not (eth == eth2 or
                                        (math.isnan(eth) and
                                         math.isnan(eth2))):
        raise AssertionError("principal axes differ at %d digits"
                             % CTOR_DPS_CHECK)
    # (the exact angle is in (-pi/2, pi/2]; near -pi/2 it may round to
    # -1.5707963267948966, which is above -pi/2)
    if not (math.isnan(eth) or -math.pi / 2 <= eth <= math.pi / 2):
        raise AssertionError("angle out of range")
    return dict(A=a, THETA=th, Q=q, EIG_A=ea, EIG_THETA=eth, EIG_GAP=gap,
                KIND=kind)


# Output ---------------------------------------------------------------------


PAIR_DATASETS = (
    # name, width (0: scalar), dtype, description
    ("R12", 2, "f8", "c2 - c1, exact input"),
    ("Q1", 3, "f8", "Q1 = (Q00, Q01, Q11), exact input"),
    ("Q2", 3, "f8", "Q2, as Q1"),
    ("MU2", 0, "f8", "mu^2 = max over [0, 1] of lambda (1 - lambda) "
     "r12^T Q(lambda)^-1 r12, correctly rounded"),
    ("LAMBDA", 0, "f8", "lambda*, the maximiser, correctly rounded"),
    ("MU2_MINUS_1", 0, "f8", "mu^2 - 1, correctly rounded from the exact "
     "value"),
    ("CLASS", 0, "i4", "the class, an index into CLASS_NAMES"),
    ("ONE_MINUS_LAMBDA", 0, "f8", "1 - lambda*, correctly rounded from the "
     "exact value"),
    ("COND1", 0, "f8", "cond2(Q1) = e_max / e_min of the stored form (80 "
     "digits), rounded"),
    ("COND2", 0, "f8", "cond2(Q2), as COND1"),
    ("LAMBDA_WINDOW", 0, "f8", "sqrt(2 ulp(MU2) / |f''(lambda*)|): the "
     "half-width of the lambda interval on which f is within one ulp of "
     "mu^2 (a scale for lambda tolerances; f'' = c'(lambda*) / b(lambda*)^2 "
     "exact at the certified root, the square root rounded in doubles)"),
    ("CANDIDATE", 0, "i4", "the attempt of the record: its inputs are drawn "
     "from default_rng([seed, class, k, CANDIDATE])"),
    ("F_LAMBDA", 4, "f8", "lambda values: LAMBDA, 0.5 and two draws "
     "U(0, 1) of default_rng([seed, class, k])"),
    ("F", 4, "f8", "f(F_LAMBDA[j]) = lambda (1 - lambda) r12^T Q(lambda)^-1 "
     "r12, exact in rational arithmetic, rounded once"),
)

GEOM_DATASETS = (
    ("PAIR_INDEX", 0, "i4", "the row of the pair in pw85_2d_pairs.h5"),
    ("CLASS", 0, "i4", "its class, an index into CLASS_NAMES"),
    ("R12", 2, "f8", "c2 - c1, exact input (as in the pairs file)"),
    ("Q1", 3, "f8", "(Q00, Q01, Q11), exact input"),
    ("Q2", 3, "f8", "as Q1"),
    ("MU2", 0, "f8", "mu^2 (as in the pairs file)"),
    ("MU2_MINUS_1", 0, "f8", "mu^2 - 1"),
    ("LAMBDA", 0, "f8", "lambda*"),
    ("ONE_MINUS_LAMBDA", 0, "f8", "1 - lambda*"),
    ("S", 2, "f8", "s = Q(lambda*)^-1 r12"),
    ("POINT", 2, "f8", "x - c1 = (1 - lambda*) Q1 s, the contact point of "
     "the ellipses scaled by mu (seed eq. (9a))"),
    ("NORMAL", 2, "f8", "n = s / |s|, unit, from ellipse 1 towards 2 "
     "(n . r12 > 0; seed eq. (8))"),
    ("D_R12", 2, "f8", "d mu^2 / d r12 = 2 lambda (1 - lambda) s"),
    ("D_THETA1", 0, "f8", "d mu^2 / d theta1 = 2 lambda (1 - lambda)^2 "
     "s x (Q1 s), s x v = s0 v1 - s1 v0, for Q1 -> R(theta1) Q1 "
     "R(theta1)^T, R(t) = [[cos t, -sin t], [sin t, cos t]] (radians)"),
    ("D_THETA2", 0, "f8", "d mu^2 / d theta2 = 2 lambda^2 (1 - lambda) "
     "s x (Q2 s)"),
    ("D_Q1", 3, "f8", "d mu^2 / d q1[k] = -lambda (1 - lambda)^2 "
     "(s0^2, 2 s0 s1, s1^2) (the off-diagonal entry counts twice)"),
    ("D_Q2", 3, "f8", "d mu^2 / d q2[k] = -lambda^2 (1 - lambda) "
     "(s0^2, 2 s0 s1, s1^2)"),
    ("COND_Q", 0, "f8", "cond2(Q(lambda*)), for tolerances"),
)

CTOR_DATASETS = (
    ("A", 2, "f8", "semi-axes, exact input"),
    ("THETA", 0, "f8", "angle (radians), exact input: a[0] along "
     "(cos theta, sin theta), a[1] along (-sin theta, cos theta)"),
    ("Q", 3, "f8", "(a0^2 c^2 + a1^2 s^2, (a0^2 - a1^2) c s, "
     "a0^2 s^2 + a1^2 c^2), c = cos theta, s = sin theta, correctly rounded"),
    ("EIG_A", 2, "f8", "semi-axes sqrt(e_j) of the exact stored Q, "
     "decreasing, correctly rounded"),
    ("EIG_THETA", 0, "f8", "the angle in (-pi/2, pi/2] of the direction of "
     "EIG_A[0] (atan2(2 Q01, Q00 - Q11) / 2), correctly rounded; NaN when "
     "Q01 = 0 and Q00 = Q11 (a circle: any angle is right)"),
    ("EIG_GAP", 0, "f8", "(e0 - e1) / e0: the direction is ill-posed to "
     "about 1e-16 / EIG_GAP"),
    ("KIND", 0, "i4", "an index into the attribute kind_names"),
)


def write_group(group, rows, spec):
    for name, width, dtype, desc in spec:
        arr = np.array([r[name] for r in rows], dtype=dtype)
        if width:
            arr = arr.reshape(len(rows), width)
        ds = group.create_dataset(name, data=np.ascontiguousarray(arr),
                                  track_times=False)
        ds.attrs["description"] = np.bytes_(desc)


def write_file(path, groups, attrs):
    """groups: [(group name or "", rows, spec, attrs)], written in order into
    a temporary file, then renamed."""
    import h5py
    tmp = path + ".tmp"
    with h5py.File(tmp, "w", libver="earliest") as f:
        for k, v in attrs.items():
            f.attrs[k] = v
        for gname, rows, spec, gattrs in groups:
            g = f if not gname else f.create_group(gname)
            for k, v in gattrs.items():
                g.attrs[k] = v
            write_group(g, rows, spec)
        names = np.array([n.encode() for n in CLASS_NAMES])
        f.create_dataset("CLASS_NAMES", data=names, track_times=False)
    os.replace(tmp, path)


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def class_summary(pairs):
    lines = []
    for i, (name, _) in enumerate(CLASSES):
        rows = [r for r in pairs if r["CLASS"] == i]
        if not rows:
            continue
        mu2 = [r["MU2"] for r in rows]
        dev = [abs(r["MU2_MINUS_1"]) for r in rows]
        end = [min(r["LAMBDA"], r["ONE_MINUS_LAMBDA"]) for r in rows]
        near1 = sum(1 for r in rows if r["ONE_MINUS_LAMBDA"] < r["LAMBDA"])
        cond = [max(r["COND1"], r["COND2"]) for r in rows]
        win = [r["LAMBDA_WINDOW"] / min(r["LAMBDA"], r["ONE_MINUS_LAMBDA"])
               for r in rows]
        lines.append(
            "  %-17s %4d: mu2 %.1e .. %.1e, |mu2-1| >= %.1e, min(l, 1-l) "
            "%.1e .. %.1e (%d near 1), cond %.1e .. %.1e, window/min(l,1-l) "
            "%.1e .. %.1e" % (name, len(rows), min(mu2), max(mu2), min(dev),
                              min(end), max(end), near1, min(cond), max(cond),
                              min(win), max(win)))
    return "\n".join(lines)


def generate(outdir, jobs, seed, count=None, only=None, pairs_path=None,
             geom_path=None, log=print):
    """Write the files; returns their paths.  count: records per class
    (a quick trial); pairs_path, geom_path: explicit output paths."""
    import mpmath
    t0 = time.time()
    classes = [(i, n if count is None else min(n, count))
               for i, (_, n) in enumerate(CLASSES)]
    tasks = [(seed, i, k) for i, n in classes for k in range(n)]
    common = ("generated by data/gen_2d_data.py (seed %d) with numpy %s, "
              "mpmath %s; layout and recipes in data/README.md, section "
              "'Ellipses (2D)'." % (seed, np.__version__, mpmath.__version__))
    paths = []
    with multiprocessing.Pool(jobs) as pool:
        out = []
        for i, o in enumerate(pool.imap(pair_record, tasks, chunksize=2)):
            out.append(o)
            if (i + 1) % 300 == 0:
                log("  pairs: %d / %d (%.0f s)" % (i + 1, len(tasks),
                                                   time.time() - t0))
        pairs = [r for r, _ in out]
        t1 = time.time()
        log("pairs: %d in %.0f s (worker time %.0f s)"
            % (len(pairs), t1 - t0, sum(s["seconds"] for _, s in out)))
        rej = {}
        for _, s in out:
            for k, v in s["rejected"].items():
                rej[k] = rej.get(k, 0) + v
        log("  rejected candidates: %r" % rej)
        for i, (name, _) in enumerate(CLASSES):
            rc = {}
            for r, s in out:
                if r["CLASS"] == i:
                    for k, v in s["rejected"].items():
                        rc[k] = rc.get(k, 0) + v
            if rc:
                log("    %s: %r" % (name, rc))
        dpss = {}
        for _, s in out:
            dpss[s["dps"]] = dpss.get(s["dps"], 0) + 1
        log("  route A certified at digits: %r (0: lambda* = 1/2 exactly)"
            % dict(sorted(dpss.items())))
        dpsb = {}
        for _, s in out:
            dpsb[s["dps_b"]] = dpsb.get(s["dps_b"], 0) + 1
        log("  route B identical at d and 2d digits on %d of %d pairs, "
            "d = %d .. %d (d > %d on %d pairs)"
            % (len(pairs), len(pairs), min(dpsb), max(dpsb), DPS_B,
               sum(v for k, v in dpsb.items() if k > DPS_B)))
        log("  F: %d values exact, identical by an mpmath solve at d digits"
            % (4 * len(pairs)))
        log(class_summary(pairs))
        if only in (None, "pairs"):
            attrs = {
                "description": np.bytes_(
                    "pw85 reference pairs of ellipses (issue 29), " + common
                    + " MU2, LAMBDA, MU2_MINUS_1, ONE_MINUS_LAMBDA correctly "
                    "rounded for the stored doubles (certified enclosures in "
                    "exact rational arithmetic; identical by an mpmath route "
                    "at d and 2d digits, d >= %d)." % DPS_B),
                "class_names": np.bytes_(",".join(CLASS_NAMES)),
                "generator": np.bytes_("data/gen_2d_data.py"),
                "seed": seed,
            }
            path = pairs_path or os.path.join(outdir, PAIRS_FILE)
            write_file(path, [("", pairs, PAIR_DATASETS, {})], attrs)
            log("wrote %s (%d bytes, sha256 %s)"
                % (path, os.path.getsize(path), sha256(path)))
            paths.append(path)
        if only in (None, "geometry"):
            gtasks = []
            for i, n in classes:
                idx = [j for j, r in enumerate(pairs) if r["CLASS"] == i]
                gtasks += [(j, pairs[j]) for j in idx[:GEOM_PER_CLASS]]
            gout = pool.map(geometry_record, gtasks, chunksize=1)
            t2 = time.time()
            log("geometry: %d pairs in %.0f s" % (len(gout), t2 - t1))
            worst = {}
            for _, s in gout:
                for k, e in s["fd_err"].items():
                    worst[k] = max(worst.get(k, 0.0), e)
            for k, e in sorted(worst.items()):
                log("  FD vs closed form, %-8s worst relative error %.2e"
                    % (k, e))
            log("  identities: worst relative residual %.2e"
                % max(s["id_err"] for _, s in gout))
            ctasks = [(c, k) for c, (_, n) in enumerate(CTOR_KINDS)
                      for k in range(n)]
            ctors = pool.map(ctor_record, ctasks, chunksize=4)
            log("constructors: %d cases in %.0f s" % (len(ctors),
                                                      time.time() - t2))
            attrs = {
                "description": np.bytes_(
                    "pw85 contact geometry and derivatives of mu^2 for pairs "
                    "of ellipses (issue 29), " + common + " References at "
                    "%d digits (more where lambda* is ill-conditioned), "
                    "identical from a cold start at %d (and more); "
                    "derivatives checked "
                    "against central finite differences (relative step %s) "
                    "on every pair: worst relative error %.2e."
                    % (GEOM_DPS, GEOM_DPS_CHECK, FD_H, max(worst.values()))),
                "class_names": np.bytes_(",".join(CLASS_NAMES)),
                "generator": np.bytes_("data/gen_2d_data.py"),
                "seed": seed,
            }
            cattrs = {
                "description": np.bytes_(
                    "ellipse constructors (semi-axes and angle -> q) and "
                    "principal axes of the stored q; case k of kind i from "
                    "default_rng([%d, i, k]); %d digits, identical at %d."
                    % (CTOR_SEED, CTOR_DPS, CTOR_DPS_CHECK)),
                "kind_names": np.bytes_(",".join(n for n, _ in CTOR_KINDS)),
            }
            path = geom_path or os.path.join(outdir, GEOM_FILE)
            write_file(path, [("", [r for r, _ in gout], GEOM_DATASETS, {}),
                              ("constructors", ctors, CTOR_DATASETS, cattrs)],
                       attrs)
            log("wrote %s (%d bytes, sha256 %s)"
                % (path, os.path.getsize(path), sha256(path)))
            paths.append(path)
    log("total %.0f s" % (time.time() - t0))
    return paths


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--outdir", default=os.path.dirname(
        os.path.abspath(__file__)))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--count", type=int, default=None,
                    help="records per class (a quick trial only)")
    ap.add_argument("--only", choices=("pairs", "geometry"), default=None)
    args = ap.parse_args(argv)
    os.makedirs(args.outdir, exist_ok=True)
    generate(args.outdir, args.jobs, SEED, args.count, args.only)
    return 0


if __name__ == "__main__":
    sys.exit(main())
