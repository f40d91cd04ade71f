#!/usr/bin/env bash
# Install what USER-SPHTHERMAL needs to build LAMMPS 29Sep2021 and the package
# on Debian bookworm. As root it runs apt-get; otherwise it prints the command
# and stops. Idempotent: a machine that has everything is left as it is.
set -euo pipefail

packages="build-essential cmake ccache git dpkg-dev pkg-config libopenmpi-dev openmpi-bin
  libfftw3-dev googletest libyaml-dev python3-numpy python3-matplotlib"

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

# 'apt-get source lammps' needs a deb-src entry for bookworm.
if ! grep -rqsE '^(deb-src|Types:.*deb-src)' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  if [ "$(id -u)" -ne 0 ]; then
    echo "bootstrap: no deb-src entry for bookworm; add one (as root) with:" >&2
    echo "  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' > /etc/apt/sources.list.d/bookworm-src.sources && apt-get update" >&2
    exit 1
  fi
  echo "bootstrap: adding a deb-src entry for bookworm"
  printf 'Types: deb-src\nURIs: http://deb.debian.org/debian\nSuites: bookworm\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    > /etc/apt/sources.list.d/bookworm-src.sources
  apt-get update -q
fi
echo "bootstrap: prerequisites present"
