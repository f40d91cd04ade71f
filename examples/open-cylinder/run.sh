#!/bin/sh
# The cylinder in a channel of Schafer & Turek (1996), test 2D-1 (Re = 20):
# drag and lift coefficients and the pressure difference across the
# cylinder against the benchmark's intervals; the cylinder heated (in.cylinder's
# heat = yes, Pr = 0.71): its mean Nusselt number against the finite-element
# reference of tools/cylinder_heat_fe.py, 3.18844 (error 2e-6).
# Test 2D-2 (Re = 100, periodic shedding): the Strouhal number, the largest
# drag and lift coefficients and the pressure difference against the
# benchmark's intervals (analyse_shedding.py).
#   ./run.sh          2D-1: 10 and 20 particles per diameter, to t = 8 s, averaged from 3 s, PNGs
#   ./run.sh quick    2D-1: 10 per diameter, to t = 4 s, averaged from 2 s (the CI test
#                     open.validation.cylinder_10)
#   ./run.sh shedding 2D-2: 10, 15 and 20 per diameter, to t = 6 s, fitted from 3 s,
#                     a PNG of 20
#   ./run.sh shedding-quick
#                     2D-2: 10 per diameter, to t = 3 s, fitted from 1.5 s (the CI
#                     test open.validation.shedding_10)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), PYTHON.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

# measured (README.md): C_D +2.2 and +1.6 % above the benchmark's interval
# at 10 and 20 per diameter, dp -1.8 and +1.9 %, C_L 0.018 and 0.011 (its
# noise 0.12-0.24 rms), Nu +2.6 and +0.24 %; the quick run Nu +2.8 %
# 2D-2: St +6.5 %, +1.2 %, inside the interval at 10, 15, 20 per diameter;
# C_D,max +7.5 and +10 %, C_L,max 0 and +19 % at 15 and 20
# the cylinder's mean Nusselt number at Re = 20, Pr = 0.71, from the
# reference's results file (3.18844)
NU_REF=$(awk '/^Nu *=/ {print $3}' "$root/tools/cylinder_heat_fe_results.txt")
[ -n "$NU_REF" ] || { echo "no Nu in tools/cylinder_heat_fe_results.txt" >&2; exit 1; }
# the cylinder's rings for <n> particles per diameter into <file>
cylinder_rings() {
  "$PYTHON" "$here/cylinder_rings.py" "$1" "$2" 2> /dev/null
}
case "${1:-}" in
  shedding|shedding-quick)
    if [ "$1" = shedding ]; then
      sizes="10 15 20"; tend=6; from=3; limits="--max-st 3"
    else
      sizes=10; tend=3; from=1.5; limits="--max-st 12 --min-lift 0.2"
    fi
    for n in $sizes; do
      name=shedding_$n
      cylinder_rings $n $name.data
      $run "$LMP" -in "$here/in.cylinder" -var plugin "$PLUGIN" -var n $n -var re 100 \
        -var tend $tend -var data $name.data -var out $name -log log.$name > /dev/null
      echo "$n per diameter:"
      grep -E "^final" log.$name
      png=""
      [ "$1" = shedding ] && [ $n = 20 ] && png="--png $name.png"
      # 10 per diameter is too coarse for 3 %: checked for shedding only
      check=$limits
      [ "$1" = shedding ] && [ $n = 10 ] && check="--max-st 12 --min-lift 0.2"
      ok=0
      "$PYTHON" "$here/analyse_shedding.py" $name.forces --from $from $check $png \
        > $name.analysis || ok=1
      cat $name.analysis
      [ $ok -eq 0 ] || failed=1
    done
    exit ${failed:-0} ;;
  quick)
    sizes=10; tend=4; from=2
    limits="--max-drag 4 --max-dp 5 --min-lift -0.1 --max-lift 0.1 --max-nu 4" ;;
  *)
    sizes="10 20"; tend=8; from=3
    limits="--max-drag 3 --max-dp 4 --min-lift -0.1 --max-lift 0.1 --max-nu 3" ;;
esac
for n in $sizes; do
  name=cylinder_$n
  cylinder_rings $n $name.data
  $run "$LMP" -in "$here/in.cylinder" -var plugin "$PLUGIN" -var n $n -var tend $tend \
    -var data $name.data -var out $name -var heat yes -log log.$name > /dev/null
  echo "$n per diameter:"
  grep -E "^final" log.$name
  png=""
  [ "${1:-}" = quick ] || png="--png $name.png"
  ok=0
  "$PYTHON" "$here/analyse.py" $name.forces --from $from $limits --nu-ref $NU_REF $png \
    > $name.analysis || ok=1
  cat $name.analysis
  [ $ok -eq 0 ] || failed=1
done
exit ${failed:-0}
