#!/bin/sh
# A fixed packed bed of unresolved grains with liquid flowing through it
# (fix sph/grains, in.bed) against Ergun's equation (tools/grain_exact.py):
# porosities 0.5 and 0.7, pressure gradients of 10 Pa/m to 100 kPa/m
# (particle Reynolds numbers 0.03 to 180), Gidaspow's drag (Ergun's below
# a porosity of 0.8) and Di Felice's.
#   ./run.sh          the whole table (about 1 min on one core)
# The CI runs two rows (tests granular.bed.*: unittest/grains/test_grains.py).
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
cd "$here"
"$PYTHON" results.py "$OUT/bed.txt" > results.md
cat results.md
