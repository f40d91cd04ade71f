# the package's architecture: styles find each other by type through SPHHub
# (no by-name or void* look-ups outside it; the check's self-test sees each
# kind of offence), and no source file above 800 lines
set(sphthermal_src ${SPHTHERMAL_PKG_DIR})
sphthermal_python_test(robust.architecture.coupling robust/check_coupling.py
  ARGS ${sphthermal_src} LABELS unit)
sphthermal_python_test(robust.architecture.coupling_selftest robust/check_coupling.py
  ARGS ${sphthermal_src} --expect-offence ${CMAKE_CURRENT_LIST_DIR}/coupling_offender.cpp.txt
  LABELS unit)
sphthermal_python_test(robust.architecture.file_sizes robust/check_file_sizes.py
  ARGS ${sphthermal_src} LABELS unit)
