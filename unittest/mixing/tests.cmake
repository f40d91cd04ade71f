# mixing tests (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)
add_header_test(test_mixing_terms mixing/test_mixing_terms.c C_EXTENSIONS OFF)
# the same checks with the header compiled as C++
add_header_test_cxx(test_mixing_terms_cxx mixing/test_mixing_terms_cxx.cpp)
sphthermal_unit_checks(mixing.terms test_mixing_terms robinson composition ftle entropy)
sphthermal_test(mixing.terms.cxx LABELS unit COMMAND test_mixing_terms_cxx entropy)
add_error_cases(mixing mixing/errors.in)
# compute sph/mixing against values computed independently in the script
foreach(check segregated uniform shear restart renumber)
  sphthermal_python_test(mixing.${check} mixing/test_mixing.py LAMMPS ARGS ${check} LABELS unit)
endforeach()
# coarse versions of the examples' tanks (Reece et al. 2024, section 3.4)
sphthermal_python_test(mixing.validation.tank2d mixing/test_tank.py LAMMPS ARGS tank2d
  LABELS validation)
foreach(components two one)
  sphthermal_python_test(mixing.validation.tank3d_${components} mixing/test_tank.py LAMMPS
    ARGS tank3d --components ${components} LABELS validation)
endforeach()
sphthermal_python_test(mixing.mpi.ranks mixing/test_mixing.py LAMMPS ARGS ranks LABELS mpi)
