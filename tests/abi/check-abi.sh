#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The built library against the committed ABI baseline of the last release
# (tests/abi/*.abi, written by update-baseline.sh), with libabigail's abidiff.
# Passes when nothing changed or when the only changes are additions (they
# are printed); fails on any removed or changed function, variable or
# symbol, on an incompatible change (abidiff exit bit 8) and on an error of
# abidiff. Exit status 77 (a skip) when abidiff is not installed or the
# library has no debug information (buildtype=release, stripped).
# Usage: check-abi.sh ABIDIFF HEADERS-DIR BASELINE LIBRARY
# (ABIDIFF empty or not found: skip)
set -u
abidiff=$1 headers=$2 baseline=$3 lib=$4
here=$(cd "$(dirname "$0")" && pwd)
. "$here/abi-options.sh"

if [ -z "$abidiff" ] || ! command -v "$abidiff" >/dev/null; then
  echo "SKIP: abidiff not found (Debian: apt-get install abigail-tools)"
  exit 77
fi

# Without DWARF, abidiff compares symbol names only and would pass a
# changed parameter type (its --fail-no-debug-info does not catch a
# stripped library): ask abidw, from the same package, for declarations.
abidw=$(dirname "$(command -v "$abidiff")")/abidw
# shellcheck disable=SC2086 # the option lists are word-split on purpose
if ! "$abidw" $abi_common_options "$lib" 2>/dev/null | grep -q '<function-decl'; then
  echo "SKIP: no debug information in $lib (abidw finds no function declaration)"
  exit 77
fi

# shellcheck disable=SC2086
report=$("$abidiff" $abi_common_options \
  --headers-dir2 "$headers" "$baseline" "$lib" 2>&1)
status=$?
printf '%s\n' "$report"

if [ $((status & 3)) -ne 0 ]; then
  # Bit 1: an error, bit 2: a usage error.
  echo "FAIL: abidiff could not compare $lib with $baseline (exit status $status)"
  exit 1
fi
if [ $((status & 8)) -ne 0 ]; then
  echo "FAIL: incompatible ABI change in $lib against $baseline (above)"
  exit 1
fi
if [ $((status & 4)) -ne 0 ]; then
  # An ABI change that abidiff does not call incompatible: a pass only if
  # every summary counts 0 removed and 0 changed and nothing else changed.
  bad=$(printf '%s\n' "$report" | grep -E \
    '[1-9][0-9]* (Removed|Changed)|SONAME changed|architecture changed' || true)
  if [ -n "$bad" ]; then
    echo "FAIL: ABI change in $lib against $baseline that is not an addition:"
    printf '%s\n' "$bad"
    exit 1
  fi
  echo "ok: additions only (above), compatible with $baseline;"
  echo "    a release records them with tests/abi/update-baseline.sh"
  exit 0
fi
echo "ok: the ABI of $lib is that of $baseline"
exit 0
