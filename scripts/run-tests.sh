#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The whole test suite: every test of a release-like build, then every test
# again in a build instrumented by AddressSanitizer and UndefinedBehavior-
# Sanitizer (any report fails the test), then the C test programs under
# valgrind memcheck, and the multi-threaded tests under ThreadSanitizer;
# a build with both kinds of library (default_library=both): the archives,
# the ABI and the bindings again.
# Build trees: build/, build-asan/, build-tsan/, build-both/, build-fuzz/.
set -eu
cd "$(dirname "$0")/.."

[ -f build/build.ninja ] || meson setup build
meson test -C build --print-errorlogs

[ -f build-asan/build.ninja ] ||
  meson setup build-asan -Db_sanitize=address,undefined -Db_lundef=false
ASAN_OPTIONS=halt_on_error=1:abort_on_error=1 \
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
  meson test -C build-asan --print-errorlogs

# --- both kinds of library (issue 18) -----------------------------------
# default_library=both: the tests of the archives (suite 'static'), and the
# suites that link or load the library (unit, abi, tutorial, legacy, the
# bindings), now next to an archive of the same name. Not the reference
# data, Python, install and docs suites: build/ runs them.
[ -f build-both/build.ninja ] ||
  meson setup build-both -Ddefault_library=both -Ddocs=disabled -Dpython=disabled
ninja -C build-both -j2
meson test -C build-both --no-rebuild --print-errorlogs --suite static \
  --suite unit --suite abi --suite tutorial --suite legacy --suite fortran \
  --suite node
# --- end of both kinds of library ---------------------------------------

# --- checkers (issue 14, item 3) ---------------------------------------
# valgrind memcheck: the C test programs of build/ (suites unit, ref-data,
# legacy, abi; not CPython, meson or qemu), any error or definite leak a
# failure (meson.build, setup 'valgrind'; log:
# build/meson-logs/testlog-valgrind.json).
if command -v valgrind >/dev/null; then
  meson test -C build --setup=valgrind --print-errorlogs \
    --suite unit --suite ref-data --suite legacy --suite abi --no-suite python
else
  echo "valgrind not found: memcheck run skipped"
fi
# ThreadSanitizer: the multi-threaded tests (test-threads; test-batch,
# whose batches run concurrently from several threads; test-index, whose
# queries run from several threads at once), in a build whose kernels have
# no target_clones (fma_clones=false: TSan crashes in their ifunc resolver
# at start-up) and without OpenMP (openmp=disabled: libgomp is not
# instrumented, and TSan reports its fork and join as races; the batches
# and the all-pairs queries then run in the calling thread there, and their
# OpenMP threads are tested for identical results in the other builds).
# Only what they need is built.
[ -f build-tsan/build.ninja ] ||
  meson setup build-tsan -Db_sanitize=thread -Dfma_clones=false \
    -Ddocs=disabled -Dpython=disabled -Dopenmp=disabled
meson configure build-tsan -Dopenmp=disabled
ninja -C build-tsan -j2 tests/test-threads tests/test-batch tests/test-index
TSAN_OPTIONS=halt_on_error=1 \
  meson test -C build-tsan --no-rebuild --print-errorlogs threads batch index
# --- end of checkers ----------------------------------------------------

# ---- fuzz (issue 14, item 1) ------------------------------------------
# When clang is present: the libFuzzer targets of tests/fuzz, built with
# ASan and UBSan in build-fuzz/, each replaying every committed input of
# its corpus once, in a fixed order (suite 'fuzz', tests/fuzz/run-fuzz.sh).
# Campaigns: scripts/fuzz-campaign.sh, docs/testing.rst, "Fuzzing".
if command -v clang >/dev/null 2>&1 && command -v clang++ >/dev/null 2>&1; then
  [ -f build-fuzz/build.ninja ] ||
    CC=clang CXX=clang++ meson setup build-fuzz -Dfuzz=enabled \
      -Ddocs=disabled -Dpython=disabled -Dtests=enabled
  # Only the fuzz targets are built there (not the whole project again).
  ninja -C build-fuzz tests/fuzz/fuzz-contact-raw \
    tests/fuzz/fuzz-contact-structured tests/fuzz/fuzz-f \
    tests/fuzz/fuzz-legacy tests/fuzz/fuzz-geometry tests/fuzz/fuzz-index \
    tests/fuzz/fuzz-2d
  meson test -C build-fuzz --no-rebuild --suite fuzz --print-errorlogs
else
  echo "run-tests.sh: clang not found, fuzz targets not run"
fi
# ---- end fuzz ---------------------------------------------------------
