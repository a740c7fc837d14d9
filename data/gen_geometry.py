#!/usr/bin/python3
# SPDX-License-Identifier: BSD-3-Clause
"""Generate data/pw85_geometry_pairs.h5: references for the contact geometry,
the derivatives of mu^2 and the ellipsoid constructors (issue 15).

Root group, N pairs (r12, q1, q2) of triaxial ellipsoids in named blocks:
mu^2, lambda*, s = Q(lambda*)^-1 r12, the contact point, the normal and the
first derivatives of mu^2 (the outputs of pw85_contact_geometry and
pw85_contact_derivatives).  Group constructors/: semi-axes with a rotation
matrix or a quaternion and the forms Q they define (pw85_ellipsoid_rotation,
pw85_ellipsoid_quaternion), and the eigen-decomposition of the stored form
(pw85_principal_axes).  The layout is in data/README.md.

Formulas (seed pw85-1.0 documentation, chapter "Theory"): Q(lambda) =
(1 - lambda) Q1 + lambda Q2 (eq. (10)), f(lambda) = lambda (1 - lambda)
r12^T Q(lambda)^-1 r12 (eq. (11)), lambda* the root of f' (eq. (12)),
x - c1 = (1 - lambda) Q1 s (eq. (9a)), x - c2 = -lambda Q2 s (eq. (9b)),
the common normal along Q1^-1 (x - c1) (eq. (8)), and Q = R diag(a^2) R^T
(eq. (2)).  The derivatives follow from the envelope theorem
(d mu^2 = partial f at fixed lambda*, as stated in include/pw85/pw85.h).

Every input is a double and is treated as exact; every reference is computed
from those doubles at DPS digits (or in exact rational arithmetic, for the
constructors) and rounded once to nearest.  The generator asserts, before
writing:

* every pair recomputed from a cold start at DPS_CHECK digits gives the same
  doubles in every dataset, and mu2, lambda and mu2_minus_1 equal the
  certified exact-integer route of gen_ref_data.contact;
* the identities of the seed at DPS digits: x on both scaled ellipsoids
  (eq. (13)), the normal along Q1^-1 (x - c1) and -Q2^-1 (x - c2) (eq. (8)),
  and d_rot1 = d_r12 x (x - c1), d_rot2 = (x - c2) x d_r12;
* the closed forms of the derivatives against central finite differences of
  mu^2 (the max over lambda solved again at each perturbed input, FD_DPS
  digits, relative step FD_H) for every component of r12, q1, q2 and of the
  rotation vectors of both ellipsoids, on every pair: agreement to FD_RTOL;
* the constructors' forms by a second route (mpmath at 100 digits, with
  p / |p| and the usual rotation formula) and the eigen-decomposition again
  at EIG_DPS_CHECK digits: the same doubles.

Usage (from the repository root):
    /usr/bin/python3 data/gen_geometry.py [--outdir DIR] [--jobs N]
"""

import argparse
import itertools
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

GEOM_FILE = "pw85_geometry_pairs.h5"
SEED = 1515           # pairs: record k of block b from default_rng([SEED, b, k, attempt])
CTOR_SEED = 1516      # constructors: default_rng([CTOR_SEED, kind, k, attempt])
DPS = 100             # digits of the pair references
DPS_CHECK = 150       # cold-start recomputation: must give the same doubles
FD_DPS = 110          # digits of the finite-difference check
FD_H = "1e-30"        # its relative step (small enough for cond(Q) = 1e12:
#                       truncation error ~ (FD_H cond)^2, rounding ~ 1e-80)
FD_RTOL = 1e-15       # required agreement of FD and closed forms
ID_TOL = "1e-50"      # the identities must hold to this (relative)
ZERO_TOL = "1e-60"    # a component below this, relative to the scale of its
#                       vector, is rounding noise around an exact 0: stored 0
COND_DPS = 80         # digits of the eigenvalues of cond_q*
EIG_DPS = 80          # digits of the eigen-decomposition of q_quat
EIG_DPS_CHECK = 120   # and of its check
MP_CTOR_DPS = 100     # digits of the second route of the constructors

# (name, count), in file order.
PAIR_BLOCKS = (
    ("generic", 200),
    ("near_tangent", 60),
    ("lambda_end", 60),
    ("spheroids_spheres", 40),
    ("principal_axis", 40),
)
CTOR_KINDS = (
    ("random", 180),
    ("spheroid", 40),
    ("sphere", 12),
    ("axis_aligned", 48),
    ("near_unit", 30),
)

SYM_IDX = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))


# High-precision kernels (mpmath numbers, at the caller's working precision) ---


def mpf_list(x):
    import mpmath
    return [mpmath.mpf(float(t)) for t in x]


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]


def cross(u, v):
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0]]


def norm(u):
    """The 2-norm of a vector of any length."""
    import mpmath
    return mpmath.sqrt(sum(t * t for t in u))


def sym_mv(q, v):
    """Q v for the upper triangle q[6]."""
    return [q[0] * v[0] + q[1] * v[1] + q[2] * v[2],
            q[1] * v[0] + q[3] * v[1] + q[4] * v[2],
            q[2] * v[0] + q[4] * v[1] + q[5] * v[2]]


def sym_solve(q, b):
    """Q^-1 b by Q = L D L^T (Q symmetric positive definite)."""
    d0 = q[0]
    l10, l20 = q[1] / d0, q[2] / d0
    d1 = q[3] - l10 * q[1]
    t = q[4] - l20 * q[1]
    l21 = t / d1
    d2 = q[5] - l20 * q[2] - l21 * t
    y0 = b[0]
    y1 = b[1] - l10 * y0
    y2 = b[2] - l20 * y0 - l21 * y1
    x2 = y2 / d2
    x1 = y1 / d1 - l21 * x2
    x0 = y0 / d0 - l10 * x1 - l20 * x2
    return [x0, x1, x2]


def full(q):
    return [[q[0], q[1], q[2]], [q[1], q[3], q[4]], [q[2], q[4], q[5]]]


def upper(m):
    return [m[i][j] for i, j in SYM_IDX]


def outer6(s):
    """(s0^2, 2 s0 s1, 2 s0 s2, s1^2, 2 s1 s2, s2^2): s s^T as a derivative
    with respect to the stored entries (off-diagonal entries count twice)."""
    return [s[0] * s[0], 2 * s[0] * s[1], 2 * s[0] * s[2], s[1] * s[1],
            2 * s[1] * s[2], s[2] * s[2]]


def eigvals_sorted(q, dps):
    """The eigenvalues of the symmetric q[6] (mpmath.eigsy), increasing."""
    import mpmath
    with mpmath.workdps(dps):
        m = mpmath.matrix(full(q))
        ev = mpmath.eigsy(m, eigvals_only=True)
        return sorted(ev[i] for i in range(3))


def cond2(q, dps=COND_DPS):
    """cond2(Q) = lambda_max / lambda_min of the exact q (mpf or doubles)."""
    ev = eigvals_sorted(q, dps)
    if ev[0] <= 0:
        raise AssertionError("form not positive definite")
    return float(ev[2] / ev[0])


# The contact function at high precision ------------------------------------


def solve_lambda(r, q1, q2, lam0=None):
    """lambda* = argmax f at the working precision: safeguarded Newton on f'
    (f concave, f'(0) > 0 > f'(1)), bisection when a step leaves the
    bracket.  f' = (1 - 2l) r.s - l(1 - l) s.u, f'' = -2 r.s - 2(1 - 2l) s.u
    + 2 l(1 - l) u.Q^-1 u with s = Q^-1 r, u = (Q2 - Q1) s (the seed's
    residual g = -f', chapter "Optimization")."""
    import mpmath
    eps = mpmath.mpf(10) ** (-(mpmath.mp.dps - 12))
    q12 = [b - a for a, b in zip(q1, q2)]
    lo, hi = mpmath.mpf(0), mpmath.mpf(1)
    x = mpmath.mpf(0.5) if lam0 is None else mpmath.mpf(lam0)
    for _ in range(3000):
        y = 1 - x
        q = [y * a + x * b for a, b in zip(q1, q2)]
        s = sym_solve(q, r)
        u = sym_mv(q12, s)
        rs, su, uv = dot(r, s), dot(s, u), dot(u, sym_solve(q, u))
        d1 = (1 - 2 * x) * rs - x * y * su
        d2 = -2 * rs - 2 * (1 - 2 * x) * su + 2 * x * y * uv
        if d1 > 0:
            lo = x
        elif d1 < 0:
            hi = x
        else:
            return x
        xn = x - d1 / d2 if d2 < 0 else lo - 1
        if not lo < xn < hi:
            xn = (lo + hi) / 2
        if abs(xn - x) <= eps * min(x, 1 - x):
            return xn
        x = xn
    raise AssertionError("solve_lambda did not converge")


def mu2_at(r, q1, q2, lam0=None):
    """mu^2 = f(lambda*) at the working precision."""
    lam = solve_lambda(r, q1, q2, lam0)
    q = [(1 - lam) * a + lam * b for a, b in zip(q1, q2)]
    return lam * (1 - lam) * dot(r, sym_solve(q, r)), lam


def geometry(r12, q1, q2, dps, lam0=None):
    """Every reference of a pair, as mpmath numbers (see the module docstring
    and data/README.md for the formulas)."""
    import mpmath
    with mpmath.workdps(dps):
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        lam = solve_lambda(r, Q1, Q2, lam0)
        oml = 1 - lam  # exact: lam in (0, 1) has at most prec bits
        q = [oml * a + lam * b for a, b in zip(Q1, Q2)]
        s = sym_solve(q, r)
        mu2 = lam * oml * dot(r, s)
        q1s, q2s = sym_mv(Q1, s), sym_mv(Q2, s)
        c1 = lam * oml * oml   # -d mu2 / d Q1 = c1 s s^T
        c2 = lam * lam * oml   # -d mu2 / d Q2 = c2 s s^T
        ns = norm(s)
        lever = 2 * lam * oml * ns * (norm(q1s) * oml + norm(q2s) * lam)
        g = {
            "mu2": mu2, "mu2_minus_1": mu2 - 1, "lambda": lam,
            "one_minus_lambda": oml, "s": s,
            "point": [oml * t for t in q1s],            # eq. (9a)
            "normal": [t / ns for t in s],               # eq. (8)
            "d_r12": [2 * lam * oml * t for t in s],
            "d_rot1": [2 * c1 * t for t in cross(s, q1s)],
            "d_rot2": [2 * c2 * t for t in cross(s, q2s)],
            "d_q1": [-c1 * t for t in outer6(s)],
            "d_q2": [-c2 * t for t in outer6(s)],
            "q_lambda": q,
        }
        # exact zeros (e.g. s x Q1 s for a sphere) come out as noise
        tol = mpmath.mpf(ZERO_TOL)
        for k, v in g.items():
            if k == "q_lambda" or not isinstance(v, list):
                continue
            scale = lever if k.startswith("d_rot") else norm(v)
            g[k] = [t if abs(t) > tol * scale else mpmath.mpf(0) for t in v]
        return g


PAIR_REFS = ("mu2", "mu2_minus_1", "lambda", "one_minus_lambda", "s",
             "point", "normal", "d_r12", "d_rot1", "d_rot2", "d_q1", "d_q2")


def rounded(g):
    """The references of geometry() rounded once to nearest (float64)."""
    out = {}
    for k in PAIR_REFS:
        v = g[k]
        out[k] = (np.array([float(t) for t in v]) if isinstance(v, list)
                  else np.float64(float(v)))
    return out


def identities(r12, q1, q2, g):
    """The largest relative residual of the seed's identities at DPS."""
    import mpmath
    with mpmath.workdps(DPS):
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        x1 = g["point"]                      # x - c1
        x2 = [a - b for a, b in zip(x1, r)]  # x - c2
        mu2, n = g["mu2"], g["normal"]
        # eq. (13): x on both ellipsoids scaled by mu
        e = [abs(dot(x1, sym_solve(Q1, x1)) / mu2 - 1),
             abs(dot(x2, sym_solve(Q2, x2)) / mu2 - 1)]
        # eq. (8): the normal along Q1^-1 (x - c1) and -Q2^-1 (x - c2)
        for v in (sym_solve(Q1, x1), [-t for t in sym_solve(Q2, x2)]):
            nv = norm(v)
            e.append(norm([a / nv - b for a, b in zip(v, n)]))
        e.append(abs(norm(n) - 1))
        # lever arms: d_rot1 = d_r12 x (x - c1), d_rot2 = (x - c2) x d_r12
        gr = g["d_r12"]
        scale = norm(gr) * (norm(x1) + norm(x2))
        for a, b in ((g["d_rot1"], cross(gr, x1)),
                     (g["d_rot2"], cross(x2, gr))):
            e.append(norm([u - v for u, v in zip(a, b)]) / scale)
        if not dot(n, r) > 0:
            raise AssertionError("normal . r12 <= 0")
        worst = max(e)
        if not worst < mpmath.mpf(ID_TOL):
            raise AssertionError("identity residual %s" % mpmath.nstr(worst, 5))
        return float(worst)


def rotation_mp(omega):
    """R(omega) = exp([omega]_x), Rodrigues' formula."""
    import mpmath
    t = norm(omega)
    k = [w / t for w in omega]
    K = [[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]]
    K2 = [[sum(K[i][m] * K[m][j] for m in range(3)) for j in range(3)]
          for i in range(3)]
    st, ct = mpmath.sin(t), 1 - mpmath.cos(t)
    return [[(1 if i == j else 0) + st * K[i][j] + ct * K2[i][j]
             for j in range(3)] for i in range(3)]


def rotate_form(q, R):
    """R Q R^T for the upper triangle q (not rounded)."""
    Q = full(q)
    RQ = [[sum(R[i][m] * Q[m][j] for m in range(3)) for j in range(3)]
          for i in range(3)]
    return upper([[sum(RQ[i][m] * R[j][m] for m in range(3))
                   for j in range(3)] for i in range(3)])


def fd_check(r12, q1, q2, g):
    """Central differences of mu^2 (max over lambda solved again at every
    perturbed input, FD_DPS digits) against the closed forms; returns the
    relative error in the norm of each vector, and which closed forms are 0
    (to 1e-30 of their natural scale; then the error is relative to it)."""
    import mpmath
    errors, zeros = {}, []
    with mpmath.workdps(FD_DPS):
        h = mpmath.mpf(FD_H)
        r, Q1, Q2 = mpf_list(r12), mpf_list(q1), mpf_list(q2)
        lam0 = g["lambda"]
        # natural scales: |g|, |g| |lever arm|, lambda (1 - lambda)^2 |s|^2
        gr = [mpmath.mpf(t) for t in g["d_r12"]]
        x1 = [mpmath.mpf(t) for t in g["point"]]
        x2 = [a - b for a, b in zip(x1, r)]
        lam, oml = mpmath.mpf(g["lambda"]), mpmath.mpf(g["one_minus_lambda"])
        s2 = dot(g["s"], g["s"])
        natural = {"d_r12": norm(gr), "d_rot1": norm(gr) * norm(x1),
                   "d_rot2": norm(gr) * norm(x2),
                   "d_q1": lam * oml * oml * s2, "d_q2": lam * lam * oml * s2}

        def diff(plus, minus, step):
            fp, _ = mu2_at(*plus, lam0=lam0)
            fm, _ = mu2_at(*minus, lam0=lam0)
            return (fp - fm) / (2 * step)

        fd = {k: [] for k in natural}
        hr = h * norm(r)
        for i in range(3):
            rp, rm = list(r), list(r)
            rp[i] += hr
            rm[i] -= hr
            fd["d_r12"].append(diff((rp, Q1, Q2), (rm, Q1, Q2), hr))
        for name, which in (("d_q1", 0), ("d_q2", 1)):
            qq = (Q1, Q2)[which]
            hq = h * max(abs(t) for t in qq)
            for k in range(6):
                qp, qm = list(qq), list(qq)
                qp[k] += hq
                qm[k] -= hq
                args_p = (r, qp, Q2) if which == 0 else (r, Q1, qp)
                args_m = (r, qm, Q2) if which == 0 else (r, Q1, qm)
                fd[name].append(diff(args_p, args_m, hq))
        for name, which in (("d_rot1", 0), ("d_rot2", 1)):
            qq = (Q1, Q2)[which]
            for k in range(3):
                w = [mpmath.mpf(0)] * 3
                w[k] = h
                qp = rotate_form(qq, rotation_mp(w))
                w[k] = -h
                qm = rotate_form(qq, rotation_mp(w))
                args_p = (r, qp, Q2) if which == 0 else (r, Q1, qp)
                args_m = (r, qm, Q2) if which == 0 else (r, Q1, qm)
                fd[name].append(diff(args_p, args_m, h))
        for k, nat in natural.items():
            closed = [mpmath.mpf(t) for t in g[k]]
            den = norm(closed)
            if den <= mpmath.mpf("1e-30") * nat:
                den = nat
                zeros.append(k)
            errors[k] = float(norm([a - b for a, b in zip(fd[k], closed)])
                              / den)
    return errors, zeros


# Inputs of the pairs -----------------------------------------------------------


def unit(rng, n):
    v = rng.normal(size=n)
    return v / np.linalg.norm(v)


def axes_of(rng, log_ar, centre, kind="triaxial"):
    """Semi-axes 10**e of aspect ratio 10**log_ar about 10**centre, in a
    random order; kind "spheroid" makes two of them equal (the same
    double), "sphere" all three."""
    lo, hi = centre - log_ar / 2, centre + log_ar / 2
    if kind == "sphere":
        e = [centre] * 3
    elif kind == "spheroid":
        e = [hi, hi, lo] if rng.uniform() < 0.5 else [hi, lo, lo]
    else:
        e = [hi, rng.uniform(lo, hi), lo]
    e = [e[i] for i in rng.permutation(3)]
    return [float(10.0**x) for x in e]


def random_rotation(rng):
    """A rotation matrix in doubles (orthonormal to rounding) from a random
    unit quaternion; only a recipe: the forms are exact for these doubles."""
    return gen.rotation_from_quaternion(unit(rng, 4))


def form(axes, rot):
    """Q = R diag(a^2) R^T exact from the doubles, rounded once (seed eq. (2));
    None if not positive definite."""
    q = gen.triaxial_exact(axes, np.asarray(rot, dtype=np.float64))
    return q if gen.positive_definite_exact(q) else None


def mu2_unit(u, q1, q2, dps=40):
    """mu^2 for r12 = u (doubles), for scaling r12 to a target."""
    import mpmath
    with mpmath.workdps(dps):
        mu2, _ = mu2_at(mpf_list(u), mpf_list(q1), mpf_list(q2))
        return mu2


def scaled(u, q1, q2, target):
    """r12 = t u rounded, with t such that mu^2(t u) = target exactly."""
    import mpmath
    with mpmath.workdps(50):
        t = mpmath.sqrt(mpmath.mpf(target) / mu2_unit(u, q1, q2, 50))
        return [float(mpmath.mpf(float(x)) * t) for x in u]


def pair_candidate(block, rng):
    """(r12, q1, q2) of a candidate of the block, or None (rejected)."""
    name = PAIR_BLOCKS[block][0]
    eye = np.eye(3)
    log_mu2 = rng.uniform(-3.0, 3.0)
    if name in ("generic", "near_tangent"):
        q1 = form(axes_of(rng, rng.uniform(0, 6), rng.uniform(-1.5, 1.5)),
                  random_rotation(rng))
        q2 = form(axes_of(rng, rng.uniform(0, 6), rng.uniform(-1.5, 1.5)),
                  random_rotation(rng))
        if q1 is None or q2 is None:
            return None
        u = unit(rng, 3)
        if name == "generic":
            return scaled(u, q1, q2, 10.0**log_mu2), q1, q2
        sign = 1 if rng.uniform() < 0.5 else -1
        delta = sign * 10.0**rng.uniform(-15, -3)
        import mpmath
        with mpmath.workdps(50):
            r12 = scaled(u, q1, q2, 1 + mpmath.mpf(delta))
        return r12, q1, q2
    if name == "lambda_end":
        # a small ellipsoid (size ratio 10^U(2, 8.5)) beside a large one
        big = form(axes_of(rng, rng.uniform(0, 2), 0.0), random_rotation(rng))
        small = form(axes_of(rng, rng.uniform(0, 2), -rng.uniform(2, 8.5)),
                     random_rotation(rng))
        if big is None or small is None:
            return None
        q1, q2 = (big, small) if rng.uniform() < 0.5 else (small, big)
        return scaled(unit(rng, 3), q1, q2, 10.0**log_mu2), q1, q2
    if name == "spheroids_spheres":
        shapes = (("sphere", "sphere"), ("sphere", "spheroid"),
                  ("spheroid", "spheroid"), ("spheroid", "triaxial"))
        kinds = shapes[int(rng.integers(0, 4))]
        qs = []
        for kind in kinds:
            a = axes_of(rng, rng.uniform(0, 4), rng.uniform(-1.5, 1.5), kind)
            # spheres axis-aligned: Q = a^2 I exactly (a^2 rounded)
            qs.append(form(a, eye if kind == "sphere" else
                           random_rotation(rng)))
        if None in qs:
            return None
        q1, q2 = qs if rng.uniform() < 0.5 else qs[::-1]
        return scaled(unit(rng, 3), q1, q2, 10.0**log_mu2), q1, q2
    if name == "principal_axis":
        # 0: both forms diagonal, r12 = t e_j (exact zeros); 1: a shared
        # rotation R, r12 along R e_j; 2: r12 along R1 e_j, R2 independent
        mode = int(rng.integers(0, 3))
        j = int(rng.integers(0, 3))
        r1 = eye if mode == 0 else random_rotation(rng)
        r2 = (eye if mode == 0 else r1 if mode == 1 else random_rotation(rng))
        q1 = form(axes_of(rng, rng.uniform(0, 6), rng.uniform(-1.5, 1.5)), r1)
        q2 = form(axes_of(rng, rng.uniform(0, 6), rng.uniform(-1.5, 1.5)), r2)
        if q1 is None or q2 is None:
            return None
        u = [float(x) for x in np.asarray(r1)[:, j]]
        return scaled(u, q1, q2, 10.0**log_mu2), q1, q2
    raise ValueError(name)


def pair_record(task):
    """Record k of block b: inputs, references, checks."""
    b, k = task
    t0 = time.time()
    rejected = 0
    for attempt in range(100):
        rng = np.random.default_rng([SEED, b, k, attempt])
        cand = pair_candidate(b, rng)
        if cand is not None:
            break
        rejected += 1
    else:
        raise AssertionError("no candidate for block %d record %d" % (b, k))
    r12, q1, q2 = ([float(x) for x in v] for v in cand)
    g = geometry(r12, q1, q2, DPS)
    ref = rounded(g)
    # the same doubles from a cold start at DPS_CHECK digits
    ref2 = rounded(geometry(r12, q1, q2, DPS_CHECK))
    for key in PAIR_REFS:
        if np.asarray(ref[key]).tobytes() != np.asarray(ref2[key]).tobytes():
            raise AssertionError("%s differs at %d digits (block %d, %d)"
                                 % (key, DPS_CHECK, b, k))
    # the certified exact-integer route of gen_ref_data
    res = gen.contact(gen.Pair(q1, q2), r12)
    if (res.mu2, res.lam, res.mu2m1) != (float(ref["mu2"]),
                                         float(ref["lambda"]),
                                         float(ref["mu2_minus_1"])):
        raise AssertionError("mu2/lambda differ from gen_ref_data.contact "
                             "(block %d, %d)" % (b, k))
    id_err = identities(r12, q1, q2, g)
    fd_err, fd_zeros = fd_check(r12, q1, q2, g)
    worst = max(fd_err.values())
    if not worst <= FD_RTOL:
        raise AssertionError("finite differences: %r (block %d, %d)"
                             % (fd_err, b, k))
    ref["cond_q1"] = cond2(q1)
    ref["cond_q2"] = cond2(q2)
    ref["cond_q"] = cond2(g["q_lambda"])
    for q in (q1, q2):
        if not gen.positive_definite_exact(q):
            raise AssertionError("stored form not positive definite")
    ref.update(r12=r12, q1=q1, q2=q2, block=b)
    stats = dict(rejected=rejected, id_err=id_err, fd_err=fd_err,
                 fd_zeros=fd_zeros, seconds=time.time() - t0)
    return ref, stats


# Constructors ------------------------------------------------------------------


def quaternion_of(rot):
    """A unit quaternion (w, x, y, z) of the rotation matrix rot (Shepperd's
    method, doubles, normalised in doubles): a recipe only."""
    m = np.asarray(rot, dtype=np.float64)
    t = np.trace(m)
    i = int(np.argmax([t, m[0, 0], m[1, 1], m[2, 2]]))
    if i == 0:
        w = math.sqrt(1 + t) / 2
        p = [w, (m[2, 1] - m[1, 2]) / (4 * w), (m[0, 2] - m[2, 0]) / (4 * w),
             (m[1, 0] - m[0, 1]) / (4 * w)]
    else:
        a = i - 1
        b, c = (a + 1) % 3, (a + 2) % 3
        v = math.sqrt(1 + m[a, a] - m[b, b] - m[c, c]) / 2
        p = [0.0] * 4
        p[0] = (m[c, b] - m[b, c]) / (4 * v)
        p[1 + a] = v
        p[1 + b] = (m[a, b] + m[b, a]) / (4 * v)
        p[1 + c] = (m[a, c] + m[c, a]) / (4 * v)
    p = np.array(p)
    return p / np.linalg.norm(p)


def signed_permutations():
    """The 48 signed permutation matrices (24 rotations, 24 reflections)."""
    out = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1, -1), repeat=3):
            m = np.zeros((3, 3))
            for i in range(3):
                m[i, perm[i]] = signs[i]
            out.append(m)
    return out


def quat_form_exact(a, p):
    """Q = R(p/|p|) diag(a^2) R(p/|p|)^T exact for the doubles a, p:
    R(p/|p|) = R~(p)/|p|^2 with R~ the homogeneous quadratic form of the
    active rotation v -> p v p*; rounded once."""
    w, x, y, z = (Fraction(float(t)) for t in p)
    n2 = w * w + x * x + y * y + z * z
    R = [[w * w + x * x - y * y - z * z, 2 * (x * y - w * z),
          2 * (x * z + w * y)],
         [2 * (x * y + w * z), w * w - x * x + y * y - z * z,
          2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x),
          w * w - x * x - y * y + z * z]]
    a2 = [Fraction(float(t)) ** 2 for t in a]
    return [float(sum(R[i][m] * R[j][m] * a2[m] for m in range(3)) / (n2 * n2))
            for i, j in SYM_IDX]


def rot_scale_exact(a, rot):
    """sum_m |R_im R_jm| a_m^2 per stored entry, exact, rounded once."""
    R = [[Fraction(float(rot[i][j])) for j in range(3)] for i in range(3)]
    a2 = [Fraction(float(t)) ** 2 for t in a]
    return [float(sum(abs(R[i][m] * R[j][m]) * a2[m] for m in range(3)))
            for i, j in SYM_IDX]


def ctor_forms_mp(a, rot, p):
    """Second route for q_rot and q_quat: mpmath at MP_CTOR_DPS digits, with
    p/|p| and the usual (non-homogeneous) rotation formula."""
    import mpmath
    with mpmath.workdps(MP_CTOR_DPS):
        a2 = [mpmath.mpf(float(t)) ** 2 for t in a]
        R = [mpf_list(row) for row in rot]
        qr = [float(sum(R[i][m] * R[j][m] * a2[m] for m in range(3)))
              for i, j in SYM_IDX]
        pm = mpf_list(p)
        n = mpmath.sqrt(sum(t * t for t in pm))
        w, x, y, z = (t / n for t in pm)
        P = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z),
              2 * (x * z + w * y)],
             [2 * (x * y + w * z), 1 - 2 * (x * x + z * z),
              2 * (y * z - w * x)],
             [2 * (x * z - w * y), 2 * (y * z + w * x),
              1 - 2 * (x * x + y * y)]]
        qq = [float(sum(P[i][m] * P[j][m] * a2[m] for m in range(3)))
              for i, j in SYM_IDX]
        return qr, qq


def eigen(q, dps):
    """Semi-axes (decreasing), relative gaps and sign-normalised directions
    of the exact form q (doubles), from mpmath.eigsy at dps digits, rounded.
    gap_j = min_{k != j} |e_j - e_k| / e_max (e = a^2).  Columns 0 and 1:
    entry of largest magnitude positive; column 2 = column 0 x column 1
    (det +1), as pw85_principal_axes.  A column whose eigenvalue is
    repeated exactly is NaN; if column 0 or 1 is NaN, column 2 is
    normalised as the first two."""
    import mpmath
    with mpmath.workdps(dps):
        m = mpmath.matrix(full(mpf_list(q)))
        ev, V = mpmath.eigsy(m)
        order = sorted(range(3), key=lambda i: -ev[i])
        e = [ev[i] for i in order]
        if e[2] <= 0:
            raise AssertionError("q_quat not positive definite")
        cols = [[V[r, i] for r in range(3)] for i in order]
        # residual of the decomposition
        res = max(abs(sum(cols[k][i] * e[k] * cols[k][j] for k in range(3))
                      - m[i, j]) for i in range(3) for j in range(3))
        if res > mpmath.mpf(10) ** (-(dps - 10)) * e[0]:
            raise AssertionError("eigsy residual")
        gap = [min(abs(e[j] - e[k]) for k in range(3) if k != j) / e[0]
               for j in range(3)]
        degenerate = [gp <= mpmath.mpf(10) ** (-(dps - 20)) for gp in gap]
        ties = 0

        def normalise(c):
            nonlocal ties
            mags = sorted((abs(t), i) for i, t in enumerate(c))
            if mags[2][0] - mags[1][0] <= mpmath.mpf("1e-30") * mags[2][0]:
                ties += 1
            return [-t for t in c] if c[mags[2][1]] < 0 else c

        out = [None] * 3
        for j in range(3):
            if not degenerate[j]:
                out[j] = normalise(cols[j])
        if out[0] is not None and out[1] is not None:
            out[2] = cross(out[0], out[1])
        vec = np.full((3, 3), np.nan)
        for j in range(3):
            if out[j] is not None:
                vec[:, j] = [float(t) for t in out[j]]
        return (np.array([float(mpmath.sqrt(t)) for t in e]),
                np.array([0.0 if d else float(gp)
                          for gp, d in zip(gap, degenerate)]),
                vec.reshape(9), ties)


def ctor_candidate(kind, k, rng):
    """(a, rot, quat) of constructor case k of the kind."""
    name = CTOR_KINDS[kind][0]
    shape = {"spheroid": "spheroid", "sphere": "sphere"}.get(name, "triaxial")
    if name == "axis_aligned":
        if k % 12 == 0:
            shape = "spheroid"
        elif k % 12 == 6:
            shape = "sphere"
    a = axes_of(rng, rng.uniform(0, 8), rng.uniform(-3, 3), shape)
    if name == "axis_aligned":
        rot = signed_permutations()[k]
        proper = rot if np.linalg.det(rot) > 0 else -rot
        return a, rot, quaternion_of(proper)
    p = unit(rng, 4)
    rot = gen.rotation_from_quaternion(p)
    if name == "near_unit":
        # R off orthonormal by ~1e-9 (entries perturbed, used as given),
        # |p|^2 - 1 = +-2e-10 ... 2e-7 (p normalised by the library)
        rot = rot + 10.0**rng.uniform(-10, -8) * rng.normal(size=(3, 3))
        eps = 10.0**rng.uniform(-10, -7) * (1 if rng.uniform() < 0.5 else -1)
        p = p * (1 + eps)
    return a, np.asarray(rot, dtype=np.float64), np.asarray(p)


def ctor_record(task):
    kind, k = task
    rejected = 0
    for attempt in range(1000):
        rng = np.random.default_rng([CTOR_SEED, kind, k, attempt])
        a, rot, p = ctor_candidate(kind, k, rng)
        a = [float(t) for t in a]
        rot = [[float(t) for t in row] for row in rot]
        p = [float(t) for t in p]
        q_quat = quat_form_exact(a, p)
        if gen.positive_definite_exact(q_quat):
            break
        rejected += 1
    else:
        raise AssertionError("no constructor case %d of kind %d" % (k, kind))
    # the library accepts these (PW85_UNIT_TOL = 1e-6), with a margin
    R = [[Fraction(t) for t in row] for row in rot]
    ortho = max(abs(sum(R[m][i] * R[m][j] for m in range(3))
                    - (1 if i == j else 0)) for i in range(3) for j in range(3))
    pn = abs(sum(Fraction(t) ** 2 for t in p) - 1)
    if not (ortho < Fraction(1, 2 * 10**6) and pn < Fraction(1, 2 * 10**6)):
        raise AssertionError("rotation or quaternion off unit")
    q_rot = gen.triaxial_exact(a, np.array(rot))
    qr_mp, qq_mp = ctor_forms_mp(a, rot, p)
    # (the mpmath route leaves noise ~1e-100 a^2 where the exact value is 0,
    # e.g. a sphere from a quaternion)
    amax2 = max(a) ** 2
    if any(x != y and not (y == 0 and abs(x) <= 1e-80 * amax2)
           for x, y in zip(qr_mp + qq_mp, q_rot + q_quat)):
        raise AssertionError("constructor forms: mpmath route differs "
                             "(kind %d, %d)" % (kind, k))
    ea, gap, vec, ties = eigen(q_quat, EIG_DPS)
    ea2, gap2, vec2, _ = eigen(q_quat, EIG_DPS_CHECK)
    for u, v in ((ea, ea2), (gap, gap2), (vec, vec2)):
        if u.tobytes() != v.tobytes():
            raise AssertionError("eigen-decomposition differs at %d digits "
                                 "(kind %d, %d)" % (EIG_DPS_CHECK, kind, k))
    rec = dict(a=a, rot=np.array(rot).reshape(9), q_rot=q_rot,
               q_rot_scale=rot_scale_exact(a, rot), quat=p, q_quat=q_quat,
               eig_a=ea, eig_gap=gap, eig_vectors=vec, kind=kind)
    return rec, dict(rejected=rejected, ties=ties,
                     degenerate=int(np.isnan(vec).any()))


# Output --------------------------------------------------------------------------


PAIR_DATASETS = (
    # name, width (0: scalar), units, definition
    ("r12", 3, "length", "c2 - c1, the exact input"),
    ("q1", 6, "length^2", "Q1, upper triangle row by row, exact input "
     "(R diag(a^2) R^T from doubles, rounded once)"),
    ("q2", 6, "length^2", "Q2, as q1"),
    ("block", 0, "", "index into the attribute block_names (int32)"),
    ("mu2", 0, "1", "mu^2 = f(lambda*) = max of lambda(1-lambda) "
     "r12^T Q(lambda)^-1 r12 (seed Theory eqs. (10)-(12))"),
    ("mu2_minus_1", 0, "1", "mu^2 - 1, rounded from the exact value"),
    ("lambda", 0, "1", "lambda*, the maximiser"),
    ("one_minus_lambda", 0, "1", "1 - lambda*, rounded from the exact value"),
    ("s", 3, "1/length", "s = Q(lambda*)^-1 r12"),
    ("point", 3, "length", "x - c1 = (1 - lambda*) Q1 s (seed eq. (9a))"),
    ("normal", 3, "1", "n = s/|s| (seed eq. (8)), from 1 towards 2"),
    ("d_r12", 3, "1/length", "d mu^2 / d r12 = 2 lambda(1-lambda) s"),
    ("d_rot1", 3, "1/radian", "d mu^2 / d omega1 = 2 lambda(1-lambda)^2 "
     "s x (Q1 s), Q1 -> R(omega1) Q1 R(omega1)^T"),
    ("d_rot2", 3, "1/radian", "d mu^2 / d omega2 = 2 lambda^2(1-lambda) "
     "s x (Q2 s)"),
    ("d_q1", 6, "1/length^2", "d mu^2 / d q1[k] = -lambda(1-lambda)^2 "
     "(s0^2, 2s0s1, 2s0s2, s1^2, 2s1s2, s2^2)"),
    ("d_q2", 6, "1/length^2", "d mu^2 / d q2[k] = -lambda^2(1-lambda) "
     "(s0^2, 2s0s1, 2s0s2, s1^2, 2s1s2, s2^2)"),
    ("cond_q1", 0, "1", "cond2(Q1) = lambda_max/lambda_min (mpmath.eigsy, "
     "%d digits)" % COND_DPS),
    ("cond_q2", 0, "1", "cond2(Q2), as cond_q1"),
    ("cond_q", 0, "1", "cond2(Q(lambda*)), as cond_q1"),
)

CTOR_DATASETS = (
    ("a", 3, "length", "semi-axes, exact input"),
    ("rot", 9, "1", "R row by row, rot[3i+j] = R_ij, column j the direction "
     "of a[j]; exact input (orthonormal to rounding, or ~1e-9 in kind "
     "near_unit; det -1 for 24 of axis_aligned)"),
    ("q_rot", 6, "length^2", "R diag(a^2) R^T, exact from the doubles, "
     "rounded once (seed eq. (2))"),
    ("q_rot_scale", 6, "length^2", "sum_m |R_im R_jm| a_m^2 per entry, "
     "exact, rounded (the scale of the error bound in pw85.h)"),
    ("quat", 4, "1", "p = (w, x, y, z), exact input, |p| = 1 to rounding "
     "(to 1e-10 ... 1e-7 in kind near_unit)"),
    ("q_quat", 6, "length^2", "R(p/|p|) diag(a^2) R(p/|p|)^T, R(p) the "
     "active rotation v -> p v p*, exact from the doubles, rounded once"),
    ("eig_a", 3, "length", "semi-axes sqrt(e_j) of the exact stored q_quat, "
     "decreasing (mpmath.eigsy, %d digits)" % EIG_DPS),
    ("eig_gap", 3, "1", "min over k != j of |e_j - e_k| / e_0 (e = eig_a^2); "
     "0 for an exactly repeated eigenvalue"),
    ("eig_vectors", 9, "1", "directions, row by row, column j for eig_a[j]; "
     "columns 0, 1 with their entry of largest magnitude positive, column 2 "
     "= column 0 x column 1 (det +1); NaN for an exactly repeated "
     "eigenvalue"),
    ("kind", 0, "", "index into the attribute kind_names (int32)"),
)


def write_file(path, pairs, ctors, attrs, ctor_attrs):
    import h5py
    tmp = path + ".tmp"
    with h5py.File(tmp, "w", libver="earliest") as f:
        for k, v in attrs.items():
            f.attrs[k] = v
        for group, rows, spec in ((f, pairs, PAIR_DATASETS),
                                  (f.create_group("constructors"), ctors,
                                   CTOR_DATASETS)):
            if group is not f:
                for k, v in ctor_attrs.items():
                    group.attrs[k] = v
            for name, width, units, desc in spec:
                if name in ("block", "kind"):
                    arr = np.array([r[name] for r in rows], dtype=np.int32)
                else:
                    arr = np.array([np.asarray(r[name], dtype=np.float64)
                                    for r in rows], dtype=np.float64)
                    if width:
                        arr = arr.reshape(len(rows), width)
                ds = group.create_dataset(name, data=arr, track_times=False)
                ds.attrs["units"] = np.bytes_(units)
                ds.attrs["description"] = np.bytes_(desc)
    os.replace(tmp, path)


def main(argv=None):
    import mpmath
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--outdir", default=os.path.dirname(
        os.path.abspath(__file__)))
    ap.add_argument("--jobs", type=int, default=2)
    args = ap.parse_args(argv)
    t0 = time.time()
    pair_tasks = [(b, k) for b, (_, n) in enumerate(PAIR_BLOCKS)
                  for k in range(n)]
    ctor_tasks = [(c, k) for c, (_, n) in enumerate(CTOR_KINDS)
                  for k in range(n)]
    with multiprocessing.Pool(args.jobs) as pool:
        ctor_out = pool.map(ctor_record, ctor_tasks, chunksize=4)
        t1 = time.time()
        print("constructors: %d cases (%.0f s)" % (len(ctor_out), t1 - t0))
        pair_out = []
        for i, out in enumerate(pool.imap(pair_record, pair_tasks,
                                          chunksize=1)):
            pair_out.append(out)
            if (i + 1) % 40 == 0:
                print("  pairs: %d / %d (%.0f s)" % (i + 1, len(pair_tasks),
                                                     time.time() - t1),
                      flush=True)
    pairs = [r for r, _ in pair_out]
    ctors = [r for r, _ in ctor_out]

    # statistics
    print("pairs: %d in %.0f s (worker time %.0f s)" % (
        len(pairs), time.time() - t1, sum(s["seconds"] for _, s in pair_out)))
    fd_worst = {}
    for (r, s) in pair_out:
        for k, e in s["fd_err"].items():
            if e >= fd_worst.get(k, (-1,))[0]:
                fd_worst[k] = (e, r["block"])
    for k, (e, b) in sorted(fd_worst.items()):
        print("  FD vs closed form, %-7s worst relative error %.2e (block %s)"
              % (k, e, PAIR_BLOCKS[b][0]))
    fd_max = max(e for e, _ in fd_worst.values())
    zero_counts = {}
    for _, s in pair_out:
        for k in s["fd_zeros"]:
            zero_counts[k] = zero_counts.get(k, 0) + 1
    print("  closed forms 0 (to 1e-30 of their scale): %r" % zero_counts)
    id_max = max(s["id_err"] for _, s in pair_out)
    print("  identities: worst relative residual %.2e" % id_max)
    print("  rejected candidates: %d" % sum(s["rejected"] for _, s in pair_out))
    for b, (name, n) in enumerate(PAIR_BLOCKS):
        rows = [r for r in pairs if r["block"] == b]
        mu2 = np.array([r["mu2"] for r in rows])
        end = np.array([min(r["lambda"], r["one_minus_lambda"]) for r in rows])
        dev = np.array([abs(r["mu2_minus_1"]) for r in rows])
        cq = np.array([max(r["cond_q1"], r["cond_q2"]) for r in rows])
        print("  %-18s %3d: mu2 %.2e ... %.2e, |mu2-1| >= %.2e, "
              "min(l, 1-l) >= %.2e, max cond %.2e, cond_q <= %.2e"
              % (name, n, mu2.min(), mu2.max(), dev.min(), end.min(),
                 cq.max(), max(r["cond_q"] for r in rows)))
    print("constructors: rejected %d (q_quat not positive definite), "
          "%d with a repeated eigenvalue, %d near-ties of sign normalisation"
          % (sum(s["rejected"] for _, s in ctor_out),
             sum(s["degenerate"] for _, s in ctor_out),
             sum(s["ties"] for _, s in ctor_out)))
    gaps = np.array([r["eig_gap"] for r in ctors])
    print("  eig_gap > 0: %.2e ... %.2e" % (gaps[gaps > 0].min(), gaps.max()))

    common = ("generated by data/gen_geometry.py with numpy %s and mpmath %s."
              % (np.__version__, mpmath.__version__))
    attrs = {
        "description": np.bytes_(
            "pw85 contact geometry and derivatives of mu^2 (issue 15), "
            + common + " Record k of block b drawn from "
            "np.random.default_rng([%d, b, k, attempt]) (the first accepted "
            "attempt). References computed from the stored doubles at %d "
            "digits (mpmath) and rounded once; identical from a cold start "
            "at %d digits; mu2, lambda, mu2_minus_1 identical to the "
            "certified exact route of gen_ref_data.contact; derivatives "
            "checked against central finite differences (%d digits, "
            "relative step %s) on every pair: worst relative error %.2e. "
            "Layout: data/README.md." % (SEED, DPS, DPS_CHECK, FD_DPS, FD_H,
                                         fd_max)),
        "block_names": np.bytes_(",".join(n for n, _ in PAIR_BLOCKS)),
        "generator": np.bytes_("data/gen_geometry.py"),
        "mp_dps": DPS, "seed": SEED, "fd_max_rel_error": fd_max,
    }
    ctor_attrs = {
        "description": np.bytes_(
            "pw85 ellipsoid constructors and principal axes (issue 15), "
            + common + " Case k of kind c drawn from "
            "np.random.default_rng([%d, c, k, attempt]) (first attempt with "
            "q_quat positive definite). q_rot, q_rot_scale, q_quat exact in "
            "rational arithmetic, rounded once, and checked by mpmath at %d "
            "digits; eig_* by mpmath.eigsy at %d digits, identical at %d."
            % (CTOR_SEED, MP_CTOR_DPS, EIG_DPS, EIG_DPS_CHECK)),
        "kind_names": np.bytes_(",".join(n for n, _ in CTOR_KINDS)),
        "mp_dps": EIG_DPS, "seed": CTOR_SEED,
    }
    os.makedirs(args.outdir, exist_ok=True)
    path = os.path.join(args.outdir, GEOM_FILE)
    write_file(path, pairs, ctors, attrs, ctor_attrs)
    print("wrote %s (%d bytes, sha256 %s) in %.0f s" % (
        path, os.path.getsize(path), gen.sha256(path), time.time() - t0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
