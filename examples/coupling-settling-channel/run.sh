#!/bin/sh
# A heavy disc (a rigid body of fix rigid) settling in a closed channel of
# very viscous oil, against the Stokes drag of tools/cylinder_stokes.py
# (README.md).
#   ./run.sh          R = 4, 6, 8 and 12 dx with the oil weightless (weight body), R = 4 and
#                     6 dx with gravity on everything (weight all), 0.15 s after the release,
#                     PNG; each weight-body run's error, less the lattice error of the viscous
#                     term, within 0.8 (dx/R)^2 (about 10 min on 2 ranks)
#   ./run.sh quick    R = 4 dx, weight body, 0.15 s: the speed within 8 % of the reference
#                     from 0.05 to 0.15 s, its error drifting by less than 1.5 % (the CI test
#                     coupling.validation.settling_channel_4)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

settle() {    # n weight tend
  $run "$LMP" -in "$here/in.channel" -var plugin "$PLUGIN" -var n $1 -var weight $2 -var tend $3 \
    -var out "channel_$2_$1" -log "log.channel_$2_$1" > /dev/null
  grep -E "^final" "log.channel_$2_$1"
}
case "${1:-}" in
  quick)
    settle 4 body 0.15
    "$PYTHON" "$here/compare.py" channel_body_4 --skip 0.05 --until 0.15 --max-error 0.08 \
      --max-drift 0.015 ;;
  *)
    for n in 4 6 8 12; do settle $n body 0.15; done
    for n in 4 6; do settle $n all 0.15; done
    "$PYTHON" "$here/compare.py" channel_all_4 channel_all_6
    "$PYTHON" "$here/compare.py" channel_body_4 channel_body_6 channel_body_8 channel_body_12 \
      --max-body 0.8 --png settling.png ;;
esac
