# SPDX-License-Identifier: BSD-3-Clause
"""The ctypes prototypes of pw85.h and pw85_legacy.h, and how to apply them.

Each table maps a function's name to (restype, argtypes), as the header
declares it. Arrays cross into C as the address of a validated,
C-contiguous float64 buffer (`_convert`), so a ``double *`` is declared
``c_void_p``: ctypes converts the int address without calling back into
Python, which keeps each call cheap.
"""

import ctypes

_DOUBLE_P = ctypes.c_void_p  # double * (or double const *)
_DOUBLE = ctypes.c_double
_INT = ctypes.c_int
_SIZE = ctypes.c_size_t
_BATCH_INPUTS = [_SIZE] + [_DOUBLE_P, _SIZE] * 3

#: libpw85 (include/pw85/pw85.h).
LIBPW85 = {
    "pw85_strerror": (ctypes.c_char_p, [_INT]),
    "pw85_version": (ctypes.c_char_p, []),
    "pw85__cholesky_decomp": (None, [_DOUBLE_P, _DOUBLE_P]),
    "pw85__cholesky_solve": (None, [_DOUBLE_P, _DOUBLE_P, _DOUBLE_P]),
    "pw85_spheroid": (None, [_DOUBLE, _DOUBLE, _DOUBLE_P, _DOUBLE_P]),
    "pw85_f_neg": (_DOUBLE, [_DOUBLE, _DOUBLE_P]),
    "pw85__residual": (None, [_DOUBLE, _DOUBLE_P, _DOUBLE_P, _DOUBLE_P,
                              _DOUBLE_P]),
    "pw85_contact_function": (_INT, [_DOUBLE_P, _DOUBLE_P, _DOUBLE_P,
                                     _DOUBLE_P]),
    "pw85_overlap": (_INT, [_DOUBLE_P, _DOUBLE_P, _DOUBLE_P,
                            ctypes.POINTER(_INT)]),
    "pw85_ellipsoid_rotation": (_INT, [_DOUBLE_P] * 3),
    "pw85_ellipsoid_quaternion": (_INT, [_DOUBLE_P] * 3),
    "pw85_principal_axes": (_INT, [_DOUBLE_P] * 3),
    "pw85_contact_geometry": (_INT, [_DOUBLE_P] * 4),
    "pw85_contact_derivatives": (_INT, [_DOUBLE_P] * 5),
    # The batches: n, then (address, stride) of r12, q1 and q2, then the
    # outputs, the statuses and the thread count.
    "pw85_batch_threads": (_INT, [_INT, _SIZE]),
    "pw85_contact_function_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2
                                    + [_INT]),
    "pw85_overlap_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2 + [_INT]),
    "pw85_contact_geometry_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2
                                    + [_INT]),
    "pw85_contact_derivatives_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 3
                                       + [_INT]),
    # The constructors' batches: n, (address, stride) of each input, the
    # outputs, the statuses and the thread count.
    "pw85_spheroid_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2 + [_INT]),
    "pw85_ellipsoid_rotation_batch": (_INT, [_SIZE] + [_DOUBLE_P, _SIZE] * 2
                                      + [_DOUBLE_P] * 2 + [_INT]),
    "pw85_ellipsoid_quaternion_batch": (_INT, [_SIZE] + [_DOUBLE_P, _SIZE] * 2
                                        + [_DOUBLE_P] * 2 + [_INT]),
    "pw85_principal_axes_batch": (_INT, [_SIZE, _DOUBLE_P, _SIZE]
                                  + [_DOUBLE_P] * 3 + [_INT]),
    # Since 2.3.0.
    "pw85_spheroid_checked": (_INT, [_DOUBLE, _DOUBLE, _DOUBLE_P,
                                     _DOUBLE_P]),
    "pw85_principal_axes_quaternion": (_INT, [_DOUBLE_P] * 3),
    "pw85_principal_axes_quaternion_batch": (_INT, [_SIZE, _DOUBLE_P, _SIZE]
                                             + [_DOUBLE_P] * 3 + [_INT]),
}

#: The ellipses of libpw85 (include/pw85/pw85_2d.h, since 2.5.0), declared
#: by pypw85.d2 when it is imported.
LIBPW85_2D = {
    "pw85_2d_f_neg": (_DOUBLE, [_DOUBLE, _DOUBLE_P]),
    "pw85_2d_contact_function": (_INT, [_DOUBLE_P] * 4),
    "pw85_2d_overlap": (_INT, [_DOUBLE_P] * 3 + [ctypes.POINTER(_INT)]),
    "pw85_2d_contact_geometry": (_INT, [_DOUBLE_P] * 4),
    "pw85_2d_contact_derivatives": (_INT, [_DOUBLE_P] * 5),
    "pw85_2d_ellipse": (_INT, [_DOUBLE_P, _DOUBLE, _DOUBLE_P]),
    "pw85_2d_principal_axes": (_INT, [_DOUBLE_P, _DOUBLE_P,
                                      ctypes.POINTER(_DOUBLE)]),
    "pw85_2d_contact_function_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2
                                       + [_INT]),
    "pw85_2d_overlap_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2
                              + [_INT]),
    "pw85_2d_contact_geometry_batch": (_INT, _BATCH_INPUTS + [_DOUBLE_P] * 2
                                       + [_INT]),
    "pw85_2d_contact_derivatives_batch": (_INT, _BATCH_INPUTS
                                          + [_DOUBLE_P] * 3 + [_INT]),
    "pw85_2d_ellipse_batch": (_INT, [_SIZE] + [_DOUBLE_P, _SIZE] * 2
                              + [_DOUBLE_P] * 2 + [_INT]),
    "pw85_2d_principal_axes_batch": (_INT, [_SIZE, _DOUBLE_P, _SIZE]
                                     + [_DOUBLE_P] * 3 + [_INT]),
}

#: libpw85_legacy (include/pw85/pw85_legacy.h).
LIBPW85_LEGACY = {
    "pw85_legacy__det_sym": (_DOUBLE, [_DOUBLE_P]),
    "pw85_legacy__xT_adjA_x": (_DOUBLE, [_DOUBLE_P, _DOUBLE_P]),
    "pw85_legacy__detQ_as_poly": (None, [_DOUBLE_P] * 5),
    "pw85_legacy__rT_adjQ_r_as_poly": (None, [_DOUBLE_P] * 5),
    "pw85_legacy_f1": (_DOUBLE, [_DOUBLE] + [_DOUBLE_P] * 4),
    "pw85_legacy_f2": (_DOUBLE, [_DOUBLE] + [_DOUBLE_P] * 4),
    "pw85_legacy_contact_function1": (_INT, [_DOUBLE_P] * 4),
    "pw85_legacy_contact_function2": (_INT, [_DOUBLE_P] * 4),
}


def declare(lib, table):
    """Set restype and argtypes of every function of table on lib."""
    for symbol, (restype, argtypes) in table.items():
        function = getattr(lib, symbol)
        function.restype = restype
        function.argtypes = argtypes
