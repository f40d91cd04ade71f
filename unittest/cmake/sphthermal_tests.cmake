# Registration helpers of the USER-SPHTHERMAL tests, included by
# unittest/CMakeLists.txt before the areas' <area>/tests.cmake. Every test
# is registered in the unittest directory (include(), not add_subdirectory):
# its working directory, output paths and cross-area properties (DEPENDS,
# RESOURCE_LOCK) are the same whichever file registers it. Paths given
# relative are relative to unittest/ (SPHTHERMAL_TESTS_DIR).
#
#   sphthermal_test           any command, with its properties
#   sphthermal_unit_checks    <prefix>.<check> for each check of a C test program
#   sphthermal_lammps_test    a LAMMPS input case (lmp -in ... -var plugin ...)
#   sphthermal_python_test    a Python test script (optionally --lmp/--plugin)
#   sphthermal_state_test     sphtest.py state/same/eq6 with the state driver
#   add_example_test          an example's coarse check (examples/<e>/run.sh <mode>)
#   add_error_cases           every case of an errors.in file
#   add_header_test(_cxx)     a test program of the package's C99 headers
#
# Options common to the test helpers (all optional):
#   LABELS <label>...            unit, regression, validation, mpi
#   PROCESSORS <n>               ctest's PROCESSORS
#   WORKING_DIRECTORY <dir>      run there (default: ctest's, <build>/unittest)
#   PASS <regex>... / FAIL <regex>...   PASS_/FAIL_REGULAR_EXPRESSION
#   WILL_FAIL                    a control that must fail
#   RESOURCE_LOCK <name>         tests that write the same file, one at a time
#   ENVIRONMENT <NAME=VALUE>...  ctest's ENVIRONMENT (every test also gets
#                                PYTHONPATH=<repo>/tools:<repo>/unittest/tools)

set(SPHTHERMAL_TESTS_DIR ${CMAKE_CURRENT_LIST_DIR}/..)
get_filename_component(SPHTHERMAL_TESTS_DIR ${SPHTHERMAL_TESTS_DIR} ABSOLUTE)

# the one way the Python scripts find shared code: tools/ (sphthermal_tools,
# the reference solvers) and the test harness unittest/tools (sphtest,
# checks, lammps_checks, cavity_scenes); every test gets it, and a script
# run at configure time runs as ${SPHTHERMAL_PYTHON}
set(SPHTHERMAL_PYTHONPATH ${SPHTHERMAL_ROOT}/tools:${SPHTHERMAL_TESTS_DIR}/tools)
set(SPHTHERMAL_PYTHON ${CMAKE_COMMAND} -E env PYTHONPATH=${SPHTHERMAL_PYTHONPATH} ${PYTHON_NUMPY})

set(sphthermal_test_flags WILL_FAIL)
set(sphthermal_test_values PROCESSORS WORKING_DIRECTORY RESOURCE_LOCK)
set(sphthermal_test_lists LABELS PASS FAIL ENVIRONMENT)

# the helpers below parse their own keywords and the common options
# (<prefix>_<option>, cmake_parse_arguments's variables) and hand these on
# to sphthermal_test: sphthermal_parse(<prefix> <first arg> <flags> <values> <lists>)
# is cmake_parse_arguments(PARSE_ARGV ...) with the common options added, and
# refuses unknown arguments; sphthermal_forward(<prefix> <out>) lists the
# common options given, as sphthermal_test takes them
macro(sphthermal_parse prefix first flags values lists)
  cmake_parse_arguments(PARSE_ARGV ${first} ${prefix} "${flags};${sphthermal_test_flags}"
                        "${values};${sphthermal_test_values}" "${lists};${sphthermal_test_lists}")
  if(${prefix}_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "a sphthermal test helper (${name}): unknown arguments: "
                        "${${prefix}_UNPARSED_ARGUMENTS}")
  endif()
endmacro()
macro(sphthermal_forward prefix out)
  set(${out} "")
  foreach(option ${sphthermal_test_flags})
    if(${prefix}_${option})
      list(APPEND ${out} ${option})
    endif()
  endforeach()
  foreach(option ${sphthermal_test_values} ${sphthermal_test_lists})
    if(DEFINED ${prefix}_${option})
      list(APPEND ${out} ${option} ${${prefix}_${option}})
    endif()
  endforeach()
endmacro()

# a path relative to unittest/ made absolute
function(sphthermal_test_path out path)
  if(NOT IS_ABSOLUTE "${path}")
    set(path ${SPHTHERMAL_TESTS_DIR}/${path})
  endif()
  set(${out} ${path} PARENT_SCOPE)
endfunction()

# sphthermal_test(<name> [options] COMMAND <command>...)
function(sphthermal_test name)
  cmake_parse_arguments(PARSE_ARGV 1 T "${sphthermal_test_flags}" "${sphthermal_test_values}"
                        "${sphthermal_test_lists};COMMAND")
  if(T_UNPARSED_ARGUMENTS OR NOT T_COMMAND)
    message(FATAL_ERROR "sphthermal_test(${name}): no COMMAND or unknown arguments: ${T_UNPARSED_ARGUMENTS}")
  endif()
  if(T_WORKING_DIRECTORY)
    add_test(NAME ${name} COMMAND ${T_COMMAND} WORKING_DIRECTORY ${T_WORKING_DIRECTORY})
  else()
    add_test(NAME ${name} COMMAND ${T_COMMAND})
  endif()
  if(T_LABELS)
    set_tests_properties(${name} PROPERTIES LABELS "${T_LABELS}")
  endif()
  if(T_PROCESSORS)
    set_tests_properties(${name} PROPERTIES PROCESSORS ${T_PROCESSORS})
  endif()
  if(T_PASS)
    set_tests_properties(${name} PROPERTIES PASS_REGULAR_EXPRESSION "${T_PASS}")
  endif()
  if(T_FAIL)
    set_tests_properties(${name} PROPERTIES FAIL_REGULAR_EXPRESSION "${T_FAIL}")
  endif()
  if(T_WILL_FAIL)
    set_tests_properties(${name} PROPERTIES WILL_FAIL TRUE)
  endif()
  if(T_RESOURCE_LOCK)
    set_tests_properties(${name} PROPERTIES RESOURCE_LOCK ${T_RESOURCE_LOCK})
  endif()
  list(APPEND T_ENVIRONMENT PYTHONPATH=${SPHTHERMAL_PYTHONPATH})
  set_tests_properties(${name} PROPERTIES ENVIRONMENT "${T_ENVIRONMENT}")
endfunction()

# sphthermal_unit_checks(<prefix> <program> <check>...): the tests
# <prefix>.<check> = '<program> <check>', labelled unit
function(sphthermal_unit_checks prefix program)
  foreach(check ${ARGN})
    sphthermal_test(${prefix}.${check} LABELS unit COMMAND ${program} ${check})
  endforeach()
endfunction()

# sphthermal_lammps_test(<name> <input> [VARS <name> <value>...] [IN_BUILD_DIR] [options])
# runs 'lmp -in <input> -var plugin <plugin> [-var <name> <value>]... -log none'
# in the input's directory (IN_BUILD_DIR: in <build>/unittest, ctest's default;
# WORKING_DIRECTORY: there),
# with FAIL ERROR unless FAIL is given (NO_FAIL: none)
function(sphthermal_lammps_test name input)
  sphthermal_parse(L 2 "IN_BUILD_DIR;NO_FAIL" "" "VARS")
  sphthermal_test_path(input ${input})
  set(vars "")
  list(LENGTH L_VARS n)
  math(EXPR odd "${n} % 2")
  if(odd)
    message(FATAL_ERROR "sphthermal_lammps_test(${name}): VARS wants name value pairs: ${L_VARS}")
  endif()
  while(L_VARS)
    list(GET L_VARS 0 var)
    list(GET L_VARS 1 value)
    list(REMOVE_AT L_VARS 0 1)
    list(APPEND vars -var ${var} ${value})
  endwhile()
  set(where "")
  if(L_WORKING_DIRECTORY)
    set(where WORKING_DIRECTORY ${L_WORKING_DIRECTORY})
  elseif(NOT L_IN_BUILD_DIR)
    get_filename_component(dir ${input} DIRECTORY)
    set(where WORKING_DIRECTORY ${dir})
  endif()
  set(fail FAIL ERROR)
  if(L_FAIL)
    set(fail FAIL ${L_FAIL})
  elseif(L_NO_FAIL)
    set(fail "")
  endif()
  unset(L_FAIL)
  unset(L_WORKING_DIRECTORY)
  sphthermal_forward(L options)
  sphthermal_test(${name} ${where} ${fail} ${options}
    COMMAND ${SPHTHERMAL_LMP} -in ${input} -var plugin ${SPHTHERMAL_PLUGIN} ${vars} -log none)
endfunction()

# sphthermal_python_test(<name> <script> [LAMMPS] [ARGS <arg>...] [options]):
# '<python> <script> [--lmp <lmp> --plugin <plugin>] <arg>...'
function(sphthermal_python_test name script)
  sphthermal_parse(P 2 "LAMMPS" "" "ARGS")
  sphthermal_forward(P options)
  sphthermal_test_path(script ${script})
  set(lammps "")
  if(P_LAMMPS)
    set(lammps --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN})
  endif()
  sphthermal_test(${name} ${options} COMMAND ${PYTHON_NUMPY} ${script} ${lammps} ${P_ARGS})
endfunction()

# sphthermal_state_test(<name> <mode> <input> [ARGS <arg>...] [REF <ref>] [NP <n>]
#                       [RTOL <rtol>] [DRIVER2 <driver>] [options]): unittest/tools/sphtest.py
# with the host state driver and the plugin,
#   state: '<args> --ref <ref>' (default label regression)
#   same:  '[--driver2 <d>] <args> [--np 1 --np2 <n> --mpirun <mpirun>] --rtol <rtol>'
#          (default label regression, with NP mpi and PROCESSORS <n>)
#   eq6:   '<args>' (default label unit)
function(sphthermal_state_test name mode input)
  sphthermal_parse(S 3 "" "REF;NP;RTOL;DRIVER2" "ARGS")
  sphthermal_test_path(input ${input})
  set(head ${sphtest} ${mode} --driver $<TARGET_FILE:sph_state_host>)
  set(tail "")
  set(labels regression)
  set(processors ${S_PROCESSORS})
  if(mode STREQUAL "state")
    sphthermal_test_path(ref ${S_REF})
    set(tail --ref ${ref})
  elseif(mode STREQUAL "same")
    if(S_DRIVER2)
      list(APPEND head --driver2 ${S_DRIVER2})
    endif()
    if(S_NP)
      set(tail --np 1 --np2 ${S_NP} --mpirun ${MPIRUN})
      set(labels mpi)
      if(NOT processors)
        set(processors ${S_NP})
      endif()
    endif()
    if(NOT S_RTOL STREQUAL "")
      list(APPEND tail --rtol ${S_RTOL})
    endif()
  elseif(mode STREQUAL "eq6")
    set(labels unit)
  else()
    message(FATAL_ERROR "sphthermal_state_test(${name}): unknown mode ${mode}")
  endif()
  if(S_LABELS)
    set(labels ${S_LABELS})
  endif()
  if(processors)
    set(processors PROCESSORS ${processors})
  endif()
  unset(S_LABELS)
  unset(S_PROCESSORS)
  sphthermal_forward(S options)
  sphthermal_test(${name} LABELS ${labels} ${processors} ${options}
    COMMAND ${head} --input ${input} ${plugin_var} ${S_ARGS} ${tail})
endfunction()

# add_example_test(<name> <example> <mode> <out> [ENV NAME=VALUE...] [options]):
# examples/<example>/run.sh <mode> (an example's coarse check) with LMP,
# PLUGIN, OUT (<build>/unittest/<out>) and PYTHON in its environment, and
# the NAME=VALUE pairs after ENV; labelled validation unless LABELS is given
function(add_example_test name example mode out)
  sphthermal_parse(EXAMPLE 4 "" "" "ENV")
  if(NOT EXAMPLE_LABELS)
    set(EXAMPLE_LABELS validation)
  endif()
  sphthermal_forward(EXAMPLE options)
  sphthermal_test(${name} ${options}
    COMMAND ${CMAKE_COMMAND} -E env LMP=${SPHTHERMAL_LMP} PLUGIN=${SPHTHERMAL_PLUGIN}
            OUT=${CMAKE_CURRENT_BINARY_DIR}/${out} PYTHON=${PYTHON_NUMPY} ${EXAMPLE_ENV}
            ${SPHTHERMAL_ROOT}/examples/${example}/run.sh ${mode})
endfunction()

# add_error_cases(<area> <cases file>): every case of the file is a test
# <area>.error.<name> (labelled unit); each records the source line that
# raised its message, for robust.error_branches (which runs after them all:
# the global property sphthermal_error_tests lists them)
set(error_sites_dir ${CMAKE_CURRENT_BINARY_DIR}/error-sites)
function(add_error_cases area cases)
  sphthermal_test_path(cases ${cases})
  execute_process(COMMAND ${SPHTHERMAL_PYTHON} ${SPHTHERMAL_TESTS_DIR}/tools/sphtest.py error --list
                          --cases ${cases} --lmp x --plugin x
                  OUTPUT_VARIABLE case_names OUTPUT_STRIP_TRAILING_WHITESPACE)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${cases})
  string(REPLACE "\n" ";" case_names "${case_names}")
  foreach(name ${case_names})
    sphthermal_test(${area}.error.${name} LABELS unit
      COMMAND ${sphtest} error --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN}
              --cases ${cases} --name ${name} --record ${error_sites_dir})
    set_property(GLOBAL APPEND PROPERTY sphthermal_error_tests ${area}.error.${name})
  endforeach()
endfunction()

# a test program of the package's C99 headers (extra target properties,
# e.g. C_EXTENSIONS OFF, after the source), and its twin that compiles the
# same test as C++ (a .cpp that includes the .c, found in its directory)
function(add_header_test target source)
  sphthermal_test_path(source ${source})
  add_executable(${target} ${source})
  target_include_directories(${target} PRIVATE ${SPHTHERMAL_PKG_DIR})
  set_target_properties(${target} PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON ${ARGN})
  target_compile_options(${target} PRIVATE -Wall -Wextra -pedantic)
  target_link_libraries(${target} PRIVATE m)
endfunction()
function(add_header_test_cxx target source)
  sphthermal_test_path(source ${source})
  get_filename_component(dir ${source} DIRECTORY)
  add_executable(${target} ${source})
  target_include_directories(${target} PRIVATE ${SPHTHERMAL_PKG_DIR} ${dir})
  target_compile_options(${target} PRIVATE -Wall -Wextra)
endfunction()

# the state driver (unittest/tools/sph_state.c) linked to a LAMMPS build
function(add_state_driver target lammps_build_dir)
  add_executable(${target} ${SPHTHERMAL_TESTS_DIR}/tools/sph_state.c)
  target_include_directories(${target} PRIVATE ${LAMMPS_SOURCE_DIR}/src)
  target_link_libraries(${target} PRIVATE ${lammps_build_dir}/liblammps.so MPI::MPI_C)
  set_target_properties(${target} PROPERTIES BUILD_RPATH ${lammps_build_dir})
endfunction()
