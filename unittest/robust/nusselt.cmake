# compute sph/nusselt: a staircase wall (an annulus cut from the lattice)
# warns and its heat estimate is exact within 0.3 %; flat walls with
# corners do not warn, on 1 and 2 ranks
foreach(np 1 2)
  add_test(NAME robust.nusselt.staircase.np${np}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_nusselt_staircase.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --np ${np} --mpirun ${MPIRUN})
  set_tests_properties(robust.nusselt.staircase.np${np} PROPERTIES LABELS unit)
endforeach()
