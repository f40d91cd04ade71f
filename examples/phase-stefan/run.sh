#!/bin/sh
# Melting by fix sph/phase against Neumann's exact solution of the Stefan
# problem (tools/stefan.py): the one-phase problem (the solid at its melting
# point), the two-phase one (the solid 0.5 below it; also with the solid
# conducting 2 and 0.5 times the melt, and with the liquid's specific heat
# 2 and 0.5 times the solid's) and a mushy zone 0.1 wide, at 40, 80, 160 and 320 particles on [0, 4] (the melt 0.94 to 1.24
# deep at t = 1): the depth's error against time and resolution, the
# temperature profile, and the energy balance.
#   ./run.sh          every case (about 2 min on one core)
# The CI runs 20 and 80, and the jumps at a spacing of 0.025 (tests
# phase.stefan.*: unittest/phase/test_phase.py).
# Environment: LMP, PLUGIN, OUT (default ./out).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

for n in 40 80 160 320; do
  $run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n $n -var every 20 \
    -var out "one_$n.dump" -log "log.one_$n" > /dev/null
  $run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n $n -var every 20 -var ti -0.5 \
    -var out "two_$n.dump" -log "log.two_$n" > /dev/null
done
# the solid conducting 2 and 0.5 times the melt
# (the first on [0, 6], the same spacings: its solid takes the heat farther)
for n in 80 160 320; do
  $run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n $((3 * n / 2)) -var lx 6.0 -var every 20 \
    -var ti -0.5 -var ks 2.0 -var out "two_k2_$((3 * n / 2)).dump" -log "log.two_k2_$((3 * n / 2))" > /dev/null
  $run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n $n -var every 20 -var ti -0.5 -var ks 0.5 \
    -var out "two_k05_$n.dump" -log "log.two_k05_$n" > /dev/null
done
# the liquid's specific heat 2 and 0.5 times the solid's
for n in 80 160 320; do
  for cl in 2 05; do
    $run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n $n -var every 20 -var ti -0.5 \
      -var cl $(echo $cl | sed 's/^0/0./') -var out "two_c${cl}_$n.dump" -log "log.two_c${cl}_$n" > /dev/null
  done
done
$run "$LMP" -in "$here/in.stefan" -var plugin "$PLUGIN" -var n 80 -var every 20 -var ti -0.05 \
  -var mushy 0.1 -var out "mushy_80.dump" -log "log.mushy_80" > /dev/null
cd "$here"
"$PYTHON" results.py "$OUT" > results.md
cat results.md
