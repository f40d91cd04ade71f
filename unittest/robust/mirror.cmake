# mirror walls around an obstacle (a surface region 'side out'): exact for
# a linear field, on 1 and 2 ranks
foreach(np 1 2)
  add_test(NAME robust.mirror.side_out.np${np}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_mirror_side.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --np ${np} --mpirun ${MPIRUN})
  set_tests_properties(robust.mirror.side_out.np${np} PROPERTIES LABELS unit)
endforeach()

# a medium atom past the wall's surface: refused as set up, taken within a
# tolerance at a later run's start (drift), refused beyond it
add_test(NAME robust.mirror.drift
  COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_mirror_drift.py
          --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN})
set_tests_properties(robust.mirror.drift PROPERTIES LABELS unit)
