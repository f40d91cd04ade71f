#!/bin/sh
# A bed of free grains poured at random through liquid and fluidised by an
# upward flow (fix sph/grains, LAMMPS's pair granular): the bed's pressure
# drop against the superficial velocity U, for both forms of the fluid's
# force on the grains (keyword pressure), against Ergun's equation at the
# bed's porosity and the minimum fluidisation velocity of Ergun and of Wen
# and Yu (tools/grain_exact.py).
#   ./run.sh          the whole table (about 10 min on two cores)
# The CI runs one velocity below the onset and one above it with the
# hydrostatic form (tests granular.fluidised.*: unittest/grains/
# test_grains.py).
# Environment: LMP, PLUGIN, JOBS (runs at once, default 2), OUT (default ./out).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

# the hydrostatic form through the onset; the gradient form below it
{
  for U in 0.003 0.0045 0.006 0.0075 0.009 0.0105 0.012; do echo "hydrostatic $U"; done
  for U in 0.003 0.0045 0.006; do echo "gradient $U"; done
} | xargs -P "${JOBS:-2}" -n 2 sh -c '"$0" -in "$1" -var plugin "$2" -var n 8 -var layers 20 \
  -var height 36 -var time 1.5 -var pour wet -var pressure "$3" -var velocity "$4" \
  -var label "$3-$4" -log "log.$3-$4" > /dev/null' "$LMP" "$here/in.fluidised" "$PLUGIN"
cat log.hydrostatic-* log.gradient-* | grep -E "^freebed " > fluidised.txt
cd "$here"
"$PYTHON" results.py "$OUT/fluidised.txt" "$OUT" > results.md
cat results.md
