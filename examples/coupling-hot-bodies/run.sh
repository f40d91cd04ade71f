#!/bin/sh
# Showcase: three hot steel discs (rigid bodies, with contact) settling in a
# tank of liquid gallium, with natural convection around them.
#   ./run.sh          5 particles across a disc's radius (dx = 1 mm), to t = 2 s, PNG (about 3 min on 2 ranks)
#   ./run.sh quick    3 across, to t = 1 s, the checks only (the CI test coupling.showcase.bodies_3)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

case "${1:-}" in
  quick) n=3; tend=1; png="" ;;
  *) n=5; tend=2; png="--png bodies.png" ;;
esac
dx=$(awk "BEGIN { print 0.005 / $n }")
$run "$LMP" -in "$here/in.bodies" -var plugin "$PLUGIN" -var n $n -var tend $tend \
  -var out "bodies_$n" -log "log.bodies_$n" > /dev/null
grep -E "^final" "log.bodies_$n"
"$PYTHON" "$here/plot.py" "bodies_$n.dump" --dx "$dx" $png
