# SPDX-License-Identifier: BSD-3-Clause
"""How pypw85 finds libpw85 and libpw85_legacy, with no configuration file.

Each test copies the package into a temporary directory, as `meson install`
would, with a _paths.py of its own, and imports it in a fresh interpreter
(the same /usr/bin/python3) whose environment has no PW85_LIBRARY,
PW85_LEGACY_LIBRARY or LD_LIBRARY_PATH unless the test sets them.
"""

import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

import pypw85

from conftest import SOURCE_ROOT, TUTORIAL_MU2

PACKAGE_DIR = pathlib.Path(pypw85.__file__).resolve().parent
LIBPW85 = os.path.abspath(pypw85._library_path)

PROBE = """
import pypw85
print(pypw85._library_path)
print(pypw85.__version__)
q1 = pypw85.spheroid(10, 0.1, [0, 0, 1])
q2 = pypw85.spheroid(0.5, 5, [1, 0, 0])
print(repr(pypw85.contact_function([0.7, -0.7, 1.1], q1, q2)[0]))
"""


def legacy_path():
    try:
        import pypw85.legacy
    except ImportError:
        return None
    return os.path.abspath(pypw85.legacy._library_path)


def install_copy(root, libpw85, libpw85_legacy=None, paths=True):
    """Copy pypw85 under root, with a _paths.py naming the given paths."""
    target = root / "pypw85"
    target.mkdir()
    for source in PACKAGE_DIR.glob("*.py"):
        if source.name != "_paths.py":  # written below, or absent
            shutil.copy(source, target / source.name)
    if paths:
        (target / "_paths.py").write_text(
            "LIBPW85 = %r\nLIBPW85_LEGACY = %r\n" % (libpw85, libpw85_legacy))
    return root


def run(root, code, **env_vars):
    env = {k: v for k, v in os.environ.items()
           if k not in ("PW85_LIBRARY", "PW85_LEGACY_LIBRARY",
                        "LD_LIBRARY_PATH", "PYTHONPATH")}
    env.update(PYTHONPATH=str(root), PYTHONDONTWRITEBYTECODE="1", **env_vars)
    return subprocess.run([sys.executable, "-c", code], env=env,
                          capture_output=True, text=True, timeout=120)


def test_installed_path_without_environment(tmp_path):
    root = install_copy(tmp_path, LIBPW85, legacy_path())
    result = run(root, PROBE)
    assert result.returncode == 0, result.stderr
    path, version, mu2 = result.stdout.split()
    assert path == LIBPW85
    assert version == pypw85.__version__
    assert float(mu2) == pytest.approx(TUTORIAL_MU2, rel=1e-15)
    assert result.stderr == ""


def test_installed_legacy_path_without_environment(tmp_path):
    legacy = legacy_path()
    if legacy is None:
        pytest.skip("libpw85_legacy is not built")
    root = install_copy(tmp_path, LIBPW85, legacy)
    result = run(root, "import pypw85.legacy as l; print(l._library_path); "
                 "print(l._det_sym([1, 0, 0, 2, 0, 3]))")
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == [legacy, "6.0"]


def test_environment_overrides_installed_path(tmp_path):
    root = install_copy(tmp_path, "/fake/installed/lib/libpw85.so.2")
    result = run(root, PROBE, PW85_LIBRARY=LIBPW85)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split()[0] == LIBPW85
    assert result.stderr == ""


def test_failed_environment_falls_back_with_warning(tmp_path):
    root = install_copy(tmp_path, LIBPW85)
    result = run(root, PROBE, PW85_LIBRARY="/nonexistent/libpw85.so.2")
    assert result.returncode == 0, result.stderr
    assert result.stdout.split()[0] == LIBPW85
    assert "RuntimeWarning" in result.stderr
    assert "/nonexistent/libpw85.so.2" in result.stderr
    # The warning points at the code that imported pypw85 (python -c),
    # not into the package.
    assert result.stderr.startswith("<string>:2: RuntimeWarning"), \
        result.stderr


def import_error(result):
    if result.returncode == 0:
        pytest.skip("a libpw85 of ABI 2 is installed where the dynamic "
                    "loader finds it: loaded %s" % result.stdout.split()[0])
    assert "ImportError" in result.stderr, result.stderr
    return result.stderr[result.stderr.index("ImportError"):]


def test_import_error_names_every_place(tmp_path):
    fake = "/fake/installed/lib/libpw85.so.2"
    root = install_copy(tmp_path, fake)
    message = import_error(run(root, PROBE, PW85_LIBRARY="/nonexistent"))
    print(message)
    places = ["1. $PW85_LIBRARY = '/nonexistent': ",
              "2. installed path %r (recorded in pypw85/_paths.py): " % fake,
              "3. system search for 'libpw85.so.2'",
              "4. ctypes.util.find_library('pw85')"]
    for place in places:
        assert place in message
    # Each place says why it failed.
    assert message.count("No such file or directory") >= 3


def test_import_error_without_installed_path(tmp_path):
    root = install_copy(tmp_path, None, paths=False)
    message = import_error(run(root, PROBE))
    assert "$PW85_LIBRARY: not set" in message
    assert "installed path: none recorded (pypw85/_paths.py is absent" \
        in message


def test_not_libpw85_is_skipped(tmp_path):
    """A library without the pw85 symbols is rejected, with the reason."""
    root = install_copy(tmp_path, "/fake/libpw85.so.2")
    libm = "libm.so.6"
    message = import_error(run(root, PROBE, PW85_LIBRARY=libm))
    assert "$PW85_LIBRARY = 'libm.so.6': not libpw85: no symbol pw85_" \
        in message


def test_legacy_import_error(tmp_path):
    root = install_copy(tmp_path, LIBPW85, None)
    result = run(root, "import pypw85.legacy",
                 PW85_LEGACY_LIBRARY="/nonexistent/libpw85_legacy.so.2")
    if result.returncode == 0:
        pytest.skip("a libpw85_legacy is installed system-wide")
    assert "ImportError: pypw85: cannot load libpw85_legacy" in result.stderr
    assert "/nonexistent/libpw85_legacy.so.2" in result.stderr
    assert "installed path: none recorded (libpw85_legacy was not built" \
        in result.stderr
    assert "libpw85_legacy.so.2" in result.stderr


def test_only_numpy_at_run_time(tmp_path):
    """Importing pypw85 (and .legacy) adds to what NumPy loads only pypw85
    and modules of the standard library."""
    root = install_copy(tmp_path, LIBPW85, legacy_path())
    code = """
import sys
import numpy
before = set(sys.modules)
import pypw85
try:
    import pypw85.legacy
except ImportError:
    pass
new = {m.split(".")[0] for m in set(sys.modules) - before}
print(" ".join(sorted(new - set(sys.stdlib_module_names))))
"""
    result = run(root, code)
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == ["pypw85"]


def test_meson_installs_every_module():
    """bindings/python/meson.build installs every module of the package (a
    module left out breaks only the installed copy)."""
    meson_build = (SOURCE_ROOT / "bindings" / "python" / "meson.build").read_text()
    installed = set(re.findall(r"'pypw85/(\w+\.py)'", meson_build))
    modules = {p.name for p in PACKAGE_DIR.glob("*.py")} - {"_paths.py"}
    assert "__init__.py" in modules and "legacy.py" in modules
    assert installed == modules
