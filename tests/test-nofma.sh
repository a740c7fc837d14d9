#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The portable ("default") clones of the FMA-dispatched kernels give results
# bit-identical to the FMA clones: dump-results runs natively (FMA clones on
# a CPU with FMA) and under qemu-x86_64 -cpu Nehalem (no FMA: the load-time
# dispatch picks the default clones), and the two dumps must be equal byte
# for byte. Exit 77 (skip) when qemu-x86_64 is missing or the host has no
# FMA (then both runs would take the same clone).
# Usage: test-nofma.sh QEMU PROBE DUMP WORKDIR DATA...
set -eu
qemu=$1 probe=$2 dump=$3 work=$4
shift 4

if [ "$qemu" = none ]; then
  echo "SKIP: qemu-x86_64 not found (Debian package qemu-user)"
  exit 77
fi
native_clone=$("$probe")
if [ "$native_clone" != fma ]; then
  echo "SKIP: this CPU has no FMA (native run takes the '$native_clone' clone)"
  exit 77
fi
# Nehalem: SSE4.2, no AVX, no FMA. qemu's warnings on stderr are harmless.
emulated_clone=$("$qemu" -cpu Nehalem "$probe")
echo "clone picked: native $native_clone, qemu -cpu Nehalem $emulated_clone"
if [ "$emulated_clone" != default ]; then
  echo "FAIL: under qemu the dispatch did not pick the default clone"
  exit 1
fi

mkdir -p "$work"
echo "native:"
"$dump" "$work/fma.bin" "$@"
echo "qemu-x86_64 -cpu Nehalem:"
"$qemu" -cpu Nehalem "$dump" "$work/nofma.bin" "$@"
if [ -n "${PW85_NOFMA_CORRUPT:-}" ]; then
  # A check of this check: flip one byte of the emulated dump.
  printf '\377' | dd of="$work/nofma.bin" bs=1 seek="$PW85_NOFMA_CORRUPT" \
    conv=notrunc status=none
fi
if cmp "$work/fma.bin" "$work/nofma.bin"; then
  echo "bit-identical: $(wc -c < "$work/fma.bin") bytes"
else
  echo "FAIL: the default clones differ from the FMA clones (cmp above:" \
       "byte offset; records in tests/dump-results.c)"
  exit 1
fi
