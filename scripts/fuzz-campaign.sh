#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# A fuzz campaign: runs libFuzzer targets of tests/fuzz, each for a given
# time, mutating from the committed corpus, and keeps what they find.
#
#   scripts/fuzz-campaign.sh [-t SECONDS] [-s SEED] [-o DIR] [TARGET...]
#
#   -t  seconds per target (default 1800: the campaign length of record)
#   -s  libFuzzer's seed (default: from the clock, printed, so that a run
#       can be repeated; its path can still differ: comparison tracing and
#       address-space randomisation are not reproducible)
#   -o  where findings go (default fuzz-findings/ at the top of the tree):
#       DIR/TARGET/crash-*, timeout-*, leak-*, with the log DIR/TARGET.log;
#       the grown corpus in DIR/TARGET/corpus (the committed one untouched)
#   TARGET  contact-raw contact-structured f legacy geometry index 2d
#           (default: all)
#
# Targets run one after another, each with one job per core (-fork); the
# build is build-fuzz/ (clang, -Dfuzz=enabled), set up if missing.
#
# A finding becomes a regression seed:
#   1. replay it:   build-fuzz/tests/fuzz/fuzz-TARGET DIR/TARGET/crash-...
#   2. minimise:    build-fuzz/tests/fuzz/fuzz-TARGET -minimize_crash=1 \
#                     -runs=100000 -exact_artifact_path=/tmp/min FILE
#   3. commit it as tests/fuzz/corpus/CORPUS/regress-NAME (CORPUS: the
#      target's corpus, contact-raw for geometry), with the fix and a unit
#      test of the same input; suite 'fuzz' then replays it on every run.
set -eu
cd "$(dirname "$0")/.."
seconds=1800 seed=$(date +%s) out=fuzz-findings
while getopts t:s:o: opt; do
  case $opt in
    t) seconds=$OPTARG ;;
    s) seed=$OPTARG ;;
    o) out=$OPTARG ;;
    *) sed -n '3,30p' "$0"; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
targets=${*:-contact-raw contact-structured f legacy geometry index 2d}
jobs=$(nproc 2>/dev/null || echo 1)

[ -f build-fuzz/build.ninja ] ||
  CC=clang CXX=clang++ meson setup build-fuzz -Dfuzz=enabled \
    -Ddocs=disabled -Dpython=disabled -Dtests=enabled
for t in $targets; do
  ninja -C build-fuzz "tests/fuzz/fuzz-$t"
done

echo "fuzz-campaign: seed $seed, $seconds s per target, findings in $out/"
found=0
for t in $targets; do
  case $t in geometry) corpus=contact-raw ;; *) corpus=$t ;; esac
  mkdir -p "$out/$t/corpus"
  cp tests/fuzz/corpus/"$corpus"/* "$out/$t/corpus/"
  echo "fuzz-campaign: $t ..."
  build-fuzz/tests/fuzz/fuzz-"$t" -seed="$seed" -max_total_time="$seconds" \
    -fork="$jobs" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -timeout=60 -artifact_prefix="$out/$t/" -print_final_stats=1 \
    "$out/$t/corpus" >"$out/$t.log" 2>&1 || true
  n=$(find "$out/$t" -maxdepth 1 -type f \
        \( -name 'crash-*' -o -name 'timeout-*' -o -name 'leak-*' \) | wc -l)
  echo "fuzz-campaign: $t: $n finding(s)$(tail -n 3 "$out/$t.log" | tr '\n' ' ')"
  found=$((found + n))
done
echo "fuzz-campaign: $found finding(s) in all"
[ "$found" -eq 0 ]
