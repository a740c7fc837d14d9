#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The archive hides its internals as well as an archive can: every symbol
# it defines with default visibility (the symbols a shared object linked
# from it would export) is a pw85_* function, but for the dispatchers that
# GCC emits for target_clones with default visibility whatever the flags
# (pw85::detail::*, IFUNC, and their .resolver); and the pw85_* functions
# are exactly those of the shared library's committed list.
# Usage: check-archive.sh READELF ARCHIVE SYMBOL-LIST
set -eu
readelf=$1 archive=$2 expected=$3
export LC_ALL=C
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
# Defined (Ndx not UND), global or weak, default visibility: "TYPE NAME".
"$readelf" -s -W "$archive" |
  awk '$5 ~ /^(GLOBAL|WEAK)$/ && $6 == "DEFAULT" && $7 != "UND" { print $4, $8 }' |
  sort -u >"$tmp/visible"
grep -v -E '^(FUNC pw85_[A-Za-z0-9_]+|IFUNC _ZN4pw856detail[A-Za-z0-9_]+|FUNC _ZN4pw856detail[A-Za-z0-9_]+\.resolver)$' \
  "$tmp/visible" >"$tmp/leaks" || true
awk '$1 == "FUNC" && $2 ~ /^pw85_/ { print $2 }' "$tmp/visible" >"$tmp/api"
grep -v -e '^#' -e '^$' -e '^PW85' "$expected" | sed 's/@.*//' | sort >"$tmp/expected"
status=0
if [ -s "$tmp/leaks" ]; then
  echo "FAIL: $archive gives default visibility to:"; cat "$tmp/leaks"; status=1
fi
if ! cmp -s "$tmp/api" "$tmp/expected"; then
  echo "FAIL: the pw85_* functions of $archive (>) differ from $expected (<):"
  diff "$tmp/expected" "$tmp/api" || true
  status=1
fi
[ "$status" -ne 0 ] ||
  echo "ok: $(wc -l <"$tmp/api") pw85_* functions, $(grep -c detail "$tmp/visible" || true) target_clones dispatchers, nothing else visible"
exit "$status"
