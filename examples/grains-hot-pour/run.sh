#!/bin/sh
# Hot glass grains poured into a tank of cold oil (fix sph/grains with
# natural convection): 2 s of the scene (about 4 min on one core; LAMMPS
# 4Feb2025 and later), results.md, the dump for OVITO or ParaView (out/hot-pour.dump:
# column v_T the temperature of oil, tank and grains) and hot-pour.png.
# The CI runs 0.05 s of it (test granular.hot_pour).
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

$run "$LMP" -in "$here/in.hot-pour" -var plugin "$PLUGIN" -var time ${TIME:-2.0} -log log.hot-pour > /dev/null
grep -E "^hot-pour: " log.hot-pour
cd "$here"
"$PYTHON" results.py "$OUT/log.hot-pour" > results.md
cat results.md
"$PYTHON" plot.py "$OUT/hot-pour.dump" 0,0.15,0.4,1.0,2.0 hot-pour.png
