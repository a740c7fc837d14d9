#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate data/pw85_hard_pairs.h5, the hard set of issue 13 (item 4).

Seeded pairs (r12, q1, q2) in named classes that stress the contact function
inside its documented domain (cond(Q1), cond(Q2) < 1e16): aspect ratios
1e4-1e7, cond(Q) 1e12 to just below 1e16 from rotations and from bad scaling
of the stored entries, end-on needles, nearly parallel needles and nearly
coplanar discs, lambda* within 1e-20 ... 1e-3 of 0 or 1, tiny |r12|, near
tangency on both sides, extreme length scales, and the reproducers quoted in
issue 13.  The layout and the recipe of each class are in data/README.md.

The references reuse the machinery of gen_ref_data.py (imported, not copied):
contact() gives MU2, LAMBDA, MU2_MINUS_1 correctly rounded for the stored
doubles from exact integer arithmetic (a certified enclosure of lambda* about
1e-96 wide, a certified enclosure of mu^2 by concavity, Descartes' rule for a
single root of c = numerator of f' in (0, 1)).  On top of that, this script

* certifies explicitly, with exact integer signs of c, that f' changes sign
  across lambda* +- 1e-50 min(lambda*, 1 - lambda*) (lambda* from an mpmath
  root of the exact c at 150 digits, itself checked against LAMBDA);
* re-checks c(0) > 0 > c(1) and the single sign variation of Descartes on
  (0, 1), so that the maximum is the global one on [0, 1] (f' = c/b^2 with
  b = det Q(lambda) > 0 has a single sign change);
* checks every stored form positive definite in exact rational arithmetic
  (leading minors, Fractions) and computes cond(Q) = lambda_max/lambda_min
  at 80 digits (mpmath.eigsy), requiring cond < 1e16;
* recomputes every pair by the independent mpmath route (contact_mp, LU
  solves at 100 digits, Newton on g of seed ch. 5) and reports agreement.

Usage (from the repository root):
    /usr/bin/python3 data/gen_hard_set.py [--outdir DIR] [--jobs N]
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
import gen_ref_data as gen  # noqa: E402

HARD_SEED = 1301
HARD_FILE = "pw85_hard_pairs.h5"
COND_MAX = 1e16
CERT_REL = Fraction(1, 10**50)  # f' certified to change sign within this
CERT_BITS = 600                 # fractional bits of the certificate points
ROOT_DPS = 150                  # mpmath digits of the root used to certify
COND_DPS = 80                   # mpmath digits of the eigenvalues
MP_DPS = 100                    # digits of the independent mpmath route

# The classes, in file order: (name, count).  Each record k of class i is
# drawn from np.random.default_rng([HARD_SEED, i, k]); rejected candidates
# are skipped and the first `count` accepted ones kept, in k order.
CLASSES = (
    ("reproducers", 3),
    ("needles", 200),
    ("discs", 200),
    ("triaxial", 200),
    ("cond_rotation", 200),
    ("cond_scaling", 200),
    ("end_on_needles", 200),
    ("parallel_needles_side", 200),
    ("parallel_needles_end", 200),
    ("coplanar_discs_face", 200),
    ("coplanar_discs_edge", 200),
    ("lambda_end_well", 200),
    ("lambda_end_ill", 200),
    ("tiny_r12", 200),
    ("near_tangent", 200),
    ("near_tangent_ill", 200),
    ("extreme_scales", 100),
)
CLASS_NAMES = tuple(n for n, _ in CLASSES)

# Issue 13, "Why": the three inputs quoted as C99 hex floats (r12; q1; q2).
REPRODUCERS = (
    # pw85_overlap answers -1 for disjoint ellipsoids (mu^2 = 1 + 27 ulps)
    (("0x1.72cfad234bec1p+29", "0", "0x1.72cfad2104ec1p+29"),
     ("0x1.0b4781cf03ae2p+97", "-0x1.b6cee94939e22p+98",
      "0x1.61ca1196086b6p+98", "0x1.683763d7d7a13p+100",
      "-0x1.226cc6aacc6d9p+100", "0x1.d44f990e1a85cp+99"),
     ("0x1.0e21523f0f2b8p+42", "-0x1.30f88815e729ep+39",
      "0x1.19b59cd2c576p+40", "0x1.9b24847dfbe45p+41",
      "-0x1.0272b18fa3c17p+39", "0x1.f154f8f494c28p+41")),
    # lambda* = 6.4e-9 with an ill-conditioned q2: mu^2 off by 3e-2 relative
    (("-0x1.c15fcb7d782aep-18", "-0", "-0"),
     ("0x1.d7e7b461ce539p-103", "0", "0", "0x1.d7e7b461ce539p-103", "0",
      "0x1.5c763b357216ap-66"),
     ("0x1.67bf96dbacf68p+16", "0x1.5ece74b1d2e12p+19",
      "-0x1.9ca4c3e53ab15p+16", "0x1.561638a22fe66p+22",
      "-0x1.92630d2e7a2f1p+19", "0x1.d950f410f0759p+16")),
    # lambda* = 1 - 4.6e-21, not representable, well-conditioned forms
    (("-0x1.abe93cb113313p+53", "0x1.4846d31119745p+53",
      "-0x1.0266beac794ffp+53"),
     ("0x1.e3ba3d3e7bb18p+111", "0x1.3a81af22885e3p+113",
      "-0x1.121d442fa2fe7p+112", "0x1.e3d1b09a68e01p+114",
      "-0x1.88e562694ad14p+113", "0x1.5a2415c51c504p+112"),
     ("0x1.1fa79f99f1ae6p-27", "-0x1.0c0ba45ea3d27p-28",
      "-0x1.320bb27444539p-29", "0x1.35d7734c3701cp-28",
      "-0x1.ed10ba459858dp-29", "0x1.2c78d0cfbbb5fp-27")),
)


def _hex(v):
    return float.fromhex(v)


# Building blocks ---------------------------------------------------------------


def unit(rng, n):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def axes_of(rng, shape, log_ar, centre):
    """Semi-axes 10**e with aspect ratio 10**log_ar about 10**centre, in the
    order (long, middle, short) before the permutation; shape 0 needle (two
    short axes, the second up to 10x longer), 1 disc (two long axes), 2
    triaxial (middle axis log-uniform in between)."""
    lo, hi = centre - log_ar / 2, centre + log_ar / 2
    if shape == 0:
        e = [hi, lo + rng.uniform(0.0, min(1.0, log_ar)), lo]
    elif shape == 1:
        e = [hi, hi - rng.uniform(0.0, min(1.0, log_ar)), lo]
    else:
        e = [hi, rng.uniform(lo, hi), lo]
    return [float(x) for x in gen.pow10(e)]


def form(axes, quat):
    """Q = sum a_i^2 v_i v_i^T, v_i = columns of the rotation of quat
    (exact from the doubles, rounded once: gen_ref_data.triaxial_exact)."""
    return gen.triaxial_exact(axes, gen.rotation_from_quaternion(quat))


def random_form(rng, shape, log_ar, centre, perm=True):
    axes = axes_of(rng, shape, log_ar, centre)
    if perm:
        axes = [axes[i] for i in rng.permutation(3)]
    return form(axes, unit(rng, 4))


def small_rotation(rng, quat, log_angle):
    """quat times a rotation of angle 10**log_angle about a random axis."""
    axis = unit(rng, 3)
    angle = 10.0**log_angle
    q = gen._quaternion_product(
        list(quat), [math.cos(angle / 2)] + [math.sin(angle / 2) * x
                                             for x in axis])
    return np.array(q) / np.linalg.norm(q)


def perpendicular(rng, v):
    """A random unit vector perpendicular to the unit vector v."""
    w = unit(rng, 3)
    w = w - np.dot(w, v) * v
    return w / np.linalg.norm(w)


def tilt(rng, v, angle):
    """The unit vector at the given angle from v, in a random plane."""
    w = perpendicular(rng, v)
    return math.cos(angle) * v + math.sin(angle) * w


def scale_form(q, d):
    """D Q D for the stored doubles q and d = diag(D), exact, rounded once."""
    qf = [Fraction(x) for x in q]
    df = [Fraction(float(x)) for x in d]
    idx = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))
    return gen.sym_from_exact([qf[k] * df[i] * df[j]
                               for k, (i, j) in enumerate(idx)])


def cond_mp(q):
    """cond2(Q) = lambda_max / lambda_min at COND_DPS digits (a float), or
    inf when the stored form is not positive definite in exact arithmetic."""
    import mpmath
    if not gen.positive_definite_exact(q):
        return math.inf
    with mpmath.workdps(COND_DPS):
        m = mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                           [q[2], q[4], q[5]]])
        ev = mpmath.eigsy(m, eigvals_only=True)
        ev = sorted(ev[i] for i in range(3))
        if ev[0] <= 0:
            raise AssertionError("exact minors positive, eigenvalue <= 0")
        return float(ev[2] / ev[0])


def mu2_exact_mpf(res):
    import mpmath
    return mpmath.mpf(res.mu2_num) / res.mu2_den * mpmath.ldexp(1,
                                                                res.mu2_exp)


def scale_to(pair, u, target):
    """r12 = u sqrt(target / mu0^2) at 120 digits, rounded to doubles (mu0^2
    for r = u by the exact route); target an mpf."""
    import mpmath
    res0 = gen.contact(pair, list(u))
    with mpmath.workdps(120):
        s = mpmath.sqrt(target / mu2_exact_mpf(res0))
        return [float(mpmath.mpf(float(x)) * s) for x in u]


def nearest_neighbour(pair, r, delta):
    """Among r and its 26 neighbours (each component -1, 0, +1 ulp), the one
    whose mu^2 - 1 is nearest to delta (first in this order on ties), as in
    gen_ref_data.generate_general."""
    best = None
    for s0 in (-1, 0, 1):
        for s1 in (-1, 0, 1):
            for s2 in (-1, 0, 1):
                rr = [gen._ulp_step(x, st) for x, st in zip(r, (s0, s1, s2))]
                res = gen.contact(pair, rr)
                d = abs(Fraction(res.mu2m1) - Fraction(delta))
                if best is None or d < best[0]:
                    best = (d, rr)
    return best[1]


def generic_target(rng):
    import mpmath
    return mpmath.mpf(10) ** mpmath.mpf(float(rng.uniform(-2.0, 2.0)))


# The classes --------------------------------------------------------------------
#
# Each maker returns (r12, q1, q2, spec) where spec holds what the acceptance
# test needs: "cond" (lo, hi) bounds on max(cond1, cond2) or per form,
# "lam_end" (lo, hi) bounds on min(lambda*, 1 - lambda*), "delta" for near
# tangency.


def make_reproducer(rng, k):
    r, q1, q2 = REPRODUCERS[k]
    return [_hex(x) for x in r], [_hex(x) for x in q1], \
        [_hex(x) for x in q2], {}


def _aspect_class(shape):
    def make(rng, k):
        q1 = random_form(rng, shape, rng.uniform(4.0, 7.0),
                         rng.uniform(-1.0, 1.0))
        q2 = random_form(rng, int(rng.integers(0, 3)), rng.uniform(0.0, 7.0),
                         rng.uniform(-1.0, 1.0))
        if rng.uniform() < 0.5:
            q1, q2 = q2, q1
        r = scale_to(gen.Pair(q1, q2), unit(rng, 3), generic_target(rng))
        return r, q1, q2, {}
    return make


def _ill_form(rng, how):
    """A form of cond 10**U(12, 16) (before rounding): how = 'rotation' (axes
    of aspect ratio 10**U(6, 8), random rotation) or 'scaling' (D Q D, Q of
    aspect ratio 10**U(0, 1), D of spread 10**U(6, 8), no power of 2)."""
    if how == "rotation":
        return random_form(rng, int(rng.integers(0, 3)),
                           rng.uniform(6.0, 8.0), rng.uniform(-1.0, 1.0))
    q = random_form(rng, 2, rng.uniform(0.0, 1.0), 0.0)
    spread = rng.uniform(6.0, 8.0)
    o = rng.uniform(-3.0, 3.0)
    e = np.array([o, o + spread, o + rng.uniform(0.0, spread)])
    return scale_form(q, gen.pow10(e[rng.permutation(3)]))


def _cond_class(how):
    def make(rng, k):
        q1 = _ill_form(rng, how)
        if rng.uniform() < 0.5:
            q2 = _ill_form(rng, how)
        else:
            q2 = random_form(rng, int(rng.integers(0, 3)),
                             rng.uniform(0.0, 2.0), rng.uniform(-1.0, 1.0))
        if rng.uniform() < 0.5:
            q1, q2 = q2, q1
        r = scale_to(gen.Pair(q1, q2), unit(rng, 3), generic_target(rng))
        return r, q1, q2, {"cond_max": (1e12, COND_MAX)}
    return make


def make_end_on(rng, k):
    quat = unit(rng, 4)
    rot = gen.rotation_from_quaternion(quat)
    axes = axes_of(rng, 0, rng.uniform(4.0, 7.0), rng.uniform(-1.0, 1.0))
    q1 = form(axes, quat)  # long axis = first column of rot
    q2 = random_form(rng, int(rng.integers(0, 3)), rng.uniform(0.0, 7.0),
                     rng.uniform(-1.0, 1.0))
    u = tilt(rng, rot[:, 0], 10.0**rng.uniform(-12.0, -2.0))
    if rng.uniform() < 0.5:
        q1, q2 = q2, q1
    r = scale_to(gen.Pair(q1, q2), u, generic_target(rng))
    return r, q1, q2, {}


def _pair_class(shape, along):
    """Two needles (shape 0) or discs (shape 1), the second rotation the first
    times a rotation of angle 10**U(-10, -2); r12 along (along = True) or
    perpendicular to (False) the first column of the rotation (the needle's
    axis, the disc's normal), tilted by 10**U(-10, -2) (along) or within
    +-0.1 rad (perpendicular)."""
    def make(rng, k):
        quat1 = unit(rng, 4)
        rot = gen.rotation_from_quaternion(quat1)
        quat2 = small_rotation(rng, quat1, rng.uniform(-10.0, -2.0))
        qs = []
        for quat in (quat1, quat2):
            axes = axes_of(rng, shape, rng.uniform(4.0, 7.0),
                           rng.uniform(-1.0, 1.0))
            if shape == 1:  # disc: the short axis first (the normal)
                axes = [axes[2], axes[0], axes[1]]
            qs.append(form(axes, quat))
        v = rot[:, 0]
        if along:
            u = tilt(rng, v, 10.0**rng.uniform(-10.0, -2.0))
        else:
            u = tilt(rng, perpendicular(rng, v),
                     rng.uniform(-0.1, 0.1))
        r = scale_to(gen.Pair(qs[0], qs[1]), u, generic_target(rng))
        return r, qs[0], qs[1], {}
    return make


def _lambda_end_class(ill):
    """Sizes 10**U(3, 19.8) apart (Q up to ~1e40 apart): lambda* within
    1e-20 ... 1e-3 of 0 or 1.  Well-conditioned forms (aspect ratio
    10**U(0, 2)) or ill-conditioned ones (one or both of aspect ratio
    10**U(5, 8), cond(Q) up to just below 1e16)."""
    def make(rng, k):
        ratio = rng.uniform(3.0, 19.8)
        centre = rng.uniform(-10.0, 10.0)
        centres = [centre, centre - ratio]
        if ill:
            which = int(rng.integers(0, 3))  # 0: small ill, 1: big, 2: both
            ars = [rng.uniform(5.0, 8.0) if (which == 2 or which == i) else
                   rng.uniform(0.0, 2.0) for i in (1, 0)]
        else:
            ars = [rng.uniform(0.0, 2.0), rng.uniform(0.0, 2.0)]
        qs = [random_form(rng, int(rng.integers(0, 3)), ars[i], centres[i])
              for i in (0, 1)]
        if rng.uniform() < 0.5:
            qs.reverse()
        r = scale_to(gen.Pair(qs[0], qs[1]), unit(rng, 3),
                     generic_target(rng))
        spec = {"lam_end": (1e-20, 1e-3)}
        if ill:
            spec["cond_max"] = (1e10, COND_MAX)
        return r, qs[0], qs[1], spec
    return make


def make_tiny_r12(rng, k):
    import mpmath
    q1 = random_form(rng, int(rng.integers(0, 3)), rng.uniform(0.0, 6.0),
                     rng.uniform(-2.0, 2.0))
    q2 = random_form(rng, int(rng.integers(0, 3)), rng.uniform(0.0, 6.0),
                     rng.uniform(-2.0, 2.0))
    t = rng.uniform(8.0, 100.0)  # |r12| ~ 10**-t of the sizes: mu ~ 10**-t
    target = mpmath.mpf(10) ** mpmath.mpf(-2.0 * t)
    r = scale_to(gen.Pair(q1, q2), unit(rng, 3), target)
    return r, q1, q2, {}


def _near_tangent_class(ill):
    """mu^2 = 1 + delta, delta = +-10**U(-15, -6); moderately conditioned
    forms (aspect ratio 10**U(0, 4)) or one or both of cond 1e12-1e16 (from
    rotation or scaling).  r12 is the neighbour (+-1 ulp per component) whose
    mu^2 - 1 is nearest to delta; the candidate is kept only if mu^2 - 1 has
    the sign of delta and |mu^2 - 1| is in [0.5e-15, 2e-6]."""
    def make(rng, k):
        import mpmath
        if ill:
            how = ("rotation", "scaling")[int(rng.integers(0, 2))]
            q1 = _ill_form(rng, how)
            q2 = _ill_form(rng, how) if rng.uniform() < 0.5 else \
                random_form(rng, int(rng.integers(0, 3)),
                            rng.uniform(0.0, 4.0), rng.uniform(-1.0, 1.0))
            if rng.uniform() < 0.5:
                q1, q2 = q2, q1
        else:
            q1, q2 = (random_form(rng, int(rng.integers(0, 3)),
                                  rng.uniform(0.0, 4.0),
                                  rng.uniform(-1.0, 1.0)) for _ in range(2))
        delta = float(rng.choice([-1.0, 1.0]) * 10.0**rng.uniform(-15.0, -6.0))
        pair = gen.Pair(q1, q2)
        r = scale_to(pair, unit(rng, 3), 1 + mpmath.mpf(delta))
        r = nearest_neighbour(pair, r, delta)
        spec = {"delta": delta}
        if ill:
            spec["cond_max"] = (1e12, COND_MAX)
        return r, q1, q2, spec
    return make


def make_extreme_scales(rng, k):
    """Both forms and r12 scaled by 2**+-500 or 10**+-150 (lengths): the
    general pairs' ellipsoids (aspect ratio 10**U(0, 4)) at the ends of the
    exponent range."""
    s = [2.0**500, 2.0**-500, 1e150, 1e-150][int(rng.integers(0, 4))]
    q1, q2 = (random_form(rng, int(rng.integers(0, 3)),
                          rng.uniform(0.0, 4.0), rng.uniform(-1.0, 1.0))
              for _ in range(2))
    q1 = scale_form(q1, [s] * 3)
    q2 = scale_form(q2, [s] * 3)
    u = [float(x) * s for x in unit(rng, 3)]
    r = scale_to(gen.Pair(q1, q2), u, generic_target(rng))
    return r, q1, q2, {}


MAKERS = {
    "reproducers": make_reproducer,
    "needles": _aspect_class(0),
    "discs": _aspect_class(1),
    "triaxial": _aspect_class(2),
    "cond_rotation": _cond_class("rotation"),
    "cond_scaling": _cond_class("scaling"),
    "end_on_needles": make_end_on,
    "parallel_needles_side": _pair_class(0, False),
    "parallel_needles_end": _pair_class(0, True),
    "coplanar_discs_face": _pair_class(1, True),
    "coplanar_discs_edge": _pair_class(1, False),
    "lambda_end_well": _lambda_end_class(False),
    "lambda_end_ill": _lambda_end_class(True),
    "tiny_r12": make_tiny_r12,
    "near_tangent": _near_tangent_class(False),
    "near_tangent_ill": _near_tangent_class(True),
    "extreme_scales": make_extreme_scales,
}


# Certification --------------------------------------------------------------------


def root_mp(c, dps):
    """The root of the integer polynomial c in (0, 1), at dps digits, by a
    safeguarded Newton iteration (c(0) > 0 > c(1))."""
    import mpmath
    with mpmath.workdps(dps + 20):
        cf = [mpmath.mpf(x) for x in c]
        dcf = [i * cf[i] for i in range(1, 7)]

        def ev(p, x):
            v = p[-1]
            for y in reversed(p[:-1]):
                v = v * x + y
            return v
        lo, hi = mpmath.mpf(0), mpmath.mpf(1)
        x = mpmath.mpf(0.5)
        tol = mpmath.mpf(10) ** (-dps)
        for _ in range(20000):
            v = ev(cf, x)
            if v > 0:
                lo = x
            elif v < 0:
                hi = x
            else:
                return x
            d = ev(dcf, x)
            xn = x - v / d if d != 0 else lo - 1
            if not (lo < xn < hi):
                xn = (lo + hi) / 2
            if abs(xn - x) <= tol * min(x, 1 - x) or \
                    hi - lo <= tol * min(lo, 1 - hi):
                return xn
            x = xn
        raise AssertionError("root_mp did not converge")


def certify(pair, r, res):
    """Exact certificate of the maximiser; returns (lambda*, f''(lambda*)) as
    mpf at ROOT_DPS digits.  Raises AssertionError on failure."""
    import mpmath
    a, sr = pair.a_coeffs(r)
    c = gen.c_coeffs(list(a), list(pair.b))
    # global maximum: c(0) > 0 > c(1) and one Descartes sign variation on
    # (0, 1), i.e. exactly one root of c = b^2 f' 2^-e in (0, 1)
    if not (c[0] > 0 and sum(c) < 0 and gen.descartes_01(c) == 1):
        raise AssertionError("c: no single sign change on (0, 1)")
    for dps in (ROOT_DPS, 2 * ROOT_DPS, 4 * ROOT_DPS):
        lam = root_mp(c, dps)
        with mpmath.workdps(dps + 20):
            m = min(lam, 1 - lam)
            if not m > 0:
                raise AssertionError("lambda* at an end")
            one = 1 << CERT_BITS
            h = m / 10**50
            xl = int(mpmath.floor((lam - h) * one))
            xh = int(mpmath.ceil((lam + h) * one))
        # the certificate points are within lambda* +- 1e-50 m (+ 2^-600)
        if gen.c_eval(c, xl, CERT_BITS) > 0 > gen.c_eval(c, xh, CERT_BITS):
            break
    else:
        raise AssertionError("f' sign change not certified")
    with mpmath.workdps(ROOT_DPS):
        if float(lam) != res.lam:
            raise AssertionError("LAMBDA differs from the mpmath root")
        e = pair.sq - 2 * sr

        def ev(p, x):
            v = mpmath.mpf(0)
            for y in reversed(p):
                v = v * x + y
            return v
        bl = ev(list(pair.b), lam)
        fpp = ev([i * c[i] for i in range(1, 7)], lam) / bl**2 * \
            mpmath.ldexp(1, e)  # f'' = c'/b^2 2^e where c = 0
        return lam, fpp


class Rejected(Exception):
    pass


def candidate(task):
    """Build, check and compute candidate k of class ci; returns a dict or a
    string naming the reason of the rejection."""
    import mpmath
    ci, k = task
    name = CLASS_NAMES[ci]
    rng = np.random.default_rng([HARD_SEED, ci, k])
    try:
        r, q1, q2, spec = MAKERS[name](rng, k)
    except ValueError:  # Pair(): a form not positive definite
        return "not positive definite"
    except AssertionError as exc:  # contact() on a form not definite
        return "while scaling r12: %s" % exc
    r = [float(x) for x in r]
    q1 = [float(x) for x in q1]
    q2 = [float(x) for x in q2]
    if not all(math.isfinite(x) for x in r + q1 + q2):
        return "not finite"
    c1, c2 = cond_mp(q1), cond_mp(q2)
    if not (c1 < COND_MAX and c2 < COND_MAX):
        return "cond >= 1e16 or not positive definite"
    if "cond_max" in spec:
        lo, hi = spec["cond_max"]
        if not lo <= max(c1, c2) < hi:
            return "cond out of the class range"
    pair = gen.Pair(q1, q2)
    try:
        res = gen.contact(pair, r)
    except AssertionError as exc:  # e.g. a subnormal result
        return "exact route: %s" % exc
    lam, fpp = certify(pair, r, res)
    with mpmath.workdps(ROOT_DPS):
        mend = float(min(lam, 1 - lam))
    if "lam_end" in spec:
        lo, hi = spec["lam_end"]
        if not lo <= mend <= hi:
            return "lambda* not within the class range of an end"
    if "delta" in spec:
        d = spec["delta"]
        if not (math.copysign(1.0, res.mu2m1) == math.copysign(1.0, d)
                and 0.5e-15 <= abs(res.mu2m1) <= 2e-6):
            return "mu^2 - 1 out of the class range"
    # the independent route
    mp = gen.contact_mp(r, q1, q2, dps=MP_DPS)
    return dict(r=r, q1=q1, q2=q2, mu2=res.mu2, lam=res.lam, m1=res.mu2m1,
                cond1=c1, cond2=c2, mend=mend, fpp=float(fpp), k=k,
                mp=tuple(mp))


def generate(outdir, jobs, log, count=None):
    import mpmath
    t0 = time.time()
    classes = [(nm, c if count is None or nm == "reproducers" else count)
               for nm, c in CLASSES]
    records, cls, rejects = [], [], {}
    pool = multiprocessing.Pool(jobs) if jobs > 1 else None
    mapper = pool.imap if pool else map
    for ci, (name, count) in enumerate(classes):
        got, k = [], 0
        while len(got) < count:
            size = count if name == "reproducers" else \
                max(count - len(got), 8) + 8
            batch = [(ci, kk) for kk in range(k, k + size)]
            k += len(batch)
            for out in mapper(candidate, batch):
                if isinstance(out, str):
                    key = (name, out)
                    rejects[key] = rejects.get(key, 0) + 1
                elif len(got) < count:
                    got.append(out)
            if name == "reproducers" and len(got) < count:
                raise AssertionError("a reproducer was rejected")
        records += got
        cls += [ci] * count
        log("  %-22s %4d pairs (candidates 0..%d; %.0f s)"
            % (name, count, got[-1]["k"], time.time() - t0))
    if pool:
        pool.close()
        pool.join()
    for (name, why), n in sorted(rejects.items()):
        log("  rejected in %s: %d (%s)" % (name, n, why))
    n = len(records)
    cls = np.array(cls, dtype=np.int32)
    data = dict(
        r12=np.array([x["r"] for x in records], dtype=np.float64),
        q1=np.array([x["q1"] for x in records], dtype=np.float64),
        q2=np.array([x["q2"] for x in records], dtype=np.float64),
        MU2=np.array([x["mu2"] for x in records], dtype=np.float64),
        LAMBDA=np.array([x["lam"] for x in records], dtype=np.float64),
        MU2_MINUS_1=np.array([x["m1"] for x in records], dtype=np.float64),
        cond1=np.array([x["cond1"] for x in records], dtype=np.float64),
        cond2=np.array([x["cond2"] for x in records], dtype=np.float64))
    data["class"] = cls
    # cross-check: the mpmath route on every pair
    agree = sum(x["mp"] == (x["mu2"], x["lam"], x["m1"]) for x in records)
    log("  cross-check: %d of %d pairs identical (MU2, LAMBDA, MU2_MINUS_1) "
        "by the mpmath route at %d digits" % (agree, n, MP_DPS))
    for i, x in enumerate(records):
        if x["mp"] != (x["mu2"], x["lam"], x["m1"]):
            log("    pair %d (%s): exact %r, mpmath %r" % (
                i, CLASS_NAMES[cls[i]], (x["mu2"], x["lam"], x["m1"]),
                x["mp"]))
    # per-class statistics
    log("  %-22s %5s %9s %9s %9s %9s %9s %9s %9s" % (
        "class", "n", "max cond", "min mu2", "max mu2", "min|mu2-1|",
        "min end", "max end", "min win"))
    for ci, name in enumerate(CLASS_NAMES):
        sel = [x for x, c in zip(records, cls) if c == ci]
        cond = [max(x["cond1"], x["cond2"]) for x in sel]
        # the lambda window in which f stays within one ulp of mu^2
        win = [math.sqrt(2 * math.ulp(x["mu2"]) / abs(x["fpp"]))
               if x["fpp"] else math.inf for x in sel]
        log("  %-22s %5d %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e %9.2e" % (
            name, len(sel), max(cond), min(x["mu2"] for x in sel),
            max(x["mu2"] for x in sel), min(abs(x["m1"]) for x in sel),
            min(x["mend"] for x in sel), max(x["mend"] for x in sel),
            min(win)))
    recipe = (
        "pw85 hard pairs (issue 13, item 4), generated by data/gen_hard_set.py "
        "with numpy %s and mpmath %s. Record k of class i drawn from "
        "np.random.default_rng([%d, i, k]); the first accepted candidates are "
        "kept (data/README.md gives each class's recipe). Every stored form "
        "is positive definite in exact rational arithmetic and has cond < "
        "1e16 (mpmath eigsy at %d digits; datasets cond1, cond2). MU2, "
        "LAMBDA, MU2_MINUS_1 are correctly rounded for the stored doubles "
        "(gen_ref_data.contact: exact integer arithmetic), with f' certified "
        "to change sign across lambda* +- 1e-50 min(lambda*, 1 - lambda*) "
        "and a single sign change on (0, 1) (Descartes). Classes (dataset "
        "class, attribute class_names, comma-separated; attribute "
        "candidates: the k of each record): %s." % (
            np.__version__, mpmath.__version__, HARD_SEED, COND_DPS,
            ", ".join("%d %s (%d)" % (i, nm, c)
                      for i, (nm, c) in enumerate(classes))))
    path = os.path.join(outdir, HARD_FILE)
    gen.write_h5(path, data, {k: None for k in data},
                 {"description": np.bytes_(recipe), "seed": HARD_SEED,
                  "class_names": np.bytes_(",".join(CLASS_NAMES)),
                  "candidates": np.array([x["k"] for x in records],
                                         dtype=np.int64)})
    log("wrote %s: %d pairs (%.0f s)" % (path, n, time.time() - t0))
    return data


def main(argv=None):
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--outdir", default=here)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--count", type=int, default=None,
                    help="pairs per class (a quick trial; default: CLASSES)")
    args = ap.parse_args(argv)
    t0 = time.time()

    def log(msg):
        print(msg, flush=True)

    os.makedirs(args.outdir, exist_ok=True)
    generate(args.outdir, max(args.jobs, 1), log, args.count)
    p = os.path.join(args.outdir, HARD_FILE)
    log("%s  %s  (%d bytes)" % (gen.sha256(p), HARD_FILE, os.path.getsize(p)))
    log("total run time: %.1f s" % (time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
