#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Installs pw85, shared and static (default_library=both), into a temporary
# prefix and checks what was installed; then uses that copy as a user
# would: the stand-alone Meson project of tutorial/consumer through
# pkg-config; the tutorial and a program calling both libraries linked
# statically through `pkg-config --static`; the stand-alone CMake project
# of tutorial/consumer-cmake through pw85Config.cmake, shared and static
# (skipped without CMake). Each program must print the expected figures.
# With PACK = yes (HDF5 found), pw85-pack from the prefix, without
# LD_LIBRARY_PATH, writes files that h5py reads back (tests/pack/ checks
# them in detail).
# Usage: test-install.sh MESON SOURCE-DIR NM [CMAKE [PACK]]
set -eu
meson=$1 src=$2 nm=$3 cmake=${4:-} pack=${5:-no}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
prefix=$tmp/prefix

step() { echo "== $*"; }

step "configure, build and install into $prefix"
"$meson" setup "$tmp/build" "$src" --prefix="$prefix" --libdir=lib \
  --buildtype=release -Dtests=disabled -Dtutorial=false -Ddocs=disabled \
  -Dpython=disabled -Ddefault_library=both >"$tmp/setup.log" 2>&1 ||
  { cat "$tmp/setup.log"; exit 1; }
"$meson" compile -C "$tmp/build" >"$tmp/compile.log" 2>&1 ||
  { cat "$tmp/compile.log"; exit 1; }
"$meson" install -C "$tmp/build" --quiet

step "installed files"
for f in include/pw85/pw85.h include/pw85/pw85.hpp include/pw85/pw85_index.hpp \
         include/pw85/pw85_version.h \
         include/pw85/pw85.f90 lib/libpw85.so lib/libpw85.so.2 lib/libpw85.a \
         lib/libpw85_legacy.a lib/pkgconfig/pw85.pc \
         lib/cmake/pw85/pw85Config.cmake lib/cmake/pw85/pw85ConfigVersion.cmake; do
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
expected=$src/tutorial/expected-output.txt
# uses EXE shared|static: EXE loads the installed libpw85.so.2, or no
# libpw85 at all.
uses() {
  if [ "$2" = shared ]; then
    ldd "$1" | grep -q "$prefix/lib/libpw85.so.2" ||
      { echo "$1 does not load the installed library:"; ldd "$1"; exit 1; }
  elif readelf -d "$1" | grep -q 'NEEDED.*libpw85'; then
    echo "$1 is not linked statically:"; readelf -d "$1" | grep NEEDED; exit 1
  fi
}
for exe in tutorial tutorial-cpp; do
  uses "$tmp/consumer/$exe" shared
  "$src/tests/check-output.sh" "$expected" "$tmp/consumer/$exe"
done
echo "ok: installed pw85 found through pkg-config and used"

step "static linking through pkg-config --static"
cc=${CC:-cc}
# The archives instead of the shared libraries, and what they need
# (Libs.private, Requires.private).
static_libs() {
  pkg-config --static --libs "$1" |
    sed 's/-lpw85_legacy\b/-Wl,-Bstatic -lpw85_legacy -Wl,-Bdynamic/; s/-lpw85\b/-Wl,-Bstatic -lpw85 -Wl,-Bdynamic/'
}
# shellcheck disable=SC2046 # the flags are word-split on purpose
"$cc" -o "$tmp/tutorial-static" "$src/tutorial/tutorial.c" \
  $(pkg-config --cflags pw85) $(static_libs pw85)
uses "$tmp/tutorial-static" static
"$src/tests/check-output.sh" "$expected" "$tmp/tutorial-static"
# Both archives in one program: they define nothing twice.
# shellcheck disable=SC2046
"$cc" -o "$tmp/both-static" "$src/tests/static/both.c" \
  $(pkg-config --cflags pw85_legacy) $(static_libs pw85_legacy)
uses "$tmp/both-static" static
"$tmp/both-static"

step "pw85-pack from the installed copy"
for f in include/pw85/pw85_image.h include/pw85/pw85_image.hpp; do
  [ -e "$prefix/$f" ] || { echo "missing: $f"; exit 1; }
done
if [ "$pack" = yes ]; then
  [ -x "$prefix/bin/pw85-pack" ] || { echo "missing: bin/pw85-pack"; exit 1; }
  mkdir "$tmp/pack"
  (cd "$tmp/pack" && env -u LD_LIBRARY_PATH "$prefix/bin/pw85-pack" --n 300 \
     --axes 1,0.5,0.2 --fraction 0.2 --seed 9 --out pack.h5 --xyz pack.xyz \
     --voxels 16)
  # and ellipses (--2d): the 2D layout
  (cd "$tmp/pack" && env -u LD_LIBRARY_PATH "$prefix/bin/pw85-pack" --2d --n 300 \
     --axes 1,0.5 --fraction 0.5 --seed 9 --out flat.h5 --voxels 16)
  /usr/bin/python3 - "$tmp/pack" <<'PY'
import math, os, sys
import h5py
d = sys.argv[1]
assert sorted(os.listdir(d)) == ["flat.h5", "flat.xdmf", "pack.h5", "pack.xdmf",
                                 "pack.xyz"], os.listdir(d)
with h5py.File(os.path.join(d, "pack.h5"), "r") as f:
    assert f["centres"].shape == (300, 3) and f["forms"].shape == (300, 6)
    assert f["image"].shape == (16, 16, 16)
    assert f.attrs["seed"] == 9 and f.attrs["method"] == "fire"  # the default
    assert "dimension" not in f.attrs
    v = 4 / 3 * math.pi * 0.1 * 300 / f["box"][()].prod()
    assert abs(f.attrs["packing_fraction"] - v) < 1e-15, f.attrs["packing_fraction"]
with h5py.File(os.path.join(d, "flat.h5"), "r") as f:
    assert f["centres"].shape == (300, 2) and f["forms"].shape == (300, 3)
    assert f["angles"].shape == (300,) and f["image"].shape == (16, 16)
    assert f.attrs["dimension"] == 2 and f.attrs["method"] == "fire"
    a = math.pi * 0.5 * 300 / f["box"][()].prod()
    assert abs(f.attrs["packing_fraction"] - a) < 1e-15, f.attrs["packing_fraction"]
print("ok: pw85-pack from the prefix (ellipsoids and --2d), files read back by h5py")
PY
fi

if [ -z "$cmake" ]; then
  echo "cmake not found: the CMake package is not tested"
  exit 0
fi
step "the CMake package: find_package(pw85), shared and static"
for kind in shared static; do
  flag=OFF
  [ $kind = shared ] || flag=ON
  "$cmake" -S "$src/tutorial/consumer-cmake" -B "$tmp/cmake-$kind" \
    -DCMAKE_PREFIX_PATH="$prefix" -DPW85_USE_STATIC_LIBS=$flag \
    >"$tmp/cmake-$kind.log" 2>&1 || { cat "$tmp/cmake-$kind.log"; exit 1; }
  "$cmake" --build "$tmp/cmake-$kind" >>"$tmp/cmake-$kind.log" 2>&1 ||
    { cat "$tmp/cmake-$kind.log"; exit 1; }
  for exe in tutorial tutorial-cpp tutorial-fortran; do
    [ -e "$tmp/cmake-$kind/$exe" ] || { echo "($exe not built)"; continue; }
    echo "-- $kind: $exe"
    uses "$tmp/cmake-$kind/$exe" $kind
    "$src/tests/check-output.sh" "$expected" "$tmp/cmake-$kind/$exe"
  done
done
# The version file: 2.x at least as new as asked; not 3.
mkdir "$tmp/cmake-version"
printf '%s\n' 'cmake_minimum_required(VERSION 3.13)' 'project(v NONE)' \
  'find_package(pw85 ${WANT} REQUIRED COMPONENTS ${COMPONENTS})' \
  'message(STATUS "pw85 ${pw85_VERSION}")' >"$tmp/cmake-version/CMakeLists.txt"
check_cmake() {  # check_cmake ok|fail VERSION [COMPONENT]
  rm -rf "$tmp/cmake-version/build"
  if "$cmake" -S "$tmp/cmake-version" -B "$tmp/cmake-version/build" \
       -DCMAKE_PREFIX_PATH="$prefix" -DWANT="$2" -DCOMPONENTS="${3:-}" \
       >"$tmp/cmake-version.log" 2>&1; then result=ok; else result=fail; fi
  echo "find_package(pw85 $2 ${3:+COMPONENTS $3}): $result"
  [ "$result" = "$1" ] || { cat "$tmp/cmake-version.log"; exit 1; }
}
check_cmake ok 2.1
check_cmake ok 2.1 legacy
check_cmake fail 3.0
check_cmake fail 2.1 nonesuch
echo "ok: the installed CMake package, shared and static"
