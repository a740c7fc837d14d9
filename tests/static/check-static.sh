#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# A program linked with the archives needs no libpw85 at run time, and
# prints what it should.
# Usage: check-static.sh READELF EXPECTED-OUTPUT|- PROGRAM
set -eu
readelf=$1 expected=$2 program=$3
if "$readelf" -d "$program" | grep 'NEEDED.*libpw85'; then
  echo "FAIL: $program needs a shared libpw85 (above)"
  exit 1
fi
if [ "$expected" = - ]; then
  exec "$program"
fi
exec "$(dirname "$0")/../check-output.sh" "$expected" "$program"
