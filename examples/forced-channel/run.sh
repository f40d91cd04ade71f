#!/bin/sh
# Run the heated channel and compare it with the finite-volume reference
# (tools/channel_fv.py); writes channel.png.
#   ./run.sh            Re = 652, walls at 420 K, 20 particles across (the
#                       paper's resolution), from the developed flow to
#                       t = 150 s (1892 s of loop on one core, shared)
#   ./run.sh quick      Re = 65.2, 10 across, to t = 800 s (the CI test
#                       forced.validation.channel_re65_10, about 140 s; at
#                       Re = 652 10 across is too coarse: the flow breaks up)
#   ./run.sh thick      the thick-wall channel (10 m slabs, KSK = k_s/k); with
#                       N=10 RE=65.2 TEND=800 the CI test
#                       forced.validation.thick_re65_10 (about 190 s)
#   ./run.sh exchanger  the parallel-flow and counter-flow heat exchangers
#                       (in.exchanger, section 4.5), to TEND = 200 s with the
#                       plate's cp lowered to 2.5 (the steady state does not
#                       depend on it; PLATECP), a frame every 25 s (the
#                       outlets of each printed), about 1.4 hours each;
#                       SHIFTC, CONTINUITY, NOSLIP, HOLD, EOS, FLOW,
#                       CONDUCTION and DTRESET as for in.channel (the same
#                       defaults)
# Environment: LMP, PLUGIN, NP, OUT as in the other examples; N (particles
# across), TEND (s), RE, KSK, INLET (periodic|open: in.channel's inlet, a
# true inlet and outlet with open; the CI test forced.validation.open_re65_10
# is INLET=open ./run.sh quick), SHIFT (yes|no), SHIFTC (C of the shift;
# in.channel's 0.5), START (developed|rest),
# HOLD (yes|no: the fluid keeps its volume; in.channel's yes), CONTINUITY
# (yes|no: the shift's continuity keyword; in.channel's no), NOSLIP
# (surface|shepard: the walls' no-slip velocity; in.channel's surface),
# and in.channel's variables that add to the package's defaults: EOS
# (keywords of the eos, e.g. "background 0.01 relative"), FLOW (options
# of pair sph/harmonic/visc), CONDUCTION (options of pair sph/cleary/heat,
# e.g. "mean interface"), DTRESET (keywords of fix sph/dt/reset, e.g.
# "acoustic 0.15");
# MAX_T_ERROR (exit 1 above it, % of T_w - T_in), MAX_VY (exit 1 above it,
# % of u_max).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = exchanger ]; then
  for arrangement in parallel counter; do
    rm -f "exchanger-$arrangement.dump"
    $run "$LMP" -in "$here/in.exchanger" -var plugin "$PLUGIN" -var arrangement "$arrangement" \
      -var tend "${TEND:-200}" -var every 25 -var platecp "${PLATECP:-2.5}" \
      ${SHIFTC:+-var shiftc "$SHIFTC"} ${CONTINUITY:+-var continuity "$CONTINUITY"} \
      ${NOSLIP:+-var noslip "$NOSLIP"} ${HOLD:+-var hold "$HOLD"} ${EOS:+-var eos "$EOS"} \
      ${FLOW:+-var flow "$FLOW"} ${CONDUCTION:+-var conduction "$CONDUCTION"} \
      ${DTRESET:+-var dtreset "$DTRESET"} -var out "exchanger-$arrangement" \
      -log "log.exchanger-$arrangement" | grep -E "^u_max|^dt =|Loop time"
  done
  "$PYTHON" "$here/analyse_exchanger.py" exchanger-parallel.dump exchanger-counter.dump \
    --history --png exchanger.png ${MAX_OUTLET_ERROR:+--max-outlet-error "$MAX_OUTLET_ERROR"}
  exit 0
fi

WALLS=dirichlet
case "${1:-}" in
  quick) N=${N:-10} RE=${RE:-65.2} TEND=${TEND:-800} ;;
  thick) WALLS=thick ;;
esac
N=${N:-20}
TEND=${TEND:-150}
RE=${RE:-652}
KSK=${KSK:-1}
INLET=${INLET:-periodic}
name=channel-$WALLS
open_flag=""
if [ "$INLET" != periodic ]; then name=$name-$INLET; open_flag=--open; fi
rm -f "$name.dump"
$run "$LMP" -in "$here/in.channel" -var plugin "$PLUGIN" -var n "$N" -var tend "$TEND" \
  -var re "$RE" -var walls "$WALLS" -var inlet "$INLET" -var ksk "$KSK" -var shift "${SHIFT:-yes}" \
  ${SHIFTC:+-var shiftc "$SHIFTC"} \
  ${CONTINUITY:+-var continuity "$CONTINUITY"} ${NOSLIP:+-var noslip "$NOSLIP"} \
  ${HOLD:+-var hold "$HOLD"} ${EOS:+-var eos "$EOS"} ${FLOW:+-var flow "$FLOW"} \
  ${CONDUCTION:+-var conduction "$CONDUCTION"} ${DTRESET:+-var dtreset "$DTRESET"} \
  -var start "${START:-developed}" -var every "$TEND" -var out "$name" -log "log.$name" |
  grep -E "^u_max|^dt =|speed of sound|Loop time|sph/cleary/heat:"
"$PYTHON" "$here/analyse.py" "$name.dump" --walls "$WALLS" --ksk "$KSK" --re "$RE" --n "$N" \
  --png "$name.png" $open_flag ${MAX_T_ERROR:+--max-t-error "$MAX_T_ERROR"} ${MAX_VY:+--max-vy "$MAX_VY"}
