#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Write the seed corpus of the fuzz targets (tests/fuzz/corpus/<target>/).

Deterministic: the same files on every run. The pairs are the tutorial's,
spheres, needles, discs, triaxial ellipsoids, nearly tangent pairs, and a
few invalid inputs (NaN, infinity, not positive definite, ranges beyond a
double), each written in the layout its target reads (see the comment at
the top of each fuzz_*.cpp). Regression seeds found by fuzzing live in
corpus/<target>/regress-* and are not touched here.

    /usr/bin/python3 tests/fuzz/make_corpus.py
"""
import math
import os
import random
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


def spheroid(a, c, n):
    """Q = a² I + (c² - a²) n nᵀ, upper triangle row by row."""
    d = c * c - a * a
    return [a * a + d * n[i] * n[j] for i in range(3) for j in range(i, 3)]


def unit(v):
    s = math.sqrt(sum(x * x for x in v))
    return [x / s for x in v]


def triaxial(a, b, c, axis, angle):
    """R diag(a², b², c²) Rᵀ, R the rotation by angle about axis."""
    x, y, z = unit(axis)
    s, co = math.sin(angle), math.cos(angle)
    t = 1 - co
    R = [[t * x * x + co, t * x * y - s * z, t * x * z + s * y],
         [t * x * y + s * z, t * y * y + co, t * y * z - s * x],
         [t * x * z - s * y, t * y * z + s * x, t * z * z + co]]
    d = [a * a, b * b, c * c]
    return [sum(R[i][m] * R[j][m] * d[m] for m in range(3))
            for i in range(3) for j in range(i, 3)]


def pairs():
    """(name, r12, q1, q2)."""
    ez, ex, ey = [0., 0., 1.], [1., 0., 0.], [0., 1., 0.]
    sph = spheroid(1., 1., ez)
    out = [
        ("tutorial", [0.7, -0.7, 1.1],
         spheroid(10., 0.1, ez), spheroid(0.5, 5., ex)),
        ("coincident", [0., 0., 0.], sph, spheroid(2., 0.5, ey)),
        ("needles", [0.5, 0.3, 0.1], spheroid(1e-3, 1., ex),
         spheroid(1e-3, 1., ey)),
        ("discs", [0.1, 0.2, 1.5], spheroid(1., 1e-3, ez),
         spheroid(1., 1e-3, unit([1., 1., 1.]))),
        ("needle-disc", [0.3, 0., 0.2], spheroid(1e-4, 2., ez),
         spheroid(3., 1e-4, ex)),
        ("aspect1e8", [1., 1., 1.], spheroid(1e-8, 1., unit([1., 2., 3.])),
         spheroid(1., 1e-8, unit([3., -1., 2.]))),
        ("sizes", [1e3, 0., 0.], spheroid(1e-3, 1e-3, ez),
         spheroid(1e3, 1e3, ez)),
        ("triaxial", [1.2, -0.4, 0.9], triaxial(1., 0.3, 2., [1, 2, 3], 0.7),
         triaxial(0.2, 1.5, 0.8, [-2, 1, 0.5], 2.1)),
        ("lambda-edge", [1e-3, 0., 0.], spheroid(1e-6, 1e-6, ez),
         spheroid(1., 1., ez)),
        ("far", [1e6, 2e6, -3e6], sph, spheroid(0.1, 3., ey)),
        ("nan", [float("nan"), 0., 0.], sph, sph),
        ("inf", [1., 0., 0.], [float("inf")] + sph[1:], sph),
        ("notposdef", [1., 0., 0.], [1., 2., 0., 1., 0., 1.], sph),
        ("negdiag", [1., 0., 0.], sph, [-1., 0., 0., 1., 0., 1.]),
        ("range", [1., 0., 0.], [1e-300, 0., 0., 1e-300, 0., 1e-300],
         [1e300, 0., 0., 1e300, 0., 1e300]),
        ("overflow", [1e300, 0., 0.], [1e-300, 0., 0., 1e-300, 0., 1e-300],
         [1e-300, 0., 0., 1e-300, 0., 1e-300]),
        ("subnormal", [5e-324, 0., 0.], sph, sph),
    ]
    # Two unit spheres at distance 2(1 + s 2^-k): mu2 = (1 + s 2^-k)².
    for k in (1, 10, 26, 40, 52):
        for s in (-1, 1):
            d = 2 * (1 + s * 2.0 ** -k)
            out.append(("spheres-tangent-%+d-%d" % (s, k), [d, 0., 0.],
                        sph, sph))
    # Nearly tangent ellipsoids: the tutorial's direction, scaled by hand
    # to mu2 ~ 1 (mu2 = 3.36271 at r12 = (0.7, -0.7, 1.1)).
    t = 1 / math.sqrt(3.36271)
    out.append(("tutorial-tangent", [0.7 * t, -0.7 * t, 1.1 * t],
                spheroid(10., 0.1, ez), spheroid(0.5, 5., ex)))
    return out


def ellipse(a0, a1, theta):
    """R(θ) diag(a0², a1²) R(θ)ᵀ, upper triangle row by row."""
    c, s = math.cos(theta), math.sin(theta)
    return [c * c * a0 * a0 + s * s * a1 * a1, c * s * (a0 * a0 - a1 * a1),
            s * s * a0 * a0 + c * c * a1 * a1]


def pairs_2d():
    """(name, r12, q1, q2) for fuzz-2d: the classes of the 2D reference
    data (data/gen_2d_data.py) and invalid inputs."""
    circ = [1., 0., 1.]
    out = [
        ("tutorial", [0.7, -0.7], ellipse(10., 0.1, 0.), ellipse(0.5, 5., 0.)),
        ("coincident", [0., 0.], circ, ellipse(2., 0.5, 1.)),
        ("needles", [0.5, 0.3], ellipse(1., 1e-3, 0.), ellipse(1e-3, 1., 0.3)),
        ("aspect1e6", [1., 1.], ellipse(1., 1e-6, 0.4),
         ellipse(1e-6, 1., -1.1)),
        ("aspect1e8", [1., 2.], ellipse(1., 1e-8, 2.), ellipse(1., 1e-8, 0.1)),
        ("sizes", [1e3, 0.], [1e-6, 0., 1e-6], [1e6, 0., 1e6]),
        ("lambda-edge", [1e-3, 0.], [1e-12, 0., 1e-12], circ),
        ("far", [1e6, -2e6], circ, ellipse(0.1, 3., 0.7)),
        ("tiny-r", [1e-300, 2e-300], ellipse(2., 1., 0.2), ellipse(1., 3., 1.)),
        ("scales", [1e-150, 0.], [1e-300, 0., 1e-300],
         [2e-300, 1e-301, 1e-300]),
        ("nan", [float("nan"), 0.], circ, circ),
        ("inf", [1., 0.], [float("inf"), 0., 1.], circ),
        ("notposdef", [1., 0.], [1., 2., 1.], circ),
        ("singular", [1., 0.], [1., 1., 1.], circ),
        ("negdiag", [1., 0.], circ, [-1., 0., 1.]),
        ("range", [1., 0.], [1e-300, 0., 1e-300], [1e300, 0., 1e300]),
        ("overflow", [1e300, 0.], [1e-300, 0., 1e-300], [1e-300, 0., 1e-300]),
        ("subnormal", [5e-324, 0.], circ, circ),
    ]
    # Two unit circles at distance 2(1 + s 2^-k): mu2 = (1 + s 2^-k)².
    for k in (1, 26, 52):
        for s in (-1, 1):
            d = 2 * (1 + s * 2.0 ** -k)
            out.append(("circles-tangent-%+d-%d" % (s, k), [d, 0.], circ,
                        circ))
    # Ellipses nearly tangent, at random orientations and aspect ratios.
    rng = random.Random(2)
    for i in range(12):
        a1, b1 = 1., 10.0 ** -rng.randrange(0, 8)
        a2, b2 = 10.0 ** rng.uniform(-2, 2), 10.0 ** -rng.randrange(0, 8)
        q1 = ellipse(a1, b1, rng.uniform(-3, 3))
        q2 = ellipse(a2, b2 * a2, rng.uniform(-3, 3))
        t = rng.uniform(-3, 3)
        out.append(("random-%02d" % i, [math.cos(t), math.sin(t)], q1, q2))
    return out


def f64(xs):
    return b"".join(struct.pack("<d", x) for x in xs)


def write(target, name, data):
    d = os.path.join(HERE, "corpus", target)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def main():
    ps = pairs()
    for i, (name, r, q1, q2) in enumerate(ps):
        # fuzz-contact-raw: 15 doubles, then the scaling exponent byte.
        write("contact-raw", name, f64(r + q1 + q2) + bytes([(7 * i) % 41]))
        # fuzz-f and fuzz-legacy: mode, lambda, 15 doubles.
        mode = i % 8
        write("f", name, bytes([mode]) + f64([0.3] + r + q1 + q2))
        write("legacy", name, bytes([mode % 5]) + f64([0.3] + r + q1 + q2))
    # Spheroid mode (bit 3): r12, then a, c, n of each form.
    spheroid_seeds = [
        ("spheroid-tutorial", [0.7, -0.7, 1.1], (10., 0.1, [0., 0., 1.]),
         (0.5, 5., [1., 0., 0.])),
        ("spheroid-needle", [0.2, 0.1, 0.], (1e-5, 1., [0., 0.6, 0.8]),
         (1., 1., [1., 0., 0.])),
        ("spheroid-nonunit", [1., 1., 1.], (1., 2., [3., 4., 0.]),
         (2., 1., [0., 0., 0.])),
    ]
    for j, (name, r, (a1, c1, n1), (a2, c2, n2)) in enumerate(spheroid_seeds):
        body = f64([0.75] + r + [a1, c1] + n1 + [0.] + [a2, c2] + n2 + [0.])
        write("f", name, bytes([8 | (j + 1)]) + body)
        write("legacy", name, bytes([8 | (j + 1)]) + body)
    # fuzz-2d: 8 doubles (r12, q1, q2), the scaling exponent, the mode
    # (symmetry, threads), the angle of the rotation, the λ of f_neg.
    for i, (name, r, q1, q2) in enumerate(pairs_2d()):
        write("2d", name, f64(r + q1 + q2) +
              bytes([(7 * i) % 41, i % 16]) +
              struct.pack("<HH", (4099 * i) % 65536, (6151 * i) % 65536))
    # fuzz-contact-structured: flags, scale, 2 × (3 × (exp, mantissa),
    # quaternion 4 × int16), direction 3 × int16, j, s, k.
    rng = random.Random(85)

    def structured(flags, scale, exps, quats, direction, j, s, k):
        b = bytes([flags, scale])
        for e3, q in zip(exps, quats):
            for e in e3:
                b += struct.pack("<bB", e, rng.randrange(256))
            b += struct.pack("<4h", *q)
        b += struct.pack("<3h", *direction) + bytes([j, s, k])
        return b

    write("contact-structured", "spheres",
          structured(0, 60, [(0, 0, 0), (0, 0, 0)], [(1, 0, 0, 0)] * 2,
                     (1, 0, 0), 0, 1, 21))
    write("contact-structured", "spheres-tangent-52",
          structured(0, 60, [(0, 0, 0), (0, 0, 0)], [(1, 0, 0, 0)] * 2,
                     (1, 2, 3), 52, 2, 25))
    for i in range(30):
        flags = rng.randrange(4)
        exps = [tuple(rng.randrange(-128, 128) for _ in range(3))
                for _ in range(2)]
        quats = [tuple(rng.randrange(-32768, 32768) for _ in range(4))
                 for _ in range(2)]
        direction = tuple(rng.randrange(-32768, 32768) for _ in range(3))
        write("contact-structured", "random-%02d" % i,
              structured(flags, rng.randrange(121), exps, quats, direction,
                         rng.choice([0, 1, 8, 20, 30, 40, 50, 53, 60]),
                         rng.randrange(3), rng.randrange(41)))


if __name__ == "__main__":
    main()
