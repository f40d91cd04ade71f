# fix sph/dt/reset in every unit style: the same scene (conduction; a
# viscous flow under gravity) in si and in <units> gets the same timestep
# and limits in seconds, so each limit has the unit factor ftm2v with which
# fix sph integrates the rates; each run stays finite and bounded
foreach(units cgs metal real electron lj)
  add_test(NAME robust.dt_units.${units}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_dt_units.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --units ${units})
  set_tests_properties(robust.dt_units.${units} PROPERTIES LABELS unit)
endforeach()

# a fixed timestep (checked by the internal fix SPH/TIMESTEP/CHECK that the
# package's pairs add): no warning below the smallest limit the pairs know, a
# warning above it, none with fix sph/dt/reset (which sets dt itself)
foreach(units si metal real)
  add_test(NAME robust.timestep.fixed.${units}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_dt_units.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --fixed ${units})
  set_tests_properties(robust.timestep.fixed.${units} PROPERTIES LABELS unit)
endforeach()
