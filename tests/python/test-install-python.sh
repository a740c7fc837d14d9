#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Installs pw85 with its Python package into a temporary prefix, deletes the
# build tree, then imports that copy of pypw85 with no PW85_LIBRARY, no
# PW85_LEGACY_LIBRARY and no LD_LIBRARY_PATH: the absolute library paths
# written into pypw85/_paths.py at configure time must be enough. Runs the
# Python tutorial against it.
# Usage: test-install-python.sh MESON SOURCE-DIR PYTHON
set -eu
meson=$1 src=$2 python=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix=$tmp/prefix
unset PW85_LIBRARY PW85_LEGACY_LIBRARY LD_LIBRARY_PATH PYTHONPATH
export PYTHONNOUSERSITE=1 PYTHONDONTWRITEBYTECODE=1

step() { echo "== $*"; }

step "configure, build and install into $prefix"
# python.install_env=prefix: the package goes under the prefix, not into
# the system's or a virtualenv's site-packages.
"$meson" setup "$tmp/build" "$src" --prefix="$prefix" --libdir=lib \
  --buildtype=release -Dtests=disabled -Dtutorial=false -Ddocs=disabled -Dpython=enabled \
  -Dpython.install_env=prefix >"$tmp/setup.log" 2>&1 ||
  { cat "$tmp/setup.log"; exit 1; }
"$meson" compile -C "$tmp/build" >"$tmp/compile.log" 2>&1 ||
  { cat "$tmp/compile.log"; exit 1; }
"$meson" install -C "$tmp/build" --quiet
rm -rf "$tmp/build"

step "installed package"
init=$(find "$prefix" -path '*/pypw85/__init__.py')
[ "$(printf '%s\n' "$init" | grep -c .)" = 1 ] ||
  { echo "expected one pypw85/__init__.py under $prefix, found: '$init'"; exit 1; }
pkg=$(dirname "$init")
site=$(dirname "$pkg")
echo "site dir: ${site#"$prefix"/}"
for f in __init__.py legacy.py _paths.py; do
  [ -f "$pkg/$f" ] || { echo "missing: $pkg/$f"; exit 1; }
done
cat "$pkg/_paths.py"
grep -qF "LIBPW85 = '$prefix/lib/libpw85.so.2'" "$pkg/_paths.py" ||
  { echo "_paths.py does not name $prefix/lib/libpw85.so.2"; exit 1; }
legacy=
if grep -qF "LIBPW85_LEGACY = '$prefix/lib/libpw85_legacy.so.2'" "$pkg/_paths.py"; then
  legacy=$prefix/lib/libpw85_legacy.so.2
  [ -e "$legacy" ] || { echo "missing: $legacy"; exit 1; }
else
  grep -qF "LIBPW85_LEGACY = None" "$pkg/_paths.py" ||
    { echo "_paths.py: unexpected LIBPW85_LEGACY"; exit 1; }
fi

# From a directory holding no pypw85, with only the installed site dir on
# the path.
cd "$tmp"

step "import pypw85 with no PW85_LIBRARY and no LD_LIBRARY_PATH"
PYTHONPATH=$site "$python" -W error::RuntimeWarning - "$prefix" "$site" "$legacy" <<'PY'
import os
import sys

import pypw85

prefix, site, legacy = sys.argv[1:]
assert pypw85.__file__ == os.path.join(site, "pypw85", "__init__.py"), \
    pypw85.__file__
assert pypw85._library_path == prefix + "/lib/libpw85.so.2", \
    pypw85._library_path
q1 = pypw85.spheroid(10.0, 0.1, [0.0, 0.0, 1.0])
q2 = pypw85.spheroid(0.5, 5.0, [1.0, 0.0, 0.0])
mu2, lambda_ = pypw85.contact_function([0.7, -0.7, 1.1], q1, q2)
print("pypw85 %s from %s" % (pypw85.__version__, pypw85._library_path))
print("contact_function: mu2 = %r, lambda = %r" % (mu2, lambda_))
assert abs(mu2 - 3.3627060406386292) <= 1e-15 * mu2, mu2
if legacy:
    import pypw85.legacy
    assert pypw85.legacy._library_path == legacy, \
        pypw85.legacy._library_path
    mu2_2, _ = pypw85.legacy.contact_function2([0.7, -0.7, 1.1], q1, q2)
    print("legacy from %s: contact_function2: mu2 = %r"
          % (pypw85.legacy._library_path, mu2_2))
PY

step "the tutorial against the installed copy"
PYTHONPATH=$site "$python" "$src/tutorial/tutorial.py" >"$tmp/tutorial.log" 2>&1 ||
  { cat "$tmp/tutorial.log"; echo "tutorial.py failed"; exit 1; }
cat "$tmp/tutorial.log"
grep -q '^μ² = 3\.36270604063' "$tmp/tutorial.log" ||
  { echo "tutorial.py does not print μ² = 3.36270604063..."; exit 1; }
echo "ok: the installed pypw85 finds its libraries with no configuration"
