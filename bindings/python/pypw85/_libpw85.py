# SPDX-License-Identifier: BSD-3-Clause
"""The copy of libpw85 that pypw85 loaded, with its prototypes declared.

Loaded once, on first import of pypw85 (see `_loader` for where from).
"""

from ._loader import check_abi, load_library
from ._symbols import LIBPW85, declare

lib, path = load_library("pw85", "PW85_LIBRARY", "LIBPW85", LIBPW85,
                         check_abi)
declare(lib, LIBPW85)

#: The version of the library loaded, "MAJOR.MINOR.PATCH" (pw85_version()).
version = lib.pw85_version().decode("ascii")


def strerror(status):
    """The library's message for a status code (pw85_strerror)."""
    return lib.pw85_strerror(status).decode("utf-8", "replace")
