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
