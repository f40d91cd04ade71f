#!/bin/sh
# Run the hydrostatic column and print its spurious speed and pressure error.
#   ./run.sh          about 20 x 40 particles (staggered), 1e5 steps (8 s), about 80 s
#   ./run.sh quick    the same column for 2e4 steps (1.6 s), the CI test flow.validation.hydrostatic_20x40
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), PYTHON (with numpy).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = quick ]; then
  size="-var nx 20 -var ny 40 -var steps 20000"
  # measured (README.md): largest speed 0.24 % of sqrt(g H) (at t = 0.07 s), pressure error 0.25 % of
  # rho0 g H; the square lattice (-var lattice sq) gives 1.8 % and 1.09 %, and fails
  limits="--max-speed 0.75 --max-pressure-error 0.6"
else
  size="-var nx 20 -var ny 40 -var steps 100000"
  limits=""
fi

rm -f hydrostatic.speed hydrostatic.end hydrostatic.par
$run "$LMP" -in "$here/in.hydrostatic" -var plugin "$PLUGIN" $size -log log.hydrostatic
"$PYTHON" "$here/analyse.py" hydrostatic --png hydrostatic.png --label "20 x 40" $limits
