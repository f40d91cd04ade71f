# fix sph/open: inlets and outlets (included by unittest/CMakeLists.txt;
# helpers: cmake/sphthermal_tests.cmake)
set(open_input ${CMAKE_CURRENT_LIST_DIR}/in.open)
sphthermal_lammps_test(open.uniform_stream ${open_input}
  VARS check uniform scene stream inflow uniform LABELS validation PASS "uniform: atoms")
foreach(inflow uniform parabolic)
  sphthermal_lammps_test(open.balance.${inflow} ${open_input}
    VARS check balance inflow ${inflow} LABELS validation PASS "balance: atoms in")
endforeach()
# energy and momentum through the planes: with the atoms that crossed and
# the buffers' conduction and forces, the fluid's change to round-off
# (unshifted and shifted, 1 and 2 ranks)
set(flux_vars check flux scene stream inflow uniform push yes steps 1000)
sphthermal_lammps_test(open.balance.flux ${open_input} VARS ${flux_vars}
  LABELS unit PASS "flux: the fluid change")
sphthermal_lammps_test(open.balance.flux_shifted ${open_input} VARS ${flux_vars} shift default
  LABELS unit PASS "flux: the fluid change")
sphthermal_test(open.mpi.balance_flux_np2 LABELS mpi PROCESSORS 2 PASS "flux: the fluid change"
  FAIL ERROR WORKING_DIRECTORY ${CMAKE_CURRENT_LIST_DIR}
  ENVIRONMENT OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
  COMMAND ${MPIRUN} --oversubscribe -np 2 ${SPHTHERMAL_LMP} -in ${open_input}
          -var plugin ${SPHTHERMAL_PLUGIN} -var check flux -var scene stream -var inflow uniform
          -var push yes -var steps 1000 -log none)
foreach(np 2 4)
  sphthermal_state_test(open.mpi.np${np} same ${open_input}
    ARGS --var check=state --var lo=-0.2 --var steps=600 NP ${np} RTOL 1e-10)
endforeach()
set(in_build_dir WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
# 200 steps: round-off grows to 1e-9 by 600 steps in the channel's corners
sphthermal_state_test(open.restart same ${open_input} ${in_build_dir}
  ARGS --var check=state --var lo=-0.2 --var steps=200 --var split=two --var2 split=yes
       RTOL 1e-12)
# the shift's continuity is on by default for the fluid of an open boundary
# (it holds the fluid's particles: without it the heated channel lost 2 %
# of them in two flow-through times and ran 2 % fast), off when given
sphthermal_lammps_test(open.shift.continuity_default ${open_input}
  VARS check balance shift default steps 300
  LABELS unit PASS "continuity yes \\(the default for an open boundary's fluid\\)")
sphthermal_lammps_test(open.shift.continuity_given ${open_input}
  VARS check balance shift no steps 300
  LABELS unit PASS "balance: atoms in" FAIL "ERROR|the default for an open")
# a dump sorted by ID while atoms are created and deleted in balance
sphthermal_python_test(open.dump_sort_id open/test_dump_sort.py LAMMPS LABELS unit)
add_error_cases(open ${CMAKE_CURRENT_LIST_DIR}/errors.in)
add_example_test(open.validation.channel_10 open-channel quick channel_10)
add_example_test(open.validation.cylinder_10 open-cylinder quick cylinder_10)
add_example_test(open.validation.shedding_10 open-cylinder shedding-quick shedding_10)
sphthermal_python_test(open.reference.channel_entrance tools/test_channel_entrance.py LABELS unit)
