# SPDX-License-Identifier: BSD-3-Clause
"""The exception pypw85 raises for an input the library rejects."""

from ._constants import STATUS_NAMES
from ._libpw85 import strerror


class Error(ValueError):
    """An input rejected by pw85, or a result it cannot represent.

    Parameters
    ----------
    status : int
        A pw85 status code (`EDOM`, `ENOTPOSDEF`, `ERANGE`, ...).
    where : str, optional
        The function that failed.
    detail : str, optional
        What exactly was wrong.

    Attributes
    ----------
    status : int
        The status code.
    strerror : str
        The library's message for it (``pw85_strerror(status)``).
    """

    # Where users (and pickle) find it.
    __module__ = "pypw85"

    def __init__(self, status, where=None, detail=None):
        super().__init__(status, where, detail)
        self.status = status
        self.strerror = strerror(status)
        self.where = where
        self.detail = detail

    def __str__(self):
        text = "%s (%s)" % (self.strerror,
                            STATUS_NAMES.get(self.status,
                                             "status %d" % self.status))
        if self.detail:
            text += ": " + self.detail
        if self.where:
            text = self.where + ": " + text
        return text
