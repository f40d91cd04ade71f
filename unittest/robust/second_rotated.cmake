# pair sph/cleary/heat 'correction second' on a lattice rotated by atan(1/2):
# with free edges the Laplacian of a quadratic field exact on every corrected
# atom (the regularised solve alone left 1.1e-3 deep inside, worse than the
# plain term's 1.6e-4), periodic no worse than the plain term
foreach(case free periodic)
  add_test(NAME robust.second_rotated.${case}
    COMMAND ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/robust/test_second_rotated.py
            --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --case ${case})
  set_tests_properties(robust.second_rotated.${case} PROPERTIES LABELS unit)
endforeach()
