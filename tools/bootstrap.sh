#!/usr/bin/env bash
# Install what USER-SPHTHERMAL needs to build LAMMPS (4Feb2025 from Debian 13
# "trixie"'s source, 29Sep2021 from Debian 12 "bookworm"'s source) and the
# package on Debian bookworm. As root it runs apt-get; otherwise it prints the
# commands and stops. Idempotent: a machine that has everything is left as it is.
#
# The source entries (deb-src for bookworm and trixie, main only: no binary
# package comes from trixie) are derived from the machine's own Debian entry:
# its archive address and signing key, so a mirror or proxy keeps working.
set -euo pipefail

# liblapack-dev: LAMMPS's RHEO package (the bench's peer) needs LAPACK, which
# Debian's repacked 4Feb2025 source does not bundle (no lib/linalg);
# python3-docutils: the docs.rst tests (every page parses), left out without it;
# libeigen3-dev: LAMMPS's MACHDYN package (the thermo-mechanical solids)
packages="build-essential cmake ccache git dpkg-dev pkg-config libopenmpi-dev openmpi-bin
  libfftw3-dev googletest libyaml-dev liblapack-dev libeigen3-dev python3-numpy python3-matplotlib
  python3-scipy python3-docutils"

missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done

if [ -n "$missing" ]; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "bootstrap: missing Debian packages:$missing" >&2
    echo "bootstrap: install them with:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y$missing" >&2
    exit 1
  fi
  echo "bootstrap: installing$missing"
  apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $missing
fi

# The machine's Debian archive: the first binary entry that serves suite
# bookworm (deb822 .sources or one-line .list), with its Signed-By key.
debian_archive() {
  local f
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    # one stanza per paragraph; print "URI KEY" of a deb stanza with bookworm
    awk 'BEGIN { RS = ""; FS = "\n" }
         {
           types = ""; uris = ""; suites = ""; key = ""
           for (i = 1; i <= NF; i++) {
             if ($i ~ /^Types:/)     types = $i
             if ($i ~ /^URIs:/)      { uris = $i; sub(/^URIs:[ \t]*/, "", uris) }
             if ($i ~ /^Suites:/)    suites = $i
             if ($i ~ /^Signed-By:/) { key = $i; sub(/^Signed-By:[ \t]*/, "", key) }
           }
           if (types ~ /(^|[ \t])deb([ \t]|$)/ && suites ~ /[ \t]bookworm([ \t]|$)/ && uris != "") {
             split(uris, u, /[ \t]+/); print u[1], key; exit
           }
         }' "$f"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    # deb [signed-by=KEY] URI bookworm main
    sed -n -E 's/^deb[ \t]+(\[([^]]*)\][ \t]+)?([^ \t]+)[ \t]+bookworm[ \t].*/\3 \2/p' "$f" |
      sed -E 's/ .*signed-by=([^ ]+).*/ \1/; s/ [^ ]*=[^ ]*$/ /'
  done
}
archive=$(debian_archive | head -n 1)
uri=${archive%% *}
key=${archive#* }
[ "$key" = "$archive" ] && key=""
if [ -z "$uri" ]; then
  echo "bootstrap: no Debian bookworm entry found in /etc/apt/sources.list{,.d}; add deb-src entries for bookworm and trixie by hand" >&2
  exit 1
fi
[ -n "$key" ] || key=/usr/share/keyrings/debian-archive-keyring.gpg

# cmake/fetch-lammps.sh needs the source package of each release
. "$(dirname "$0")/../cmake/lammps-releases.sh"
# no grep -q on the pipe: with pipefail, apt-cache's SIGPIPE would fail it
has_source() {
  apt-cache showsrc lammps 2>/dev/null | grep -c "^Version: $debian_version" >/dev/null
}
need_update=0
for release in $lammps_releases; do
  lammps_release "$release"
  has_source && continue
  entry="Types: deb-src\nURIs: $uri\nSuites: $suite\nComponents: main\nSigned-By: $key\n"
  file=/etc/apt/sources.list.d/$suite-src.sources
  if [ "$(id -u)" -ne 0 ]; then
    echo "bootstrap: no source entry for $suite (LAMMPS $release); add one (as root) with:" >&2
    echo "  printf '$entry' > $file && apt-get update" >&2
    exit 1
  fi
  echo "bootstrap: adding a deb-src entry for $suite ($uri)"
  printf "$entry" >"$file"
  need_update=1
done
if [ $need_update = 1 ]; then
  apt-get update -q
  for release in $lammps_releases; do
    lammps_release "$release"
    has_source || { echo "bootstrap: still no source of lammps for $suite (LAMMPS $release) after apt-get update" >&2; exit 1; }
  done
fi
echo "bootstrap: prerequisites present"
