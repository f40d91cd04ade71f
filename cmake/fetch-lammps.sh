#!/usr/bin/env bash
# Unpack LAMMPS from Debian's source package into DEST:
#   cmake/fetch-lammps.sh RELEASE DEST
# RELEASE is 4Feb2025 (Debian 13 "trixie", lammps 20250204+dfsg.1) or
# 29Sep2021 (Debian 12 "bookworm", lammps 20220106.git7586adbb6a+ds1, which is
# 29Sep2021 update 2). Does nothing when DEST already holds that release.
#
# The tarballs are listed by 'apt-get --print-uris source' (with checksums)
# and fetched by apt's own downloader, which works where 'apt-get source'
# fails on the .dsc; Debian's patches are applied as dpkg-source would.
# Downloads are kept in $SPHTHERMAL_DOWNLOADS (default ~/.cache/sphthermal).
set -euo pipefail
release=${1:?usage: fetch-lammps.sh 4Feb2025|29Sep2021 DEST}
dest=${2:?usage: fetch-lammps.sh 4Feb2025|29Sep2021 DEST}
. "$(dirname "$0")/lammps-releases.sh"
lammps_release "$release" || {
  echo "fetch-lammps: unknown LAMMPS release '$release' ($lammps_releases)" >&2
  exit 1
}
if [ -f "$dest/src/version.h" ] && grep -q "$version_text" "$dest/src/version.h"; then
  exit 0
fi

fail() {
  echo "fetch-lammps: $*" >&2
  echo "fetch-lammps: is there a deb-src entry for $suite? run tools/bootstrap.sh" >&2
  exit 1
}
version=$(apt-cache showsrc lammps 2>/dev/null | sed -n "s/^Version: \($debian_version.*\)/\1/p" | sort -V | tail -n 1)
[ -n "$version" ] || fail "no source package lammps $debian_version* known to apt"
uris=$(apt-get --print-uris -q source "lammps=$version" 2>/dev/null | grep "^'") ||
  fail "'apt-get --print-uris source lammps=$version' failed"

downloads=${SPHTHERMAL_DOWNLOADS:-${XDG_CACHE_HOME:-$HOME/.cache}/sphthermal}
mkdir -p "$downloads"
# fetch one tarball (orig or debian) into the download cache; print its path
fetch() {
  local line uri file sum
  line=$(echo "$uris" | grep -E "$1" | head -n 1)
  [ -n "$line" ] || fail "no $1 in the source package lammps=$version"
  uri=$(echo "$line" | awk '{print $1}' | tr -d "'")
  file=$(echo "$line" | awk '{print $2}')
  sum=$(echo "$line" | awk '{print $4}')
  if ! { [ -f "$downloads/$file" ] && echo "${sum#SHA256:}  $downloads/$file" | sha256sum -c --quiet - 2>/dev/null; }; then
    echo "fetch-lammps: downloading $file" >&2
    /usr/lib/apt/apt-helper download-file "$uri" "$downloads/$file.part" "$sum" >&2 ||
      fail "could not download $uri"
    mv "$downloads/$file.part" "$downloads/$file"
  fi
  echo "$downloads/$file"
}
orig=$(fetch '\.orig\.tar\.')
debian=$(fetch '\.debian\.tar\.')

work=$(mktemp -d "${TMPDIR:-/tmp}/lammps-fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT
tar -xf "$orig" -C "$work"
tree=$(find "$work" -mindepth 1 -maxdepth 1 -type d | head -n 1)
[ -n "$tree" ] && [ -f "$tree/src/version.h" ] || fail "$orig holds no LAMMPS tree"
tar -xf "$debian" -C "$tree"
if [ -f "$tree/debian/patches/series" ]; then
  grep -v '^\s*#' "$tree/debian/patches/series" | while read -r patch _; do
    [ -n "$patch" ] || continue
    patch -d "$tree" -p1 -s <"$tree/debian/patches/$patch" || fail "Debian patch $patch does not apply"
  done
fi
grep -q "$version_text" "$tree/src/version.h" ||
  fail "Debian's lammps $version is not LAMMPS $release: $(grep VERSION "$tree/src/version.h")"
rm -rf "$dest"
mkdir -p "$(dirname "$dest")"
mv "$tree" "$dest"
echo "fetch-lammps: LAMMPS $(sed -n 's/.*LAMMPS_VERSION "\(.*\)"/\1/p' "$dest/src/version.h") (Debian $version) in $dest"
