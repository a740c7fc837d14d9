# SPDX-License-Identifier: BSD-3-Clause
"""Replay of a seeded sample of data/pw85_ref_data.h5 through pypw85.

The file (layout of the published pw85 reference data set) holds
F[i, j, k, l] = f(lambdas[l]; r12 = directions[k], q1 = spheroids[i],
q2 = spheroids[j]) and MU2/LAMBDA[i, j, k, m] for r12 = distances[m] *
directions[k], each the correctly rounded double of the exact value.

Tolerances are at most 10 times the worst error measured on the whole data
set (libpw85 2.1.0, x86-64, gcc 12): f and μ² are bit-exact (all 1,539,648
values of F and 419,904 of MU2), so their tolerance is 0; λ is within
1.1e-15 (absolute) of LAMBDA. Each test prints the worst error of its
sample.
"""

import os
import pathlib

import numpy as np
import pytest

import pypw85

h5py = pytest.importorskip(
    "h5py", reason="h5py is needed to read the reference data "
    "(Debian: python3-h5py)")

# Sample sizes and tolerances (see the module docstring).
N_F = 20000
N_CONTACT = 5000
F_RTOL = 0.0
MU2_RTOL = 0.0
LAMBDA_ATOL = 1e-14


@pytest.fixture(scope="module")
def ref():
    path = os.environ.get("PW85_REF_DATA")
    if not path:
        path = (pathlib.Path(__file__).resolve().parents[2] / "data"
                / "pw85_ref_data.h5")
        if not path.exists():
            pytest.skip("no reference data at %s (set PW85_REF_DATA)" % path)
    # When PW85_REF_DATA is set (by meson), a missing file is a failure.
    with h5py.File(path, "r") as h:
        return {name: h[name][...] for name in
                ("spheroids", "directions", "lambdas", "distances", "F",
                 "MU2", "LAMBDA")}


def relative_errors(actual, expected):
    """|actual − expected| / |expected|; 0 where both are 0."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    diff = np.abs(actual - expected)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(diff == 0, 0.0, diff / np.abs(expected))


def test_f(ref):
    rng = np.random.default_rng(20190715)
    shape = ref["F"].shape
    index = rng.integers(0, shape, size=(N_F, 4))
    actual = np.array([
        pypw85.f(ref["lambdas"][l], ref["directions"][k],
                 ref["spheroids"][i], ref["spheroids"][j])
        for i, j, k, l in index])
    expected = ref["F"][tuple(index.T)]
    errors = relative_errors(actual, expected)
    worst = int(errors.argmax())
    print("\nf: %d values, worst relative error %.3g at (i, j, k, l) = %s"
          " (%r, expected %r)" % (N_F, errors[worst], tuple(index[worst]),
                                  actual[worst], expected[worst]))
    assert errors[worst] <= F_RTOL, (
        "f at (i, j, k, l) = %s: %r, expected %r"
        % (tuple(index[worst]), actual[worst], expected[worst]))


def test_contact_function(ref):
    rng = np.random.default_rng(20190716)
    shape = ref["MU2"].shape
    index = rng.integers(0, shape, size=(N_CONTACT, 4))
    actual = np.empty((N_CONTACT, 2))
    for n, (i, j, k, m) in enumerate(index):
        r12 = ref["distances"][m] * ref["directions"][k]  # as in the file
        pypw85.contact_function(r12, ref["spheroids"][i],
                                ref["spheroids"][j], actual[n])
    mu2 = ref["MU2"][tuple(index.T)]
    lambda_ = ref["LAMBDA"][tuple(index.T)]
    mu2_errors = relative_errors(actual[:, 0], mu2)
    lambda_errors = np.abs(actual[:, 1] - lambda_)
    w_mu2 = int(mu2_errors.argmax())
    w_lambda = int(lambda_errors.argmax())
    print("\ncontact_function: %d pairs, worst relative error of mu2 %.3g "
          "at (i, j, k, m) = %s, worst absolute error of lambda %.3g at %s"
          % (N_CONTACT, mu2_errors[w_mu2], tuple(index[w_mu2]),
             lambda_errors[w_lambda], tuple(index[w_lambda])))
    assert mu2_errors[w_mu2] <= MU2_RTOL, (
        "mu2 at (i, j, k, m) = %s: %r, expected %r"
        % (tuple(index[w_mu2]), actual[w_mu2, 0], mu2[w_mu2]))
    # overlap agrees with the sign of μ² − 1 (0 within 4 ulps of 1).
    eps = np.finfo(np.float64).eps
    expected = np.where(np.abs(mu2 - 1) <= 4 * eps, 0, np.sign(mu2 - 1))
    for n, (i, j, k, m) in enumerate(index):
        r12 = ref["distances"][m] * ref["directions"][k]
        assert pypw85.overlap(r12, ref["spheroids"][i],
                              ref["spheroids"][j]) == expected[n], (
            "overlap at (i, j, k, m) = %s, mu2 = %r" % ((i, j, k, m), mu2[n]))
    assert lambda_errors[w_lambda] <= LAMBDA_ATOL, (
        "lambda at (i, j, k, m) = %s: %r, expected %r"
        % (tuple(index[w_lambda]), actual[w_lambda, 1], lambda_[w_lambda]))
