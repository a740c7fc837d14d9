# SPDX-License-Identifier: BSD-3-Clause
"""Do two spheroids overlap? The Python tutorial (seed chapter 2.1).

E1 is an oblate spheroid centred at x1 = (-0.5, 0.4, -0.7), equatorial
radius a1 = 10, polar radius c1 = 0.1, polar axis (0, 0, 1). E2 is a prolate
spheroid centred at x2 = (0.2, -0.3, 0.4), equatorial radius a2 = 0.5, polar
radius c2 = 5, polar axis (1, 0, 0). We compute their contact function μ²,
then check the answer geometrically ("checking the output"): the point x0
where the two ellipsoids, both scaled by μ, touch, lies on both, and their
normals there are opposite.

Run it with an installed pw85 (``/usr/bin/python3 tutorial/tutorial.py``);
it exits with status 1 if a check fails.

Tolerances: every check compares quantities that are equal in exact
arithmetic, so only rounding separates them. The matrices involved have a
condition number of at most 1e4 (Q1's eigenvalues are 100 and 0.01), which
amplifies the rounding errors of double precision (1.1e-16) to about 1e-12
at worst; the points x0 also carry the error of λ, which moves them to
first order, and λ is accurate to about 1e-15. A relative tolerance of 1e-10
leaves a margin of 100 over both, and still fails for any real mistake
(a wrong μ² or λ, a wrong formula or storage order).
"""

import sys

import numpy as np

import pypw85

RTOL = 1e-10
failures = 0


def check(what, actual, expected, scale=None):
    """Print one check; count it as failed if |actual - expected| is more
    than RTOL times scale (by default, |expected|)."""
    global failures
    actual, expected = np.asarray(actual), np.asarray(expected)
    if scale is None:
        scale = np.abs(expected).max()
    error = np.abs(actual - expected).max()
    ok = error <= RTOL * scale
    failures += not ok
    print("  %-44s %s (error %.1e)" % (what, "ok" if ok else "FAILED", error))


# The two ellipsoids.
x1 = np.array([-0.5, 0.4, -0.7])
n1 = np.array([0., 0., 1.])
a1, c1 = 10, 0.1
x2 = np.array([0.2, -0.3, 0.4])
n2 = np.array([1., 0., 0.])
a2, c2 = 0.5, 5.
r12 = x2 - x1

# Their quadratic forms Q1, Q2, as the upper triangles q1, q2 (double[6]).
q1 = pypw85.spheroid(a1, c1, n1)
q2 = pypw85.spheroid(a2, c2, n2)
print("q1 = {}".format(q1))
print("q2 = {}".format(q2))

# The contact function μ² and the maximiser λ.
mu2, lambda_ = pypw85.contact_function(r12, q1, q2)
print('μ² = {}'.format(mu2))
print('λ = {}'.format(lambda_))
print("μ² > 1: the ellipsoids do not overlap" if mu2 > 1 else
      "μ² <= 1: the ellipsoids overlap")

print()
print("Checking the output")

# Q1 and Q2 as 3x3 symmetric matrices, from their upper triangles.
Q1 = np.zeros((3, 3), dtype=np.float64)
i, j = np.triu_indices_from(Q1)
Q1[i, j] = q1
Q1[j, i] = q1
Q2 = np.zeros_like(Q1)
Q2[i, j] = q2
Q2[j, i] = q2
print("Q1 =\n{}".format(Q1))
print("Q2 =\n{}".format(Q2))

# The remarkable points of each ellipsoid (centred at the origin) are on
# its surface: xᵀ·Q⁻¹·x = 1.
print("remarkable points, on the surface of E1 and E2:")
Q1_inv = np.linalg.inv(Q1)
Q2_inv = np.linalg.inv(Q2)
for name, Q_inv, points in [
        ("E1", Q1_inv, [(a1, 0., 0.), (-a1, 0., 0.), (0., a1, 0.),
                        (0., -a1, 0.), (0., 0., c1), (0., 0., -c1)]),
        ("E2", Q2_inv, [(c2, 0., 0.), (-c2, 0., 0.), (0., a2, 0.),
                        (0., -a2, 0.), (0., 0., a2), (0., 0., -a2)])]:
    for x in points:
        x = np.array(x)
        check("%s: x = %s" % (name, x), Q_inv.dot(x).dot(x), 1.0)

# The contact point x0, from Q = (1-λ)·Q1 + λ·Q2 (eq. (10)) and
# x = Q⁻¹·r12, by eq. (9a) and by eq. (9b): both must give the same point.
Q = (1 - lambda_) * Q1 + lambda_ * Q2
x = np.linalg.solve(Q, r12)
x0a = x1 + (1 - lambda_) * np.dot(Q1, x)  # eq. (9a)
x0b = x2 - lambda_ * np.dot(Q2, x)  # eq. (9b)
print("x0 by eq. (9a) = {}".format(x0a))
print("x0 by eq. (9b) = {}".format(x0b))
check("x0: eq. (9a) = eq. (9b)", x0a, x0b,
      scale=max(np.abs(x0a).max(), np.abs(r12).max()))

# Scaling E_i by μ scales Q_i by μ² and Q_i⁻¹ by μ⁻²: x0 must lie on both
# scaled ellipsoids.
x0 = x0a
Q1 *= mu2
Q2 *= mu2
Q1_inv /= mu2
Q2_inv /= mu2
print("x0 on both ellipsoids scaled by μ:")
check("(x0-x1)ᵀ·(μ²Q1)⁻¹·(x0-x1) = 1", Q1_inv.dot(x0 - x1).dot(x0 - x1), 1.0)
check("(x0-x2)ᵀ·(μ²Q2)⁻¹·(x0-x2) = 1", Q2_inv.dot(x0 - x2).dot(x0 - x2), 1.0)

# The normal to E_i at x0 is along Q_i⁻¹·(x0 - x_i): they must be opposite,
# so that the scaled ellipsoids are externally tangent at x0.
n1 = Q1_inv.dot(x0 - x1)
n1 /= np.linalg.norm(n1)
n2 = Q2_inv.dot(x0 - x2)
n2 /= np.linalg.norm(n2)
print("n1 = {}".format(n1))
print("n2 = {}".format(n2))
check("opposite unit normals: n1 = -n2", n1, -n2, scale=1.0)

if failures:
    print("%d check(s) FAILED" % failures)
    sys.exit(1)
print("all checks passed: E1 and E2 are in external contact at x0 once "
      "scaled by μ")
