#!/bin/sh
# Run the differentially heated cavity, compare it with the benchmark and the
# reference solver, and write cavity.png.
#   ./run.sh              Ra = 1e4, 40 x 40 fluid particles, to t = 0.3 (about 3 minutes)
#                         (t = 1.5 at Ra = 1e3)
#   ./run.sh quick        the same at 20 x 20 (about 40 s)
#   ./run.sh conduction   Ra = 0: Nu must be 1 (20 x 20, to t = 0.6)
#   ./run.sh air          Reece et al. 2024 section 3.2 in SI units (in.air),
#                         N = 40 across to t* = 0.5 (TSTAR), about 5 minutes;
#                         DELTA=0 for their Table 2 (no density diffusion),
#                         END_SECONDS=60 for the run time of their Table 3
#   RA=1e5 N=60 ./run.sh  another Rayleigh number or resolution
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), RA, N, TEND, KERNEL, HDX, BG
# (background pressure / (rho0 c0^2)), NZ (> 0: quasi-2-D, 3-D with a
# periodic depth of NZ spacings); CONDUCTION (options of pair
# sph/cleary/heat), GRADIENT (correction of pair sph/harmonic/visc: gradient
# or none), NOSLIP (the walls' no-slip velocity: shepard or surface) and SHIFT (D of fix sph/shift; 0: no shifting), in.cavity's
# defaults when unset (any of KERNEL to POTENTIAL runs in.cavity-options, the
# scene with every setting a variable; without them in.cavity, the flagship); SQUEEZE (the largest compression by the buoyancy,
# g beta dT L / c0^2: sets the least speed of sound), POTENTIAL (sweeps per
# step of fix sph/boussinesq's potential; 0: off), ACOUSTIC (the acoustic
# coefficient of fix sph/dt/reset), MAX_NU_ERROR (exit 1 above it, %).
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = air ]; then
  # Reece et al. 2024, section 3.2, in SI units (in.air): Ra = 1.203e5, Pr = 0.705
  $run "$LMP" -in "$here/in.air" -var plugin "$PLUGIN" -var n "${N:-40}" \
    -var tstar "${TSTAR:-0.5}" -var seconds "${END_SECONDS:-0}" \
    -var delta "${DELTA:-0.1}" -var acoustic "${ACOUSTIC:-0.1}" -var out air.dump -log log.air | grep -E "^Reece|^at t|final"
  "$PYTHON" "$here/analyse.py" air.dump --log log.air --ra 1.2033e5 --pr 0.7051 \
    --si 0.0386 2.13594e-5 283 20 --png air.png
  exit 0
fi
case "${1:-}" in
  conduction) RA=0 N=${N:-20} TEND=${TEND:-0.6} ;;
  quick) N=${N:-20} ;;
esac
RA=${RA:-1e4}
N=${N:-40}
if [ "$RA" != 0 ] && [ -z "${KERNEL:-}${HDX:-}${BG:-}${NZ:-}${CONDUCTION:-}${GRADIENT:-}${NOSLIP:-}${SHIFT:-}${SQUEEZE:-}${ACOUSTIC:-}${POTENTIAL:-}" ]; then
  # the flagship: every numerical setting the package's default
  $run "$LMP" -in "$here/in.cavity" -var plugin "$PLUGIN" -var ra "$RA" -var n "$N" \
    ${TEND:+-var tend "$TEND"} -log log.cavity | grep -E "default|final"
else
  # the same scene with every setting a variable (the studies of options)
  $run "$LMP" -in "$here/in.cavity-options" -var plugin "$PLUGIN" -var ra "$RA" -var n "$N" \
    -var tend "${TEND:-0}" -var kernel "${KERNEL:-wendland}" -var hdx "${HDX:-2.0}" \
    -var bg "${BG:-0.1}" -var nz "${NZ:-0}" ${CONDUCTION:+-var conduction "$CONDUCTION"} \
    ${GRADIENT:+-var gradient "$GRADIENT"} ${NOSLIP:+-var noslip "$NOSLIP"} ${SHIFT:+-var shift "$SHIFT"} \
    ${SQUEEZE:+-var squeeze "$SQUEEZE"} ${POTENTIAL:+-var potential "$POTENTIAL"} -var acoustic "${ACOUSTIC:-0.1}" \
    -var out cavity.dump -log log.cavity | grep -E "^Ra =|final"
fi
if [ "$RA" = 0 ]; then
  echo "without buoyancy the exact Nu is 1"
  exit 0
fi
"$PYTHON" "$here/analyse.py" cavity.dump --log log.cavity --ra "$RA" --nz "${NZ:-0}" --png cavity.png \
  ${MAX_NU_ERROR:+--max-nu-error "$MAX_NU_ERROR"}
