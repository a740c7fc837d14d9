# SPDX-License-Identifier: BSD-3-Clause
"""The macros and status codes of pw85.h, as Python values.

Written by hand from include/pw85/pw85.h; tests/python/test_constants.py
parses that header and fails if any ``#define PW85_*`` number differs from
the value here or has no counterpart. The messages of the status codes are
not repeated here: they come from the library's pw85_strerror().
"""

DIM = 3  # PW85_DIM
SYM = 6  # PW85_SYM
# What each of the next three governs in pw85_contact_function is
# documented with its re-export in __init__.py.
LAMBDA_ATOL = 1e-6  # PW85_LAMBDA_ATOL
MAX_ITER = 25  # PW85_MAX_ITER
NR_ITER = 3  # PW85_NR_ITER

UNIT_TOL = 1e-6  # PW85_UNIT_TOL

# Offsets into the outputs of contact_geometry and contact_derivatives.
GEOM_MU2 = 0  # PW85_GEOM_MU2
GEOM_LAMBDA = 1  # PW85_GEOM_LAMBDA
GEOM_POINT = 2  # PW85_GEOM_POINT
GEOM_NORMAL = 5  # PW85_GEOM_NORMAL
GEOM_SIZE = 8  # PW85_GEOM_SIZE
DERIV_R12 = 0  # PW85_DERIV_R12
DERIV_ROT1 = 3  # PW85_DERIV_ROT1
DERIV_ROT2 = 6  # PW85_DERIV_ROT2
DERIV_Q1 = 9  # PW85_DERIV_Q1
DERIV_Q2 = 15  # PW85_DERIV_Q2
DERIV_SIZE = 21  # PW85_DERIV_SIZE

# The status codes; their meanings are documented in __init__.py, their
# messages come from pw85_strerror().
SUCCESS = 0  # PW85_SUCCESS
EFAULT = 1  # PW85_EFAULT
EDOM = 2  # PW85_EDOM
ENOTPOSDEF = 3  # PW85_ENOTPOSDEF
ERANGE = 4  # PW85_ERANGE
ENOMEM = 5  # PW85_ENOMEM
ENOCONV = 6  # PW85_ENOCONV
EINVAL = 7  # PW85_EINVAL
ECANCELLED = 8  # PW85_ECANCELLED

# The C name of each status code, for messages.
STATUS_NAMES = {
    SUCCESS: "PW85_SUCCESS",
    EFAULT: "PW85_EFAULT",
    EDOM: "PW85_EDOM",
    ENOTPOSDEF: "PW85_ENOTPOSDEF",
    ERANGE: "PW85_ERANGE",
    ENOMEM: "PW85_ENOMEM",
    ENOCONV: "PW85_ENOCONV",
    EINVAL: "PW85_EINVAL",
    ECANCELLED: "PW85_ECANCELLED",
}
