#!/bin/sh
# A disc (a rigid body of fix rigid) released in a tank of water at rest:
# neutrally buoyant and 10 % heavier than the water (work in progress: see README.md).
#   ./run.sh          both discs, R = 5 dx, 0.5 s after a 0.2 s settling (about 5 min)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"
for rhob in neutral 1100; do
  $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob $rhob -var out "tank_$rhob" \
    -log "log.tank_$rhob" > /dev/null
  grep -E "^(disc of|released|final)" "log.tank_$rhob"
done
