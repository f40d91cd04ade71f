# Sourced by examples/*/run.sh after setting 'here' to the example's directory.
# Sets root, LMP, PLUGIN, PYTHON, OUT, NP and 'run' (the mpirun prefix when
# NP > 1) from the environment or their defaults, puts <repo>/tools on
# PYTHONPATH (the analysis scripts import sphthermal_tools and the solvers
# of tools/ from there, as in the tests), and enters OUT.
root=$(cd "$here/../.." && pwd)
export PYTHONPATH="$root/tools${PYTHONPATH:+:$PYTHONPATH}"
LMP=${LMP:-$root/build/lmp}
PLUGIN=${PLUGIN:-$root/build/sphthermalplugin.so}
PYTHON=${PYTHON:-$("$root/tools/find-python.sh")}
OUT=${OUT:-$here/out}
NP=${NP:-1}
run=""
if [ "$NP" -gt 1 ]; then
  run="mpirun --oversubscribe -np $NP"
  [ "$(id -u)" -eq 0 ] && run="$run --allow-run-as-root"
fi
mkdir -p "$OUT"
cd "$OUT"
