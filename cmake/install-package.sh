#!/usr/bin/env bash
# Install USER-SPHTHERMAL into a LAMMPS source tree (4Feb2025 or 29Sep2021) as a package:
#   cmake/install-package.sh [--link] /path/to/lammps
# then build LAMMPS with CMake (-D PKG_SPH=on -D PKG_USER-SPHTHERMAL=on) or
# with make (make yes-sph yes-user-sphthermal). It
#   - copies src/USER-SPHTHERMAL into <lammps>/src (--link: a symbolic link,
#     so edits here reach that tree without reinstalling),
#   - adds USER-SPHTHERMAL to STANDARD_PACKAGES in <lammps>/cmake/CMakeLists.txt
#     with pkg_depends(USER-SPHTHERMAL SPH),
#   - adds user-sphthermal to the PACKAGE list of <lammps>/src/Makefile,
#   - copies the material files (potentials/*.sphmat) into <lammps>/potentials,
#     where LAMMPS keeps potential files (installed with LAMMPS; found through
#     LAMMPS_POTENTIALS, as fix sph/materials looks there).
# Running it again is harmless. Do not load the plugin into a LAMMPS built so.
set -euo pipefail

link=0
if [ "${1:-}" = "--link" ]; then link=1; shift; fi
tree=${1:?usage: install-package.sh [--link] /path/to/lammps}
pkg=$(cd "$(dirname "$0")/../src/USER-SPHTHERMAL" && pwd)
cmakelists=$tree/cmake/CMakeLists.txt
makefile=$tree/src/Makefile

[ -f "$tree/src/version.h" ] && [ -f "$cmakelists" ] || {
  echo "install-package: $tree is not a LAMMPS source tree" >&2
  exit 1
}
grep -qE '"(4 Feb 2025|29 Sep 2021)"' "$tree/src/version.h" ||
  echo "install-package: warning: $tree is neither LAMMPS 4Feb2025 nor 29Sep2021 (the tested versions); continuing" >&2

dest=$tree/src/USER-SPHTHERMAL
rm -rf "$dest"
if [ $link = 1 ]; then
  ln -s "$pkg" "$dest"
else
  cp -r "$pkg" "$dest"
fi

if ! grep -q '^  USER-SPHTHERMAL$' "$cmakelists"; then
  sed -i 's/^  SPH$/  SPH\n  USER-SPHTHERMAL/' "$cmakelists"
  # after the first dependency rule of LAMMPS's own packages
  sed -i '0,/^pkg_depends(.*)$/s//&\npkg_depends(USER-SPHTHERMAL SPH)/' "$cmakelists"
fi
grep -q '^  USER-SPHTHERMAL$' "$cmakelists" && grep -q '^pkg_depends(USER-SPHTHERMAL SPH)$' "$cmakelists" || {
  echo "install-package: could not register USER-SPHTHERMAL in $cmakelists" >&2
  exit 1
}

if [ -f "$makefile" ] && ! grep -q 'user-sphthermal' "$makefile"; then
  sed -i '0,/^\tsph \\$/s//\tsph \\\n\tuser-sphthermal \\/' "$makefile"
fi

potentials=$(cd "$(dirname "$0")/../potentials" && pwd)
mkdir -p "$tree/potentials"
cp "$potentials"/*.sphmat "$tree/potentials/"

echo "install-package: USER-SPHTHERMAL installed in $tree ($([ $link = 1 ] && echo linked || echo copied))"
