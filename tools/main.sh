#!/usr/bin/env bash
# The main job: install prerequisites, build LAMMPS (4Feb2025 by default,
# or '--lammps 29Sep2021') and the USER-SPHTHERMAL plugin, run the flagship
# example (natural convection in the differentially heated square cavity at
# Ra = 1e4, de Vahl Davis 1983), print its mean Nusselt number against the
# benchmark and write the isotherm/streamline PNG.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
. tools/lammps-release.sh
tools/bootstrap.sh
cmake -S cmake -B "$build" -D LAMMPS_RELEASE="$release" -D LAMMPS_SIZES="$sizes"
cmake --build "$build" -j"$(nproc)" --target sphthermalplugin lmp-link
LMP=$root/$build/lmp PLUGIN=$root/$build/sphthermalplugin.so examples/convection-cavity/run.sh
