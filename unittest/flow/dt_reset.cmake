# Tests of fix sph/dt/reset, included by flow/tests.cmake (helpers:
# cmake/sphthermal_tests.cmake)
function(dt_reset_test name)
  sphthermal_python_test(flow.dt_reset.${name} flow/test_dt_reset.py LAMMPS ${ARGN})
endfunction()
set(mpirun --mpirun ${MPIRUN})

# pure conduction: dt = 0.1 h^2 rho cv / k_max exactly (uniform, also with the
# 'h' keyword), and against per-atom rho, cv, k(T) while T evolves (varying)
dt_reset_test(thermal.uniform ARGS ${mpirun} conduction --case uniform LABELS unit)
dt_reset_test(thermal.uniform_h ARGS ${mpirun} conduction --case uniform --h 0.011 LABELS unit)
dt_reset_test(thermal.varying ARGS ${mpirun} conduction --case varying LABELS unit)
dt_reset_test(thermal.every5 ARGS ${mpirun} conduction --case varying --every 5 LABELS unit)

# channel flow: the four limits, the active one and dt against a Python
# computation from the dumped v, f, mass, rho; each case makes another limit
# active (acoustic, force, viscous; Tait EOS; per-atom mass; the min and max
# bounds; N = 5 with an explicit h); time = sum of dt in each
foreach(case acoustic force viscous tait peratom_mass max min every5)
  dt_reset_test(flow.${case} ARGS ${mpirun} flow --case ${case} LABELS unit)
endforeach()

# time continues across write_restart / read_restart (LAMMPS 29Sep2021 alone
# restarts it at 0) and equals one session running twice
dt_reset_test(restart ARGS ${mpirun} restart LABELS regression)

# 'until T': the run ends at T exactly (N = 1 and 5), the next run is not
# stopped by it, a run that starts at T stops at once with a warning
dt_reset_test(until ARGS ${mpirun} until LABELS unit)

# 'time t0': after a set-up run and reset_timestep 0 the next run starts at
# t0 (LAMMPS 29Sep2021's reset_timestep keeps the time)
dt_reset_test(time ARGS ${mpirun} time LABELS unit)

# the same dt sequence and active limits on 2 and 4 ranks as on 1
foreach(np 2 4)
  dt_reset_test(mpi.np${np} ARGS ${mpirun} mpi --np ${np} LABELS mpi PROCESSORS ${np})
endforeach()

# bad input: each a LAMMPS ERROR naming the command and the argument
add_error_cases(flow.dt_reset flow/dt_reset_errors.in)
