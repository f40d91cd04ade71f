# Sourced by tools/main.sh and tools/test.sh: reads an optional leading
# '--lammps RELEASE' from the arguments and sets
#   release  4Feb2025 (default) or 29Sep2021
#   build    the build directory of that release: build (4Feb2025) or
#            build-29Sep2021, each with its own LAMMPS, plugin and tests
#   args     the remaining arguments
release=4Feb2025
if [ "${1:-}" = "--lammps" ]; then
  release=${2:?--lammps needs a release: 4Feb2025 or 29Sep2021}
  shift 2
fi
case $release in
  4Feb2025) build=build ;;
  29Sep2021) build=build-29Sep2021 ;;
  *) echo "$(basename "$0"): unknown LAMMPS release '$release' (4Feb2025 or 29Sep2021)" >&2; exit 1 ;;
esac
args=("$@")
