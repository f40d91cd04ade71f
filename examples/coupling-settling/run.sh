#!/bin/sh
# A disc (a rigid body of fix rigid) released in a tank of water at rest:
# neutrally buoyant and 10 % heavier than the water (work in progress: see README.md).
#   ./run.sh          both discs, R = 5 dx, 0.5 s after a 0.2 s settling (about 5 min)
#   ./run.sh quick    the neutral disc held for 0.2 s: its SPH pressure force within 0.5 % of
#                     its weight of the exact force of the water's pressure field (the CI test
#                     coupling.validation.neutral_force)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"
if [ "${1:-}" = quick ]; then
  $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob neutral -var tend 0.001 \
    -var out tank_neutral -var snapshot yes -log log.tank_neutral > /dev/null
  grep -E "^(disc of|released)" log.tank_neutral
  exec "$PYTHON" "$here/held_force.py" tank_neutral.release --log log.tank_neutral \
    --max-mismatch 0.005
fi
for rhob in neutral 1100; do
  $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob $rhob -var out "tank_$rhob" \
    -var snapshot yes -log "log.tank_$rhob" > /dev/null
  grep -E "^(disc of|released|final)" "log.tank_$rhob"
done
# the held neutral disc's force against the water's own pressure field
"$PYTHON" "$here/held_force.py" tank_neutral.release --log log.tank_neutral
