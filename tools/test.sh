#!/usr/bin/env bash
# The whole test suite: install prerequisites, build LAMMPS (host and
# in-tree), the plugin and the tests, then run every test with ctest.
# Extra arguments go to ctest (e.g. -L unit, -R kernel).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
tools/bootstrap.sh
cmake -S cmake -B build
cmake --build build -j"$(nproc)"
cd build
ctest --output-on-failure -j"$(nproc)" "$@"
