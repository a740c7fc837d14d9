# SPDX-License-Identifier: BSD-3-Clause
"""Random sequential addition with pypw85.Index (the Python twin of rsa.c).

Triaxial ellipsoids (semi-axes 1, 0.5, 0.2, random orientations) are
dropped one after the other at random places of a periodic cube, each kept
only if it overlaps none already there, until a target packing fraction is
reached or too many attempts in a row fail; the packing is then checked by
the all-pairs query (no overlapping pair). The candidates are decided in
batches by one call (`Index.overlap_any_many`, on two threads), with the
result of deciding them one at a time.

    python3 rsa.py [N [FRACTION]]    (default: 2000 ellipsoids at 0.25)

Prints the packing fraction reached and the time; exit status 0 when the
check passes. `rsa_packing` is also what the documentation's figure draws.
"""

import sys
import time

import numpy as np

import pypw85

AXES = np.array([1.0, 0.5, 0.2])


def random_forms(rng, n, axes=AXES):
    """n quadratic forms R·diag(a²)·Rᵀ of uniformly random rotations."""
    quat = rng.normal(size=(n, 4))
    w, x, y, z = (quat / np.linalg.norm(quat, axis=1)[:, None]).T
    rot = np.stack([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]).transpose(2, 0, 1)
    full = (rot * axes**2) @ rot.transpose(0, 2, 1)
    i, j = np.triu_indices(3)
    return full[:, i, j]


def rsa_packing(n, target, seed=1, max_failures=20000):
    """Random sequential addition: (index, centres, forms, side, attempts)."""
    volume = 4.0 / 3.0 * np.pi * AXES.prod()
    side = (n * volume / target) ** (1.0 / 3.0)
    index = pypw85.Index([side] * 3)
    rng = np.random.default_rng(seed)
    centres, forms = [], []
    attempts = failures = 0

    def reject(k):
        """Count k rejected candidates, up to the limit of failures in a
        row; False when it is reached."""
        nonlocal attempts, failures
        k = min(k, max_failures - failures)
        attempts += k
        failures += k
        return failures < max_failures

    batch = 256
    while len(centres) < n and failures < max_failures:
        # Candidates drawn and decided in batches, against the ellipsoids
        # placed before the batch, in one call; then taken in order. One
        # that overlaps those is rejected (it would overlap the larger set
        # of a one-by-one loop too); one found free is decided again if an
        # ellipsoid was placed earlier in the batch. The result is that of
        # deciding each candidate alone, in order, and Python only visits
        # the candidates found free.
        cs = rng.uniform(0.0, side, (batch, 3))
        qs = random_forms(rng, batch)
        results, _ = index.overlap_any_many(cs, qs, threads=2)
        placed_in_batch = False
        last = -1  # the last candidate taken
        for i in np.flatnonzero(results > 0):
            if not reject(i - last - 1):  # those before i
                break
            last = i
            if placed_in_batch and index.overlap_any(cs[i], qs[i])[0] <= 0:
                if not reject(1):
                    break
                continue
            attempts += 1
            index.insert(len(centres), cs[i], qs[i])
            centres.append(cs[i])
            forms.append(qs[i])
            placed_in_batch = True
            failures = 0
            if len(centres) == n:
                break
        else:
            reject(batch - last - 1)  # the rest of the batch
        # About 16 placements per batch as they become rare.
        batch = min(16384, max(256, 16 * attempts // (len(centres) + 1)))
    return index, np.array(centres), np.array(forms), side, attempts


def main(argv):
    n = int(argv[1]) if len(argv) > 1 else 2000
    target = float(argv[2]) if len(argv) > 2 else 0.25
    t0 = time.perf_counter()
    index, centres, _, side, attempts = rsa_packing(n, target)
    seconds = time.perf_counter() - t0
    fraction = len(centres) * 4.0 / 3.0 * np.pi * AXES.prod() / side**3
    ids, _, _ = index.overlapping_pairs(threads=2)
    print("%d ellipsoids placed in %d attempts, packing fraction %.4f "
          "(target %.4f), %.3f s" % (len(centres), attempts, fraction, target,
                                     seconds))
    print("overlapping pairs: %d" % len(ids))
    index.close()
    return 0 if len(ids) == 0 else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
