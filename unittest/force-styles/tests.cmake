# LAMMPS's YAML pair-style tests of the package's pairs, run by the in-tree
# build's test_pair_style (included by unittest/CMakeLists.txt)
if(SPHTHERMAL_BUILD_INTREE)
  file(GLOB yaml_tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/*.yaml)
  foreach(yaml ${yaml_tests})
    get_filename_component(name ${yaml} NAME_WE)
    set(area conduction)
    if(name MATCHES "harmonic_visc")
      set(area flow)
    endif()
    sphthermal_test(${area}.yaml.${name} LABELS regression ENVIRONMENT "OMP_NUM_THREADS=1"
      WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR}
      COMMAND ${LAMMPS_TEST_PAIR_STYLE} ${yaml} -d ${CMAKE_CURRENT_LIST_DIR})
  endforeach()
endif()
