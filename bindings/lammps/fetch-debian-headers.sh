#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The LAMMPS headers that liblammps-dev lacks (atom_vec.h,
# atom_vec_ellipsoid.h, neigh_request.h, lammpsplugin.h, the bundled fmt),
# taken from Debian's source package of the INSTALLED version of lammps,
# and checked: the source's src/version.h must give the version of
# liblammps.pc, and each header that liblammps-dev ships must be
# byte-identical to the source's. Prints the directory that holds the
# headers (its src/), made once and kept in a cache:
#   ${PW85_LAMMPS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/pw85}/lammps-<version>
# Needs: dpkg-query, apt-get and dpkg-source (dpkg-dev), network access to
# a Debian mirror. apt's own configuration is not touched: a deb-src list
# and apt's lists live in a temporary directory.
# Exit status 0: the path on stdout; otherwise the cause on stderr.
set -eu

die() { echo "fetch-debian-headers: $*" >&2; exit 1; }

version=$(dpkg-query -W -f='${Version}' liblammps-dev 2>/dev/null) ||
  die "liblammps-dev is not installed"
[ -n "$version" ] || die "liblammps-dev is not installed"
# The source version: the binary's without a binNMU suffix (+bN).
srcversion=$(dpkg-query -W -f='${source:Version}' liblammps-dev)
cache=${PW85_LAMMPS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/pw85}
dest=$cache/lammps-$srcversion
incdir=${PW85_LAMMPS_INCLUDEDIR:-/usr/include/lammps}

check() {
  tree=$1
  # The version of liblammps.pc (a date, 20210929) against version.h's
  # ("29 Sep 2021").
  pcver=$(pkg-config --modversion liblammps 2>/dev/null) ||
    die "pkg-config finds no liblammps"
  hdate=$(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"$/\1/p' "$tree/version.h")
  hnum=$(LC_ALL=C date -u -d "$hdate" +%Y%m%d 2>/dev/null) ||
    die "cannot read the version in $tree/version.h"
  [ "$hnum" = "$pcver" ] ||
    die "source version $hnum ($hdate) is not the installed $pcver"
  for h in "$incdir"/*.h; do
    cmp -s "$h" "$tree/$(basename "$h")" ||
      die "$h differs from the source package's $(basename "$h")"
  done
}

if [ -f "$dest/src/atom_vec_ellipsoid.h" ]; then
  check "$dest/src"
  echo "$dest/src"
  exit 0
fi

command -v dpkg-source >/dev/null || die "dpkg-source not found (package dpkg-dev)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/lists/partial" "$tmp/cache/archives/partial"
# Debian 12's main archive (bookworm), where the installed version comes from.
suite=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
echo "deb-src http://deb.debian.org/debian $suite main" > "$tmp/sources.list"
apt_opts="-q -o Dir::Etc::SourceList=$tmp/sources.list
  -o Dir::Etc::SourceParts=/dev/null -o Dir::State::Lists=$tmp/lists
  -o Dir::Cache=$tmp/cache -o APT::Sandbox::User=root"
# shellcheck disable=SC2086
apt-get $apt_opts update >&2 || die "apt-get update (deb-src $suite) failed"
# shellcheck disable=SC2086
(cd "$tmp" && apt-get $apt_opts source --download-only "lammps=$srcversion") >&2 ||
  die "apt-get source lammps=$srcversion failed"
(cd "$tmp" && dpkg-source -x ./*.dsc unpacked) >/dev/null ||
  die "dpkg-source -x failed"
check "$tmp/unpacked/src"
# Keep only headers: the core's, fmt's, and those of ASPHERE and PLUGIN.
mkdir -p "$dest.tmp/src/fmt" "$dest.tmp/src/ASPHERE" "$dest.tmp/src/PLUGIN"
cp "$tmp"/unpacked/src/*.h "$dest.tmp/src/"
cp "$tmp"/unpacked/src/fmt/* "$dest.tmp/src/fmt/"
cp "$tmp"/unpacked/src/ASPHERE/*.h "$dest.tmp/src/ASPHERE/"
cp "$tmp"/unpacked/src/PLUGIN/*.h "$dest.tmp/src/PLUGIN/"
cp "$tmp"/unpacked/LICENSE "$dest.tmp/"
echo "lammps $srcversion, Debian source package, headers only" > "$dest.tmp/README"
rm -rf "$dest"
mv "$dest.tmp" "$dest"
echo "$dest/src"
