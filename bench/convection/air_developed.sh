#!/bin/bash
# The developed air cavity of Reece et al. 2024, section 3.2 (154 x 154, 2
# ranks), from the state of a finished 60 s run: 1,830 steps, LAMMPS's
# timing breakdown. Usage (from the repository root, after the 60 s run of
# examples/convection-cavity/run.sh air wrote its dump):
#   bench/convection/air_developed.sh [dump] [extra lmp arguments, e.g. -var dtevery 10]
# Variables: PLUGIN (default build/sphthermalplugin.so), LMP (build/lmp), NP (2).
set -e
root=$(cd "$(dirname "$0")/../.." && pwd)
dump=${1:-$root/examples/convection-cavity/out/air154/air.dump}
shift || true
plugin=$(realpath "${PLUGIN:-$root/build/sphthermalplugin.so}")
lmp=$(realpath "${LMP:-$root/build/lmp}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# the dump's temperatures as an atomfile-style variable
{ awk '/ITEM: NUMBER OF ATOMS/{getline; print; exit}' "$dump"; awk 'f{print $1, $6} /ITEM: ATOMS/{f=1}' "$dump"; } > "$work/T.atomfile"
step=$(awk '/ITEM: TIMESTEP/{getline; print; exit}' "$dump")
cd "$work"
# 1,830 steps: 0.19 s of flow at dt = 1.04e-4 s
mpirun ${MPIRUN_FLAGS:-} -np "${NP:-2}" "$lmp" -in "$root/examples/convection-cavity/in.air" \
  -var plugin "$plugin" -var n 154 -var delta 0 -var seconds 0.19 -var every 1000 \
  -var from "$dump" -var fromstep "$step" -var fromT "$work/T.atomfile" -var out "$work/air.dump" \
  "$@" -log log.lammps > out.txt || { tail -5 out.txt; exit 1; }
grep -A8 "^Section" log.lammps | tail -8
grep "Loop time" log.lammps | tail -2 | head -1
