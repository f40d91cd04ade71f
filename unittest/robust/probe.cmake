# every style of the package on 2 ranks and across a restart (one probe per
# style and per main option, the table in test_probe.py); coverage: every
# style the sources declare has a probe
execute_process(
  COMMAND ${SPHTHERMAL_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_probe.py --lmp - --plugin - --list
  OUTPUT_VARIABLE sphthermal_probes OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE probe_list_rc)
if(NOT probe_list_rc EQUAL 0)
  message(FATAL_ERROR "robust/test_probe.py --list failed: ${probe_list_rc}")
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
  ${CMAKE_CURRENT_LIST_DIR}/test_probe.py)
foreach(probe ${sphthermal_probes})
  sphthermal_python_test(robust.probe.${probe} robust/test_probe.py LAMMPS
    ARGS --mpirun ${MPIRUN} --probe ${probe} LABELS unit)
endforeach()
sphthermal_python_test(robust.probe.coverage robust/test_probe.py LAMMPS
  ARGS --coverage LABELS unit)

# bad forms of each probe's command line (robust.syntax.<probe>)
execute_process(
  COMMAND ${SPHTHERMAL_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/test_probe.py --lmp - --plugin -
          --list-syntax
  OUTPUT_VARIABLE sphthermal_syntax_probes OUTPUT_STRIP_TRAILING_WHITESPACE)
foreach(probe ${sphthermal_syntax_probes})
  sphthermal_python_test(robust.syntax.${probe} robust/test_probe.py LAMMPS
    ARGS --probe ${probe} --syntax LABELS unit)
endforeach()
