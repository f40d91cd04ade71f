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

# the one dispatcher from run-time settings to a loop's template parameters
add_header_test_cxx(test_dispatch robust/test_dispatch.cpp)
set_target_properties(test_dispatch PROPERTIES CXX_STANDARD 11 CXX_STANDARD_REQUIRED ON
  CXX_EXTENSIONS OFF)
sphthermal_test(robust.architecture.dispatch LABELS unit COMMAND test_dispatch)
