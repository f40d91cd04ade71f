#!/bin/sh
# Run the erf slab example and print its error against the exact solution.
#   ./run.sh          80 x 20 particles, as in Cleary 1998, section 3.1, then the same
#                     particles with LAMMPS's pair sph/heatconduction for comparison
#   ./run.sh quick    40 x 10 particles (the CI validation test)
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), PYTHON (with numpy).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = quick ]; then
  size="-var nx 40 -var ny 10 -var dt 0.01"
  dt=0.01
  # thresholds: measured errors (see README.md) plus a margin
  limits="--max-mean-error 0.3 --max-error 3.0"
else
  size="-var nx 80 -var ny 20 -var dt 0.005"
  dt=0.005
  limits="--max-mean-error 0.3"
fi

rm -f erf.dump
$run "$LMP" -in "$here/in.erf" -var plugin "$PLUGIN" $size -log log.erf
"$PYTHON" "$here/analyse.py" erf.dump --dt $dt --png erf.png $limits
if [ "${1:-}" != quick ]; then
  rm -f erf-heatconduction.dump
  $run "$LMP" -in "$here/in.erf" -var plugin "$PLUGIN" $size -var pair heatconduction \
    -var out erf-heatconduction.dump -log log.erf-heatconduction > /dev/null
  "$PYTHON" "$here/analyse.py" erf-heatconduction.dump --dt $dt --png erf-heatconduction.png \
    --label "pair sph/heatconduction" | tail -n 3
fi
