#!/usr/bin/env bash
# The same numbers from both supported LAMMPS releases: runs every stored
# regression state of the test suite (conduction rates on four kernels and
# five variants, the flow states on five variants) with the plugin and
# state driver of two build directories, and compares them field by field
# (T, esph, desph, rho, drho, x, v, f).
#   tools/compare-releases.sh [BUILD_A [BUILD_B [RTOL]]]
# defaults: build (4Feb2025), build-29Sep2021, 1e-14 (measured: 0, bitwise)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
a=$(cd "${1:-$root/build}" && pwd)
b=$(cd "${2:-$root/build-29Sep2021}" && pwd)
rtol=${3:-1e-14}
python=$("$root/tools/find-python.sh")
sphtest() {
  "$python" "$root/unittest/tools/sphtest.py" same \
    --driver "$a/unittest/sph_state_host" --driver2 "$b/unittest/sph_state_host" \
    --var plugin="$a/sphthermalplugin.so" --var2 plugin="$b/sphthermalplugin.so" --rtol "$rtol" "$@"
}
failed=0
check() {
  local name=$1
  shift
  if out=$(sphtest "$@" 2>&1); then
    echo "ok   $name"
  else
    echo "FAIL $name"
    echo "$out" | grep -v '^ok' | sed 's/^/     /'
    failed=1
  fi
}
rates=$root/unittest/conduction/in.rates
flow=$root/unittest/flow/in.flow
for kernel in lucy cubic quintic wendland; do
  check "conduction rates, $kernel" --input "$rates" --var kernel=$kernel
done
check "conduction rates, harmonic mean, eta 0" --input "$rates" --var kernel=cubic --var mean=harmonic --var eta=0
check "conduction rates, arithmetic mean" --input "$rates" --var kernel=cubic --var mean=arithmetic --var eta=0
check "conduction rates, k(T)" --input "$rates" --var kernel=cubic --var laws=varying
check "conduction rates, isothermal wall" --input "$rates" --var kernel=cubic --var wall=yes --var laws=varying
check "conduction rates, Dirichlet wall" --input "$rates" --var kernel=cubic --var wall=dirichlet --var laws=varying
check "flow, default" --input "$flow"
check "flow, sum pressure, Morris viscosity" --input "$flow" --var pressure=sum --var viscosity=morris --var delta=0
check "flow, symmetric pressure, Cleary viscosity" --input "$flow" --var pressure=symmetric --var viscosity=cleary --var delta=0
check "flow, gravity" --input "$flow" --var body=-0.5
check "flow, gravity, Fourtakas diffusion" --input "$flow" --var body=-0.5 --var fourtakas=yes
[ $failed = 0 ] && echo "compare-releases: $(basename "$a") and $(basename "$b") agree to $rtol on every state"
exit $failed
