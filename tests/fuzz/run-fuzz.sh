#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# run-fuzz.sh TARGET CORPUS...
# Replays every file of the committed corpus directories CORPUS (seed
# inputs and regression seeds, regress-*) through the fuzz target, each
# exactly once, in a fixed order: no mutation, no randomness, so the
# verdict is the same on every run of the same commit. The source tree is
# never written (libFuzzer, given files rather than directories, neither
# mutates nor saves). Exit status: 0 when every input keeps the contract,
# 1 otherwise (not 77, libFuzzer's default, which meson reads as a skip).
# Exploration (mutation for a given time) is scripts/fuzz-campaign.sh.
set -eu
exe=$1
shift
files=$(for dir in "$@"; do find "$dir" -type f; done | LC_ALL=C sort)
[ -n "$files" ] || { echo "run-fuzz.sh: no input in $*" >&2; exit 1; }
set -f  # the names are split on newlines only, never globbed
IFS='
'
# shellcheck disable=SC2086
exec "$exe" -error_exitcode=1 -timeout_exitcode=1 -timeout=60 $files
