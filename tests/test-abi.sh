#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The ABI of a shared library, as the dynamic loader sees it, must be
# exactly the committed list: its version nodes, each with the node it
# inherits (readelf -V), and its exported symbols, each with its node
# (nm -D). An ABI change is always deliberate. With headers: every
# exported function is declared in one of them, in the node of its @since
# (PREFIX_MAJOR.MINOR; no @since: the oldest node).
# Usage: test-abi.sh NM READELF LIBRARY SYMBOL-LIST [NODE-PREFIX HEADER...]
set -eu
nm=$1 readelf=$2 lib=$3 expected=$4 prefix=${5:-}
shift 4
[ $# -eq 0 ] || shift
export LC_ALL=C
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

# Version definitions, in order, but the base one (the soname):
# "NODE" or "NODE PARENT".
"$readelf" -V -W "$lib" | awk '
  /^Version definition section/ { d = 1; next }
  /^Version (needs|symbols) section/ { d = 0 }
  d && /Name:/ && !/Flags: BASE/ { if (node != "") print line; node = $NF; line = node }
  d && /Parent 1:/ { line = line " " $NF }
  END { if (node != "") print line }' >"$tmp/actual"
# Defined symbols: "NAME@@NODE" (default version), "NAME@NODE" (an older
# one), or "NAME" (unversioned); the nodes themselves (type A) are above.
"$nm" -D --defined-only "$lib" | awk '$2 != "A" { print $3 }' | sort >>"$tmp/actual"
grep -v -e '^#' -e '^$' "$expected" >"$tmp/expected"

status=0
if cmp -s "$tmp/expected" "$tmp/actual"; then
  echo "ok: $(grep -c @ "$tmp/actual" || true) symbols in $(grep -vc @ "$tmp/actual" || true) version nodes, as in $expected"
else
  echo "the ABI of $lib differs from $expected (< expected, > actual):"
  diff "$tmp/expected" "$tmp/actual" || true
  status=1
fi

[ $# -gt 0 ] || exit "$status"
# "NAME SINCE" for every PW85_API function of the headers (SINCE: "-" when
# its comment has no @since); the name is the first identifier followed by
# "(" on the PW85_API line or the next.
awk '
  /\/\*\*/ { since = "-" }
  match($0, /@since [0-9]+\.[0-9]+/) { since = substr($0, RSTART + 7, RLENGTH - 7) }
  /^PW85_API/ { pending = 2 }
  pending > 0 {
    if (match($0, /pw85[A-Za-z0-9_]*[ \t]*\(/)) {
      name = substr($0, RSTART, RLENGTH - 1); sub(/[ \t]+$/, "", name)
      print name, since; pending = 0; since = "-"
    } else pending--
  }' "$@" >"$tmp/declared"
oldest=$(sed -n '1{s/ .*//;p;}' "$tmp/actual")
grep @ "$tmp/actual" | while IFS= read -r entry; do
  name=${entry%%@*} node=${entry##*@}
  since=$(awk -v n="$name" '$1 == n { print $2 }' "$tmp/declared")
  case $since in
    '') echo "$name is exported but not declared in $*" ;;
    -) [ "$node" = "$oldest" ] ||
         echo "$name has no @since in $* but is in $node, not $oldest" ;;
    *) [ "$node" = "${prefix}_$since" ] ||
         echo "$name is @since $since in $* but in $node, not ${prefix}_$since" ;;
  esac
done >"$tmp/since"
if [ -s "$tmp/since" ]; then
  cat "$tmp/since"
  status=1
else
  echo "ok: every exported function is declared in $*, in the node of its @since"
fi
exit "$status"
