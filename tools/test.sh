#!/usr/bin/env bash
# The whole test suite: install prerequisites, build LAMMPS (4Feb2025 by
# default, or '--lammps 29Sep2021'; '--sizes bigbig' for LAMMPS's 64-bit
# atom IDs, in its own build directory; host and in-tree), the plugin and
# the tests, then run every test with ctest. Further arguments go to ctest
# (e.g. -L unit, -R kernel).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
. tools/lammps-release.sh
tools/bootstrap.sh
cmake -S cmake -B "$build" -D LAMMPS_RELEASE="$release" -D LAMMPS_SIZES="$sizes"
cmake --build "$build" -j"$(nproc)"
cd "$build"
# one job more than cores: a LAMMPS start-up waits on I/O for much of its time
ctest --output-on-failure -j"$(($(nproc) + 1))" ${args[@]+"${args[@]}"}
