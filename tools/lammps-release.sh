# Sourced by tools/main.sh and tools/test.sh: reads optional leading
# '--lammps RELEASE' and '--sizes bigbig' from the arguments and sets
#   release  4Feb2025 (default) or 29Sep2021
#   sizes    smallbig (default, LAMMPS's) or bigbig (64-bit atom IDs)
#   build    the build directory of that release: build (4Feb2025) or
#            build-29Sep2021, each with its own LAMMPS, plugin and tests;
#            with bigbig the same name and -bigbig
#   args     the remaining arguments
. "$(dirname "${BASH_SOURCE[0]}")/../cmake/lammps-releases.sh"
release=${lammps_releases%% *}
sizes=smallbig
while [ "${1:-}" = "--lammps" ] || [ "${1:-}" = "--sizes" ]; do
  case $1 in
    --lammps) release=${2:?--lammps needs a release: $lammps_releases} ;;
    --sizes) sizes=${2:?--sizes needs smallbig or bigbig} ;;
  esac
  shift 2
done
lammps_release "$release" || {
  echo "$(basename "$0"): unknown LAMMPS release '$release' ($lammps_releases)" >&2
  exit 1
}
case $sizes in
  smallbig) ;;
  bigbig) build=$build-bigbig ;;
  *)
    echo "$(basename "$0"): unknown integer sizes '$sizes' (smallbig, bigbig)" >&2
    exit 1
    ;;
esac
args=("$@")
