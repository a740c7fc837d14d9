# SPDX-License-Identifier: BSD-3-Clause
"""pypw85's ellipsoid constructors, principal axes, contact geometry and
derivatives: the wrappers (shapes, layouts, errors), and the derivatives
against finite differences of μ² computed by mpmath at 40 digits (an
independent computation: μ² maximised with mpmath's root finder)."""

import mpmath
import numpy as np
import pytest

import pypw85

rng = np.random.default_rng(2026)


def random_rotation():
    q, r = np.linalg.qr(rng.normal(size=(3, 3)))
    q = q * np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def random_pair(max_aspect=10.0):
    def one():
        a = 10.0 ** rng.uniform(-0.5, 0.5) * max_aspect ** -rng.uniform(
            0, 1, size=3)
        return pypw85.ellipsoid_rotation(a, random_rotation())
    return rng.normal(size=3), one(), one()


# ---- The wrappers.

def test_pack_unpack():
    m = np.array([[1.0, 2.0, 3.0], [2.0, 4.0, 5.0], [3.0, 5.0, 6.0]])
    q = pypw85.pack_sym(m)
    assert q.tolist() == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    assert pypw85.unpack_sym(q).tolist() == m.tolist()
    with pytest.raises(ValueError, match="not symmetric"):
        pypw85.pack_sym(m + np.triu(np.ones((3, 3)), 1))
    with pytest.raises(ValueError, match="shape"):
        pypw85.pack_sym(np.ones((2, 2)))
    with pytest.raises(TypeError):
        pypw85.pack_sym(np.array([["a"] * 3] * 3))


def test_constructors_agree():
    """A rotation as (3, 3) or flat, and as a quaternion, give the same Q
    (a quarter turn about z: a[0] along y, a[1] along −x)."""
    a = [3.0, 2.0, 0.5]
    rot = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    expected = [4.0, 0.0, 0.0, 9.0, 0.0, 0.25]
    assert pypw85.ellipsoid_rotation(a, rot).tolist() == expected
    assert pypw85.ellipsoid_rotation(a, rot.ravel()).tolist() == expected
    p = [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)]
    np.testing.assert_allclose(pypw85.ellipsoid_quaternion(a, p), expected,
                               rtol=0, atol=1e-14)
    axes, r = pypw85.principal_axes(expected)
    assert axes.tolist() == [3.0, 2.0, 0.5]
    np.testing.assert_allclose(r, [[0, 1, 0], [1, 0, 0], [0, 0, -1]],
                               atol=1e-15)


@pytest.mark.parametrize("call, status", [
    (lambda: pypw85.ellipsoid_rotation([1, 0, 1], np.eye(3)), pypw85.EINVAL),
    (lambda: pypw85.ellipsoid_rotation([1, 1, 1], 1.1 * np.eye(3)),
     pypw85.EINVAL),
    (lambda: pypw85.ellipsoid_rotation([1, np.nan, 1], np.eye(3)),
     pypw85.EDOM),
    (lambda: pypw85.ellipsoid_quaternion([1, 1, 1], [1, 1, 0, 0]),
     pypw85.EINVAL),
    (lambda: pypw85.ellipsoid_quaternion([1e200, 1, 1], [1, 0, 0, 0]),
     pypw85.ERANGE),
    (lambda: pypw85.principal_axes([1, 2, 0, 1, 0, 1]), pypw85.ENOTPOSDEF),
    (lambda: pypw85.contact_geometry([1, 0, 0], [1, 2, 0, 1, 0, 1],
                                     [1, 0, 0, 1, 0, 1]), pypw85.ENOTPOSDEF),
    (lambda: pypw85.contact_derivatives([np.inf, 0, 0], [1, 0, 0, 1, 0, 1],
                                        [1, 0, 0, 1, 0, 1]), pypw85.EDOM),
])
def test_errors(call, status):
    with pytest.raises(pypw85.Error) as info:
        call()
    assert info.value.status == status


def test_layouts_and_outputs(tutorial):
    """The slices of pypw85's layout constants; μ² that of
    contact_function; geometry of both calls equal; preallocated
    outputs."""
    mu2, lam = pypw85.contact_function(tutorial.r12, tutorial.q1,
                                       tutorial.q2)
    out = np.empty(pypw85.GEOM_SIZE)
    g = pypw85.contact_geometry(tutorial.r12, tutorial.q1, tutorial.q2, out)
    assert g is out
    g2, d = pypw85.contact_derivatives(tutorial.r12, tutorial.q1, tutorial.q2)
    assert g.tolist() == g2.tolist()
    assert g[pypw85.GEOM_MU2] == mu2
    assert abs(g[pypw85.GEOM_LAMBDA] - lam) <= 1e-12
    n = g[pypw85.GEOM_NORMAL:pypw85.GEOM_NORMAL + 3]
    assert abs(np.linalg.norm(n) - 1.0) <= 4e-16
    assert d.shape == (pypw85.DERIV_SIZE,)
    buffer = np.empty(pypw85.DERIV_SIZE)
    with pytest.raises(ValueError, match="separate"):
        pypw85.contact_derivatives(tutorial.r12, tutorial.q1, tutorial.q2,
                                   buffer[:pypw85.GEOM_SIZE], buffer)


# ---- Finite differences in extended precision.

mpmath.mp.dps = 40


def mp_mu2(r, q1, q2, lam0):
    """μ² = max f by mpmath: the root of f′(λ) = (1 − 2λ)·r·s −
    λ(1−λ)·sᵀ(Q2 − Q1)s, s = Q(λ)⁻¹r (docs/implementation.rst, eq. (4.5)), from lam0."""
    def full(q):
        return mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                              [q[2], q[4], q[5]]])
    r = mpmath.matrix(list(r))
    m1, m2 = full(q1), full(q2)

    def s_of(lam):
        return mpmath.lu_solve((1 - lam) * m1 + lam * m2, r)

    def fprime(lam):
        s = s_of(lam)
        rs = (r.T * s)[0]
        return (1 - 2 * lam) * rs - lam * (1 - lam) * (s.T * (m2 - m1) * s)[0]
    lam = mpmath.findroot(fprime, mpmath.mpf(lam0), tol=mpmath.mpf(10) ** -36)
    s = s_of(lam)
    return lam * (1 - lam) * (r.T * s)[0]


def mp_rotate(q, axis, angle):
    """R·Q·Rᵀ for the rotation by angle about the coordinate axis."""
    c, s = mpmath.cos(angle), mpmath.sin(angle)
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    rot = mpmath.eye(3)
    rot[i, i], rot[i, j], rot[j, i], rot[j, j] = c, -s, s, c
    m = mpmath.matrix([[q[0], q[1], q[2]], [q[1], q[3], q[4]],
                       [q[2], q[4], q[5]]])
    m = rot * m * rot.T
    return [m[0, 0], m[0, 1], m[0, 2], m[1, 1], m[1, 2], m[2, 2]]


@pytest.mark.parametrize("seed", range(6))
def test_derivatives_against_mpmath_differences(seed):
    """Central differences at 40 digits with steps of 1e-12 (relative):
    truncation 1e-24, rounding 1e-28; the library's derivatives agree to
    a few ulps of the norm of each block (torques: of their scale
    |r12|·|∂μ²/∂r12|, as a torque may vanish)."""
    global rng
    rng = np.random.default_rng(seed)
    r, q1, q2 = random_pair(1e3 if seed % 2 else 10.0)
    g, d = pypw85.contact_derivatives(r, q1, q2)
    lam = g[pypw85.GEOM_LAMBDA]
    h = mpmath.mpf(10) ** -12
    fd = np.empty(pypw85.DERIV_SIZE)
    rm = [mpmath.mpf(x) for x in r]
    q1m = [mpmath.mpf(x) for x in q1]
    q2m = [mpmath.mpf(x) for x in q2]
    scale_r = mpmath.sqrt(sum(x * x for x in rm))
    for i in range(3):
        hr = h * scale_r
        rp, rn = list(rm), list(rm)
        rp[i] += hr
        rn[i] -= hr
        fd[pypw85.DERIV_R12 + i] = (mp_mu2(rp, q1m, q2m, lam)
                                    - mp_mu2(rn, q1m, q2m, lam)) / (2 * hr)
        fd[pypw85.DERIV_ROT1 + i] = (
            mp_mu2(rm, mp_rotate(q1m, i, h), q2m, lam)
            - mp_mu2(rm, mp_rotate(q1m, i, -h), q2m, lam)) / (2 * h)
        fd[pypw85.DERIV_ROT2 + i] = (
            mp_mu2(rm, q1m, mp_rotate(q2m, i, h), lam)
            - mp_mu2(rm, q1m, mp_rotate(q2m, i, -h), lam)) / (2 * h)
    diag = [0, 3, 5]
    rows, cols = [0, 0, 0, 1, 1, 2], [0, 1, 2, 1, 2, 2]
    for k in range(6):
        for q, start, which in ((q1m, pypw85.DERIV_Q1, 1),
                                (q2m, pypw85.DERIV_Q2, 2)):
            hq = h * mpmath.sqrt(q[diag[rows[k]]] * q[diag[cols[k]]])
            qp, qn = list(q), list(q)
            qp[k] += hq
            qn[k] -= hq
            if which == 1:
                up, down = mp_mu2(rm, qp, q2m, lam), mp_mu2(rm, qn, q2m, lam)
            else:
                up, down = mp_mu2(rm, q1m, qp, lam), mp_mu2(rm, q1m, qn, lam)
            fd[start + k] = (up - down) / (2 * hq)
    grad = np.linalg.norm(d[0:3])
    for start, n in ((0, 3), (3, 3), (6, 3), (9, 6), (15, 6)):
        block = slice(start, start + n)
        scale = np.linalg.norm(fd[block])
        if start in (3, 6):
            scale = max(scale, float(scale_r) * grad)
        err = np.linalg.norm(d[block] - fd[block]) / scale
        assert err <= 64 * np.finfo(float).eps, (start, err, d[block],
                                                  fd[block])
