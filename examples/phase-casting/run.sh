#!/bin/sh
# Two casting-like scenes of fix sph/phase; writes their results, PNGs and
# dumps (OVITO, ParaView) in out/:
#   ./run.sh casting  a melt flowing through a chilled mould, a solid shell
#                     growing on its walls (with fix sph/open), 20 particles
#                     across, to t = 150 H / U: results.md, casting.png,
#                     out/casting.dump; about 6 min on one core
#   ./run.sh pour     a melt poured into a cold open mould under gravity,
#                     freezing as it flows, 20 and 40 particles across the
#                     column, to t = 20 sqrt(a / g): pour.md, pour.png,
#                     out/pour20.dump, out/pour40.dump; about 8 min
#   ./run.sh          both
# The CI runs coarse versions (tests phase.casting and phase.pour:
# unittest/phase/test_casting.py, test_pour.py).
# Environment: LMP, PLUGIN, OUT (default ./out), NP.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"
scenes=${1:-casting pour}

for scene in $scenes; do
  case $scene in
    casting)
      $run "$LMP" -in "$here/in.casting" -var plugin "$PLUGIN" -var n 20 -log log.casting > /dev/null
      (cd "$here" && "$PYTHON" results.py "$OUT" 20 > results.md && cat results.md)
      ;;
    pour)
      for n in 20 40; do
        $run "$LMP" -in "$here/in.pour" -var plugin "$PLUGIN" -var n $n -var out pour$n \
          -log log.pour$n > /dev/null
      done
      (cd "$here" && "$PYTHON" pour.py "$OUT" 20 40 > pour.md && cat pour.md)
      ;;
    *) echo "run.sh: unknown scene $scene (casting or pour)" >&2; exit 1 ;;
  esac
done
