# The LAMMPS releases USER-SPHTHERMAL supports, for the shell scripts
# (cmake/fetch-lammps.sh, tools/bootstrap.sh, tools/main.sh, tools/test.sh);
# the superbuild's LAMMPS_RELEASE takes the same names. Sourced.
lammps_releases="4Feb2025 29Sep2021"    # the first is the default

# lammps_release RELEASE: sets, or fails for an unknown release,
#   suite           the Debian release whose source package holds it
#   debian_version  the start of that package's version
#   version_text    LAMMPS_VERSION in its src/version.h
#   build           the build directory tools/main.sh and tools/test.sh use
lammps_release() {
  case $1 in
    4Feb2025) suite=trixie debian_version=20250204 version_text='4 Feb 2025' build=build ;;
    29Sep2021) suite=bookworm debian_version=20220106 version_text='29 Sep 2021' build=build-29Sep2021 ;;
    *) return 1 ;;
  esac
}
