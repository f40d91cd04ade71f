#!/bin/sh
# Run the differentially heated cavity and print the mean Nusselt numbers.
#   ./run.sh              Ra = 1e4, 40 x 40 fluid particles, to t = 0.3 (about 1 minute)
#   ./run.sh conduction   Ra = 0: Nu must be 1 (20 x 20, to t = 0.6)
#   RA=1e5 N=60 ./run.sh  another Rayleigh number or resolution
# Environment: LMP (LAMMPS binary), PLUGIN (sphthermalplugin.so), NP (MPI
# ranks), OUT (output directory, default ./out), RA, N, TEND, KERNEL, HDX.
set -e
here=$(cd "$(dirname "$0")" && pwd)
. "$here/../common.sh"

if [ "${1:-}" = conduction ]; then
  RA=0 N=${N:-20} TEND=${TEND:-0.6}
fi
RA=${RA:-1e4}
N=${N:-40}
TEND=${TEND:-0.3}
$run "$LMP" -in "$here/in.cavity" -var plugin "$PLUGIN" -var ra "$RA" -var n "$N" \
  -var tend "$TEND" -var kernel "${KERNEL:-quintic}" -var hdx "${HDX:-1.0}" \
  -var out cavity.dump -log log.cavity | grep -E "^Ra =|final:"
echo "de Vahl Davis (1983) mean Nu: 1.118 (Ra 1e3), 2.243 (1e4), 4.519 (1e5), 8.800 (1e6); 1 without buoyancy"
