#!/bin/sh
# Run the k = exp(4 T) example and print its error.
#   ./run.sh          80 x 20 particles, as in Cleary 1998, section 3.3 (about 2 minutes)
#   ./run.sh quick    40 x 4 particles (the CI test conduction.validation.exp_k_40x4)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = quick ]; then
  size="-var nx 40 -var ny 4 -var dt 0.001"
  # measured: largest mean error 0.44 % (t = 1 s), steady max 0.88 % (README.md)
  limits="--cells 200 --max-mean-error 0.5 --max-steady-error 1.0"
else
  size="-var nx 80 -var ny 20 -var dt 0.00025"
  limits="--cells 400"
fi

rm -f exp-k.dump.t*
$run "$LMP" -in "$here/in.exp-k" -var plugin "$PLUGIN" $size -log log.exp-k
"$PYTHON" "$here/analyse.py" exp-k.dump --png exp-k.png $limits
