# SPDX-License-Identifier: BSD-3-Clause
# The libabigail options shared by update-baseline.sh (abidw) and
# check-abi.sh (abidiff), sourced by both: only the interfaces that the
# library exports and the types its public headers declare count.
# shellcheck shell=sh
abi_common_options="--drop-private-types --exported-interfaces-only"
# abidw only: no absolute paths, no source locations, type ids that do not
# depend on the order of the DWARF, so that the file is reproducible.
abidw_options="--no-corpus-path --no-comp-dir-path --no-show-locs --type-id-style hash"
