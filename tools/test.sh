#!/usr/bin/env bash
# The whole test suite: install prerequisites, build LAMMPS (4Feb2025 by
# default, or '--lammps 29Sep2021'; host and in-tree), the plugin and the
# tests, then run every test with ctest. Further arguments go to ctest
# (e.g. -L unit, -R kernel).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
. tools/lammps-release.sh
tools/bootstrap.sh
cmake -S cmake -B "$build" -D LAMMPS_RELEASE="$release"
cmake --build "$build" -j"$(nproc)"
cd "$build"
ctest --output-on-failure -j"$(nproc)" ${args[@]+"${args[@]}"}
