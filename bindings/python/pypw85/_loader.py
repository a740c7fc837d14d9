# SPDX-License-Identifier: BSD-3-Clause
"""Finding and loading (dlopen) libpw85 and libpw85_legacy.

A library is loaded from the first of these places that works (the package
documentation says the same to users):

1. the environment variable named by the caller (``PW85_LIBRARY`` or
   ``PW85_LEGACY_LIBRARY``), a full path, if set and not empty;
2. the path where ``meson install`` put the library, recorded in
   ``pypw85/_paths.py`` at configure time: absolute, or relative to the
   package's directory (a wheel, installed by pip, holds the library
   beside this file);
3. the dynamic loader's usual search for the soname (``libpw85.so.2``);
4. ``ctypes.util.find_library``.

A library that loads but lacks one of the expected symbols, or fails the
caller's check, is skipped. If the environment variable named a library
that failed and a later place worked, a `RuntimeWarning` says so; if no
place works, `ImportError` lists every place tried and why each failed.
"""

import ctypes
import ctypes.util
import os
import sys
import warnings

try:
    from . import _paths
except ImportError:  # Not installed by meson (e.g. run from the sources).
    _paths = None

#: The ABI this package is written for: the soname's major version
#: (libpw85.so.2). Change it only together with the library's soversion.
ABI_MAJOR = 2

_PACKAGE_DIR = os.path.dirname(__file__)


def soname(name, major=ABI_MAJOR):
    """The file name the dynamic loader looks for (e.g. libpw85.so.2)."""
    if sys.platform == "darwin":
        return "lib%s.%d.dylib" % (name, major)
    if sys.platform in ("win32", "cygwin"):
        return "%s%s-%d.dll" % ("cyg" if sys.platform == "cygwin" else "lib",
                                name, major)
    return "lib%s.so.%d" % (name, major)


def check_abi(lib):
    """Raise OSError if lib's pw85_version() is not of ABI_MAJOR."""
    lib.pw85_version.argtypes = []
    lib.pw85_version.restype = ctypes.c_char_p
    version = lib.pw85_version().decode("ascii", "replace")
    if version.split(".")[0] != str(ABI_MAJOR):
        raise OSError("pw85_version() is %s, not %d.x" % (version, ABI_MAJOR))


def _stacklevel_outside_package():
    """The stacklevel at which warnings.warn, called by the caller of this
    function, names the first frame outside pypw85: the code that imported
    it. Frames of the import machinery are skipped, as warnings.warn skips
    them."""
    def in_import_machinery(frame):
        filename = frame.f_code.co_filename
        return "importlib" in filename and "_bootstrap" in filename

    frame, level = sys._getframe(1), 1
    while frame is not None and \
            os.path.dirname(frame.f_code.co_filename) == _PACKAGE_DIR:
        frame = frame.f_back
        while frame is not None and in_import_machinery(frame):
            frame = frame.f_back
        level += 1
    return level


def load_library(name, env_var, paths_key, symbols, check=None):
    """dlopen lib<name> from the first place that works (see above).

    Parameters
    ----------
    name : str
        The library's name without prefix nor suffix ("pw85").
    env_var : str
        The environment variable that may name it (a full path).
    paths_key : str
        The name of its installed path in pypw85/_paths.py ("LIBPW85").
    symbols : iterable of str
        The symbols it must have.
    check : callable, optional
        Called with the loaded library; raises OSError to reject it.

    Returns
    -------
    (ctypes.CDLL, str)
        The library and the path or name it was loaded from.

    Raises
    ------
    ImportError
        Listing every place tried and why each one failed.
    """
    so = soname(name)
    installed = getattr(_paths, paths_key, None)
    if installed is not None:  # relative: in the package (a wheel)
        installed = os.path.join(_PACKAGE_DIR, installed)
    candidates = []  # (where, path or None, reason if None)
    env_path = os.environ.get(env_var)
    if env_path:
        candidates.append(("$%s = %%r" % env_var, env_path, None))
    else:
        candidates.append(("$%s" % env_var, None, "not set"))
    if _paths is None:
        candidates.append(("installed path", None,
                           "none recorded (pypw85/_paths.py is absent: this "
                           "copy of pypw85 was not installed by meson)"))
    elif installed is None:
        candidates.append(("installed path", None,
                           "none recorded (lib%s was not built with this "
                           "pypw85)" % name))
    else:
        candidates.append(("installed path %r (recorded in pypw85/_paths.py)",
                           installed, None))
    candidates.append(("system search for %r (LD_LIBRARY_PATH, "
                       "/etc/ld.so.cache, default directories)", so, None))

    tried = []

    def attempt(where, path, reason):
        if path is None:
            tried.append("%s: %s" % (where, reason))
            return None
        try:
            lib = ctypes.CDLL(path)
            missing = [s for s in symbols if not hasattr(lib, s)]
            if missing:
                raise OSError("not lib%s: no symbol %s"
                              % (name, ", ".join(missing)))
            if check is not None:
                check(lib)
        except OSError as exc:
            tried.append("%s: %s" % (where % path, exc))
            return None
        if env_path and path != env_path:
            warnings.warn("pypw85: could not load $%s; loaded %r instead (%s)"
                          % (env_var, path, tried[0]), RuntimeWarning,
                          stacklevel=_stacklevel_outside_package())
        return lib

    for where, path, reason in candidates:
        lib = attempt(where, path, reason)
        if lib is not None:
            return lib, path
    # Last resort, looked up only when needed (it may run ldconfig or gcc).
    found = ctypes.util.find_library(name)
    if found is None:
        tried.append("ctypes.util.find_library(%r): not found" % name)
    elif found != so:
        lib = attempt("ctypes.util.find_library(%r) = %%r" % name, found,
                      None)
        if lib is not None:
            return lib, found
    raise ImportError(
        "pypw85: cannot load lib%s (ABI %d, %s). Places tried, in order:\n"
        "%s\nSet %s to the full path of %s, or reinstall pw85 with "
        "meson (which records where it puts the library)."
        % (name, ABI_MAJOR, so,
           "\n".join("  %d. %s" % (k + 1, t) for k, t in enumerate(tried)),
           env_var, so), name="pypw85")
