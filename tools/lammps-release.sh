# Sourced by tools/main.sh and tools/test.sh: reads an optional leading
# '--lammps RELEASE' from the arguments and sets
#   release  4Feb2025 (default) or 29Sep2021
#   build    the build directory of that release: build (4Feb2025) or
#            build-29Sep2021, each with its own LAMMPS, plugin and tests
#   args     the remaining arguments
. "$(dirname "${BASH_SOURCE[0]}")/../cmake/lammps-releases.sh"
release=${lammps_releases%% *}
if [ "${1:-}" = "--lammps" ]; then
  release=${2:?--lammps needs a release: $lammps_releases}
  shift 2
fi
lammps_release "$release" || {
  echo "$(basename "$0"): unknown LAMMPS release '$release' ($lammps_releases)" >&2
  exit 1
}
args=("$@")
