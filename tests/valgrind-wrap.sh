#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The exe_wrapper of `meson test --setup=valgrind` (root meson.build): runs
# PROGRAM under VALGRIND (options from VALGRIND_OPTS, which the setup sets)
# when it is a program of this build, and as is when it is a script or a
# system program (/usr, /bin: CPython, meson, qemu), whose memory is not
# ours to check and which valgrind would only slow down a hundredfold.
# Usage: valgrind-wrap.sh VALGRIND PROGRAM [ARGS...]
set -eu
valgrind=$1
shift
case "$1" in
  /usr/* | /bin/*) exec "$@" ;;
esac
if [ "$(head -c 2 "$1")" = '#!' ]; then
  exec "$@"
fi
exec "$valgrind" "$@"
