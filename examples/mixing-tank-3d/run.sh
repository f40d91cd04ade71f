#!/bin/sh
# The heated cylindrical tank in 3-D (in.tank3d): set up the particles with
# tools/sph_boundary.py, run, and plot the fields and the mixing measures.
#   ./run.sh            two components (Reece et al. 2024 section 3.4.2),
#                       16 particles across, to t = 30 s
#   ./run.sh one        one component (section 3.4.1, nu = 1e-4 m^2/s), the
#                       top half as a passive tracer
#   ./run.sh air        one component with air's viscosity 1.506e-5 m^2/s
#                       (section 3.4.1's first case: was it axisymmetric?)
#   ./run.sh quick      two components, 12 across, to t = 5 s (a minute)
# Environment: LMP, PLUGIN, NP (MPI ranks), OUT (default ./out), N
# (particles across the diameter and the height), TEND (s), C0 (m/s).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

components=two
case "${1:-}" in
  one) components=one ;;
  air) components=air ;;
  quick) N=${N:-12} TEND=${TEND:-5} ;;
esac
N=${N:-16}
TEND=${TEND:-30}
name=tank3d_${components}_${N}

# the particles (tools/sph_boundary.py; the layout is described in
# tools/mixing_tank.py, write_tank_data).
dx=$("$PYTHON" "$root/tools/mixing_tank.py" setup "$N" "$name.data")
$run "$LMP" -in "$here/in.tank3d" -var plugin "$PLUGIN" -var data "$name.data" -var dx "$dx" \
  -var components "$components" -var tend "$TEND" ${C0:+-var c0 "$C0"} -var out "$name.dump" -var mixing "$name.mixing.txt" -var density "$name.density.txt" \
  -log "log.$name" | grep -E "^Reece|^final"
"$PYTHON" "$root/tools/mixing_tank.py" "$name.dump" --mixing "$name.mixing.txt" --dim 3 --dx "$dx" \
  --png "$name"
