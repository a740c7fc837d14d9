# SPDX-License-Identifier: BSD-3-Clause
"""Shared fixtures of the pypw85 tests (run by `meson test --suite python`).

meson sets PYTHONPATH to bindings/python, PW85_LIBRARY (and PW85_LEGACY_LIBRARY)
to the libraries of the build tree, PW85_REF_DATA, PW85_SOURCE_ROOT and
PW85_EXPECTED_VERSION.
"""

import os
import pathlib
import types

import numpy as np
import pytest

import pypw85

SOURCE_ROOT = pathlib.Path(
    os.environ.get("PW85_SOURCE_ROOT")
    or pathlib.Path(__file__).resolve().parents[2])

# Seed, chapter 2.1: an oblate and a prolate spheroid.
X1 = (-0.5, 0.4, -0.7)
N1 = (0.0, 0.0, 1.0)
A1, C1 = 10.0, 0.1
X2 = (0.2, -0.3, 0.4)
N2 = (1.0, 0.0, 0.0)
A2, C2 = 0.5, 5.0
# μ² computed with mpmath at 50 digits for the doubles above (r12 = x2 - x1
# rounded to doubles, q1 and q2 as pw85_spheroid returns them); λ likewise.
TUTORIAL_MU2 = 3.3627060406386292
TUTORIAL_LAMBDA = 0.16685895534055481


@pytest.fixture
def tutorial():
    """The two spheroids of the tutorial, as arrays."""
    x1, x2 = np.array(X1), np.array(X2)
    return types.SimpleNamespace(
        x1=x1, x2=x2, r12=x2 - x1,
        q1=pypw85.spheroid(A1, C1, np.array(N1)),
        q2=pypw85.spheroid(A2, C2, np.array(N2)))


@pytest.fixture
def rng():
    """A seeded generator: every run draws the same numbers."""
    return np.random.default_rng(0x9E85)


def random_spd(rng, scale=1.0):
    """A random symmetric positive definite matrix (upper triangle)."""
    m = rng.standard_normal((3, 3))
    a = scale * (m @ m.T + 0.5 * np.eye(3))
    return a[np.triu_indices(3)]


def full(a):
    """The 3×3 symmetric matrix of an upper triangle a[6]."""
    m = np.empty((3, 3))
    i, j = np.triu_indices(3)
    m[i, j] = a
    m[j, i] = a
    return m


def legacy_or_skip():
    """pypw85.legacy; skip if it is not built, fail if it should load."""
    if os.environ.get("PW85_EXPECT_LEGACY") == "1":
        import pypw85.legacy
        return pypw85.legacy
    try:
        import pypw85.legacy
    except ImportError as exc:
        pytest.skip("libpw85_legacy is not built in this configuration "
                    "(-Dlegacy=false, or src/legacy not there yet): %s"
                    % str(exc).splitlines()[0], allow_module_level=True)
    return pypw85.legacy
