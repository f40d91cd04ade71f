# set-up tests: the short form (sph/set, the body force read once, the
# material-file search) and the Howto's scenes (included by
# unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)
set(potentials --potentials ${SPHTHERMAL_TESTS_DIR}/../potentials)
add_error_cases(setup setup/errors.in)
foreach(case materials hydrostatic)
  sphthermal_python_test(setup.short_form.${case} setup/test_short_form.py LAMMPS
    ARGS ${potentials} --case ${case} LABELS regression)
endforeach()
# a no-slip steel wall keeps steel's density and heat capacity (1 and 2 ranks)
# the hot-block scene of the Howto runs as written and its heat flows balance (1 and 2 ranks)
foreach(np 1 2)
  set(labels validation)
  if(np GREATER 1)
    set(labels validation mpi)
  endif()
  sphthermal_python_test(setup.solid_wall.np${np} setup/test_solid_wall.py LAMMPS
    ARGS ${potentials} --np ${np} --mpirun ${MPIRUN} LABELS ${labels})
  sphthermal_python_test(setup.hot_block.np${np} setup/test_hot_block.py LAMMPS
    ARGS --np ${np} --mpirun ${MPIRUN} LABELS ${labels})
endforeach()
# the 3-d boundary set-up: the closed cylindrical tank of tools/sph_boundary.py, read by LAMMPS
sphthermal_python_test(setup.cylinder setup/test_cylinder_setup.py LAMMPS LABELS unit)
# sph/faces: the groups of a walled block (2-d) and around a cylinder (3-d), 1 and 2 ranks
foreach(dim 2 3)
  foreach(np 1 2)
    set(labels unit)
    if(np GREATER 1)
      set(labels unit mpi)
    endif()
    sphthermal_python_test(setup.faces.${dim}d.np${np} setup/test_faces.py LAMMPS
      ARGS --dim ${dim} --np ${np} --mpirun ${MPIRUN} LABELS ${labels})
  endforeach()
endforeach()
