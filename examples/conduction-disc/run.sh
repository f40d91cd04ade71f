#!/bin/sh
# Conduction in a disc, correct against naive boundary set-up (Cleary 1998, section 3.5).
#   ./run.sh          the disc 30 particles across (R = 15 dx), cubic h = 1.3 dx: Cleary's set-up
#                     (tools/sph_boundary.py, eps = 0.42, one wall ring), the naive set-up
#                     (4- and 8-connected outermost lattice points), 2 and 3 wall rings,
#                     eps = 0.3, 0.45, 0.5, 0.6, a lattice with a particle at the centre,
#                     h = dx (about 15 s)
#   ./run.sh quick    Cleary's set-up and the naive one only, same disc (the CI test
#                     conduction.validation.disc_30)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

dx=0.0333333333333333333    # R / 15 with R = 0.5 m
disc() {    # label [hdx] -- sph_boundary.py options
  label=$1; hdx=$2; shift 3
  "$PYTHON" "$root/tools/sph_boundary.py" disc --radius 0.5 --dx $dx --rho 1000 --T 1 --Twall 0 \
    -o "$label.data" "$@"
  rm -f "$label.flux" "$label.dump"
  $run "$LMP" -in "$here/in.disc" -var plugin "$PLUGIN" -var data "$label.data" -var hdx $hdx \
    -var out "$label" -log "log.$label" > /dev/null
  echo "$label:$label"
}

if [ "${1:-}" = quick ]; then
  runs="$(disc correct 1.3 --) $(disc naive 1.3 -- --naive)"
  # measured (README.md): mean error 0.803 % (at Fo = 0.01), max 6.17 %; heat flow 2.61 % (energy
  # method), 2.03 % (direct estimate), both at Fo = 0.01; the naive set-up: 2.32 %, 9.3 %, 4.3 %, 13.4 %
  "$PYTHON" "$here/analyse.py" $runs --png disc.png \
    --max-mean-error 0.85 --max-error 6.5 --max-flux-error 2.8 --max-direct-error 2.2
  exit 0
fi
runs="$(disc correct 1.3 --) $(disc naive 1.3 -- --naive) $(disc rings3 1.3 -- --layers 3)"
runs="$runs $(disc naive8 1.3 -- --naive --connectivity 8) $(disc rings2 1.3 -- --layers 2)"
for eps in 0.3 0.45 0.5 0.6; do runs="$runs $(disc eps$eps 1.3 -- --eps $eps)"; done
runs="$runs $(disc centred 1.3 -- --offset 0,0) $(disc centred-eps0.5 1.3 -- --offset 0,0 --eps 0.5)"
runs="$runs $(disc h1.0 1.0 --) $(disc h1.0-rings2 1.0 -- --layers 2) $(disc h1.0-naive 1.0 -- --naive)"
# Cleary 1998: mean error < 0.5 % at each time
"$PYTHON" "$here/analyse.py" $runs --png disc.png --plot correct,naive,rings3 --max-mean-error 0.85
