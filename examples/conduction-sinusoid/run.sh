#!/bin/sh
# Run the sinusoid example and print the wall heat flux error.
#   ./run.sh          40 x 40 particles, as in Cleary 1998, section 3.4
#   ./run.sh quick    20 x 20 particles (the CI test conduction.validation.sinusoid_20)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = quick ]; then
  n=20 dt=0.001
  limits="--max-error 2.0 --max-direct-error 2.0"    # measured 1.63 %, 1.63 % (README.md)
else
  n=40 dt=0.0005
  limits="--max-error 1.4 --max-direct-error 3.1"    # Cleary 1998: 1.4 % (energy), 3.1 % (direct)
fi

rm -f sinusoid.flux sinusoid.dump
$run "$LMP" -in "$here/in.sinusoid" -var plugin "$PLUGIN" -var n $n -var dt $dt -log log.sinusoid
"$PYTHON" "$here/analyse.py" sinusoid --n $n --dt $dt --png sinusoid.png $limits
