#!/bin/sh
# forced.validation.laminar_652: the heated channel of examples/forced-channel
# at Re = 652, 20 across, cut to 40 m, from the developed flow to t = 60 s
# with delta-plus shifting: the largest |v| of the fluid must stay below
# MAX_VY % of u_max (without shifting it exceeds 2 % by t = 40 s).
#   laminar.sh LMP PLUGIN PYTHON WORKDIR MAX_VY
set -e
lmp=$1 plugin=$2 python=$3 work=$4 max_vy=$5
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$work"
cd "$work"
"$lmp" -in "$root/examples/forced-channel/in.channel" -var plugin "$plugin" -var length 40 \
  -var tend 60 -var every 60 -var out laminar -log log.laminar > /dev/null
"$python" "$root/examples/forced-channel/stability.py" log.laminar:shifted --png laminar.png \
  --max-vy "$max_vy"
