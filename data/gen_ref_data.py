#!/usr/bin/python3
"""Generate the pw85 reference data sets.

Writes, next to this script (or in --outdir):

* pw85_ref_data.h5      radii, directions, spheroids, lambdas, F,
                        distances, MU2, LAMBDA;
* pw85_general_pairs.h5 seeded random triaxial pairs (generic and
                        near-tangent) with MU2, LAMBDA, MU2_MINUS_1;
* pw85_finish_pairs.h5  seeded random triaxial pairs on which the
                        compensated finish decides mu^2 (same layout).

Every reference value is computed from the double-precision inputs exactly
as they are stored in the files, and is the correctly rounded double of the
exact mathematical value:

* f(lambda) is a rational function of the (dyadic rational) inputs.  It is
  evaluated in exact integer arithmetic and rounded once (Python's int / int
  true division is correctly rounded).
* The maximiser lambda* of f is the unique root in (0, 1) of the degree-6
  polynomial c(lambda), numerator of f'(lambda) (seed documentation, chapter
  4.2, eqs (13)-(15)).  The integer coefficients of c are computed exactly;
  the root is enclosed in a bracket [lo, hi] of dyadic numbers with P
  fractional bits (P = 320 by default, about 96 decimal digits) on which the
  sign of c is evaluated EXACTLY (integer Horner scheme).  The bracket is
  refined by a safeguarded Newton/bisection iteration until its width is a
  few units of 2**-P, far below 1e-45 relative.
* f is concave on [0, 1] (it is the lower envelope of functions that are
  affine in lambda, seed ch. 3, eq. (4)-(5)), so for any x in the bracket
  f(x) <= mu^2 <= f(x) + |f'(x)| (max distance from x to the bracket ends).
  Both ends of this enclosure, and of the bracket of lambda*, are rounded to
  doubles; the generator asserts that they round to the same double, which
  certifies that the stored MU2 and LAMBDA are correctly rounded.
  The generator also asserts c(0) > 0 > c(1) exactly, and that
  (1+t)^6 c(1/(1+t)) has exactly one coefficient sign variation (Descartes'
  rule: exactly one root of c in (0, 1), counted with multiplicity).

Independent self-checks (printed at the end) recompute samples with a higher
number of fractional bits, and with a completely different method (mpmath at
100 digits, LU solve of Q(lambda) s = r, Newton on the residual g of seed
chapter 5, eq. (4)-(5)).

Usage (from the repository root):
    /usr/bin/python3 data/gen_ref_data.py [--outdir DIR] [--jobs N]
                                          [--only ref|general|finish]
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

# Constants of the data sets ------------------------------------------------

RADII = (0.01999, 1.999, 99.999)
DISTANCES = (0.15, 1.1, 11.0)
NUM_LAMBDAS = 11

P_BITS = 320  # fractional bits of the dyadic root enclosure (~96 digits)
P_CHECK = P_BITS + 160  # self-check with ~48 more digits
REL_WIDTH = 10**45  # bracket width must be < lambda* / REL_WIDTH

GENERAL_SEED = 20190712
GENERAL_N = 2000
GENERAL_NUM_GENERIC = 800
GENERAL_DELTAS = (-1e-3, -1e-6, -1e-8, -1e-10, -1e-12, -1e-14,
                  1e-14, 1e-12, 1e-10, 1e-8, 1e-6, 1e-3)

REF_FILE = "pw85_ref_data.h5"
GENERAL_FILE = "pw85_general_pairs.h5"

H5_OPTS = dict(compression="gzip", compression_opts=4, shuffle=True,
               track_times=False)


# Small data sets -------------------------------------------------------------


def make_radii():
    return np.array(RADII, dtype=np.float64)


def make_distances():
    return np.array(DISTANCES, dtype=np.float64)


def make_lambdas():
    return np.array([l / 10 for l in range(NUM_LAMBDAS)], dtype=np.float64)


def make_directions():
    """The 12 unit vectors (0, ±u, ±v), (±v, 0, ±u), (±u, ±v, 0)."""
    import mpmath
    with mpmath.workdps(60):
        phi = (1 + mpmath.sqrt(5)) / 2
        u_mp = 1 / mpmath.sqrt(1 + phi**2)
        v_mp = phi * u_mp
        u, v = float(u_mp), float(v_mp)
    out = []
    for su in (-1.0, 1.0):
        for sv in (-1.0, 1.0):
            uu, vv = su * u, sv * v
            out += [(0.0, uu, vv), (vv, 0.0, uu), (uu, vv, 0.0)]
    return np.array(out, dtype=np.float64)


def sym_from_exact(m):
    """Round the exact (Fraction) upper triangle m[6] to doubles."""
    return [float(x) for x in m]


def spheroid_exact(a, c, n):
    """Q = a² I + (c² − a²) n nᵀ, exact from the doubles, rounded once."""
    a, c = Fraction(a), Fraction(c)
    n = [Fraction(x) for x in n]
    a2 = a * a
    d = c * c - a2
    m = [a2 + d * n[0] * n[0], d * n[0] * n[1], d * n[0] * n[2],
         a2 + d * n[1] * n[1], d * n[1] * n[2], a2 + d * n[2] * n[2]]
    return sym_from_exact(m)


def make_spheroids(radii, directions):
    out = []
    for a in radii:
        for c in radii:
            for n in directions:
                out.append(spheroid_exact(float(a), float(c),
                                          [float(x) for x in n]))
    return np.array(out, dtype=np.float64)


# Exact integer kernels --------------------------------------------------------


def to_ints(values):
    """Return (ints, s) such that values[i] == ints[i] * 2**-s exactly."""
    values = [float(x) for x in values]
    s = 0
    for x in values:
        if not math.isfinite(x):
            raise ValueError("non finite input")
        d = x.as_integer_ratio()[1]
        s = max(s, d.bit_length() - 1)
    ints = []
    for x in values:
        n, d = x.as_integer_ratio()
        ints.append(n * ((1 << s) // d))
    return ints, s


def adj6(m):
    """Adjugate of the symmetric matrix m[6] (same storage)."""
    m00, m01, m02, m11, m12, m22 = m
    return [m11 * m22 - m12 * m12, m02 * m12 - m01 * m22,
            m01 * m12 - m02 * m11, m00 * m22 - m02 * m02,
            m01 * m02 - m00 * m12, m00 * m11 - m01 * m01]


def det6(m):
    a = adj6(m)
    return m[0] * a[0] + m[1] * a[1] + m[2] * a[2]


def xtax(a, x):
    """xᵀ A x for symmetric A[6]."""
    x0, x1, x2 = x
    return (a[0] * x0 * x0 + a[3] * x1 * x1 + a[5] * x2 * x2
            + 2 * (a[1] * x0 * x1 + a[2] * x0 * x2 + a[4] * x1 * x2))


def frob6(a, b):
    """tr(A B) for symmetric A[6], B[6]."""
    return (a[0] * b[0] + a[3] * b[3] + a[5] * b[5]
            + 2 * (a[1] * b[1] + a[2] * b[2] + a[4] * b[4]))


class Pair:
    """Exact polynomial data of the pair (Q1, Q2).

    With Q1 = Q1i 2**-sq, Q2 = Q2i 2**-sq and D = Q2i − Q1i:
        adj(Q1i + λ D) = A0 + λ A1 + λ² A2      (integer matrices)
        det(Q1i + λ D) = b0 + b1 λ + b2 λ² + b3 λ³  (integers)
    A0 = adj Q1i, A2 = adj D, A1 = adj Q2i − A0 − A2 (adj is quadratic);
    b0 = det Q1i, b1 = tr(adj(Q1i) D), b2 = tr(Q1i adj D), b3 = det D.
    """

    __slots__ = ("sq", "A", "b")

    def __init__(self, q1, q2):
        ints, self.sq = to_ints(list(q1) + list(q2))
        q1i, q2i = ints[:6], ints[6:]
        d = [y - x for x, y in zip(q1i, q2i)]
        a0, a2 = adj6(q1i), adj6(d)
        a1 = [z - x - y for x, y, z in zip(a0, a2, adj6(q2i))]
        self.A = (a0, a1, a2)
        b0, b3 = det6(q1i), det6(d)
        b1, b2 = frob6(a0, d), frob6(q1i, a2)
        if b0 + b1 + b2 + b3 != det6(q2i):
            raise AssertionError("inconsistent determinant expansion")
        if b0 <= 0 or det6(q2i) <= 0:
            raise ValueError("quadratic form not positive definite")
        self.b = (b0, b1, b2, b3)

    def a_coeffs(self, r):
        """(a0, a1, a2), sr with a(λ) = rᵀ adj(Q(λ)) r = Σ a_k λ^k · 2**(-2sq-2sr)."""
        ri, sr = to_ints(r)
        return tuple(xtax(ak, ri) for ak in self.A), sr


def pmul(p, q):
    out = [0] * (len(p) + len(q) - 1)
    for i, x in enumerate(p):
        if x:
            for j, y in enumerate(q):
                out[i + j] += x * y
    return out


def padd(p, q):
    n = max(len(p), len(q))
    return [(p[i] if i < len(p) else 0) + (q[i] if i < len(q) else 0)
            for i in range(n)]


def pder(p):
    return [i * p[i] for i in range(1, len(p))]


def c_coeffs(a, b):
    """Numerator of f' for f = λ(1−λ) a/b:  c = (1−2λ) a b + λ(1−λ)(a'b − a b')."""
    ab = pmul(a, b)
    w = padd(pmul(pder(a), b), [-x for x in pmul(a, pder(b))])
    c = padd(pmul([1, -2], ab), pmul([0, 1, -1], w))
    if len(c) != 7:
        raise AssertionError("degree of c")
    return c


def c_coeffs_seed(a, b):
    """Same, transcribed from seed ch. 4.2 eqs (15a)-(15g) (used as a check)."""
    a0, a1, a2 = a
    b0, b1, b2, b3 = b
    return [a0 * b0, 2 * (a1 - a0) * b0,
            -a0 * (b1 + b2) + 3 * b0 * (a2 - a1) + a1 * b1,
            2 * (b1 * (a2 - a1) - a0 * b3) - 4 * a2 * b0,
            (a0 - a1) * b3 + (a2 - a1) * b2 - 3 * a2 * b1,
            -2 * a2 * b2, -a2 * b3]


def round_ratio(num, den, e):
    """Correctly rounded double of num / den * 2**e (integers).

    CPython's int / int true division is correctly rounded (round half to
    even); results are required to be normal doubles (or zero)."""
    x = (num << e) / den if e >= 0 else num / (den << -e)
    if x != 0 and not abs(x) >= sys.float_info.min:
        raise AssertionError("subnormal result")
    return x


def f_exact(pair, a, sr, lam):
    """Correctly rounded f(lam) for the double lam; a from pair.a_coeffs."""
    n, d = float(lam).as_integer_ratio()
    t = d.bit_length() - 1
    a0, a1, a2 = a
    b0, b1, b2, b3 = pair.b
    an = (a0 << 2 * t) + ((a1 * n) << t) + a2 * n * n
    bn = (b0 << 3 * t) + ((b1 * n) << 2 * t) + ((b2 * n * n) << t) + b3 * n**3
    num = n * ((1 << t) - n) * an
    return round_ratio(num, bn, pair.sq - 2 * sr - t)


def f_value_F(pair, r, lam):
    a, sr = pair.a_coeffs(r)
    return f_exact(pair, a, sr, lam)


def c_eval(c, x, p):
    """Exact C = c(x/2^p)·2^(6p) (c of degree 6)."""
    v = c[6]
    for i in range(5, -1, -1):
        v = v * x + (c[i] << ((6 - i) * p))
    return v


def dc_eval(c, x, p):
    """Exact C' = c'(x/2^p)·2^(5p)."""
    v = 6 * c[6]
    for i in range(5, 0, -1):
        v = v * x + ((i * c[i]) << ((6 - i) * p))
    return v


def _float_poly(c):
    m = max(abs(x).bit_length() for x in c)
    sh = max(m - 60, 0)
    return [float(x >> sh) if x >= 0 else -float((-x) >> sh) for x in c]


def _float_start(c):
    """Double-precision estimate of the root of c in (0, 1) (start only)."""
    cf = _float_poly(c)
    lo, hi = 0.0, 1.0
    x = 0.5
    for _ in range(80):
        v = cf[6]
        dv = 0.0
        for i in range(5, -1, -1):
            dv = dv * x + v
            v = v * x + cf[i]
        if v > 0:
            lo = x
        elif v < 0:
            hi = x
        else:
            return x
        if hi - lo <= 1e-15 * hi:
            break
        xn = x - v / dv if dv != 0 else -1.0
        if not (lo < xn < hi):
            xn = 0.5 * (lo + hi)
        if abs(xn - x) <= 1e-15 * x:
            return xn
        x = xn
    return x


def descartes_01(c):
    """Sign variations of (1+t)^6 c(1/(1+t)): bound on roots of c in (0,1)."""
    # (1+t)^6 c(1/(1+t)) = Σ c_i (1+t)^(6-i)
    p = [0] * 7
    for i, ci in enumerate(c):
        k = 6 - i
        binom = 1
        for j in range(k + 1):
            p[j] += ci * binom
            binom = binom * (k - j) // (j + 1)
    signs = [x > 0 for x in p if x != 0]
    return sum(1 for u, v in zip(signs, signs[1:]) if u != v)


class RootStats:
    def __init__(self):
        self.cases = 0
        self.newton = 0
        self.bisect = 0
        self.max_steps = 0
        self.exact_roots = 0
        self.retries = 0
        self.min_lambda = 1.0
        self.max_lambda = 0.0
        self.descartes = {}
        self.max_kappa = 0.0  # root condition number Σ|c_i|λ^i / (λ|c'(λ)|)

    def merge(self, o):
        self.cases += o.cases
        self.newton += o.newton
        self.bisect += o.bisect
        self.max_steps = max(self.max_steps, o.max_steps)
        self.exact_roots += o.exact_roots
        self.retries += o.retries
        self.min_lambda = min(self.min_lambda, o.min_lambda)
        self.max_lambda = max(self.max_lambda, o.max_lambda)
        for k, v in o.descartes.items():
            self.descartes[k] = self.descartes.get(k, 0) + v
        self.max_kappa = max(self.max_kappa, o.max_kappa)

    def summary(self):
        return ("%d root findings, Newton steps %d (%.2f/case), bisection "
                "steps %d, max steps/case %d, roots hit exactly at a dyadic %d, "
                "precision retries %d, lambda* in [%.6g, 1-%.6g], "
                "Descartes variations on (0,1) %s, max condition number of "
                "the root of c %.3g" % (
                    self.cases, self.newton,
                    self.newton / max(self.cases, 1), self.bisect,
                    self.max_steps, self.exact_roots, self.retries,
                    self.min_lambda, 1 - self.max_lambda,
                    dict(sorted(self.descartes.items())), self.max_kappa))


class ContactResult:
    __slots__ = ("mu2", "lam", "mu2m1", "mu2_num", "mu2_den", "mu2_exp")


def _contact_p(pair, a, sr, p, stats):
    b = pair.b
    c = c_coeffs(list(a), list(b))
    if len(c) != 7:
        raise AssertionError("degree of c")
    one = 1 << p
    # c(0) > 0 > c(1), exactly
    if not (c[0] > 0 and sum(c) < 0):
        raise AssertionError("c(0) > 0 > c(1) violated")
    lo, hi = 0, one
    x = int(round(_float_start(c) * one))
    x = min(max(x, 1), one - 1)
    nsteps = 0
    prev_dx = None
    exact = False
    while True:
        cx = c_eval(c, x, p)
        if cx == 0:
            lo = hi = x
            exact = True
            break
        if cx > 0:
            lo = x
        else:
            hi = x
        if hi - lo <= 2:
            break
        dcx = dc_eval(c, x, p)
        nsteps += 1
        use_newton = False
        if dcx != 0:
            # integer Newton correction, rounded to nearest
            if dcx > 0:
                dx = (2 * cx + dcx) // (2 * dcx)
            else:
                dx = (-2 * cx - dcx) // (-2 * dcx)
            if abs(dx) <= 1:
                # converged at resolution 2^-p: enclose with a few ulps
                stats.newton += 1
                k = 2
                while not exact and hi - lo > 2 * k:
                    for xt in (x - k, x + k):
                        if lo < xt < hi:
                            vt = c_eval(c, xt, p)
                            if vt > 0:
                                lo = xt
                            elif vt < 0:
                                hi = xt
                            else:
                                lo = hi = xt
                                exact = True
                                break
                    k *= 4
                break
            xn = x - dx
            # accept if inside the bracket and converging (or already tiny)
            if lo < xn < hi and (prev_dx is None or 2 * abs(dx) <= abs(prev_dx)
                                 or abs(dx) < 1 << 64):
                use_newton = True
        if use_newton:
            stats.newton += 1
            prev_dx = dx
            x = xn
        else:
            stats.bisect += 1
            prev_dx = None
            x = (lo + hi) // 2
    if hi - lo > 64:
        raise AssertionError("bracket too wide")
    if not exact and (hi - lo) * REL_WIDTH >= lo:
        return None  # insufficient fractional bits for this lambda*
    # certified rounding of lambda*
    lam_lo, lam_hi = lo / one, hi / one
    if lam_lo != lam_hi:
        return None
    # mu^2 enclosure (f concave on [0, 1])
    xm = (lo + hi) // 2
    a0, a1, a2 = a
    b0, b1, b2, b3 = b
    an = (a0 << 2 * p) + ((a1 * xm) << p) + a2 * xm * xm
    bn = (b0 << 3 * p) + ((b1 * xm) << 2 * p) + ((b2 * xm * xm) << p) \
        + b3 * xm**3
    fnum = xm * (one - xm) * an  # f = fnum / (2^p bn) · 2^e
    e = pair.sq - 2 * sr
    w = max(xm - lo, hi - xm)
    cm = abs(c_eval(c, xm, p)) if w else 0
    # f' = C / bn² · 2^e ; bound |f'| w 2^-p = |C| w / (2^p bn²) 2^e
    den_lo = bn << p
    num_lo = fnum
    num_hi_bn = fnum * bn + cm * w  # over den_lo * bn
    mu2 = round_ratio(num_lo, den_lo, e)
    if w and round_ratio(num_hi_bn, den_lo * bn, e) != mu2:
        return None
    # mu^2 − 1 = (num·2^e − den)/den
    if e >= 0:
        m1_lo = round_ratio((num_lo << e) - den_lo, den_lo, 0)
        m1_hi = round_ratio((num_hi_bn << e) - den_lo * bn, den_lo * bn, 0) \
            if w else m1_lo
    else:
        m1_lo = round_ratio(num_lo - (den_lo << -e), den_lo << -e, 0)
        m1_hi = round_ratio(num_hi_bn - ((den_lo * bn) << -e),
                            (den_lo * bn) << -e, 0) if w else m1_lo
    if m1_lo != m1_hi:
        return None
    res = ContactResult()
    res.mu2, res.lam, res.mu2m1 = mu2, lam_lo, m1_lo
    res.mu2_num, res.mu2_den, res.mu2_exp = num_lo, den_lo, e
    # statistics
    stats.cases += 1
    stats.max_steps = max(stats.max_steps, nsteps)
    stats.exact_roots += exact
    stats.min_lambda = min(stats.min_lambda, lam_lo)
    stats.max_lambda = max(stats.max_lambda, lam_lo)
    nd = descartes_01(c)
    stats.descartes[nd] = stats.descartes.get(nd, 0) + 1
    if nd != 1:
        raise AssertionError("more than one sign variation on (0, 1)")
    if not exact:
        absc = [abs(v) for v in c]
        num_k = c_eval(absc, xm, p)
        den_k = abs(dc_eval(c, xm, p)) * xm
        if den_k:
            stats.max_kappa = max(stats.max_kappa,
                                  round_ratio(num_k, den_k, 0))
    return res


def contact(pair, r, p=P_BITS, stats=None):
    """Certified correctly rounded (mu2, lambda*, mu2 − 1) for r, pair."""
    if stats is None:
        stats = RootStats()
    a, sr = pair.a_coeffs(r)
    while True:
        res = _contact_p(pair, a, sr, p, stats)
        if res is not None:
            return res
        stats.retries += 1
        p += 256
        if p > 4000:
            raise AssertionError("no certified result")


# Independent high-precision route (mpmath, LU solve) ---------------------------


def _mp_inputs(q1, q2, r):
    import mpmath

    def full(q):
        q = [mpmath.mpf(float(x)) for x in q]
        return mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                              [q[2], q[4], q[5]]])
    return full(q1), full(q2), mpmath.matrix([mpmath.mpf(float(x))
                                              for x in r])


def f_mp(lam, r, q1, q2, dps=80):
    """f(lam) by an LU solve at dps digits (independent of the integer route),
    rounded to the nearest double."""
    import mpmath
    with mpmath.workdps(dps):
        Q1, Q2, rv = _mp_inputs(q1, q2, r)
        lam = mpmath.mpf(float(lam))
        s = mpmath.lu_solve((1 - lam) * Q1 + lam * Q2, rv)
        return float(lam * (1 - lam) * (rv.T * s)[0])


def contact_mp(r, q1, q2, dps=100):
    """(mu2, lambda*, mu2 - 1) rounded to doubles, computed at dps digits by a
    safeguarded Newton iteration on g = mu2^2 - mu1^2 (seed ch. 5, eqs (4),
    (5)), every Q(lambda)^-1 applied by an LU solve."""
    import mpmath
    with mpmath.workdps(dps):
        Q1, Q2, rv = _mp_inputs(q1, q2, r)
        Q12 = Q2 - Q1

        def g_dg(lam):
            Q = (1 - lam) * Q1 + lam * Q2
            s = mpmath.lu_solve(Q, rv)
            u = Q12 * s
            v = mpmath.lu_solve(Q, u)
            rs, su, uv = (rv.T * s)[0], (s.T * u)[0], (u.T * v)[0]
            g = (2 * lam - 1) * rs + lam * (1 - lam) * su
            dg = 2 * rs + 2 * (1 - 2 * lam) * su - 2 * lam * (1 - lam) * uv
            return g, dg

        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        x = mpmath.mpf(0.5)
        tol = mpmath.mpf(10) ** (-(dps - 15))
        for _ in range(5000):
            g, dg = g_dg(x)
            if g < 0:
                lo = x
            elif g > 0:
                hi = x
            else:
                break
            xn = x - g / dg if dg != 0 else lo - 1
            if not (lo < xn < hi):
                xn = (lo + hi) / 2
            done = abs(xn - x) <= tol * x or hi - lo <= tol * lo
            x = xn
            if done:
                break
        else:
            raise AssertionError("contact_mp did not converge")
        s = mpmath.lu_solve((1 - x) * Q1 + x * Q2, rv)
        mu2 = x * (1 - x) * (rv.T * s)[0]
        return float(mu2), float(x), float(mu2 - 1)


# Main reference data set ---------------------------------------------------------


_G = {}


def _init_worker(directions, spheroids, lambdas, distances):
    _G["directions"] = [list(map(float, d)) for d in directions]
    _G["spheroids"] = [list(map(float, q)) for q in spheroids]
    _G["lambdas"] = [float(x) for x in lambdas]
    _G["distances"] = [float(x) for x in distances]
    _G["dir_np"] = np.asarray(directions, dtype=np.float64)


def r12_vector(d, direction):
    """r12 = d*dir, componentwise IEEE double product (as a C test does)."""
    return [float(x) for x in np.multiply(np.float64(d),
                                          np.asarray(direction, np.float64))]


def compute_row(i):
    """F[i], MU2[i], LAMBDA[i] and statistics for spheroid i as Q1."""
    t0 = time.time()
    dirs, sph, lams, dists = (_G["directions"], _G["spheroids"],
                              _G["lambdas"], _G["distances"])
    nq, nk, nl, nm = len(sph), len(dirs), len(lams), len(dists)
    F = np.empty((nq, nk, nl))
    MU2 = np.empty((nq, nk, nm))
    LAM = np.empty((nq, nk, nm))
    stats = RootStats()
    for j in range(nq):
        pair = Pair(sph[i], sph[j])
        for k in range(nk):
            a, sr = pair.a_coeffs(dirs[k])
            for l in range(nl):
                F[j, k, l] = f_exact(pair, a, sr, lams[l])
            for m in range(nm):
                res = contact(pair, r12_vector(dists[m], dirs[k]), P_BITS,
                              stats)
                MU2[j, k, m] = res.mu2
                LAM[j, k, m] = res.lam
    return i, F, MU2, LAM, stats, time.time() - t0


def invariant_failures(data):
    """Exact identities of the full arrays; returns a list of failures.

    f and the contact function are even in r, and directions[k'] =
    -directions[k] exactly for some k' (so are the r12 = d*dir products);
    identical spheroid rows (n and -n give the same Q) must give identical
    slices; f(0) = f(1) = 0; 0 < LAMBDA < 1; LAMBDA = 1/2 when q1 == q2.
    """
    fails = []
    dirs, sph = data["directions"], data["spheroids"]
    F, MU2, LAM = data["F"], data["MU2"], data["LAMBDA"]
    keys = [(d + 0.0).tobytes() for d in dirs]  # +0.0 == -0.0 here
    opp = [keys.index((0.0 - d).tobytes()) for d in dirs]
    rows = {}
    canon = [rows.setdefault(q.tobytes(), i) for i, q in enumerate(sph)]

    def eq(a, b):
        return a.shape == b.shape and np.ascontiguousarray(a).tobytes() == \
            np.ascontiguousarray(b).tobytes()
    for name, arr in (("F", F), ("MU2", MU2), ("LAMBDA", LAM)):
        if not eq(arr, arr[:, :, opp, :]):
            fails.append("%s not even in the direction" % name)
        if not eq(arr, arr[canon][:, canon]):
            fails.append("%s differs for identical spheroids" % name)
    if not (np.all(F[..., 0] == 0) and np.all(F[..., -1] == 0)):
        fails.append("F(0) or F(1) not zero")
    if not np.all(F[..., 1:-1] > 0):
        fails.append("F not positive inside (0, 1)")
    if not (np.all(MU2 > 0) and np.all((LAM > 0) & (LAM < 1))):
        fails.append("MU2 <= 0 or LAMBDA outside (0, 1)")
    same_q = np.array(canon)[:, None] == np.array(canon)[None, :]
    if not np.all(LAM[same_q] == 0.5):
        fails.append("LAMBDA != 1/2 for q1 == q2")
    return fails


def self_check_ref(data, log):
    """Recompute samples at higher precision and with the mpmath route."""
    rng = np.random.default_rng(12345)
    sph, dirs, lams, dists = (data["spheroids"], data["directions"],
                              data["lambdas"], data["distances"])
    F, MU2, LAM = data["F"], data["MU2"], data["LAMBDA"]
    # seed eqs (15a)-(15g) give the same c as the direct expansion
    for _ in range(200):
        i, j, k = (int(rng.integers(0, n)) for n in (108, 108, 12))
        pair = Pair(sph[i], sph[j])
        a, _ = pair.a_coeffs(dirs[k])
        assert c_coeffs(list(a), list(pair.b)) == \
            c_coeffs_seed(a, pair.b), "eq. (15) mismatch"
    log("  c(λ) from the expansion equals seed eqs (15a)-(15g): 200 cases")
    # F: independent LU solve at 80 digits, 1000 entries
    n_f = 5000
    bad = 0
    for _ in range(n_f):
        i, j, k, l = (int(rng.integers(0, n)) for n in (108, 108, 12, 11))
        v = f_mp(lams[l], dirs[k], sph[i], sph[j], dps=80)
        bad += v != F[i, j, k, l]
    assert bad == 0, "F: %d mismatches with the mpmath LU route" % bad
    log("  F: %d random entries identical with mpmath LU solve at 80 digits"
        % n_f)
    # MU2/LAMBDA: higher fractional bits, 400 cases; mpmath route, 200 cases
    n_p = 2000
    for t in range(n_p):
        i, j, k, m = (int(rng.integers(0, n)) for n in (108, 108, 12, 3))
        if t < 12:
            j = i  # include the exactly rational lambda* = 1/2 case
        pair = Pair(sph[i], sph[j])
        res = contact(pair, r12_vector(dists[m], dirs[k]), P_CHECK)
        assert res.mu2 == MU2[i, j, k, m] and res.lam == LAM[i, j, k, m], \
            "MU2/LAMBDA mismatch at P_CHECK for %s" % ((i, j, k, m),)
    log("  MU2/LAMBDA: %d random cases identical with %d fractional bits "
        "(vs %d)" % (n_p, P_CHECK, P_BITS))
    n_mp = 1000
    for _ in range(n_mp):
        i, j, k, m = (int(rng.integers(0, n)) for n in (108, 108, 12, 3))
        mu2, lam, _ = contact_mp(r12_vector(dists[m], dirs[k]), sph[i],
                                 sph[j], dps=100)
        assert mu2 == MU2[i, j, k, m] and lam == LAM[i, j, k, m], \
            "MU2/LAMBDA mismatch with mpmath route for %s" % ((i, j, k, m),)
    log("  MU2/LAMBDA: %d random cases identical with mpmath at 100 digits "
        "(LU solve, Newton on g of seed ch. 5)" % n_mp)


def generate_ref(outdir, jobs, log):
    t0 = time.time()
    radii = make_radii()
    directions = make_directions()
    spheroids = make_spheroids(radii, directions)
    lambdas = make_lambdas()
    distances = make_distances()
    nq, nk, nl, nm = len(spheroids), len(directions), len(lambdas), \
        len(distances)
    F = np.empty((nq, nq, nk, nl))
    MU2 = np.empty((nq, nq, nk, nm))
    LAM = np.empty((nq, nq, nk, nm))
    stats = RootStats()
    init = (directions, spheroids, lambdas, distances)
    log("reference data: %d spheroids, %d directions, %d lambdas, %d "
        "distances, %d workers" % (nq, nk, nl, nm, jobs))
    if jobs > 1:
        pool = multiprocessing.Pool(jobs, initializer=_init_worker,
                                    initargs=init)
        rows = pool.imap(compute_row, range(nq), chunksize=1)
    else:
        _init_worker(*init)
        pool = None
        rows = map(compute_row, range(nq))
    for n, (i, Fi, MUi, LAi, st, dt) in enumerate(rows, 1):
        F[i], MU2[i], LAM[i] = Fi, MUi, LAi
        stats.merge(st)
        if n % 6 == 0 or n == nq:
            log("  row %3d/%d done (%.1f s for this row, %.0f s elapsed)"
                % (n, nq, dt, time.time() - t0))
    if pool is not None:
        pool.close()
        pool.join()
    log("  " + stats.summary())
    data = dict(radii=radii, directions=directions, spheroids=spheroids,
                lambdas=lambdas, F=F, distances=distances, MU2=MU2,
                LAMBDA=LAM)
    log("self-checks (reference data):")
    fails = invariant_failures(data)
    assert not fails, fails
    log("  exact invariants of the full arrays hold (evenness in r, "
        "identical spheroids, F(0)=F(1)=0, LAMBDA=1/2 for q1 == q2)")
    self_check_ref(data, log)
    path = os.path.join(outdir, REF_FILE)
    write_h5(path, data, {
        "radii": None, "directions": None, "spheroids": None,
        "lambdas": None, "distances": None,
        "F": (1, nq, nk, nl), "MU2": (1, nq, nk, nm),
        "LAMBDA": (1, nq, nk, nm)},
        {"description": (
            "pw85 reference data (layout of Zenodo 10.5281/zenodo.3323683 "
            "for radii/directions/spheroids/lambdas/F; distances, MU2, "
            "LAMBDA added). All values are the correctly rounded doubles "
            "of the exact values for the stored double inputs. "
            "F[i,j,k,l] = f(lambdas[l]; r=directions[k], q1=spheroids[i], "
            "q2=spheroids[j]); MU2/LAMBDA[i,j,k,m] for r12 = "
            "distances[m]*directions[k] (IEEE double products). "
            "Generated by data/gen_ref_data.py.")})
    log("wrote %s (%.0f s)" % (path, time.time() - t0))
    return stats


def write_h5(path, data, chunks, attrs):
    import h5py
    tmp = path + ".tmp"
    with h5py.File(tmp, "w", libver="earliest") as f:
        for k, v in attrs.items():
            f.attrs[k] = v
        for name, ch in chunks.items():
            arr = np.ascontiguousarray(data[name])
            if ch is None:
                f.create_dataset(name, data=arr, track_times=False)
            else:
                f.create_dataset(name, data=arr, chunks=ch, **H5_OPTS)
    os.replace(tmp, path)


# General pairs ------------------------------------------------------------------


def rotation_from_quaternion(q):
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def triaxial_exact(axes, rot):
    """Q = Σ a_i² v_i v_iᵀ (v_i = columns of rot), exact, rounded once."""
    a = [Fraction(float(x)) for x in axes]
    v = [[Fraction(float(rot[r, i])) for r in range(3)] for i in range(3)]
    m = []
    for r, s in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)):
        m.append(sum(a[i] * a[i] * v[i][r] * v[i][s] for i in range(3)))
    return sym_from_exact(m)


def _ulp_step(x, step):
    if step < 0:
        return math.nextafter(x, -math.inf)
    if step > 0:
        return math.nextafter(x, math.inf)
    return x


def pow10(e):
    """10**x for each double x of the sequence e, correctly rounded, as a
    float64 array: the same doubles on every machine. (numpy's power ufunc
    is not: on CPUs with AVX-512, numpy 1.24 evaluates it with SVML, whose
    last bits differ from libm's, so inputs drawn through it depended on
    the machine that drew them. Python's scalar 10.0**x is libm's pow.)
    At 160 bits, then rounded once: wrong only within 2**-100 relative of a
    midpoint between doubles."""
    import mpmath
    with mpmath.workprec(160):
        ten = mpmath.mpf(10)
        return np.array([float(ten ** mpmath.mpf(float(x))) for x in e])


def random_axes(rng):
    mode = int(rng.integers(0, 6))
    if mode <= 2:  # generic: each semi-axis log-uniform in [1e-2, 1e2]
        e = rng.uniform(-2.0, 2.0, 3)
    elif mode == 3:  # needle: one long, two short (aspect ratio ~1e4)
        e = np.array([rng.uniform(1.9, 2.0), rng.uniform(-2.0, -1.9),
                      rng.uniform(-2.0, -1.0)])
    elif mode == 4:  # disc: two long, one short
        e = np.array([rng.uniform(1.9, 2.0), rng.uniform(1.0, 2.0),
                      rng.uniform(-2.0, -1.9)])
    else:  # triaxial extreme
        e = np.array([rng.uniform(-2.0, -1.9), rng.uniform(-0.5, 0.5),
                      rng.uniform(1.9, 2.0)])
    return [float(x) for x in pow10(e[rng.permutation(3)])]


def random_ellipsoid(rng):
    axes = random_axes(rng)
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    return triaxial_exact(axes, rotation_from_quaternion(q))


def positive_definite_exact(q):
    m = [Fraction(x) for x in q]
    return (m[0] > 0 and m[0] * m[3] - m[1] * m[1] > 0
            and det6(m) > 0)


def generate_general(outdir, log):
    import mpmath
    t0 = time.time()
    rng = np.random.default_rng(GENERAL_SEED)
    n = GENERAL_N
    ndelta = len(GENERAL_DELTAS)
    per = (n - GENERAL_NUM_GENERIC) // ndelta
    assert GENERAL_NUM_GENERIC + per * ndelta == n
    r12 = np.empty((n, 3))
    q1 = np.empty((n, 6))
    q2 = np.empty((n, 6))
    MU2 = np.empty(n)
    LAM = np.empty(n)
    M1 = np.empty(n)
    kind = np.zeros(n, dtype=np.int32)
    delta = np.zeros(n)
    target = np.empty(n)
    stats = RootStats()
    for c in range(n):
        e1 = random_ellipsoid(rng)
        e2 = random_ellipsoid(rng)
        assert positive_definite_exact(e1) and positive_definite_exact(e2)
        u = rng.normal(size=3)
        u = [float(x) for x in u / np.linalg.norm(u)]
        if c < GENERAL_NUM_GENERIC:
            tgt = mpmath.mpf(10) ** mpmath.mpf(float(rng.uniform(-4.0, 4.0)))
            dl = 0.0
        else:
            dl = GENERAL_DELTAS[(c - GENERAL_NUM_GENERIC) // per]
            kind[c] = 1
            tgt = None
        pair = Pair(e1, e2)
        res0 = contact(pair, u, P_BITS, stats)
        with mpmath.workdps(120):
            mu0 = (mpmath.mpf(res0.mu2_num) / res0.mu2_den
                   * mpmath.ldexp(1, res0.mu2_exp))
            if tgt is None:
                tgt = 1 + mpmath.mpf(dl)
            s = mpmath.sqrt(tgt / mu0)
            r = [float(mpmath.mpf(x) * s) for x in u]
        res = contact(pair, r, P_BITS, stats)
        if kind[c] == 1:
            # rounding r12 to doubles moves mu^2 by up to ~1e-14 for these
            # ill-conditioned pairs: among the 27 neighbours of r (each
            # component -1, 0, +1 ulp) keep the one whose mu^2 - 1 is
            # nearest to delta (first one in this order on ties)
            best = (abs(res.mu2m1 - dl), r, res)
            for s0 in (-1, 0, 1):
                for s1 in (-1, 0, 1):
                    for s2 in (-1, 0, 1):
                        rr = [_ulp_step(x, st) for x, st in
                              zip(r, (s0, s1, s2))]
                        if rr == r:
                            continue
                        rs = contact(pair, rr, P_BITS, stats)
                        if abs(rs.mu2m1 - dl) < best[0]:
                            best = (abs(rs.mu2m1 - dl), rr, rs)
            _, r, res = best
        r12[c], q1[c], q2[c] = r, e1, e2
        MU2[c], LAM[c], M1[c] = res.mu2, res.lam, res.mu2m1
        delta[c] = dl
        target[c] = float(tgt)
        if (c + 1) % 500 == 0:
            log("  general pairs: %d/%d (%.0f s)" % (c + 1, n,
                                                     time.time() - t0))
    log("  " + stats.summary())
    # self-checks
    near = kind == 1
    dev = np.abs(M1[near] - delta[near])
    rel = dev / np.abs(delta[near])
    log("  near-tangent: max |MU2_MINUS_1 - delta| = %.3g, max relative "
        "%.3g (effect of rounding r12 to doubles); sign(MU2_MINUS_1) == "
        "sign(delta) in all %d cases" % (dev.max(), rel.max(), near.sum()))
    assert dev.max() < 0.5e-14
    assert np.all(np.sign(M1[near]) == np.sign(delta[near]))
    assert np.all((MU2[near] > 1) == (delta[near] > 0))
    tdev = np.abs(MU2 / target - 1).max()
    log("  max |MU2/target - 1| = %.3g (effect of rounding r12)" % tdev)
    assert tdev < 1e-13
    chk = np.random.default_rng(54321).permutation(n)
    for c in chk:
        pair = Pair(q1[c], q2[c])
        res = contact(pair, r12[c], P_CHECK)
        assert (res.mu2, res.lam, res.mu2m1) == (MU2[c], LAM[c], M1[c])
    log("  general pairs: all %d cases identical with %d fractional "
        "bits" % (n, P_CHECK))
    for c in chk[:300]:
        mu2, lam, m1 = contact_mp(r12[c], q1[c], q2[c], dps=100)
        assert (mu2, lam, m1) == (MU2[c], LAM[c], M1[c]), c
    log("  general pairs: 300 random cases identical with mpmath at 100 "
        "digits (MU2, LAMBDA, MU2_MINUS_1)")
    ratios = []
    for q in (q1, q2):
        for row in q:
            w = np.linalg.eigvalsh(np.array([[row[0], row[1], row[2]],
                                             [row[1], row[3], row[4]],
                                             [row[2], row[4], row[5]]]))
            ratios.append(math.sqrt(w[-1] / w[0]))
    log("  aspect ratios: max %.4g, median %.4g" % (max(ratios),
                                                     np.median(ratios)))
    data = dict(r12=r12, q1=q1, q2=q2, MU2=MU2, LAMBDA=LAM,
                MU2_MINUS_1=M1, kind=kind, delta=delta)
    recipe = (
        "pw85 general triaxial pairs, generated by data/gen_ref_data.py "
        "with numpy %s, np.random.default_rng(%d). N = %d cases. For each "
        "case: two ellipsoids, then a direction. Ellipsoid: mode = "
        "rng.integers(0, 6); semi-axes 10**e, e drawn uniformly (modes "
        "0-2: each e in [-2, 2]; 3 needle: [1.9,2],[-2,-1.9],[-2,-1]; 4 "
        "disc: [1.9,2],[1,2],[-2,-1.9]; 5 triaxial: [-2,-1.9],[-0.5,0.5],"
        "[1.9,2]) "
        "then permuted by rng.permutation(3); rotation from the unit "
        "quaternion rng.normal(size=4)/norm; Q = sum a_i^2 v_i v_i^T "
        "computed exactly from the doubles and rounded. Direction u = "
        "rng.normal(size=3)/norm. Cases 0..%d (kind 0): target mu^2 = "
        "10**rng.uniform(-4, 4); cases %d.. (kind 1, %d per delta, deltas "
        "%s in that order): target mu^2 = 1 + delta. r12 = u * sqrt(target "
        "/ mu0^2) computed at 120 digits (mu0^2 for r = u) and rounded to "
        "doubles; for kind 1 the 27 neighbours of r12 (each component moved "
        "by -1, 0, +1 ulp) are tried and the one giving mu^2 - 1 nearest to "
        "delta is kept. MU2, LAMBDA, MU2_MINUS_1 are correctly rounded for the "
        "stored doubles r12, q1, q2." % (
            np.__version__, GENERAL_SEED, n, GENERAL_NUM_GENERIC - 1,
            GENERAL_NUM_GENERIC, per, list(GENERAL_DELTAS)))
    path = os.path.join(outdir, GENERAL_FILE)
    write_h5(path, data, {k: None for k in data},
             {"description": recipe, "seed": GENERAL_SEED})
    log("wrote %s (%.0f s)" % (path, time.time() - t0))


# Finish pairs -------------------------------------------------------------------
#
# Inputs on which the last step of the search, the compensated finish
# (src/finish.cpp), decides the last bit of mu^2.  Candidate k is drawn from
# its own stream np.random.default_rng([FINISH_SEED, k]) by finish_candidate;
# FINISH_CASES lists the candidates kept, in increasing order.  They were
# chosen (data/README.md) as the candidates on which at least one of three
# mutants of the library (M_gain, M_carry, M_step) returns a mu^2 different
# from the unmutated library's, which is correctly rounded on all of them.
# Only the choice of indices used the library; every input is regenerated
# here from the seed, and every reference is computed by contact().

FINISH_SEED = 1207
FINISH_FILE = "pw85_finish_pairs.h5"
FINISH_SCANNED = 4000  # candidates 0 .. FINISH_SCANNED - 1 were tried
FINISH_CASES = (
    6, 9, 10, 28, 34, 57, 65, 66, 71, 96, 104, 125, 128, 130, 135, 136,
    137, 148, 149, 154, 169, 170, 171, 174, 177, 193, 198, 213, 223, 225,
    228, 234, 236, 240, 242, 243, 260, 284, 295, 308, 313, 316, 333, 337,
    342, 350, 356, 359, 362, 363, 366, 377, 378, 387, 389, 393, 403, 418,
    433, 437, 440, 473, 480, 487, 491, 520, 526, 532, 534, 539, 549, 557,
    566, 580, 584, 586, 600, 610, 613, 638, 653, 661, 662, 667, 668, 669,
    674, 686, 687, 688, 698, 699, 709, 721, 730, 731, 748, 754, 758, 764,
    771, 775, 785, 788, 794, 798, 808, 813, 820, 825, 828, 835, 837, 838,
    842, 848, 849, 865, 871, 876, 877, 885, 887, 888, 889, 893, 898, 905,
    906, 928, 931, 933, 936, 943, 958, 971, 997, 1011, 1012, 1023, 1038,
    1057, 1059, 1060, 1067, 1076, 1080, 1097, 1111, 1117, 1130, 1151, 1154,
    1163, 1176, 1185, 1193, 1208, 1228, 1229, 1230, 1232, 1237, 1238, 1259,
    1262, 1289, 1293, 1295, 1300, 1308, 1309, 1316, 1326, 1332, 1340, 1344,
    1370, 1373, 1380, 1381, 1384, 1389, 1395, 1399, 1402, 1420, 1430, 1435,
    1437, 1448, 1465, 1467, 1471, 1476, 1485, 1501, 1507, 1510, 1512, 1516,
    1517, 1519, 1538, 1545, 1552, 1553, 1563, 1567, 1585, 1586, 1599, 1601,
    1604, 1607, 1617, 1622, 1625, 1626, 1638, 1645, 1657, 1686, 1688, 1704,
    1720, 1721, 1732, 1736, 1737, 1739, 1767, 1774, 1790, 1798, 1836, 1843,
    1849, 1862, 1864, 1869, 1870, 1872, 1875, 1885, 1889, 1890, 1914, 1922,
    1923, 1932, 1936, 1946, 1948, 1956, 1979, 1981, 1985, 1991, 1993, 1994,
    1996, 2004, 2005, 2021, 2058, 2060, 2061, 2063, 2088, 2092, 2093, 2094,
    2103, 2104, 2119, 2123, 2133, 2141, 2143, 2144, 2148, 2151, 2152, 2156,
    2164, 2170, 2178, 2182, 2216, 2225, 2228, 2238, 2242, 2251, 2256, 2258,
    2274, 2278, 2284, 2285, 2289, 2291, 2303, 2311, 2319, 2328, 2334, 2337,
    2345, 2350, 2360, 2362, 2371, 2375, 2383, 2387, 2407, 2415, 2417, 2422,
    2424, 2430, 2431, 2438, 2439, 2449, 2454, 2456, 2464, 2466, 2481, 2486,
    2500, 2509, 2511, 2512, 2516, 2526, 2534, 2562, 2567, 2568, 2570, 2581,
    2584, 2585, 2600, 2608, 2620, 2621, 2640, 2642, 2682, 2688, 2690, 2695,
    2699, 2718, 2746, 2747, 2748, 2763, 2776, 2779, 2784, 2803, 2805, 2806,
    2815, 2816, 2824, 2826, 2833, 2845, 2853, 2857, 2864, 2868, 2874, 2878,
    2879, 2885, 2888, 2905, 2923, 2930, 2932, 2945, 2968, 2978, 2982, 2983,
    2989, 3009, 3015, 3017, 3023, 3025, 3026, 3027, 3048, 3051, 3052, 3053,
    3054, 3058, 3061, 3065, 3067, 3070, 3078, 3083, 3086, 3095, 3100, 3105,
    3125, 3127, 3149, 3150, 3158, 3159, 3170, 3174, 3184, 3186, 3188, 3191,
    3192, 3205, 3224, 3228, 3231, 3233, 3239, 3240, 3242, 3244, 3246, 3275,
    3282, 3285, 3293, 3297, 3307, 3309, 3340, 3346, 3352, 3358, 3366, 3372,
    3373, 3375, 3383, 3384, 3392, 3397, 3398, 3413, 3417, 3419, 3425, 3432,
    3440, 3441, 3460, 3468, 3472, 3476, 3479, 3484, 3501, 3503, 3505, 3509,
    3515, 3525, 3534, 3539, 3540, 3543, 3544, 3569, 3574, 3588, 3597, 3619,
    3652, 3656, 3657, 3675, 3686, 3688, 3689, 3700, 3702, 3704, 3706, 3713,
    3715, 3729, 3736, 3749, 3753, 3754, 3758, 3760, 3767, 3771, 3774, 3776,
    3788, 3808, 3822, 3823, 3835, 3843, 3844, 3845, 3848, 3853, 3855, 3868,
    3872, 3910, 3913, 3917, 3936, 3949, 3961, 3975, 3992, 3996, 3997,)


def _quaternion_product(a, b):
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    return [w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
            w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
            w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
            w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2]


def _finish_axes(rng, centre, log_ar):
    """Semi-axes 10**e, aspect ratio 10**log_ar about 10**centre."""
    lo, hi = centre - log_ar / 2, centre + log_ar / 2
    shape = int(rng.integers(0, 3))
    if shape == 0:  # needle
        e = [hi, lo, lo + rng.uniform(0.0, 1.0)]
    elif shape == 1:  # disc
        e = [hi, hi - rng.uniform(0.0, 1.0), lo]
    else:  # triaxial
        e = [hi, rng.uniform(lo, hi), lo]
    return [float(x) for x in pow10(np.array(e)[rng.permutation(3)])]


def finish_candidate(k):
    """Candidate k: (q1, q2, u, target, delta, family).

    family 0: the second rotation is the first times a small rotation (angle
    10**U(-8, -1) about a random axis), so Q(lambda) keeps the thin
    directions both share and is ill-conditioned; 1: random rotations, the
    second ellipsoid 10**U(1.5, 3) times larger or smaller (lambda* near 0
    or 1); 2: random rotations; in families 0-2 the aspect ratio of each
    ellipsoid is 10**U(2, 6); 3: aspect ratios 10**U(0, 4), random
    rotations, as in the general pairs.  Sizes 10**U(-1, 1) about which the
    axes spread.  Target mu^2: 10**U(-2, 2) (delta = 0) or 1 + delta with
    delta = +-10**U(-14, -3)."""
    import mpmath
    rng = np.random.default_rng([FINISH_SEED, k])
    family = int(rng.integers(0, 4))
    rot1 = rng.normal(size=4)
    rot1 /= np.linalg.norm(rot1)
    if family == 0:
        axis = rng.normal(size=3)
        axis /= np.linalg.norm(axis)
        angle = 10.0**rng.uniform(-8.0, -1.0)
        rot2 = _quaternion_product(
            rot1, [math.cos(angle / 2)] + [math.sin(angle / 2) * x
                                           for x in axis])
    else:
        rot2 = rng.normal(size=4)
        rot2 /= np.linalg.norm(rot2)
    qs = []
    for i, rot in enumerate((rot1, rot2)):
        log_ar = rng.uniform(2.0, 6.0) if family != 3 else \
            rng.uniform(0.0, 4.0)
        centre = rng.uniform(-1.0, 1.0)
        if family == 1 and i == 1:
            centre += rng.choice([-1, 1]) * rng.uniform(1.5, 3.0)
        axes = _finish_axes(rng, centre, log_ar)
        qs.append(triaxial_exact(axes, rotation_from_quaternion(rot)))
    u = rng.normal(size=3)
    u = [float(x) for x in u / np.linalg.norm(u)]
    if rng.uniform() < 0.5:
        delta = 0.0
        target = mpmath.mpf(10) ** mpmath.mpf(float(rng.uniform(-2.0, 2.0)))
    else:
        delta = float(rng.choice([-1, 1]) * 10.0**rng.uniform(-14.0, -3.0))
        target = 1 + mpmath.mpf(delta)
    return qs[0], qs[1], u, target, delta, family


def finish_inputs(k, stats=None):
    """(q1, q2, r12, delta, family) of candidate k: r12 = u*sqrt(target/mu0^2)
    at 120 digits (mu0^2 for r = u, by contact()), rounded to doubles."""
    import mpmath
    q1, q2, u, target, delta, family = finish_candidate(k)
    if not (positive_definite_exact(q1) and positive_definite_exact(q2)):
        return None
    res0 = contact(Pair(q1, q2), u, P_BITS, stats)
    with mpmath.workdps(120):
        mu0 = (mpmath.mpf(res0.mu2_num) / res0.mu2_den
               * mpmath.ldexp(1, res0.mu2_exp))
        s = mpmath.sqrt(target / mu0)
        r = [float(mpmath.mpf(x) * s) for x in u]
    return q1, q2, r, delta, family


def generate_finish(outdir, log):
    """pw85_finish_pairs.h5: the FINISH_CASES candidates, general pairs'
    layout (data/README.md)."""
    t0 = time.time()
    n = len(FINISH_CASES)
    assert n > 0 and list(FINISH_CASES) == sorted(set(FINISH_CASES))
    r12 = np.empty((n, 3))
    q1 = np.empty((n, 6))
    q2 = np.empty((n, 6))
    MU2 = np.empty(n)
    LAM = np.empty(n)
    M1 = np.empty(n)
    kind = np.zeros(n, dtype=np.int32)
    delta = np.zeros(n)
    family = np.empty(n, dtype=np.int32)
    stats = RootStats()
    for c, k in enumerate(FINISH_CASES):
        inputs = finish_inputs(k, stats)
        assert inputs is not None, "finish candidate %d not positive " \
            "definite" % k
        e1, e2, r, dl, fam = inputs
        res = contact(Pair(e1, e2), r, P_BITS, stats)
        r12[c], q1[c], q2[c] = r, e1, e2
        MU2[c], LAM[c], M1[c] = res.mu2, res.lam, res.mu2m1
        kind[c], delta[c], family[c] = dl != 0.0, dl, fam
    log("  " + stats.summary())
    # self-checks: every case at higher precision and with mpmath
    for c in range(n):
        res = contact(Pair(q1[c], q2[c]), r12[c], P_CHECK)
        assert (res.mu2, res.lam, res.mu2m1) == (MU2[c], LAM[c], M1[c]), c
        mu2, lam, m1 = contact_mp(r12[c], q1[c], q2[c], dps=100)
        assert (mu2, lam, m1) == (MU2[c], LAM[c], M1[c]), c
    log("  finish pairs: all %d cases identical with %d fractional bits "
        "and with mpmath at 100 digits (MU2, LAMBDA, MU2_MINUS_1)"
        % (n, P_CHECK))
    near = kind == 1
    log("  %d cases, families %s, %d near-tangent (max |MU2_MINUS_1 - "
        "delta| = %.3g), MU2 in [%.3g, %.3g], LAMBDA in [%.3g, 1-%.3g]"
        % (n, np.bincount(family, minlength=4).tolist(), near.sum(),
           np.abs(M1[near] - delta[near]).max(), MU2.min(), MU2.max(),
           LAM.min(), 1 - LAM.max()))
    data = dict(r12=r12, q1=q1, q2=q2, MU2=MU2, LAMBDA=LAM,
                MU2_MINUS_1=M1, kind=kind, delta=delta)
    recipe = (
        "pw85 finish pairs, generated by data/gen_ref_data.py with numpy "
        "%s. Case c is candidate k = attribute candidates[c], drawn from "
        "np.random.default_rng([%d, k]) by finish_candidate(k) (family in "
        "attribute family), with r12 = u * sqrt(target / mu0^2) at 120 "
        "digits rounded to doubles. The candidates were chosen as those "
        "among the first %d on which a mutant of the library's compensated "
        "finish (M_gain: no quadratic-model gain; M_carry: no f_lo carry; "
        "M_step: no compensated step) returned another mu^2 than the "
        "unmutated library (data/README.md). kind 1: target 1 + delta; "
        "kind 0: target 10**U(-2, 2). MU2, LAMBDA, MU2_MINUS_1 are "
        "correctly rounded for the stored doubles r12, q1, q2." % (
            np.__version__, FINISH_SEED, FINISH_SCANNED))
    path = os.path.join(outdir, FINISH_FILE)
    write_h5(path, data, {k: None for k in data},
             {"description": recipe, "seed": FINISH_SEED,
              "candidates": np.array(FINISH_CASES, dtype=np.int64),
              "family": family})
    log("wrote %s (%.0f s)" % (path, time.time() - t0))


def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--outdir", default=here,
                    help="output directory (default: the script's folder)")
    ap.add_argument("--jobs", type=int, default=2,
                    help="worker processes (default 2)")
    ap.add_argument("--only", choices=("ref", "general", "finish"),
                    default=None, help="generate only one of the files")
    args = ap.parse_args(argv)
    t0 = time.time()

    def log(msg):
        print(msg, flush=True)

    os.makedirs(args.outdir, exist_ok=True)
    if args.only in (None, "ref"):
        generate_ref(args.outdir, max(args.jobs, 1), log)
    if args.only in (None, "general"):
        generate_general(args.outdir, log)
    if args.only in (None, "finish"):
        generate_finish(args.outdir, log)
    for name in (REF_FILE, GENERAL_FILE, FINISH_FILE):
        p = os.path.join(args.outdir, name)
        if os.path.exists(p):
            log("%s  %s  (%d bytes)" % (sha256(p), name, os.path.getsize(p)))
    log("total run time: %.1f s" % (time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
