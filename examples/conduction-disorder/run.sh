#!/bin/sh
# Stress tests of pair sph/cleary/heat on particles that are not a lattice
# (README.md): the two-material slab, 80 x 20, plain, with correction
# consistent or second, with mean interface (the interface estimated from
# the particles) or the distances given (+given: the true plane x = 0.5),
# against disorder, lattice angle and property ratio; writes
# results.jsonl, prints the table and writes disorder.png.
#   ./run.sh          all cases (about 45 minutes; OPERATORS=... for some)
#   ./run.sh quick    jitter 0.2, k ratio 3, rho cv ratio 0.5, four operators (the CI
#                     test, 30 seconds)
#   ./run.sh steel-water  the steel/water lattice with h = dx, plain (the CI test,
#                     about a minute, most of it the reference)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON,
# OPERATORS (default: none consistent consistent+interface consistent+given
# second+given).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

# kernel support in spacings (cubic B-spline: 2 h)
support=2.6

# case label, operator (none, consistent or second, with +interface or
# +given for mean interface), data options, k2, rhocv2, [nx]
slab() {
  label=$1 operator=$2 options=$3 k2=$4 rhocv2=$5 nx=${6:-80}
  correction=${operator%+*}
  mean=harmonic distance=estimated
  [ "$correction" = "$operator" ] || mean=interface
  [ "${operator#*+}" = given ] && distance=given
  name=$(echo "$label-$operator" | tr " =,/+" "_____")
  spacing=$("$PYTHON" "$here/disorder.py" data "$name.data" --nx "$nx" --ny $((nx / 4)) $options)
  $run "$LMP" -in "$here/in.disorder" -var plugin "$PLUGIN" -var data "$name.data" \
    -var spacing "$spacing" -var nx "$nx" -var k2 "$k2" -var rhocv2 "$rhocv2" \
    -var support "$support" -var correction "$correction" -var mean "$mean" \
    -var distance "$distance" -var out "$name" \
    -log "log.$name" > /dev/null
  shift 6
  "$PYTHON" "$here/disorder.py" errors "$name" --k2 "$k2" --rhocv2 "$rhocv2" --nx "$nx" \
    --label "$label $operator" "$@"
}

if [ "${1:-}" = quick ]; then
  # thresholds: the measured errors (README.md) with a margin
  slab "jitter 0.2" none "--jitter 0.2" 3 0.5 80 --max-drift 1e-12
  slab "jitter 0.2" consistent "--jitter 0.2" 3 0.5 80 --max-error 1.1 --max-drift 1e-12
  # measured 0.84 %: above 0.9 the interface estimate no longer helps
  slab "jitter 0.2" consistent+interface "--jitter 0.2" 3 0.5 80 --max-error 0.9 \
    --max-drift 1e-12
  # the bound asked of disordered particles: 1.5 times the lattice's 0.45 % (measured 0.611 %)
  slab "jitter 0.2" second+given "--jitter 0.2" 3 0.5 80 --max-error 0.675 --max-drift 1e-12
  exit 0
fi
if [ "${1:-}" = steel-water ]; then
  # the bound asked of the steel/water slab, 0.5 % at both times (measured 0.469 % and
  # 0.054 %); a second-order finite-volume solution on the same 80 cells is off by 0.528 %
  support=2.0
  slab "steel/water lattice h=dx" none "" 0.04114 1.1057 80 --max-error 0.5 --max-drift 1e-12
  exit 0
fi

rm -f results.jsonl
for operator in ${OPERATORS:-none consistent consistent+interface consistent+given second+given}; do
  for jitter in 0 0.05 0.1 0.2 0.3; do
    slab "jitter $jitter" $operator "--jitter $jitter" 3 0.5 80 --results results.jsonl
  done
  for angle in 8.5 20.2 36.9 45.0; do
    slab "angle $angle" $operator "--angle $angle" 3 0.5 80 --results results.jsonl
  done
  # jittered by 0.2 dx: k ratio, rho cv ratio (steel/water: 0.613/14.9, 997*4179/(7900*477))
  for ratio in "3 0.5" "10 1" "100 1" "1000 1" "1 1000" "1000 1000" "0.04114 1.1057"; do
    set -- $ratio
    slab "ratio k=$1,rhocv=$2" $operator "--jitter 0.2" $1 $2 80 --results results.jsonl
  done
  slab "steel/water lattice" $operator "" 0.04114 1.1057 80 --results results.jsonl
done
"$PYTHON" "$here/disorder.py" report results.jsonl disorder.png
