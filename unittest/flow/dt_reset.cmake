# Tests of fix sph/dt/reset, included by unittest/CMakeLists.txt after
# PYTHON_NUMPY and MPIRUN are set. Uses SPHTHERMAL_LMP, SPHTHERMAL_PLUGIN.
set(dt_reset_test ${PYTHON_NUMPY} ${CMAKE_CURRENT_SOURCE_DIR}/flow/test_dt_reset.py
    --lmp ${SPHTHERMAL_LMP} --plugin ${SPHTHERMAL_PLUGIN} --mpirun ${MPIRUN})

# pure conduction: dt = 0.1 h^2 rho cv / k_max exactly (uniform, also with the
# 'h' keyword), and against per-atom rho, cv, k(T) while T evolves (varying)
add_test(NAME flow.dt_reset.thermal.uniform COMMAND ${dt_reset_test} conduction --case uniform)
add_test(NAME flow.dt_reset.thermal.uniform_h COMMAND ${dt_reset_test} conduction --case uniform --h 0.011)
add_test(NAME flow.dt_reset.thermal.varying COMMAND ${dt_reset_test} conduction --case varying)
add_test(NAME flow.dt_reset.thermal.every5
  COMMAND ${dt_reset_test} conduction --case varying --every 5)
set_tests_properties(flow.dt_reset.thermal.uniform flow.dt_reset.thermal.uniform_h
                     flow.dt_reset.thermal.varying flow.dt_reset.thermal.every5
                     PROPERTIES LABELS unit)

# channel flow: the four limits, the active one and dt against a Python
# computation from the dumped v, f, mass, rho; each case makes another limit
# active (acoustic, force, viscous; Tait EOS; per-atom mass; the min and max
# bounds; N = 5 with an explicit h); time = sum of dt in each
foreach(case acoustic force viscous tait peratom_mass max min every5)
  add_test(NAME flow.dt_reset.flow.${case} COMMAND ${dt_reset_test} flow --case ${case})
  set_tests_properties(flow.dt_reset.flow.${case} PROPERTIES LABELS unit)
endforeach()

# time continues across write_restart / read_restart (LAMMPS 29Sep2021 alone
# restarts it at 0) and equals one session running twice
add_test(NAME flow.dt_reset.restart COMMAND ${dt_reset_test} restart)
set_tests_properties(flow.dt_reset.restart PROPERTIES LABELS regression)

# the same dt sequence and active limits on 2 and 4 ranks as on 1
foreach(np 2 4)
  add_test(NAME flow.dt_reset.mpi.np${np} COMMAND ${dt_reset_test} mpi --np ${np})
  set_tests_properties(flow.dt_reset.mpi.np${np} PROPERTIES LABELS mpi PROCESSORS ${np})
endforeach()

# bad input: each a LAMMPS ERROR naming the command and the argument
add_error_cases(flow.dt_reset ${CMAKE_CURRENT_SOURCE_DIR}/flow/dt_reset_errors.in)
