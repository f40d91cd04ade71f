#!/bin/sh
# Three solids to steady state (Ng et al. 2020, section 4.2) against the composite-wall
# solution and a fine 1-D finite-volume transient.
#   ./run.sh          80 x 20 (s = 0.05 m, as in the paper), cubic kernel h = dx, to t = 3000 s:
#                     dummy walls (fix sph/wall/dirichlet), then wall particles held at the
#                     wall temperatures (fix sph/wall/isothermal), then dummy walls with
#                     h = 1.3 dx, with the harmonic mean and with mean interface
#                     (about 3 minutes)
#   ./run.sh quick    40 x 10, dummy walls (the CI test)
#   ./run.sh interface  40 x 10, dummy walls, h = 1.3 dx, mean interface (the CI
#                     test conduction.interface.three_solids_40x10)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

lammps() {    # name, then -var arguments
  name=$1
  shift
  rm -f "$name.dump"
  $run "$LMP" -in "$here/in.three-solids" -var plugin "$PLUGIN" -var out "$name.dump" -log "log.$name" "$@"
}

if [ "${1:-}" = quick ]; then
  lammps three-solids-quick -var nx 40 -var ny 10
  # measured (README.md): steady-state max error 0.0032 % (the transient left at
  # t = 3000 s), transient 0.103 % against the finite-volume solution
  "$PYTHON" "$here/analyse.py" three-solids-quick --cells 120 --max-steady 0.01 --max-transient 0.13
  exit 0
fi

if [ "${1:-}" = interface ]; then
  lammps three-solids-interface -var nx 40 -var ny 10 -var hdx 1.3 -var mean interface
  # measured (README.md): steady 0.0099 %, transient 0.25 %; with the
  # harmonic mean 0.087 % and 0.48 %
  "$PYTHON" "$here/analyse.py" three-solids-interface --cells 120 --max-steady 0.02 \
    --max-transient 0.3
  exit 0
fi
lammps three-solids
"$PYTHON" "$here/analyse.py" three-solids --max-steady 0.01 --max-transient 0.15
lammps three-solids-isothermal -var wall isothermal > /dev/null
"$PYTHON" "$here/analyse.py" three-solids-isothermal --label "isothermal walls" | tail -n 3
lammps three-solids-h1.3 -var hdx 1.3 > /dev/null
"$PYTHON" "$here/analyse.py" three-solids-h1.3 --label "dirichlet walls, h = 1.3 dx" | tail -n 3
lammps three-solids-h1.3-interface -var hdx 1.3 -var mean interface > /dev/null
"$PYTHON" "$here/analyse.py" three-solids-h1.3-interface \
  --label "dirichlet walls, h = 1.3 dx, mean interface" | tail -n 3
