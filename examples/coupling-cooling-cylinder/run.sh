#!/bin/sh
# A hot steel cylinder cooling in quiescent water, a rigid body of SPH
# particles, against tools/conjugate_cylinder.py.
#   ./run.sh          20 particles across the radius (dx = 0.5 mm), to t = 60 s, PNG (about 5 min)
#   ./run.sh quick    10 across, to t = 20 s (the CI test coupling.validation.cooling_cylinder_10)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

case "${1:-}" in
  quick) n=10; tend=20; times=10,20; limit=1.0 ;;    # measured 0.45 % and 0.04 % of 60 K
  *) n=20; tend=60; times=10,20,30,40,60; limit=1.0 ;;
esac
rm -f "cooling_$n.series"
$run "$LMP" -in "$here/in.cooling" -var plugin "$PLUGIN" -var n $n -var tend $tend \
  -var out "cooling_$n" -log "log.cooling_$n" > /dev/null
R=$(sed -n 's/.*equal-area R \([0-9.e+-]*\) m.*/\1/p' "log.cooling_$n" | tail -1)
png=""
[ "${1:-}" = quick ] || png="--png cooling.png"
"$PYTHON" "$here/compare.py" "cooling_$n.series" --R "$R" --box 0.04 --times $times \
  --max-error $limit $png
