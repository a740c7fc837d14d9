#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Runs a program and compares its standard output with a file, exactly.
# Usage: check-output.sh EXPECTED PROGRAM [ARGS...]
set -eu
expected=$1
shift
actual=$("$@")
if [ "$actual" = "$(cat "$expected")" ]; then
  printf '%s\n' "$actual"
  exit 0
fi
echo "output of $* differs from $expected"
echo "--- expected"; cat "$expected"
echo "--- actual"; printf '%s\n' "$actual"
exit 1
