#!/bin/sh
# Fixed packed beds of unresolved grains (fix sph/grains):
# - in.bed: liquid flowing through, against Ergun's equation
#   (tools/grain_exact.py): porosities 0.5 and 0.7, pressure gradients of
#   10 Pa/m to 100 kPa/m (particle Reynolds numbers 0.03 to 250),
#   Gidaspow's drag (Ergun's below a porosity of 0.8) and Di Felice's;
# - in.heatbed: the bed heated by a hot inflow, against Schumann's solution
#   (tools/schumann.py), at exchange lengths of 8 and 21 mm (liquid
#   conductivities 0.06 and 0.015 W/m/K; LAMMPS 4Feb2025 and later).
#   ./run.sh          the whole table (about 5 min on one core)
# The CI runs three rows of the first and a coarse second (tests
# granular.bed.*, granular.heatbed: unittest/grains/test_grains.py).
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

: > bed.txt
# porosity, gradient (Pa/m), speed of sound (m/s: 10 times the pores'
# largest speed, and dt at most a tenth of the drag's relaxation time),
# simulated time (s: 15 relaxation times)
for drag in gidaspow difelice; do
  for row in "0.5 10 0.5 0.1" "0.5 300 0.5 0.1" "0.5 1e4 0.5 0.1" "0.5 1e5 2.0 0.1" \
    "0.7 10 0.15 0.4" "0.7 300 0.15 0.4" "0.7 1e4 0.9 0.4" "0.7 1e5 3.2 0.4"; do
    set -- $row
    label="$drag-$1-$2"
    $run "$LMP" -in "$here/in.bed" -var plugin "$PLUGIN" -var drag $drag -var porosity $1 \
      -var gradient $2 -var c0 $3 -var time $4 -var label "$label" -log "log.$label" > /dev/null
    grep -E "^bed " "log.$label" >> bed.txt
  done
done
: > heatbed.txt
# conductivity, particles along the bed, simulated time (s)
for row in "0.06 48 1.5" "0.015 96 3.0"; do
  set -- $row
  label="heatbed-$1"
  $run "$LMP" -in "$here/in.heatbed" -var plugin "$PLUGIN" -var k $1 -var length $2 -var time $3 \
    -var label "$label" -log "log.$label" > /dev/null
  grep -E "^heatbed " "log.$label" >> heatbed.txt
done
cd "$here"
"$PYTHON" results.py "$OUT/bed.txt" "$OUT/heatbed.txt" "$OUT" > results.md
cat results.md
