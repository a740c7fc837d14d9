#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# pw85 as a subproject: the stand-alone consumer of tutorial/consumer, as
# a parent project with this source tree in subprojects/pw85, builds the
# library and nothing else (no tests, tutorials, legacy library, Python
# package, Fortran module or documentation), installs only the library and
# the files that describe it into the parent's prefix (never the reference
# data), and its tutorials print the expected figures. A parent that asks
# for the legacy library gets it.
# Usage: test-subproject.sh MESON SOURCE-DIR
set -eu
meson=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

step() { echo "== $*"; }

# The parent: tutorial/ (consumer/ and the tutorials it builds), with a
# link to this tree as its subproject.
cp -R "$src/tutorial" "$tmp/tutorial"
parent=$tmp/tutorial/consumer
rm -rf "$parent/subprojects"
mkdir "$parent/subprojects"
ln -s "$src" "$parent/subprojects/pw85"

step "configure the parent, pw85 as its subproject"
"$meson" setup "$tmp/build" "$parent" --force-fallback-for=pw85 \
  --prefix="$tmp/prefix" --libdir=lib >"$tmp/setup.log" 2>&1 ||
  { cat "$tmp/setup.log"; exit 1; }
sed -n '/^pw85 /,/^pw85-consumer/p' "$tmp/setup.log" | grep -E ':' || true

step "what pw85 builds there"
"$meson" introspect --targets "$tmp/build" >"$tmp/targets.json"
names=$(/usr/bin/env python3 -c '
import json, sys
for t in json.load(open(sys.argv[1])):
    if t["subproject"] == "pw85":
        print(t["name"])' "$tmp/targets.json" 2>/dev/null ||
  sed 's/"name": "/\n&/g' "$tmp/targets.json" | sed -n 's/^"name": "\([^"]*\)".*/\1/p')
printf '%s\n' $names
for name in $names; do
  case $name in
    pw85|pw85-core|pw85-batch|pw85-index|pw85-pack-core|pw85-image) ;;
    *) echo "FAIL: the subproject builds '$name'"; exit 1 ;;
  esac
done
"$meson" introspect --tests "$tmp/build" | grep -q '"name"' &&
  { echo "FAIL: the subproject registers tests"; exit 1; }

step "build"
start=$(date +%s)
"$meson" compile -C "$tmp/build" >"$tmp/compile.log" 2>&1 ||
  { cat "$tmp/compile.log"; exit 1; }
echo "$(grep -c '^\[' "$tmp/compile.log") steps, $(($(date +%s) - start)) s"

step "what it installs into the parent's prefix"
"$meson" install -C "$tmp/build" --destdir "$tmp/destdir" --quiet
(cd "$tmp/destdir" && find . ! -type d | sed 's|^\./||' | sort) >"$tmp/installed"
sed "s|^${tmp#/}/prefix/||" "$tmp/installed" | tee "$tmp/installed-rel"
unexpected=$(grep -v -E '^(include/pw85/pw85(\.h|\.hpp|_index\.h|_index\.hpp|_pack\.h|_pack\.hpp|_image\.h|_image\.hpp|_2d\.h|_2d_index\.h|_2d_index\.hpp|_2d_pack\.h|_2d_pack\.hpp|_version\.h)|lib/libpw85\.so(\.[0-9.]+)?|lib/pkgconfig/pw85\.pc|lib/cmake/pw85/pw85Config(Version)?\.cmake)$' \
  "$tmp/installed-rel" || true)
[ -z "$unexpected" ] || { echo "FAIL: installed: $unexpected"; exit 1; }

step "run the parent's programs"
for exe in tutorial tutorial-cpp; do
  "$src/tests/check-output.sh" "$src/tutorial/expected-output.txt" "$tmp/build/$exe"
done

step "a parent that asks for the legacy library gets it"
"$meson" configure "$tmp/build" -Dpw85:legacy=true >/dev/null
"$meson" setup --reconfigure "$tmp/build" "$parent" >"$tmp/reconfigure.log" 2>&1 ||
  { cat "$tmp/reconfigure.log"; exit 1; }
"$meson" introspect --targets "$tmp/build" | grep -q '"name": "pw85_legacy"' ||
  { echo "FAIL: no pw85_legacy target with -Dpw85:legacy=true"; exit 1; }
echo "ok: pw85 as a subproject builds and installs the library alone"
