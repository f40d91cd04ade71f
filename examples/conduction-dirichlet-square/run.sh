#!/bin/sh
# Convergence study of the steady Dirichlet square (Reece et al. 2024, section 3.1).
#   ./run.sh          n = 10, 20, 40, 80 particles across; cubic (h = dx) and Wendland
#                     (h = 1.3 dx) with extrapolated dummy walls, cubic with isothermal
#                     wall particles for comparison (about 2 minutes)
#   ./run.sh quick    n = 10, 20, cubic, dummy walls (the CI test)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

square() {    # label kernel hdx wall n
  $run "$LMP" -in "$here/in.square" -var plugin "$PLUGIN" -var kernel $2 -var hdx $3 -var wall $4 \
    -var n $5 -var out "$1-$5.dump" -log "log.$1-$5" > /dev/null
  echo "$1:$5:$1-$5.dump"
}

if [ "${1:-}" = quick ]; then
  runs="$(square cubic cubic 1.0 dirichlet 10) $(square cubic cubic 1.0 dirichlet 20)"
  # measured: L2 0.032 % at n = 20, order 1.07 (README.md)
  "$PYTHON" "$here/analyse.py" $runs --max-l2 0.04 --min-order 0.9
  exit 0
fi
runs=""
for n in 10 20 40 80; do
  runs="$runs $(square cubic cubic 1.0 dirichlet $n) $(square wendland wendland 1.3 dirichlet $n)"
  runs="$runs $(square cubic-isothermal cubic 1.0 isothermal $n)"
done
"$PYTHON" "$here/analyse.py" $runs
