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
}
