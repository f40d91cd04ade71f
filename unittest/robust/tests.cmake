# robust tests: bad values and misuses (included by unittest/CMakeLists.txt;
# helpers: cmake/sphthermal_tests.cmake)

# non-finite values, out-of-range laws and misuses of styles and groups
add_error_cases(robust robust/errors.in)
# the probes of each style and option: robust/<name>_errors.in gives the
# tests robust.<name>.error.<case>; robust/<name>.cmake adds any other test
file(GLOB robust_case_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*_errors.in)
foreach(cases ${robust_case_files})
  get_filename_component(stem ${cases} NAME_WE)
  string(REGEX REPLACE "_errors$" "" stem ${stem})
  add_error_cases(robust.${stem} ${cases})
endforeach()
file(GLOB robust_cmake_files CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.cmake)
list(REMOVE_ITEM robust_cmake_files ${CMAKE_CURRENT_LIST_FILE})
foreach(file ${robust_cmake_files})
  include(${file})
endforeach()

# a stop on one rank of two (a NaN position found by the rank that owns the
# atom) names its rank and the atom, before MPI aborts (SPHCheck::stop)
sphthermal_test(robust.faults.error.mpi.nan_position_dirichlet_wall LABELS mpi PROCESSORS 2
  COMMAND ${sphtest} error --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
          --cases ${CMAKE_CURRENT_LIST_DIR}/faults_errors.in --name nan_position_dirichlet_wall
          --np 2 --mpirun ${MPIRUN})

# every error and warning call of the package's sources is raised by an
# error case (the cases run first: they record the lines that raised them;
# robust.error_branches runs after all of them: unittest/CMakeLists.txt
# gives it their list as DEPENDS once every area has registered its cases)
file(GLOB error_case_files CONFIGURE_DEPENDS ${SPHTHERMAL_TESTS_DIR}/*/*errors.in)
sphthermal_test(robust.error_branches LABELS unit
  COMMAND ${sphtest} branches --package ${SPHTHERMAL_PKG_DIR} --records ${error_sites_dir}
          --plugin ${SPHTHERMAL_PLUGIN} --cases ${error_case_files})

# the books of the thermal fixes in both orders of the fixes
foreach(pair iso_flux_same_atoms iso_flux iso_dir flux_dir)
  sphthermal_python_test(robust.books.${pair} robust/test_books.py LAMMPS ARGS --pair ${pair}
    LABELS validation)
endforeach()

# fix sph/dt/reset's defaults keep T within its initial range at extreme
# conductivity and heat-capacity ratios and disorder; 4 times past its limit
# they do not
foreach(case arithmetic_k1e4 harmonic_k1e4 arithmetic_k1e4_rhocv1e3 harmonic_rhocv1e3_disorder)
  sphthermal_python_test(robust.dt_stable.${case} robust/test_dt_stable.py LAMMPS
    ARGS --case ${case} LABELS validation)
endforeach()
