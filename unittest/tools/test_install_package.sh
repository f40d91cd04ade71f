#!/usr/bin/env bash
# cmake/install-package.sh on a scratch copy of a LAMMPS tree's build files:
# registers USER-SPHTHERMAL exactly once (also when run twice), copies the
# material files into <lammps>/potentials, and the make
# route refuses without SPH and installs with it.
#   test_install_package.sh <lammps-source-dir>
set -euo pipefail
lammps=${1:?usage: test_install_package.sh <lammps-source-dir>}
root=$(cd "$(dirname "$0")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

mkdir -p "$scratch/cmake" "$scratch/src"
# pristine build files: drop what an earlier install added to the shared tree
grep -v '^  USER-SPHTHERMAL$\|^pkg_depends(USER-SPHTHERMAL SPH)$' "$lammps/cmake/CMakeLists.txt" \
  > "$scratch/cmake/CMakeLists.txt"
grep -v '^	user-sphthermal \\$' "$lammps/src/Makefile" > "$scratch/src/Makefile"
cp "$lammps/src/version.h" "$lammps/src/lammps.h" "$lammps"/src/*.sh \
   "$lammps/src/Makefile.package.empty" "$lammps/src/Makefile.package.settings.empty" "$scratch/src/"
cp -r "$lammps/src/SPH" "$scratch/src/SPH"

"$root/cmake/install-package.sh" "$scratch"
"$root/cmake/install-package.sh" "$scratch"

fail() { echo "FAIL: $*"; exit 1; }
[ "$(grep -c '^  USER-SPHTHERMAL$' "$scratch/cmake/CMakeLists.txt")" = 1 ] || fail "STANDARD_PACKAGES entry"
[ "$(grep -c '^pkg_depends(USER-SPHTHERMAL SPH)$' "$scratch/cmake/CMakeLists.txt")" = 1 ] || fail "pkg_depends"
[ "$(grep -c '^	user-sphthermal \\$' "$scratch/src/Makefile")" = 1 ] || fail "Makefile PACKAGE list"
diff -r "$root/src/USER-SPHTHERMAL" "$scratch/src/USER-SPHTHERMAL" || fail "package files not copied"
for f in "$root"/potentials/*.sphmat; do
  cmp -s "$f" "$scratch/potentials/$(basename "$f")" || fail "material file $(basename "$f") not in <lammps>/potentials"
done

cd "$scratch/src"
out=$(make yes-user-sphthermal 2>&1 || true)
echo "$out" | grep -q 'Must install SPH package' || fail "make yes-user-sphthermal without SPH: $out"
[ ! -e pair_sph_cleary_heat.cpp ] || fail "installed without SPH"
make yes-sph >/dev/null
make yes-user-sphthermal >/dev/null
for f in "$root"/src/USER-SPHTHERMAL/*.cpp "$root"/src/USER-SPHTHERMAL/*.h; do
  [ -e "$(basename "$f")" ] || fail "make yes-user-sphthermal did not install $(basename "$f")"
done
make no-user-sphthermal >/dev/null
[ ! -e pair_sph_cleary_heat.cpp ] || fail "make no-user-sphthermal left files"
echo "PASS install-package.sh and make yes/no-user-sphthermal"
