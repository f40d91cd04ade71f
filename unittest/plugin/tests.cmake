# plugin, package and build tests (included by unittest/CMakeLists.txt;
# helpers: cmake/sphthermal_tests.cmake)
sphthermal_test(plugin.styles LABELS unit
  COMMAND ${sphtest} styles --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
          --package ${SPHTHERMAL_PKG_DIR})
sphthermal_test(plugin.exports LABELS unit COMMAND ${sphtest} exports --plugin ${SPHTHERMAL_PLUGIN})
# in-tree route: cmake/install-package.sh and make yes/no-user-sphthermal
sphthermal_test(package.install LABELS unit
  COMMAND ${SPHTHERMAL_TESTS_DIR}/tools/test_install_package.sh ${LAMMPS_SOURCE_DIR})

# LAMMPS 4Feb2025 loads the plugin from LAMMPS_PLUGIN_PATH at start
if(LAMMPS_RELEASE STREQUAL "4Feb2025")
  sphthermal_test(plugin.autoload LABELS unit
    PASS "Loaded 1 plugins.*USER-SPHTHERMAL plugin is already loaded: plugin load ignored.*autoload: pair style sph/cleary/heat defined"
    FAIL "ERROR"
    COMMAND ${CMAKE_COMMAND} -E env LAMMPS_PLUGIN_PATH=${CMAKE_BINARY_DIR}
            ${SPHTHERMAL_LMP} -in ${CMAKE_CURRENT_LIST_DIR}/in.autoload
            -var plugin ${SPHTHERMAL_PLUGIN} -log none)
endif()

# the in-tree build (LAMMPS with the package compiled in) gives the plugin's numbers
if(SPHTHERMAL_BUILD_INTREE)
  add_state_driver(sph_state_intree ${LAMMPS_INTREE_BUILD_DIR})
  add_dependencies(sph_state_intree lammps-intree)
  set(intree DRIVER2 $<TARGET_FILE:sph_state_intree> RTOL 1e-14)
  foreach(kernel ${kernels})
    sphthermal_state_test(plugin.same_as_intree.${kernel} same ${rates_input} ${intree}
      ARGS --var kernel=${kernel} --var2 plugin=none)
  endforeach()
  sphthermal_state_test(plugin.same_as_intree.flow same ${flow_input} ${intree}
    ARGS --var2 plugin=none)
endif()

# the superbuild refuses a LAMMPS tree of the other release and an unknown release
if(LAMMPS_RELEASE STREQUAL "4Feb2025")
  set(other_release 29Sep2021)
else()
  set(other_release 4Feb2025)
endif()
sphthermal_test(build.error.release_mismatch LABELS unit
  PASS "holds[\n ]+LAMMPS[\n ]+${LAMMPS_RELEASE},[\n ]+not[\n ]+LAMMPS_RELEASE=${other_release}"
  COMMAND ${CMAKE_COMMAND} -S ${SPHTHERMAL_ROOT}/cmake -B ${CMAKE_CURRENT_BINARY_DIR}/release_mismatch
          -D LAMMPS_RELEASE=${other_release} -D LAMMPS_SOURCE_DIR=${LAMMPS_SOURCE_DIR})
sphthermal_test(build.error.unknown_release LABELS unit
  PASS "LAMMPS_RELEASE=2Aug2023:[\n ]+USER-SPHTHERMAL[\n ]+supports[\n ]+4Feb2025[\n ]+and[\n ]+29Sep2021"
  COMMAND ${CMAKE_COMMAND} -S ${SPHTHERMAL_ROOT}/cmake -B ${CMAKE_CURRENT_BINARY_DIR}/unknown_release
          -D LAMMPS_RELEASE=2Aug2023 -D LAMMPS_SOURCE_DIR=${LAMMPS_SOURCE_DIR})
