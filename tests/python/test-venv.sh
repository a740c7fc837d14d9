#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# pip install --no-build-isolation (meson-python, pyproject.toml) of a copy
# of the source tree into a new virtual environment, offline; then, from
# that environment, with no PW85_LIBRARY and no LD_LIBRARY_PATH: pip's
# metadata, pypw85 loading the libraries inside its package, a threaded
# batch, and the Python tutorial. Exit status 77 (a skip) when venv,
# pip or meson-python is missing.
# Usage: test-venv.sh PYTHON SOURCE-DIR VERSION
set -eu
python=$1 src=$2 version=$3
skip() { echo "SKIP: $*"; exit 77; }
"$python" -c 'import ensurepip, venv' 2>/dev/null ||
  skip "the venv module cannot create environments (Debian: python3-venv)"
"$python" -m pip --version >/dev/null 2>&1 || skip "no pip (Debian: python3-pip)"
"$python" -c 'import mesonpy' 2>/dev/null ||
  skip "no meson-python (Debian: python3-mesonpy)"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
unset PW85_LIBRARY PW85_LEGACY_LIBRARY LD_LIBRARY_PATH LD_PRELOAD PYTHONPATH
export PYTHONNOUSERSITE=1 PYTHONDONTWRITEBYTECODE=1 PIP_NO_INDEX=1 \
  PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1
step() { echo "== $*"; }

step "copy the source tree (meson-python writes into it), no build trees"
"$python" - "$src" "$tmp/src" <<'PY'
import os, shutil, sys
root = sys.argv[1]
def ignore(directory, names):
    if os.path.samefile(directory, root):  # .git, build directories
        return [n for n in names if n == ".git" or os.path.isdir(
            os.path.join(directory, n, "meson-private"))]
    return [n for n in names if n == "__pycache__"]
shutil.copytree(root, sys.argv[2], ignore=ignore, symlinks=True)
PY

step "python -m venv --system-site-packages (NumPy from the system)"
"$python" -m venv --system-site-packages "$tmp/venv"
venv_python=$tmp/venv/bin/python

step "pip install --no-build-isolation --no-index (offline)"
cd "$tmp"
"$venv_python" -m pip install --no-build-isolation --no-index \
  --config-settings=compile-args=-j2 "$tmp/src" >"$tmp/pip.log" 2>&1 ||
  { cat "$tmp/pip.log"; echo "pip install failed"; exit 1; }
tail -n 1 "$tmp/pip.log"

step "pip show pypw85"
"$venv_python" -m pip show pypw85 >"$tmp/show.log"
cat "$tmp/show.log"
grep -qx "Version: $version" "$tmp/show.log" ||
  { echo "pip show: not version $version"; exit 1; }

step "import pypw85 from the environment"
"$venv_python" -W error::RuntimeWarning - "$tmp/venv" "$version" <<'PY'
import importlib.metadata
import os
import sys

import numpy as np

import pypw85
import pypw85.legacy

venv, version = sys.argv[1:]
package = os.path.dirname(pypw85.__file__)
assert package.startswith(venv + os.sep), pypw85.__file__
assert pypw85.__version__ == version, pypw85.__version__
assert importlib.metadata.version("pypw85") == version
# The libraries inside the package (pypw85/_paths.py: relative names).
assert pypw85._library_path == os.path.join(package, "libpw85.so.2"), \
    pypw85._library_path
assert pypw85.legacy._library_path == \
    os.path.join(package, "libpw85_legacy.so.2"), pypw85.legacy._library_path
print("pypw85 %s from %s" % (pypw85.__version__, pypw85._library_path))
rng = np.random.default_rng(1)
r12 = rng.uniform(-2.0, 2.0, (1000, 3))
q = pypw85.spheroid(1.0, 0.5, [0.0, 0.0, 1.0])
one = pypw85.contact_function(r12, q, q)
assert np.array_equal(pypw85.contact_function(r12, q, q, threads=2), one)
assert np.array_equal(one[999], pypw85.contact_function(r12[999], q, q))
print("batch of 1000 pairs on 2 threads: ok")
PY

step "the tutorial from the environment"
"$venv_python" "$src/tutorial/tutorial.py" >"$tmp/tutorial.log" 2>&1 ||
  { cat "$tmp/tutorial.log"; echo "tutorial.py failed"; exit 1; }
cat "$tmp/tutorial.log"
grep -q '^μ² = 3\.36270604063' "$tmp/tutorial.log" ||
  { echo "tutorial.py does not print μ² = 3.36270604063..."; exit 1; }
echo "ok: pip installed pypw85 $version into a virtual environment"
