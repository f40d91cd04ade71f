# pair sph/cleary/heat 'correction consistent' on a lattice rotated against
# free edges (atoms exactly on the edges, corners cutting the rows): desph
# finite, the corners on the plain term, energy kept, a linear field exact
# deep inside
foreach(case cubic_f wendland_s quintic_f)
  add_test(NAME robust.consistent_edge.${case}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_consistent_edge.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --case ${case})
  set_tests_properties(robust.consistent_edge.${case} PROPERTIES LABELS unit)
endforeach()
