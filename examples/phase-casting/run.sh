#!/bin/sh
# The casting-like scene: a melt flowing through a chilled mould, a solid
# shell growing on its walls (fix sph/phase with fix sph/open), 20
# particles across, to t = 150 H / U; writes results.md, casting.png and
# out/casting.dump (OVITO, ParaView).
#   ./run.sh          about 6 min on one core
# The CI runs n = 10 to t = 30 (test phase.casting:
# unittest/phase/test_casting.py).
# Environment: LMP, PLUGIN, OUT (default ./out), NP.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

$run "$LMP" -in "$here/in.casting" -var plugin "$PLUGIN" -var n 20 -log log.casting > /dev/null
cd "$here"
"$PYTHON" results.py "$OUT" 20 > results.md
cat results.md
