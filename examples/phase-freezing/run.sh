#!/bin/sh
# Freezing of a liquid in a square cavity cooled from one side (fix
# sph/phase with natural convection in the liquid, Ra = 1e5, Pr = 1, Stefan
# number 1) at 20, 30 and 40 particles across, to the steady state (t = 320
# in units of H, rho, cv and the temperature difference), against the
# package's finite-volume enthalpy-porosity solver (tools/phase_fv.py), and
# the same without gravity (pure conduction: Neumann's solution while the
# solid is thin, a solid H/2 thick at the steady state).
#   ./run.sh          about 45 min on one core (n = 40 is 30 of them)
# The CI runs n = 20 to t = 80 (tests phase.freezing.*:
# unittest/phase/test_phase.py).
# Environment: LMP, PLUGIN, OUT (default ./out), NP.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

for n in 20 30 40; do
  mkdir -p "n$n"
  (cd "n$n" && $run "$LMP" -in "$here/in.freezing" -var plugin "$PLUGIN" -var n $n -var tend 320 \
    -log log.freezing > /dev/null)
done
mkdir -p conduction
(cd conduction && $run "$LMP" -in "$here/in.freezing" -var plugin "$PLUGIN" -var n 40 -var tend 320 \
  -var g 0.0 -log log.freezing > /dev/null)
cd "$here"
"$PYTHON" results.py "$OUT" 20 30 40 > results.md
cat results.md
