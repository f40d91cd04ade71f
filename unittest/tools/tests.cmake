# tests of the test tools, the repository's scripts and the benchmarks
# (included by unittest/CMakeLists.txt; helpers: cmake/sphthermal_tests.cmake)

# docs, examples, benchmarks and sources cite the papers, not internal seed numbers
sphthermal_test(docs.citations LABELS unit COMMAND ${CMAKE_CURRENT_LIST_DIR}/check_citations.sh)
# every :doc: and :ref: target of the docs exists (the package's pages or
# those of LAMMPS 4Feb2025, which the docs link to), every relative link of
# the Markdown files names a file; the self-test must see each broken link
# (with a LAMMPS tree that has its docs, as Debian's source has)
if(EXISTS ${LAMMPS_SOURCE_DIR}/doc/src)
  sphthermal_python_test(docs.links_selftest tools/check_doc_links.py
    ARGS ${SPHTHERMAL_ROOT} --lammps-doc ${LAMMPS_SOURCE_DIR}/doc/src
         --expect-broken ${CMAKE_CURRENT_LIST_DIR}/doc_links_broken.rst.txt LABELS unit)
  if(LAMMPS_RELEASE STREQUAL "4Feb2025")
    sphthermal_python_test(docs.links tools/check_doc_links.py
      ARGS ${SPHTHERMAL_ROOT} --lammps-doc ${LAMMPS_SOURCE_DIR}/doc/src LABELS unit)
  endif()
endif()

# the state driver refuses atom IDs that would leave rows of its table unset
sphthermal_test(tools.sph_state.error.ids_gap LABELS unit
  PASS "sph_state: atom ID 4 is not in 1\\.\\.3"
  COMMAND $<TARGET_FILE:sph_state_host> ${CMAKE_CURRENT_BINARY_DIR}/state_ids_gap.out
          ${CMAKE_CURRENT_LIST_DIR}/state_ids_gap.in)
sphthermal_test(tools.sph_state.error.ids_twice LABELS unit
  PASS "sph_state: atom ID 1 is given to more than one atom"
  COMMAND $<TARGET_FILE:sph_state_host> ${CMAKE_CURRENT_BINARY_DIR}/state_ids_twice.out
          ${CMAKE_CURRENT_LIST_DIR}/state_ids_twice.in
          -var data ${CMAKE_CURRENT_LIST_DIR}/state_ids_twice.data)
# the plotting helper turns a dump and a fix ave/time file into PNGs
sphthermal_python_test(tools.sphplot tools/test_sphplot.py ARGS --python ${PYTHON_NUMPY}
  LABELS unit)
# time averages and steady state of a series (sphthermal_tools.series)
sphthermal_python_test(tools.series tools/test_series.py LABELS unit)
# the 2-d Wendland C2 of the examples' analysis scripts (tools/wendland2d.py)
sphthermal_python_test(tools.wendland2d tools/test_wendland2d.py LABELS unit)
# the finite-volume reference of the phase-change examples (tools/phase_fv.py)
sphthermal_python_test(tools.phase_fv tools/test_phase_fv.py LABELS unit)

# the RHEO comparison (bench/rheo) runs, coarse, with its error bounds: RHEO
# is built on LAMMPS 4Feb2025 only
if(LAMMPS_RELEASE STREQUAL "4Feb2025")
  sphthermal_python_test(bench.rheo_quick ${SPHTHERMAL_ROOT}/bench/rheo/run_bench.py
    ARGS --quick --repeat 1 --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
         --out ${CMAKE_CURRENT_BINARY_DIR}/rheo_quick
         --results ${CMAKE_CURRENT_BINARY_DIR}/rheo_quick
    LABELS validation)
  # melting by fix sph/phase and by RHEO's Tfreeze on the Stefan problem
  sphthermal_python_test(bench.rheo_stefan_quick ${SPHTHERMAL_ROOT}/bench/rheo/run_stefan.py
    ARGS --quick --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
         --out ${CMAKE_CURRENT_BINARY_DIR}/rheo_stefan_quick
    LABELS validation)
endif()

# the stress suite's CI subset (bench/stress): a jittered cavity and a
# jittered Poiseuille flow, short, each stable with finite results
sphthermal_python_test(bench.stress_quick ${SPHTHERMAL_ROOT}/bench/stress/stress.py LAMMPS
  ARGS --quick --out ${CMAKE_CURRENT_BINARY_DIR}/stress_quick
       --results ${CMAKE_CURRENT_BINARY_DIR}/stress_quick/results.md
  LABELS regression)

# every doc page parses as reStructuredText without a warning (where
# docutils is installed: Debian's python3-docutils)
execute_process(COMMAND ${PYTHON_NUMPY} -c "import docutils" RESULT_VARIABLE no_docutils
                OUTPUT_QUIET ERROR_QUIET)
if(NOT no_docutils)
  file(GLOB doc_pages CONFIGURE_DEPENDS ${SPHTHERMAL_ROOT}/doc/src/*.rst)
  sphthermal_python_test(docs.rst tools/check_rst.py ARGS ${doc_pages} LABELS unit)
  sphthermal_python_test(docs.rst_selftest tools/check_rst.py
    ARGS --expect-problems ${CMAKE_CURRENT_LIST_DIR}/rst_faults.rst.txt LABELS unit)
else()
  message(STATUS "docs.rst left out: no docutils (apt-get install python3-docutils)")
endif()

# the stress table of Stability_sphthermal.rst is that of bench/stress/results.md
sphthermal_python_test(docs.stress_table ${SPHTHERMAL_ROOT}/bench/stress/stress.py ARGS --doc-check
  LABELS unit)

# the measured numbers the docs quote are those of the results files the
# benchmarks and reference solvers write (the quotes: doc_numbers.txt);
# the self-test must see each wrong quote of doc_numbers_faults.txt fail
sphthermal_python_test(docs.numbers tools/check_doc_numbers.py ARGS ${SPHTHERMAL_ROOT} LABELS unit)
sphthermal_python_test(docs.numbers_selftest tools/check_doc_numbers.py
  ARGS ${SPHTHERMAL_ROOT} --table ${CMAKE_CURRENT_LIST_DIR}/doc_numbers_faults.txt --expect-fail
  LABELS unit)
