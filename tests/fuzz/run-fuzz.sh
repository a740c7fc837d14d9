#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# run-fuzz.sh TARGET CORPUS WORKDIR RUNS [libFuzzer options...]
# Runs a fuzz target for RUNS executions with seed 1 on a fresh copy of the
# committed corpus CORPUS, in WORKDIR (recreated), so that the source tree
# is never written. Crash inputs are saved in WORKDIR. Exit status: the
# target's (0: no contract violated, no sanitizer report; 1 otherwise:
# not 77, libFuzzer's default, which meson reads as a skip).
set -eu
exe=$1 corpus=$2 work=$3 runs=$4
shift 4
rm -rf "$work"
mkdir -p "$work/corpus"
cp "$corpus"/* "$work/corpus/"
exec "$exe" -runs="$runs" -seed=1 -print_final_stats=1 \
  -error_exitcode=1 -timeout_exitcode=1 \
  -artifact_prefix="$work/" "$@" "$work/corpus"
