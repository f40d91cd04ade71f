#!/usr/bin/env bash
# Unpack LAMMPS 29Sep2021 (update 2) from Debian's source package into DEST
# (default build/lammps-src). Does nothing when DEST already holds that version.
set -euo pipefail
dest=${1:-build/lammps-src}
if [ -f "$dest/src/version.h" ] && grep -q '29 Sep 2021' "$dest/src/version.h"; then
  exit 0
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/lammps-fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$work" && apt-get source -q lammps >/dev/null 2>apt-source.err) || {
  cat "$work/apt-source.err" >&2
  echo "fetch-lammps: 'apt-get source lammps' failed (is there a deb-src entry for bookworm? run tools/bootstrap.sh)" >&2
  exit 1
}
tree=$(find "$work" -mindepth 1 -maxdepth 1 -type d -name 'lammps-*' | head -n 1)
grep -q '29 Sep 2021' "$tree/src/version.h" || {
  echo "fetch-lammps: Debian's source is not LAMMPS 29Sep2021: $(grep VERSION "$tree/src/version.h")" >&2
  exit 1
}
rm -rf "$dest"
mkdir -p "$(dirname "$dest")"
mv "$tree" "$dest"
echo "fetch-lammps: LAMMPS $(sed -n 's/.*LAMMPS_VERSION "\(.*\)"/\1/p' "$dest/src/version.h") in $dest"
