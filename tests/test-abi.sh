#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The exported dynamic symbols of a library must be exactly the committed
# list: an ABI change is always deliberate.
# Usage: test-abi.sh NM LIBRARY SYMBOL-LIST
set -eu
nm=$1 lib=$2 expected=$3
actual=$("$nm" -D --defined-only "$lib" | awk '{ sub(/@.*/, "", $3); print $3 }' | sort)
if [ "$actual" = "$(sort "$expected")" ]; then
  echo "ok: $(printf '%s\n' "$actual" | wc -l) symbols, as in $expected"
  exit 0
fi
echo "exported symbols differ from $expected (< expected, > actual):"
printf '%s\n' "$actual" | diff "$expected" - || true
exit 1
