#!/bin/sh
# One unresolved grain in still fluid (fix sph/grains) against the exact
# values of its exchange laws (tools/grain_exact.py): the terminal slip of
# a settling grain (Di Felice's drag at Re = 0.02, 1.6 and 55) and the
# cooling of a held hot grain (lumped capacitance, Ranz-Marshall and Gunn),
# at fluid spacings of 1 and 0.5 mm (2.5 and 1.25 grain diameters); the
# buoyancy in a column of liquid at rest under gravity (in.column).
#   ./run.sh          the whole table (about 40 s on one core)
# The CI runs the 1 mm settling and cooling and the column (tests
# granular.settle.*, granular.heat.*, granular.column: unittest/grains/test_grains.py).
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

one() {    # label, then -var name value pairs
  label=$1
  shift
  $run "$LMP" -in "$here/in.single" -var plugin "$PLUGIN" "$@" -log "log.$label" > /dev/null
  grep -E "^(settle|heat):" "log.$label"
}

: > settle.txt
: > heat.txt
for resolution in "0.001 8" "0.0005 16"; do
  set -- $resolution
  spacing=$1
  n=$2
  # viscosity, speed of sound (10 times the largest speed), simulated time
  for flow in "0.05 0.1 0.03" "0.005 1.0 0.1" "0.0005 1.0 0.1"; do
    set -- $flow
    one "settle-$spacing-$1" -var mode settle -var spacing $spacing -var n $n -var mu $1 -var c0 $2 \
      -var time $3 -var dump 1 -var label "settle-$spacing-$1" >> settle.txt
  done
  for law in ranz-marshall gunn; do
    one "heat-$spacing-$law" -var mode heat -var spacing $spacing -var n $n -var heat $law \
      -var dump 1 -var label "heat-$spacing-$law" >> heat.txt
  done
done
# buoyancy: a grain of the liquid's density and a glass bead in a column at rest
: > column.txt
for rho in 1000.0 2500.0; do
  $run "$LMP" -in "$here/in.column" -var plugin "$PLUGIN" -var rho_grain $rho -log "log.column-$rho" > /dev/null
  grep "^column:" "log.column-$rho" >> column.txt
done
"$PYTHON" "$here/results.py" settle.txt heat.txt column.txt > "$here/results.md"
cat "$here/results.md"
