#!/bin/sh
# Xu's 3-D bar, a MACHDYN solid, heated at one face, against the exact series.
#   ./run.sh          n = 4 (Xu's spacing) and 8 particles across, held face and flux, and the
#                     held face of the bar alone, with free side faces (about 30 minutes)
#   ./run.sh quick    n = 4, both cases, and the held case with the bar in atom style sph's
#                     convention, which must give the same temperatures (the CI test)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

bar() {    # case n machdyn label [around]
  $run "$LMP" -in "$here/in.bar" -var plugin "$PLUGIN" -var case $1 -var n $2 -var machdyn $3 \
    -var around ${5:-yes} -var out "$1-$4.dump" -log "log.$1-$4" > /dev/null
  echo "$1:$4:$1-$4.dump"
}

if [ "${1:-}" = quick ]; then
  # measured (README.md): 0.57 % (held), 1.24 % (flux) at n = 4
  "$PYTHON" "$here/analyse.py" $(bar held 4 yes n=4) $(bar flux 4 yes n=4) --max-error 1.3
  "$PYTHON" "$here/analyse.py" $(bar held 4 yes n=4) $(bar held 4 no sph-n=4) --same-as n=4 \
    --rtol 1e-10 --png same.png
  exit 0
fi
"$PYTHON" "$here/analyse.py" $(bar held 4 yes n=4) $(bar held 8 yes n=8) $(bar flux 4 yes n=4) \
  $(bar flux 8 yes n=8) $(bar held 4 yes free-n=4 no) $(bar held 8 yes free-n=8 no) \
  --results "$here/results.md"
cp bar.png "$here/bar.png"
