#!/bin/sh
# Locate the Rayleigh-Benard onset by the growth rate of a small perturbation
# (in.rb) and compare it with linear theory (tools/rb_linear.py); writes
# onset.png and the logs log.rb.* in OUT.
#   ./run.sh              W = 2H, 20 particles per H, regula falsi from
#                         [1000, 4000] (about 30 s of LAMMPS, 6 to 8 runs)
#   ./run.sh wide15       W = 1.5H (linear theory Ra_c = 1955.81)
#   N=30 ./run.sh         another resolution (about 2 minutes)
#   METHOD=bisect STEPS=6 ./run.sh   halve the bracket on the sign of sigma
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), PYTHON,
# OUT (output directory, default ./out), N, WIDTH, LO, HI, STEPS, METHOD
# (falsi or bisect), WINDOW (fit window "T0 T1", default "0.1 0.3"; the runs
# end at T1), EPS (perturbation), MAX_ONSET_ERROR (exit 1 above it, %),
# RESULTS (the results file that keeps each width's and resolution's onset,
# default onsets.txt here).
# The runs are serial (NP is not used).
#   ./run.sh nu           convection above onset: Ra = 1e4 and 2e4 (RA="..."),
#                         N particles per H, to t = 0.8, mean Nu over
#                         t >= 0.4 against tools/rb_fv.py; writes nu.txt
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = nu ]; then
  # shellcheck disable=SC2086
  "$PYTHON" "$here/analyse.py" nu --run ${RA:-1e4 2e4} --n "${N:-20}" --tend "${TEND:-0.8}" \
    --lmp "$LMP" --plugin "$PLUGIN" \
    --from "${FROM:-0.4}" --out nu.txt ${MAX_NU_ERROR:+--max-error "$MAX_NU_ERROR"}
  exit
fi

if [ "${1:-}" = wide15 ]; then
  WIDTH=${WIDTH:-1.5}
fi
WIDTH=${WIDTH:-2.0}
N=${N:-20}
WINDOW=${WINDOW:-0.1 0.3}
export LMP PLUGIN
# shellcheck disable=SC2086
"$PYTHON" "$here/analyse.py" onset --width "$WIDTH" --n "$N" \
  --lo "${LO:-1000}" --hi "${HI:-4000}" --steps "${STEPS:-6}" --method "${METHOD:-falsi}" \
  --window $WINDOW --eps "${EPS:-1e-2}" --out . --png onset.png \
  --results "${RESULTS:-$here/onsets.txt}" \
  ${MAX_ONSET_ERROR:+--max-error "$MAX_ONSET_ERROR"}
