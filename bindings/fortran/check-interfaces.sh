#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Every function that the C headers declare (PW85_API) has a bind(C)
# interface of the same name in the Fortran module, and the module binds
# nothing else.
# Usage: check-interfaces.sh HEADER... MODULE-SOURCE
set -eu
[ $# -ge 2 ] || { echo "usage: $0 HEADER... MODULE-SOURCE" >&2; exit 2; }
headers=
while [ $# -gt 1 ]; do
  headers="$headers $1"
  shift
done
module=$1
export LC_ALL=C
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
# The name of a PW85_API function: the first identifier followed by "(" on
# its PW85_API line or the next.
awk '/^PW85_API/ { pending = 2 }
  pending > 0 {
    if (match($0, /pw85[A-Za-z0-9_]*[ \t]*\(/)) {
      name = substr($0, RSTART, RLENGTH - 1); sub(/[ \t]+$/, "", name)
      print name; pending = 0
    } else pending--
  }' $headers | sort >"$tmp/declared"
sed -n "s/.*bind(C, name='\([A-Za-z0-9_]*\)').*/\1/p" "$module" | sort >"$tmp/bound"
if cmp -s "$tmp/declared" "$tmp/bound"; then
  echo "ok: the $(wc -l <"$tmp/bound") functions of$headers are bound in $module"
  exit 0
fi
echo "functions of$headers (<) and bind(C) interfaces of $module (>) differ:"
diff "$tmp/declared" "$tmp/bound" || true
exit 1
