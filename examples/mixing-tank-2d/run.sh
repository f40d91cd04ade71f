#!/bin/sh
# Run the two-component heated tank of Reece et al. 2024, section 3.4.3, in
# 2-D (in.tank), then print its frames and write tank.png (analyse.py), and
# the mixing measures and fields (tools/mixing_tank.py: tank_mixing_*.png).
#   ./run.sh              39 x 39 fluid particles to t = 150 s (about an hour on one core)
#   TEND=300 ./run.sh     to t = 300 s, Reece et al.'s end (about 2 h)
#   TEND=60 ./run.sh      to t = 60 s (about 25 min; the fluid is within 0.002 K of 303 K)
#   N=77 ./run.sh         dp = 0.0005 m (about 8 times the cost)
#   ./run.sh quick        16 x 16 to t = 40 s (the CI setting, about a minute)
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), N, TEND.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"
if [ "${1:-}" = quick ]; then N=${N:-16} TEND=${TEND:-40}; fi
$run "$LMP" -in "$here/in.tank" -var plugin "$PLUGIN" -var n "${N:-39}" \
  -var tend "${TEND:-150}" -var out tank.dump -log log.tank | grep -E "^Reece|^mean T|^final"
"$PYTHON" "$here/analyse.py" tank.dump --png tank.png
# the mixing measures against time, the fields, the particles lost, the symmetry
"$PYTHON" "$root/tools/mixing_tank.py" tank.dump --mixing mixing.txt --dim 2 \
  --dx "$("$PYTHON" -c "print(0.0386 / ${N:-39})")" --png tank_mixing
