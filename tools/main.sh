#!/usr/bin/env bash
# The main job: install prerequisites, build LAMMPS 29Sep2021 and the
# USER-SPHTHERMAL plugin, run the flagship example (erf slab, Cleary 1998,
# section 3.1) and print its error against the exact solution.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
tools/bootstrap.sh
cmake -S cmake -B build
cmake --build build -j"$(nproc)" --target sphthermalplugin lmp-link
examples/conduction-erf/run.sh
