#!/bin/sh
# A disc (a rigid body of fix rigid) released in a tank of water at rest:
# neutrally buoyant and 10 % heavier than the water (README.md).
#   ./run.sh             both discs, R = 5 dx, 0.5 s after a 0.2 s settling, and the neutral
#                        disc with the plain pressure gradient (about 3 min on 2 ranks)
#   ./run.sh rest        the neutral disc released into the water as sph/set hydrostatic
#                        leaves it: it moves less than 0.1 dx in 0.25 s (the CI test
#                        coupling.validation.neutral_rest)
#   ./run.sh rest_plain  the same with the plain pressure gradient: it rises 0.62 dx, and the
#                        check fails (the CI control coupling.validation.neutral_rest_plain)
#   ./run.sh quick       the plain gradient, the neutral disc held for 0.2 s: its SPH pressure
#                        force within 0.5 % of its weight of the exact force of the water's
#                        pressure field (the CI test coupling.validation.neutral_force)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"
case "${1:-}" in
  rest | rest_plain)
    correction=gradient
    [ "$1" = rest_plain ] && correction=none
    $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob neutral -var settle 0 \
      -var tend 0.25 -var correction $correction -var out "tank_$1" -log "log.tank_$1" > /dev/null
    exec "$PYTHON" "$here/rest_check.py" "tank_$1.series" --log "log.tank_$1" --max-move 0.1
    ;;
esac
if [ "${1:-}" = quick ]; then
  $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob neutral -var tend 0.001 \
    -var correction none -var out tank_neutral -var snapshot yes -log log.tank_neutral > /dev/null
  grep -E "^(disc of|released)" log.tank_neutral
  exec "$PYTHON" "$here/held_force.py" tank_neutral.release --log log.tank_neutral \
    --max-mismatch 0.005
fi
for case in neutral:gradient 1100:gradient neutral:none; do
  rhob=${case%:*} correction=${case#*:}
  name=tank_${rhob}_$correction
  echo "disc $rhob, correction $correction:"
  $run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var rhob $rhob -var out $name \
    -var correction $correction -var snapshot yes -log log.$name > /dev/null
  grep -E "^(disc of|released|final)" log.$name
  "$PYTHON" "$here/rest_check.py" $name.series --log log.$name
done
# the held neutral disc's force against the water's own pressure field (held_force.py
# recomputes the plain gradient's force)
"$PYTHON" "$here/held_force.py" tank_neutral_none.release --log log.tank_neutral_none
