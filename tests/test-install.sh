#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Installs pw85 into a temporary prefix, checks what was installed, then
# builds the stand-alone consumer project of tutorial/consumer against that
# copy through pkg-config and runs it.
# Usage: test-install.sh MESON SOURCE-DIR NM
set -eu
meson=$1 src=$2 nm=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix=$tmp/prefix

step() { echo "== $*"; }

step "configure, build and install into $prefix"
"$meson" setup "$tmp/build" "$src" --prefix="$prefix" --libdir=lib \
  --buildtype=release -Dtests=disabled -Dtutorial=false -Ddocs=disabled >"$tmp/setup.log" 2>&1 ||
  { cat "$tmp/setup.log"; exit 1; }
"$meson" compile -C "$tmp/build" >"$tmp/compile.log" 2>&1 ||
  { cat "$tmp/compile.log"; exit 1; }
"$meson" install -C "$tmp/build" --quiet

step "installed files"
for f in include/pw85/pw85.h include/pw85/pw85.hpp include/pw85/pw85_version.h \
         lib/libpw85.so lib/libpw85.so.2 lib/pkgconfig/pw85.pc; do
  [ -e "$prefix/$f" ] || { echo "missing: $f"; exit 1; }
done
soname=$(readelf -d "$prefix/lib/libpw85.so" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
[ "$soname" = libpw85.so.2 ] || { echo "soname: '$soname'"; exit 1; }

step "exported symbols of the installed library"
# (Type A: the version nodes, listed by readelf -V below.)
others=$("$nm" -D --defined-only "$prefix/lib/libpw85.so.2" | awk '$2 != "A" {print $3}' | grep -v '^pw85_' || true)
[ -z "$others" ] || { echo "not pw85_*: $others"; exit 1; }
readelf -V "$prefix/lib/libpw85.so.2" | grep -E 'Name: PW85_|Parent'

step "pkg-config"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
pkg-config --modversion pw85
pkg-config --cflags --libs pw85

step "build the consumer project against the installed copy"
"$meson" setup "$tmp/consumer" "$src/tutorial/consumer" >"$tmp/consumer.log" 2>&1 ||
  { cat "$tmp/consumer.log"; exit 1; }
"$meson" compile -C "$tmp/consumer" >>"$tmp/consumer.log" 2>&1 ||
  { cat "$tmp/consumer.log"; exit 1; }

step "run it"
export LD_LIBRARY_PATH="$prefix/lib"
for exe in tutorial tutorial-cpp; do
  ldd "$tmp/consumer/$exe" | grep -q "$prefix/lib/libpw85.so.2" ||
    { echo "$exe does not load the installed library:"; ldd "$tmp/consumer/$exe"; exit 1; }
  "$src/tests/check-output.sh" "$src/tutorial/expected-output.txt" "$tmp/consumer/$exe"
done
echo "ok: installed pw85 found through pkg-config and used"
