#!/bin/sh
# Run the dam break at 10, 20 and 40 particles across the column (to
# t = 0.6 s, well after the impact on the far wall), and once at 20 without
# the artificial viscosity (to t = 0.3 s); write results.md and
# dam_break.png beside this script, dumps of the n = 40 run for OVITO or
# ParaView in OUT. About 3 min of one core.
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), PYTHON (with numpy).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

for n in 10 20 40; do
  dumps=none
  [ "$n" = 40 ] && dumps=dam_break
  $run "$LMP" -in "$here/in.dam_break" -var plugin "$PLUGIN" -var n $n -var out $dumps \
    -log log.n$n > /dev/null
done
$run "$LMP" -in "$here/in.dam_break" -var plugin "$PLUGIN" -var n 20 -var alpha 0 -var tend 0.3 \
  -log log.n20.alpha0 > /dev/null
"$PYTHON" "$here/results.py" log.n10 log.n20 log.n40 --plain log.n20.alpha0 \
  --md "$here/results.md" --png "$here/dam_break.png"
