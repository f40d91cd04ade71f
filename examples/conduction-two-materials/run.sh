#!/bin/sh
# Run the two-materials example (Cleary 1998, section 3.2) and print its errors.
#   ./run.sh          80 x 20: k ratio 3 and rho ratio 0.5 with pair sph/cleary/heat and
#                     with LAMMPS's pair sph/heatconduction, then air/water (about 2 minutes)
#   ./run.sh quick    40 x 10, k ratio 3 and rho ratio 0.5 only (the CI test)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

lammps() {    # name, then -var arguments
  name=$1
  shift
  $run "$LMP" -in "$here/in.two-materials" -var plugin "$PLUGIN" -var out "$name" \
    -log "log.$name" "$@"
}

if [ "${1:-}" = quick ]; then
  # thresholds: measured errors (see README.md) plus a margin
  lammps ratio-quick -var nx 40 -var ny 10 -var dt 0.0025 -var tend 25
  "$PYTHON" "$here/analyse.py" ratio-quick --nx 40 --dt 0.0025 --cells 200 --max-error 0.6 --max-drift 1e-12
  exit 0
fi

lammps ratio -var case ratio
"$PYTHON" "$here/analyse.py" ratio --dt 0.0003125 --max-error 0.5 --max-drift 1e-12
lammps ratio-heatconduction -var case ratio -var pair heatconduction
"$PYTHON" "$here/analyse.py" ratio-heatconduction --dt 0.0003125 --label "pair sph/heatconduction"
lammps airwater -var case airwater -var dt 0.5 -var tend 42500
"$PYTHON" "$here/analyse.py" airwater --case airwater --dt 0.5 --cells 200 --max-error 0.5 --max-drift 1e-12
