#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# What the version nodes are for: a program that needs a newer library than
# the one installed fails to start, with a message that names the version.
# For every version node N of LIBRARY but the oldest, that has a symbol:
# - a probe program that uses one symbol of N is linked against LIBRARY
#   (its requirement of N must then appear in its own version needs);
# - an older library is built, with LIBRARY's soname and the symbols and
#   nodes of LIBRARY up to the node before N (what an older release
#   exported, by the policy of pw85.h; stub functions suffice: the loader
#   checks versions before anything runs);
# - the probe must start with LIBRARY, and must fail to start with the
#   older library, the loader naming N ("version `N' not found").
# The probe of the oldest node must start with every older library.
# Usage: test-symbol-versions.sh CC NM READELF LIBRARY
set -eu
cc=$1 nm=$2 readelf=$3 lib=$4
export LC_ALL=C
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM

soname=$("$readelf" -d "$lib" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
[ -n "$soname" ] || { echo "$lib has no soname"; exit 1; }
# "NODE [PARENT]" in order of definition, then "NAME NODE" per symbol.
"$readelf" -V -W "$lib" | awk '
  /^Version definition section/ { d = 1; next }
  /^Version (needs|symbols) section/ { d = 0 }
  d && /Name:/ && !/Flags: BASE/ { print $NF }' >"$tmp/nodes"
"$nm" -D --defined-only "$lib" | awk '$3 ~ /@@/ { split($3, s, "@@"); print s[1], s[2] }' |
  sort >"$tmp/symbols"
[ "$(wc -l <"$tmp/nodes")" -ge 2 ] ||
  { echo "$lib has fewer than two version nodes:"; cat "$tmp/nodes"; exit 1; }

# probe NODE: a program that uses the first symbol of NODE, linked against
# LIBRARY; prints its path, or nothing when NODE has no symbol.
probe() {
  sym=$(awk -v n="$1" '$2 == n { print $1; exit }' "$tmp/symbols")
  [ -n "$sym" ] || return 0
  printf 'extern void %s(void);\nint main(void) {\n  void (*volatile p)(void) = %s;\n  return p == 0;\n}\n' \
    "$sym" "$sym" >"$tmp/probe-$1.c"
  "$cc" "$tmp/probe-$1.c" "$lib" -o "$tmp/probe-$1"
  "$readelf" -V -W "$tmp/probe-$1" | grep -q "Name: $1 " ||
    { echo "probe-$1 (uses $sym) does not require $1:"; "$readelf" -V -W "$tmp/probe-$1"; exit 1; }
  echo "$tmp/probe-$1"
}

# older NODE: LIBRARY as it was before NODE, in $tmp/before-NODE/.
older() {
  dir=$tmp/before-$1
  mkdir "$dir"
  : >"$dir/stub.c"
  : >"$dir/stub.map"
  parent= local='local: *;'
  while read -r node; do
    [ "$node" != "$1" ] || break
    printf '%s {\n  global:\n' "$node" >>"$dir/stub.map"
    awk -v n="$node" '$2 == n { print "    " $1 ";" }' "$tmp/symbols" >>"$dir/stub.map"
    awk -v n="$node" '$2 == n { print "void " $1 "(void) {}" }' "$tmp/symbols" >>"$dir/stub.c"
    printf '  %s\n} %s;\n' "$local" "$parent" >>"$dir/stub.map"
    parent=$node local=
  done <"$tmp/nodes"
  "$cc" -shared -fPIC -o "$dir/$soname" -Wl,-soname,"$soname" \
    -Wl,--version-script,"$dir/stub.map" "$dir/stub.c"
}

oldest=$(sed -n 1p "$tmp/nodes")
base_probe=$(probe "$oldest")
[ -n "$base_probe" ] || { echo "no symbol in the oldest node, $oldest"; exit 1; }
libdir=$(cd "$(dirname "$lib")" && pwd)
shown=0 status=0
for node in $(sed 1d "$tmp/nodes"); do
  exe=$(probe "$node")
  if [ -z "$exe" ]; then
    echo "-- $node: no symbol yet, so no program can require it"
    continue
  fi
  older "$node"
  echo "-- $node: $(basename "$exe") uses $(awk -v n="$node" '$2 == n { print $1; exit }' "$tmp/symbols")@@$node"
  if ! LD_LIBRARY_PATH=$libdir "$exe"; then
    echo "FAIL: it does not start with $lib"; status=1
  fi
  if LD_LIBRARY_PATH=$tmp/before-$node "$base_probe"; then :; else
    echo "FAIL: the library before $node does not load a program that needs $oldest only"; status=1
  fi
  if LD_LIBRARY_PATH=$tmp/before-$node "$exe" 2>"$tmp/err"; then
    echo "FAIL: it starts with a library without $node"; status=1
  elif grep -q "version \`$node' not found" "$tmp/err"; then
    echo "ok: with a library without $node, the loader says:"
    sed 's/^/   /' "$tmp/err"
    shown=$((shown + 1))
  else
    echo "FAIL: with a library without $node, it fails without naming $node:"
    cat "$tmp/err"; status=1
  fi
done
[ "$shown" -gt 0 ] || { echo "FAIL: no node shown"; status=1; }
exit "$status"
