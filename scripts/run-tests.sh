#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite: every test of a release-like build, then every test
# again in a build instrumented by AddressSanitizer and UndefinedBehavior-
# Sanitizer (any report fails the test). Build trees: build/, build-asan/.
set -eu
cd "$(dirname "$0")/.."

[ -f build/build.ninja ] || meson setup build
meson test -C build --print-errorlogs

[ -f build-asan/build.ninja ] ||
  meson setup build-asan -Db_sanitize=address,undefined -Db_lundef=false
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1 \
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  meson test -C build-asan --print-errorlogs

# ---- fuzz (issue 14, item 1) ------------------------------------------
# When clang is present: the libFuzzer targets of tests/fuzz, built with
# ASan and UBSan in build-fuzz/, each run for a short fixed number of
# executions from a copy of the committed corpus (suite 'fuzz'). Long runs:
# docs/testing.rst, "Fuzzing".
if command -v clang >/dev/null 2>&1 && command -v clang++ >/dev/null 2>&1; then
  [ -f build-fuzz/build.ninja ] ||
    CC=clang CXX=clang++ meson setup build-fuzz -Dfuzz=enabled \
      -Ddocs=disabled -Dpython=disabled -Dtests=enabled
  # Only the fuzz targets are built there (not the whole project again).
  ninja -C build-fuzz tests/fuzz/fuzz-contact-raw \
    tests/fuzz/fuzz-contact-structured tests/fuzz/fuzz-f \
    tests/fuzz/fuzz-legacy
  meson test -C build-fuzz --no-rebuild --suite fuzz --print-errorlogs
else
  echo "run-tests.sh: clang not found, fuzz targets not run"
fi
# ---- end fuzz ---------------------------------------------------------
