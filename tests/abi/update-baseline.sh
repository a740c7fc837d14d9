#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Regenerate the ABI baselines (tests/abi/*.abi) from the libraries of a
# build directory (configured with debug information: the default
# buildtype, debugoptimized, has it). A release runs it, reviews the diff
# and commits it with the version bump; tests/abi/check-abi.sh then
# compares every later build with it.
# Usage: tests/abi/update-baseline.sh [BUILD-DIR]   (default: build)
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${1:-build}
. "$here/abi-options.sh"
abidw=${ABIDW:-abidw}
command -v "$abidw" >/dev/null ||
  { echo "abidw not found (Debian: apt-get install abigail-tools)" >&2; exit 1; }
for lib in src/libpw85.so.2 src/legacy/libpw85_legacy.so.2; do
  [ -e "$build/$lib" ] || { echo "no $build/$lib: build it first" >&2; exit 1; }
  out="$here/$(basename "$lib" .so.2).abi"
  # shellcheck disable=SC2086 # the option lists are word-split on purpose
  "$abidw" $abi_common_options $abidw_options \
    --headers-dir "$root/include/pw85" --out-file "$out.tmp" "$build/$lib"
  # The one path left is each translation unit's, as the compiler saw it
  # from the build directory: keep it relative to the source root.
  # The licence and provenance go inside the root element: abidiff
  # recognises an ABI file by its first bytes, <abi-corpus.
  sed -E -e "s|(<abi-instr [^>]*path=')[^']*/(src/[^']*')|\1\2|" \
    -e '1a\  <!-- SPDX-License-Identifier: BSD-3-Clause -->' \
    -e '1a\  <!-- The ABI of the last release, written by tests/abi/update-baseline.sh -->' \
    "$out.tmp" >"$out"
  rm -f "$out.tmp"
  echo "wrote $out"
done
