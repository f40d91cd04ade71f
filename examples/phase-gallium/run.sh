#!/bin/sh
# Melting of gallium in a cavity heated from one side (fix sph/phase with
# natural convection in the melt) at 20, 28 and 40 particles across the
# height, to 19 min, against the experiment of Gau and Viskanta (1986) and
# the computation of Blais and Ilinca (2018) (tools/gallium_reference.py).
#   ./run.sh          about 75 min on one core (n = 40 is 46 of them)
# The CI runs n = 14 to 2 min (tests phase.gallium.*:
# unittest/phase/test_phase.py).
# Environment: LMP, PLUGIN, OUT (default ./out), NP.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

for n in 20 28 40; do
  mkdir -p "n$n"
  (cd "n$n" && $run "$LMP" -in "$here/in.gallium" -var plugin "$PLUGIN" -var n $n -var every 2000 \
    -log log.gallium > /dev/null)
done
cd "$here"
"$PYTHON" results.py "$OUT" 20 28 40 > results.md
cat results.md
