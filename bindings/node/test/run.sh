#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# node --test on the package, once its dependency is installed (npm ci in
# bindings/node; .ci/run does it): a skip (77) otherwise.
# Usage: run.sh NODE (PW85_LIBRARY and PW85_EXPECTED_VERSION set)
set -eu
node=$1
cd "$(dirname "$0")/.."
if ! "$node" -e "require.resolve('koffi')" 2>/dev/null; then
  echo "SKIP: koffi is not installed: run 'npm ci' in $(pwd)"
  exit 77
fi
exec "$node" --test test/
